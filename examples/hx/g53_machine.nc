(000 HX MC manual 7.1.1 G53 machine coordinate selection - example, trimmed: N01 G40 G80 and N04 G30 are left out; numbers as printed, without decimal point: X-140 = -0.140 mm)
N02 G53 G90 X-140 Y-120 Z0
N03 G92 X0 Y0 Z150
N05 G54 G00 G90 X0 Y0
N60 M30
