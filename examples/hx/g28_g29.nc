(000 6.3: G28 to the reference position via X30. Y50. Z10., G29 back through it)
G90 G54 X0. Y0. Z0.
G28 X30. Y50. Z10.
G29 X0. Y0. Z0.
M30
