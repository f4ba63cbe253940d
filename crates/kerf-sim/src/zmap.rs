//! The machining center's stock: a height field (Z-map) of f32 heights
//! at cell centres over the stock's XY rectangle, each column of
//! material running from the stock bottom up to its height.

use crate::envelope::Sweep;
use crate::tool::MillTool;

/// Most cells a height field may have (256 MB of f32).
pub const MAX_CELLS: usize = 64 << 20;
/// Cells of the default resolution (64 MB of f32).
pub const DEFAULT_CELLS: usize = 16 << 20;
/// A grid of more than [`crate::mesh::MAX_TOP_VERTICES`] cells is a whole
/// number of 16-cell blocks in X and Y, so that the STL can be decimated
/// by 2, 4, 8 or 16.
pub const BLOCK: usize = 16;
/// Height changes below this are not material (mm).
pub const EPS: f64 = 1e-6;

/// The height field.
#[derive(Clone, Debug)]
pub struct ZMap {
    pub x0: f64,
    pub y0: f64,
    pub dx: f64,
    pub dy: f64,
    pub nx: usize,
    pub ny: usize,
    /// Stock bottom and top.
    pub zmin: f64,
    pub ztop: f64,
    pub h: Vec<f32>,
    /// An upper bound of the heights in each square of [`BLOCK`] cells
    /// (row-major, `nbx` per row): a move skips the squares it cannot
    /// lower with one comparison each.
    bmax: Vec<f32>,
    nbx: usize,
}

/// What one move does to the stock.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Cut {
    /// Material removed by the cutting part, mm³.
    pub removed: f64,
    /// Material the non-cutting part (shank, holder) met, mm³.
    pub holder: f64,
}

impl ZMap {
    /// A full block; `res` is the largest cell size wanted (mm).
    pub fn new(min: [f64; 3], max: [f64; 3], res: f64) -> Result<ZMap, String> {
        let (lx, ly) = (max[0] - min[0], max[1] - min[1]);
        let cells = |l: f64| -> usize {
            let n = (l / res).ceil().max(1.0) as usize;
            n.div_ceil(BLOCK) * BLOCK
        };
        let (fx, fy) = ((lx / res).ceil(), (ly / res).ceil());
        if !(fx * fy).is_finite() || fx * fy > MAX_CELLS as f64 {
            return Err(format!(
                "--sim-res {res}: {:.0} cells on {lx} x {ly} mm, more than {MAX_CELLS} (256 MB)",
                fx * fy
            ));
        }
        // Whole blocks only where the STL will be decimated.
        let (nx, ny) = if fx * fy <= crate::mesh::MAX_TOP_VERTICES as f64 {
            ((fx as usize).max(1), (fy as usize).max(1))
        } else {
            (cells(lx), cells(ly))
        };
        if nx * ny > MAX_CELLS {
            return Err(format!(
                "--sim-res {res}: {} cells, more than {MAX_CELLS}",
                nx * ny
            ));
        }
        Ok(ZMap {
            x0: min[0],
            y0: min[1],
            dx: lx / nx as f64,
            dy: ly / ny as f64,
            nx,
            ny,
            zmin: min[2],
            ztop: max[2],
            h: vec![max[2] as f32; nx * ny],
            bmax: vec![max[2] as f32; nx.div_ceil(BLOCK) * ny.div_ceil(BLOCK)],
            nbx: nx.div_ceil(BLOCK),
        })
    }

    /// The default cell size: the finest whose grid fits [`DEFAULT_CELLS`].
    pub fn default_res(lx: f64, ly: f64) -> f64 {
        // Leave room for the rounding up to whole blocks.
        let r = (lx * ly / DEFAULT_CELLS as f64).sqrt();
        let r = r * 1.02 + 1e-9;
        (r.max(1e-3) * 1000.0).ceil() / 1000.0
    }

    /// Cell area, mm².
    pub fn cell_area(&self) -> f64 {
        self.dx * self.dy
    }

    /// Centre of cell (i, j).
    #[inline]
    pub fn centre(&self, i: usize, j: usize) -> (f64, f64) {
        (
            self.x0 + (i as f64 + 0.5) * self.dx,
            self.y0 + (j as f64 + 0.5) * self.dy,
        )
    }

    /// Height of cell (i, j).
    #[inline]
    pub fn at(&self, i: usize, j: usize) -> f64 {
        self.h[j * self.nx + i] as f64
    }

    /// Material left, mm³.
    pub fn volume(&self) -> f64 {
        let s: f64 = self
            .h
            .iter()
            .map(|&z| (z as f64 - self.zmin).max(0.0))
            .sum();
        s * self.cell_area()
    }

    /// Removes what the tool sweeps along `s` (when `write`, keeping the
    /// old heights in `undo`) and measures what the shank and holder meet
    /// (against the heights before the move). With `write` false nothing
    /// changes.
    pub fn cut(
        &mut self,
        tool: &MillTool,
        s: &Sweep,
        write: bool,
        undo: &mut Vec<(u32, f32)>,
    ) -> Cut {
        let mut cut = Cut::default();
        let zmin = self.zmin;
        // Shank/holder: cylinders stacked from the top of the flutes.
        let mut guards: [(f64, f64, f64); 8] = [(0.0, 0.0, 0.0); 8];
        let mut ng = 0;
        if tool.flute_length < 1.0e4 {
            let mut b = tool.flute_length;
            if tool.holder.is_empty() {
                guards[0] = (tool.radius, b, f64::INFINITY);
                ng = 1;
            }
            for &(r, l) in tool.holder.iter().take(8) {
                guards[ng] = (r, b, l);
                b += l;
                ng += 1;
            }
        }
        let reach = tool.reach();
        let fast_flat = s.level() && matches!(tool.kind, crate::tool::MillKind::Flat) && ng == 0;
        let grid = self.grid();
        let h = &mut self.h;
        // Nothing at or below the move's lowest tip height can change (the
        // tool's profile and the holder are above the tip).
        // On a row at distance dy from the move's Y range every cell is at
        // least dy from the axis, so the tool reaches no lower than
        // zlow + f(dy) there (and the holder no lower than zlow + its
        // lowest offset): cells at or below that cannot change.
        let zlow = s.p0[2].min(s.p1[2]);
        let bmin = guards[..ng]
            .iter()
            .map(|g| g.1)
            .fold(f64::INFINITY, f64::min);
        let (ya, yb) = (s.p0[1].min(s.p1[1]), s.p0[1].max(s.p1[1]));
        // A level flat end mill without a holder lowers every cell of its
        // capsule (the cells whose centres are within its radius of the
        // move) to its height: no envelope to evaluate.
        let flat_z = fast_flat.then(|| s.p0[2].max(zmin));
        let (bmax, nbx) = (&self.bmax, self.nbx);
        let mut touched: Vec<usize> = Vec::new();
        grid.for_rows(s, reach, |j, y, a, b| {
            let dy = (ya - y).max(y - yb).max(0.0).min(tool.radius);
            let floor = (zlow + tool.profile(dy).min(bmin)).max(zmin) as f32;
            let base = j * grid.nx;
            let brow = (j / BLOCK) * nbx;
            let mut i = a;
            while i <= b {
                let bi = i / BLOCK;
                let end = ((bi + 1) * BLOCK - 1).min(b);
                let (i0, ie) = (i, end);
                i = end + 1;
                // Nothing in this square is above what the move can reach.
                if bmax[brow + bi] <= floor {
                    continue;
                }
                let mut wrote = false;
                for k in i0..=ie {
                    let v = &mut h[base + k];
                    if *v <= floor {
                        continue;
                    }
                    let old = *v as f64;
                    let z = if let Some(z) = flat_z {
                        Some(z)
                    } else {
                        if old <= zmin + EPS {
                            continue;
                        }
                        let x = grid.x0 + (k as f64 + 0.5) * grid.dx;
                        for &(r, b, l) in &guards[..ng] {
                            if let Some(z) = s.flat(x, y, r, b) {
                                if old > z + EPS {
                                    cut.holder += old.min(z + l) - z;
                                }
                            }
                        }
                        s.tool_above(tool, x, y, old - EPS).map(|z| z.max(zmin))
                    };
                    if let Some(z) = z {
                        if z < old - EPS {
                            cut.removed += old - z;
                            if write {
                                undo.push(((base + k) as u32, *v));
                                *v = z as f32;
                                wrote = true;
                            }
                        }
                    }
                }
                if wrote && touched.last() != Some(&(brow + bi)) {
                    touched.push(brow + bi);
                }
            }
        });
        touched.sort_unstable();
        touched.dedup();
        for b in touched {
            self.bmax[b] = self.block_max(b);
        }
        let a = self.cell_area();
        cut.removed *= a;
        cut.holder *= a;
        cut
    }

    /// Puts back the heights a [`Self::cut`] changed.
    pub fn restore(&mut self, undo: &mut Vec<(u32, f32)>) {
        for &(i, z) in undo.iter().rev() {
            let i = i as usize;
            self.h[i] = z;
            let b = (i / self.nx / BLOCK) * self.nbx + (i % self.nx) / BLOCK;
            self.bmax[b] = self.bmax[b].max(z);
        }
        undo.clear();
    }

    /// The greatest height in square `b`.
    fn block_max(&self, b: usize) -> f32 {
        let (bj, bi) = (b / self.nbx, b % self.nbx);
        let (i0, i1) = (bi * BLOCK, ((bi + 1) * BLOCK).min(self.nx));
        let (j0, j1) = (bj * BLOCK, ((bj + 1) * BLOCK).min(self.ny));
        let mut m = f32::NEG_INFINITY;
        for j in j0..j1 {
            let row = &self.h[j * self.nx + i0..j * self.nx + i1];
            m = row.iter().fold(m, |a, &v| a.max(v));
        }
        m
    }

    /// Height at the cell under (x, y), if inside.
    pub fn height_at(&self, x: f64, y: f64) -> Option<f64> {
        let i = ((x - self.x0) / self.dx).floor();
        let j = ((y - self.y0) / self.dy).floor();
        if i < 0.0 || j < 0.0 || i >= self.nx as f64 || j >= self.ny as f64 {
            return None;
        }
        Some(self.at(i as usize, j as usize))
    }

    /// The cell layout.
    pub fn grid(&self) -> Grid {
        Grid {
            x0: self.x0,
            y0: self.y0,
            dx: self.dx,
            dy: self.dy,
            nx: self.nx,
            ny: self.ny,
        }
    }
}

/// The cell layout of a height field.
#[derive(Clone, Copy, Debug)]
pub struct Grid {
    pub x0: f64,
    pub y0: f64,
    pub dx: f64,
    pub dy: f64,
    pub nx: usize,
    pub ny: usize,
}

/// Cell index range (inclusive) whose centres lie within [lo, hi].
fn range(lo: f64, hi: f64, o: f64, d: f64, n: usize) -> Option<(usize, usize)> {
    let a = ((lo - o) / d - 0.5).ceil().max(0.0);
    let b = ((hi - o) / d - 0.5).floor().min(n as f64 - 1.0);
    (a <= b).then_some((a as usize, b as usize))
}

impl Grid {
    /// Cells within `r` of the move's XY path, row by row: calls
    /// `f(row, y, first, last)` with the row's span of cell columns.
    pub fn for_rows(&self, s: &Sweep, r: f64, mut f: impl FnMut(usize, f64, usize, usize)) {
        let (xa, xb) = (s.p0[0].min(s.p1[0]) - r, s.p0[0].max(s.p1[0]) + r);
        let (ya, yb) = (s.p0[1].min(s.p1[1]) - r, s.p0[1].max(s.p1[1]) + r);
        let Some((i0, i1)) = range(xa, xb, self.x0, self.dx, self.nx) else {
            return;
        };
        let Some((j0, j1)) = range(ya, yb, self.y0, self.dy, self.ny) else {
            return;
        };
        for j in j0..=j1 {
            let y = self.y0 + (j as f64 + 0.5) * self.dy;
            // The X span of the capsule on this row narrows the scan.
            let (lo, hi) = capsule_span(s, r, y);
            let Some((a, b)) = range(
                (lo - 1e-9).max(xa),
                (hi + 1e-9).min(xb),
                self.x0,
                self.dx,
                self.nx,
            ) else {
                continue;
            };
            let (a, b) = (a.max(i0), b.min(i1));
            if a <= b {
                f(j, y, a, b);
            }
        }
    }
}

/// X interval of the capsule (points within `r` of the move's XY
/// segment) on the row at `y`: the end discs and the band between them.
fn capsule_span(s: &Sweep, r: f64, y: f64) -> (f64, f64) {
    let mut lo = f64::INFINITY;
    let mut hi = f64::NEG_INFINITY;
    for p in [s.p0, s.p1] {
        let dy = y - p[1];
        if dy.abs() <= r {
            let w = (r * r - dy * dy).sqrt();
            lo = lo.min(p[0] - w);
            hi = hi.max(p[0] + w);
        }
    }
    let (dx, dy) = (s.p1[0] - s.p0[0], s.p1[1] - s.p0[1]);
    let l = dx.hypot(dy);
    if l > 1e-12 {
        let (ux, uy) = (dx / l, dy / l);
        let yy = y - s.p0[1];
        // cross = xx uy - yy ux in [-r, r]; along = xx ux + yy uy in [0, l],
        // with xx = x - x0: each a linear interval in xx.
        let (a1, b1) = lin_interval(uy, -yy * ux, -r, r);
        let (a2, b2) = lin_interval(ux, yy * uy, 0.0, l);
        let (a, b) = (a1.max(a2), b1.min(b2));
        if a <= b {
            lo = lo.min(s.p0[0] + a);
            hi = hi.max(s.p0[0] + b);
        }
    }
    (lo, hi)
}

/// The x with `k x + c` in [lo, hi].
fn lin_interval(k: f64, c: f64, lo: f64, hi: f64) -> (f64, f64) {
    if k.abs() < 1e-12 {
        if (lo..=hi).contains(&c) {
            (f64::NEG_INFINITY, f64::INFINITY)
        } else {
            (f64::INFINITY, f64::NEG_INFINITY)
        }
    } else {
        let (a, b) = ((lo - c) / k, (hi - c) / k);
        (a.min(b), a.max(b))
    }
}
