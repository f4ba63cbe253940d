//! The cell layout of the machining center's height field: a rectangle
//! of `nx × ny` cells of `dx × dy` mm from (x0, y0), and which cells a
//! move's capsule covers, row by row.

use crate::envelope::Sweep;

/// The cell layout of a height field.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Grid {
    /// Corner of the first cell (the stock's XMIN, YMIN), mm.
    pub x0: f64,
    pub y0: f64,
    /// Cell size, mm.
    pub dx: f64,
    pub dy: f64,
    /// Cells in X and Y.
    pub nx: usize,
    pub ny: usize,
}

impl Grid {
    /// Cell area, mm².
    pub fn cell_area(&self) -> f64 {
        self.dx * self.dy
    }

    /// Number of cells.
    pub fn cells(&self) -> usize {
        self.nx * self.ny
    }

    /// The far corner (XMAX, YMAX), mm.
    pub fn end(&self) -> (f64, f64) {
        (
            self.x0 + self.nx as f64 * self.dx,
            self.y0 + self.ny as f64 * self.dy,
        )
    }

    /// Centre of cell (i, j).
    #[inline]
    pub fn centre(&self, i: usize, j: usize) -> (f64, f64) {
        (
            self.x0 + (i as f64 + 0.5) * self.dx,
            self.y0 + (j as f64 + 0.5) * self.dy,
        )
    }

    /// The cell under (x, y), if inside.
    pub fn cell_at(&self, x: f64, y: f64) -> Option<(usize, usize)> {
        let i = ((x - self.x0) / self.dx).floor();
        let j = ((y - self.y0) / self.dy).floor();
        if i < 0.0 || j < 0.0 || i >= self.nx as f64 || j >= self.ny as f64 {
            return None;
        }
        Some((i as usize, j as usize))
    }

    /// The cells of the bounding box of the points within `r` of the
    /// move's XY path: ((first, last) column, (first, last) row), or None
    /// when it misses the grid.
    pub fn bounds(&self, s: &Sweep, r: f64) -> Option<((usize, usize), (usize, usize))> {
        let (xa, xb) = (s.p0[0].min(s.p1[0]) - r, s.p0[0].max(s.p1[0]) + r);
        let (ya, yb) = (s.p0[1].min(s.p1[1]) - r, s.p0[1].max(s.p1[1]) + r);
        let cols = range(xa, xb, self.x0, 1.0 / self.dx, self.nx)?;
        let rows = range(ya, yb, self.y0, 1.0 / self.dy, self.ny)?;
        Some((cols, rows))
    }

    /// Cells within `r` of the move's XY path, row by row: calls
    /// `f(row, y, first, last)` with the row's span of cell columns.
    pub fn for_rows(&self, s: &Sweep, r: f64, f: impl FnMut(usize, f64, usize, usize)) {
        if let Some((_, rows)) = self.bounds(s, r) {
            self.for_rows_in(s, r, rows, f);
        }
    }

    /// [`Self::for_rows`] on the rows from `rows.0` to `rows.1` only.
    pub fn for_rows_in(
        &self,
        s: &Sweep,
        r: f64,
        rows: (usize, usize),
        mut f: impl FnMut(usize, f64, usize, usize),
    ) {
        let (xa, xb) = (s.p0[0].min(s.p1[0]) - r, s.p0[0].max(s.p1[0]) + r);
        let ix = 1.0 / self.dx;
        let Some((i0, i1)) = range(xa, xb, self.x0, ix, self.nx) else {
            return;
        };
        let cap = Capsule::new(s, r);
        for j in rows.0..=rows.1.min(self.ny.saturating_sub(1)) {
            let y = self.y0 + (j as f64 + 0.5) * self.dy;
            // The X span of the capsule on this row narrows the scan.
            let (lo, hi) = cap.span(y);
            let Some((a, b)) = range(max(lo - 1e-9, xa), min(hi + 1e-9, xb), self.x0, ix, self.nx)
            else {
                continue;
            };
            let (a, b) = (a.max(i0), b.min(i1));
            if a <= b {
                f(j, y, a, b);
            }
        }
    }
}

/// Cell index range (inclusive) whose centres lie within [lo, hi], cells
/// of 1 / `inv` from `o`.
#[inline]
fn range(lo: f64, hi: f64, o: f64, inv: f64, n: usize) -> Option<(usize, usize)> {
    // Clamped to [-1, n] first, so that the integer rounding below (the
    // baseline x86-64 has no instruction for ceil and floor) is exact.
    let top = n as f64;
    let a = ceil(min(max((lo - o) * inv - 0.5, -1.0), top)).max(0);
    let b = floor(min(max((hi - o) * inv - 0.5, -1.0), top)).min(n as i64 - 1);
    (a <= b).then_some((a as usize, b as usize))
}

/// ⌈v⌉ of a finite v of moderate size (NaN gives 0).
#[inline]
fn ceil(v: f64) -> i64 {
    let t = v as i64;
    if (t as f64) < v {
        t + 1
    } else {
        t
    }
}

/// ⌊v⌋ of a finite v of moderate size (NaN gives 0).
#[inline]
fn floor(v: f64) -> i64 {
    let t = v as i64;
    if (t as f64) > v {
        t - 1
    } else {
        t
    }
}

/// The points within `r` of a move's XY segment, prepared for its X
/// interval on a row.
struct Capsule {
    p0: [f64; 2],
    p1: [f64; 2],
    r: f64,
    /// Unit direction, its reciprocals (infinite along an axis) and the
    /// length; None for a vertical move.
    dir: Option<([f64; 2], [f64; 2], f64)>,
}

impl Capsule {
    fn new(s: &Sweep, r: f64) -> Capsule {
        let (dx, dy) = (s.p1[0] - s.p0[0], s.p1[1] - s.p0[1]);
        let l = dx.hypot(dy);
        let dir = (l > 1e-12).then(|| {
            let u = [dx / l, dy / l];
            let inv = |v: f64| {
                if v.abs() < 1e-12 {
                    f64::INFINITY
                } else {
                    1.0 / v
                }
            };
            (u, [inv(u[0]), inv(u[1])], l)
        });
        Capsule {
            p0: [s.p0[0], s.p0[1]],
            p1: [s.p1[0], s.p1[1]],
            r,
            dir,
        }
    }

    /// The X interval on the row at `y`: the end discs and the band
    /// between them (empty: lo > hi).
    #[inline]
    fn span(&self, y: f64) -> (f64, f64) {
        let r = self.r;
        let mut lo = f64::INFINITY;
        let mut hi = f64::NEG_INFINITY;
        for p in [self.p0, self.p1] {
            let dy = y - p[1];
            if dy * dy <= r * r {
                let w = (r * r - dy * dy).sqrt();
                lo = min(lo, p[0] - w);
                hi = max(hi, p[0] + w);
            }
        }
        if let Some(([ux, uy], [iux, iuy], l)) = self.dir {
            let yy = y - self.p0[1];
            // cross = xx uy - yy ux in [-r, r]; along = xx ux + yy uy in
            // [0, l], with xx = x - x0: each a linear interval in xx.
            let (a1, b1) = lin_interval(uy, iuy, -yy * ux, -r, r);
            let (a2, b2) = lin_interval(ux, iux, yy * uy, 0.0, l);
            let (a, b) = (max(a1, a2), min(b1, b2));
            if a <= b {
                lo = min(lo, self.p0[0] + a);
                hi = max(hi, self.p0[0] + b);
            }
        }
        (lo, hi)
    }
}

/// The x with `k x + c` in [lo, hi] (`inv` = 1 / k, infinite for k 0).
#[inline]
fn lin_interval(k: f64, inv: f64, c: f64, lo: f64, hi: f64) -> (f64, f64) {
    if inv.is_infinite() || k.abs() < 1e-12 {
        if (lo..=hi).contains(&c) {
            (f64::NEG_INFINITY, f64::INFINITY)
        } else {
            (f64::INFINITY, f64::NEG_INFINITY)
        }
    } else {
        let (a, b) = ((lo - c) * inv, (hi - c) * inv);
        (min(a, b), max(a, b))
    }
}

/// The lesser of two numbers that are not NaN (a plain comparison: the
/// library's `f64::min` also orders NaN, in several more instructions).
#[inline]
fn min(a: f64, b: f64) -> f64 {
    if a < b {
        a
    } else {
        b
    }
}

/// The greater of two numbers that are not NaN.
#[inline]
fn max(a: f64, b: f64) -> f64 {
    if a > b {
        a
    } else {
        b
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rows_cover_exactly_the_cells_within_the_radius() {
        // 1 mm cells from (0, 0); a move (2.2, 3.1) -> (7.9, 5.4), r 1.7:
        // every cell whose centre is within r of the segment, and no other,
        // by the distance to the segment worked out directly.
        let g = Grid {
            x0: 0.0,
            y0: 0.0,
            dx: 1.0,
            dy: 1.0,
            nx: 12,
            ny: 10,
        };
        let s = Sweep::new([2.2, 3.1, 0.0], [7.9, 5.4, -1.0]);
        let mut got = Vec::new();
        g.for_rows(&s, 1.7, |j, _, a, b| got.extend((a..=b).map(|i| (i, j))));
        let mut want = Vec::new();
        for j in 0..10 {
            for i in 0..12 {
                let (x, y) = g.centre(i, j);
                let (vx, vy) = (5.7, 2.3);
                let t = (((x - 2.2) * vx + (y - 3.1) * vy) / (vx * vx + vy * vy)).clamp(0.0, 1.0);
                let d = (x - 2.2 - t * vx).hypot(y - 3.1 - t * vy);
                if d <= 1.7 {
                    want.push((i, j));
                }
            }
        }
        assert_eq!(got, want);
        assert_eq!(g.cell_at(11.5, 9.99), Some((11, 9)));
        for v in [-2.5, -2.0, -0.5, 0.0, 0.3, 1.0, 7.999, 8.0] {
            assert_eq!(ceil(v), v.ceil() as i64, "{v}");
            assert_eq!(floor(v), v.floor() as i64, "{v}");
        }
        assert_eq!(g.cell_at(12.0, 1.0), None);
    }
}
