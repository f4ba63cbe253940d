//! The lowest point of a ball end mill's sweep on a vertical line, as the
//! lower intersection of the line with a capsule: the ball's centre runs
//! along the segment `C(t) = P(t) + (0, 0, R)`, every point within R of
//! it is inside the swept sphere, and the swept envelope over (x, y) is
//! the lowest z at distance R from the segment. One square root per cell
//! (the infinite cylinder's lower root), two more where the lowest point
//! is on an end sphere; the constants of a row are worked out once.
//!
//! It gives the same heights as [`crate::envelope::Sweep::tool_above`]
//! (the minimum of `z(t) + f(ρ(t))` over t) and is used by the height
//! field for ball end mills on moves with a horizontal component of at
//! least [`MIN_RUN`] (a steeper move uses the general evaluation).

use crate::envelope::Sweep;

/// Least horizontal length of a move for the capsule evaluation, mm.
pub const MIN_RUN: f64 = 1e-3;

/// A ball end mill's straight move prepared for the capsule evaluation.
#[derive(Clone, Copy, Debug)]
pub struct BallSweep {
    /// The ball's centre at the start.
    c0: [f64; 3],
    /// The move.
    d: [f64; 3],
    /// Squared horizontal and whole lengths of the move.
    l2: f64,
    l3sq: f64,
    inv_l3sq: f64,
    inv_l2: f64,
    r2: f64,
}

/// The terms of one row (a line of constant y).
#[derive(Clone, Copy, Debug)]
pub struct BallRow {
    wy: f64,
    wy2: f64,
    wy1: f64,
}

impl BallSweep {
    /// A ball of radius `r` along `s`, or None when the move's horizontal
    /// length is below [`MIN_RUN`].
    pub fn new(s: &Sweep, r: f64) -> Option<BallSweep> {
        let d = [s.p1[0] - s.p0[0], s.p1[1] - s.p0[1], s.p1[2] - s.p0[2]];
        let l2 = d[0] * d[0] + d[1] * d[1];
        if l2 < MIN_RUN * MIN_RUN {
            return None;
        }
        let l3sq = l2 + d[2] * d[2];
        Some(BallSweep {
            c0: [s.p0[0], s.p0[1], s.p0[2] + r],
            d,
            l2,
            l3sq,
            inv_l3sq: 1.0 / l3sq,
            inv_l2: 1.0 / l2,
            r2: r * r,
        })
    }

    /// The row at `y`.
    #[inline]
    pub fn row(&self, y: f64) -> BallRow {
        let wy = y - self.c0[1];
        BallRow {
            wy,
            wy2: wy * wy,
            wy1: (wy - self.d[1]) * (wy - self.d[1]),
        }
    }

    /// The lowest point of the tool over (x, row's y), or None when the
    /// tool does not pass over it.
    #[inline]
    pub fn lowest(&self, row: &BallRow, x: f64) -> Option<f64> {
        let wx = x - self.c0[0];
        let h2 = wx * wx + row.wy2;
        let k = wx * self.d[0] + row.wy * self.d[1];
        let dz = self.d[2];
        // The line (x, y, c0z + ζ) at distance R from the move's line:
        // l2 ζ² - 2 k dz ζ + c = 0.
        let c = self.l3sq * (h2 - self.r2) - k * k;
        let q = k * dz;
        let disc = q * q - self.l2 * c;
        if disc < 0.0 {
            return None;
        }
        let s = disc.sqrt();
        // The lower root, without cancellation.
        let zeta = if q >= 0.0 && q + s > 0.0 {
            c / (q + s)
        } else {
            (q - s) * self.inv_l2
        };
        let t = (k + zeta * dz) * self.inv_l3sq;
        if (0.0..=1.0).contains(&t) {
            return Some(self.c0[2] + zeta);
        }
        // Otherwise the lowest point is on an end sphere.
        let wx1 = wx - self.d[0];
        let h1 = wx1 * wx1 + row.wy1;
        let mut best: Option<f64> = None;
        if h2 <= self.r2 {
            best = Some(self.c0[2] - (self.r2 - h2).sqrt());
        }
        if h1 <= self.r2 {
            let z = self.c0[2] + dz - (self.r2 - h1).sqrt();
            best = Some(best.map_or(z, |b| b.min(z)));
        }
        best
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shape::Shape;
    use crate::tool::{MillKind, MillTool};
    use proptest::prelude::*;

    fn ball(r: f64) -> Shape {
        Shape::of(&MillTool {
            kind: MillKind::Ball,
            ..MillTool::flat(r)
        })
    }

    #[test]
    fn a_level_slot_and_a_ramp_by_hand() {
        // R 3 along X at z 0: over a point 2 mm off the path the ball's
        // surface is 3 - √(9 - 4) above the tip.
        let s = Sweep::new([0.0, 0.0, 0.0], [10.0, 0.0, 0.0]);
        let b = BallSweep::new(&s, 3.0).unwrap();
        let z = b.lowest(&b.row(2.0), 5.0).unwrap();
        assert!((z - (3.0 - 5f64.sqrt())).abs() < 1e-12, "{z}");
        assert_eq!(b.lowest(&b.row(3.01), 5.0), None);
        // Ramp down 45° from (0,0,0) to (10,0,-10): on the path (y 0) at
        // x 5 the lowest point is where the sphere's normal is vertical,
        // i.e. the lowest point of the sphere centred on the axis through
        // the line: z = c(t) - R where the capsule's lower side is at
        // R √2 below the centre line along the vertical: -5 + 3 - 3√2.
        let s = Sweep::new([0.0, 0.0, 0.0], [10.0, 0.0, -10.0]);
        let b = BallSweep::new(&s, 3.0).unwrap();
        let z = b.lowest(&b.row(0.0), 5.0).unwrap();
        assert!((z - (-5.0 + 3.0 - 3.0 * 2f64.sqrt())).abs() < 1e-12, "{z}");
        // Beyond the low end the end sphere: x 12 is 2 mm past (10, -10).
        let z = b.lowest(&b.row(0.0), 12.0).unwrap();
        assert!((z - (-10.0 + 3.0 - 5f64.sqrt())).abs() < 1e-12, "{z}");
        // A move steeper than MIN_RUN is left to the general evaluation.
        assert!(BallSweep::new(&Sweep::new([0.0; 3], [1e-4, 0.0, -5.0]), 3.0).is_none());
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(4000))]
        /// On random moves and points the capsule evaluation agrees with
        /// the general one (the minimum of z(t) + f(ρ(t))).
        #[test]
        fn agrees_with_the_general_envelope(
            p0 in prop::array::uniform3(-10.0f64..10.0),
            d in prop::array::uniform3(-6.0f64..6.0),
            q in prop::array::uniform2(-16.0f64..16.0),
            r in 0.2f64..6.0,
        ) {
            let p1 = [p0[0] + d[0], p0[1] + d[1], p0[2] + d[2]];
            let s = Sweep::new(p0, p1);
            let Some(b) = BallSweep::new(&s, r) else { return Ok(()); };
            let fast = b.lowest(&b.row(q[1]), q[0]);
            let slow = s.tool_above(&ball(r), q[0], q[1], f64::INFINITY);
            match (fast, slow) {
                (Some(f), Some(g)) => prop_assert!((f - g).abs() < 1e-9, "{f} {g}"),
                (None, None) => {}
                (f, g) => {
                    // Only on the rim: the point within 1e-9 of R from the
                    // XY segment.
                    let (vx, vy) = (d[0], d[1]);
                    let t = (((q[0] - p0[0]) * vx + (q[1] - p0[1]) * vy) / (vx * vx + vy * vy))
                        .clamp(0.0, 1.0);
                    let e = (q[0] - p0[0] - t * vx).hypot(q[1] - p0[1] - t * vy);
                    prop_assert!((e - r).abs() < 1e-6, "{f:?} {g:?} at {e} of {r}");
                }
            }
        }
    }
}
