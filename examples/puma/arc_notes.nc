(001 PUMA training manual p.15 notes on G02/G03: note 5 - I, K and R in one block, R is effective; note 2 - G02 I_ makes a full circle; note 4 - R less than half the move, the control makes a half circle - own program)
G97 S800 M03
G00 X20.0 Z2.0
G01 Z-10.0 F0.2
G03 X40.0 Z-20.0 I20.0 K5.0 R10.0
G02 I-5.0
G02 X60.0 Z-20.0 R3.0
G00 X100.0 Z10.0
M30
