%
O0310 (FANUC G31 SKIP: PROBE THE TOP, SET Z FROM IT, PROBE A SIDE, THEN CUT)
N10 G17 G21 G40 G49 G80 G90 G94 G54
N20 T1 M6
N30 G0 X20. Y20. Z30.
(G31 moves until the skip signal; the skip position comes back in #5061-#5063)
N40 G31 Z-20. F150.
#100=#5063
N50 G0 Z[#100+10.]
(incremental skip along X; one-shot: the next block moves in G0 again)
N60 G91 G31 X-30. F100.
#101=#5061
N70 G90 X[#101+5.] Z[#100+10.]
N80 S2000 M3
N90 G0 X0 Y0
N100 G1 Z[#100-1.] F300.
N110 X40.
N120 Y40.
N130 G0 Z30.
N140 M30
%
