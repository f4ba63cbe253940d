(000 HX MC manual 4.3.2 ,R corner rounding - example program; decimal points added, and the third block printed "X50 Z50" read as X50. Y50. as in 4.3.1 - see docs/dialects.md)
G00 X10. Y30. ;
G01 X30. ,R15. F300. ;
X50. Y50. ;
