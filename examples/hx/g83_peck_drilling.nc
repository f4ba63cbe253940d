(000 §12.3.3 G83 peck drilling: decimal points added [the manual prints X75 Y50 Z-70 R5 Q6 F100, which the HX reads in 0.001 mm]; the manual's start position [G92 X0 Y0 Z100] is reached with G54 G00, not G92, because hx-mc's reference position is at the + end of travel)
G54 G90 G00 X0. Y0. Z100.
N1 S500 M03
N2 G90 G99 G83 X75. Y50. Z-70. R5. Q6. F100
N3 Y-50.
N4 X-75.
N5 G98 Y50.
N6 G80 G00 X0 Y0 M05
N7 M30
