(000 HX MC manual 4.4 last block "G02 X-100. I30. R50." - R and I in one block: R is used, I ignored [Fanuc rule, also 001 p.15 note 5]; the block is taken out of the 4.4 example, which ends in G91 mode)
G54 G90 G00 X0. Y0. Z0.
G91 G17 G02 X-100. I30. R50. F100.
M30
