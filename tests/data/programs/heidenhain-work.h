0 BEGIN PGM ISO230X MM
1 ;Positioning test of axis X by axcheck: ISO 230-2:1997
2 ;3 targets, 2 runs, standard cycle, overrun 5.000 mm, dwell 2.000 s, feed 1000 mm/min
3 ;Targets as the data file numbers them:
4 ;T1 = 10.000 mm
5 ;T2 = 55.300 mm
6 ;T3 = 100.000 mm
7 ;Work coordinates, as --coordinates work asks: every position is in the active work offset
8 ;The compensation tables axcheck writes are in machine positions: add the active work offset of axis X to each table position
9 ;Only axis X moves: no block changes a tool, a tool length or an offset
10 ;Check the axis address, the travel and the feed; run it once without the laser first
11 ;Not confirmed: the cycle 9 text in other dialog languages; comments after an L block; whether M91 blocks leave out the tool length on TNC 640
12 ;start at 5.000 mm
13 L X+5.000 R0 F1000.000
14 ;T1 up, run 1 at 10.000 mm
15 L X+10.000
16 CYCL DEF 9.0 DWELL TIME
17 CYCL DEF 9.1 DWELL 2.000
18 ;T2 up, run 1 at 55.300 mm
19 L X+55.300
20 CYCL DEF 9.0 DWELL TIME
21 CYCL DEF 9.1 DWELL 2.000
22 ;T3 up, run 1 at 100.000 mm
23 L X+100.000
24 CYCL DEF 9.0 DWELL TIME
25 CYCL DEF 9.1 DWELL 2.000
26 ;overrun at 105.000 mm
27 L X+105.000
28 ;T3 down, run 1 at 100.000 mm
29 L X+100.000
30 CYCL DEF 9.0 DWELL TIME
31 CYCL DEF 9.1 DWELL 2.000
32 ;T2 down, run 1 at 55.300 mm
33 L X+55.300
34 CYCL DEF 9.0 DWELL TIME
35 CYCL DEF 9.1 DWELL 2.000
36 ;T1 down, run 1 at 10.000 mm
37 L X+10.000
38 CYCL DEF 9.0 DWELL TIME
39 CYCL DEF 9.1 DWELL 2.000
40 ;overrun at 5.000 mm
41 L X+5.000
42 ;T1 up, run 2 at 10.000 mm
43 L X+10.000
44 CYCL DEF 9.0 DWELL TIME
45 CYCL DEF 9.1 DWELL 2.000
46 ;T2 up, run 2 at 55.300 mm
47 L X+55.300
48 CYCL DEF 9.0 DWELL TIME
49 CYCL DEF 9.1 DWELL 2.000
50 ;T3 up, run 2 at 100.000 mm
51 L X+100.000
52 CYCL DEF 9.0 DWELL TIME
53 CYCL DEF 9.1 DWELL 2.000
54 ;overrun at 105.000 mm
55 L X+105.000
56 ;T3 down, run 2 at 100.000 mm
57 L X+100.000
58 CYCL DEF 9.0 DWELL TIME
59 CYCL DEF 9.1 DWELL 2.000
60 ;T2 down, run 2 at 55.300 mm
61 L X+55.300
62 CYCL DEF 9.0 DWELL TIME
63 CYCL DEF 9.1 DWELL 2.000
64 ;T1 down, run 2 at 10.000 mm
65 L X+10.000
66 CYCL DEF 9.0 DWELL TIME
67 CYCL DEF 9.1 DWELL 2.000
68 END PGM ISO230X MM
