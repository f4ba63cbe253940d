//! Fixed-point number text for G-code words: a value rounded to a number
//! of decimals, always with a decimal point (`10.`, `-0.5`, `12.345`), no
//! exponent, no `-0`, trailing zeros dropped. Written straight into a byte
//! buffer without going through `fmt`, since every output block has several.

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
pub fn put_scaled(out: &mut Vec<u8>, n: i64, dec: u32) {
    // Built right to left in a stack buffer, appended once.
    let mut text = [0u8; 32];
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

/// Appends `v` rounded to `dec` decimals.
pub fn put(out: &mut Vec<u8>, v: f64, dec: u32) {
    put_scaled(out, scaled(v, dec), dec);
}

/// Appends an unsigned integer (M, T, O numbers).
pub fn put_uint(out: &mut Vec<u8>, mut u: u64, min_digits: usize) {
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
