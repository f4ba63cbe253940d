(000 HX MC manual 4.3 G01 linear interpolation - example program)
G54 G00 X0. Y0. Z0.
G90 G01 X-50. F100.
Y-40.
Z-30.
G91 X50. Y40. Z30.
M30
