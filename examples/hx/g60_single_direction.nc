(000 §4.2 G60 single direction positioning example; overrun PI 61-63 = +1.0 mm on hx-mc [values not printed, assumed])
G54 G00 X0. Y0. Z0
G90 G60 X50.
G60 Y50.
G60 Z50.
G91 G60 X-50. Y-50. Z-50.
M30
