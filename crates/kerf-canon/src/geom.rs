//! Plane geometry of canonical arcs that every consumer of the stream
//! needs (time, plots, bounding boxes). Coordinates are (u, v) in the arc
//! plane's (first, second) axes; CCW is seen from the positive normal.

use std::f64::consts::{PI, TAU};

use crate::{Pos, NAXES};

/// The length of a straight move from `p0` to `p1` as a control times it
/// outside G112/G107: its linear axes (X Y Z), or its rotary axes (A B C,
/// degrees as mm) when no linear axis moves. The planner times feeds by
/// it and the G-code writer scales G112/G107 feeds against it.
#[inline]
pub fn machine_len(p0: &Pos, p1: &Pos) -> f64 {
    let mut s = 0.0;
    for i in 0..3 {
        let d = p1[i] - p0[i];
        s += d * d;
    }
    if s > 0.0 {
        return s.sqrt();
    }
    for i in 3..NAXES {
        let d = p1[i] - p0[i];
        s += d * d;
    }
    s.sqrt()
}

/// Swept angle (radians, > 0) from `s` to `e` about `c`. Coincident start
/// and end make a full circle.
pub fn sweep(s: (f64, f64), e: (f64, f64), c: (f64, f64), ccw: bool) -> f64 {
    if (s.0 - e.0).hypot(s.1 - e.1) < 1e-9 {
        return TAU;
    }
    let a0 = (s.1 - c.1).atan2(s.0 - c.0);
    let a1 = (e.1 - c.1).atan2(e.0 - c.0);
    let d = if ccw { a1 - a0 } else { a0 - a1 };
    d.rem_euclid(TAU)
}

/// Bounding box (min u, min v, max u, max v) of the arc.
pub fn bbox(s: (f64, f64), e: (f64, f64), c: (f64, f64), ccw: bool) -> (f64, f64, f64, f64) {
    let r = (s.0 - c.0).hypot(s.1 - c.1);
    let mut b = (s.0.min(e.0), s.1.min(e.1), s.0.max(e.0), s.1.max(e.1));
    let a0 = (s.1 - c.1).atan2(s.0 - c.0);
    let sw = sweep(s, e, c, ccw);
    for k in 0..4 {
        let q = k as f64 * PI / 2.0;
        // Angle travelled from the start to reach direction q.
        let mut d = if ccw { q - a0 } else { a0 - q };
        d = d.rem_euclid(TAU);
        if d <= sw {
            let (px, py) = (c.0 + r * q.cos(), c.1 + r * q.sin());
            b = (b.0.min(px), b.1.min(py), b.2.max(px), b.3.max(py));
        }
    }
    b
}
