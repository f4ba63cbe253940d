(000 HX MC manual 4.3.1 ,C chamfering - example program; decimal points added: printed as X10 Y30 ... ,C5 they would be 0.001 mm units)
G00 X10. Y30. ;
G01 X30. ,C5. F300. ;
X50. Y50. ;
