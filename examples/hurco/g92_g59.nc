(002 Hurco MAX turning manual G92 work coordinate offsets [sets the program coordinates at the current position, no motion] and G59 cancel work coordinate offsets - own example)
N10 G21 G90 G07
N20 G00 X50 Z100
N30 G92 X0 Z0
N40 G01 X10 Z-10 F200
N50 G59
N60 G00 X50 Z100
N70 M30
