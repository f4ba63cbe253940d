(000 HX MC manual 8.1 G90 absolute "G90 X10. Y30. Z20." [extraction reads Z220.] followed by 8.2 G91 incremental "G91 X40. Y-30. Z-10.")
G54 G00 G90 X10. Y30. Z20.
G91 X40. Y-30. Z-10.
M30
