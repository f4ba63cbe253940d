(corner: turn of 60 deg between two 40 mm lines at F3000)
G90 G54 G00 X0. Y0. Z0.
G91 G94 G17 G64
G01 X-40. F3000
X-20.0000 Y-34.6410
M30
