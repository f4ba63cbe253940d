(002 Straight OD Thread sample: variable depth per pass, two finish passes of .02, three spring passes)
G70 G90 M03 S120
G0 Z4.1
G78 X.9 J.2 Z1.2 K2 F.15 D.04 E.03 P2 L.02 R3
M30
