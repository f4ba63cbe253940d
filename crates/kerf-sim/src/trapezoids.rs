//! The lathe's half section cut into trapezoids between consecutive
//! vertex z values (each slab's edges paired by even-odd), for the flat
//! faces of the picture's cut-away.

use crate::lathe::Contour;

/// A trapezoid: z from `z.0` to `z.1`, bottom edge r `lo.0`..`lo.1`, top
/// edge `hi.0`..`hi.1` (at the slab's left and right ends).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Trapezoid {
    pub z: (f64, f64),
    pub lo: (f64, f64),
    pub hi: (f64, f64),
}

impl Trapezoid {
    /// Area, mm².
    pub fn area(&self) -> f64 {
        0.5 * (self.z.1 - self.z.0) * ((self.hi.0 - self.lo.0) + (self.hi.1 - self.lo.1))
    }
}

/// The region inside `loops` (even-odd) as trapezoids.
pub fn trapezoids(loops: &[Contour]) -> Vec<Trapezoid> {
    // Non-vertical edges as (z_left, r_left, z_right, r_right), by z_left.
    let mut edges: Vec<[f64; 4]> = Vec::new();
    for c in loops {
        for (i, p) in c.iter().enumerate() {
            let q = c[(i + 1) % c.len()];
            if p[0] < q[0] {
                edges.push([p[0], p[1], q[0], q[1]]);
            } else if q[0] < p[0] {
                edges.push([q[0], q[1], p[0], p[1]]);
            }
        }
    }
    edges.sort_by(|a, b| a[0].total_cmp(&b[0]));
    let mut zs: Vec<f64> = edges.iter().flat_map(|e| [e[0], e[2]]).collect();
    zs.sort_by(f64::total_cmp);
    zs.dedup();
    let at = |e: &[f64; 4], z: f64| e[1] + (e[3] - e[1]) * (z - e[0]) / (e[2] - e[0]);
    let mut out = Vec::new();
    let mut active: Vec<[f64; 4]> = Vec::new();
    let mut next = 0;
    let mut cross: Vec<(f64, f64, f64)> = Vec::new();
    for w in zs.windows(2) {
        let (za, zb) = (w[0], w[1]);
        active.retain(|e| e[2] > za);
        while next < edges.len() && edges[next][0] <= za {
            if edges[next][2] > za {
                active.push(edges[next]);
            }
            next += 1;
        }
        let zm = 0.5 * (za + zb);
        cross.clear();
        cross.extend(active.iter().map(|e| (at(e, zm), at(e, za), at(e, zb))));
        cross.sort_by(|a, b| a.0.total_cmp(&b.0));
        for p in cross.chunks_exact(2) {
            out.push(Trapezoid {
                z: (za, zb),
                lo: (p[0].1, p[0].2),
                hi: (p[1].1, p[1].2),
            });
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_stepped_section_with_a_bore_has_its_area() {
        // z 0..10 r 2..5, then z 10..20 r 2..3, with a bore r < 2 empty:
        // area 30 + 10 = 40.
        let c = vec![
            [0.0, 2.0],
            [20.0, 2.0],
            [20.0, 3.0],
            [10.0, 3.0],
            [10.0, 5.0],
            [0.0, 5.0],
        ];
        let t = trapezoids(&[c]);
        let a: f64 = t.iter().map(Trapezoid::area).sum();
        assert!((a - 40.0).abs() < 1e-12, "{a}");
        assert_eq!(t.len(), 2);
        // A triangle z 0..4, r 0 at both ends rising to 4 at z 2: area 8.
        let tri = vec![[0.0, 0.0], [4.0, 0.0], [2.0, 4.0]];
        let a: f64 = trapezoids(&[tri]).iter().map(Trapezoid::area).sum();
        assert!((a - 8.0).abs() < 1e-12, "{a}");
    }
}
