(000 HX MC manual 11.1 M codes: M00 program stop, M01 optional stop, M02 program end - own example; a batch run continues past M00/M01 and ends at M02)
G54 G90 G00 X0. Y0. Z10.
M00
G01 X20. F300.
M01
Y20.
M02
G00 X100.
