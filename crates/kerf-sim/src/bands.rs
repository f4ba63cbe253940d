//! The rows of a move's capsule on the height field, band by band (16
//! rows, a square's height): on one thread, or split between two at a
//! band boundary for a move with many cells to evaluate (each thread owns
//! its bands' heights, run maxima and square maxima, so nothing is
//! shared). The heights are the same either way (each cell is worked
//! out on its own), and so are the volumes: each band's removed volume is
//! summed on its own and the bands' sums are added in band order, on one
//! thread or two.

use crate::envelope::Sweep;
use crate::grid::Grid;
use crate::kernels::Pass;
use crate::shape::Shape;
use crate::tool::MillTool;
use crate::zmap::{BLOCK, CHUNK};

/// Cells to evaluate (rows of the bands not skipped by the span of the
/// capsule's columns) from which a move is split between two threads:
/// about a million instructions of the envelope, against some 50,000 to
/// start and join a thread.
pub const SPLIT_CELLS: usize = 16_384;

/// The rows of one band that a move covers: (row, y, first, last, floor).
type Band = [(usize, f64, usize, usize, f32); BLOCK];

/// A band to work: its index and its first and last row.
pub type Todo = (usize, usize, usize);

/// Whole bands of the height field, from band `band0`.
pub struct Cells<'a> {
    pub grid: Grid,
    /// Runs per row.
    pub nc: usize,
    pub band0: usize,
    pub h: &'a mut [f32],
    pub cmax: &'a mut [f32],
    pub bmax: &'a mut [f32],
}

/// What a move needs to know of each row: its capsule and its floor.
#[derive(Clone, Copy)]
pub struct Scan<'a> {
    pub s: &'a Sweep,
    /// Radius of the tool or its holder, mm.
    pub reach: f64,
    radius: f64,
    /// The move's Y range.
    ya: f64,
    yb: f64,
    zlow: f64,
    /// The lowest guard above the tip.
    bmin: f64,
    shape: Shape,
    zmin: f64,
}

impl<'a> Scan<'a> {
    /// The scan of `tool` along `s` (its pass `pass`) over a stock whose
    /// bottom is `zmin`.
    pub fn new(tool: &MillTool, s: &'a Sweep, pass: &Pass, zmin: f64) -> Scan<'a> {
        Scan {
            s,
            reach: tool.reach(),
            radius: tool.radius,
            ya: s.p0[1].min(s.p1[1]),
            yb: s.p0[1].max(s.p1[1]),
            zlow: s.p0[2].min(s.p1[2]),
            bmin: pass.guards.lowest(),
            shape: pass.shape,
            zmin,
        }
    }

    /// The height at or below which nothing can change on the rows from
    /// `y_lo` to `y_hi`. Nothing at or below the move's lowest tip height
    /// can (the tool's profile and the holder are above the tip); on a
    /// row at distance dy from the move's Y range every cell is at least
    /// dy from the axis, so the tool reaches no lower than zlow + f(dy)
    /// there (and the holder no lower than zlow + its lowest offset).
    #[inline]
    pub fn floor(&self, y_lo: f64, y_hi: f64) -> f32 {
        let dy = (self.ya - y_hi)
            .max(y_lo - self.yb)
            .max(0.0)
            .min(self.radius);
        (self.zlow + self.shape.profile(dy).min(self.bmin)).max(self.zmin) as f32
    }
}

impl<'a> Cells<'a> {
    /// The bands from band `m` on, and those before it.
    fn split(self, m: usize) -> (Cells<'a>, Cells<'a>) {
        let rows = (m - self.band0) * BLOCK;
        let (nx, nc) = (self.grid.nx, self.nc);
        let (h0, h1) = self.h.split_at_mut((rows * nx).min(self.h.len()));
        let (c0, c1) = self.cmax.split_at_mut((rows * nc).min(self.cmax.len()));
        let (b0, b1) = self
            .bmax
            .split_at_mut(((m - self.band0) * nc).min(self.bmax.len()));
        let part = |band0, h, cmax, bmax| Cells {
            grid: self.grid,
            nc,
            band0,
            h,
            cmax,
            bmax,
        };
        (part(self.band0, h0, c0, b0), part(m, h1, c1, b1))
    }

    /// Works the bands `todo` (in order), pushing each one's removed and
    /// holder sums (cell heights, mm) to `out`.
    fn work(&mut self, pass: &mut Pass, scan: &Scan, todo: &[Todo], out: &mut Vec<(f64, f64)>) {
        let grid = self.grid;
        let mut band: Band = [(0, 0.0, 0, 0, 0.0); BLOCK];
        for &(_, first, last) in todo {
            let rows = (first, last);
            let mut n = 0;
            grid.for_rows_in(scan.s, scan.reach, rows, |j, y, a, b| {
                band[n] = (j, y, a, b, scan.floor(y, y));
                n += 1;
            });
            (pass.removed, pass.holder) = (0.0, 0.0);
            if n > 0 {
                self.band(pass, &band[..n]);
            }
            out.push((pass.removed, pass.holder));
        }
    }

    /// The rows of one band, square by square: a square whose greatest
    /// height is at or below every row's floor is skipped, then each row's
    /// run whose greatest height is at or below its floor.
    fn band(&mut self, pass: &mut Pass, rows: &[(usize, f64, usize, usize, f32)]) {
        let (nx, nc, g) = (self.grid.nx, self.nc, self.grid);
        let bj = rows[0].0 / BLOCK;
        let (lb, row0) = (bj - self.band0, self.band0 * BLOCK);
        let lo = rows.iter().map(|r| r.2).min().unwrap_or(0);
        let hi = rows.iter().map(|r| r.3).max().unwrap_or(0);
        let floor = rows.iter().map(|r| r.4).fold(f32::INFINITY, f32::min);
        for c in lo / CHUNK..=hi / CHUNK {
            if self.bmax[lb * nc + c] <= floor {
                continue;
            }
            let mut changed = false;
            for &(j, y, a, b, floor) in rows {
                let lj = j - row0;
                let (first, last) = (a.max(c * CHUNK), b.min(c * CHUNK + CHUNK - 1));
                if first > last || self.cmax[lj * nc + c] <= floor {
                    continue;
                }
                let x0 = g.x0 + (first as f64 + 0.5) * g.dx;
                // A run at or below the tool's lowest point over it.
                let top = self.cmax[lj * nc + c] as f64;
                if top <= pass.floor_over(y, x0, x0 + (last - first) as f64 * g.dx) {
                    continue;
                }
                let h = &mut self.h[lj * nx + first..=lj * nx + last];
                if pass.run(h, (j * nx + first) as u32, x0, g.dx, y, floor) {
                    let run = &self.h[lj * nx + c * CHUNK..lj * nx + ((c + 1) * CHUNK).min(nx)];
                    self.cmax[lj * nc + c] = run.iter().fold(f32::NEG_INFINITY, |m, &v| m.max(v));
                    changed = true;
                }
            }
            if changed {
                let rows = bj * BLOCK..((bj + 1) * BLOCK).min(g.ny);
                self.bmax[lb * nc + c] = rows
                    .map(|j| self.cmax[(j - row0) * nc + c])
                    .fold(f32::NEG_INFINITY, f32::max);
            }
        }
    }
}

/// Works the bands `todo` of `cells` with `pass`, the pass of `tool` (on a
/// second thread, with a pass of its own, for the later half of the bands
/// when `split`); returns the removed and holder sums added in band order.
pub fn run(
    mut cells: Cells,
    pass: &mut Pass,
    tool: &MillTool,
    scan: &Scan,
    todo: &[Todo],
    split: bool,
) -> (f64, f64) {
    let mut sums = Vec::with_capacity(todo.len());
    if split && todo.len() >= 2 {
        let k = todo.len() / 2;
        let (mut a, mut b) = cells.split(todo[k].0);
        let mut undo = Vec::new();
        let (keep, write) = (pass.undo.is_some(), pass.write);
        let later = std::thread::scope(|sc| {
            let worker = sc.spawn(|| {
                let mut p = Pass::new(tool, scan.s, scan.zmin, write, keep.then_some(&mut undo));
                let mut out = Vec::with_capacity(todo.len() - k);
                b.work(&mut p, scan, &todo[k..], &mut out);
                out
            });
            a.work(pass, scan, &todo[..k], &mut sums);
            worker
                .join()
                .unwrap_or_else(|e| std::panic::resume_unwind(e))
        });
        sums.extend(later);
        if let Some(u) = pass.undo.as_deref_mut() {
            u.append(&mut undo);
        }
    } else {
        cells.work(pass, scan, todo, &mut sums);
    }
    sums.iter()
        .fold((0.0, 0.0), |(r, h), &(dr, dh)| (r + dr, h + dh))
}
