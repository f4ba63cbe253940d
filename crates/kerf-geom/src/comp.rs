//! Pure plane geometry of cutter radius compensation C (000 §13.2.2,
//! fanuc-semantics §4) and lathe tool nose radius compensation: offset
//! vectors, the corner between two compensated paths in the three angle
//! ranges (inner: intersection; outer obtuse: intersection of the tangent
//! offset lines; outer acute: the two extension vectors), G39 corner arcs,
//! start-up and cancel types, and the interference (gouge) checks.
//!
//! Conventions: a path is a [`Seg`] in the plane's (first, second) axis
//! coordinates; an offset `r` is signed, positive to the **left** of the
//! direction of travel (G41 with a positive offset value), negative to the
//! right (G42, or G41 with a negative value). The interpreter glue that
//! holds blocks is in `interp/comp.rs`.

pub use crate::corner::{Seg, P};
use crate::vec2::{add, cross, dot, len, mul, sub};

/// Distances below this (mm) are zero.
pub const EPS: f64 = 1e-6;

fn unit(a: P) -> P {
    let l = len(a);
    if l < 1e-300 {
        (0.0, 0.0)
    } else {
        (a.0 / l, a.1 / l)
    }
}
/// The left normal of a direction.
pub use crate::vec2::left;
/// Distance between two points.
pub fn dist(a: P, b: P) -> f64 {
    len(sub(a, b))
}

/// Why a compensated path cannot be made.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CompError {
    /// The offset is larger than the radius of an inside arc.
    ArcTooSmall,
    /// The offset paths at an inner corner do not meet.
    NoIntersection,
}

/// The unit direction of travel at the start of a path.
pub fn start_tangent(s: &Seg) -> P {
    match *s {
        Seg::Line { a, b } => unit(sub(b, a)),
        Seg::Arc { a, c, ccw, .. } => arc_tangent(a, c, ccw),
    }
}

/// The unit direction of travel at the end of a path.
pub fn end_tangent(s: &Seg) -> P {
    match *s {
        Seg::Line { a, b } => unit(sub(b, a)),
        Seg::Arc { b, c, ccw, .. } => arc_tangent(b, c, ccw),
    }
}

fn arc_tangent(p: P, c: P, ccw: bool) -> P {
    let l = left(unit(sub(p, c)));
    if ccw {
        l
    } else {
        mul(l, -1.0)
    }
}

/// The radius an arc has at `p` after offsetting by `r` (negative: the
/// offset is larger than the radius of an inside arc).
fn offset_radius(p: P, c: P, ccw: bool, r: f64) -> f64 {
    // The centre is on the left of a CCW arc: a left offset shrinks it.
    let rho = dist(p, c);
    if ccw {
        rho - r
    } else {
        rho + r
    }
}

/// The offset point at `p` of the path (perpendicular vector of length
/// |r|), for an arc radial at the radius `p` really has (an arc whose end
/// is not on its circle keeps its own end radius).
fn perp(s: &Seg, p: P, r: f64) -> Result<P, CompError> {
    match *s {
        Seg::Line { .. } => Ok(add(p, mul(left(start_tangent(s)), r))),
        Seg::Arc { c, ccw, .. } => {
            let rho = offset_radius(p, c, ccw, r);
            if rho <= EPS {
                return Err(CompError::ArcTooSmall);
            }
            Ok(add(c, mul(unit(sub(p, c)), rho)))
        }
    }
}

/// The offset point at the start of a path.
pub fn perp_start(s: &Seg, r: f64) -> Result<P, CompError> {
    perp(s, s.start(), r)
}

/// The offset point at the end of a path.
pub fn perp_end(s: &Seg, r: f64) -> Result<P, CompError> {
    perp(s, s.end(), r)
}

/// The offset of a path: a line (point, unit direction) or a circle.
#[derive(Clone, Copy, Debug)]
enum Off {
    Line(P, P),
    Circle(P, f64),
}

fn offset_at(s: &Seg, p: P, r: f64) -> Result<Off, CompError> {
    match *s {
        Seg::Line { .. } => Ok(Off::Line(perp(s, p, r)?, start_tangent(s))),
        Seg::Arc { c, ccw, .. } => {
            let rho = offset_radius(p, c, ccw, r);
            if rho <= EPS {
                return Err(CompError::ArcTooSmall);
            }
            Ok(Off::Circle(c, rho))
        }
    }
}

fn intersect(o1: &Off, o2: &Off) -> ([P; 2], usize) {
    let none = ([(0.0, 0.0); 2], 0);
    match (o1, o2) {
        (Off::Line(p, u), Off::Line(q, w)) => {
            let d = cross(*u, *w);
            if d.abs() < 1e-12 {
                return none;
            }
            let t = cross(sub(*q, *p), *w) / d;
            ([add(*p, mul(*u, t)), (0.0, 0.0)], 1)
        }
        (Off::Line(p, u), Off::Circle(c, rho)) | (Off::Circle(c, rho), Off::Line(p, u)) => {
            let m = sub(*p, *c);
            let bh = dot(m, *u);
            let disc = bh * bh - (dot(m, m) - rho * rho);
            if disc < 0.0 {
                return none;
            }
            let s = disc.sqrt();
            ([add(*p, mul(*u, -bh - s)), add(*p, mul(*u, -bh + s))], 2)
        }
        (Off::Circle(c1, r1), Off::Circle(c2, r2)) => {
            let d = dist(*c1, *c2);
            if d < 1e-12 || d > r1 + r2 || d < (r1 - r2).abs() {
                return none;
            }
            let a = (r1 * r1 - r2 * r2 + d * d) / (2.0 * d);
            let h = (r1 * r1 - a * a).max(0.0).sqrt();
            let e = unit(sub(*c2, *c1));
            let m = add(*c1, mul(e, a));
            ([add(m, mul(left(e), h)), add(m, mul(left(e), -h))], 2)
        }
    }
}

/// One piece of the connection between two compensated paths.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Piece {
    /// A straight move to the point.
    Line(P),
    /// A corner arc (G39) to the point about the centre.
    Arc(P, P, bool),
}

impl Piece {
    /// The end point.
    pub fn end(&self) -> P {
        match *self {
            Piece::Line(p) | Piece::Arc(p, _, _) => p,
        }
    }
}

/// How the compensated paths of two blocks meet: the first block's path
/// ends at `end1`, then the pieces in `via` (at most three), and the second
/// block's path starts at the last point reached (`start2`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Join {
    /// Where the first path ends (on its offset line or circle, a line
    /// possibly extended).
    pub end1: P,
    /// Straight moves (and a G39 arc) after it.
    pub via: [Piece; 3],
    /// Number of pieces in `via`.
    pub n: usize,
}

impl Join {
    /// The paths meet at one point.
    pub fn at(p: P) -> Join {
        Join {
            end1: p,
            via: [Piece::Line(p); 3],
            n: 0,
        }
    }
    fn push(&mut self, p: Piece) {
        let last = self.start2();
        if dist(last, p.end()) < EPS && matches!(p, Piece::Line(_)) {
            return;
        }
        self.via[self.n] = p;
        self.n += 1;
    }
    /// Where the second path starts.
    pub fn start2(&self) -> P {
        if self.n == 0 {
            self.end1
        } else {
            self.via[self.n - 1].end()
        }
    }
    /// The pieces after `end1`.
    pub fn pieces(&self) -> &[Piece] {
        &self.via[..self.n]
    }
}

/// The corner class of the turn from direction `t1` to `t2` for an offset
/// on side `side` (+1 left, -1 right).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Class {
    /// The tool is inside the corner (α ≥ 180° on the workpiece side):
    /// the offset paths' intersection.
    Inner,
    /// Outside, 90° ≤ α < 180°.
    Obtuse,
    /// Outside, α < 90° (and a reversal).
    Acute,
}

/// Classifies the corner between `t1` and `t2` (unit directions).
pub fn classify(t1: P, t2: P, side: f64) -> Class {
    let (x, d) = (cross(t1, t2), dot(t1, t2));
    if x.abs() < 1e-9 {
        // Straight on (α = 180°) or a reversal (α = 0).
        return if d > 0.0 { Class::Inner } else { Class::Acute };
    }
    if side * x > 0.0 {
        // Turning towards the tool's side.
        Class::Inner
    } else if d >= -1e-12 {
        Class::Obtuse
    } else {
        Class::Acute
    }
}

/// Options of the corner between two blocks.
#[derive(Clone, Copy, Debug, Default)]
pub struct CornerOpt {
    /// G39 after the first block: corner arc (outer corners), ending on the
    /// vector perpendicular to this direction (None: the second path's).
    pub g39: Option<Option<P>>,
    /// The second path is a start-up from the programmed corner and the
    /// corner is not an intersection there: the perpendicular vector only.
    pub perpendicular: bool,
}

/// The compensated corner between `s1` (offset `r1`) and `s2` (offset
/// `r2`); `s1.end()` is `s2.start()`. Same side: `r1` is used on both
/// paths (a new offset value applies from the end of the second block);
/// a change of side: the offset paths' intersection, else the two
/// perpendicular vectors joined by a straight move.
pub fn corner(s1: &Seg, r1: f64, s2: &Seg, r2: f64, opt: CornerOpt) -> Result<Join, CompError> {
    let k = s1.end();
    let (t1, t2) = (end_tangent(s1), start_tangent(s2));
    if r1 == 0.0 && r2 == 0.0 {
        return Ok(Join::at(k));
    }
    let side_change = r1 * r2 < 0.0;
    let r2 = if side_change || r1 == 0.0 || r2 == 0.0 {
        r2
    } else {
        r1
    };
    let p1 = perp(s1, k, r1)?;
    let p2 = perp(s2, k, r2)?;
    if side_change || r1 == 0.0 || r2 == 0.0 {
        let o1 = offset_at(s1, k, r1)?;
        let o2 = offset_at(s2, k, r2)?;
        let (pts, n) = intersect(&o1, &o2);
        if let Some(x) = nearest(&pts[..n], k) {
            return Ok(Join::at(x));
        }
        let mut j = Join::at(p1);
        j.push(Piece::Line(p2));
        return Ok(j);
    }
    let side = r1.signum();
    let a = r1.abs();
    let class = classify(t1, t2, side);
    if let (Some(dir), false) = (opt.g39, class == Class::Inner) {
        // G39: an arc of radius |r| about the corner.
        let d = dir.map(unit).unwrap_or(t2);
        let q = add(k, mul(left(d), r1));
        let ccw = cross(t1, d) > 0.0;
        let mut j = Join::at(p1);
        if dist(p1, q) >= EPS {
            j.via[0] = Piece::Arc(q, k, ccw);
            j.n = 1;
        }
        j.push(Piece::Line(p2));
        return Ok(j);
    }
    if opt.perpendicular && class == Class::Inner {
        return Ok(Join::at(p2));
    }
    let line1 = matches!(s1, Seg::Line { .. });
    let line2 = matches!(s2, Seg::Line { .. });
    match class {
        Class::Inner => {
            if dist(p1, p2) < EPS {
                return Ok(Join::at(p1));
            }
            let o1 = offset_at(s1, k, r1)?;
            let o2 = offset_at(s2, k, r2)?;
            let (pts, n) = intersect(&o1, &o2);
            match nearest(&pts[..n], k) {
                Some(x) => Ok(Join::at(x)),
                None => Err(CompError::NoIntersection),
            }
        }
        Class::Obtuse => {
            // The tangent offset lines' intersection.
            let (pts, n) = intersect(&Off::Line(p1, t1), &Off::Line(p2, t2));
            let x = if n == 1 { pts[0] } else { p1 };
            let mut j = Join::at(if line1 { x } else { p1 });
            if !line1 {
                j.push(Piece::Line(x));
            }
            if !line2 {
                j.push(Piece::Line(p2));
            }
            Ok(j)
        }
        Class::Acute => {
            let e1 = add(p1, mul(t1, a));
            let e2 = sub(p2, mul(t2, a));
            let mut j = Join::at(if line1 { e1 } else { p1 });
            if !line1 {
                j.push(Piece::Line(e1));
            }
            j.push(Piece::Line(e2));
            if !line2 {
                j.push(Piece::Line(p2));
            }
            Ok(j)
        }
    }
}

/// The candidate nearest the corner.
fn nearest(pts: &[P], k: P) -> Option<P> {
    pts.iter()
        .copied()
        .min_by(|a, b| dist(*a, k).total_cmp(&dist(*b, k)))
}

/// The start-up corner (000 §13.2.2 (1)): `s` is the start-up line from the
/// uncompensated start, `l` the next path, `r` the offset. Type A: the
/// start-up ends on the vector perpendicular to `l` at its start; type B:
/// outside corners as in offset mode (intersection / extension vectors).
pub fn startup(s: &Seg, l: &Seg, r: f64, type_b: bool) -> Result<Join, CompError> {
    let t1 = end_tangent(s);
    let t2 = start_tangent(l);
    // A start-up that nearly reverses (α < 1°) or a zero-length one: the
    // perpendicular vector.
    let reverse = dot(t1, t2) < -(1.0f64.to_radians().cos());
    if !type_b || reverse || len(sub(s.end(), s.start())) < EPS {
        return Ok(Join::at(perp_start(l, r)?));
    }
    corner(
        s,
        r,
        l,
        r,
        CornerOpt {
            g39: None,
            perpendicular: true,
        },
    )
}

/// The cancel corner (000 §13.2.2 (4)): `c` the last compensated path,
/// `e` the G40 line to the uncompensated end point (or, with I/J/K, the
/// line in that direction), `r` the offset. Returns where `c` ends and
/// the pieces before the straight move to the programmed end. Type A and
/// inner corners: the vector perpendicular to `c` at its end; type B:
/// the outer vectors as in offset mode; with I/J (`ij`): the offset-mode
/// corner with that direction in every case.
pub fn cancel(c: &Seg, e: &Seg, r: f64, type_b: bool, ij: bool) -> Result<Join, CompError> {
    let p1 = perp_end(c, r)?;
    if dist(e.start(), e.end()) < EPS {
        return Ok(Join::at(p1));
    }
    let class = classify(end_tangent(c), start_tangent(e), r.signum());
    if !ij && (!type_b || class == Class::Inner) {
        return Ok(Join::at(p1));
    }
    corner(c, r, e, r, CornerOpt::default())
}

/// Interference check of a compensated straight move: it must not reverse
/// the programmed direction (more than 90° off).
pub fn line_reverses(prog: (P, P), comp: (P, P)) -> bool {
    let d = sub(prog.1, prog.0);
    let e = sub(comp.1, comp.0);
    len(e) >= EPS && len(d) >= EPS && dot(d, e) < 0.0
}

/// Interference check of a compensated arc: its sweep (same centre and
/// direction) must not differ from the programmed sweep by more than 180°.
pub fn arc_reverses(prog: &Seg, comp: (P, P)) -> bool {
    let Seg::Arc { a, b, c, ccw } = *prog else {
        return false;
    };
    let full = dist(a, b) < 1e-9;
    let sw = kerf_canon::geom::sweep(a, b, c, ccw);
    let sc = if full && dist(comp.0, comp.1) < 1e-6 {
        std::f64::consts::TAU
    } else {
        kerf_canon::geom::sweep(comp.0, comp.1, c, ccw)
    };
    (sw - sc).abs() > std::f64::consts::PI
}

/// The vector from the nose centre to the imaginary tool tip for a lathe
/// tip direction (001 p.29, fanuc-semantics §4.9), in (Z, X) plane
/// coordinates, per unit of nose radius; 0 and 9: the centre itself.
pub fn tip_vector(tip: u8) -> P {
    // (Z, X): 1 = (+X, +Z), 2 = (+X, -Z), 3 = (-X, -Z), 4 = (-X, +Z),
    // 5 = +Z, 6 = +X, 7 = -Z, 8 = -X.
    match tip {
        1 => (1.0, 1.0),
        2 => (-1.0, 1.0),
        3 => (-1.0, -1.0),
        4 => (1.0, -1.0),
        5 => (1.0, 0.0),
        6 => (0.0, 1.0),
        7 => (-1.0, 0.0),
        8 => (0.0, -1.0),
        _ => (0.0, 0.0),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn line(a: P, b: P) -> Seg {
        Seg::Line { a, b }
    }
    fn near(a: P, b: P) -> bool {
        dist(a, b) < 1e-9
    }

    #[test]
    fn square_outer_corner_is_the_offset_lines_intersection() {
        // +X then +Y (left turn); G42 r = 2 (right side = outside):
        // offset lines y = -2 and x = 12 meet at (12, -2).
        let j = corner(
            &line((0.0, 0.0), (10.0, 0.0)),
            -2.0,
            &line((10.0, 0.0), (10.0, 10.0)),
            -2.0,
            CornerOpt::default(),
        )
        .unwrap();
        assert!(near(j.end1, (12.0, -2.0)) && j.n == 0, "{j:?}");
        // G41: inside, offset lines y = 2 and x = 8 → (8, 2).
        let j = corner(
            &line((0.0, 0.0), (10.0, 0.0)),
            2.0,
            &line((10.0, 0.0), (10.0, 10.0)),
            2.0,
            CornerOpt::default(),
        )
        .unwrap();
        assert!(near(j.end1, (8.0, 2.0)) && j.n == 0, "{j:?}");
    }

    #[test]
    fn acute_outer_corner_has_two_extension_vectors() {
        // +X then back at 135° to the left (direction (-1, 1)/√2), G42 r=1:
        // outside. E1 = (10, -1) + (1, 0) = (11, -1); P2 = (10, 0) + right
        // normal of (-1,1)/√2 = (1, 1)/√2; E2 = P2 - (-1, 1)/√2 = (2/√2, 0).
        let s = 0.5f64.sqrt();
        let j = corner(
            &line((0.0, 0.0), (10.0, 0.0)),
            -1.0,
            &line((10.0, 0.0), (0.0, 10.0)),
            -1.0,
            CornerOpt::default(),
        )
        .unwrap();
        assert!(near(j.end1, (11.0, -1.0)), "{j:?}");
        assert_eq!(j.n, 1);
        assert!(near(j.start2(), (10.0 + 2.0 * s, 0.0)), "{j:?}");
    }

    #[test]
    fn inside_arc_smaller_than_the_offset() {
        let arc = Seg::Arc {
            a: (0.0, 0.0),
            b: (10.0, 0.0),
            c: (5.0, 0.0),
            ccw: true,
        };
        // CCW arc of radius 5, left offset 6: larger than the radius.
        assert_eq!(perp_start(&arc, 6.0), Err(CompError::ArcTooSmall));
        assert!(perp_start(&arc, -6.0).is_ok());
    }

    #[test]
    fn reversal_check() {
        assert!(line_reverses(
            ((0.0, 0.0), (1.0, 0.0)),
            ((2.0, 0.0), (1.5, 0.0))
        ));
        assert!(!line_reverses(
            ((0.0, 0.0), (1.0, 0.0)),
            ((2.0, 0.0), (2.5, 1.0))
        ));
    }
}
