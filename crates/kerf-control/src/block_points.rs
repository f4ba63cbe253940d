//! [`PointScan`]: the decimal-point check's fast path for the blocks of
//! a long program. Nearly every block of one is plain words whose
//! dimensions all have a point (`G01 X6.7292 Y0.0000 Z43.0946 F1500.`):
//! there the check has nothing to note but how many non-zero dimension
//! words were written with a point. [`PointScan::points`] decides that in
//! one loop over the bytes, an automaton whose table (made once per check
//! from the byte classes and [`step`]) gives for a state and a byte the
//! next state and whether the word is a counted dimension, without the
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

/// Byte classes: the ten digits are their own (`0..=9`).
const BLANK: u8 = 10;
const POINT: u8 = 11;
const MINUS: u8 = 12;
const SEMI: u8 = 13;
/// A dimension letter of the profile, G, M, any other letter the plain
/// reader takes (not N or O).
const DIM: u8 = 14;
const G: u8 = 15;
const M: u8 = 16;
const LETTER: u8 = 17;
const OTHER: u8 = 18;
const CLASSES: u8 = 19;

/// The longest number the scan follows, in digits (longer ones, or the
/// profile's limit when it is lower, go the general way).
const CAP: usize = 8;

/// States. A number's: its kind (a dimension whose digits are all zero
/// so far, a dimension with a digit that is not, anything else), whether
/// its point has been read and its digits so far (`0..=CAP`).
const FAIL: usize = 0;
/// Before a word (at the start, or after a number and blanks).
const WORD: usize = 1;
/// After `;`: the rest is not read.
const DONE: usize = 2;
const AFTER_DIM: usize = 3;
const AFTER_LETTER: usize = 4;
const SIGN_DIM: usize = 5;
const SIGN_LETTER: usize = 6;
const AFTER_G: usize = 7;
const AFTER_M: usize = 8;
/// G or M and two digits that make no code the check notes.
const CODE_DONE: usize = 9;
/// G or M and one digit (`+ digit`).
const G_DIGIT: usize = 10;
const M_DIGIT: usize = 20;
const NUMBER: usize = 30;
const STATES: usize = NUMBER + 6 * (CAP + 1);

/// A number's kinds.
const ZERO_DIM: usize = 0;
const DIM_NZ: usize = 1;
const OTHER_NUM: usize = 2;

fn number(kind: usize, point: bool, digits: usize) -> usize {
    NUMBER + (kind * 2 + usize::from(point)) * (CAP + 1) + digits
}

/// The entry of a table: the next state times 256 (the index of its row),
/// and [`COUNT`] when the byte makes the word a non-zero dimension
/// with a point.
const COUNT: u16 = 1 << 15;

/// The fast path of one check (its profile's dimension letters and digit
/// limit); see the module documentation.
pub(crate) struct PointScan {
    /// `STATES` rows of 256 entries, padded to 128 rows (the index is
    /// masked, so it needs no bounds check).
    table: Box<[u16; 1 << 15]>,
    /// The states the text may end in.
    ends: [bool; STATES],
    /// Whether the scan is used (a digit limit of at least 2).
    on: bool,
}

/// Where a word starting with a letter of class `k` goes.
fn start(k: u8) -> usize {
    match k {
        DIM => AFTER_DIM,
        G => AFTER_G,
        M => AFTER_M,
        LETTER => AFTER_LETTER,
        _ => FAIL,
    }
}

/// The end of a word at a byte of class `k`.
fn end_word(k: u8) -> usize {
    match k {
        BLANK => WORD,
        SEMI => DONE,
        _ => start(k),
    }
}

/// Whether G (`g`) or M code `v` is one the check notes (G04, G10, G20,
/// G21, G65, G66, M98).
fn noted(g: bool, v: usize) -> bool {
    if g {
        matches!(v, 4 | 10 | 20 | 21 | 65 | 66)
    } else {
        v == 98
    }
}

/// The automaton: the state after `s` and a byte of class `k`, and
/// whether that byte completes a counted word; `cap` the digits a number
/// may have.
fn step(s: usize, k: u8, cap: usize) -> (usize, bool) {
    let digit = k < 10;
    let d = usize::from(k);
    let ends = matches!(k, BLANK | SEMI | DIM | G | M | LETTER);
    match s {
        FAIL => (FAIL, false),
        DONE => (DONE, false),
        WORD => (
            if digit || k == POINT {
                FAIL
            } else {
                end_word(k)
            },
            false,
        ),
        AFTER_DIM | SIGN_DIM | AFTER_LETTER | SIGN_LETTER => {
            let dim = s == AFTER_DIM || s == SIGN_DIM;
            let kind = match (dim, d) {
                (false, _) => OTHER_NUM,
                (true, 0) => ZERO_DIM,
                (true, _) => DIM_NZ,
            };
            let next = match k {
                _ if digit => number(kind, false, 1),
                POINT => number(if dim { ZERO_DIM } else { OTHER_NUM }, true, 0),
                MINUS if s == AFTER_DIM => SIGN_DIM,
                MINUS if s == AFTER_LETTER => SIGN_LETTER,
                _ => FAIL,
            };
            (next, false)
        }
        AFTER_G | AFTER_M if digit => ((if s == AFTER_G { G_DIGIT } else { M_DIGIT }) + d, false),
        AFTER_G | AFTER_M => (FAIL, false),
        _ if (G_DIGIT..NUMBER).contains(&s) => {
            let (g, first) = (s < M_DIGIT, (s - G_DIGIT) % 10);
            let next = match k {
                _ if digit && !noted(g, first * 10 + d) => CODE_DONE,
                _ if ends && !noted(g, first) => end_word(k),
                _ => FAIL,
            };
            (next, false)
        }
        CODE_DONE => (if ends { end_word(k) } else { FAIL }, false),
        _ => {
            let i = s - NUMBER;
            let (kind, point, n) = (i / (2 * (CAP + 1)), i / (CAP + 1) % 2 == 1, i % (CAP + 1));
            match k {
                _ if digit && n < cap => {
                    let kind = if kind == ZERO_DIM && d != 0 {
                        DIM_NZ
                    } else {
                        kind
                    };
                    let counted = point && kind == DIM_NZ && s != number(DIM_NZ, true, n);
                    (number(kind, point, n + 1), counted)
                }
                POINT if !point => (number(kind, true, n), kind == DIM_NZ),
                // A dimension without a point, or no digit.
                _ if ends && n > 0 && (point || kind != DIM_NZ) => (end_word(k), false),
                _ => (FAIL, false),
            }
        }
    }
}

/// Whether a text may end in state `s`.
fn may_end(s: usize) -> bool {
    match s {
        WORD | DONE | CODE_DONE => true,
        _ if (G_DIGIT..M_DIGIT).contains(&s) => s != G_DIGIT + 4,
        _ if (M_DIGIT..NUMBER).contains(&s) => true,
        _ if s >= NUMBER => step(s, BLANK, CAP).0 == WORD,
        _ => false,
    }
}

impl PointScan {
    /// For the dimension letters `letters` and the parser's digit limit.
    pub fn new(letters: Letters, max_digits: u8) -> PointScan {
        let cap = usize::from(max_digits).min(CAP);
        let mut class = [OTHER; 256];
        for c in 0..=255u8 {
            let up = c.to_ascii_uppercase();
            class[usize::from(c)] = match c {
                _ if is_blank(c) => BLANK,
                b'0'..=b'9' => c - b'0',
                b'.' => POINT,
                b'-' => MINUS,
                b';' => SEMI,
                _ if !up.is_ascii_uppercase() || up == b'N' || up == b'O' => OTHER,
                _ if letters.has(up) => DIM,
                _ if up == b'G' => G,
                _ if up == b'M' => M,
                _ => LETTER,
            };
        }
        let mut rows = [[(FAIL, false); CLASSES as usize]; STATES];
        for (s, row) in rows.iter_mut().enumerate() {
            for (k, e) in row.iter_mut().enumerate() {
                *e = step(s, k as u8, cap);
            }
        }
        let mut table: Box<[u16; 1 << 15]> = vec![0; 1 << 15].try_into().unwrap();
        for (s, row) in rows.iter().enumerate() {
            for c in 0..256 {
                let (next, counted) = row[usize::from(class[c])];
                table[s * 256 + c] = (next * 256) as u16 | if counted { COUNT } else { 0 };
            }
        }
        let mut ends = [false; STATES];
        for (s, e) in ends.iter_mut().enumerate() {
            *e = may_end(s);
        }
        PointScan {
            table,
            ends,
            on: max_digits >= 2,
        }
    }

    /// The number of non-zero dimension words of `text` (all written with
    /// a point) when it is a plain block that `read_plain` takes with no
    /// G04, G10, G20, G21, G65, G66 or M98 and no dimension without a
    /// point; `None` when the block must be read the general way.
    #[inline]
    pub fn points(&self, text: &[u8]) -> Option<u64> {
        let mut s = WORD * 256;
        let mut n = 0u64;
        let mut step = |c: u8| {
            let e = self.table[(s + usize::from(c)) & 0x7fff];
            s = usize::from(e & !COUNT);
            n += u64::from(e >> 15);
        };
        // Four bytes a turn (a quarter of the loop's own tests).
        let mut quads = text.chunks_exact(4);
        for q in &mut quads {
            step(q[0]);
            step(q[1]);
            step(q[2]);
            step(q[3]);
        }
        for &c in quads.remainder() {
            step(c);
        }
        (self.on && self.ends[s >> 8]).then_some(n)
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
        let scans = profiles.map(|(l, max)| PointScan::new(l, max));
        let mut x: u64 = 0x9E37_79B9_7F4A_7C15;
        let (mut answered, mut plain) = (0, 0);
        for _ in 0..300_000 {
            let r = next(&mut x);
            let (letters, max) = profiles[(r % 3) as usize];
            let scan = &scans[(r % 3) as usize];
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
            let got = scan.points(text.as_bytes());
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
