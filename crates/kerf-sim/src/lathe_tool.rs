//! Lathe tool outlines in (Z, X) relative to the programmed point: the
//! insert's nose arc (split with a chord tolerance of 0.5 µm) and its
//! cutting edges, a grooving blade, or a drill on the axis.

use std::f64::consts::PI;

use crate::hull::Pt;
use crate::tool::{tip_vector, LatheKind, LatheTool};

/// Chord tolerance of a nose arc, mm.
pub const NOSE_TOL: f64 = 0.5e-3;

/// Points of an arc about `c` of radius `r` from angle `a0` to `a1`
/// (radians, increasing), chords within [`NOSE_TOL`].
fn arc(c: Pt, r: f64, a0: f64, a1: f64, out: &mut Vec<Pt>) {
    if r <= 0.0 {
        out.push(c);
        return;
    }
    let da = 2.0 * (1.0 - NOSE_TOL / r).max(-1.0).acos();
    // Pieces split at the quadrant points, so that the extreme points in
    // Z and X (where the imaginary tip's tangents touch) are vertices.
    let q = PI / 2.0;
    let mut cuts = vec![a0];
    let mut k = (a0 / q).floor() + 1.0;
    while k * q < a1 - 1e-12 {
        cuts.push(k * q);
        k += 1.0;
    }
    cuts.push(a1);
    out.push((c.0 + r * a0.cos(), c.1 + r * a0.sin()));
    for w in cuts.windows(2) {
        let n = (((w[1] - w[0]) / da).ceil() as usize).clamp(1, 4096);
        for i in 1..=n {
            let a = w[0] + (w[1] - w[0]) * i as f64 / n as f64;
            let (s, co) = a.sin_cos();
            // Exact zeros at the quadrant points.
            let snap = |v: f64| if v.abs() < 1e-15 { 0.0 } else { v };
            out.push((c.0 + r * snap(co), c.1 + r * snap(s)));
        }
    }
}

/// The cutting outline (a convex point set) of a lathe tool.
pub fn cutting_outline(t: &LatheTool) -> Vec<Pt> {
    let r = t.nose_radius;
    let v = tip_vector(t.tip);
    let c = (-r * v.0, -r * v.1);
    let mut out = Vec::new();
    match t.kind {
        LatheKind::Insert {
            angle,
            edge,
            bisector,
        } => {
            let u = bisector.to_radians();
            let half = angle.to_radians() / 2.0;
            // Edge directions into the body; outward normals.
            let (e1, e2) = (u + half, u - half);
            let (n1, n2) = (e1 + PI / 2.0, e2 - PI / 2.0);
            // The nose arc from n2 to n1 through the apex (-u): n2 < n1 going the
            // long way round the back, so walk from n1 up to n2 + 2π.
            let (a0, mut a1) = (n1, n2);
            while a1 < a0 {
                a1 += 2.0 * PI;
            }
            arc(c, r, a0, a1, &mut out);
            for (n, e) in [(n1, e1), (n2, e2)] {
                let tp = (c.0 + r * n.cos(), c.1 + r * n.sin());
                out.push((tp.0 + edge * e.cos(), tp.1 + edge * e.sin()));
            }
        }
        LatheKind::Groove { width, depth } => {
            let sz = if v.0 > 0.0 { -1.0 } else { 1.0 };
            let sx = if v.1 > 0.0 { -1.0 } else { 1.0 };
            // Nose circles at the two corners on the cutting end.
            let c1 = (sz * r, sx * r);
            let c2 = (sz * (width - r), sx * r);
            let (a0, a1) = if sx > 0.0 { (PI, 2.0 * PI) } else { (0.0, PI) };
            arc(c1, r, a0, a1, &mut out);
            arc(c2, r, a0, a1, &mut out);
            out.push((0.0, sx * depth));
            out.push((sz * width, sx * depth));
        }
        LatheKind::Drill {
            diameter,
            point_angle,
            flute_length,
        } => {
            let rr = diameter / 2.0;
            let h = rr / (point_angle.to_radians() / 2.0).tan();
            let l = flute_length.min(1000.0).max(h);
            out.extend([(0.0, 0.0), (h, rr), (l, rr), (l, -rr), (h, -rr)]);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::hull::Hull;

    fn hull(t: &LatheTool) -> Hull {
        let mut pts = cutting_outline(t);
        let mut h = Hull::default();
        Hull::of(&mut pts, &mut h);
        h
    }

    #[test]
    fn a_tip_3_insert_touches_its_programmed_point_from_above_and_right() {
        // Tip 3: the programmed point is the corner (-Z, -X) of the nose's box,
        // so the outline's least z and least x are both 0.
        let t = LatheTool::from_offset(0.8, 3);
        let pts = cutting_outline(&t);
        let zmin = pts.iter().map(|p| p.0).fold(f64::INFINITY, f64::min);
        let xmin = pts.iter().map(|p| p.1).fold(f64::INFINITY, f64::min);
        assert!(zmin.abs() < 1e-9 && xmin.abs() < 1e-9, "{zmin} {xmin}");
        // At z = 0.8 (the nose centre's z) the outline starts at x = 0.
        let h = hull(&t);
        let (lo, _) = h.slice(0.8).unwrap();
        assert!(lo.abs() < 1e-9);
        // Chords within 0.5 µm: at z = 0.8 - 0.8 sin 30° the nose is at
        // x = 0.8 - 0.8 cos 30°.
        let z = 0.8 - 0.4;
        let want = 0.8 - 0.8 * (30f64).to_radians().cos();
        let (lo, _) = h.slice(z).unwrap();
        assert!(
            (lo - want).abs() <= NOSE_TOL && lo >= want - 1e-12,
            "{lo} {want}"
        );
    }

    #[test]
    fn a_groove_blade_spans_its_width() {
        let t = LatheTool {
            kind: LatheKind::Groove {
                width: 3.0,
                depth: 10.0,
            },
            nose_radius: 0.2,
            tip: 3,
            holder: vec![],
        };
        let h = hull(&t);
        assert_eq!(h.z_range(), Some((0.0, 3.0)));
        let (lo, hi) = h.slice(1.5).unwrap();
        assert!(lo.abs() < 1e-12 && (hi - 10.0).abs() < 1e-12);
    }
}
