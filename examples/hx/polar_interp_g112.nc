(000 4.6 G112/G113 polar coordinate interpolation example; G42 and G40 left out, cutter compensation is issue 5: the programmed contour)
G54 G90 G00 X60. C0. Z50.
G112
G01 X20. F100.
C10.
G03 X10. C20. R10.
G01 X-20.
C-10.
G03 X-10. C-20. I10. J0.
G01 X20.
C0.
X60.
G113
M30
