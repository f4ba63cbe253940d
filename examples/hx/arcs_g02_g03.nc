(000 HX MC manual 4.4 G02/G03 circular interpolation - example program: XY, ZX, YZ planes, R+/R-, full circles)
G54 G00 X0. Y0. Z0.
(XY plane)
G90 G17 G02 X50. Y50. I50. F100.
G03 X0. Y0. R-50.
G91 G03 X100. Y100. J100.
G02 X-100. Y-100. R-100.
(ZX plane)
G90 G18 G02 Z50. X50. K50. F200.
G03 Z0. X0. R-50.
G91 G03 Z100. X100. I100.
G02 Z-100. X-100. R-100.
(YZ plane)
G90 G19 G02 Y50. Z50. J50. F300.
G03 Y0. Z0. R-50.
G91 G03 Y100. Z100. K100.
G02 Y-100. Z-100. R-100.
(full circles - still G91)
G17 G02 I50.
G03 J50.
G02 I50. J50.
M30
