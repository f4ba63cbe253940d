//! An upper bound of a junction's turn angle from the chord of its unit
//! tangents, so that the planner can skip the `acos` when even that angle
//! would not lower the junction speed.
//!
//! With `c` the cosine of the turn and `s = √(2·(1 − c))` (the length of
//! `u2 − u1` for unit tangents, `2·sin(θ/2)`), the turn `θ = acos(c)` in
//! [0, π] satisfies `θ ≤ s·π/2` (`sin x ≥ 2x/π` on [0, π/2]); for a
//! smaller chord `sin x ≥ x·(1 − x²/6)` gives tighter factors. Each
//! factor below is its exact bound rounded up by at least 1e-4, far more
//! than the few units in the last place by which `s` and `acos` are
//! rounded.

/// An angle, rad, no smaller than `acos(c)` for the `c` whose chord is
/// `s` (`s = √(max(2·(1 − c), 0))`, as the planner computes it).
pub(super) fn turn_bound(s: f64) -> f64 {
    // s ≤ 0.1: θ/2 ≤ asin(0.05) = 0.050021, 1/(1 − 0.050021²/6) = 1.000417.
    // s ≤ 1.42: θ/2 ≤ asin(0.71) = 0.789498, 1/(1 − 0.789498²/6) = 1.115928.
    if s <= 0.1 {
        s * 1.0006
    } else if s <= 1.42 {
        s * 1.1161
    } else {
        s * (std::f64::consts::FRAC_PI_2 * 1.0001)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The chord as the planner computes it from the cosine.
    fn chord(c: f64) -> f64 {
        (2.0 * (1.0 - c)).max(0.0).sqrt()
    }

    #[test]
    fn the_bound_is_never_below_the_angle() {
        // Cosines over the whole range, densest near 1 (small turns,
        // where 1 − c cancels) and near −1 (reversals).
        let mut cs = vec![1.0, -1.0, 0.0, 0.995, 0.755];
        for i in 1..=200_000 {
            let x = i as f64 / 200_000.0;
            cs.push(1.0 - x * x * 2.0);
            cs.push(1.0 - 1e-16 * i as f64);
            cs.push(-1.0 + 1e-12 * i as f64);
        }
        for c in cs {
            let c: f64 = c.clamp(-1.0, 1.0);
            let (th, b) = (c.acos(), turn_bound(chord(c)));
            assert!(b >= th, "c = {c}: acos {th} > bound {b}");
        }
    }

    #[test]
    fn the_bound_is_close_for_small_turns() {
        // 1° turn: the bound is within 0.1 % of the angle, so the check
        // it serves keeps almost every junction where the curvature limit
        // cannot bind.
        let th = 1f64.to_radians();
        let b = turn_bound(chord(th.cos()));
        assert!(b >= th && b < th * 1.001, "{b} vs {th}");
        // A right angle (chord √2): at most 11.7 % above.
        let b = turn_bound(chord(0.0));
        let right = std::f64::consts::FRAC_PI_2;
        assert!(b >= right && b < right * 1.117, "{b}");
    }
}
