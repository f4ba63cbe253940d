//! HX G107 cylindrical interpolation in the output. Its moves reach the
//! expander already as machine Z/Y and C (degrees; arcs as chords), so
//! the path needs nothing; what G107 changes is the meaning of F, which
//! is the speed along the developed surface (000 §4.7: C counts as the
//! arc length C·π·r/180 on the cylinder of radius r).
//!
//! - `--to fanuc` (the same kind of control, which has G107): the output
//!   selects G107 again around those moves (`G18 G107 C57.299` …
//!   `G107 C0`), so the control times them as the original.
//! - `--to linuxcnc` (no G107): each feed is scaled so that a control
//!   timing a move by its linear axes (by the rotary axes when no linear
//!   axis moves), as LinuxCNC and kerf's planner do outside G107, takes
//!   the time the original takes on the surface.
//!
//! G112 polar moves are left as they are: kerf's planner times them by
//! their machine axes, the same with or without G112.

use std::io::Write;

use kerf_canon::{Axis, Feed, Motion, Pos, RotaryMode, NAXES};

use crate::expander::{Expander, Written};
use crate::num;
use crate::target::Target;

/// The length of the move from `p0` to `p1` as a control without G107
/// times it (the linear axes; the rotary axes, degrees as mm, when no
/// linear axis moves) over its length on the developed surface, where C
/// counts `mm_per_deg` mm a degree; 1 for a move that does not move.
pub(crate) fn plain_over_surface(p0: &Pos, p1: &Pos, mm_per_deg: f64) -> f64 {
    let d: [f64; NAXES] = std::array::from_fn(|i| p1[i] - p0[i]);
    let sq = |r: std::ops::Range<usize>| r.map(|i| d[i] * d[i]).sum::<f64>();
    let linear = sq(0..3);
    let plain = if linear > 0.0 { linear } else { sq(3..NAXES) };
    let c = Axis::C as usize;
    let surface = sq(0..NAXES) - d[c] * d[c] + (d[c] * mm_per_deg).powi(2);
    if surface > 0.0 {
        (plain / surface).sqrt()
    } else {
        1.0
    }
}

impl<W: Write> Expander<W> {
    /// The words for a change of the rotary-axis interpolation.
    pub(crate) fn rotary_words(&mut self, r: RotaryMode) -> Written {
        let was = std::mem::replace(&mut self.rotary, r);
        if self.sp().target == Target::LinuxCnc {
            return Written::Nothing;
        }
        match (was, r) {
            (_, RotaryMode::Cylinder { radius, plane }) => {
                self.plane_code(plane);
                self.code("G107");
                self.buf().extend_from_slice(b" C");
                let dec = self.sp().decimals;
                num::put(self.buf(), radius, dec);
                Written::Block
            }
            (RotaryMode::Cylinder { .. }, _) => {
                self.code("G107");
                self.buf().extend_from_slice(b" C0");
                Written::Block
            }
            _ => Written::Nothing,
        }
    }

    /// The feed to write for a move in G107 on a target without G107;
    /// `f` itself otherwise (and for inverse time, a time already).
    pub(crate) fn surface_feed(&self, f: Feed, m: &Motion) -> Feed {
        let RotaryMode::Cylinder { radius, .. } = self.rotary else {
            return f;
        };
        if self.sp().target != Target::LinuxCnc {
            return f;
        }
        let k = radius * std::f64::consts::PI / 180.0;
        let r = plain_over_surface(&self.prev_mto(), &m.mto, k);
        match f {
            Feed::PerMin(v) => Feed::PerMin(v * r),
            Feed::PerRev(v) => Feed::PerRev(v * r),
            Feed::InverseTime(v) => Feed::InverseTime(v),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_ratio_is_the_plain_length_over_the_developed_one() {
        // r = 10: π/18 mm a degree. Z20 C180: the surface length
        // √(20² + (10π)²) = 37.2419, timed plain by Z alone: 20/37.2419.
        let pi = std::f64::consts::PI;
        let k = 10.0 * pi / 180.0;
        let to = [0.0, 0.0, 20.0, 0.0, 0.0, 180.0];
        let r = plain_over_surface(&[0.0; 6], &to, k);
        assert!(
            (r - 20.0 / (400.0 + 100.0 * pi * pi).sqrt()).abs() < 1e-12,
            "{r}"
        );
        // C90 alone: plain 90 "mm" (degrees), surface 10π/2 = 15.708.
        let r = plain_over_surface(&[0.0; 6], &[0.0, 0.0, 0.0, 0.0, 0.0, 90.0], k);
        assert!((r - 90.0 / 15.707_963_3).abs() < 1e-6, "{r}");
        // Z alone is the same length both ways; no move is 1.
        let r = plain_over_surface(&[0.0; 6], &[0.0, 0.0, 5.0, 0.0, 0.0, 0.0], k);
        assert_eq!(r, 1.0);
        assert_eq!(plain_over_surface(&[1.0; 6], &[1.0; 6], k), 1.0);
    }
}
