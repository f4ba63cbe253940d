(000 HX MC manual 5.4 G04 dwell - example program, trimmed: the G95 / #3120 macro part after X20. is left out)
G54 G00 X0. Y0. Z0.
G94 G01 X10. F500.
G04 X3
X20.
M30
