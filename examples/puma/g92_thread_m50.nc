(001 G92 Example M50 x 1.5 as printed: G92 X49.4 Z-32.0 R-6.166 F1.5 then X49.0 X48.7 X48.5; the two "-" placeholder lines of the print are left out)
G30 U0 W0 ;
G50 S1000 T0100 ;
G97 S1000 M03 ;
G00 X70.0 Z5.0 T0101 M08 ;
G92 X49.4 Z-32.0 R-6.166 F1.5 ;
X49.0 ;
X48.7 ;
X48.5 ;
G30 U0 W0 ;
M30 ;
