(000 HX MC manual 7.2.1 G92 work coordinate setting - example, trimmed: N01 G40 G80, N02 G28 and N04 G30 are left out; the program starts at the reference position where N02 G28 would put it; numbers as printed: X140 = 0.140 mm)
N03 G92 G90 X140 Y120 Z150
N05 G00 G90 X0 Y0
N60 M30
