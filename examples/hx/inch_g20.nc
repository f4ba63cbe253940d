(000 HX MC manual 8.4 G20 inch input, least input increment 0.0001 inch - own example)
G20 G90 G54 G00 X1. Y2. Z.5
G01 X1.5 F10.
X25000
G91 Y-5000 Z-.25
M30
