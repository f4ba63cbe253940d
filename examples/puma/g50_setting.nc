(001 PUMA training manual p.95 O3334 "when not using TOOL MEASURE": G50 coordinate setting; the extraction reads "G50 T100. Z100.", taken as X100. Z100.; G96 S170 replaced by G97 S500 and the moves after it are own)
O3334
N1 G50 X100. Z100. T0100 S1800 M42
G97 S500 M03
G00 X50. Z5.
G01 Z-20. F0.2
U10. W-5.
G00 X100. Z100.
M30
