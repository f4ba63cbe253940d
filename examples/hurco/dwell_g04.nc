(002 Hurco MAX turning manual G04 dwell: "G04 F2.1" = 2.1 s in G94, "G04 F10" = 10 spindle revolutions in G95 - own program around the manual's blocks)
G21 G90 G07
G00 X20 Z5
G04 F2.1
G95 S500 M03
G04 F10
G01 Z-10 F.2
M30
