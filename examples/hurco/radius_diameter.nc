(002 Hurco MAX turning manual G07/G08 radius/diameter programming, Table 4: X end points follow G07/G08, I K R are always radius values - own example)
G21 G90 G08
G00 X100 Z5
G01 Z-20 F150
G07 X60
G08 X100 Z-30
G07 G02 X60 Z-40 I10 K0
G08 G03 X140 Z-50 I0 K-10
G00 X200 Z5
M30
