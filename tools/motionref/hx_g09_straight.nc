(three collinear moves, G09 on the middle one)
G90 G54 G00 X0. Y0. Z0.
G91 G94 G17 G64
G01 X-20. F3000
G09 X-20.
X-20.
M30
