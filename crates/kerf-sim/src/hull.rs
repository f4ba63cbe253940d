//! Convex hulls in the (Z, radius) half plane and their slices by the
//! vertical lines of the lathe model's columns.

/// A point (z, r).
pub type Pt = (f64, f64);

/// A convex polygon as its lower and upper chains, both from the least
/// to the greatest z.
#[derive(Clone, Debug, Default)]
pub struct Hull {
    pub lower: Vec<Pt>,
    pub upper: Vec<Pt>,
}

fn cross(o: Pt, a: Pt, b: Pt) -> f64 {
    (a.0 - o.0) * (b.1 - o.1) - (a.1 - o.1) * (b.0 - o.0)
}

impl Hull {
    /// The convex hull of `pts` (Andrew's monotone chain); `pts` is
    /// sorted in place.
    pub fn of(pts: &mut [Pt], out: &mut Hull) {
        pts.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
        out.lower.clear();
        out.upper.clear();
        for &p in pts.iter() {
            while out.lower.len() >= 2
                && cross(
                    out.lower[out.lower.len() - 2],
                    out.lower[out.lower.len() - 1],
                    p,
                ) <= 0.0
            {
                out.lower.pop();
            }
            out.lower.push(p);
            while out.upper.len() >= 2
                && cross(
                    out.upper[out.upper.len() - 2],
                    out.upper[out.upper.len() - 1],
                    p,
                ) >= 0.0
            {
                out.upper.pop();
            }
            out.upper.push(p);
        }
    }

    /// Least and greatest z.
    pub fn z_range(&self) -> Option<(f64, f64)> {
        Some((self.lower.first()?.0, self.lower.last()?.0))
    }

    /// The hull's r interval on the line z = `z`, if it meets it.
    pub fn slice(&self, z: f64) -> Option<(f64, f64)> {
        let (a, b) = self.z_range()?;
        if z < a || z > b {
            return None;
        }
        Some((
            chain_at(&self.lower, z, false),
            chain_at(&self.upper, z, true),
        ))
    }

    /// Slices at the evenly spaced z values `z0 + k dz` for k in
    /// `k0..=k1`, in order: calls `f(k, lo, hi)`. Walks both chains once.
    pub fn slices(
        &self,
        z0: f64,
        dz: f64,
        k0: usize,
        k1: usize,
        mut f: impl FnMut(usize, f64, f64),
    ) {
        let (mut il, mut iu) = (0, 0);
        for k in k0..=k1 {
            let z = z0 + k as f64 * dz;
            while il + 2 < self.lower.len() && self.lower[il + 1].0 < z {
                il += 1;
            }
            while iu + 2 < self.upper.len() && self.upper[iu + 1].0 < z {
                iu += 1;
            }
            let lo = seg_at(&self.lower[il..], z, false);
            let hi = seg_at(&self.upper[iu..], z, true);
            f(k, lo, hi);
        }
    }
}

/// r of a chain at z (vertical edges: the extreme value).
fn chain_at(c: &[Pt], z: f64, upper: bool) -> f64 {
    let mut i = 0;
    while i + 2 < c.len() && c[i + 1].0 < z {
        i += 1;
    }
    seg_at(&c[i..], z, upper)
}

fn seg_at(c: &[Pt], z: f64, upper: bool) -> f64 {
    if c.len() == 1 {
        return c[0].1;
    }
    let (p, q) = (c[0], c[1]);
    let w = q.0 - p.0;
    if w <= 1e-15 {
        return if upper { p.1.max(q.1) } else { p.1.min(q.1) };
    }
    let t = ((z - p.0) / w).clamp(0.0, 1.0);
    p.1 + t * (q.1 - p.1)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_square_hull_slices_to_its_height() {
        let mut pts = vec![(0.0, 0.0), (2.0, 0.0), (2.0, 2.0), (0.0, 2.0), (1.0, 1.0)];
        let mut h = Hull::default();
        Hull::of(&mut pts, &mut h);
        assert_eq!(h.slice(1.0), Some((0.0, 2.0)));
        assert_eq!(h.slice(3.0), None);
        // A triangle (0,0) (4,0) (0,4): at z = 1, r from 0 to 3.
        let mut pts = vec![(0.0, 0.0), (4.0, 0.0), (0.0, 4.0)];
        Hull::of(&mut pts, &mut h);
        assert_eq!(h.slice(1.0), Some((0.0, 3.0)));
        let mut got = Vec::new();
        h.slices(0.5, 1.0, 0, 3, |k, lo, hi| got.push((k, lo, hi)));
        assert_eq!(
            got,
            vec![(0, 0.0, 3.5), (1, 0.0, 2.5), (2, 0.0, 1.5), (3, 0.0, 0.5)]
        );
    }
}
