(002 G98 second example: G80 is needed to change the init plane)
N010 G0 Z10
N020 G81 Z5 F60 (feed to Z5, rapid to Z10)
N030 G80 Z20
N040 G81 Z15 (rapid to Z10, feed up to Z15, rapid to Z20)
N050 G80
M30
