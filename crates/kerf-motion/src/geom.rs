//! Segment geometry in machine coordinates: straight lines and arcs
//! (circular or helical), with path length, tangents and points along them.

use kerf_canon::{ArcDir, Plane, Pos, NAXES};

/// The shape of one segment.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Geom {
    /// Straight line from `p0` to `p1`.
    Line { p0: Pos, p1: Pos },
    /// Arc from `p0` to `p1` about `c` in `plane` (first two axes), with
    /// the normal axis (and any other axis) moving linearly.
    Arc {
        p0: Pos,
        p1: Pos,
        c: Pos,
        plane: Plane,
        /// Start angle, radians.
        th0: f64,
        /// Signed sweep, radians (positive = counter-clockwise).
        sweep: f64,
        /// Start and end radius (equal up to the interpreter's tolerance;
        /// the radius is interpolated linearly between them).
        r0: f64,
        r1: f64,
    },
}

/// Path length of a straight move: the linear axes, or the rotary axes
/// when no linear axis moves (degrees then): kerf-canon's
/// [`machine_len`](kerf_canon::geom::machine_len).
pub use kerf_canon::geom::machine_len as line_len;

impl Geom {
    /// An arc from the canonical data (machine coordinates).
    pub fn arc(p0: Pos, p1: Pos, c: Pos, plane: Plane, dir: ArcDir, turns: u32) -> Geom {
        let (a1, a2, _) = plane.axes();
        let s = (p0[a1], p0[a2]);
        let e = (p1[a1], p1[a2]);
        let cc = (c[a1], c[a2]);
        let ccw = matches!(dir, ArcDir::Ccw);
        let mut sw = kerf_canon::geom::sweep(s, e, cc, ccw) + std::f64::consts::TAU * turns as f64;
        if !ccw {
            sw = -sw;
        }
        Geom::Arc {
            p0,
            p1,
            c,
            plane,
            th0: (s.1 - cc.1).atan2(s.0 - cc.0),
            sweep: sw,
            r0: (s.0 - cc.0).hypot(s.1 - cc.1),
            r1: (e.0 - cc.0).hypot(e.1 - cc.1),
        }
    }

    /// Start point.
    pub fn start(&self) -> Pos {
        match self {
            Geom::Line { p0, .. } | Geom::Arc { p0, .. } => *p0,
        }
    }

    /// End point.
    pub fn end(&self) -> Pos {
        match self {
            Geom::Line { p1, .. } | Geom::Arc { p1, .. } => *p1,
        }
    }

    /// Path length.
    pub fn len(&self) -> f64 {
        match self {
            Geom::Line { p0, p1 } => line_len(p0, p1),
            Geom::Arc {
                p0,
                p1,
                plane,
                sweep,
                r0,
                r1,
                ..
            } => {
                let (a1, a2, _) = plane.axes();
                let planar = 0.5 * (r0 + r1) * sweep.abs();
                let mut other = 0.0;
                for i in 0..3 {
                    if i != a1 && i != a2 {
                        let d = p1[i] - p0[i];
                        other += d * d;
                    }
                }
                (planar * planar + other).sqrt()
            }
        }
    }

    /// The part of the path from fraction `u0` to `u1` (fractions of the
    /// length: the parameter is proportional to it on lines and helices).
    pub fn sub(&self, u0: f64, u1: f64) -> Geom {
        match *self {
            Geom::Line { .. } => Geom::Line {
                p0: self.at(u0),
                p1: self.at(u1),
            },
            Geom::Arc {
                c,
                plane,
                th0,
                sweep,
                r0,
                r1,
                ..
            } => Geom::Arc {
                p0: self.at(u0),
                p1: self.at(u1),
                c,
                plane,
                th0: th0 + sweep * u0,
                sweep: sweep * (u1 - u0),
                r0: r0 + (r1 - r0) * u0,
                r1: r0 + (r1 - r0) * u1,
            },
        }
    }

    /// Radius of an arc (mean of start and end), `None` for a line.
    pub fn radius(&self) -> Option<f64> {
        match self {
            Geom::Arc { r0, r1, .. } => Some(0.5 * (r0 + r1)),
            Geom::Line { .. } => None,
        }
    }

    /// Point at fraction `u` (0..1) of the path.
    pub fn at(&self, u: f64) -> Pos {
        match self {
            Geom::Line { p0, p1 } => {
                let mut p = *p0;
                for i in 0..NAXES {
                    p[i] += (p1[i] - p0[i]) * u;
                }
                p
            }
            Geom::Arc {
                p0,
                p1,
                c,
                plane,
                th0,
                sweep,
                r0,
                r1,
            } => {
                let (a1, a2, _) = plane.axes();
                let mut p = *p0;
                for i in 0..NAXES {
                    p[i] += (p1[i] - p0[i]) * u;
                }
                if u >= 1.0 {
                    return *p1;
                }
                let th = th0 + sweep * u;
                let r = r0 + (r1 - r0) * u;
                p[a1] = c[a1] + r * th.cos();
                p[a2] = c[a2] + r * th.sin();
                p
            }
        }
    }

    /// Unit tangent (per axis slot, per unit of path length) at fraction `u`.
    pub fn tangent(&self, u: f64) -> Pos {
        let len = self.len();
        let mut t = [0.0; NAXES];
        if len <= 0.0 {
            return t;
        }
        match self {
            Geom::Line { p0, p1 } => {
                for i in 0..NAXES {
                    t[i] = (p1[i] - p0[i]) / len;
                }
            }
            Geom::Arc {
                p0,
                p1,
                plane,
                th0,
                sweep,
                r0,
                r1,
                ..
            } => {
                let (a1, a2, _) = plane.axes();
                for i in 0..NAXES {
                    t[i] = (p1[i] - p0[i]) / len;
                }
                let th = th0 + sweep * u;
                let r = r0 + (r1 - r0) * u;
                // d/ds of (r cos th, r sin th) with dth/ds = sweep/len.
                let w = sweep / len;
                let dr = (r1 - r0) / len;
                t[a1] = -r * th.sin() * w + dr * th.cos();
                t[a2] = r * th.cos() * w + dr * th.sin();
            }
        }
        t
    }
}
