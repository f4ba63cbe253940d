(000 HX MC manual 2.3.3 optional block skip "/" - own example; see block_delete.skip.expect.toml for the switch on)
G54 G90 G00 X0. Y0. Z10.
/G00 X50.
G01 Y20. F200.
/X10. Y30.
X-20.
M30
