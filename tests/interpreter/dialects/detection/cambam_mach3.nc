( Made using CamBam - written in its style for ncbridge's tests )
( PANEL 2 )
( T1 : 3.175 )
G21 G90 G91.1 G64 G40
G0 Z3.0
( T1 : 3.175 )
T1 M6
( Profile1 )
G17
M3 S12000
G0 X10.0 Y10.0
G1 F300.0 Z-1.0
G1 F900.0 X40.0
G3 X45.0 Y15.0 I0.0 J5.0
G1 Y30.0
G0 Z3.0
M5
M30
