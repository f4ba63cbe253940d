//! The lathe's stock: the part is a solid of revolution, so it is held as
//! its half section in the (Z, radius) plane, sampled in columns of width
//! `dz` along Z. Each column holds the radius intervals where material
//! is, exact in radius (f64) at the column's centre.

use std::f64::consts::PI;

use crate::hull::{Hull, Pt};

/// Most columns (8 million: 0.001 mm over 8 m).
pub const MAX_COLUMNS: usize = 8 << 20;
/// Radius changes below this are not material (mm).
pub const EPS: f64 = 1e-7;

/// The half section.
#[derive(Clone, Debug)]
pub struct Section {
    /// Z of the left edge of column 0 and the column width.
    pub z0: f64,
    pub dz: f64,
    /// Material intervals (r_in, r_out) per column, sorted, disjoint.
    pub cols: Vec<Vec<(f64, f64)>>,
}

/// What one sweep did: volume removed and, for a check, volume met.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Touch {
    pub volume: f64,
}

impl Section {
    /// A bar or tube from `z_end` to `z_face`, radii `r_in`..`r_out`.
    pub fn new(
        r_in: f64,
        r_out: f64,
        z_end: f64,
        z_face: f64,
        res: f64,
    ) -> Result<Section, String> {
        let len = z_face - z_end;
        let n = (len / res).ceil();
        if !n.is_finite() || n > MAX_COLUMNS as f64 {
            return Err(format!(
                "--sim-res {res}: {n:.0} columns over {len} mm, more than {MAX_COLUMNS}"
            ));
        }
        let n = (n as usize).max(1);
        Ok(Section {
            z0: z_end,
            dz: len / n as f64,
            cols: vec![vec![(r_in, r_out)]; n],
        })
    }

    /// Centre z of column k.
    pub fn zc(&self, k: usize) -> f64 {
        self.z0 + (k as f64 + 0.5) * self.dz
    }

    /// Volume of revolution of the material, mm³.
    pub fn volume(&self) -> f64 {
        let s: f64 = self
            .cols
            .iter()
            .flatten()
            .map(|&(a, b)| b * b - a * a)
            .sum();
        PI * s * self.dz
    }

    /// Columns whose centres lie in [a, b].
    fn range(&self, a: f64, b: f64) -> Option<(usize, usize)> {
        let k0 = ((a - self.z0) / self.dz - 0.5).ceil().max(0.0);
        let k1 = ((b - self.z0) / self.dz - 0.5)
            .floor()
            .min(self.cols.len() as f64 - 1.0);
        (k0 <= k1).then_some((k0 as usize, k1 as usize))
    }

    /// Removes (when `write`) the material inside the convex hull `h`,
    /// mirrored about the axis where it reaches below r = 0, and returns
    /// the volume it holds.
    pub fn sweep(&mut self, h: &Hull, write: bool) -> f64 {
        let Some((za, zb)) = h.z_range() else {
            return 0.0;
        };
        let Some((k0, k1)) = self.range(za, zb) else {
            return 0.0;
        };
        let mut vol = 0.0;
        let z0 = self.z0 + 0.5 * self.dz;
        let cols = &mut self.cols;
        h.slices(z0, self.dz, k0, k1, |k, lo, hi| {
            let (lo, hi) = fold(lo, hi);
            if hi - lo > EPS {
                vol += subtract(&mut cols[k], lo, hi, write);
            }
        });
        PI * vol * self.dz
    }

    /// The half section's boundary as closed loops of (z, r) points, for
    /// the STL and the picture: each column's intervals as rectangles,
    /// merged into outlines.
    pub fn intervals(&self, k: usize) -> &[(f64, f64)] {
        &self.cols[k]
    }
}

/// The interval in r ≥ 0 covered by [lo, hi] and its mirror.
fn fold(lo: f64, hi: f64) -> (f64, f64) {
    if lo >= 0.0 {
        (lo, hi)
    } else if hi <= 0.0 {
        (-hi, -lo)
    } else {
        (0.0, hi.max(-lo))
    }
}

/// Removes [lo, hi] from the intervals of one column (when `write`);
/// returns the sum of r² differences removed.
fn subtract(col: &mut Vec<(f64, f64)>, lo: f64, hi: f64, write: bool) -> f64 {
    let mut removed = 0.0;
    let mut changed = false;
    for &(a, b) in col.iter() {
        let (x, y) = (a.max(lo), b.min(hi));
        if y - x > EPS {
            removed += y * y - x * x;
            changed = true;
        }
    }
    if write && changed {
        // In place: trim, drop or split the intervals the cut meets.
        let mut i = 0;
        while i < col.len() {
            let (a, b) = col[i];
            if b <= lo || a >= hi {
                i += 1;
                continue;
            }
            match (a < lo - EPS, b > hi + EPS) {
                (true, true) => {
                    col[i] = (a, lo);
                    col.insert(i + 1, (hi, b));
                    i += 2;
                }
                (true, false) => {
                    col[i].1 = lo;
                    i += 1;
                }
                (false, true) => {
                    col[i].0 = hi;
                    i += 1;
                }
                (false, false) => {
                    col.remove(i);
                }
            }
        }
    }
    removed
}

/// The convex hull of an outline placed at two points (the region a
/// convex tool sweeps along a straight move), into `out`.
pub fn swept(outline: &[Pt], p0: Pt, p1: Pt, scratch: &mut Vec<Pt>, out: &mut Hull) {
    scratch.clear();
    for p in [p0, p1] {
        scratch.extend(outline.iter().map(|q| (q.0 + p.0, q.1 + p.1)));
    }
    Hull::of(scratch, out);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn subtracting_splits_and_trims_intervals() {
        let mut c = vec![(0.0, 10.0)];
        let r = subtract(&mut c, 4.0, 6.0, true);
        assert_eq!(c, vec![(0.0, 4.0), (6.0, 10.0)]);
        assert!((r - 20.0).abs() < 1e-12);
        let r = subtract(&mut c, 3.0, 20.0, true);
        assert_eq!(c, vec![(0.0, 3.0)]);
        assert!((r - (16.0 - 9.0 + 100.0 - 36.0)).abs() < 1e-12);
    }

    #[test]
    fn a_rectangle_through_the_axis_is_mirrored() {
        assert_eq!(fold(-2.0, 1.0), (0.0, 2.0));
        assert_eq!(fold(-3.0, -1.0), (1.0, 3.0));
    }
}
