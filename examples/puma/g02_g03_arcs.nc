(001 PUMA training manual p.14-15 G02/G03 circular interpolation: X/Z or U/W end point, I/K radius values from the start point, or R - own program for the page's shoulder figure)
G97 S800 M03
G00 X20.0 Z2.0
G01 Z-25.0 F0.2
G02 X30.0 W-5.0 R5.0
G01 X40.0
G03 X50.0 Z-35.0 I0 K-5.0
G01 Z-60.0
G02 U10.0 W-5.0 I5.0
G00 X100.0 Z10.0
M30
