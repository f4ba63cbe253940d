(002 Hurco MAX turning manual G53 program machine coordinates: one block ignores work, tool and fixture offsets - own example)
G21 G90 G07
G00 X100 Z50
G53 X200 Z-100
X100 Z50
M30
