//! The plain-block scanner: a block made only of simple words (an
//! upper-case address letter from a given set, an optional `-` and a
//! plain number: digits, a point, digits, no blank inside), each letter
//! at most once, separated by blanks, and nothing else: no comment, no
//! `;`, no `/`, no `%`, no `N` or `O`, no macro syntax, no lower case.
//!
//! [`plain_words`] reads such a block in one pass and gives its words
//! exactly as [`crate::parse_block`] would (the same numbers, digit
//! counts and byte positions: both read a number by
//! [`crate::plain_number`]); for any other text it says no, and the
//! caller parses the block the general way. `tests/plain_scan.rs` checks
//! it against the parser on generated blocks.

use crate::block::Num;
use crate::parse::{is_blank, plain_number};

/// One word of a plain block.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlainWord {
    /// The address letter (upper case).
    pub letter: u8,
    /// The number as the parser reads it (sign applied).
    pub num: Num,
    /// Byte index of the letter in the block text.
    pub at: u32,
}

/// The bit of letter `l` (`A`-`Z`) in a letter set.
#[inline]
pub const fn letter_bit(l: u8) -> u32 {
    1 << (l - b'A')
}

/// Reads `text` as a plain block whose letters are all in `allowed` (a
/// set of [`letter_bit`]s; `N` and `O` are never plain), handing each
/// word to `each` in the order written: true when the block is one and
/// `each` took every word, false as soon as the text shows it is not (or
/// `each` says no), and for a block with no word. `max_digits` is the
/// parser's digit limit ([`crate::LexOptions::max_digits`]). The words
/// handed out before a false are not the block's: the caller drops them.
#[inline]
pub fn plain_words(
    text: &[u8],
    max_digits: u8,
    allowed: u32,
    mut each: impl FnMut(PlainWord) -> bool,
) -> bool {
    let allowed = allowed & !(letter_bit(b'N') | letter_bit(b'O'));
    let t = text;
    let mut i = 0;
    while i < t.len() && is_blank(t[i]) {
        i += 1;
    }
    let mut seen = 0u32;
    while i < t.len() {
        let l = t[i];
        if !l.is_ascii_uppercase() {
            return false;
        }
        let bit = letter_bit(l);
        if allowed & bit == 0 || seen & bit != 0 {
            return false;
        }
        seen |= bit;
        let neg = t.get(i + 1) == Some(&b'-');
        let s = i + 1 + neg as usize;
        if !t.get(s).is_some_and(u8::is_ascii_digit) {
            return false;
        }
        let Some((mut num, end)) = plain_number(t, s, max_digits as usize) else {
            return false;
        };
        if neg {
            num.value = -num.value;
        }
        let at = i as u32;
        if !each(PlainWord { letter: l, num, at }) {
            return false;
        }
        i = end;
    }
    seen != 0
}

/// Words a [`PlainScan`] holds at most (a plain block has each letter
/// once; the interpreter's plain blocks have at most five).
pub const SCAN_WORDS: usize = 6;

/// A block's text scanned ahead of its execution (by the read-ahead
/// thread, `crate::source::LineSource::read_ahead`): what [`plain_words`]
/// with every word taken said of it.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum PlainScan {
    /// Not scanned (or more than [`SCAN_WORDS`] words): scan the text.
    #[default]
    Unknown,
    /// Not a plain block.
    No,
    /// A plain block: its first `n` words, in the order written.
    Words {
        n: u8,
        words: [PlainWord; SCAN_WORDS],
    },
}

impl PlainScan {
    /// `text` scanned as [`plain_words`] would with `max_digits` and
    /// `allowed`, every word kept.
    pub fn of(text: &[u8], max_digits: u8, allowed: u32) -> PlainScan {
        let none = PlainWord {
            letter: 0,
            num: Num {
                value: 0.0,
                point: false,
                digits: 0,
            },
            at: 0,
        };
        let mut words = [none; SCAN_WORDS];
        let (mut n, mut room) = (0usize, true);
        let plain = plain_words(text, max_digits, allowed, |w| {
            if n == SCAN_WORDS {
                room = false;
                return false;
            }
            words[n] = w;
            n += 1;
            true
        });
        match (room, plain) {
            (false, _) => PlainScan::Unknown,
            (true, false) => PlainScan::No,
            (true, true) => PlainScan::Words { n: n as u8, words },
        }
    }

    /// What [`plain_words`] over the scanned text with the scan's
    /// `max_digits` and `allowed` returns, `each` called on the same
    /// words in the same order; `text` is read only when the scan is
    /// [`PlainScan::Unknown`].
    #[inline]
    pub fn words(
        &self,
        text: &[u8],
        max_digits: u8,
        allowed: u32,
        mut each: impl FnMut(PlainWord) -> bool,
    ) -> bool {
        match self {
            PlainScan::Unknown => plain_words(text, max_digits, allowed, each),
            PlainScan::No => false,
            PlainScan::Words { n, words } => words[..*n as usize].iter().all(|&w| each(w)),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const XYZ: u32 = letter_bit(b'X') | letter_bit(b'Y') | letter_bit(b'Z');
    const GXYZF: u32 = XYZ | letter_bit(b'G') | letter_bit(b'F');

    /// A word as (letter, value, point, digits, at).
    type Seen = (char, f64, bool, u8, u32);

    fn scan(t: &str, allowed: u32) -> Option<Vec<Seen>> {
        let mut out = Vec::new();
        let plain = plain_words(t.as_bytes(), 12, allowed, |w| {
            let n = w.num;
            out.push((w.letter as char, n.value, n.point, n.digits, w.at));
            true
        });
        plain.then_some(out)
    }

    #[test]
    fn a_surface_block_reads_word_by_word() {
        // Bytes: G0 1 _3 X4 .. Y14 .. Z24 ..; X6.7292 is 5 digits.
        let w = scan("G01 X6.7292 Y0.0000 Z-43.0946 F1500.", GXYZF).unwrap();
        assert_eq!(
            w,
            [
                ('G', 1.0, false, 2, 0),
                ('X', 6.7292, true, 5, 4),
                ('Y', 0.0, true, 5, 12),
                ('Z', -43.0946, true, 6, 20),
                ('F', 1500.0, true, 4, 30),
            ]
        );
        // Leading and trailing blanks, a carriage return.
        let w = scan("  X1 Y-2.\r", XYZ).unwrap();
        assert_eq!(w, [('X', 1.0, false, 1, 2), ('Y', -2.0, true, 1, 5)]);
    }

    #[test]
    fn anything_else_is_not_plain() {
        for t in [
            "",
            "   ",
            "x1",
            "X1 X2",
            "N10 X1",
            "X1 ; note",
            "X1 (note)",
            "/X1",
            "%",
            "X#1",
            "X[1+2]",
            "X 1",
            "X1 2",
            "X.5",
            "X-.5",
            "X+1",
            "X1,Y2",
            "X1 ,C1",
            "M03",
            "X1234567890123",
            "X--1",
        ] {
            assert_eq!(scan(t, GXYZF), None, "{t:?}");
        }
        // A letter outside the set.
        assert_eq!(scan("G01 X1", XYZ), None);
        // Every letter but N and O may be allowed.
        assert_eq!(
            scan("A1 B1 C1 D1 E1 F1 G1 H1 I1", u32::MAX).map(|w| w.len()),
            Some(9)
        );
        assert_eq!(scan("A1 N1", u32::MAX), None);
        // The caller may refuse a word.
        assert!(!plain_words(b"X1 Y2", 12, XYZ, |w| w.letter != b'Y'));
    }

    #[test]
    fn a_scan_ahead_gives_what_the_scanner_gives() {
        let all = |t: &str| {
            let mut out = Vec::new();
            let scan = PlainScan::of(t.as_bytes(), 12, GXYZF);
            let plain = scan.words(b"not read", 12, GXYZF, |w| {
                out.push(w);
                true
            });
            (scan, plain, out)
        };
        let (scan, plain, out) = all("G01 X6.7292 Y0 Z-4.5");
        assert!(plain && matches!(scan, PlainScan::Words { n: 4, .. }));
        assert_eq!(out[3].at, 15);
        assert_eq!(out[3].num.value, -4.5);
        let (scan, plain, out) = all("G01 X1 (c)");
        assert_eq!((scan, plain, out.len()), (PlainScan::No, false, 0));
        // Six words fit, a seventh does not: the text is scanned again.
        let six = PlainScan::of(b"A1 B1 C1 D1 E1 F1", 12, u32::MAX);
        assert!(matches!(six, PlainScan::Words { n: 6, .. }));
        let seven = PlainScan::of(b"A1 B1 C1 D1 E1 F1 G1", 12, u32::MAX);
        assert_eq!(seven, PlainScan::Unknown);
        assert!(seven.words(b"A1 B1 C1 D1 E1 F1 G1", 12, u32::MAX, |_| true));
        // The caller may refuse a scanned word.
        let s = PlainScan::of(b"X1 Y2", 12, XYZ);
        assert!(!s.words(b"", 12, XYZ, |w| w.letter != b'Y'));
    }
}
