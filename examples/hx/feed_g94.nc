(000 HX MC manual 5.2.1 G94 feed per minute - example program)
G54 G00 X0. Y0. Z0.
G94 G01 X100. F500.
M30
