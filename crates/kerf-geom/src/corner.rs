//! Chamfer (`,C`) and corner rounding (`,R`) between two paths in a plane
//! (000 §4.3.1-4.3.2, Fanuc): pure geometry, no interpreter state.
//!
//! The first path ends and the second starts at the virtual corner K.
//! [`chamfer`] finds the points at straight-line distance c from K on each
//! path; [`round`] finds the arc of radius r tangent to both paths. Either
//! result gives the trimmed end of the first path (`p1`), the inserted
//! line or arc, and the trimmed start of the second path (`p2`); an arc
//! path keeps its centre. Coordinates are (u, v) in the plane's (first,
//! second) axes, as in [`crate::arc`]; CCW is seen from the plane normal.

use std::f64::consts::TAU;

pub use crate::vec2::P;
use crate::vec2::{add, cross, dot, left, len, mul, sub};

/// Distances below this (mm) are zero: the slack of the fit checks.
pub const EPS: f64 = 1e-6;

/// One path in the plane.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Seg {
    /// A straight move from `a` to `b`.
    Line {
        /// Start.
        a: P,
        /// End.
        b: P,
    },
    /// A circular move from `a` to `b` about `c` (a == b: a full circle).
    Arc {
        /// Start.
        a: P,
        /// End.
        b: P,
        /// Centre.
        c: P,
        /// Counter-clockwise (G03).
        ccw: bool,
    },
}

/// The inserted corner.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Corner {
    /// A straight chamfer from `p1` (on the first path) to `p2` (on the
    /// second).
    Chamfer {
        /// Trimmed end of the first path.
        p1: P,
        /// Trimmed start of the second path.
        p2: P,
    },
    /// An arc from `p1` to `p2` about `c`, tangent to both paths.
    Round {
        /// Trimmed end of the first path (tangent point).
        p1: P,
        /// Trimmed start of the second path (tangent point).
        p2: P,
        /// Centre of the corner arc.
        c: P,
        /// Direction of the corner arc.
        ccw: bool,
    },
}

impl Corner {
    /// The trimmed end of the first path.
    pub fn p1(&self) -> P {
        match *self {
            Corner::Chamfer { p1, .. } | Corner::Round { p1, .. } => p1,
        }
    }

    /// The trimmed start of the second path.
    pub fn p2(&self) -> P {
        match *self {
            Corner::Chamfer { p2, .. } | Corner::Round { p2, .. } => p2,
        }
    }
}

/// Why no corner can be inserted.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CornerError {
    /// The paths meet tangentially or reverse: there is no corner to cut.
    NoCorner,
    /// The chamfer or radius does not fit on one of the paths.
    TooLarge,
}

fn unit(a: P) -> P {
    let l = len(a);
    (a.0 / l, a.1 / l)
}

impl Seg {
    /// The start point.
    pub fn start(&self) -> P {
        match *self {
            Seg::Line { a, .. } | Seg::Arc { a, .. } => a,
        }
    }

    /// The end point.
    pub fn end(&self) -> P {
        match *self {
            Seg::Line { b, .. } | Seg::Arc { b, .. } => b,
        }
    }

    /// The same path with another start point (an arc keeps its centre).
    pub fn with_start(self, p: P) -> Seg {
        match self {
            Seg::Line { b, .. } => Seg::Line { a: p, b },
            Seg::Arc { b, c, ccw, .. } => Seg::Arc { a: p, b, c, ccw },
        }
    }

    /// The same path with another end point (an arc keeps its centre).
    pub fn with_end(self, p: P) -> Seg {
        match self {
            Seg::Line { a, .. } => Seg::Line { a, b: p },
            Seg::Arc { a, c, ccw, .. } => Seg::Arc { a, b: p, c, ccw },
        }
    }

    /// The unit direction of travel at point `p` of the path.
    fn tangent(&self, p: P) -> P {
        match *self {
            Seg::Line { a, b } => unit(sub(b, a)),
            Seg::Arc { c, ccw, .. } => {
                let r = unit(sub(p, c));
                if ccw {
                    left(r)
                } else {
                    mul(left(r), -1.0)
                }
            }
        }
    }

    /// Radius (from the start point) of an arc.
    fn radius(&self) -> f64 {
        match *self {
            Seg::Line { .. } => f64::INFINITY,
            Seg::Arc { a, c, .. } => len(sub(a, c)),
        }
    }

    /// Angle travelled from the start to `p` (a point on the circle).
    fn angle_to(&self, p: P) -> f64 {
        match *self {
            Seg::Line { .. } => 0.0,
            Seg::Arc { a, c, ccw, .. } => {
                if len(sub(p, a)) < EPS {
                    return 0.0;
                }
                let a0 = (a.1 - c.1).atan2(a.0 - c.0);
                let a1 = (p.1 - c.1).atan2(p.0 - c.0);
                let d = if ccw { a1 - a0 } else { a0 - a1 };
                d.rem_euclid(TAU)
            }
        }
    }

    /// True when `p` (on the line or circle of the path) lies on the path
    /// itself, within [`EPS`].
    fn holds(&self, p: P) -> bool {
        match *self {
            Seg::Line { a, b } => {
                let d = sub(b, a);
                let l = len(d);
                let t = dot(sub(p, a), d) / l;
                t >= -EPS && t <= l + EPS
            }
            Seg::Arc { a, b, c, ccw } => {
                if len(sub(p, a)) < EPS || len(sub(p, b)) < EPS {
                    return true;
                }
                let sweep = kerf_canon::geom::sweep(a, b, c, ccw);
                let r = self.radius();
                // Angular slack equivalent to EPS along the circle.
                self.angle_to(p) <= sweep + EPS / r
            }
        }
    }

    /// The point on the path at straight-line distance `d` from `k`, where
    /// `k` is the path's end (`backward`) or its start; None when the
    /// circle is too small for the distance.
    fn at_distance(&self, k: P, d: f64, backward: bool) -> Option<P> {
        match *self {
            Seg::Line { a, b } => {
                let u = unit(sub(b, a));
                Some(if backward {
                    sub(k, mul(u, d))
                } else {
                    add(k, mul(u, d))
                })
            }
            Seg::Arc { c, ccw, .. } => {
                let r = self.radius();
                if d > 2.0 * r + EPS {
                    return None;
                }
                // Chord d subtends 2·asin(d / 2r) at the centre.
                let phi = 2.0 * (d / (2.0 * r)).min(1.0).asin();
                let forward = ccw != backward;
                let th = (k.1 - c.1).atan2(k.0 - c.0) + if forward { phi } else { -phi };
                Some((c.0 + r * th.cos(), c.1 + r * th.sin()))
            }
        }
    }

    /// The point of the path nearest to a fillet centre `f`, i.e. the
    /// tangent point of a circle about `f` that touches the path's line or
    /// circle.
    fn foot(&self, f: P) -> P {
        match *self {
            Seg::Line { a, b } => {
                let u = unit(sub(b, a));
                add(a, mul(u, dot(sub(f, a), u)))
            }
            Seg::Arc { c, .. } => add(c, mul(unit(sub(f, c)), self.radius())),
        }
    }
}

/// The turn at the corner: +1 left (CCW), -1 right (CW), or NoCorner when
/// the paths meet tangentially or reverse.
fn turn(s1: &Seg, s2: &Seg) -> Result<f64, CornerError> {
    let k = s1.end();
    let (t1, t2) = (s1.tangent(k), s2.tangent(k));
    let x = cross(t1, t2);
    if x.abs() < 1e-9 {
        return Err(CornerError::NoCorner);
    }
    Ok(x.signum())
}

fn degenerate(s: &Seg) -> bool {
    match *s {
        Seg::Line { a, b } => len(sub(b, a)) < EPS,
        Seg::Arc { a, c, .. } => len(sub(a, c)) < EPS,
    }
}

/// A chamfer whose ends lie at straight-line distance `c` from the corner
/// along each path. `s1.end()` must equal `s2.start()`.
pub fn chamfer(s1: &Seg, s2: &Seg, c: f64) -> Result<Corner, CornerError> {
    if degenerate(s1) || degenerate(s2) {
        // A path used up by the corner at its other end.
        return Err(CornerError::TooLarge);
    }
    turn(s1, s2)?;
    let k = s1.end();
    let p1 = s1.at_distance(k, c, true).ok_or(CornerError::TooLarge)?;
    let p2 = s2.at_distance(k, c, false).ok_or(CornerError::TooLarge)?;
    if !s1.holds(p1) || !s2.holds(p2) {
        return Err(CornerError::TooLarge);
    }
    Ok(Corner::Chamfer { p1, p2 })
}

/// The offset of a path by `r` to side `side` (+1 left): a line (point,
/// unit direction) or a circle (centre, radius).
enum Offset {
    Line(P, P),
    Circle(P, f64),
}

fn offset(s: &Seg, side: f64, r: f64) -> Option<Offset> {
    match *s {
        Seg::Line { a, b } => {
            let u = unit(sub(b, a));
            Some(Offset::Line(add(a, mul(left(u), side * r)), u))
        }
        Seg::Arc { c, ccw, .. } => {
            // The centre is on the left of a CCW arc: offsetting towards it
            // shrinks the circle.
            let towards = if ccw { side } else { -side };
            let rho = s.radius() - towards * r;
            (rho > EPS).then_some(Offset::Circle(c, rho))
        }
    }
}

/// Intersections of two offset paths (0, 1 or 2 points).
fn intersect(o1: &Offset, o2: &Offset) -> Vec<P> {
    match (o1, o2) {
        (Offset::Line(p, u), Offset::Line(q, w)) => {
            let d = cross(*u, *w);
            if d.abs() < 1e-12 {
                return vec![];
            }
            let t = cross(sub(*q, *p), *w) / d;
            vec![add(*p, mul(*u, t))]
        }
        (Offset::Line(p, u), Offset::Circle(c, rho))
        | (Offset::Circle(c, rho), Offset::Line(p, u)) => {
            // |p + t·u - c|² = ρ²
            let m = sub(*p, *c);
            let bh = dot(m, *u);
            let disc = bh * bh - (dot(m, m) - rho * rho);
            if disc < 0.0 {
                return vec![];
            }
            let s = disc.sqrt();
            vec![add(*p, mul(*u, -bh - s)), add(*p, mul(*u, -bh + s))]
        }
        (Offset::Circle(c1, r1), Offset::Circle(c2, r2)) => {
            let d = len(sub(*c2, *c1));
            if d < 1e-12 || d > r1 + r2 || d < (r1 - r2).abs() {
                return vec![];
            }
            let a = (r1 * r1 - r2 * r2 + d * d) / (2.0 * d);
            let h = (r1 * r1 - a * a).max(0.0).sqrt();
            let e = unit(sub(*c2, *c1));
            let m = add(*c1, mul(e, a));
            vec![add(m, mul(left(e), h)), add(m, mul(left(e), -h))]
        }
    }
}

/// A corner arc of radius `r` tangent to both paths. `s1.end()` must equal
/// `s2.start()`. Its centre lies on both paths' offsets by r towards the
/// inside of the corner; of the candidates whose tangent points lie on the
/// two paths, the one nearest the corner is taken.
pub fn round(s1: &Seg, s2: &Seg, r: f64) -> Result<Corner, CornerError> {
    if degenerate(s1) || degenerate(s2) {
        // A path used up by the corner at its other end.
        return Err(CornerError::TooLarge);
    }
    let side = turn(s1, s2)?;
    let k = s1.end();
    let (Some(o1), Some(o2)) = (offset(s1, side, r), offset(s2, side, r)) else {
        return Err(CornerError::TooLarge);
    };
    let mut best: Option<(f64, Corner)> = None;
    for f in intersect(&o1, &o2) {
        let (p1, p2) = (s1.foot(f), s2.foot(f));
        if !s1.holds(p1) || !s2.holds(p2) {
            continue;
        }
        let dist = len(sub(f, k));
        let better = match best {
            None => true,
            Some((d, _)) => dist < d,
        };
        if better {
            best = Some((
                dist,
                Corner::Round {
                    p1,
                    p2,
                    c: f,
                    ccw: side > 0.0,
                },
            ));
        }
    }
    best.map(|b| b.1).ok_or(CornerError::TooLarge)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn near(a: P, b: P) -> bool {
        (a.0 - b.0).abs() < 1e-9 && (a.1 - b.1).abs() < 1e-9
    }

    #[track_caller]
    fn assert_near(a: P, b: P) {
        assert!(near(a, b), "{a:?} != {b:?}");
    }

    fn line(a: P, b: P) -> Seg {
        Seg::Line { a, b }
    }

    /// The inserted arc is tangent to a path at its tangent point p: the
    /// radius to p is perpendicular to the path's direction there, and p is
    /// at distance r from the fillet centre.
    #[track_caller]
    fn assert_tangent(s: &Seg, p: P, c: P, r: f64) {
        assert!((len(sub(p, c)) - r).abs() < 1e-9, "not on the corner arc");
        let t = s.tangent(p);
        assert!(dot(t, unit(sub(p, c))).abs() < 1e-9, "not tangent at {p:?}");
    }

    #[test]
    fn line_line_right_angle_chamfer() {
        // G01 X50 ,C5 then Y50 from (0,0): the chamfer runs from 5 before
        // the corner (45,0) to 5 after it (50,5).
        let s1 = line((0.0, 0.0), (50.0, 0.0));
        let s2 = line((50.0, 0.0), (50.0, 50.0));
        let c = chamfer(&s1, &s2, 5.0).unwrap();
        assert_eq!(
            c,
            Corner::Chamfer {
                p1: (45.0, 0.0),
                p2: (50.0, 5.0)
            }
        );
    }

    #[test]
    fn line_line_right_angle_round() {
        // ,R5 at the same corner: the 90° fillet touches 5 before and
        // after the corner; left turn, so CCW about (45,5).
        let s1 = line((0.0, 0.0), (50.0, 0.0));
        let s2 = line((50.0, 0.0), (50.0, 50.0));
        let Corner::Round { p1, p2, c, ccw } = round(&s1, &s2, 5.0).unwrap() else {
            panic!("round")
        };
        assert_near(p1, (45.0, 0.0));
        assert_near(p2, (50.0, 5.0));
        assert_near(c, (45.0, 5.0));
        assert!(ccw);
        // A right turn (then Y-50) rounds CW about (45,-5).
        let s2 = line((50.0, 0.0), (50.0, -50.0));
        let Corner::Round { c, ccw, .. } = round(&s1, &s2, 5.0).unwrap() else {
            panic!("round")
        };
        assert_near(c, (45.0, -5.0));
        assert!(!ccw);
    }

    #[test]
    fn line_line_sixty_degree_turn() {
        // From (0,0) along +X to K = (10,0), then to (15, 5√3): the
        // direction turns by 60° (interior angle 120°). Chamfer 2: (8,0)
        // and K + 2·(cos60°, sin60°) = (11, √3).
        let k = (10.0, 0.0);
        let e = (15.0, 5.0 * 3f64.sqrt());
        let s1 = line((0.0, 0.0), k);
        let s2 = line(k, e);
        let c = chamfer(&s1, &s2, 2.0).unwrap();
        assert_near(c.p1(), (8.0, 0.0));
        assert_near(c.p2(), (11.0, 3f64.sqrt()));
        // Corner R 3: tangent length t = r·tan(60°/2) = 3/√3 = √3;
        // p1 = (10-√3, 0), p2 = K + √3·(1/2, √3/2) = (10+√3/2, 1.5);
        // centre = p1 + 3·(0,1) = (10-√3, 3).
        let s3 = 3f64.sqrt();
        let Corner::Round { p1, p2, c, ccw } = round(&s1, &s2, 3.0).unwrap() else {
            panic!("round")
        };
        assert_near(p1, (10.0 - s3, 0.0));
        assert_near(p2, (10.0 + s3 / 2.0, 1.5));
        assert_near(c, (10.0 - s3, 3.0));
        assert!(ccw);
        assert_tangent(&s1, p1, c, 3.0);
        assert_tangent(&s2, p2, c, 3.0);
    }

    #[test]
    fn line_line_obtuse_135_degree_corner() {
        // 000 §4.3.1/4.3.2 geometry: (10,30) → (30,30) → (50,50); the path
        // turns 45° left (interior angle 135°). R15: t = 15·tan 22.5° =
        // 15(√2-1) = 6.213203; p1 = (30-t, 30), p2 = (30,30) + t(1,1)/√2,
        // centre (30-t, 45).
        let t = 15.0 * (2f64.sqrt() - 1.0);
        let s1 = line((10.0, 30.0), (30.0, 30.0));
        let s2 = line((30.0, 30.0), (50.0, 50.0));
        let Corner::Round { p1, p2, c, ccw } = round(&s1, &s2, 15.0).unwrap() else {
            panic!("round")
        };
        assert_near(p1, (30.0 - t, 30.0));
        let q = t / 2f64.sqrt();
        assert_near(p2, (30.0 + q, 30.0 + q));
        assert_near(c, (30.0 - t, 45.0));
        assert!(ccw);
        // C5: (25,30) and (30 + 5/√2, 30 + 5/√2).
        let c = chamfer(&s1, &s2, 5.0).unwrap();
        let q = 5.0 / 2f64.sqrt();
        assert_near(c.p1(), (25.0, 30.0));
        assert_near(c.p2(), (30.0 + q, 30.0 + q));
    }

    #[test]
    fn line_then_arc() {
        // Line (0,0) → K (10,0) heading +X, then a CW arc about (20,0),
        // radius 10, from K (angle 180°) to (20,10) (angle 90°): it leaves
        // K heading +Y, a left turn of 90°.
        let k = (10.0, 0.0);
        let s1 = line((0.0, 0.0), k);
        let s2 = Seg::Arc {
            a: k,
            b: (20.0, 10.0),
            c: (20.0, 0.0),
            ccw: false,
        };
        // Chamfer 2. On the line: (8,0). On the arc, circle (K, 2) ∩
        // circle ((20,0), 10): subtracting the equations gives
        // x = 10 + 2²/(2·10) = 10.2, y = ±√(4 - 0.2²) = ±√3.96; the arc
        // goes up, so y > 0.
        let c = chamfer(&s1, &s2, 2.0).unwrap();
        assert_near(c.p1(), (8.0, 0.0));
        assert_near(c.p2(), (10.2, 3.96f64.sqrt()));
        // Corner R 2. Left turn: the fillet lies above the line, its
        // centre on y = 2; the arc's centre is on the right of CW travel,
        // so the fillet is outside the circle, its centre at 10 + 2 = 12
        // from (20,0): (x-20)² + 2² = 12² → x = 20 - √140 = 8.167789
        // (the other root, 31.8, touches the line beyond its end).
        let x = 20.0 - 140f64.sqrt();
        let Corner::Round { p1, p2, c, ccw } = round(&s1, &s2, 2.0).unwrap() else {
            panic!("round")
        };
        assert_near(c, (x, 2.0));
        assert_near(p1, (x, 0.0));
        // p2: on the arc's circle on the ray from (20,0) to the centre.
        assert_near(p2, (20.0 + (x - 20.0) * 10.0 / 12.0, 2.0 * 10.0 / 12.0));
        assert!(ccw);
        assert_tangent(&s1, p1, c, 2.0);
        assert_tangent(&s2, p2, c, 2.0);
    }

    #[test]
    fn arc_then_line() {
        // CCW quarter circle about (0,0), radius 10, from (10,0) to K
        // (0,10), arriving heading -X; then a line to (0,30) heading +Y:
        // a right turn of 90°.
        let k = (0.0, 10.0);
        let s1 = Seg::Arc {
            a: (10.0, 0.0),
            b: k,
            c: (0.0, 0.0),
            ccw: true,
        };
        let s2 = line(k, (0.0, 30.0));
        // Corner R 3. Right turn: the fillet is on the right of both
        // paths: for the line (heading +Y) on x = 3; for the CCW arc
        // (centre on its left) outside the circle, at 10 + 3 = 13 from
        // (0,0): 3² + y² = 13² → y = √160 = 12.649111.
        let y = 160f64.sqrt();
        let Corner::Round { p1, p2, c, ccw } = round(&s1, &s2, 3.0).unwrap() else {
            panic!("round")
        };
        assert_near(c, (3.0, y));
        assert_near(p2, (0.0, y));
        assert_near(p1, (3.0 * 10.0 / 13.0, y * 10.0 / 13.0));
        assert!(!ccw);
        assert_tangent(&s1, p1, c, 3.0);
        assert_tangent(&s2, p2, c, 3.0);
        // Chamfer 4. On the line: (0,14). On the arc, circle (K, 4) ∩
        // circle ((0,0), 10): y = 10 - 4²/(2·10) = 9.2, x = ±√(16 - 0.8²);
        // before K on the CCW arc means x > 0.
        let c = chamfer(&s1, &s2, 4.0).unwrap();
        assert_near(c.p1(), (15.36f64.sqrt(), 9.2));
        assert_near(c.p2(), (0.0, 14.0));
    }

    #[test]
    fn arc_then_arc() {
        // s1: CW about (0,0), radius 10, from (0,10) to K (10,0), arriving
        // heading -Y. s2: CCW about (10,10), radius 10, from K (angle
        // -90°) to (20,10), leaving heading +X. A left turn of 90°.
        let k = (10.0, 0.0);
        let s1 = Seg::Arc {
            a: (0.0, 10.0),
            b: k,
            c: (0.0, 0.0),
            ccw: false,
        };
        let s2 = Seg::Arc {
            a: k,
            b: (20.0, 10.0),
            c: (10.0, 10.0),
            ccw: true,
        };
        // Corner R 2. Left turn: the fillet is on the left of both; s1's
        // centre is on its right (CW), so the fillet centre is at 12 from
        // (0,0); s2's centre is on its left, so at 8 from (10,10).
        // Circle-circle intersection: the centres are d = √200 apart,
        // the foot of the common chord a = (12² - 8² + 200)/(2d) = 140/d
        // from (0,0), a² = 98, h = √(144 - 98) = √46; the foot is (7,7),
        // the offsets ±h·(-1,1)/√2 = ±√23·(-1,1). The candidate near K
        // is (7 + √23, 7 - √23) = (11.795832, 2.204168).
        let r23 = 23f64.sqrt();
        let want = (7.0 + r23, 7.0 - r23);
        assert!((len(want) - 12.0).abs() < 1e-12);
        assert!((len(sub(want, (10.0, 10.0))) - 8.0).abs() < 1e-12);
        let Corner::Round { p1, p2, c, ccw } = round(&s1, &s2, 2.0).unwrap() else {
            panic!("round")
        };
        assert_near(c, want);
        assert!(ccw);
        // Tangent points: on each circle, on the ray to the fillet centre.
        assert_near(p1, mul(want, 10.0 / 12.0));
        assert_near(
            p2,
            add((10.0, 10.0), mul(sub(want, (10.0, 10.0)), 10.0 / 8.0)),
        );
        assert_tangent(&s1, p1, c, 2.0);
        assert_tangent(&s2, p2, c, 2.0);
        // Chamfer 2 on both: a chord of 2 on radius 10 subtends
        // φ = 2·asin(0.1). Before K on the CW s1 is angle +φ; after K on
        // the CCW s2 is angle -90° + φ about (10,10).
        let phi = 2.0 * 0.1f64.asin();
        let c = chamfer(&s1, &s2, 2.0).unwrap();
        assert_near(c.p1(), (10.0 * phi.cos(), 10.0 * phi.sin()));
        let t = -std::f64::consts::FRAC_PI_2 + phi;
        assert_near(c.p2(), (10.0 + 10.0 * t.cos(), 10.0 + 10.0 * t.sin()));
        assert!((len(sub(c.p1(), k)) - 2.0).abs() < 1e-9);
        assert!((len(sub(c.p2(), k)) - 2.0).abs() < 1e-9);
    }

    #[test]
    fn too_large_and_no_corner() {
        let s1 = line((0.0, 0.0), (10.0, 0.0));
        let s2 = line((10.0, 0.0), (10.0, 4.0));
        // Chamfer 5 is longer than the 4 mm second path.
        assert_eq!(chamfer(&s1, &s2, 5.0), Err(CornerError::TooLarge));
        // Exactly 4 fits (the second path is used up).
        assert_eq!(chamfer(&s1, &s2, 4.0).unwrap().p2(), (10.0, 4.0));
        // R5 on a 90° corner needs 5 mm of each path.
        assert_eq!(round(&s1, &s2, 5.0), Err(CornerError::TooLarge));
        assert!(round(&s1, &s2, 4.0).is_ok());
        // Straight on, or straight back: no corner.
        let on = line((10.0, 0.0), (20.0, 0.0));
        assert_eq!(chamfer(&s1, &on, 1.0), Err(CornerError::NoCorner));
        let back = line((10.0, 0.0), (5.0, 0.0));
        assert_eq!(round(&s1, &back, 1.0), Err(CornerError::NoCorner));
        // A line running tangentially into an arc.
        let tangent = Seg::Arc {
            a: (10.0, 0.0),
            b: (20.0, 10.0),
            c: (10.0, 10.0),
            ccw: true,
        };
        assert_eq!(round(&s1, &tangent, 1.0), Err(CornerError::NoCorner));
        // A chord longer than the arc's diameter (CW half circle of
        // radius 1 leaving K heading +Y).
        let small = Seg::Arc {
            a: (10.0, 0.0),
            b: (12.0, 0.0),
            c: (11.0, 0.0),
            ccw: false,
        };
        assert_eq!(chamfer(&s1, &small, 3.0), Err(CornerError::TooLarge));
        // A fillet that must sit inside a concave arc of radius √2 (CCW
        // about (9,1), leaving K heading 45° up): R3 does not fit.
        let inside = Seg::Arc {
            a: (10.0, 0.0),
            b: (10.0, 2.0),
            c: (9.0, 1.0),
            ccw: true,
        };
        assert_eq!(round(&s1, &inside, 3.0), Err(CornerError::TooLarge));
        assert!(round(&s1, &inside, 0.5).is_ok());
        // A path used up by a corner at its other end leaves no room.
        let used = line((10.0, 0.0), (10.0, 0.0));
        assert_eq!(chamfer(&s1, &used, 1.0), Err(CornerError::TooLarge));
    }
}
