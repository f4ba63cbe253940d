(quarter circle radius 100, F3000, alone)
G90 G54 G00 X0. Y0. Z0.
G91 G94 G17 G64
G03 X-100. Y-100. J-100. F3000
M30
