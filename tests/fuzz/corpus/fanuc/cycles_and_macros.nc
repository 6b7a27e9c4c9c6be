%
O0201 (FANUC CYCLES AND MACROS)
N10 G17 G21 G40 G49 G80 G90 G94 G54
N20 T2 M6
N30 G43 H2
N40 S1200 M3
N50 G0 Z30.
(G73 chip breaking, then G91 holes with K repeats: R from the initial level, Z from R)
N60 G99 G73 X10. Y10. Z-8. R2. Q3. F150
N70 G91 X10. Y0 Z-10. R-28. K3
N80 G90 G80
N90 G0 Z30.
(dwell in both forms: X seconds, P milliseconds)
N100 G4 X0.5
N110 G4 P250
(boring cycles: feed out, rapid out, dwell and feed out)
N120 G98 G85 X10. Y30. Z-6. R2. F80
N130 G86 X20. Z-6. R2.
N140 G89 X30. Z-6. R2. P400
N150 G80
(a macro IF THEN and a computed GOTO)
#10=5.
IF [#10 GT 4.] THEN #11=1.
IF [#11 EQ 1.] GOTO 200
N160 G0 X99.
N200 G0 X[#10*2] Y[SQRT[16.]]
(local coordinates and an incremental polar move)
N210 G52 X50. Y50.
N220 G16 G0 X10. Y90.
N230 G91 Y90.
N240 G90 G15
N250 G52 X0 Y0
N260 M98 P300
N270 G0 Z50.
N280 M30
O300
N10 G0 X1. Y1.
N20 M99
%
