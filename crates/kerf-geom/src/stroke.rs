//! Stored stroke check 2 (G22/G23, 000 §15.5.3): a box in machine
//! coordinates the tool may not enter (or, by parameter, not leave), and
//! the tests of a move's whole path against it: straight lines, the HX's
//! non-linear rapid (each axis at its own rate: a dog-leg of up to three
//! straight pieces) and arcs (as chords within a tolerance).

use kerf_canon::Pos;

/// A forbidden area: the box `lo..hi` on X, Y, Z (machine coordinates; an
/// axis not given spans everything).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Area {
    /// Lower corner (I, J, K of G22).
    pub lo: [f64; 3],
    /// Upper corner (X, Y, Z of G22).
    pub hi: [f64; 3],
    /// The outside of the box is forbidden instead of the inside.
    pub outside: bool,
}

/// Points closer than this to the boundary count as on it (allowed).
const EPS: f64 = 1e-9;

impl Area {
    /// True when a point is in the forbidden region.
    pub fn forbids(&self, p: &Pos) -> bool {
        let inside = (0..3).all(|i| p[i] > self.lo[i] + EPS && p[i] < self.hi[i] - EPS);
        if self.outside {
            (0..3).any(|i| p[i] < self.lo[i] - EPS || p[i] > self.hi[i] + EPS)
        } else {
            inside
        }
    }

    /// True when the straight segment `a`→`b` passes through the forbidden
    /// region (touching the boundary is allowed).
    pub fn segment_enters(&self, a: &Pos, b: &Pos) -> bool {
        if self.outside {
            // The allowed region is convex: a segment leaves it only if an
            // end point does.
            return self.forbids(a) || self.forbids(b);
        }
        // Slab method on the open box.
        let (mut t0, mut t1) = (0.0f64, 1.0f64);
        for i in 0..3 {
            let (lo, hi) = (self.lo[i] + EPS, self.hi[i] - EPS);
            let d = b[i] - a[i];
            if d.abs() < 1e-15 {
                if a[i] <= lo || a[i] >= hi {
                    return false;
                }
                continue;
            }
            let (mut ta, mut tb) = ((lo - a[i]) / d, (hi - a[i]) / d);
            if ta > tb {
                std::mem::swap(&mut ta, &mut tb);
            }
            t0 = t0.max(ta);
            t1 = t1.min(tb);
            if t0 >= t1 {
                return false;
            }
        }
        true
    }
}

/// The corners of a non-linear rapid from `a` to `b`: every axis starts
/// together at its own rate (`rates`, mm/min per X Y Z) and stops when it
/// arrives, so the path bends where the quickest axes finish.
pub fn dogleg(a: &Pos, b: &Pos, rates: [f64; 3]) -> Vec<Pos> {
    let mut times: Vec<f64> = (0..3)
        .map(|i| {
            if rates[i] > 0.0 {
                (b[i] - a[i]).abs() / rates[i]
            } else {
                0.0
            }
        })
        .filter(|t| *t > 0.0)
        .collect();
    times.sort_by(f64::total_cmp);
    times.dedup_by(|x, y| (*x - *y).abs() < 1e-15);
    let mut pts = vec![*a];
    for &t in &times {
        let mut p = *b;
        for i in 0..3 {
            let ti = if rates[i] > 0.0 {
                (b[i] - a[i]).abs() / rates[i]
            } else {
                0.0
            };
            if ti > t {
                p[i] = a[i] + (b[i] - a[i]) * t / ti;
            }
        }
        pts.push(p);
    }
    if pts.len() == 1 {
        pts.push(*b);
    }
    pts
}

/// Chord points of an arc in machine coordinates: centre `c`, plane axes
/// `(a1, a2)`, start `s`, end `e`, signed sweep `sweep` (radians, CCW
/// positive), the other axes moving linearly; chords deviate at most
/// `tol` from the arc.
pub fn arc_points(
    s: &Pos,
    e: &Pos,
    c: (f64, f64),
    axes: (usize, usize),
    sweep: f64,
    tol: f64,
) -> Vec<Pos> {
    let (a1, a2) = axes;
    let r = (s[a1] - c.0).hypot(s[a2] - c.1);
    let n = crate::rotary::arc_chords(r, sweep, tol);
    let a0 = (s[a2] - c.1).atan2(s[a1] - c.0);
    let mut pts = Vec::with_capacity(n + 1);
    for k in 0..=n {
        let f = k as f64 / n as f64;
        let mut p = *s;
        for i in 0..p.len() {
            p[i] = s[i] + (e[i] - s[i]) * f;
        }
        let a = a0 + sweep * f;
        p[a1] = c.0 + r * a.cos();
        p[a2] = c.1 + r * a.sin();
        pts.push(p);
    }
    pts[n] = *e;
    pts
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64, y: f64, z: f64) -> Pos {
        [x, y, z, 0.0, 0.0, 0.0]
    }

    /// 000 §15.5.3 area A: X -190…-120, Y -150…-100, all Z.
    fn area_a() -> Area {
        Area {
            lo: [-190.0, -150.0, f64::NEG_INFINITY],
            hi: [-120.0, -100.0, f64::INFINITY],
            outside: false,
        }
    }

    #[test]
    fn segments_against_the_box() {
        let a = area_a();
        // Crossing straight through: y = -125 from x -300 to 0.
        assert!(a.segment_enters(&p(-300.0, -125.0, 0.0), &p(0.0, -125.0, 0.0)));
        // Along the boundary y = -100: allowed.
        assert!(!a.segment_enters(&p(-300.0, -100.0, 0.0), &p(0.0, -100.0, 0.0)));
        // Diagonal clipping the corner (-120, -100): the line x + y = -225
        // passes through (-125, -100) and (-120, -105): inside the box.
        assert!(a.segment_enters(&p(-200.0, -25.0, 0.0), &p(-25.0, -200.0, 0.0)));
        // The line x + y = -215 touches only outside: (-115,-100) … no.
        assert!(!a.segment_enters(&p(-200.0, -15.0, 0.0), &p(-15.0, -200.0, 0.0)));
        // Ending inside.
        assert!(a.segment_enters(&p(0.0, 0.0, 0.0), &p(-150.0, -120.0, 0.0)));
    }

    #[test]
    fn outside_forbidden() {
        let a = Area {
            outside: true,
            ..area_a()
        };
        assert!(!a.segment_enters(&p(-150.0, -120.0, 0.0), &p(-130.0, -110.0, 5.0)));
        assert!(a.segment_enters(&p(-150.0, -120.0, 0.0), &p(-100.0, -110.0, 0.0)));
    }

    #[test]
    fn dogleg_corners() {
        // X 100 at 10000/min (0.01 min), Y 50 at 10000 (0.005 min): the
        // path bends at (50, 50) then runs along X.
        let pts = dogleg(
            &p(0.0, 0.0, 0.0),
            &p(100.0, 50.0, 0.0),
            [10000.0, 10000.0, 10000.0],
        );
        assert_eq!(
            pts,
            vec![p(0.0, 0.0, 0.0), p(50.0, 50.0, 0.0), p(100.0, 50.0, 0.0)]
        );
    }

    #[test]
    fn arc_chords_stay_within_tolerance() {
        // Quarter circle radius 10 about the origin, CCW from (10,0) to (0,10).
        let pts = arc_points(
            &p(10.0, 0.0, 0.0),
            &p(0.0, 10.0, 0.0),
            (0.0, 0.0),
            (0, 1),
            std::f64::consts::FRAC_PI_2,
            1e-3,
        );
        // Sagitta of each chord ≤ 1e-3: r (1 - cos(θ/2)) with θ = (π/2)/n.
        let n = (pts.len() - 1) as f64;
        assert!(10.0 * (1.0 - ((std::f64::consts::FRAC_PI_2 / n) / 2.0).cos()) <= 1e-3);
        for q in &pts {
            assert!((q[0].hypot(q[1]) - 10.0).abs() < 1e-9);
        }
    }
}
