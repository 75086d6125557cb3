% ISO230TEST
; Positioning test of axis X by axcheck: ISO 230-2:1997
; 5 targets, 2 runs, standard cycle, overrun 4.000 mm, dwell 2.500 s, feed 1500 mm/min
; Targets as the data file numbers them:
; T1 = -192.000 mm
; T2 = 75.092 mm
; T3 = 301.276 mm
; T4 = 534.100 mm
; T5 = 792.000 mm
; Check the axis address, the travel and the feed; run it once without the laser first
; Not confirmed: G53 as no zero offset depends on P-ZERO-00001; not run on a control
G17 G71 G90 G94 G40 G53
G01 X-196.000 F1500.000 ; start at -196.000 mm
G01 X-192.000 ; T1 up, run 1 at -192.000 mm
#TIME 2.500
G01 X75.092 ; T2 up, run 1 at 75.092 mm
#TIME 2.500
G01 X301.276 ; T3 up, run 1 at 301.276 mm
#TIME 2.500
G01 X534.100 ; T4 up, run 1 at 534.100 mm
#TIME 2.500
G01 X792.000 ; T5 up, run 1 at 792.000 mm
#TIME 2.500
G01 X796.000 ; overrun at 796.000 mm
G01 X792.000 ; T5 down, run 1 at 792.000 mm
#TIME 2.500
G01 X534.100 ; T4 down, run 1 at 534.100 mm
#TIME 2.500
G01 X301.276 ; T3 down, run 1 at 301.276 mm
#TIME 2.500
G01 X75.092 ; T2 down, run 1 at 75.092 mm
#TIME 2.500
G01 X-192.000 ; T1 down, run 1 at -192.000 mm
#TIME 2.500
G01 X-196.000 ; overrun at -196.000 mm
G01 X-192.000 ; T1 up, run 2 at -192.000 mm
#TIME 2.500
G01 X75.092 ; T2 up, run 2 at 75.092 mm
#TIME 2.500
G01 X301.276 ; T3 up, run 2 at 301.276 mm
#TIME 2.500
G01 X534.100 ; T4 up, run 2 at 534.100 mm
#TIME 2.500
G01 X792.000 ; T5 up, run 2 at 792.000 mm
#TIME 2.500
G01 X796.000 ; overrun at 796.000 mm
G01 X792.000 ; T5 down, run 2 at 792.000 mm
#TIME 2.500
G01 X534.100 ; T4 down, run 2 at 534.100 mm
#TIME 2.500
G01 X301.276 ; T3 down, run 2 at 301.276 mm
#TIME 2.500
G01 X75.092 ; T2 down, run 2 at 75.092 mm
#TIME 2.500
G01 X-192.000 ; T1 down, run 2 at -192.000 mm
#TIME 2.500
M30
