//! Fixed-point number text for G-code words: a value rounded to a number
//! of decimals, always with a decimal point (`10.`, `-0.5`, `12.345`), no
//! exponent, no `-0`, trailing zeros dropped. Written straight into a byte
//! buffer without going through `fmt`, since every output block has several.

pub use kerf_canon::digits::LineText;
use kerf_canon::digits::{put_fixed, swar8, SMALL, ZEROS};

/// The integer `v × 10^dec` rounded half away from zero, saturating at
/// ±10^15 (no axis, feed or speed comes near; it keeps the text bounded).
pub fn scaled(v: f64, dec: u32) -> i64 {
    // `f64::round` is a library call on the x86-64 baseline; adding ½ with
    // the value's sign and truncating (`as` saturates, NaN gives 0) is not.
    let s = (v * POW10[dec as usize]).clamp(-1e15, 1e15);
    (s + 0.5f64.copysign(s)) as i64
}

/// The value a scaled integer stands for.
pub fn unscaled(n: i64, dec: u32) -> f64 {
    n as f64 / POW10[dec as usize]
}

/// Appends the scaled integer `n` (value × 10^dec) as decimal text.
///
/// The common case (at most 8 decimals, fewer than 10^8 in the whole part)
/// is written without a digit loop: the whole part below 1000 from a
/// table, above as eight digits at once in the lanes of one `u64`
/// (kerf-canon's `digits::swar8`), the fraction of three places or fewer from a table, of
/// more as eight digits likewise, its trailing zeros counted by the word's
/// zero bytes. The rest goes by [`put_scaled_plain`],
/// which writes the same text one digit at a time.
#[inline]
pub fn put_scaled(out: &mut Vec<u8>, n: i64, dec: u32) {
    let u = n.unsigned_abs();
    if dec > 8 {
        return put_scaled_plain(out, n, dec);
    }
    let p = POW10_U[dec as usize];
    let whole = u / p;
    if whole >= 100_000_000 {
        return put_scaled_plain(out, n, dec);
    }
    let frac = u - whole * p;
    // Sign, at most 8 whole digits, the point, 8 decimals: 18 bytes.
    let mut buf = [0u8; 24];
    buf[0] = b'-';
    let mut i = usize::from(n < 0);
    if whole < 1000 {
        let (d, len) = SMALL[whole as usize];
        buf[i..i + 4].copy_from_slice(&d);
        i += len as usize;
    } else {
        let w = swar8(whole);
        // Leading zero digits (the low bytes); whole ≥ 1000 has at most 4.
        let lz = w.trailing_zeros() / 8;
        buf[i..i + 8].copy_from_slice(&((w + ZEROS) >> (8 * lz)).to_le_bytes());
        i += 8 - lz as usize;
    }
    buf[i] = b'.';
    i += 1;
    if frac != 0 && dec <= 3 {
        // Three places or fewer (millimetres): the digits from a table.
        let (d, len) = FRAC3[(frac * POW10_U[3 - dec as usize]) as usize];
        buf[i..i + 4].copy_from_slice(&d);
        i += len as usize;
    } else if frac != 0 {
        let f = swar8(frac * POW10_U[8 - dec as usize]);
        buf[i..i + 8].copy_from_slice(&(f + ZEROS).to_le_bytes());
        // Trailing zero digits are the high bytes; frac ≠ 0 leaves one.
        i += 8 - (f.leading_zeros() / 8) as usize;
    }
    put_fixed(out, &buf, i);
}

/// [`put_scaled`] one digit at a time: any `n` and `dec`, the reference
/// the fast path is tested against.
pub fn put_scaled_plain(out: &mut Vec<u8>, n: i64, dec: u32) {
    // Built right to left in a stack buffer, appended once.
    let mut text = [0u8; 48];
    let mut at = text.len();
    let mut u = n.unsigned_abs();
    // The fraction without its trailing zeros.
    let mut frac = false;
    for _ in 0..dec {
        let d = (u % 10) as u8;
        u /= 10;
        if d != 0 || frac {
            frac = true;
            at -= 1;
            text[at] = b'0' + d;
        }
    }
    at -= 1;
    text[at] = b'.';
    loop {
        at -= 1;
        text[at] = b'0' + (u % 10) as u8;
        u /= 10;
        if u == 0 {
            break;
        }
    }
    if n < 0 {
        at -= 1;
        text[at] = b'-';
    }
    out.extend_from_slice(&text[at..]);
}

/// The three decimal places of 0..1000 (`7` → `007`) without their
/// trailing zeros (`120` → `12`), padded to four bytes, and their number.
const FRAC3: [([u8; 4], u8); 1000] = {
    let mut t = [([0u8; 4], 0u8); 1000];
    let mut n = 0;
    while n < 1000 {
        let d = [
            b'0' + (n / 100) as u8,
            b'0' + (n / 10 % 10) as u8,
            b'0' + (n % 10) as u8,
            0,
        ];
        let len = if n % 100 == 0 {
            1
        } else if n % 10 == 0 {
            2
        } else {
            3
        };
        t[n] = (d, len);
        n += 1;
    }
    t
};

const POW10_U: [u64; 9] = [
    1,
    10,
    100,
    1_000,
    10_000,
    100_000,
    1_000_000,
    10_000_000,
    100_000_000,
];

/// Appends `v` rounded to `dec` decimals.
pub fn put(out: &mut Vec<u8>, v: f64, dec: u32) {
    put_scaled(out, scaled(v, dec), dec);
}

/// Appends an unsigned integer (M, T, O numbers, source lines), with
/// leading zeros to `min_digits`.
#[inline]
pub fn put_uint(out: &mut Vec<u8>, u: u64, min_digits: usize) {
    if min_digits <= 1 && u < 100_000_000 {
        if u < 1000 {
            let (d, len) = SMALL[u as usize];
            return put_fixed(out, &d, len as usize);
        }
        let w = swar8(u);
        let lz = w.trailing_zeros() / 8;
        return put_fixed(
            out,
            &((w + ZEROS) >> (8 * lz)).to_le_bytes(),
            8 - lz as usize,
        );
    }
    put_uint_plain(out, u, min_digits);
}

/// [`put_uint`] one digit at a time (any value and width).
pub fn put_uint_plain(out: &mut Vec<u8>, mut u: u64, min_digits: usize) {
    let mut digits = [0u8; 20];
    let mut len = 0;
    loop {
        digits[len] = b'0' + (u % 10) as u8;
        u /= 10;
        len += 1;
        if u == 0 && len >= min_digits {
            break;
        }
    }
    for i in (0..len).rev() {
        out.push(digits[i]);
    }
}

const POW10: [f64; 10] = [1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9];

#[cfg(test)]
mod tests {
    use super::*;

    fn text(v: f64, dec: u32) -> String {
        let mut out = Vec::new();
        put(&mut out, v, dec);
        String::from_utf8(out).unwrap()
    }

    #[test]
    fn decimal_point_always_trailing_zeros_never() {
        assert_eq!(text(10.0, 3), "10.");
        assert_eq!(text(0.0, 3), "0.");
        assert_eq!(text(-0.0004, 3), "0.");
        assert_eq!(text(12.345, 3), "12.345");
        assert_eq!(text(12.3, 4), "12.3");
        assert_eq!(text(-0.5, 3), "-0.5");
        assert_eq!(text(-0.001, 3), "-0.001");
        assert_eq!(text(0.0625, 3), "0.063");
        assert_eq!(text(99999.9995, 3), "100000.");
        assert_eq!(text(1234.5678, 0), "1235.");
    }

    #[test]
    fn rounds_half_away_from_zero() {
        assert_eq!(scaled(0.0015, 3), 2);
        assert_eq!(scaled(-0.0015, 3), -2);
        assert_eq!(scaled(f64::NAN, 3), 0);
        assert_eq!(scaled(1e30, 3), 1_000_000_000_000_000);
        assert_eq!(unscaled(-12345, 3), -12.345);
    }

    fn plain(n: i64, dec: u32) -> Vec<u8> {
        let mut out = Vec::new();
        put_scaled_plain(&mut out, n, dec);
        out
    }

    fn fast(n: i64, dec: u32) -> Vec<u8> {
        // Written after other text, as in a block.
        let mut out = b"X".to_vec();
        put_scaled(&mut out, n, dec);
        out.remove(0);
        out
    }

    #[test]
    fn the_fast_text_at_its_edges() {
        // Worked by hand: the table's end, the eight-digit word's ends, the
        // fraction's full width and the fallback beyond.
        let cases: [(i64, u32, &str); 16] = [
            (0, 3, "0."),
            (999_999, 3, "999.999"),
            (1_000_000, 3, "1000."),
            (-1_000_001, 3, "-1000.001"),
            (99_999_999_999, 3, "99999999.999"),
            (100_000_000_000, 3, "100000000."),
            (1_000_000_000_000_000, 3, "1000000000000."),
            (-1_000_000_000_000_000, 3, "-1000000000000."),
            (5, 4, "0.0005"),
            (120, 4, "0.012"),
            (7, 0, "7."),
            (-123_456_789, 8, "-1.23456789"),
            (1, 9, "0.000000001"),
            (10, 1, "1."),
            (i64::MIN + 1, 3, "-9223372036854775.807"),
            (1234, 2, "12.34"),
        ];
        for (n, dec, want) in cases {
            assert_eq!(String::from_utf8(fast(n, dec)).unwrap(), want, "{n} {dec}");
            assert_eq!(String::from_utf8(plain(n, dec)).unwrap(), want, "{n} {dec}");
        }
    }

    #[test]
    fn the_fast_text_is_the_plain_text() {
        // Random values of every size (a xorshift), every decimal count.
        let mut x: u64 = 0x9E37_79B9_7F4A_7C15;
        for k in 0..200_000u64 {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            let bits = 1 + (k % 60) as u32;
            let mut n = (x >> (64 - bits)) as i64;
            if x & 1 == 1 {
                n = -n;
            }
            let dec = (k / 60 % 10) as u32;
            assert_eq!(fast(n, dec), plain(n, dec), "{n} {dec}");
            let u = n.unsigned_abs();
            for min in [0, 1, 4] {
                let (mut a, mut b) = (Vec::new(), Vec::new());
                put_uint(&mut a, u, min);
                put_uint_plain(&mut b, u, min);
                assert_eq!(a, b, "{u} {min}");
            }
        }
    }

    #[test]
    fn the_counted_line_text_is_the_plain_text() {
        // Runs of consecutive lines across every carry (9, 99, 999999,
        // u64::MAX - 1), jumps back and forward, repeats.
        let starts = [0u64, 1, 5, 95, 995, 999_990, 12_345, u64::MAX - 3];
        let mut lt = LineText::default();
        let (mut a, mut b) = (Vec::new(), Vec::new());
        for s in starts {
            for u in (s..s.saturating_add(20)).chain([s, s, 7, s.wrapping_add(2)]) {
                lt.put(&mut a, u);
                a.push(b' ');
                put_uint_plain(&mut b, u, 1);
                b.push(b' ');
            }
        }
        assert_eq!(String::from_utf8(a).unwrap(), String::from_utf8(b).unwrap());
        let mut one = Vec::new();
        let mut lt = LineText::default();
        for u in [9, 10, 11, 99, 100] {
            lt.put(&mut one, u);
            one.push(b',');
        }
        assert_eq!(one, b"9,10,11,99,100,");
    }

    #[test]
    fn integers_with_leading_zeros() {
        let mut out = Vec::new();
        put_uint(&mut out, 1, 4);
        out.push(b' ');
        put_uint(&mut out, 30, 0);
        out.push(b' ');
        put_uint(&mut out, 0, 2);
        assert_eq!(out, b"0001 30 00");
    }
}
