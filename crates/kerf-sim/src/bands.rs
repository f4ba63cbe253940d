//! The rows of a move's capsule on the height field, band by band (16
//! rows, a square's height): every band of the move on one thread, or
//! the bands of one parity only ([`cut_parity`]: with two threads each
//! owns the bands of one parity, their heights, run maxima and square
//! maxima, pipe.rs). The heights are the same either way (each cell is
//! worked out on its own, from the moves before it in program order), and
//! so are the volumes: each band's removed volume is summed on its own and
//! the bands' sums are added in band order.

use crate::ball_row::{floor_between, under_line, LaneRow};
use crate::envelope::Sweep;
use crate::grid::Grid;
use crate::kernels::Pass;
use crate::shape::Shape;
use crate::tool::MillTool;
use crate::zmap::{BLOCK, CHUNK};

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
    pub fn work_one(&mut self, pass: &mut Pass, scan: &Scan, todo: &Todo) -> (f64, f64) {
        let grid = self.grid;
        let mut band: Band = [(0, 0.0, 0, 0, 0.0); BLOCK];
        let &(_, first, last) = todo;
        // Each row's terms of the ball's kernel and bounds, worked out once.
        let mut terms = [None; BLOCK];
        let mut n = 0;
        let ball = pass.ball();
        grid.for_rows_in(scan.s, scan.reach, (first, last), |j, y, a, b| {
            let row = ball.map(|ball| ball.row(y));
            let cols = match (&ball, &row) {
                (Some(ball), Some(row)) => ball.trim_cols(row, &grid, (a, b), y),
                _ => Some((a, b)),
            };
            if let Some((a, b)) = cols {
                band[n] = (j, y, a, b, scan.floor(y, y));
                terms[n] = row;
                n += 1;
            }
        });
        (pass.removed, pass.holder) = (0.0, 0.0);
        if n > 0 {
            self.band(pass, &band[..n], &terms[..n]);
        }
        (pass.removed, pass.holder)
    }

    /// The rows of one band, square by square: a square whose greatest
    /// height is at or below every row's floor is skipped, then each row's
    /// run whose greatest height is at or below its floor. `terms`: each
    /// row's terms of the ball's kernel (None for other tools).
    fn band(
        &mut self,
        pass: &mut Pass,
        rows: &[(usize, f64, usize, usize, f32)],
        terms: &[Option<LaneRow>],
    ) {
        let (nx, nc, g) = (self.grid.nx, self.nc, self.grid);
        let bj = rows[0].0 / BLOCK;
        let (lb, row0) = (bj - self.band0, self.band0 * BLOCK);
        let lo = rows.iter().map(|r| r.2).min().unwrap_or(0);
        let hi = rows.iter().map(|r| r.3).max().unwrap_or(0);
        let floor = rows.iter().map(|r| r.4).fold(f32::INFINITY, f32::min);
        let ball = pass.ball();
        // Each row's last envelope and slope worked out: (cell, value).
        let mut memo = [(usize::MAX, None); BLOCK];
        // Each row's last run that reached the kernel lowered cells: the
        // next one most likely does too (the move's new material is one
        // stretch of the row), so its bound is not worked out (a bound only
        // saves work; the kernel lowers nothing where it would skip).
        let mut hot = [false; BLOCK];
        // Each row's tangent at the middle of its span: the envelope is
        // convex along the row, so above it everywhere (along a straight
        // stretch of the cylinder, exactly on it).
        let mut tangent = [None; BLOCK];
        if let Some(ball) = ball {
            for ((l, t), r) in tangent.iter_mut().zip(terms).zip(rows) {
                let xm = cell_x(&g, (r.2 + r.3) / 2);
                *l = t.and_then(|row| ball.slope_on(&row, xm).map(|(z, s)| (xm, z, s)));
            }
        }
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
                let x0 = cell_x(&g, first);
                // A run at or below the ball's lowest point over it (from
                // its first cell to the next run's first, whose envelope
                // the next run reuses).
                if hot[ri] {
                    memo[ri].0 = usize::MAX;
                } else if let (Some(ball), Some(row)) = (ball, &terms[ri]) {
                    let end = if last < b { last + 1 } else { last };
                    if let Some(t) = tangent[ri] {
                        let low = under_line(t, x0, cell_x(&g, end));
                        if self.cmax[lj * nc + c] as f64 <= low {
                            continue;
                        }
                    }
                    let at = |k: usize| ball.slope_on(row, cell_x(&g, k));
                    let m = &mut memo[ri];
                    let left = if m.0 == first { m.1 } else { at(first) };
                    *m = (end, at(end));
                    let xe = cell_x(&g, end);
                    let low = floor_between(x0, left, xe, m.1);
                    if self.cmax[lj * nc + c] as f64 <= low {
                        continue;
                    }
                    let h = &self.h[lj * nx + first..=lj * nx + last];
                    if ball.under_tangents(h, (x0, g.dx), (x0, left), (xe, m.1)) {
                        continue;
                    }
                }
                let h = &mut self.h[lj * nx + first..=lj * nx + last];
                hot[ri] = pass.run(h, (j * nx + first) as u32, x0, g.dx, y, floor);
                if hot[ri] {
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

/// Works the bands `todo` of `cells` with `pass`; returns the removed and
/// holder sums added in band order.
pub fn run(mut cells: Cells, pass: &mut Pass, scan: &Scan, todo: &[Todo]) -> (f64, f64) {
    let mut sums = Vec::with_capacity(todo.len());
    cells.work(pass, scan, todo, &mut sums);
    sums.iter()
        .fold((0.0, 0.0), |(r, h), &(dr, dh)| (r + dr, h + dh))
}

/// The rows of band `bj` within the move's rows `j0..=j1`, and whether
/// the band can change: not when its squares over the capsule's columns
/// `i0..=i1` (`squares`, the band's square maxima) are all at or below
/// its lowest floor (that of its row nearest the move's Y range).
#[inline]
pub fn band_rows(
    grid: &Grid,
    scan: &Scan,
    squares: &[f32],
    bj: usize,
    (i0, i1): (usize, usize),
    (j0, j1): (usize, usize),
) -> Option<Todo> {
    let rows = ((bj * BLOCK).max(j0), (bj * BLOCK + BLOCK - 1).min(j1));
    let low = scan.floor(grid.centre(0, rows.0).1, grid.centre(0, rows.1).1);
    let squares = &squares[i0 / CHUNK..=i1 / CHUNK];
    (!squares.iter().all(|&m| m <= low)).then_some((bj, rows.0, rows.1))
}

/// Cuts the move `s` of `tool` (heights written, no old heights kept)
/// over the bands of one parity only (`parity`: 0 the even bands, 1 the
/// odd ones), pushing each band worked and its removed sum (cell heights,
/// mm) to `out`, in band order. The holder sums are 0: a tool with a
/// shank or holder is never cut this way (its moves may be events).
/// `follows`: the move starts where the previous one of the same tool
/// ended ([`Pass::without_start`]).
///
/// # Safety
/// No other thread uses the cells of these bands meanwhile, and `raw`'s
/// arrays are alive.
pub unsafe fn cut_parity(
    raw: &Raw,
    (tool, s, follows): (&MillTool, &Sweep, bool),
    zt: (f64, f64),
    parity: usize,
    out: &mut Vec<(u32, f64)>,
) {
    let mut pass = Pass::new(tool, s, zt, true, None);
    if follows {
        pass = pass.without_start();
    }
    let scan = Scan::new(tool, s, &pass);
    let grid = raw.grid;
    let Some((cols, rows)) = grid.bounds(s, scan.reach) else {
        return;
    };
    let first = rows.0 / BLOCK;
    let first = first + (first % 2 != parity) as usize;
    for bj in (first..=rows.1 / BLOCK).step_by(2) {
        // SAFETY: band bj is of this thread's parity (the caller's
        // contract).
        let mut cells = unsafe { raw.band(bj) };
        if let Some(t) = band_rows(&grid, &scan, cells.bmax, bj, cols, rows) {
            let (r, h) = cells.work_one(&mut pass, &scan, &t);
            debug_assert_eq!(h, 0.0);
            out.push((bj as u32, r));
        }
    }
}

/// The centre of cell column `i` ([`Grid::centre`]'s x): through u32, a
/// single conversion to f64 (a usize's takes several instructions on
/// x86-64) and the same value, a column index being below 2³².
#[inline]
fn cell_x(g: &Grid, i: usize) -> f64 {
    debug_assert!(i <= u32::MAX as usize);
    g.x0 + (i as u32 as f64 + 0.5) * g.dx
}

/// The greatest of `v` (heights are never NaN), in a loop the compiler
/// makes vector code of (`f32::max` orders NaN, which costs a branch).
#[inline]
fn greatest(v: &[f32]) -> f32 {
    // A whole run as an array: a loop of known length, unrolled.
    match <&[f32; CHUNK]>::try_from(v) {
        Ok(run) => greatest_of(run),
        Err(_) => greatest_of(v),
    }
}

#[inline(always)]
fn greatest_of(v: &[f32]) -> f32 {
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
    // Halves, quarters, eighths: three vector steps, not seven scalar.
    let mx = |a: f32, b: f32| if a > b { a } else { b };
    let m4 = [
        mx(m[0], m[4]),
        mx(m[1], m[5]),
        mx(m[2], m[6]),
        mx(m[3], m[7]),
    ];
    let m2 = [mx(m4[0], m4[2]), mx(m4[1], m4[3])];
    mx(m2[0], m2[1])
}

/// [`Cells`] as raw parts, from which each thread makes the cells of the
/// bands it owns.
#[derive(Clone, Copy)]
pub struct Raw {
    grid: Grid,
    nc: usize,
    band0: usize,
    h: (*mut f32, usize),
    cmax: (*mut f32, usize),
    bmax: (*mut f32, usize),
}
// SAFETY: the bands made from it are disjoint and each is used by one
// thread at a time.
unsafe impl Sync for Raw {}
unsafe impl Send for Raw {}

impl Raw {
    /// The raw parts of a whole height field (heights, run maxima, square
    /// maxima), valid while those arrays are neither freed nor resized
    /// (`Vec::as_mut_ptr`, which other calls of it leave valid).
    pub fn of(grid: Grid, nc: usize, [h, cmax, bmax]: [&mut Vec<f32>; 3]) -> Raw {
        Raw {
            grid,
            nc,
            band0: 0,
            h: (h.as_mut_ptr(), h.len()),
            cmax: (cmax.as_mut_ptr(), cmax.len()),
            bmax: (bmax.as_mut_ptr(), bmax.len()),
        }
    }

    /// The cells of band `bj` alone.
    ///
    /// # Safety
    /// No other live reference to that band's cells.
    #[allow(clippy::mut_from_ref)]
    pub unsafe fn band(&self, bj: usize) -> Cells<'_> {
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_cell_centre_through_u32_is_the_grid_s_centre() {
        // The grid of surface_1m's stock at 0.05 mm and a skewed one: the
        // same f64, bit for bit, as Grid::centre's usize conversion.
        let grids = [
            Grid {
                x0: 0.0,
                y0: 0.0,
                dx: 0.05,
                dy: 0.05,
                nx: 6000,
                ny: 4000,
            },
            Grid {
                x0: -3.7,
                y0: 1.0,
                dx: 0.013,
                dy: 0.2,
                nx: 7_000_000,
                ny: 3,
            },
        ];
        for g in grids {
            for i in [0, 1, 15, 16, 4095, 5999, 6000, 6_999_999] {
                assert_eq!(cell_x(&g, i).to_bits(), g.centre(i, 0).0.to_bits(), "{i}");
            }
        }
    }
}
