0 BEGIN PGM ISO230C MM
1 ;Positioning test of axis C by axcheck: ISO 230-2:1997
2 ;3 targets, 2 runs, standard cycle, overrun 5.000 deg, dwell 2.000 s, feed 1000 deg/min
3 ;Targets as the data file numbers them:
4 ;T1 = 0.000 deg
5 ;T2 = 90.000 deg
6 ;T3 = 180.000 deg
7 ;Machine coordinates: M91 in every absolute L block references that block to the machine datum
8 ;Rotary axis: after the start every move is incremental, so its sign is its direction whatever the axis's modulo or shortest-path setting
9 ;The axis is continuous, it turns freely: the start at -5.000 deg is written as its angle within one turn, 355.000 deg
10 ;Modulo, roll-over and shortest-path axes reach that angle alike; the comments give the unwrapped positions
11 ;Only axis C moves: no block changes a tool, a tool length or an offset
12 ;Check the axis address, the travel and the feed; run it once without the laser first
13 ;Not confirmed: the cycle 9 text in other dialog languages; comments after an L block; whether M91 blocks leave out the tool length on TNC 640
14 ;start at -5.000 deg
15 L C+355.000 R0 F1000.000 M91
16 ;T1 up, run 1 at 0.000 deg
17 L IC+5.000
18 CYCL DEF 9.0 DWELL TIME
19 CYCL DEF 9.1 DWELL 2.000
20 ;T2 up, run 1 at 90.000 deg
21 L IC+90.000
22 CYCL DEF 9.0 DWELL TIME
23 CYCL DEF 9.1 DWELL 2.000
24 ;T3 up, run 1 at 180.000 deg
25 L IC+90.000
26 CYCL DEF 9.0 DWELL TIME
27 CYCL DEF 9.1 DWELL 2.000
28 ;overrun at 185.000 deg
29 L IC+5.000
30 ;T3 down, run 1 at 180.000 deg
31 L IC-5.000
32 CYCL DEF 9.0 DWELL TIME
33 CYCL DEF 9.1 DWELL 2.000
34 ;T2 down, run 1 at 90.000 deg
35 L IC-90.000
36 CYCL DEF 9.0 DWELL TIME
37 CYCL DEF 9.1 DWELL 2.000
38 ;T1 down, run 1 at 0.000 deg
39 L IC-90.000
40 CYCL DEF 9.0 DWELL TIME
41 CYCL DEF 9.1 DWELL 2.000
42 ;overrun at -5.000 deg
43 L IC-5.000
44 ;T1 up, run 2 at 0.000 deg
45 L IC+5.000
46 CYCL DEF 9.0 DWELL TIME
47 CYCL DEF 9.1 DWELL 2.000
48 ;T2 up, run 2 at 90.000 deg
49 L IC+90.000
50 CYCL DEF 9.0 DWELL TIME
51 CYCL DEF 9.1 DWELL 2.000
52 ;T3 up, run 2 at 180.000 deg
53 L IC+90.000
54 CYCL DEF 9.0 DWELL TIME
55 CYCL DEF 9.1 DWELL 2.000
56 ;overrun at 185.000 deg
57 L IC+5.000
58 ;T3 down, run 2 at 180.000 deg
59 L IC-5.000
60 CYCL DEF 9.0 DWELL TIME
61 CYCL DEF 9.1 DWELL 2.000
62 ;T2 down, run 2 at 90.000 deg
63 L IC-90.000
64 CYCL DEF 9.0 DWELL TIME
65 CYCL DEF 9.1 DWELL 2.000
66 ;T1 down, run 2 at 0.000 deg
67 L IC-90.000
68 CYCL DEF 9.0 DWELL TIME
69 CYCL DEF 9.1 DWELL 2.000
70 END PGM ISO230C MM
