(000 HX MC manual 12.3.1 G81 drilling, G99 then G98 at N5 - example program as printed: no decimal points, so X75 is 0.075 mm, R5 0.005 mm, Z-15 -0.015 mm [F100 is mm/min])
(the start "G92 X0 Y0 Z100" is printed in parentheses: a comment; OCR fixes YO -> Y0, MO3 -> M03, MOS -> M05; g81_drilling.nc is the same program with decimal points)
(G92 X0 Y0 Z100 ;)
N1 S500 M03 ;
N2 G90 G99 G81 X75 Y50 Z-15 R5 F100 ;
N3 Y-50 ;
N4 X-75;
N5 G98 Y50 ;
N6 G80 G00 X0 Y0 M05 ;
N7 M30 ;
