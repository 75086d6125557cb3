% ISO230C
; Positioning test of axis C by axcheck: ISO 230-2:1997
; 3 targets, 2 runs, standard cycle, overrun 5.000 deg, dwell 2.000 s, feed 1000 deg/min
; Targets as the data file numbers them:
; T1 = 0.000 deg
; T2 = 90.000 deg
; T3 = 180.000 deg
; Machine coordinates: #SUPPRESS OFFSETS in every absolute move suppresses the zero, G92, preset, clamping, tool, measuring and manual offsets for that block
; It moves at the G01 feed set before it
; Rotary axis: after the first move every move is incremental, so its sign is its direction whatever the axis's modulo or shortest-path setting
; The axis is continuous, it turns freely: the first move goes to 0.000 deg, an angle within one turn, where an axis that counts turns and a modulo, roll-over or shortest-path axis agree; the start follows incrementally
; The comments give the positions as the data file numbers the targets
; Only axis C moves: no block changes a tool, a tool length or an offset
; Check the axis address, the travel and the feed; run it once without the laser first
; Not confirmed: #SUPPRESS OFFSETS with a multi-letter axis name and after a G01 F block of its own; not run on a control
G17 G71 G90 G94 G40
G01 F1000.000
#SUPPRESS OFFSETS C0.000 ; align at 0.000 deg
G91
G01 C-5.000 ; start at -5.000 deg
G01 C5.000 ; T1 up, run 1 at 0.000 deg
#TIME 2.000
G01 C90.000 ; T2 up, run 1 at 90.000 deg
#TIME 2.000
G01 C90.000 ; T3 up, run 1 at 180.000 deg
#TIME 2.000
G01 C5.000 ; overrun at 185.000 deg
G01 C-5.000 ; T3 down, run 1 at 180.000 deg
#TIME 2.000
G01 C-90.000 ; T2 down, run 1 at 90.000 deg
#TIME 2.000
G01 C-90.000 ; T1 down, run 1 at 0.000 deg
#TIME 2.000
G01 C-5.000 ; overrun at -5.000 deg
G01 C5.000 ; T1 up, run 2 at 0.000 deg
#TIME 2.000
G01 C90.000 ; T2 up, run 2 at 90.000 deg
#TIME 2.000
G01 C90.000 ; T3 up, run 2 at 180.000 deg
#TIME 2.000
G01 C5.000 ; overrun at 185.000 deg
G01 C-5.000 ; T3 down, run 2 at 180.000 deg
#TIME 2.000
G01 C-90.000 ; T2 down, run 2 at 90.000 deg
#TIME 2.000
G01 C-90.000 ; T1 down, run 2 at 0.000 deg
#TIME 2.000
G90
M30
