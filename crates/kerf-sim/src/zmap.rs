//! The machining center's stock: a height field (Z-map) of f32 heights
//! at cell centres over the stock's XY rectangle, each column of
//! material running from the stock bottom up to its height.

use crate::envelope::Sweep;
use crate::grid::Grid;
use crate::kernels::Pass;
use crate::tool::MillTool;

/// Most cells a height field may have: 54.5 million, 218 MB of f32 heights
/// plus 14 MB of run and square maxima, so that a run at the largest grid
/// stays under 256 MB of peak memory with the STL and the picture
/// (measured: docs/benchmarks.md, "Simulation").
pub const MAX_CELLS: usize = 52 << 20;
/// Cells of the default resolution (64 MB of f32).
pub const DEFAULT_CELLS: usize = 16 << 20;
/// A grid of more than [`crate::mesh::MAX_TOP_VERTICES`] cells is a whole
/// number of 16-cell blocks in X and Y, so that the STL can be decimated
/// by 2, 4, 8 or 16.
pub const BLOCK: usize = 16;
/// Cells per run of a row whose greatest height is kept (the runs a
/// move cannot lower are skipped with one comparison each).
pub const CHUNK: usize = 16;
/// Height changes below this are not material (mm).
pub const EPS: f64 = 1e-6;

/// The height field.
#[derive(Clone, Debug)]
pub struct ZMap {
    /// The cell layout.
    pub grid: Grid,
    /// Stock bottom and top.
    pub zmin: f64,
    pub ztop: f64,
    /// Heights, row-major (`grid.nx` per row).
    pub h: Vec<f32>,
    /// An upper bound of the heights in each run of [`CHUNK`] cells of a
    /// row (`nc` runs per row), and in each square of [`BLOCK`] rows by
    /// [`CHUNK`] cells (`nc` per band of rows): a move skips the squares
    /// and the runs it cannot lower with one comparison each.
    cmax: Vec<f32>,
    bmax: Vec<f32>,
    nc: usize,
}

/// The rows of one band that a move covers: (row, y, first, last, floor).
type Band = [(usize, f64, usize, usize, f32); BLOCK];

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
    pub fn new(min: [f64; 3], max: [f64; 3], res: f64) -> Result<ZMap, ResolutionError> {
        let (lx, ly) = (max[0] - min[0], max[1] - min[1]);
        let cells = |l: f64| -> usize {
            let n = (l / res).ceil().max(1.0) as usize;
            n.div_ceil(BLOCK) * BLOCK
        };
        let (fx, fy) = ((lx / res).ceil(), (ly / res).ceil());
        if !(fx * fy).is_finite() || fx * fy > MAX_CELLS as f64 {
            return Err(ResolutionError::TooFine {
                res,
                cells: fx * fy,
                lx,
                ly,
            });
        }
        // Whole blocks only where the STL will be decimated.
        let (nx, ny) = if fx * fy <= crate::mesh::MAX_TOP_VERTICES as f64 {
            ((fx as usize).max(1), (fy as usize).max(1))
        } else {
            (cells(lx), cells(ly))
        };
        if nx * ny > MAX_CELLS {
            return Err(ResolutionError::TooManyBlocks {
                res,
                cells: nx * ny,
            });
        }
        let nc = nx.div_ceil(CHUNK);
        Ok(ZMap {
            grid: Grid {
                x0: min[0],
                y0: min[1],
                dx: lx / nx as f64,
                dy: ly / ny as f64,
                nx,
                ny,
            },
            zmin: min[2],
            ztop: max[2],
            h: vec![max[2] as f32; nx * ny],
            cmax: vec![max[2] as f32; nc * ny],
            bmax: vec![max[2] as f32; nc * ny.div_ceil(BLOCK)],
            nc,
        })
    }

    /// The default cell size: the finest whose grid fits [`DEFAULT_CELLS`].
    pub fn default_res(lx: f64, ly: f64) -> f64 {
        // Leave room for the rounding up to whole blocks.
        let r = (lx * ly / DEFAULT_CELLS as f64).sqrt();
        let r = r * 1.02 + 1e-9;
        (r.max(1e-3) * 1000.0).ceil() / 1000.0
    }

    /// Height of cell (i, j).
    #[inline]
    pub fn at(&self, i: usize, j: usize) -> f64 {
        self.h[j * self.grid.nx + i] as f64
    }

    /// Material left, mm³.
    pub fn volume(&self) -> f64 {
        let s: f64 = self
            .h
            .iter()
            .map(|&z| (z as f64 - self.zmin).max(0.0))
            .sum();
        s * self.grid.cell_area()
    }

    /// Removes what the tool sweeps along `s` (when `write`, keeping the
    /// old heights in `undo` if given) and measures what the shank and
    /// holder meet (against the heights before the move). With `write`
    /// false nothing changes.
    pub fn cut(
        &mut self,
        tool: &MillTool,
        s: &Sweep,
        write: bool,
        undo: Option<&mut Vec<(u32, f32)>>,
    ) -> Cut {
        let mut pass = Pass::new(tool, s, self.zmin, write, undo);
        let grid = self.grid;
        // Nothing at or below the move's lowest tip height can change (the
        // tool's profile and the holder are above the tip). On a row at
        // distance dy from the move's Y range every cell is at least dy
        // from the axis, so the tool reaches no lower than zlow + f(dy)
        // there (and the holder no lower than zlow + its lowest offset):
        // cells at or below that cannot change.
        let zlow = s.p0[2].min(s.p1[2]);
        let bmin = pass.guards.lowest();
        let (ya, yb) = (s.p0[1].min(s.p1[1]), s.p0[1].max(s.p1[1]));
        let (shape, zmin) = (pass.shape, self.zmin);
        let floor_at = move |dy: f64| {
            let dy = dy.max(0.0).min(tool.radius);
            (zlow + shape.profile(dy).min(bmin)).max(zmin) as f32
        };
        let reach = tool.reach();
        if let Some(((i0, i1), (j0, j1))) = grid.bounds(s, reach) {
            let mut band: Band = [(0, 0.0, 0, 0, 0.0); BLOCK];
            for bj in j0 / BLOCK..=j1 / BLOCK {
                let rows = ((bj * BLOCK).max(j0), (bj * BLOCK + BLOCK - 1).min(j1));
                // The band's lowest floor (its row nearest the move's Y
                // range): where no square of the capsule's columns is
                // above it, no row of the band can change.
                let (y_lo, y_hi) = (grid.centre(0, rows.0).1, grid.centre(0, rows.1).1);
                let low = floor_at((ya - y_hi).max(y_lo - yb));
                let squares = &self.bmax[bj * self.nc..][i0 / CHUNK..=i1 / CHUNK];
                if squares.iter().all(|&m| m <= low) {
                    continue;
                }
                let mut n = 0;
                grid.for_rows_in(s, reach, rows, |j, y, a, b| {
                    band[n] = (j, y, a, b, floor_at((ya - y).max(y - yb)));
                    n += 1;
                });
                if n > 0 {
                    self.band(&mut pass, &band[..n]);
                }
            }
        }
        let a = grid.cell_area();
        Cut {
            removed: pass.removed * a,
            holder: pass.holder * a,
        }
    }

    /// The rows of one band, square by square: a square whose greatest
    /// height is at or below every row's floor is skipped, then each row's
    /// run whose greatest height is at or below its floor.
    fn band(&mut self, pass: &mut Pass, rows: &[(usize, f64, usize, usize, f32)]) {
        let (nx, nc) = (self.grid.nx, self.nc);
        let bj = rows[0].0 / BLOCK;
        let lo = rows.iter().map(|r| r.2).min().unwrap_or(0);
        let hi = rows.iter().map(|r| r.3).max().unwrap_or(0);
        let floor = rows.iter().map(|r| r.4).fold(f32::INFINITY, f32::min);
        for c in lo / CHUNK..=hi / CHUNK {
            if self.bmax[bj * nc + c] <= floor {
                continue;
            }
            let mut changed = false;
            for &(j, y, a, b, floor) in rows {
                let (first, last) = (a.max(c * CHUNK), b.min(c * CHUNK + CHUNK - 1));
                if first > last || self.cmax[j * nc + c] <= floor {
                    continue;
                }
                let x0 = self.grid.x0 + (first as f64 + 0.5) * self.grid.dx;
                let (i0, i1) = (j * nx + first, j * nx + last);
                let h = &mut self.h[i0..=i1];
                if pass.run(h, i0 as u32, x0, self.grid.dx, y, floor) {
                    let run = &self.h[j * nx + c * CHUNK..j * nx + ((c + 1) * CHUNK).min(nx)];
                    self.cmax[j * nc + c] = run.iter().fold(f32::NEG_INFINITY, |m, &v| m.max(v));
                    changed = true;
                }
            }
            if changed {
                let rows = bj * BLOCK..((bj + 1) * BLOCK).min(self.grid.ny);
                self.bmax[bj * nc + c] = rows
                    .map(|j| self.cmax[j * nc + c])
                    .fold(f32::NEG_INFINITY, f32::max);
            }
        }
    }

    /// Puts back the heights a [`Self::cut`] changed.
    pub fn restore(&mut self, undo: &mut Vec<(u32, f32)>) {
        for &(i, z) in undo.iter().rev() {
            let i = i as usize;
            self.h[i] = z;
            let (j, c) = (i / self.grid.nx, (i % self.grid.nx) / CHUNK);
            let (k, b) = (j * self.nc + c, (j / BLOCK) * self.nc + c);
            self.cmax[k] = self.cmax[k].max(z);
            self.bmax[b] = self.bmax[b].max(z);
        }
        undo.clear();
    }

    /// Height at the cell under (x, y), if inside.
    pub fn height_at(&self, x: f64, y: f64) -> Option<f64> {
        let (i, j) = self.grid.cell_at(x, y)?;
        Some(self.at(i, j))
    }
}

/// A `--sim-res` refused.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ResolutionError {
    /// Outside the accepted cell sizes.
    #[error("--sim-res {res}: the cell size must be 0.001-10 mm")]
    OutOfRange { res: f64 },
    /// More cells than [`MAX_CELLS`] at the resolution asked for.
    #[error("--sim-res {res}: {cells:.0} cells on {lx} x {ly} mm, more than {max} (256 MB)", max = MAX_CELLS)]
    TooFine {
        res: f64,
        cells: f64,
        lx: f64,
        ly: f64,
    },
    /// More than [`MAX_CELLS`] after rounding up to whole blocks.
    #[error("--sim-res {res}: {cells} cells, more than {max}", max = MAX_CELLS)]
    TooManyBlocks { res: f64, cells: usize },
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shape::Shape;
    use crate::tool::MillKind;
    use proptest::prelude::*;

    /// The height field after `moves` worked out cell by cell with the
    /// general envelope only (no skipped squares or runs, no fast kernel),
    /// and the material removed, mm³.
    fn reference(z: &ZMap, tool: &MillTool, moves: &[([f64; 3], [f64; 3])]) -> (Vec<f32>, f64) {
        let (g, mut h, mut removed) = (z.grid, z.h.clone(), 0.0);
        let shape = Shape::of(tool);
        for &(a, b) in moves {
            let s = Sweep::new(a, b);
            for j in 0..g.ny {
                for i in 0..g.nx {
                    let (x, y) = g.centre(i, j);
                    let v = &mut h[j * g.nx + i];
                    let old = *v as f64;
                    if old <= z.zmin + EPS {
                        continue;
                    }
                    let Some(n) = s.tool_above(&shape, x, y, old - EPS) else {
                        continue;
                    };
                    let n = n.max(z.zmin);
                    if n < old - EPS {
                        removed += old - n;
                        *v = n as f32;
                    }
                }
            }
        }
        (h, removed * g.cell_area())
    }

    fn tool(kind: u8, r: f64) -> MillTool {
        let kind = match kind {
            0 => MillKind::Flat,
            1 => MillKind::Ball,
            2 => MillKind::Drill { point_angle: 118.0 },
            _ => MillKind::Bull { corner: r / 3.0 },
        };
        MillTool {
            kind,
            ..MillTool::flat(r)
        }
    }

    /// A move: random, or level, or vertical (the fast kernels' cases).
    fn a_move() -> impl Strategy<Value = ([f64; 3], [f64; 3])> {
        let p = || (-2.0f64..22.0, -2.0f64..17.0, -6.0f64..1.0);
        (p(), p(), 0u8..3).prop_map(|((x0, y0, z0), (x1, y1, z1), how)| match how {
            0 => ([x0, y0, z0], [x1, y1, z1]),
            1 => ([x0, y0, z0], [x1, y1, z0]),
            _ => ([x0, y0, z0], [x0, y0, z1]),
        })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(300))]
        /// Random moves of a flat, ball, drill or bull tool: the same
        /// heights and volume as the cell-by-cell general evaluation.
        #[test]
        fn fast_paths_agree_with_the_general_envelope(
            kind in 0u8..4,
            r in 0.4f64..4.0,
            moves in prop::collection::vec(a_move(), 1..5),
        ) {
            let mut z = ZMap::new([0.0, 0.0, -5.0], [20.0, 15.0, 0.0], 0.25).unwrap();
            let t = tool(kind, r);
            let (want, removed) = reference(&z, &t, &moves);
            let mut got = 0.0;
            for &(a, b) in &moves {
                got += z.cut(&t, &Sweep::new(a, b), true, None).removed;
            }
            let bad = (0..want.len()).find(|&i| (z.h[i] - want[i]).abs() > 1e-6);
            prop_assert!(bad.is_none(), "cell {:?}: {:?} vs {:?}", bad,
                bad.map(|i| z.h[i]), bad.map(|i| want[i]));
            prop_assert!((got - removed).abs() <= 1e-9 * (1.0 + removed), "{got} vs {removed}");
        }
    }
}
