(001 PUMA training manual p.8 G00 positioning - the page's absolute and incremental blocks from the figure's start point X0 Z0; the first line of each half moves there)
G00 X0 Z0
G00 X150.0 Z100.0
X200.0 Z200.0
G00 X0 Z0
G00 U150.0 W100.0
U50.0 W100.0
N1234 G00 X25. Z5.
M30
