(kerf - ,R from a line into an arc and ,C from that arc into a line, chained on one arc; I/J read from the virtual corner - own example)
G90 G54 G17 G00 X0. Y0. Z0.
G01 X10. ,R2. F200.
G02 X20. Y10. I10. ,C2. F150.
G01 Y30.
M30
