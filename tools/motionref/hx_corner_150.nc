(corner: turn of 150 deg between two 40 mm lines at F3000)
G90 G54 G00 X0. Y0. Z0.
G91 G94 G17 G64
G01 X-40. F3000
X34.6410 Y-20.0000
M30
