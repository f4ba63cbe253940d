(kerf - a ,C block followed by G00: the next block must be a G01/G02/G03 in the plane, alarm at the ,C word - own example)
G90 G54 G00 X0. Y0. Z0.
G01 X50. ,C5. F300.
M08
G00 Y50.
M30
