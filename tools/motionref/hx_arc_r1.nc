(half circle radius 1, F3000, alone)
G90 G54 G00 X0. Y0. Z0.
G91 G94 G17 G64
G02 X-2. I-1. F3000
M30
