(expand test: cutter compensation G41 with a chamfer and a corner radius, tool length G43, a G65 macro pocket with arguments, G55)
G21 G17 G40 G49 G80 G90 G94
G10 L12 P1 R5.
G10 L10 P1 R100.
G10 L2 P2 X-300. Y-200. Z-260.
G54 G00 X-20. Y-20. Z50.
T1 M06
G43 H1 Z50.
S2000 M03
G00 Z5.
G01 Z-5. F200.
G41 D1 X0 Y0 F400.
G01 Y40. ,C5.
X60. ,R8.
Y0
X0
G40 X-20. Y-20.
G00 Z50.
G65 P9100 X80. Y20. R15. Z-4. F250.
G55 G00 X10. Y10.
G02 X30. Y10. R10. F300.
G49 G00 Z50.
M30
O9100
(circle pocket: centre X Y, radius R, depth Z, feed F)
G00 X#24 Y#25
Z2.
G01 Z#26 F#9
G01 X[#24 + #18]
G03 I-#18
G00 Z50.
M99
