(rapids: HX non-linear positioning, each axis its own rate)
G90 G54 G17
G00 X100. Y50. Z100.
G00 X-200. Y-100. Z20.
G00 X-200.5
G91 G00 Z-3. Y-100.
M30
