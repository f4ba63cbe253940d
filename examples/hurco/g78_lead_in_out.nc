(002 Straight OD Thread with Lead In/Lead Out Angles: A30, C5)
G70 G90 M03 S120
G0 X4.1 Z2.5
G78 X.9 J.6 Z1.2 K2 A30 C5 F.15 D.04 E.03 P2 L.02
M30
