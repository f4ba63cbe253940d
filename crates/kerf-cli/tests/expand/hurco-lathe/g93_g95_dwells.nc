(expand test: inverse time G93, per revolution G95, a dwell in revolutions and one in seconds)
G21 G90 M03 S500
G0 X50. Z5.
G93 G01 X40. Z0 F20.
X30. Z-10. F10.
G94 G01 X50. F100.
G95 G01 Z-20. F0.2
G04 F2.
G94 G04 F1.
M30
