//! Decimal digits written with integer arithmetic, shared by the text
//! writers (the toolpath's numbers in kerf-control, the G-code words in
//! kerf-expand): eight digits at once in the lanes of one `u64`, a table
//! for the integers below 1000, and a fixed-size copy.

/// The eight decimal digits of `n` < 10^8, most significant first, one
/// per byte of the little-endian word (0..=9, not ASCII): the halves,
/// quarters and digits split in parallel lanes of one `u64` (x/100 as
/// `x·5243 >> 19` for x < 10^4, x/10 as `x·103 >> 10` for x < 100).
/// Add [`ZEROS`] for the ASCII digits.
#[inline]
pub fn swar8(n: u64) -> u64 {
    let x = (n / 10_000) | ((n % 10_000) << 32);
    let q = ((x * 5243) >> 19) & 0x0000_007F_0000_007F;
    let y = q | ((x - q * 100) << 16);
    let t = ((y * 103) >> 10) & 0x000F_000F_000F_000F;
    t | ((y - t * 10) << 8)
}

/// `'0'` in every byte.
pub const ZEROS: u64 = 0x3030_3030_3030_3030;

/// The digits of 0..1000 (padded to four bytes) and their number.
pub const SMALL: [([u8; 4], u8); 1000] = {
    let mut t = [([0u8; 4], 0u8); 1000];
    let mut n = 0;
    while n < 1000 {
        let (h, d, u) = ((n / 100) as u8, (n / 10 % 10) as u8, (n % 10) as u8);
        t[n] = if n >= 100 {
            ([b'0' + h, b'0' + d, b'0' + u, 0], 3)
        } else if n >= 10 {
            ([b'0' + d, b'0' + u, 0, 0], 2)
        } else {
            ([b'0' + u, 0, 0, 0], 1)
        };
        n += 1;
    }
    t
};

/// Appends `text[..len]`: the whole fixed-size array is copied (a copy of
/// known size compiles to a few moves, where a short copy of unknown size
/// is a call) and the tail cut off again.
#[inline]
pub fn put_fixed<const N: usize>(out: &mut Vec<u8>, text: &[u8; N], len: usize) {
    let at = out.len();
    out.extend_from_slice(text);
    out.truncate(at + len);
}

/// The text of the last line number written, kept so that the next one
/// costs a copy (the same line again: a canned cycle's motions in a
/// toolpath) or a count up by one in place (the next line: nearly always,
/// in a toolpath or an expansion); any other number is spelled anew.
#[derive(Clone, Copy, Debug, Default)]
pub struct LineText {
    /// The number `text[..len]` spells; `len` 0 before the first.
    n: u64,
    text: [u8; 24],
    len: usize,
}

impl LineText {
    /// Appends the decimal digits of `u` (no padding).
    #[inline]
    pub fn put(&mut self, out: &mut Vec<u8>, u: u64) {
        if u != self.n || self.len == 0 {
            if !(self.len > 0 && Some(u) == self.n.checked_add(1) && self.count_up()) {
                self.spell(u);
            }
            self.n = u;
        }
        put_fixed(out, &self.text, self.len);
    }

    /// The text counted up by one; false where it gains a digit (all 9s).
    #[inline]
    fn count_up(&mut self) -> bool {
        let mut i = self.len;
        while i > 0 {
            i -= 1;
            if self.text[i] != b'9' {
                self.text[i] += 1;
                return true;
            }
            self.text[i] = b'0';
        }
        false
    }

    /// The text of `u` made anew (a jump: a loop, a call, the first line).
    fn spell(&mut self, mut u: u64) {
        let mut rev = [0u8; 20];
        let mut k = 0;
        loop {
            rev[k] = b'0' + (u % 10) as u8;
            u /= 10;
            k += 1;
            if u == 0 {
                break;
            }
        }
        for j in 0..k {
            self.text[j] = rev[k - 1 - j];
        }
        self.len = k;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_line_text_is_the_number_s_digits() {
        // Repeats, steps of one across every carry up to 10^6 (and one
        // more digit), jumps back and forth, zero, the largest u64: the
        // same text as the standard formatting.
        let mut c = LineText::default();
        let mut seq: Vec<u64> = vec![0, 0, 1, 1, 1, 2, 9, 10, 10, 11];
        seq.extend(0..1_000_000);
        seq.extend(9_999_990..10_000_010);
        seq.extend([5, 4, 4, 99, 100, 7, u64::MAX - 1, u64::MAX, 0, 1]);
        let mut got = Vec::new();
        for n in seq {
            got.clear();
            c.put(&mut got, n);
            assert_eq!(got, n.to_string().as_bytes(), "{n}");
        }
    }

    #[test]
    fn eight_digits_at_once_are_the_digits() {
        // Every n below 10^6 (all the decimals), and a stride over 10^8.
        let check = |n: u64| {
            let w = swar8(n);
            let want = format!("{n:08}");
            let got: String = w.to_le_bytes().iter().map(|d| (b'0' + d) as char).collect();
            assert_eq!(got, want, "{n}");
        };
        for n in 0..1_000_000 {
            check(n);
        }
        let mut n = 0u64;
        while n < 100_000_000 {
            check(n);
            n += 997;
        }
        for n in [9_999_999, 10_000_000, 99_999_999, 12_345_678, 10_000, 9_999] {
            check(n);
        }
    }

    #[test]
    fn the_small_table_holds_the_digits() {
        for (n, (d, len)) in SMALL.iter().enumerate() {
            assert_eq!(&d[..*len as usize], n.to_string().as_bytes());
        }
    }

    #[test]
    fn a_fixed_copy_keeps_only_its_length() {
        let mut out = b"x=".to_vec();
        put_fixed(&mut out, b"12.5\0\0\0\0", 4);
        assert_eq!(out, b"x=12.5");
    }
}
