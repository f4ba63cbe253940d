(000 §12.3.2 G82 drilling with dwell: decimal points added [the manual prints X75 Y50 Z-50 R5 P500 F100, which the HX reads in 0.001 mm]; the manual's start position [G92 X0 Y0 Z100] is reached with G54 G00, not G92, because hx-mc's reference position is at the + end of travel)
(N2 is printed 'GO0 G99 G82': read as G90, as in every other example of the chapter [G00 with a cycle code in one block is an alarm])
G54 G90 G00 X0. Y0. Z100.
N1 S600 M03
N2 G90 G99 G82 X75. Y50. Z-50. R5. P500 F100
N3 Y-50.
N4 X-75.
N5 G98 Y50.
N6 G80 G00 X0 Y0 M05
N7 M30
