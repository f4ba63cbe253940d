//! The smaller of a running bound and a candidate, without the NaN
//! handling of `f64::min` (one `minsd` instead of a compare and a blend).

/// `bound.min(x)` for a `bound` that is not NaN: `x` when it is below
/// `bound`, else `bound` (a NaN `x` is ignored, as `f64::min` ignores it).
/// The two differ only for a NaN `bound` or for zeros of opposite signs;
/// the planner's bounds are speeds and accelerations that start as a
/// number (a feed, a segment's speed, infinity) and its candidates are
/// quotients, products and square roots of non-negative values, so
/// neither case occurs and the result is `bound.min(x)` bit for bit.
#[inline(always)]
pub(super) fn lower(bound: f64, x: f64) -> f64 {
    if x < bound {
        x
    } else {
        bound
    }
}

#[cfg(test)]
mod tests {
    use super::lower;

    #[test]
    fn equals_f64_min_for_a_bound_that_is_a_number() {
        let specials = [
            0.0,
            f64::MIN_POSITIVE,
            5e-324,
            1e-6,
            1.0,
            1.0 + f64::EPSILON,
            400.0,
            f64::MAX,
            f64::INFINITY,
            f64::NAN,
        ];
        let mut x: u64 = 0x9e37_79b9_7f4a_7c15;
        let mut rnd = move || {
            x = x
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (x >> 11) as f64 / (1u64 << 53) as f64 * 1000.0
        };
        let mut vals: Vec<f64> = specials.to_vec();
        vals.extend((0..200).map(|_| rnd()));
        let mut below = 0;
        for &b in vals.iter().filter(|b| !b.is_nan()) {
            for &c in &vals {
                let (got, want) = (lower(b, c), b.min(c));
                assert_eq!(got.to_bits(), want.to_bits(), "{b} {c}");
                below += usize::from(c < b);
            }
        }
        // Both outcomes are exercised.
        assert!(below > 1000, "{below}");
        // The NaN candidate leaves the bound, as f64::min does.
        assert_eq!(lower(2.0, f64::NAN), 2.0);
        assert_eq!(lower(f64::INFINITY, 3.5), 3.5);
    }
}
