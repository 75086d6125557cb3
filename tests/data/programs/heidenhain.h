0 BEGIN PGM ISO230X MM
1 ;Positioning test of axis X by axcheck: ISO 230-2:1997
2 ;3 targets, 2 runs, standard cycle, overrun 5.000 mm, dwell 2.000 s, feed 1000 mm/min
3 ;Targets as the data file numbers them:
4 ;T1 = 10.000 mm
5 ;T2 = 55.300 mm
6 ;T3 = 100.000 mm
7 ;Machine coordinates: M91 in every absolute L block references that block to the machine datum
8 ;Only axis X moves: no block changes a tool, a tool length or an offset
9 ;Check the axis address, the travel and the feed; run it once without the laser first
10 ;Not confirmed: the cycle 9 text in other dialog languages; comments after an L block; whether M91 blocks leave out the tool length on TNC 640
11 ;start at 5.000 mm
12 L X+5.000 R0 F1000.000 M91
13 ;T1 up, run 1 at 10.000 mm
14 L X+10.000 M91
15 CYCL DEF 9.0 DWELL TIME
16 CYCL DEF 9.1 DWELL 2.000
17 ;T2 up, run 1 at 55.300 mm
18 L X+55.300 M91
19 CYCL DEF 9.0 DWELL TIME
20 CYCL DEF 9.1 DWELL 2.000
21 ;T3 up, run 1 at 100.000 mm
22 L X+100.000 M91
23 CYCL DEF 9.0 DWELL TIME
24 CYCL DEF 9.1 DWELL 2.000
25 ;overrun at 105.000 mm
26 L X+105.000 M91
27 ;T3 down, run 1 at 100.000 mm
28 L X+100.000 M91
29 CYCL DEF 9.0 DWELL TIME
30 CYCL DEF 9.1 DWELL 2.000
31 ;T2 down, run 1 at 55.300 mm
32 L X+55.300 M91
33 CYCL DEF 9.0 DWELL TIME
34 CYCL DEF 9.1 DWELL 2.000
35 ;T1 down, run 1 at 10.000 mm
36 L X+10.000 M91
37 CYCL DEF 9.0 DWELL TIME
38 CYCL DEF 9.1 DWELL 2.000
39 ;overrun at 5.000 mm
40 L X+5.000 M91
41 ;T1 up, run 2 at 10.000 mm
42 L X+10.000 M91
43 CYCL DEF 9.0 DWELL TIME
44 CYCL DEF 9.1 DWELL 2.000
45 ;T2 up, run 2 at 55.300 mm
46 L X+55.300 M91
47 CYCL DEF 9.0 DWELL TIME
48 CYCL DEF 9.1 DWELL 2.000
49 ;T3 up, run 2 at 100.000 mm
50 L X+100.000 M91
51 CYCL DEF 9.0 DWELL TIME
52 CYCL DEF 9.1 DWELL 2.000
53 ;overrun at 105.000 mm
54 L X+105.000 M91
55 ;T3 down, run 2 at 100.000 mm
56 L X+100.000 M91
57 CYCL DEF 9.0 DWELL TIME
58 CYCL DEF 9.1 DWELL 2.000
59 ;T2 down, run 2 at 55.300 mm
60 L X+55.300 M91
61 CYCL DEF 9.0 DWELL TIME
62 CYCL DEF 9.1 DWELL 2.000
63 ;T1 down, run 2 at 10.000 mm
64 L X+10.000 M91
65 CYCL DEF 9.0 DWELL TIME
66 CYCL DEF 9.1 DWELL 2.000
67 END PGM ISO230X MM
