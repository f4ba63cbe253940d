//! [`BlockDims`]: what the decimal-point check ([`crate::lint`]) needs of
//! one block: its non-zero literal dimension words (letter, whether a
//! point was written, where, and the value of those without a point),
//! whether the block is one the check leaves out (G04, G10, G65, G66,
//! M98) and its G20/G21.
//!
//! Most blocks of a long program are plain words (`G01 X6.7292 Y0.
//! Z43.0946 F1500.`); [`BlockDims::read_plain`] reads those in one pass
//! over the bytes without building the parser's [`Block`], and finds what
//! kerf-lang's `parse_block` gives for them: its numbers are read by the
//! parser's own fast path, [`kerf_lang::plain_digits`]. Anything else (a
//! comment, a macro word, N or O, a block delete, blanks inside a number,
//! a number past the digit limit) is refused, and the block goes to the
//! parser: [`BlockDims::read_parsed`] takes the same from its result.

use kerf_lang::{is_blank, plain_digits, Addr, Block, Val};

/// A set of address letters `A`..`Z` (one bit each), for the dimension
/// letters of a profile: a test of one bit where a slice search was a
/// call per word.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Letters(u32);

impl Letters {
    /// The set of the upper-case letters in `of`.
    pub fn new(of: &[u8]) -> Letters {
        Letters(
            of.iter()
                .filter(|c| c.is_ascii_uppercase())
                .fold(0, |m, c| m | 1 << (c - b'A')),
        )
    }

    /// Whether `c` (any byte) is in the set.
    #[inline]
    pub fn has(self, c: u8) -> bool {
        let i = c.wrapping_sub(b'A');
        i < 26 && self.0 & (1 << i) != 0
    }
}

/// One non-zero literal dimension word.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Dim {
    /// The address letter, upper case.
    pub letter: u8,
    /// Whether a decimal point was written.
    pub point: bool,
    /// The value as written, sign applied (only without a point: with
    /// one it is not needed and left 0).
    pub value: f64,
    /// Byte index of the letter in the block text.
    pub at: u32,
}

/// The check's view of one block (reused from block to block).
#[derive(Debug, Default)]
pub(crate) struct BlockDims {
    /// The non-zero literal words of the dimension letters, in order.
    pub dims: Vec<Dim>,
    /// The block has G04, G10, G65, G66 or M98.
    pub skipped: bool,
    /// Its first G20 (true) or G21 (false).
    pub inch: Option<bool>,
}

impl BlockDims {
    fn clear(&mut self) {
        self.dims.clear();
        self.skipped = false;
        self.inch = None;
    }

    /// Notes a G or M word (`value` as the parser reads it).
    #[inline]
    fn code(&mut self, letter: u8, value: f64) {
        match letter {
            b'G' => {
                self.skipped |= [4.0, 10.0, 65.0, 66.0].contains(&value);
                if self.inch.is_none() && (value == 20.0 || value == 21.0) {
                    self.inch = Some(value == 20.0);
                }
            }
            b'M' => self.skipped |= value == 98.0,
            _ => {}
        }
    }

    /// Notes one dimension word if it is one and not zero.
    #[inline]
    fn dim(&mut self, letters: Letters, letter: u8, value: f64, point: bool, at: u32) {
        if value != 0.0 && letters.has(letter) {
            let value = if point { 0.0 } else { value };
            self.dims.push(Dim {
                letter,
                point,
                value,
                at,
            });
        }
    }

    /// The same from a parsed block.
    pub fn read_parsed(&mut self, b: &Block, letters: Letters) {
        self.clear();
        for w in &b.words {
            if let (Addr::L(letter), Val::Num(n)) = (w.addr, w.val) {
                self.code(letter, n.value);
                self.dim(letters, letter, n.value, n.point, w.at);
            }
        }
    }

    /// Reads `text` when it is only one-letter words with plain numbers,
    /// blanks and an end-of-block `;`; false (and the fields unspecified)
    /// when the parser must read it. `letters` are the dimension
    /// letters, `max_digits` the parser's digit limit.
    ///
    /// A number's value is worked out only where it is needed: for G and
    /// M, and for a dimension written without a point; otherwise whether
    /// it is zero is whether its digits are.
    pub fn read_plain(&mut self, text: &[u8], letters: Letters, max_digits: u8) -> bool {
        self.clear();
        let max = usize::from(max_digits);
        let mut i = 0;
        loop {
            while text.get(i).is_some_and(|&c| is_blank(c)) {
                i += 1;
            }
            let Some(&c) = text.get(i) else {
                return true;
            };
            if c == b';' {
                return true;
            }
            let letter = c.to_ascii_uppercase();
            if !letter.is_ascii_uppercase() || letter == b'N' || letter == b'O' {
                return false;
            }
            let at = i as u32;
            i += 1;
            let neg = text.get(i) == Some(&b'-');
            i += usize::from(neg);
            let Some(num) = plain_digits(text, i, max) else {
                return false;
            };
            i = num.end;
            if letter == b'G' || letter == b'M' {
                let v = num.value();
                self.code(letter, if neg { -v } else { v });
            } else if num.mant != 0 && letters.has(letter) {
                // Digits not all zero: a value of at least 1e-18.
                let value = if num.point {
                    0.0
                } else if neg {
                    -num.value()
                } else {
                    num.value()
                };
                self.dims.push(Dim {
                    letter,
                    point: num.point,
                    value,
                    at,
                });
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use kerf_lang::{parse_block, LexOptions};

    fn hx() -> Letters {
        Letters::new(b"XYZUVWIJR")
    }

    /// What the full parser's block gives.
    fn parsed(text: &str) -> (Vec<Dim>, bool, Option<bool>) {
        let mut b = Block::default();
        parse_block(text.as_bytes(), &LexOptions::default(), &mut b).unwrap();
        let mut d = BlockDims::default();
        d.read_parsed(&b, hx());
        (d.dims, d.skipped, d.inch)
    }

    fn plain(text: &str) -> Option<(Vec<Dim>, bool, Option<bool>)> {
        let mut d = BlockDims::default();
        d.read_plain(text.as_bytes(), hx(), LexOptions::default().max_digits)
            .then_some((d.dims, d.skipped, d.inch))
    }

    #[test]
    fn plain_blocks_read_as_the_parser_reads_them() {
        for text in [
            "G01 X6.7292 Y0.0000 Z43.0946 F1500.",
            "g1x-.5y-12.z3",
            "G04 X1000 ; rest is a remark (not read",
            "X118   Y20.\tF100.",
            "",
            "   ",
            "G0X0Y0",
            "X0.1234567890 Y-000.5 R-0",
            "G20 G21 X1",
            "G4.0 X5",
            "G04.5 X5",
            "M98 P10 R2",
            "G66 X12 Y3",
        ] {
            assert_eq!(plain(text), Some(parsed(text)), "{text:?}");
        }
    }

    #[test]
    fn what_the_check_sees() {
        // Y0.0000 is zero, F is no dimension: X and Z only.
        let (dims, skipped, inch) = plain("G01 X6.7292 Y0.0000 Z-43 F1500.").unwrap();
        assert_eq!(
            dims,
            vec![
                Dim {
                    letter: b'X',
                    point: true,
                    value: 0.0,
                    at: 4
                },
                Dim {
                    letter: b'Z',
                    point: false,
                    value: -43.0,
                    at: 20
                }
            ]
        );
        assert!(!skipped);
        assert_eq!(inch, None);
        assert!(plain("G10 L2 P1 X-100").unwrap().1);
        assert_eq!(plain("G21 G20").unwrap().2, Some(false));
    }

    #[test]
    fn anything_else_goes_to_the_parser() {
        for text in [
            "N10 G01 X1.",
            "O1001",
            "G01 X1. (COMMENT)",
            "/G01 X1.",
            "G01 X#1",
            "G01 X[1+2]",
            "G01 X 1.",
            "G01 X1 2",
            "G01 X1. .5",
            "G01 X- 1.",
            "G01 X+1.",
            "%",
            "#1=2",
            "GOTO 10",
            "G01 X1234567890123.",
            "G01 X.",
            "G01 X1.,R2.",
        ] {
            assert!(plain(text).is_none(), "{text:?}");
        }
    }

    #[test]
    fn generated_blocks_read_as_the_parser_reads_them() {
        // Blocks of random bytes from the alphabet of plain words and of
        // what must go to the parser (xorshift, fixed seed): wherever the
        // plain reader takes one, the parser reads it to the same view.
        const ALPHA: &[u8] = b"GMXYZRIJKFNOxgz0123456789000...--  \t;(#[+,";
        let mut x: u64 = 0x2545_F491_4F6C_DD1D;
        let mut taken = 0;
        for _ in 0..100_000 {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            let len = (x % 24) as usize;
            let mut y = x;
            let text: String = (0..len)
                .map(|_| {
                    y = y
                        .wrapping_mul(6364136223846793005)
                        .wrapping_add(1442695040888963407);
                    ALPHA[(y >> 33) as usize % ALPHA.len()] as char
                })
                .collect();
            // Mostly letters in front of numbers, as programs write them.
            let text = format!("G{}X{text}", x % 100);
            if let Some(got) = plain(&text) {
                let mut b = Block::default();
                assert!(
                    parse_block(text.as_bytes(), &LexOptions::default(), &mut b).is_ok(),
                    "{text:?}"
                );
                assert_eq!(got, parsed(&text), "{text:?}");
                taken += 1;
            }
        }
        // The comparison is not empty.
        assert!(taken > 1000, "{taken}");
    }

    #[test]
    fn letters_are_a_set() {
        let l = hx();
        assert!(l.has(b'X') && l.has(b'R') && !l.has(b'K') && !l.has(b'x'));
        assert!(!l.has(b'[') && !l.has(b'@') && !l.has(0xC1));
    }
}
