//! `LagMemo`: the last results of [`super::lag_phase`], kept by their
//! arguments. A drilling program repeats the same rapids (the same
//! distances, hence the same trapezoid phases) thousands of times, and
//! each phase of each axis's position loop costs an `exp_m1`; a result
//! read back is the same `f64` pair the function returns, so the times
//! do not change by a bit.

use super::lag_phase;

/// Entries (a power of two).
const N: usize = 64;

/// A direct-mapped table of `lag_phase(k, v0, a, dt)` for one planner's
/// gain `k`, keyed by the bits of `(v0, a, dt)`.
#[derive(Clone, Debug)]
pub(super) struct LagMemo {
    k: f64,
    /// `dt` is never 0 in a stored key (only `dt > 0` is memoized), so an
    /// all-zero key is an empty slot.
    keys: [[u64; 3]; N],
    vals: [(f64, f64); N],
}

impl LagMemo {
    /// An empty table for gain `k`.
    pub(super) fn new(k: f64) -> LagMemo {
        LagMemo {
            k,
            keys: [[0; 3]; N],
            vals: [(1.0, 0.0); N],
        }
    }

    /// `lag_phase(k, v0, a, dt)`, from the table when it holds it.
    #[inline]
    pub(super) fn get(&mut self, v0: f64, a: f64, dt: f64) -> (f64, f64) {
        if dt <= 0.0 || dt.is_nan() {
            return lag_phase(self.k, v0, a, dt);
        }
        let key = [v0.to_bits(), a.to_bits(), dt.to_bits()];
        let h = (key[2] ^ key[0].rotate_left(21) ^ key[1].rotate_left(42))
            .wrapping_mul(0x9E37_79B9_7F4A_7C15);
        let i = (h >> 58) as usize & (N - 1);
        if self.keys[i] == key {
            return self.vals[i];
        }
        let r = lag_phase(self.k, v0, a, dt);
        self.keys[i] = key;
        self.vals[i] = r;
        r
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every value read back is the one the function computes, bit for
    /// bit, for repeated and colliding arguments alike.
    #[test]
    fn read_back_equals_the_function() {
        let k = 30.0;
        let mut m = LagMemo::new(k);
        for _ in 0..3 {
            for i in 0..500 {
                let dt = 0.001 * (1 + i % 97) as f64;
                let v0 = (i % 7) as f64 * 12.5;
                let a = if i % 3 == 0 {
                    0.0
                } else {
                    -800.0 + (i % 5) as f64
                };
                let direct = lag_phase(k, v0, a, dt);
                let got = m.get(v0, a, dt);
                assert_eq!(got.0.to_bits(), direct.0.to_bits());
                assert_eq!(got.1.to_bits(), direct.1.to_bits());
            }
        }
        // A zero or negative phase is not stored and gives the function's answer.
        assert_eq!(m.get(5.0, 1.0, 0.0), (1.0, 0.0));
        assert_eq!(m.get(5.0, 1.0, -1.0), (1.0, 0.0));
    }
}
