//! The machining center's stock: a height field (Z-map) of f32 heights
//! at cell centres over the stock's XY rectangle, each column of
//! material running from the stock bottom up to its height.

use crate::ball::{BallRow, BallSweep};
use crate::envelope::Sweep;
use crate::grid::Grid;
use crate::shape::Shape;
use crate::tool::{MillKind, MillTool};

/// Most cells a height field may have (256 MB of f32).
pub const MAX_CELLS: usize = 64 << 20;
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
    /// row (`nc` runs per row): a move skips the runs it cannot lower.
    cmax: Vec<f32>,
    nc: usize,
}

/// What one move does to the stock.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Cut {
    /// Material removed by the cutting part, mm³.
    pub removed: f64,
    /// Material the non-cutting part (shank, holder) met, mm³.
    pub holder: f64,
}

/// How a move's heights are worked out over the cells of a run.
#[derive(Clone, Copy)]
enum Kernel {
    /// A level flat end mill without shank or holder: every covered cell
    /// goes down to the one height.
    LevelFlat(f64),
    /// A ball end mill without shank or holder (ball.rs).
    Ball(BallSweep),
    /// Any tool: the envelope by [`Sweep::tool_above`] and the holder's
    /// cylinders.
    General,
}

/// The shank and holder cylinders: (radius, bottom above the tip, length).
#[derive(Clone, Copy, Default)]
struct Guards {
    c: [(f64, f64, f64); 8],
    n: usize,
}

impl Guards {
    fn of(tool: &MillTool) -> Guards {
        let mut g = Guards::default();
        if tool.flute_length < 1.0e4 {
            let mut b = tool.flute_length;
            if tool.holder.is_empty() {
                g.c[0] = (tool.radius, b, f64::INFINITY);
                g.n = 1;
            }
            for &(r, l) in tool.holder.iter().take(8 - g.n) {
                g.c[g.n] = (r, b, l);
                b += l;
                g.n += 1;
            }
        }
        g
    }

    fn all(&self) -> &[(f64, f64, f64)] {
        &self.c[..self.n]
    }

    /// The lowest of the cylinders above the tip.
    fn lowest(&self) -> f64 {
        self.all().iter().map(|g| g.1).fold(f64::INFINITY, f64::min)
    }
}

/// One move over the cells: everything the row loop needs.
struct Pass<'a> {
    s: &'a Sweep,
    shape: Shape,
    guards: Guards,
    kernel: Kernel,
    zmin: f64,
    write: bool,
    undo: Option<&'a mut Vec<(u32, f32)>>,
    cut: Cut,
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
        let guards = Guards::of(tool);
        let kernel = match tool.kind {
            _ if guards.n > 0 => Kernel::General,
            MillKind::Flat if s.level() => Kernel::LevelFlat(s.p0[2].max(self.zmin)),
            MillKind::Ball => BallSweep::new(s, tool.radius).map_or(Kernel::General, Kernel::Ball),
            _ => Kernel::General,
        };
        let mut pass = Pass {
            s,
            shape: Shape::of(tool),
            guards,
            kernel,
            zmin: self.zmin,
            write,
            undo,
            cut: Cut::default(),
        };
        let reach = tool.reach();
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
        grid.for_rows(s, reach, |j, y, a, b| {
            let dy = (ya - y).max(y - yb).max(0.0).min(tool.radius);
            let floor = (zlow + pass.shape.profile(dy).min(bmin)).max(self.zmin) as f32;
            self.row(&mut pass, j, y, (a, b), floor);
        });
        let a = grid.cell_area();
        Cut {
            removed: pass.cut.removed * a,
            holder: pass.cut.holder * a,
        }
    }

    /// The cells `span` of row `j` (at `y`), run by run, skipping the runs
    /// whose greatest height is at or below `floor`.
    fn row(&mut self, pass: &mut Pass, j: usize, y: f64, span: (usize, usize), floor: f32) {
        let nx = self.grid.nx;
        let (base, crow) = (j * nx, j * self.nc);
        let ball_row = match pass.kernel {
            Kernel::Ball(b) => Some(b.row(y)),
            _ => None,
        };
        let mut i = span.0;
        while i <= span.1 {
            let c = i / CHUNK;
            let end = ((c + 1) * CHUNK - 1).min(span.1);
            let first = i;
            i = end + 1;
            if self.cmax[crow + c] <= floor {
                continue;
            }
            let changed = (first..=end).fold(false, |w, k| {
                let x = self.grid.x0 + (k as f64 + 0.5) * self.grid.dx;
                let v = &mut self.h[base + k];
                cell(pass, ball_row.as_ref(), v, (base + k) as u32, x, y, floor) || w
            });
            if changed {
                let run = &self.h[base + c * CHUNK..base + ((c + 1) * CHUNK).min(nx)];
                self.cmax[crow + c] = run.iter().fold(f32::NEG_INFINITY, |m, &v| m.max(v));
            }
        }
    }

    /// Puts back the heights a [`Self::cut`] changed.
    pub fn restore(&mut self, undo: &mut Vec<(u32, f32)>) {
        for &(i, z) in undo.iter().rev() {
            let i = i as usize;
            self.h[i] = z;
            let c = (i / self.grid.nx) * self.nc + (i % self.grid.nx) / CHUNK;
            self.cmax[c] = self.cmax[c].max(z);
        }
        undo.clear();
    }

    /// Height at the cell under (x, y), if inside.
    pub fn height_at(&self, x: f64, y: f64) -> Option<f64> {
        let (i, j) = self.grid.cell_at(x, y)?;
        Some(self.at(i, j))
    }
}

/// One cell of height `v` (index `idx`, centre x, y) under the pass:
/// its new height written (when the pass writes) and the volumes added.
/// True when the height changed.
#[inline]
fn cell(
    pass: &mut Pass,
    ball: Option<&BallRow>,
    v: &mut f32,
    idx: u32,
    x: f64,
    y: f64,
    floor: f32,
) -> bool {
    if *v <= floor {
        return false;
    }
    let old = *v as f64;
    let z = match pass.kernel {
        Kernel::LevelFlat(z) => Some(z),
        Kernel::Ball(b) => {
            if old <= pass.zmin + EPS {
                return false;
            }
            let row = ball.expect("a ball pass has its row");
            b.lowest(row, x).map(|z| z.max(pass.zmin))
        }
        Kernel::General => {
            if old <= pass.zmin + EPS {
                return false;
            }
            for &(r, b, l) in pass.guards.all() {
                if let Some(z) = pass.s.flat(x, y, r, b) {
                    if old > z + EPS {
                        pass.cut.holder += old.min(z + l) - z;
                    }
                }
            }
            let z = pass.s.tool_above(&pass.shape, x, y, old - EPS);
            z.map(|z| z.max(pass.zmin))
        }
    };
    let Some(z) = z else {
        return false;
    };
    if z >= old - EPS {
        return false;
    }
    pass.cut.removed += old - z;
    if !pass.write {
        return false;
    }
    if let Some(u) = pass.undo.as_deref_mut() {
        u.push((idx, *v));
    }
    *v = z as f32;
    true
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
