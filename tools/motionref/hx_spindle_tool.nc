(spindle, tool change, coolant around a few moves)
G90 G54 G17 G94
T2 M06
S3000 M03
M08
G00 X10. Y10. Z5.
G01 Z-2. F300
G01 X60. F1500
S5000
G01 Y60.
M09
M05
M30
