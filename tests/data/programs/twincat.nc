% ISO230X
; Positioning test of axis X by axcheck: ISO 230-2:1997
; 3 targets, 2 runs, standard cycle, overrun 5.000 mm, dwell 2.000 s, feed 1000 mm/min
; Targets as the data file numbers them:
; T1 = 10.000 mm
; T2 = 55.300 mm
; T3 = 100.000 mm
; Machine coordinates: #SUPPRESS OFFSETS in every absolute move suppresses the zero, G92, preset, clamping, tool, measuring and manual offsets for that block
; It moves at the G01 feed set before it
; Only axis X moves: no block changes a tool, a tool length or an offset
; Check the axis address, the travel and the feed; run it once without the laser first
; Not confirmed: #SUPPRESS OFFSETS with a multi-letter axis name and after a G01 F block of its own; not run on a control
G17 G71 G90 G94 G40
G01 F1000.000
#SUPPRESS OFFSETS X5.000 ; start at 5.000 mm
#SUPPRESS OFFSETS X10.000 ; T1 up, run 1 at 10.000 mm
#TIME 2.000
#SUPPRESS OFFSETS X55.300 ; T2 up, run 1 at 55.300 mm
#TIME 2.000
#SUPPRESS OFFSETS X100.000 ; T3 up, run 1 at 100.000 mm
#TIME 2.000
#SUPPRESS OFFSETS X105.000 ; overrun at 105.000 mm
#SUPPRESS OFFSETS X100.000 ; T3 down, run 1 at 100.000 mm
#TIME 2.000
#SUPPRESS OFFSETS X55.300 ; T2 down, run 1 at 55.300 mm
#TIME 2.000
#SUPPRESS OFFSETS X10.000 ; T1 down, run 1 at 10.000 mm
#TIME 2.000
#SUPPRESS OFFSETS X5.000 ; overrun at 5.000 mm
#SUPPRESS OFFSETS X10.000 ; T1 up, run 2 at 10.000 mm
#TIME 2.000
#SUPPRESS OFFSETS X55.300 ; T2 up, run 2 at 55.300 mm
#TIME 2.000
#SUPPRESS OFFSETS X100.000 ; T3 up, run 2 at 100.000 mm
#TIME 2.000
#SUPPRESS OFFSETS X105.000 ; overrun at 105.000 mm
#SUPPRESS OFFSETS X100.000 ; T3 down, run 2 at 100.000 mm
#TIME 2.000
#SUPPRESS OFFSETS X55.300 ; T2 down, run 2 at 55.300 mm
#TIME 2.000
#SUPPRESS OFFSETS X10.000 ; T1 down, run 2 at 10.000 mm
#TIME 2.000
M30
