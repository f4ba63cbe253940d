(000 HX MC manual 4.4: the end point must lie on the arc - start radius 40, end radius 50.99: alarm [PI 151 radius tolerance] - own example)
G54 G90 G00 X0. Y0. Z0.
G17 G02 X50. Y50. I40. F100.
M30
