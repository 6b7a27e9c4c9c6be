%
O0202 (FANUC LEFT-HAND TAPPING, FINE BORING, BACK BORING)
N10 G17 G21 G40 G49 G80 G90 G94 G54
N20 T2 M6
N30 G43 H2
N40 S400 M4
N50 G0 Z30.
(G74 left-hand tapping: spindle counter-clockwise in, clockwise out, dwell P in ms)
N60 G99 G74 X10. Y10. Z-12. R3. P300 F280
N70 X30.
N80 G98 X50. Y10.
N90 G80 M5
N100 S900 M3
(G76 fine boring: oriented stop at the bottom, shift by Q, out, shift back; Q500 = 0.5 mm)
N110 G99 G76 X10. Y40. Z-15. R2. Q500 P200 F60
N120 G98 X40. Q0.8
(incremental: R from the initial level, Z from R, K repeats step the hole)
N130 G91 G76 X15. Y0 Z-10. R-25. K2
N140 G90 G80
(G87 back boring: oriented stop and shift above the part, rapid under it to R, feed up to Z)
N150 G0 Z30.
N160 G87 X80. Y20. Z-5. R-22. Q1. P100 F50
N170 G80
N180 G0 Z50.
N190 M30
%
