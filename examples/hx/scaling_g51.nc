(000 HX MC manual 15.2.2 G51 with I J K - the example as printed; the factors are 1/1000 with the decimal point: I2000. = x2, J1000. = x1)
G90 G00 X0. Y100.
G51 X0. Y0. Z0. I2000. J1000.
G02 X100. Y0. R100. F500.
G50
M30
