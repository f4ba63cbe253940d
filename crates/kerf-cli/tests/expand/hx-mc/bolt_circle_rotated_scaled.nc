(expand test: WHILE loop bolt circle with G81, G83 peck, a slot rotated by G68, a square scaled by G51, G16 polar points)
G21 G17 G40 G49 G80 G90 G94
G54 G00 X0 Y0 Z50.
T1 M06
S1500 M03
M08
#1 = 6
#2 = 40.
#3 = 0
G00 Z10.
WHILE [#3 LT #1] DO1
#4 = 360. * #3 / #1 + 15.
G99 G81 X[#2 * COS[#4]] Y[#2 * SIN[#4]] Z-12. R2. F120.
#3 = #3 + 1
END1
G80
G98 G83 X0 Y0 Z-20. R2. Q4. F100.
G80
M09
M05
T2 M06
S3000 M03
(slot rotated 30 degrees about X10 Y10)
G68 X10. Y10. R30.
G00 X0 Y0
Z2.
G01 Z-3. F200.
X30.
G03 X30. Y10. R5.
G01 X0.
G03 X0. Y0. R5.
G69
G00 Z50.
(square at half size about the origin)
G51 X0 Y0 P500
G00 X-50. Y-50.
G01 Z-1. F300.
X50.
Y50.
X-50.
Y-50.
G50
G00 Z50.
(polar points, radius 60)
G16
G00 X60. Y0
X60. Y45.
X60. Y90.
G15
M30
