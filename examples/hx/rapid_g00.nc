(000 HX MC manual 4.1 G00 rapid traverse positioning - example program)
G90 G54 G00 X0. Y0. Z0.
X100. Y50.
Y100.
Z100.
G91 X-100.
Y-100.
Z-100.
M30
