(expand test: a macro from the library folder called twice with G65, incremental moves inside it, the per-revolution feed G95 and exact stop modes)
G21 G17 G40 G49 G80 G90 G94
G54 G00 X0 Y0 Z50.
S1000 M03
G65 P9110 X10. Y10. I20. J15. Z-2. F300.
G61
G65 P9110 X50. Y10. I10. J10. Z-3. F200.
G64
G95 G01 X0 Y0 F0.1
G94 G09 G01 X5. F500.
G04 P250
M05
M30
