% ISO230X
; Positioning test of axis X by axcheck: ISO 230-2:1997
; 3 targets, 2 runs, standard cycle, overrun 5.000 mm, dwell 2.000 s, feed 1000 mm/min
; Targets as the data file numbers them:
; T1 = 10.000 mm
; T2 = 55.300 mm
; T3 = 100.000 mm
; Work coordinates, as --coordinates work asks: every position is in the active work offset
; The compensation tables axcheck writes are in machine positions: add the active work offset of axis X to each table position
; Only axis X moves: no block changes a tool, a tool length or an offset
; Check the axis address, the travel and the feed; run it once without the laser first
; Not confirmed: not run on a control
G17 G71 G90 G94 G40
G01 X5.000 F1000.000 ; start at 5.000 mm
G01 X10.000 ; T1 up, run 1 at 10.000 mm
#TIME 2.000
G01 X55.300 ; T2 up, run 1 at 55.300 mm
#TIME 2.000
G01 X100.000 ; T3 up, run 1 at 100.000 mm
#TIME 2.000
G01 X105.000 ; overrun at 105.000 mm
G01 X100.000 ; T3 down, run 1 at 100.000 mm
#TIME 2.000
G01 X55.300 ; T2 down, run 1 at 55.300 mm
#TIME 2.000
G01 X10.000 ; T1 down, run 1 at 10.000 mm
#TIME 2.000
G01 X5.000 ; overrun at 5.000 mm
G01 X10.000 ; T1 up, run 2 at 10.000 mm
#TIME 2.000
G01 X55.300 ; T2 up, run 2 at 55.300 mm
#TIME 2.000
G01 X100.000 ; T3 up, run 2 at 100.000 mm
#TIME 2.000
G01 X105.000 ; overrun at 105.000 mm
G01 X100.000 ; T3 down, run 2 at 100.000 mm
#TIME 2.000
G01 X55.300 ; T2 down, run 2 at 55.300 mm
#TIME 2.000
G01 X10.000 ; T1 down, run 2 at 10.000 mm
#TIME 2.000
M30
