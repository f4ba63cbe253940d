(full circles of radius 1, 10, 100 at F3000, each after a lead-in line)
G90 G54 G00 X0. Y0. Z0.
G91 G94 G17 G64
G01 X-10. F3000
G02 I-1.
G01 Y-20.
G02 I-10.
G01 Y-20.
G03 J-100.
M30
