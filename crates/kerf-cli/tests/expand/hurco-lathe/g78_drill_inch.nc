(expand test: inch program, G78 thread, a drill cycle, a G33 thread, G96 and a dwell)
G20 G90 M03 S120
G0 X2. Z.5
G01 X1.8 Z.1 F.01
X1.5 Z0
G02 X1.7 Z-.1 I0 K-.1
G0 Z4.1
G78 X.9 J.2 Z1.2 K2 F.15 D.04 E.03 P2 L.02 R3
G0 X0 Z.5
G81 Z-1. F5.
G80
G0 X1. Z.2
G33 Z-1. K.0625
G0 X1.2
G04 F1.5
M30
