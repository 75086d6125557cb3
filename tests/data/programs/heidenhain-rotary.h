0 BEGIN PGM ISO230C MM
1 ;Positioning test of axis C by axcheck: ISO 230-2:1997
2 ;3 targets, 2 runs, standard cycle, overrun 5.000 deg, dwell 2.000 s, feed 1000 deg/min
3 ;Targets as the data file numbers them:
4 ;T1 = 0.000 deg
5 ;T2 = 90.000 deg
6 ;T3 = 180.000 deg
7 ;Machine coordinates: M91 in every absolute L block references that block to the machine datum
8 ;Rotary axis: after the first move every move is incremental, so its sign is its direction whatever the axis's modulo or shortest-path setting
9 ;The axis is continuous, it turns freely: the first move goes to 0.000 deg, an angle within one turn, where an axis that counts turns and a modulo, roll-over or shortest-path axis agree; the start follows incrementally
10 ;The comments give the positions as the data file numbers the targets
11 ;Only axis C moves: no block changes a tool, a tool length or an offset
12 ;Check the axis address, the travel and the feed; run it once without the laser first
13 ;Not confirmed: the cycle 9 text in other dialog languages; comments after an L block; whether M91 blocks leave out the tool length on TNC 640
14 ;align at 0.000 deg
15 L C+0.000 R0 F1000.000 M91
16 ;start at -5.000 deg
17 L IC-5.000
18 ;T1 up, run 1 at 0.000 deg
19 L IC+5.000
20 CYCL DEF 9.0 DWELL TIME
21 CYCL DEF 9.1 DWELL 2.000
22 ;T2 up, run 1 at 90.000 deg
23 L IC+90.000
24 CYCL DEF 9.0 DWELL TIME
25 CYCL DEF 9.1 DWELL 2.000
26 ;T3 up, run 1 at 180.000 deg
27 L IC+90.000
28 CYCL DEF 9.0 DWELL TIME
29 CYCL DEF 9.1 DWELL 2.000
30 ;overrun at 185.000 deg
31 L IC+5.000
32 ;T3 down, run 1 at 180.000 deg
33 L IC-5.000
34 CYCL DEF 9.0 DWELL TIME
35 CYCL DEF 9.1 DWELL 2.000
36 ;T2 down, run 1 at 90.000 deg
37 L IC-90.000
38 CYCL DEF 9.0 DWELL TIME
39 CYCL DEF 9.1 DWELL 2.000
40 ;T1 down, run 1 at 0.000 deg
41 L IC-90.000
42 CYCL DEF 9.0 DWELL TIME
43 CYCL DEF 9.1 DWELL 2.000
44 ;overrun at -5.000 deg
45 L IC-5.000
46 ;T1 up, run 2 at 0.000 deg
47 L IC+5.000
48 CYCL DEF 9.0 DWELL TIME
49 CYCL DEF 9.1 DWELL 2.000
50 ;T2 up, run 2 at 90.000 deg
51 L IC+90.000
52 CYCL DEF 9.0 DWELL TIME
53 CYCL DEF 9.1 DWELL 2.000
54 ;T3 up, run 2 at 180.000 deg
55 L IC+90.000
56 CYCL DEF 9.0 DWELL TIME
57 CYCL DEF 9.1 DWELL 2.000
58 ;overrun at 185.000 deg
59 L IC+5.000
60 ;T3 down, run 2 at 180.000 deg
61 L IC-5.000
62 CYCL DEF 9.0 DWELL TIME
63 CYCL DEF 9.1 DWELL 2.000
64 ;T2 down, run 2 at 90.000 deg
65 L IC-90.000
66 CYCL DEF 9.0 DWELL TIME
67 CYCL DEF 9.1 DWELL 2.000
68 ;T1 down, run 2 at 0.000 deg
69 L IC-90.000
70 CYCL DEF 9.0 DWELL TIME
71 CYCL DEF 9.1 DWELL 2.000
72 END PGM ISO230C MM
