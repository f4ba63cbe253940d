(Fanuc 10/11 tape format one-block G71, as real lathe programs write it: D is the depth of cut. docs/dialects.md section 3)
G18 G21 G40 G80 G99
G54 G00 X70. Z2.
G97 S500 M03
G71 P1 Q2 D2. F0.3
N1 G01 X60.
N2 Z-10.
G53 G00 X330. Z0.
M30
