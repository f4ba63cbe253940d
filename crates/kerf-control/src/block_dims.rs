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
//! parser's own fast path, [`kerf_lang::plain_number`]. Anything else (a
//! comment, a macro word, N or O, a block delete, blanks inside a number,
//! a number past the digit limit) is refused, and the block goes to the
//! parser: [`BlockDims::read_parsed`] takes the same from its result.

use kerf_lang::{is_blank, plain_number, Addr, Block, Val};

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

    /// Notes one literal word (`value` as the parser reads it).
    #[inline]
    fn word(&mut self, letters: &[u8], letter: u8, value: f64, point: bool, at: u32) {
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
        if value != 0.0 && letters.contains(&letter) {
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
    pub fn read_parsed(&mut self, b: &Block, letters: &[u8]) {
        self.clear();
        for w in &b.words {
            if let (Addr::L(letter), Val::Num(n)) = (w.addr, w.val) {
                self.word(letters, letter, n.value, n.point, w.at);
            }
        }
    }

    /// Reads `text` when it is only one-letter words with plain numbers,
    /// blanks and an end-of-block `;`; false (and the fields unspecified)
    /// when the parser must read it. `letters` are the dimension
    /// letters, `max_digits` the parser's digit limit.
    pub fn read_plain(&mut self, text: &[u8], letters: &[u8], max_digits: u8) -> bool {
        self.clear();
        let max = usize::from(max_digits);
        let n = text.len();
        let mut i = 0;
        loop {
            while i < n && is_blank(text[i]) {
                i += 1;
            }
            if i == n || text[i] == b';' {
                return true;
            }
            let letter = text[i].to_ascii_uppercase();
            if !letter.is_ascii_uppercase() || letter == b'N' || letter == b'O' {
                return false;
            }
            let at = i as u32;
            i += 1;
            let neg = i < n && text[i] == b'-';
            i += usize::from(neg);
            let Some((num, end)) = plain_number(text, i, max) else {
                return false;
            };
            i = end;
            let value = if neg { -num.value } else { num.value };
            self.word(letters, letter, value, num.point, at);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use kerf_lang::{parse_block, LexOptions};

    const HX: &[u8] = b"XYZUVWIJR";

    /// What the full parser's block gives.
    fn parsed(text: &str) -> (Vec<Dim>, bool, Option<bool>) {
        let mut b = Block::default();
        parse_block(text.as_bytes(), &LexOptions::default(), &mut b).unwrap();
        let mut d = BlockDims::default();
        d.read_parsed(&b, HX);
        (d.dims, d.skipped, d.inch)
    }

    fn plain(text: &str) -> Option<(Vec<Dim>, bool, Option<bool>)> {
        let mut d = BlockDims::default();
        d.read_plain(text.as_bytes(), HX, LexOptions::default().max_digits)
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
}
