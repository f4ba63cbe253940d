//! HX G107 cylindrical and G112 polar interpolation in the output. Its moves reach the
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
//! G112 polar interpolation is the same on every target: its moves are
//! written as machine X and C (the output has no G112 plane to put them
//! in), so each F is scaled as for LinuxCNC's G107, from the move's
//! length on the face (its chord in the Cartesian X-C plane).

use std::io::Write;

use kerf_canon::{Feed, Motion, Pos, RotaryMode, NAXES};

use crate::expander::{Expander, Written};
use crate::num;
use crate::target::Target;

/// The length of a move `d` (per axis) as a control without G112/G107
/// times it (kerf-canon's machine rule).
pub(crate) fn plain_len(d: &Pos) -> f64 {
    kerf_canon::geom::machine_len(&[0.0; NAXES], d)
}

/// The feed factor that makes a control without G112/G107 take the
/// original's time: the move's plain length (`plain`, of the output's
/// own numbers) over its length on the programmed surface in `mode`
/// (from `p0` to `p1`, machine positions; `r0`, `r1` the work X at its
/// ends). 1 for a move without length or outside both modes.
pub(crate) fn feed_factor(
    mode: RotaryMode,
    plain: f64,
    p0: &Pos,
    p1: &Pos,
    r0: f64,
    r1: f64,
) -> f64 {
    match mode.programmed_len(p0, p1, r0, r1) {
        Some(surface) if surface > 0.0 && plain > 0.0 => plain / surface,
        _ => 1.0,
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

    /// The feed to write for a move in G112 (any target: the output
    /// writes machine X and C, not G112's plane) or in G107 on a target
    /// without G107; `f` itself otherwise (and for inverse time, a time
    /// already).
    pub(crate) fn surface_feed(&self, f: Feed, m: &Motion) -> Feed {
        let scaled = match self.rotary {
            RotaryMode::Off => false,
            RotaryMode::Polar => true,
            RotaryMode::Cylinder { .. } => self.sp().target == Target::LinuxCnc,
        };
        if !scaled {
            return f;
        }
        // The start's work X in the move's own work system (as the
        // planner reckons it).
        let p0 = self.prev_mto();
        let r0 = p0[0] + (m.to[0] - m.mto[0]);
        // The plain length the reading control will time: of the
        // numbers written (a chord's X can move less than a micrometre
        // more or less than the original's).
        let plain = plain_len(&self.written_move(&m.to));
        let r = feed_factor(self.rotary, plain, &p0, &m.mto, r0, m.to[0]);
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
    fn the_plain_length_is_the_linear_axes_or_else_the_rotary() {
        assert_eq!(plain_len(&[3.0, 0.0, 4.0, 0.0, 0.0, 90.0]), 5.0);
        assert_eq!(plain_len(&[0.0, 0.0, 0.0, 0.0, 0.0, 90.0]), 90.0);
        assert_eq!(plain_len(&[0.0; 6]), 0.0);
    }

    #[test]
    fn the_factor_is_the_plain_length_over_the_developed_one() {
        // r = 10: π/18 mm a degree. Z20 C180: the surface length
        // √(20² + (10π)²) = 37.2419, timed plain by Z alone: 20/37.2419.
        let pi = std::f64::consts::PI;
        let cyl = RotaryMode::Cylinder {
            radius: 10.0,
            plane: kerf_canon::Plane::ZX,
        };
        let f = |mode, to: Pos| feed_factor(mode, plain_len(&to), &[0.0; 6], &to, 0.0, 0.0);
        let r = f(cyl, [0.0, 0.0, 20.0, 0.0, 0.0, 180.0]);
        assert!(
            (r - 20.0 / (400.0 + 100.0 * pi * pi).sqrt()).abs() < 1e-12,
            "{r}"
        );
        // C90 alone: plain 90 "mm" (degrees), surface 10π/2 = 15.708.
        let r = f(cyl, [0.0, 0.0, 0.0, 0.0, 0.0, 90.0]);
        assert!((r - 90.0 / (5.0 * pi)).abs() < 1e-12, "{r}");
        // Z alone is the same length both ways; no move is 1, and so is
        // any move outside both modes.
        assert_eq!(f(cyl, [0.0, 0.0, 5.0, 0.0, 0.0, 0.0]), 1.0);
        assert_eq!(f(cyl, [0.0; 6]), 1.0);
        assert_eq!(f(RotaryMode::Off, [1.0, 0.0, 0.0, 0.0, 0.0, 90.0]), 1.0);
    }

    #[test]
    fn a_polar_move_is_timed_plain_by_its_x() {
        // 000 §4.6: X20 C0 to the virtual (20, 10): X √500, C 26.565°,
        // 10 mm on the face; plain, X alone moves √500 − 20 = 2.36068 mm.
        let r1 = 500f64.sqrt();
        let to = [r1, 0.0, 0.0, 0.0, 0.0, 26.565_051_177];
        let from = [20.0, 0.0, 0.0, 0.0, 0.0, 0.0];
        let r = feed_factor(RotaryMode::Polar, r1 - 20.0, &from, &to, 20.0, r1);
        assert!((r - (r1 - 20.0) / 10.0).abs() < 1e-9, "{r}");
    }
}
