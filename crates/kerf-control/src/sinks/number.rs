//! Number formatting for the text outputs (toolpath JSON Lines, sample
//! CSV): fixed precision written with integer arithmetic, no float
//! formatting on the common path.
//!
//! [`num`] writes a value rounded to 1e-6 (1 nm in mm) as the shortest
//! decimal of that rounded double, which is what Rust's `{}` prints for it:
//! for |v| < 1e9 the rounded value `x/10^6` has at most 15 significant
//! digits, so it is the only decimal of that length naming its double, and
//! its digits are those of the integer `x` with the point six places in.
//! Below 1e8 the decimals (and an integer part of 1000 or more; a smaller
//! one is read from a table) are made as eight digits at once in the
//! lanes of one `u64` (kerf-canon's `digits::swar8`), the leading and trailing zeros counted
//! by its zero bytes. Larger or non-finite values
//! take the `{}` path.

pub(crate) use kerf_canon::digits::put_fixed;
use kerf_canon::digits::{swar8, SMALL, ZEROS};

/// Pairs of digits "00".."99", for writing two digits per division.
const PAIRS: &[u8; 200] = b"\
0001020304050607080910111213141516171819\
2021222324252627282930313233343536373839\
4041424344454647484950515253545556575859\
6061626364656667686970717273747576777879\
8081828384858687888990919293949596979899";

/// Number of decimal digits of `n`.
#[inline]
fn digits(n: u64) -> usize {
    let mut d = 1;
    let mut p = 10u64;
    while d < 20 && n >= p {
        d += 1;
        p = p.saturating_mul(10);
    }
    d
}

/// Writes the digits of `n` into `buf[..len]`, `len` = `digits(n)`.
#[inline]
fn fill(buf: &mut [u8], mut n: u64, len: usize) {
    let mut i = len;
    while n >= 100 {
        let d = (n % 100) as usize * 2;
        n /= 100;
        i -= 2;
        buf[i] = PAIRS[d];
        buf[i + 1] = PAIRS[d + 1];
    }
    if n >= 10 {
        let d = n as usize * 2;
        buf[i - 2] = PAIRS[d];
        buf[i - 1] = PAIRS[d + 1];
    } else {
        buf[i - 1] = b'0' + n as u8;
    }
}

/// Appends the decimal digits of `n`.
#[inline]
pub fn int(out: &mut Vec<u8>, n: u64) {
    if n < 1000 {
        let (d, len) = SMALL[n as usize];
        return put_fixed(out, &d, len as usize);
    }
    if n < 100_000_000 {
        let w = swar8(n);
        let lz = w.trailing_zeros() / 8;
        let text = ((w + ZEROS) >> (8 * lz)).to_le_bytes();
        return put_fixed(out, &text, 8 - lz as usize);
    }
    let mut buf = [0u8; 20];
    let len = digits(n);
    fill(&mut buf, n, len);
    put_fixed(out, &buf, len);
}

/// `x.round()` (half away from zero) for |x| < 2^52, without the libm
/// call: the truncation and the exact remainder.
fn round(x: f64) -> i64 {
    let t = x as i64;
    let f = x - t as f64;
    if f >= 0.5 {
        t + 1
    } else if f <= -0.5 {
        t - 1
    } else {
        t
    }
}

/// The text of a number: at most 23 bytes, kept in a fixed array so that
/// it is copied by a few moves.
pub type Text = [u8; 24];

/// Number of decimal digits of `n` < 10^9 (at least 1), by comparisons.
#[inline]
fn digits9(n: u64) -> usize {
    1 + usize::from(n >= 10)
        + usize::from(n >= 100)
        + usize::from(n >= 1_000)
        + usize::from(n >= 10_000)
        + usize::from(n >= 100_000)
        + usize::from(n >= 1_000_000)
        + usize::from(n >= 10_000_000)
        + usize::from(n >= 100_000_000)
}

/// The text [`num`] writes for `v` and its length, or None where it takes
/// the `{}` path (NaN, infinite, |v| ≥ 1e9).
#[inline(always)]
fn fast(v: f64) -> Option<(Text, usize)> {
    let x = v * 1e6;
    // Below 1e14 - 1 the rounded whole part has at most 8 digits.
    if x.is_nan() || x.abs() >= 99_999_999_999_999.0 {
        return wide(v);
    }
    let mut buf = [0u8; 24];
    let n = round(x);
    if n == 0 {
        buf[..3].copy_from_slice(b"0.0");
        return Some((buf, 3));
    }
    // Sign, at most 8 integer digits, the point, 8 decimal places of
    // which the last two are zero: at most 18 bytes.
    let mut i = usize::from(n < 0);
    buf[0] = b'-';
    let a = n.unsigned_abs();
    let whole = a / 1_000_000;
    let frac = a - whole * 1_000_000;
    if whole < 1000 {
        // Most coordinates: the integer part from the table.
        let (d, len) = SMALL[whole as usize];
        buf[i..i + 4].copy_from_slice(&d);
        i += len as usize;
    } else {
        let w = swar8(whole);
        // Leading zero digits (the low bytes), keeping at least one digit.
        let lz = (w.trailing_zeros() / 8).min(7);
        buf[i..i + 8].copy_from_slice(&((w + ZEROS) >> (8 * lz)).to_le_bytes());
        i += 8 - lz as usize;
    }
    buf[i] = b'.';
    i += 1;
    if frac == 0 {
        buf[i] = b'0';
        return Some((buf, i + 1));
    }
    let f = swar8(frac * 100);
    buf[i..i + 8].copy_from_slice(&(f + ZEROS).to_le_bytes());
    // Trailing zero digits (the high bytes): at least the two added, at
    // most seven as frac is not 0.
    let tz = (f.leading_zeros() / 8) as usize;
    Some((buf, i + 8 - tz))
}

/// [`fast`] for 1e8 ≤ |v| < 1e9 (and None beyond): digit pairs.
#[cold]
fn wide(v: f64) -> Option<(Text, usize)> {
    let x = v * 1e6;
    if x.is_nan() || x.abs() >= 1e15 {
        return None;
    }
    let mut buf = [0u8; 24];
    let n = round(x);
    // Sign, 9 integer digits, the point, 6 decimals: 17 bytes.
    let mut i = usize::from(n < 0);
    buf[0] = b'-';
    let a = n.unsigned_abs();
    let whole = a / 1_000_000;
    let len = digits9(whole);
    fill(&mut buf[i..], whole, len);
    i += len;
    buf[i] = b'.';
    i += 1;
    let frac = (a % 1_000_000) as usize;
    if frac == 0 {
        buf[i] = b'0';
        return Some((buf, i + 1));
    }
    let (p, q, r) = (frac / 10_000 * 2, frac / 100 % 100 * 2, frac % 100 * 2);
    buf[i..i + 6].copy_from_slice(&[
        PAIRS[p],
        PAIRS[p + 1],
        PAIRS[q],
        PAIRS[q + 1],
        PAIRS[r],
        PAIRS[r + 1],
    ]);
    let mut len = i + 6;
    while buf[len - 1] == b'0' {
        len -= 1;
    }
    Some((buf, len))
}

/// Appends `v` rounded to 1e-6: no `-0`, no exponent, at least one digit
/// after the point (`1.0`, `-12.345679`, `0.0`).
pub fn num(out: &mut Vec<u8>, v: f64) {
    match fast(v) {
        Some((text, len)) => put_fixed(out, &text, len),
        None => slow(out, v),
    }
}

/// The last value written in one place of a record (an axis of `to`, the
/// feed …) with its text: toolpaths repeat most coordinates from one
/// record to the next, and a repeated value is copied, not formatted.
#[derive(Clone, Copy, Debug)]
pub struct Memo {
    bits: u64,
    len: u8,
    text: Text,
}

impl Default for Memo {
    fn default() -> Memo {
        // NaN bits that `num` never caches (it caches only the texts of
        // its fast path, finite values), so the first value is always
        // formatted.
        Memo {
            bits: u64::MAX,
            len: 0,
            text: [0; 24],
        }
    }
}

impl Memo {
    /// The text [`num`] writes for `v` and its length (made only when
    /// `v` is not the last value), or None where `num` takes the `{}`
    /// path.
    #[inline]
    pub fn text(&mut self, v: f64) -> Option<(&Text, usize)> {
        let bits = v.to_bits();
        if bits != self.bits {
            let (text, len) = fast(v)?;
            self.text = text;
            self.len = len as u8;
            self.bits = bits;
        }
        Some((&self.text, self.len as usize))
    }

    /// Appends `v` as [`num`] does.
    #[inline]
    pub fn put(&mut self, out: &mut Vec<u8>, v: f64) {
        let bits = v.to_bits();
        if bits != self.bits {
            let Some((text, len)) = fast(v) else {
                return slow(out, v);
            };
            self.text = text;
            self.len = len as u8;
            self.bits = bits;
        }
        put_fixed(out, &self.text, self.len as usize);
    }
}

/// The reference: `{}` of the rounded value.
fn slow(out: &mut Vec<u8>, v: f64) {
    use std::io::Write as _;
    let r = (v * 1e6).round() / 1e6;
    let r = if r == 0.0 { 0.0 } else { r };
    if r.fract() == 0.0 && r.abs() < 1e15 {
        let _ = write!(out, "{}.0", r as i64);
    } else {
        let _ = write!(out, "{r}");
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_counted_number_is_its_digits() {
        // Repeats, steps of one across every carry up to 10^7 (and one
        // more digit), jumps back and forth, zero, the largest u64.
        let mut c = kerf_canon::digits::LineText::default();
        let mut seq: Vec<u64> = vec![0, 0, 1, 1, 1, 2, 9, 10, 10, 11];
        seq.extend(0..1_000_000);
        seq.extend(9_999_990..10_000_010);
        seq.extend([5, 4, 4, 99, 100, 7, u64::MAX - 1, u64::MAX, 0, 1]);
        let (mut got, mut want) = (Vec::new(), Vec::new());
        for n in seq {
            got.clear();
            want.clear();
            c.put(&mut got, n);
            int(&mut want, n);
            assert_eq!(got, want, "{n}");
        }
    }

    #[test]
    fn numbers_are_plain_decimals() {
        let mut s = Vec::new();
        for v in [
            1.0,
            -0.0,
            0.1 + 0.2,
            -12.3456789,
            1e-9,
            2.5e7,
            -0.0000005,
            0.0000005,
        ] {
            num(&mut s, v);
            s.push(b' ');
        }
        assert_eq!(
            s,
            b"1.0 0.0 0.3 -12.345679 0.0 25000000.0 -0.000001 0.000001 "
        );
    }

    #[test]
    fn the_integer_path_writes_what_float_formatting_writes() {
        // A fixed pseudo-random sequence (xorshift) over many magnitudes,
        // plus the edges of the fast path.
        let mut x: u64 = 0x9E37_79B9_7F4A_7C15;
        let mut vals = vec![
            999_999_999.999_999,
            -999_999_999.999_999,
            1e9,
            -1e9,
            123_456_789.123_456_7,
            0.000_000_499_999,
            f64::NAN,
            f64::INFINITY,
            1e300,
        ];
        for _ in 0..200_000 {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            let mant = (x >> 11) as f64 / (1u64 << 53) as f64;
            let exp = (x % 19) as i32 - 9;
            let sign = if x & 1 == 0 { 1.0 } else { -1.0 };
            vals.push(sign * mant * 10f64.powi(exp));
        }
        for v in vals {
            let (mut a, mut b) = (Vec::new(), Vec::new());
            num(&mut a, v);
            slow(&mut b, v);
            assert_eq!(a, b, "{v:e}");
        }
    }

    #[test]
    fn edges_of_the_rounding_and_of_the_eight_digits() {
        for v in [
            -0.0,
            0.0,
            1e-7,
            -1e-7,
            5e-7,
            -5e-7,
            4.999_999e-7,
            1.5e-6,
            0.000_001,
            0.1,
            0.000_01,
            0.5,
            -0.999_999_5,
            9.999_999_5,
            999.999_999_4,
            999.999_999_5,
            -999.999_999_5,
            1_000.000_000_4,
            99_999_999.999_999,
            99_999_999.999_999_5,
            -99_999_999.999_999_9,
            100_000_000.0,
            10_000_000.0,
            12_345_678.901_234,
            1e-300,
            f64::MIN_POSITIVE,
            f64::MAX,
            f64::NEG_INFINITY,
        ] {
            let (mut a, mut b, mut c) = (Vec::new(), Vec::new(), Vec::new());
            num(&mut a, v);
            slow(&mut b, v);
            let mut m = Memo::default();
            m.put(&mut c, v);
            m.put(&mut c, v);
            assert_eq!(a, b, "{v:e}");
            assert_eq!([&b[..], &b[..]].concat(), c, "{v:e}");
        }
        let mut s = Vec::new();
        num(&mut s, -0.0);
        num(&mut s, 4e-7);
        num(&mut s, -5e-7);
        num(&mut s, 12.5);
        assert_eq!(s, b"0.00.0-0.00000112.5");
    }

    #[test]
    fn rounding_matches_f64_round() {
        for x in [
            0.5,
            -0.5,
            1.5,
            2.5,
            -2.5,
            0.499_999_999_999_999_94,
            -0.499_999_999_999_999_94,
            4_503_599_627_370_495.5,
            123.456,
            -123.5,
            1e15 - 0.5,
        ] {
            assert_eq!(round(x), x.round() as i64, "{x}");
        }
    }

    #[test]
    fn a_memo_writes_what_num_writes() {
        let mut m = Memo::default();
        let (mut a, mut b) = (Vec::new(), Vec::new());
        for v in [1.5, 1.5, -0.0, 0.0, 2.25, 2.25, 1e300, 1e300, 1.5] {
            m.put(&mut a, v);
            num(&mut b, v);
            a.push(b' ');
            b.push(b' ');
        }
        assert_eq!(a, b);
    }

    #[test]
    fn a_memo_text_is_what_num_writes() {
        let mut m = Memo::default();
        for v in [
            1.5,
            1.5,
            -0.0,
            0.0,
            2.25,
            1e300,
            2.25,
            f64::NAN,
            2.25,
            0.1 + 0.2,
        ] {
            let mut b = Vec::new();
            num(&mut b, v);
            match m.text(v) {
                Some((t, len)) => assert_eq!(&t[..len], &b[..], "{v:e}"),
                None => assert!(!v.is_finite() || v.abs() >= 1e9, "{v:e}"),
            }
        }
    }

    #[test]
    fn digit_counts_by_comparison_are_the_counts() {
        for n in [
            0,
            9,
            10,
            99,
            100,
            999_999,
            1_000_000,
            99_999_999,
            100_000_000,
            999_999_999,
        ] {
            assert_eq!(digits9(n), n.to_string().len(), "{n}");
        }
    }

    #[test]
    fn integers() {
        let mut s = Vec::new();
        for n in [
            0,
            7,
            10,
            99,
            100,
            999,
            1000,
            65_535,
            99_999_999,
            100_000_000,
            1234567890,
            u64::MAX,
        ] {
            int(&mut s, n);
            s.push(b',');
        }
        assert_eq!(
            s,
            b"0,7,10,99,100,999,1000,65535,99999999,100000000,1234567890,18446744073709551615,"
        );
        for n in (0..2_000_000).chain((0..100_000_000).step_by(9_973)) {
            let mut a = Vec::new();
            int(&mut a, n);
            assert_eq!(a, n.to_string().as_bytes());
        }
    }
}
