(000 HX MC manual 2.4.3 call and return of a sub-program - example program)
O0001
G54 G00 X0. Y0. Z0.
X20. Y40.
M98 P10 Q1 R2 L2
X70. Y20.
M98 P10
G91 G28 X0. Y0. M05
M30

O0010
N1 G90 G00 Z5.
G01 Z-10. F20.
Z-25. F100
N2 G00 Z50.
M99
