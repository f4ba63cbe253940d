(002 G38 "Datum in -X and -Z example"; E01 active: E00's machine Z5 is beyond this profile's Z travel)
G20
H00
G00 G40 X10 Z5
G38 S0 X5 A.5 T.125 V20 F10
G0 Z10
G38 S0 Z7.6 A.5 T.125 V20 F10
M30
