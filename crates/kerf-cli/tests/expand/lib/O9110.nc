O9110 (rectangular pocket ring: corner X Y, size I J, depth Z, feed F; called with G65 from tests/expand)
G00 X#24 Y#25
Z2.
G01 Z#26 F#9
G91 X#4
Y#5
X-#4
Y-#5
G90 G00 Z50.
M99
