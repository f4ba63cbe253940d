(000 6.2: G30 P2/P3/P4 return to the 2nd, 3rd and 4th reference positions)
G90 G54 X0. Y0. Z0.
G30 P2 X30. Y50. Z10.
G30 P3 X0.
G30 P4 Y0.
M30
