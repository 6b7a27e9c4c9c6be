0 BEGIN PGM ROUNDING_AND_CALLS MM
1 BLK FORM 0.1 Z X+0 Y+0 Z-20
2 BLK FORM 0.2 X+100 Y+100 Z+0
3 TOOL CALL 1 Z S3000
4 L Z+30 R0 FMAX M3
5 L X-5 Y+10 R0 FMAX
6 L Z-3 R0 F200
; corner roundings between lines and arcs: line-arc, arc-line, line-CR, CR-line
7 L X+40 Y+10 F500
8 RND R5
9 CC X+25 Y+30
10 C X+50 Y+30 DR+
11 RND R4
12 L X+40 Y+70
13 RND R3
14 CR X+10 Y+60 R+20 DR+
15 RND R2
16 L X+10 Y+30
17 L Z+30 R0 FMAX
; another program file, by a path relative to this one; its labels are its own
18 CALL PGM called\DRILL_ROW.H
19 L X+0 Y+0 R0 FMAX
; a left-hand thread: cycle 207 with a negative pitch
20 CYCL DEF 207 RIGID TAPPING NEW ~
  Q200=+2 ;SET-UP CLEARANCE ~
  Q201=-10 ;DEPTH ~
  Q239=-1 ;PITCH ~
  Q203=+0 ;SURFACE COORDINATE ~
  Q204=+0 ;2ND SET-UP CLEARANCE
21 L X+70 Y+20 R0 FMAX M99
22 L X+0 Y+0 R0 FMAX
23 END PGM ROUNDING_AND_CALLS MM
