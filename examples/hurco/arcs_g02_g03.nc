(002 Hurco MAX turning manual "Example - G02/G03 Arcs" [Figure 5]; G40 left out of N1)
N1 G90 G20
N2 G00 G07 X.0 Z.1 (G07 = radius programming)
N3 G01 Z0 F10
N4 X.2
N5 G03 X.8 Z-.6 I0 K-.6
N6 G01 G91 Z-1.0
N7 G90 G08 G02 X1.9512 Z-2.0243 R.6 (G08=diameter programming)
N8 G01 X2.2 Z-2.1487
N9 Z-2.5
N10 G00 X2.5
N11 Z.1
N12 M30
