(000 §12.3.5 G84 tapping, M6 x 1 tap at S640: F640: decimal points added [the manual prints X75 Y50 Z-15 R10 F640, which the HX reads in 0.001 mm]; the manual's start position [G92 X0 Y0 Z100] is reached with G54 G00, not G92, because hx-mc's reference position is at the + end of travel)
G54 G90 G00 X0. Y0. Z100.
N1 S640 M03
N2 G90 G99 G84 X75. Y50. Z-15. R10. F640
N3 Y-50.
N4 X-75.
N5 G98 Y50.
N6 G80 G00 X0 Y0 M05
N7 M30
