//! The depth of the cut over the mill's XY view: the lowest Z the tool
//! tip reached in each cell of a square grid, for a program too dense to
//! read as lines (a 3-D surface raster draws as a solid rectangle).
//!
//! The grid has a fixed number of cells a side ([`CELLS`]), so its
//! memory is bounded by the picture, not the program. Its cell is a
//! power of two of a millimetre; when a point falls outside the window
//! the window moves over the cut so far, and when the cut is wider than
//! the window the cell doubles and each 2×2 block of cells keeps its
//! lowest Z. A cut segment marks every cell its tip passes through (it
//! is sampled at half a cell), so the map is the tip's path, not the
//! tool's swept area.

/// Cells a side.
pub const CELLS: usize = 512;

/// The first cell size, mm (2⁻⁶).
const FIRST_CELL: f64 = 1.0 / 64.0;

/// The lowest Z per cell over the cut so far (see the module doc).
#[derive(Clone, Debug)]
pub struct DepthMap {
    n: usize,
    /// Cell size, mm.
    cell: f64,
    /// Grid index of the window's first column and row.
    origin: (i64, i64),
    /// Lowest Z per cell of the window, row by row; NaN where nothing
    /// was cut. Empty until the first point.
    z: Vec<f32>,
    /// The cut cells' index bounds (lo > hi when none).
    lo: (i64, i64),
    hi: (i64, i64),
    /// Cells that hold a depth.
    filled: usize,
}

impl Default for DepthMap {
    fn default() -> Self {
        DepthMap::new(CELLS)
    }
}

impl DepthMap {
    /// An empty map of `n` × `n` cells (at least 2).
    pub fn new(n: usize) -> DepthMap {
        DepthMap {
            n: n.max(2),
            cell: FIRST_CELL,
            origin: (0, 0),
            z: Vec::new(),
            lo: (i64::MAX, i64::MAX),
            hi: (i64::MIN, i64::MIN),
            filled: 0,
        }
    }

    /// The cell size now, mm.
    pub fn cell(&self) -> f64 {
        self.cell
    }

    /// How many cells hold a depth.
    pub fn cells(&self) -> usize {
        self.filled
    }

    /// The lowest and highest of the cells' depths (each cell's lowest
    /// Z), None before any cut.
    pub fn z_range(&self) -> Option<(f64, f64)> {
        let mut cells = self.z.iter().filter(|z| !z.is_nan());
        let first = *cells.next()?;
        let (lo, hi) = cells.fold((first, first), |(lo, hi), &z| (lo.min(z), hi.max(z)));
        Some((lo as f64, hi as f64))
    }

    /// The share of the cells inside the cut's bounding box that hold a
    /// depth (0 when nothing was cut): near 1 for an area cleared or a
    /// surface rastered at the cell size, small for a few lines.
    pub fn coverage(&self) -> f64 {
        if self.filled == 0 {
            return 0.0;
        }
        let w = (self.hi.0 - self.lo.0 + 1) as f64;
        let h = (self.hi.1 - self.lo.1 + 1) as f64;
        self.filled as f64 / (w * h)
    }

    /// Marks the straight cut from `a` to `b` (X, Y, Z, mm).
    pub fn line(&mut self, a: [f64; 3], b: [f64; 3]) {
        if a.iter().chain(&b).any(|v| !v.is_finite()) {
            return;
        }
        // The start is marked before the end is fitted, so the window
        // that holds the end holds it too, and every point between.
        self.fit(a[0], a[1]);
        self.mark(a[0], a[1], a[2] as f32);
        self.fit(b[0], b[1]);
        // Both ends fit, so the segment is at most the window's diagonal:
        // at most about 1.5 · 2 · n samples.
        let len = (b[0] - a[0]).hypot(b[1] - a[1]);
        let steps = (len / (0.5 * self.cell)).ceil().max(1.0) as usize;
        for k in 0..=steps {
            let t = k as f64 / steps as f64;
            let p = |i: usize| a[i] + (b[i] - a[i]) * t;
            self.mark(p(0), p(1), p(2) as f32);
        }
    }

    /// The lowest Z cut in the cell holding (`x`, `y`); a cell left empty
    /// between cut neighbours (a path a little wider apart than a cell)
    /// takes the lowest of its eight neighbours. None elsewhere.
    pub fn depth_at(&self, x: f64, y: f64) -> Option<f64> {
        let (i, j) = self.index(x, y);
        if let Some(z) = self.get(i, j) {
            return Some(z as f64);
        }
        let mut best: Option<f32> = None;
        for (di, dj) in [
            (-1, 0),
            (1, 0),
            (0, -1),
            (0, 1),
            (-1, -1),
            (1, 1),
            (-1, 1),
            (1, -1),
        ] {
            if let Some(z) = self.get(i + di, j + dj) {
                best = Some(best.map_or(z, |b| b.min(z)));
            }
        }
        best.map(f64::from)
    }

    fn index(&self, x: f64, y: f64) -> (i64, i64) {
        (
            (x / self.cell).floor() as i64,
            (y / self.cell).floor() as i64,
        )
    }

    fn slot(&self, i: i64, j: i64) -> Option<usize> {
        let (ci, cj) = (i - self.origin.0, j - self.origin.1);
        let n = self.n as i64;
        (ci >= 0 && cj >= 0 && ci < n && cj < n).then(|| (cj * n + ci) as usize)
    }

    fn get(&self, i: i64, j: i64) -> Option<f32> {
        let z = *self.z.get(self.slot(i, j)?)?;
        (!z.is_nan()).then_some(z)
    }

    fn mark(&mut self, x: f64, y: f64, z: f32) {
        let (i, j) = self.index(x, y);
        let Some(s) = self.slot(i, j) else { return };
        let old = self.z[s];
        if old.is_nan() {
            self.filled += 1;
            self.lo = (self.lo.0.min(i), self.lo.1.min(j));
            self.hi = (self.hi.0.max(i), self.hi.1.max(j));
            self.z[s] = z;
        } else if z < old {
            self.z[s] = z;
        }
    }

    /// Makes the window hold (`x`, `y`): coarser cells while the cut and
    /// the point are wider than the window, then the window centred on
    /// them if the point is outside it.
    fn fit(&mut self, x: f64, y: f64) {
        if self.z.is_empty() {
            self.z = vec![f32::NAN; self.n * self.n];
            let (i, j) = self.index(x, y);
            let half = (self.n / 2) as i64;
            self.origin = (i - half, j - half);
        }
        loop {
            let (i, j) = self.index(x, y);
            if self.slot(i, j).is_some() {
                return;
            }
            let lo = (self.lo.0.min(i), self.lo.1.min(j));
            let hi = (self.hi.0.max(i), self.hi.1.max(j));
            let n = self.n as i64;
            if hi.0 - lo.0 < n && hi.1 - lo.1 < n {
                // Centre the window on the cut and the point.
                let o = |lo: i64, hi: i64| lo - (n - (hi - lo + 1)) / 2;
                self.rebuild(0, (o(lo.0, hi.0), o(lo.1, hi.1)));
                return;
            }
            let o = (self.origin.0 >> 1, self.origin.1 >> 1);
            self.rebuild(1, o);
        }
    }

    /// The cells again with their index shifted right by `shift` bits
    /// (each 2×2 block merged to its lowest Z when 1), in a window at
    /// `origin` (of the new index); cells outside it are dropped (the
    /// callers choose windows that hold them all).
    fn rebuild(&mut self, shift: u32, origin: (i64, i64)) {
        let n = self.n as i64;
        let old = std::mem::replace(&mut self.z, vec![f32::NAN; self.n * self.n]);
        let old_origin = self.origin;
        self.cell *= f64::from(1u32 << shift);
        self.origin = origin;
        self.lo = (i64::MAX, i64::MAX);
        self.hi = (i64::MIN, i64::MIN);
        self.filled = 0;
        for (k, z) in old.into_iter().enumerate() {
            if z.is_nan() {
                continue;
            }
            let i = (old_origin.0 + k as i64 % n) >> shift;
            let j = (old_origin.1 + k as i64 / n) >> shift;
            if let Some(s) = self.slot(i, j) {
                if self.z[s].is_nan() {
                    self.filled += 1;
                    self.lo = (self.lo.0.min(i), self.lo.1.min(j));
                    self.hi = (self.hi.0.max(i), self.hi.1.max(j));
                    self.z[s] = z;
                } else {
                    self.z[s] = self.z[s].min(z);
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_cut_is_found_where_it_went_and_nowhere_else() {
        // One line at Z-2 from (0, 0) to (10, 0) in a map with 1/64 mm
        // cells: (5, 0) is on it, (5, 3) is 192 cells away.
        let mut m = DepthMap::new(CELLS);
        m.line([0.0, 0.0, -2.0], [10.0, 0.0, -2.0]);
        assert_eq!(m.depth_at(5.0, 0.0), Some(-2.0));
        assert_eq!(m.depth_at(5.0, 3.0), None);
        assert_eq!(m.z_range(), Some((-2.0, -2.0)));
        // 10 mm = 640 cells > 512: the cell doubled once, to 1/32 mm.
        assert_eq!(m.cell(), 1.0 / 32.0);
    }

    #[test]
    fn a_ramp_keeps_its_slope_and_the_lowest_pass_wins() {
        // Z = X / 10 over X 0..100; a second pass 1 mm lower at X 50..100.
        let mut m = DepthMap::new(CELLS);
        m.line([0.0, 0.0, 0.0], [100.0, 0.0, 10.0]);
        m.line([50.0, 0.0, 4.0], [100.0, 0.0, 9.0]);
        // 100 mm over 512 cells: the cell is 2⁻² mm (64 mm < 100 ≤ 128).
        let c = m.cell();
        assert_eq!(c, 0.25);
        for x in [10.0, 30.0, 49.0] {
            let z = m.depth_at(x + c / 2.0, 0.0).unwrap();
            // The lowest Z in the cell: the cell's left edge, within a cell.
            assert!((z - x / 10.0).abs() <= c / 10.0 + 1e-6, "{x}: {z}");
        }
        // The range is of the cells' lowest: 0 at X0, 9 at the end.
        let (lo, hi) = m.z_range().unwrap();
        assert!(
            lo == 0.0 && (hi - 9.0).abs() <= c / 10.0 + 1e-6,
            "{lo} {hi}"
        );
        for x in [60.0, 90.0] {
            let z = m.depth_at(x + c / 2.0, 0.0).unwrap();
            assert!((z - (x / 10.0 - 1.0)).abs() <= c / 10.0 + 1e-6, "{x}: {z}");
        }
    }

    #[test]
    fn coarsening_keeps_the_lowest_of_each_block() {
        // Two cuts 1/64 mm apart at Z-1 and Z-3, then one far away: after
        // the cell grows they share a cell, which keeps Z-3.
        let mut m = DepthMap::new(8);
        m.line([0.0, 0.0, -1.0], [0.0, 0.0, -1.0]);
        m.line([1.0 / 64.0, 0.0, -3.0], [1.0 / 64.0, 0.0, -3.0]);
        m.line([1.0, 0.0, 0.0], [1.0, 0.0, 0.0]);
        assert!(m.cell() >= 1.0 / 8.0);
        assert_eq!(m.depth_at(0.001, 0.001), Some(-3.0));
        assert_eq!(m.depth_at(1.0, 0.0), Some(0.0));
    }

    #[test]
    fn moving_the_window_keeps_what_was_cut() {
        // Points walking away one by one inside the span: the window
        // moves (no coarsening needed) and the first point stays.
        let mut m = DepthMap::new(64);
        for k in 0..60 {
            let x = k as f64 / 64.0;
            m.line([x, 0.0, -(k as f64)], [x, 0.0, -(k as f64)]);
        }
        assert_eq!(m.cell(), 1.0 / 64.0);
        assert_eq!(m.depth_at(0.0, 0.0), Some(0.0));
        assert_eq!(m.depth_at(59.0 / 64.0, 0.0), Some(-59.0));
    }

    #[test]
    fn coverage_tells_an_area_from_a_few_lines() {
        // A 10 × 10 mm square rastered at 0.01 mm rows: every cell of its
        // box is cut. Its outline alone: a few percent.
        let mut area = DepthMap::new(CELLS);
        for r in 0..=1000 {
            let y = r as f64 * 0.01;
            area.line([0.0, y, -1.0], [10.0, y, -1.0]);
        }
        assert!(area.coverage() > 0.99, "{}", area.coverage());
        let mut outline = DepthMap::new(CELLS);
        let c = [
            (0.0, 0.0),
            (10.0, 0.0),
            (10.0, 10.0),
            (0.0, 10.0),
            (0.0, 0.0),
        ];
        for w in c.windows(2) {
            outline.line([w[0].0, w[0].1, -1.0], [w[1].0, w[1].1, -1.0]);
        }
        assert!(outline.coverage() < 0.02, "{}", outline.coverage());
    }

    #[test]
    fn a_cell_missed_between_cut_neighbours_takes_their_depth() {
        // Rows 1.5 cells apart leave every other row of cells empty.
        let mut m = DepthMap::new(CELLS);
        m.line([0.0, 0.0, -1.0], [4.0, 0.0, -1.0]);
        let c = m.cell();
        m.line([0.0, 2.0 * c, -2.0], [4.0, 2.0 * c, -2.0]);
        assert_eq!(m.depth_at(1.0, 1.5 * c), Some(-2.0));
        assert_eq!(m.depth_at(1.0, 6.0 * c), None);
    }

    #[test]
    fn not_a_number_is_ignored() {
        let mut m = DepthMap::new(CELLS);
        m.line([f64::NAN, 0.0, 0.0], [1.0, 0.0, 0.0]);
        assert_eq!(m.z_range(), None);
        assert_eq!(m.coverage(), 0.0);
    }
}
