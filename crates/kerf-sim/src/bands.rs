//! The rows of a move's capsule on the height field, band by band (16
//! rows, a square's height): on one thread, or split between two at a
//! band boundary for a move with many cells to evaluate (each thread owns
//! its bands' heights, run maxima and square maxima, so nothing is
//! shared). The heights are the same either way (each cell is worked
//! out on its own), and so are the volumes: each band's removed volume is
//! summed on its own and the bands' sums are added in band order, on one
//! thread or two.

use crate::ball_row::floor_between;
use crate::envelope::Sweep;
use crate::grid::Grid;
use crate::helper::Helper;
use crate::kernels::Pass;
use crate::shape::Shape;
use crate::tool::MillTool;
use crate::zmap::{BLOCK, CHUNK};
use std::sync::atomic::{AtomicUsize, Ordering};

/// Cells to evaluate (rows of the bands not skipped by the span of the
/// capsule's columns) from which a move's bands are shared with the
/// helper thread (some 10,000 instructions to publish a job and wake it).
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
    tol: f64,
}

impl<'a> Scan<'a> {
    /// The scan of `tool` along `s` (its pass `pass`).
    pub fn new(tool: &MillTool, s: &'a Sweep, pass: &Pass) -> Scan<'a> {
        Scan {
            s,
            reach: tool.reach(),
            radius: tool.radius,
            ya: s.p0[1].min(s.p1[1]),
            yb: s.p0[1].max(s.p1[1]),
            zlow: s.p0[2].min(s.p1[2]),
            bmin: pass.guards.lowest(),
            shape: pass.shape,
            zmin: pass.zmin,
            tol: pass.tol,
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
    /// Works the bands `todo` (in order), pushing each one's removed and
    /// holder sums (cell heights, mm) to `out`.
    fn work(&mut self, pass: &mut Pass, scan: &Scan, todo: &[Todo], out: &mut Vec<(f64, f64)>) {
        for t in todo {
            out.push(self.work_one(pass, scan, t));
        }
    }

    /// Works one band: its removed and holder sums.
    fn work_one(&mut self, pass: &mut Pass, scan: &Scan, todo: &Todo) -> (f64, f64) {
        let grid = self.grid;
        let mut band: Band = [(0, 0.0, 0, 0, 0.0); BLOCK];
        let &(_, first, last) = todo;
        let mut n = 0;
        grid.for_rows_in(scan.s, scan.reach, (first, last), |j, y, a, b| {
            band[n] = (j, y, a, b, scan.floor(y, y));
            n += 1;
        });
        (pass.removed, pass.holder) = (0.0, 0.0);
        if n > 0 {
            self.band(pass, &band[..n]);
        }
        (pass.removed, pass.holder)
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
        let ball = pass.ball();
        // Each row's last envelope and slope worked out: (cell, value).
        let mut memo = [(usize::MAX, None); BLOCK];
        for c in lo / CHUNK..=hi / CHUNK {
            if self.bmax[lb * nc + c] <= floor {
                continue;
            }
            let mut changed = false;
            for (ri, &(j, y, a, b, floor)) in rows.iter().enumerate() {
                let lj = j - row0;
                let (first, last) = (a.max(c * CHUNK), b.min(c * CHUNK + CHUNK - 1));
                if first > last || self.cmax[lj * nc + c] <= floor {
                    continue;
                }
                let x0 = g.x0 + (first as f64 + 0.5) * g.dx;
                // A run at or below the ball's lowest point over it (from
                // its first cell to the next run's first, whose envelope
                // the next run reuses).
                if let Some(ball) = ball {
                    let end = if last < b { last + 1 } else { last };
                    let at = |k: usize| ball.with_slope(y, g.x0 + (k as f64 + 0.5) * g.dx);
                    let m = &mut memo[ri];
                    let left = if m.0 == first { m.1 } else { at(first) };
                    *m = (end, at(end));
                    let xe = g.x0 + (end as f64 + 0.5) * g.dx;
                    let low = floor_between(x0, left, xe, m.1);
                    if self.cmax[lj * nc + c] as f64 <= low {
                        continue;
                    }
                }
                let h = &mut self.h[lj * nx + first..=lj * nx + last];
                if pass.run(h, (j * nx + first) as u32, x0, g.dx, y, floor) {
                    let run = &self.h[lj * nx + c * CHUNK..lj * nx + ((c + 1) * CHUNK).min(nx)];
                    self.cmax[lj * nc + c] = greatest(run);
                    changed = true;
                }
            }
            if changed {
                let rows = bj * BLOCK..((bj + 1) * BLOCK).min(g.ny);
                self.bmax[lb * nc + c] = rows
                    .map(|j| self.cmax[(j - row0) * nc + c])
                    .fold(f32::NEG_INFINITY, |m, v| if v > m { v } else { m });
            }
        }
    }
}

/// Works the bands `todo` of `cells` with `pass`, the pass of `tool`
/// (with `helper`, when given and no old heights are kept, both threads
/// claiming the bands one at a time, each with a pass of its own);
/// returns the removed and holder sums added in band order.
pub fn run(
    mut cells: Cells,
    pass: &mut Pass,
    tool: &MillTool,
    scan: &Scan,
    todo: &[Todo],
    helper: Option<&Helper>,
) -> (f64, f64) {
    let mut sums = Vec::with_capacity(todo.len());
    match helper {
        Some(helper) if todo.len() >= 2 && pass.undo.is_none() => {
            sums.resize(todo.len(), (0.0, 0.0));
            let (raw, out) = (Shared::of(&mut cells), SumsPtr(sums.as_mut_ptr()));
            let (next, write) = (AtomicUsize::new(0), pass.write);
            helper.run(&|| {
                let mut p = Pass::new(tool, scan.s, (scan.zmin, scan.tol), write, None);
                loop {
                    let k = next.fetch_add(1, Ordering::Relaxed);
                    let Some(t) = todo.get(k) else { break };
                    // SAFETY: band k is claimed by this thread alone (the
                    // counter), its cells are its own (raw.band), and the
                    // caller's borrows outlive the job (Helper::run).
                    unsafe {
                        let r = raw.band(t.0).work_one(&mut p, scan, t);
                        out.put(k, r);
                    }
                }
            });
        }
        _ => cells.work(pass, scan, todo, &mut sums),
    }
    sums.iter()
        .fold((0.0, 0.0), |(r, h), &(dr, dh)| (r + dr, h + dh))
}

/// The greatest of `v` (heights are never NaN), in a loop the compiler
/// makes vector code of (`f32::max` orders NaN, which costs a branch).
#[inline]
fn greatest(v: &[f32]) -> f32 {
    let mut m = [f32::NEG_INFINITY; 8];
    let mut it = v.chunks_exact(8);
    for q in &mut it {
        for j in 0..8 {
            m[j] = if q[j] > m[j] { q[j] } else { m[j] };
        }
    }
    for &x in it.remainder() {
        m[0] = if x > m[0] { x } else { m[0] };
    }
    m.iter()
        .fold(f32::NEG_INFINITY, |a, &b| if b > a { b } else { a })
}

/// Each band's sums, written by whichever thread works it.
#[derive(Clone, Copy)]
struct SumsPtr(*mut (f64, f64));
// SAFETY: each slot is written by one thread (its band's claimant).
unsafe impl Sync for SumsPtr {}
unsafe impl Send for SumsPtr {}

impl SumsPtr {
    /// # Safety
    /// `k` within the sums, written by one thread.
    unsafe fn put(&self, k: usize, r: (f64, f64)) {
        unsafe { self.0.add(k).write(r) }
    }
}

/// [`Cells`] as raw parts, from which each thread makes the cells of the
/// bands it claims.
struct Shared {
    grid: Grid,
    nc: usize,
    band0: usize,
    h: (*mut f32, usize),
    cmax: (*mut f32, usize),
    bmax: (*mut f32, usize),
}
// SAFETY: the bands made from it are disjoint and each is used by one
// thread at a time.
unsafe impl Sync for Shared {}
unsafe impl Send for Shared {}

impl Shared {
    fn of(c: &mut Cells) -> Shared {
        Shared {
            grid: c.grid,
            nc: c.nc,
            band0: c.band0,
            h: (c.h.as_mut_ptr(), c.h.len()),
            cmax: (c.cmax.as_mut_ptr(), c.cmax.len()),
            bmax: (c.bmax.as_mut_ptr(), c.bmax.len()),
        }
    }

    /// The cells of band `bj` alone.
    ///
    /// # Safety
    /// No other live reference to that band's cells.
    #[allow(clippy::mut_from_ref)]
    unsafe fn band(&self, bj: usize) -> Cells<'_> {
        let (nx, nc) = (self.grid.nx, self.nc);
        let r0 = (bj - self.band0) * BLOCK;
        let rows = BLOCK.min(self.grid.ny - bj * BLOCK);
        let part = |(p, len): (*mut f32, usize), at: usize, n: usize| {
            let (at, n) = (at.min(len), n.min(len - at.min(len)));
            unsafe { std::slice::from_raw_parts_mut(p.add(at), n) }
        };
        Cells {
            grid: self.grid,
            nc,
            band0: bj,
            h: part(self.h, r0 * nx, rows * nx),
            cmax: part(self.cmax, r0 * nc, rows * nc),
            bmax: part(self.bmax, (bj - self.band0) * nc, nc),
        }
    }
}
