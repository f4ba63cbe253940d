(001 PUMA training manual p.16 G04 dwell: the page's ways to dwell 10 s - X, U with and without decimal point, P; the "P10000.0" form is left out)
G00 X50.0 Z10.0
G04 X10.0
G04 X10000
G04 U10.0
G04 U10000
G04 P10000
M30
