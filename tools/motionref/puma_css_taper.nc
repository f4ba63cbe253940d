(PUMA G96 taper in 5 blocks, feed per rev: the spindle follows X)
G50 S2000
G00 X40. Z2.
G96 S150 M03
G99
G01 Z0. F0.15
X50. Z-5.
X60. Z-10.
X70. Z-15.
X80. Z-20.
X90. Z-25.
G00 X120.
M30
