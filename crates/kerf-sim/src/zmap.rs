//! The machining center's stock: a height field (Z-map) of f32 heights
//! at cell centres over the stock's XY rectangle, each column of
//! material running from the stock bottom up to its height.

use crate::bands::{self, band_rows, Cells, Raw, Scan, Todo};
use crate::envelope::Sweep;
use crate::grid::Grid;
use crate::kernels::Pass;
use crate::pipe::{Pipe, QUEUE};
use crate::tool::MillTool;
use std::cell::Cell;

/// Most cells a height field may have: 54.5 million, 218 MB of f32 heights
/// plus 7 MB of run and square maxima, so that a run at the largest grid
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
/// move cannot lower are skipped with one comparison each). 32 took the
/// fewest instructions on surface_1m's ball moves (16, 24, 32, 48 and 64
/// measured: docs/benchmarks.md, "Simulation"): fewer runs to visit
/// than 16, fewer cells worked out for nothing than 48 or 64.
pub const CHUNK: usize = 32;
/// Height changes below this are never material (mm); the threshold of
/// a height field is the greater of this and the f32 step of its heights
/// ([`ZMap::tol`]).
pub const EPS: f64 = 1e-6;

/// The spacing of f32 values at the magnitude `m` (the step above `|m|`
/// rounded to f32, the larger of its two neighbours' distances): the
/// resolution at which heights up to `|m|` are stored.
pub fn f32_step(m: f64) -> f64 {
    let m = (m.abs() as f32).max(f32::MIN_POSITIVE);
    (f32::from_bits(m.to_bits() + 1) - m) as f64
}

/// The least lowering of a stored height that is material on a stock
/// whose heights lie within `zmin..=ztop`: the f32 step of the largest
/// magnitude, and at least [`EPS`]. A stored height is the exact envelope
/// rounded to f32 (within half a step) and a second evaluation of the
/// same envelope differs from the first by rounding of f64 (far below
/// [`EPS`] / 2), so a move that retraces material already cut lowers no
/// height by this much, and every lowering by more is material.
pub fn threshold(zmin: f64, ztop: f64) -> f64 {
    f32_step(zmin.abs().max(ztop.abs())).max(EPS)
}

/// The height field.
#[derive(Debug)]
pub struct ZMap {
    /// The cell layout.
    pub grid: Grid,
    /// Stock bottom and top.
    pub zmin: f64,
    pub ztop: f64,
    /// A height lowered by this much or less is left as it is: the
    /// model's resolution in Z ([`threshold`]).
    pub tol: f64,
    /// Heights, row-major (`grid.nx` per row).
    pub h: Vec<f32>,
    /// An upper bound of the heights in each run of [`CHUNK`] cells of a
    /// row (`nc` runs per row), and in each square of [`BLOCK`] rows by
    /// [`CHUNK`] cells (`nc` per band of rows): a move skips the squares
    /// and the runs it cannot lower with one comparison each.
    cmax: Vec<f32>,
    bmax: Vec<f32>,
    nc: usize,
    /// Threads the moves of [`Self::cut_queued`] are cut by (1 or 2;
    /// pipe.rs).
    pub threads: usize,
    /// The queue's length in moves ([`QUEUE`]; the tests make it short).
    pub queue: usize,
    /// The bands of the move being cut.
    todo: Vec<Todo>,
    /// The material removed so far by [`Self::cut_queued`] and
    /// [`Self::add_removed`], mm³, in program order.
    total: Cell<f64>,
    /// The worker that owns the odd bands, once a move was queued.
    pipe: Option<Box<Pipe>>,
    /// The tool of the last move written and where it ended (none after a
    /// restore): a move of that tool from there follows it
    /// ([`crate::kernels::Pass::without_start`]).
    last: Option<(MillTool, [f64; 3])>,
}

impl Clone for ZMap {
    /// The heights after every queued move; the copy starts its own
    /// worker when it queues a move.
    fn clone(&self) -> ZMap {
        self.settle();
        ZMap {
            grid: self.grid,
            zmin: self.zmin,
            ztop: self.ztop,
            tol: self.tol,
            h: self.h.clone(),
            cmax: self.cmax.clone(),
            bmax: self.bmax.clone(),
            nc: self.nc,
            threads: self.threads,
            queue: self.queue,
            todo: Vec::new(),
            total: self.total.clone(),
            pipe: None,
            last: self.last.clone(),
        }
    }
}

impl Drop for ZMap {
    /// The worker is stopped before the arrays it cuts are freed.
    fn drop(&mut self) {
        self.pipe = None;
    }
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
            tol: threshold(min[2], max[2]),
            h: vec![max[2] as f32; nx * ny],
            cmax: vec![max[2] as f32; nc * ny],
            bmax: vec![max[2] as f32; nc * ny.div_ceil(BLOCK)],
            nc,
            threads: default_threads(),
            queue: QUEUE,
            todo: Vec::new(),
            total: Cell::new(0.0),
            pipe: None,
            last: None,
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
        self.settle();
        self.h[j * self.grid.nx + i] as f64
    }

    /// Waits for the queued moves to be cut (by both threads; their
    /// volumes added to [`Self::removed`]): every read of the heights and
    /// every move not queued does so first. `h` may be read directly only
    /// after it.
    #[inline]
    pub fn settle(&self) {
        if let Some(p) = &self.pipe {
            p.settle(&self.total);
        }
    }

    /// The material removed by the moves queued and those added, mm³
    /// (after every queued move).
    pub fn removed(&self) -> f64 {
        self.settle();
        self.total.get()
    }

    /// Adds a move's removed volume to [`Self::removed`] (a move cut
    /// with [`Self::cut`]), after the queued moves'.
    pub fn add_removed(&mut self, v: f64) {
        self.settle();
        self.total.set(self.total.get() + v);
    }

    /// Cuts the move `s` of `tool` (which has no shank or holder, and
    /// whose move is no event: the old heights are not kept), adding its
    /// volume to [`Self::removed`]; with two threads the caller's bands
    /// are cut now and the worker's later (pipe.rs).
    pub fn cut_queued(&mut self, tool: &MillTool, s: &Sweep) {
        if self.threads > 1 && self.pipe.is_none() {
            let raw = Raw::of(
                self.grid,
                self.nc,
                [&mut self.h, &mut self.cmax, &mut self.bmax],
            );
            let zt = (self.zmin, self.tol);
            self.pipe = Pipe::start(raw, zt, self.grid.cell_area(), self.queue).map(Box::new);
        }
        let follows = self.follows(tool, s);
        match &mut self.pipe {
            Some(p) if self.threads > 1 => {
                p.cut(tool, s, follows, &self.total);
                self.ended(tool, s);
            }
            _ => {
                let c = self.cut(tool, s, true, None);
                self.add_removed(c.removed);
            }
        }
    }

    /// Whether `s` of `tool` starts where the last move written ended,
    /// with the same tool.
    fn follows(&self, tool: &MillTool, s: &Sweep) -> bool {
        matches!(&self.last, Some((t, p)) if *p == s.p0 && t == tool)
    }

    /// Notes that a move `s` of `tool` was written.
    fn ended(&mut self, tool: &MillTool, s: &Sweep) {
        match &mut self.last {
            Some((t, p)) if t == tool => *p = s.p1,
            _ => self.last = Some((tool.clone(), s.p1)),
        }
    }

    /// The worker, if started (tests).
    #[cfg(test)]
    pub(crate) fn pipe_mut(&mut self) -> Option<&mut Pipe> {
        self.pipe.as_deref_mut()
    }

    /// Material left, mm³.
    pub fn volume(&self) -> f64 {
        self.settle();
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
        self.settle();
        let (zmin, tol) = (self.zmin, self.tol);
        let mut pass = Pass::new(tool, s, (zmin, tol), write, undo);
        if self.follows(tool, s) {
            pass = pass.without_start();
        }
        if write {
            self.ended(tool, s);
        }
        let scan = Scan::new(tool, s, &pass);
        let grid = self.grid;
        let Some((cols, rows)) = grid.bounds(s, scan.reach) else {
            return Cut::default();
        };
        self.todo.clear();
        for bj in rows.0 / BLOCK..=rows.1 / BLOCK {
            let squares = &self.bmax[bj * self.nc..][..self.nc];
            self.todo
                .extend(band_rows(&grid, &scan, squares, bj, cols, rows));
        }
        let part = Cells {
            grid,
            nc: self.nc,
            band0: 0,
            h: &mut self.h,
            cmax: &mut self.cmax,
            bmax: &mut self.bmax,
        };
        let (removed, holder) = bands::run(part, &mut pass, &scan, &self.todo);
        let a = grid.cell_area();
        Cut {
            removed: removed * a,
            holder: holder * a,
        }
    }

    /// Puts back the heights a [`Self::cut`] changed.
    pub fn restore(&mut self, undo: &mut Vec<(u32, f32)>) {
        self.settle();
        self.last = None;
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

/// Threads the queued moves are cut by: `KERF_SIM_THREADS` (1 or 2) if
/// set, else 2 where the machine has two cores or more.
fn default_threads() -> usize {
    let env = std::env::var("KERF_SIM_THREADS").ok();
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    env.and_then(|v| v.trim().parse::<usize>().ok())
        .map_or(cores, |n| n)
        .clamp(1, 2)
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
        let (g, mut h, mut removed, eps) = (z.grid, z.h.clone(), 0.0, z.tol);
        let shape = Shape::of(tool);
        for &(a, b) in moves {
            let s = Sweep::new(a, b);
            for j in 0..g.ny {
                for i in 0..g.nx {
                    let (x, y) = g.centre(i, j);
                    let v = &mut h[j * g.nx + i];
                    let old = *v as f64;
                    if old <= z.zmin + eps {
                        continue;
                    }
                    let Some(n) = s.tool_above(&shape, x, y, old - eps) else {
                        continue;
                    };
                    let n = n.max(z.zmin);
                    if n < old - eps {
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
        #![proptest_config(ProptestConfig::with_cases(60))]
        /// Random moves of any tool without shank or holder queued (the
        /// odd bands cut by the worker, with a queue of 1 to 8 moves), some
        /// with a move cut at once in between (a barrier, its old heights
        /// kept): the same heights, run and square maxima, bit for bit,
        /// and the same removed volume as on one thread.
        #[test]
        fn two_threads_give_what_one_gives(
            kind in 0u8..4,
            r in 0.4f64..4.0,
            queue in 1usize..9,
            moves in prop::collection::vec((a_move(), any::<bool>()), 1..12),
        ) {
            let mut one = ZMap::new([0.0, 0.0, -5.0], [20.0, 15.0, 0.0], 0.1).unwrap();
            one.threads = 1;
            let mut two = one.clone();
            (two.threads, two.queue) = (2, queue);
            let t = tool(kind, r);
            for &((a, b), barrier) in &moves {
                let s = Sweep::new(a, b);
                if barrier {
                    let (mut u1, mut u2) = (Vec::new(), Vec::new());
                    let c1 = one.cut(&t, &s, true, Some(&mut u1));
                    let c2 = two.cut(&t, &s, true, Some(&mut u2));
                    prop_assert_eq!(c1, c2);
                    prop_assert_eq!(&u1, &u2);
                    one.add_removed(c1.removed);
                    two.add_removed(c2.removed);
                } else {
                    one.cut_queued(&t, &s);
                    two.cut_queued(&t, &s);
                }
            }
            prop_assert_eq!(one.removed().to_bits(), two.removed().to_bits());
            prop_assert!(one.h == two.h && one.cmax == two.cmax && one.bmax == two.bmax);
        }
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

    /// A chain of moves, each from where the one before ended.
    fn a_chain() -> impl Strategy<Value = Vec<[f64; 3]>> {
        let p = (-2.0f64..22.0, -2.0f64..17.0, -6.0f64..1.0);
        (prop::collection::vec((p, 0u8..4), 2..9)).prop_map(|pts| {
            let mut out: Vec<[f64; 3]> = Vec::new();
            for ((x, y, z), how) in pts {
                let q = match (out.last(), how) {
                    // A level move, a plunge, a short step (under the
                    // radius) or anywhere.
                    (Some(l), 0) => [x, y, l[2]],
                    (Some(l), 1) => [l[0], l[1], z],
                    (Some(l), 2) => [l[0] + (x - l[0]) / 20.0, l[1] + (y - l[1]) / 20.0, z],
                    _ => [x, y, z],
                };
                out.push(q);
            }
            out
        })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(200))]
        /// Chains of ball moves, queued on one or two threads: leaving out
        /// the start sphere of each move that follows the one before gives
        /// the heights, run and square maxima and volume of keeping it, bit
        /// for bit, and those of the cell-by-cell general evaluation.
        #[test]
        fn a_move_that_follows_needs_no_start_sphere(
            r in 0.4f64..4.0,
            res in 0.07f64..0.3,
            threads in 1usize..3,
            chain in a_chain(),
        ) {
            let mut with = ZMap::new([0.0, 0.0, -5.0], [20.0, 15.0, 0.0], res).unwrap();
            with.threads = threads;
            let mut without = with.clone();
            let t = tool(1, r);
            let moves: Vec<_> = chain.windows(2).map(|w| (w[0], w[1])).collect();
            let (want, removed) = reference(&with, &t, &moves);
            for &(a, b) in &moves {
                let s = Sweep::new(a, b);
                prop_assert!(!without.follows(&t, &s), "follows");
                with.cut_queued(&t, &s);
                without.cut_queued(&t, &s);
                without.last = None;
                prop_assert!(with.follows(&t, &Sweep::new(b, a)));
            }
            prop_assert_eq!(with.removed(), without.removed(), "volumes");
            let diff = (0..with.h.len()).filter(|&i| with.h[i] != without.h[i]).count();
            prop_assert!(with.h == without.h && with.cmax == without.cmax && with.bmax == without.bmax, "{} cells", diff);
            let bad = (0..want.len()).find(|&i| (with.h[i] - want[i]).abs() > 1e-6);
            prop_assert!(bad.is_none(), "cell {:?}", bad);
            let got = with.removed();
            prop_assert!((got - removed).abs() <= 1e-9 * (1.0 + removed), "{got} vs {removed}");
        }
    }

    #[test]
    fn a_move_follows_only_the_same_tool_from_its_end_and_not_after_a_restore() {
        let mut z = ZMap::new([0.0, 0.0, -5.0], [20.0, 15.0, 0.0], 0.1).unwrap();
        let (t, other) = (tool(1, 2.0), tool(1, 2.5));
        let (a, b, c) = ([2.0, 2.0, -1.0], [10.0, 3.0, -1.5], [12.0, 9.0, -1.0]);
        assert!(!z.follows(&t, &Sweep::new(a, b)));
        z.cut_queued(&t, &Sweep::new(a, b));
        assert!(z.follows(&t, &Sweep::new(b, c)));
        assert!(!z.follows(&other, &Sweep::new(b, c)));
        assert!(!z.follows(&t, &Sweep::new(a, c)));
        // A probe (nothing written) leaves the last end as it was.
        z.cut(&t, &Sweep::new(c, a), false, None);
        assert!(z.follows(&t, &Sweep::new(b, c)));
        let mut undo = Vec::new();
        z.cut(&t, &Sweep::new(b, c), true, Some(&mut undo));
        assert!(z.follows(&t, &Sweep::new(c, a)));
        z.restore(&mut undo);
        assert!(!z.follows(&t, &Sweep::new(c, a)));
        assert!(!z.follows(&t, &Sweep::new(b, c)));
    }
}
