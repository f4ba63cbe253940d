(001 PUMA training manual G98/G99 feedrate selection: "G98 G01 Z100.0 F50.0" mm/min, then per revolution - the extraction's "G97 G01 Z10.0 F0.3" read as G99; start point and spindle start added)
G00 X50.0 Z120.0
G97 S500 M03
G98 G01 Z100.0 F50.0
G99 G01 Z10.0 F0.3
M30
