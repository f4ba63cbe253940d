(square 50 mm, G61 exact stop mode)
G90 G54 G00 X0. Y0. Z0.
G91 G94 G17 G61
G01 X-50. F3000
Y-50.
X50.
Y50.
M30
