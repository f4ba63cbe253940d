(kerf showcase - small mill part on the TurboTek HX: outside contour with I/J and R arcs, a helical entry into a round pocket, dwell - own example)
O1000
G21 G17 G90 G54 G94
S3000 M03
G00 X0. Y-10. Z10.
Z2.
G01 Z-2. F150.
Y0. F400.
X40.
G03 X50. Y10. I0. J10.
G01 Y30.
G03 X40. Y40. R10.
G01 X20.
G02 X10. Y50. I0. J10.
G01 X0.
G03 X-10. Y40. R10.
G01 Y10.
G03 X0. Y0. R10.
G04 P500
G00 Z2.
X15. Y20.
G01 Z0. F150.
G02 X15. Y20. Z-3. I10. J0. F300.
G02 I10.
G04 X0.5
G00 Z10.
M05
X0. Y-10.
M30
