(000 HX MC manual 6.4 G27 reference position return check - example program as printed; the text around it is lost, the standard G27 applies: rapid to the point, then check it is the reference position)
G90 G54 X0. Y0. Z0.
G27 X100. Y100.
G27 X10.
M30
