(002 G98 first example: the init plane is the Z of the first cycle after G80)
N010 G0 Z10
N020 G81 Z5 F60 (feed to Z5, rapid to Z10)
N030 G0 Z20
N040 G81 Z15 (rapid to Z10, feed up to Z15, rapid to Z10)
N050 G80
M30
