//! Pure geometry of the interpolations that drive a rotary axis from a
//! Cartesian program: G112 polar coordinate interpolation (000 §4.6) and
//! G107 cylindrical interpolation (000 §4.7).
//!
//! A move is a [`Path`] in a *virtual plane*, parametrised by `t` in
//! [0, 1]. The machine follows it as a chain of short chords in its own
//! axes; each chord is straight in machine axes and stays within a
//! tolerance of the virtual path.
//!
//! Polar interpolation: the virtual plane is (x, y) = (linear axis X, the
//! virtual axis named C), centred on the rotary axis. A machine position is
//! `(X, θ)`: X a *signed* radius and θ the rotary angle in degrees counted
//! from the angle the rotary axis had at G112. `(X, θ)` and `(-X, θ+180°)`
//! are the same virtual point; the machine takes the one that continues its
//! motion (θ changes by at most 90°), so a line through the centre keeps θ
//! and carries X through zero.
//!
//! Cylindrical interpolation: the virtual plane is the developed surface of
//! the cylinder; a rotary angle θ is the length θ·π·r/180 on it. That map is
//! linear, so only arcs need chords (see [`arc_chords`]).

use std::f64::consts::PI;

/// Most chords one move is cut into (a bound on memory and time: past it
/// the chord tolerance is relaxed rather than the move refused).
pub const MAX_CHORDS: usize = 1 << 16;

/// Bisection depth that gives [`MAX_CHORDS`].
const MAX_DEPTH: u32 = 16;

/// Below this distance from the centre (mm) a virtual point is *at* the
/// centre: its angle is undefined and the machine keeps the angle it has.
const CENTRE_EPS: f64 = 1e-9;

/// A move in the virtual plane.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Path {
    /// Straight from `s` to `e`.
    Line { s: (f64, f64), e: (f64, f64) },
    /// Circular about `c` with radius `r`, from angle `a0` (radians)
    /// through the signed `sweep` (radians, > 0 counter-clockwise), ending
    /// exactly at `e`.
    Arc {
        c: (f64, f64),
        r: f64,
        a0: f64,
        sweep: f64,
        e: (f64, f64),
    },
}

impl Path {
    /// The point at parameter `t` (0 = start, 1 = the exact end point).
    pub fn at(&self, t: f64) -> (f64, f64) {
        match *self {
            Path::Line { s, e } => {
                if t >= 1.0 {
                    e
                } else {
                    (s.0 + t * (e.0 - s.0), s.1 + t * (e.1 - s.1))
                }
            }
            Path::Arc { c, r, a0, sweep, e } => {
                if t >= 1.0 {
                    e
                } else {
                    let a = a0 + t * sweep;
                    (c.0 + r * a.cos(), c.1 + r * a.sin())
                }
            }
        }
    }
}

/// The virtual point of machine position `(X, θ°)`.
pub fn polar_virtual(m: (f64, f64)) -> (f64, f64) {
    let th = m.1.to_radians();
    (m.0 * th.cos(), m.0 * th.sin())
}

/// `phi` (degrees) plus the whole turns that bring it nearest to `near`.
fn unwrap_near(phi: f64, near: f64) -> f64 {
    phi + 360.0 * ((near - phi) / 360.0).round()
}

/// The machine position `(X, θ°)` of virtual point `p` that continues from
/// machine position `prev`: of the two representations the one whose angle
/// is nearest `prev`'s (ties keep the sign of `prev`'s X). At the centre
/// the angle is kept and X is 0.
pub fn polar_machine(p: (f64, f64), prev: (f64, f64)) -> (f64, f64) {
    let rho = p.0.hypot(p.1);
    if rho < CENTRE_EPS {
        return (0.0, prev.1);
    }
    let phi = p.1.atan2(p.0).to_degrees();
    let a = unwrap_near(phi, prev.1);
    let b = unwrap_near(phi + 180.0, prev.1);
    let (da, db) = ((a - prev.1).abs(), (b - prev.1).abs());
    if da < db - 1e-12 || (da - db).abs() <= 1e-12 && prev.0 >= 0.0 {
        (rho, a)
    } else {
        (-rho, b)
    }
}

/// Cuts `path` into chords in machine axes for polar interpolation,
/// starting from machine position `start` (which must be the path's start
/// point). A chord is split while the machine's straight interpolation
/// misses the path by more than `tol` (mm) at its middle, or turns the
/// rotary axis by more than 45° (which keeps the choice of representation
/// sound); at most [`MAX_CHORDS`] chords. Returns `(t, (X, θ°))` of every
/// chord end in order; the last is `t = 1`, the path's exact end.
pub fn polar_chords(path: &Path, start: (f64, f64), tol: f64) -> Vec<(f64, (f64, f64))> {
    let mut out = Vec::new();
    split(path, 0.0, start, 1.0, tol.max(1e-9), 0, &mut out);
    out
}

/// One interval of [`polar_chords`]; returns the machine position at `tb`.
fn split(
    path: &Path,
    ta: f64,
    ma: (f64, f64),
    tb: f64,
    tol: f64,
    depth: u32,
    out: &mut Vec<(f64, (f64, f64))>,
) -> (f64, f64) {
    let mb = polar_machine(path.at(tb), ma);
    if depth < MAX_DEPTH {
        let tm = 0.5 * (ta + tb);
        let lin = polar_virtual((0.5 * (ma.0 + mb.0), 0.5 * (ma.1 + mb.1)));
        let p = path.at(tm);
        let off = (lin.0 - p.0).hypot(lin.1 - p.1);
        if off > tol || (mb.1 - ma.1).abs() > 45.0 {
            let mm = split(path, ta, ma, tm, tol, depth + 1, out);
            return split(path, tm, mm, tb, tol, depth + 1, out);
        }
    }
    out.push((tb, mb));
    mb
}

/// Number of equal chords of an arc of radius `r` and `sweep` radians
/// whose sagitta is at most `tol` (at least 1, at most [`MAX_CHORDS`]).
pub fn arc_chords(r: f64, sweep: f64, tol: f64) -> usize {
    let sweep = sweep.abs();
    if !(r > 0.0 && sweep > 0.0) {
        return 1;
    }
    // Sagitta of a chord spanning angle d: r (1 - cos(d/2)).
    let d = if tol >= r {
        PI / 2.0
    } else {
        (2.0 * (1.0 - tol / r).acos()).clamp(1e-9, PI / 2.0)
    };
    let n = (sweep / d).ceil();
    if n.is_finite() && n >= 1.0 {
        (n as usize).min(MAX_CHORDS)
    } else {
        1
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() < 1e-9
    }

    #[test]
    fn machine_position_continues_the_motion() {
        // (20, 10): radius √500 = 22.360680, angle atan2(10, 20) = 26.565051°.
        let m = polar_machine((20.0, 10.0), (20.0, 0.0));
        assert!(close(m.0, 500f64.sqrt()) && close(m.1, 26.56505117707799));
        // Past 180°: the angle goes on (200°, not -160°).
        let m = polar_machine((-20.0, -7.279404685324), (20.0, 185.0));
        assert!(m.0 > 0.0 && (m.1 - 200.0).abs() < 1e-6, "{m:?}");
        // Through the centre: X changes sign, θ stays.
        let m = polar_machine((-5.0, 0.0), (0.0, 0.0));
        assert!(close(m.0, -5.0) && close(m.1, 0.0));
        assert_eq!(polar_machine((0.0, 0.0), (3.0, 12.0)), (0.0, 12.0));
    }

    #[test]
    fn chords_stay_within_tolerance_and_end_exactly() {
        // A line at y = 10 from x = 20 to x = -20: θ from 26.57° to 153.43°.
        let path = Path::Line {
            s: (20.0, 10.0),
            e: (-20.0, 10.0),
        };
        let start = polar_machine((20.0, 10.0), (20.0, 0.0));
        let ch = polar_chords(&path, start, 0.001);
        assert!(ch.len() > 10 && ch.len() < 2000, "{}", ch.len());
        let (t, m) = *ch.last().unwrap();
        assert_eq!(t, 1.0);
        assert!(close(m.0, 500f64.sqrt()) && close(m.1, 180.0 - 26.56505117707799));
        let mut prev = start;
        for &(_, m) in &ch {
            let v = polar_virtual(m);
            assert!(close(v.1, 10.0), "chord end off the line: {v:?}");
            let mid = polar_virtual((0.5 * (prev.0 + m.0), 0.5 * (prev.1 + m.1)));
            assert!((mid.1 - 10.0).abs() <= 0.001 + 1e-9, "sag {mid:?}");
            prev = m;
        }
    }

    #[test]
    fn a_line_through_the_centre_is_one_chord() {
        let path = Path::Line {
            s: (10.0, 0.0),
            e: (-10.0, 0.0),
        };
        let ch = polar_chords(&path, (10.0, 0.0), 0.001);
        assert_eq!(ch, vec![(1.0, (-10.0, 0.0))]);
    }

    #[test]
    fn a_line_grazing_the_centre_is_bounded() {
        let path = Path::Line {
            s: (10.0, 1e-7),
            e: (-10.0, 1e-7),
        };
        let ch = polar_chords(&path, polar_machine((10.0, 1e-7), (10.0, 0.0)), 1e-9);
        assert!(ch.len() <= MAX_CHORDS);
        assert_eq!(ch.last().unwrap().0, 1.0);
    }

    #[test]
    fn arc_chord_counts() {
        // r = 10, tol 0.001: d = 2 acos(0.9999) = 0.028284 rad; 90° → 56.
        assert_eq!(arc_chords(10.0, PI / 2.0, 0.001), 56);
        assert_eq!(arc_chords(10.0, 0.0, 0.001), 1);
        assert_eq!(arc_chords(1e-3, PI, 1.0), 2);
        assert_eq!(arc_chords(1e12, 2.0 * PI, 1e-12), MAX_CHORDS);
    }
}
