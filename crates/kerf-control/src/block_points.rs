//! [`PointScan`]: the decimal-point check's fast path for the blocks of
//! a long program. Nearly every block of one is plain words whose
//! dimensions all have a point (`G01 X6.7292 Y0.0000 Z43.0946 F1500.`):
//! there the check has nothing to note but how many non-zero dimension
//! words were written with a point. [`PointScan::points`] decides that in
//! one loop over the bytes, by a table of byte classes, without the
//! numbers' values or the [`crate::block_dims::BlockDims`] list; for
//! anything else (a dimension without a point, a G or M word the check
//! looks at, a word [`crate::block_dims::BlockDims::read_plain`] refuses,
//! anything unusual) it gives up and the block is read the general way.
//!
//! Its answer is the general path's whenever it gives one: the same
//! syntax as `read_plain` (a number as kerf-lang's `plain_digits` takes
//! it), checked by the property test below against `read_plain` on
//! generated blocks and in `lint.rs` by whole generated programs' warnings
//! with and without it.

use kerf_lang::is_blank;

use crate::block_dims::Letters;

/// Byte classes. The word letters come last (`k >= DIM`).
const OTHER: u8 = 0;
const BLANK: u8 = 1;
const DIGIT: u8 = 2;
const POINT: u8 = 3;
const SEMI: u8 = 4;
/// The end of the text (no byte has it).
const END: u8 = 5;
/// A dimension letter of the profile.
const DIM: u8 = 6;
const G: u8 = 7;
const M: u8 = 8;
/// Any other letter the plain reader takes (not N or O).
const LETTER: u8 = 9;

/// The fast path of one check (its profile's dimension letters and digit
/// limit); see the module documentation.
pub(crate) struct PointScan {
    class: [u8; 256],
    /// The longest number in digits (`read_plain`'s `max_digits.min(18)`).
    max: usize,
}

impl PointScan {
    /// For the dimension letters `letters` and the parser's digit limit.
    pub fn new(letters: Letters, max_digits: u8) -> PointScan {
        let mut class = [OTHER; 256];
        for c in 0..=255u8 {
            let up = c.to_ascii_uppercase();
            class[usize::from(c)] = match c {
                _ if is_blank(c) => BLANK,
                b'0'..=b'9' => DIGIT,
                b'.' => POINT,
                b';' => SEMI,
                _ if !up.is_ascii_uppercase() || up == b'N' || up == b'O' => OTHER,
                _ if letters.has(up) => DIM,
                _ if up == b'G' => G,
                _ if up == b'M' => M,
                _ => LETTER,
            };
        }
        PointScan {
            class,
            max: usize::from(max_digits).min(18),
        }
    }

    #[inline(always)]
    fn class_at(&self, text: &[u8], i: usize) -> u8 {
        text.get(i).map_or(END, |&c| self.class[usize::from(c)])
    }

    /// The number of non-zero dimension words of `text` (all written with
    /// a point) when it is a plain block that `read_plain` takes with no
    /// G04, G10, G20, G21, G65, G66 or M98 and no dimension without a
    /// point; `None` when the block must be read the general way.
    #[inline]
    pub fn points(&self, text: &[u8]) -> Option<u64> {
        let mut n = 0;
        let mut i = 0;
        loop {
            let mut k = self.class_at(text, i);
            while k == BLANK {
                i += 1;
                k = self.class_at(text, i);
            }
            if k == END || k == SEMI {
                return Some(n);
            }
            if k < DIM {
                return None;
            }
            i += 1;
            i += usize::from(text.get(i) == Some(&b'-'));
            let s = i;
            let mut nz = 0u8;
            while let Some(d) = text
                .get(i)
                .map(|c| c.wrapping_sub(b'0'))
                .filter(|d| *d < 10)
            {
                nz |= d;
                i += 1;
            }
            let int_end = i;
            let point = text.get(i) == Some(&b'.');
            if point {
                i += 1;
                while let Some(d) = text
                    .get(i)
                    .map(|c| c.wrapping_sub(b'0'))
                    .filter(|d| *d < 10)
                {
                    nz |= d;
                    i += 1;
                }
            }
            let digits = i - s - usize::from(point);
            if digits == 0 || digits > self.max {
                return None;
            }
            // Blanks after a number are read with it; digits or a first
            // point after them would continue it (`plain_digits`).
            let mut next = self.class_at(text, i);
            while next == BLANK {
                i += 1;
                next = self.class_at(text, i);
            }
            if next == DIGIT || (next == POINT && !point) {
                return None;
            }
            match k {
                DIM if nz != 0 => {
                    if !point {
                        return None;
                    }
                    n += 1;
                }
                G | M if point || noted(k, &text[s..int_end]) => return None,
                _ => {}
            }
        }
    }
}

/// Whether the G (`k == G`) or M word of integer digits `digits` is one
/// the check notes (G04, G10, G20, G21, G65, G66, M98), or has more than
/// three digits (left to the general path too).
#[inline]
fn noted(k: u8, digits: &[u8]) -> bool {
    if digits.len() > 3 {
        return true;
    }
    let v = digits
        .iter()
        .fold(0u32, |v, c| v * 10 + u32::from(c - b'0'));
    if k == G {
        matches!(v, 4 | 10 | 20 | 21 | 65 | 66)
    } else {
        v == 98
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::block_dims::BlockDims;
    use kerf_lang::LexOptions;

    fn hx() -> Letters {
        Letters::new(b"XYZUVWIJR")
    }

    fn scan(text: &str) -> Option<u64> {
        PointScan::new(hx(), LexOptions::default().max_digits).points(text.as_bytes())
    }

    /// What the general path notes of a block: `Some(count)` exactly when
    /// `read_plain` takes it, it is not skipped, has no G20/G21 and all
    /// its dimensions have a point.
    fn general(text: &str, letters: Letters, max_digits: u8) -> Option<u64> {
        let mut d = BlockDims::default();
        if !d.read_plain(text.as_bytes(), letters, max_digits) {
            return None;
        }
        let all_points = d.dims.iter().all(|w| w.point);
        (!d.skipped && d.inch.is_none() && all_points).then_some(d.dims.len() as u64)
    }

    #[test]
    fn surface_blocks_count_their_pointed_dimensions() {
        assert_eq!(scan("G01 X6.7292 Y0.0000 Z43.0946 F1500."), Some(2));
        assert_eq!(scan("G01 X12.9583 Y0.0000 Z45.3368"), Some(2));
        assert_eq!(scan("x-.5 y2. r3.;(not read"), Some(3));
        assert_eq!(scan("G99 G81 X10.0000 Y10.0000 Z-1.5 R2. F150."), Some(4));
        assert_eq!(scan("X0 Y0.000 Z-0 F100"), Some(0));
        assert_eq!(scan(""), Some(0));
        assert_eq!(scan("  \t"), Some(0));
        // K is no dimension on the HX; S, T, H, D neither.
        assert_eq!(scan("G01 K2 S8000 T1 H1 D12"), Some(0));
    }

    #[test]
    fn what_the_check_notes_goes_the_general_way() {
        for text in [
            "G01 X118 Y20.",
            "G04 X1000",
            "G4 X1.",
            "G10 L2 P1 X-100.",
            "G20",
            "G21 G90",
            "G65 P9000 X12.",
            "G66 X1.",
            "M98 P10",
            "G004 X1.",
            "G4.0 X1.",
            "G1. X1.",
            "N10 G01 X1.",
            "O1001",
            "G01 X1. (C)",
            "/G01 X1.",
            "G01 X 1.",
            "G01 X1 2.",
            "G01 X1. .5",
            "G01 X.",
            "G01 X-",
            "G01 X+1.",
            "G01 X1234567890123.",
            "#1=2",
            "%",
        ] {
            assert_eq!(scan(text), None, "{text:?}");
        }
    }

    /// xorshift64.
    fn next(x: &mut u64) -> u64 {
        *x ^= *x << 13;
        *x ^= *x >> 7;
        *x ^= *x << 17;
        *x
    }

    #[test]
    fn generated_blocks_get_the_general_paths_answer() {
        // Random blocks over the bytes of plain words and of what must go
        // the general way, on the HX's letters and a lathe's, with three
        // digit limits: wherever the scan answers, it is the general
        // path's answer, and it answers most plain blocks.
        const ALPHA: &[u8] = b"GMXYZRIJKFSNOxgzm0123456789000000...--  \t;(#[+,\xc1";
        let profiles = [
            (Letters::new(b"XYZUVWIJR"), 12),
            (Letters::new(b"XYZUVWIJK"), 8),
            (Letters::new(b"XYZUVWIJK"), 3),
        ];
        let mut x: u64 = 0x9E37_79B9_7F4A_7C15;
        let (mut answered, mut plain) = (0, 0);
        for _ in 0..300_000 {
            let r = next(&mut x);
            let (letters, max) = profiles[(r % 3) as usize];
            let len = (r >> 8) % 28;
            let body: Vec<u8> = (0..len)
                .map(|_| ALPHA[(next(&mut x) >> 20) as usize % ALPHA.len()])
                .collect();
            // Mostly words as programs write them: a letter and a number.
            let mut text =
                format!("G{} X{}.{} ", (r >> 40) % 100, (r >> 48) % 400, r % 7).into_bytes();
            text.extend_from_slice(&body);
            let text = String::from_utf8_lossy(&text).into_owned();
            let want = general(&text, letters, max);
            let got = PointScan::new(letters, max).points(text.as_bytes());
            if got.is_some() {
                assert_eq!(got, want, "{text:?}");
                answered += 1;
            }
            plain += usize::from(want.is_some());
        }
        // The comparison is not empty, and the scan takes most of what it
        // could.
        assert!(answered > 10_000, "{answered}");
        assert!(answered * 10 > plain * 9, "{answered} of {plain}");
    }
}
