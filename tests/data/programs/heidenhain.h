0 BEGIN PGM ISO230X MM
1 ;Positioning test of axis X by axcheck: ISO 230-2:1997
2 ;3 targets, 2 runs, standard cycle, overrun 5.000 mm, dwell 2.000 s, feed 1000 mm/min
3 ;Targets as the data file numbers them:
4 ;T1 = 10.000 mm
5 ;T2 = 55.300 mm
6 ;T3 = 100.000 mm
7 ;Check the axis address, the travel and the feed; run it once without the laser first
8 ;Not confirmed: the cycle 9 text in other dialog languages; comments after an L block
9 ;start at 5.000 mm
10 L X+5.000 R0 F1000.000
11 ;T1 up, run 1 at 10.000 mm
12 L X+10.000
13 CYCL DEF 9.0 DWELL TIME
14 CYCL DEF 9.1 DWELL 2.000
15 ;T2 up, run 1 at 55.300 mm
16 L X+55.300
17 CYCL DEF 9.0 DWELL TIME
18 CYCL DEF 9.1 DWELL 2.000
19 ;T3 up, run 1 at 100.000 mm
20 L X+100.000
21 CYCL DEF 9.0 DWELL TIME
22 CYCL DEF 9.1 DWELL 2.000
23 ;overrun at 105.000 mm
24 L X+105.000
25 ;T3 down, run 1 at 100.000 mm
26 L X+100.000
27 CYCL DEF 9.0 DWELL TIME
28 CYCL DEF 9.1 DWELL 2.000
29 ;T2 down, run 1 at 55.300 mm
30 L X+55.300
31 CYCL DEF 9.0 DWELL TIME
32 CYCL DEF 9.1 DWELL 2.000
33 ;T1 down, run 1 at 10.000 mm
34 L X+10.000
35 CYCL DEF 9.0 DWELL TIME
36 CYCL DEF 9.1 DWELL 2.000
37 ;overrun at 5.000 mm
38 L X+5.000
39 ;T1 up, run 2 at 10.000 mm
40 L X+10.000
41 CYCL DEF 9.0 DWELL TIME
42 CYCL DEF 9.1 DWELL 2.000
43 ;T2 up, run 2 at 55.300 mm
44 L X+55.300
45 CYCL DEF 9.0 DWELL TIME
46 CYCL DEF 9.1 DWELL 2.000
47 ;T3 up, run 2 at 100.000 mm
48 L X+100.000
49 CYCL DEF 9.0 DWELL TIME
50 CYCL DEF 9.1 DWELL 2.000
51 ;overrun at 105.000 mm
52 L X+105.000
53 ;T3 down, run 2 at 100.000 mm
54 L X+100.000
55 CYCL DEF 9.0 DWELL TIME
56 CYCL DEF 9.1 DWELL 2.000
57 ;T2 down, run 2 at 55.300 mm
58 L X+55.300
59 CYCL DEF 9.0 DWELL TIME
60 CYCL DEF 9.1 DWELL 2.000
61 ;T1 down, run 2 at 10.000 mm
62 L X+10.000
63 CYCL DEF 9.0 DWELL TIME
64 CYCL DEF 9.1 DWELL 2.000
65 END PGM ISO230X MM
