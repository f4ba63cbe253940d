(000 HX MC manual 2.4.4 repeat of the main program - example program)
G54 G00 X0. Y0. Z0.
N1 G91 G01 Z5. F500.
X100.
Y100.
X-100.
Y-100.
M99 P1 L3
M30
