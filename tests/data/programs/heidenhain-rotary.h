0 BEGIN PGM ISO230C MM
1 ;Positioning test of axis C by axcheck: ISO 230-2:1997
2 ;3 targets, 2 runs, standard cycle, overrun 5.000 deg, dwell 2.000 s, feed 1000 deg/min
3 ;Targets as the data file numbers them:
4 ;T1 = 0.000 deg
5 ;T2 = 90.000 deg
6 ;T3 = 180.000 deg
7 ;Machine coordinates: M91 in every absolute L block references that block to the machine datum
8 ;Rotary axis: after the start every move is incremental, so its sign is its direction whatever the axis's modulo or shortest-path setting
9 ;The axis is continuous, it turns freely: the start at -5.000 deg is written as its angle within one turn, 355.000 deg, which modulo, roll-over and shortest-path axes reach alike; the comments give the unwrapped positions
10 ;Only axis C moves: no block changes a tool, a tool length or an offset
11 ;Check the axis address, the travel and the feed; run it once without the laser first
12 ;Not confirmed: the cycle 9 text in other dialog languages; comments after an L block; whether M91 blocks leave out the tool length on TNC 640
13 ;start at -5.000 deg
14 L C+355.000 R0 F1000.000 M91
15 ;T1 up, run 1 at 0.000 deg
16 L IC+5.000
17 CYCL DEF 9.0 DWELL TIME
18 CYCL DEF 9.1 DWELL 2.000
19 ;T2 up, run 1 at 90.000 deg
20 L IC+90.000
21 CYCL DEF 9.0 DWELL TIME
22 CYCL DEF 9.1 DWELL 2.000
23 ;T3 up, run 1 at 180.000 deg
24 L IC+90.000
25 CYCL DEF 9.0 DWELL TIME
26 CYCL DEF 9.1 DWELL 2.000
27 ;overrun at 185.000 deg
28 L IC+5.000
29 ;T3 down, run 1 at 180.000 deg
30 L IC-5.000
31 CYCL DEF 9.0 DWELL TIME
32 CYCL DEF 9.1 DWELL 2.000
33 ;T2 down, run 1 at 90.000 deg
34 L IC-90.000
35 CYCL DEF 9.0 DWELL TIME
36 CYCL DEF 9.1 DWELL 2.000
37 ;T1 down, run 1 at 0.000 deg
38 L IC-90.000
39 CYCL DEF 9.0 DWELL TIME
40 CYCL DEF 9.1 DWELL 2.000
41 ;overrun at -5.000 deg
42 L IC-5.000
43 ;T1 up, run 2 at 0.000 deg
44 L IC+5.000
45 CYCL DEF 9.0 DWELL TIME
46 CYCL DEF 9.1 DWELL 2.000
47 ;T2 up, run 2 at 90.000 deg
48 L IC+90.000
49 CYCL DEF 9.0 DWELL TIME
50 CYCL DEF 9.1 DWELL 2.000
51 ;T3 up, run 2 at 180.000 deg
52 L IC+90.000
53 CYCL DEF 9.0 DWELL TIME
54 CYCL DEF 9.1 DWELL 2.000
55 ;overrun at 185.000 deg
56 L IC+5.000
57 ;T3 down, run 2 at 180.000 deg
58 L IC-5.000
59 CYCL DEF 9.0 DWELL TIME
60 CYCL DEF 9.1 DWELL 2.000
61 ;T2 down, run 2 at 90.000 deg
62 L IC-90.000
63 CYCL DEF 9.0 DWELL TIME
64 CYCL DEF 9.1 DWELL 2.000
65 ;T1 down, run 2 at 0.000 deg
66 L IC-90.000
67 CYCL DEF 9.0 DWELL TIME
68 CYCL DEF 9.1 DWELL 2.000
69 END PGM ISO230C MM
