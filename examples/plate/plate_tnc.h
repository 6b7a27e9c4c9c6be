0 BEGIN PGM PLATE_TNC MM
1 ; ncbridge example: an 80 x 60 plate, faced, with a closed pocket and four drilled holes
2 ; program zero: lower left corner of the finished top face; stock top is 2 mm above it
3 ; --- face the top: D50 face mill, two bidirectional passes along X
4 TOOL CALL 1 Z S2400
5 L X-30 Y+15 Z+10 R0 FMAX M3 M8
6 L Z+2 R0 FMAX
7 L Z+0 R0 F300
8 L X+110 R0 F1200
9 L Y+45 R0 FMAX
10 L X-30 R0
11 L Z+10 R0 FMAX
12 ; --- closed pocket 30 x 20, 5 deep, corner radius 6: D8 end mill, two layers, contour parallel
13 TOOL CALL 2 Z S6000
14 L X+40 Y+30 Z+2 R0 FMAX M3
15 L Z-2.5 R0 F200
16 L X+45 R0 F800
17 L Y+33 R0
18 L X+35 R0
19 L Y+27 R0
20 L X+45 R0
21 L Y+30 R0
22 ; finish contour: pocket 30 x 20 with corner radius 6, tool radius 4
23 L X+51 R0
24 L Y+34 R0
25 CC X+49 Y+34
26 C X+49 Y+36 DR+
27 L X+31 R0
28 CC X+31 Y+34
29 C X+29 Y+34 DR+
30 L Y+26 R0
31 CC X+31 Y+26
32 C X+31 Y+24 DR+
33 L X+49 R0
34 CC X+49 Y+26
35 C X+51 Y+26 DR+
36 L Y+30 R0
37 L Z+5 R0 FMAX
38 L X+40 Z+2 R0 FMAX
39 L Z-5 R0 F200
40 L X+45 R0 F800
41 L Y+33 R0
42 L X+35 R0
43 L Y+27 R0
44 L X+45 R0
45 L Y+30 R0
46 ; finish contour: pocket 30 x 20 with corner radius 6, tool radius 4
47 L X+51 R0
48 L Y+34 R0
49 CC X+49 Y+34
50 C X+49 Y+36 DR+
51 L X+31 R0
52 CC X+31 Y+34
53 C X+29 Y+34 DR+
54 L Y+26 R0
55 CC X+31 Y+26
56 C X+31 Y+24 DR+
57 L X+49 R0
58 CC X+49 Y+26
59 C X+51 Y+26 DR+
60 L Y+30 R0
61 L Z+5 R0 FMAX
62 ; --- four through holes D6: drill, retract to R between holes
63 TOOL CALL 3 Z S1800
64 L X+10 Y+10 Z+10 R0 FMAX M3
65 CYCL DEF 200 DRILLING ~
  Q200=+0 ;SET-UP CLEARANCE ~
  Q201=-24 ;DEPTH ~
  Q206=+150 ;FEED RATE FOR PLUNGING ~
  Q202=+24 ;PLUNGING DEPTH ~
  Q210=+0 ;DWELL TIME AT TOP ~
  Q203=+2 ;SURFACE COORDINATE ~
  Q204=+0 ;2ND SET-UP CLEARANCE ~
  Q211=+0 ;DWELL TIME AT DEPTH
66 CYCL CALL
67 L X+70 Y+10 R0 FMAX M99
68 L X+70 Y+50 R0 FMAX M99
69 L X+10 Y+50 R0 FMAX M99
70 L Z+30 R0 FMAX
71 END PGM PLATE_TNC MM
