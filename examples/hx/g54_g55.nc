(000 HX MC manual 7.2.2 G54-G59 work coordinate systems - example 1; numbers as printed, without decimal point: X30 = 0.030 mm)
G90 G54 G00 X30 Y15
G55 X-30 Y-15
M30
