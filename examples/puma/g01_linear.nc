(001 PUMA training manual p.9 G01 linear interpolation - the page's blocks; moves to the figure's start point X0 Z0 and a spindle start added for the feed per revolution)
G00 X0 Z0
G97 S500 M03
G01 X150.0 Z100.0 F0.2
X200.0 Z200.0
G00 X0 Z0
G01 U150.0 W100.0 F0.2
U50.0 W100.0
N1234 G01 X25. Z-30. F0.2
M30
