(000 §12.4 canned cycle example, three tools, G43, 13 holes; machine hx-mc-1300.toml. Changes to the printed program: decimal points added to every dimension [the manual prints X400 Z-153 R-97 ..., which the HX reads in 0.001 mm]; the stray "R" after X400 in N05 removed)
(H11/H15/H31 = 200/190/150 mm from the figure set through #2250/#2254/#2270 before N01; N26 "G49 Z500" gets G80 G90, because G85 and G91 of N23/N24 are still in force there and the block would otherwise drill again)
#2250 = 200.
#2254 = 190.
#2270 = 150.
N01 G92 X0 Y0 Z500.
N02 G90 G00 Z250.
N03 G43 Z0 H11
N04 S30 M03
N05 G99 G81 X400. Y-350. Z-153. R-97. F120
N06 Y-550.
N07 G98 Y-750.
N08 G99 X1200.
N09 Y-550.
N10 G98 Y-350.
N11 G00 X0 Y0 M05
N12 G49 Z250. T15 M06
N13 G43 Z0 H15
N14 S20 M03
N15 G99 G82 X550. Y-450. Z-130. R-97. P300 F120
N16 G98 Y-650.
N17 G99 X1050.
N18 G98 Y-450.
N19 G00 X0 Y0 M05
N20 G49 Z250. T31 M06
N21 G43 Z0 H31
N22 S100 M03
N23 G85 G99 X800. Y-350. Z-153. R47. F50
N24 G91 Y-200. K2
N25 G28 X0 Y0 M05
N26 G80 G90 G49 Z500.
N27 M02
