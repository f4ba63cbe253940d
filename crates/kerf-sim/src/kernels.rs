//! How one move lowers the cells of a run (up to [`crate::zmap::CHUNK`]
//! cells of one row): a tight loop per case, each giving the same
//! heights as the general evaluation ([`Sweep::tool_above`], the exact
//! envelope at the cell centre) where it applies:
//!
//! - a level flat end mill without shank or holder: every covered cell
//!   goes down to the one height;
//! - a vertical move (a plunge, a drill's peck) of any tool without shank
//!   or holder: the lowest tip height plus the profile at the cell's
//!   distance from the axis;
//! - a ball end mill without shank or holder: the capsule (ball.rs);
//! - anything else: the general envelope and the holder's cylinders.

use crate::ball::BallSweep;
use crate::ball_row::BallLanes;
use crate::envelope::Sweep;
use crate::shape::Shape;
use crate::tool::{MillKind, MillTool};
use crate::zmap::CHUNK;

/// The evaluation a move uses.
#[derive(Clone, Copy, Debug)]
pub enum Kernel {
    /// Level flat end mill: the height.
    LevelFlat(f64),
    /// Vertical move: the axis and the lowest tip height.
    Vertical { x: f64, y: f64, z: f64 },
    /// Ball end mill.
    Ball(BallLanes),
    /// The general envelope and the guards.
    General,
}

/// The shank and holder cylinders: (radius, bottom above the tip, length).
#[derive(Clone, Copy, Default)]
pub struct Guards {
    c: [(f64, f64, f64); 8],
    n: usize,
}

impl Guards {
    /// The cylinders of `tool` above its flutes (none with unlimited
    /// flutes).
    pub fn of(tool: &MillTool) -> Guards {
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

    /// The lowest of the cylinders above the tip (infinite without any).
    pub fn lowest(&self) -> f64 {
        self.all().iter().map(|g| g.1).fold(f64::INFINITY, f64::min)
    }
}

/// One move over the cells: the kernel, what it needs and what it found.
pub struct Pass<'a> {
    pub s: &'a Sweep,
    pub shape: Shape,
    pub guards: Guards,
    pub kernel: Kernel,
    pub zmin: f64,
    /// The least lowering that is material (`ZMap::tol`).
    pub tol: f64,
    pub write: bool,
    pub undo: Option<&'a mut Vec<(u32, f32)>>,
    /// Σ (old - new) of the cutting part and of the guards, mm.
    pub removed: f64,
    pub holder: f64,
    /// The CPU has AVX2 and FMA (looked up once a move).
    simd: bool,
}

impl<'a> Pass<'a> {
    /// The pass of `tool` along `s` over a stock whose bottom is `zmin`
    /// and whose heights are lowered only by more than `tol` ([`crate::zmap::threshold`]).
    pub fn new(
        tool: &MillTool,
        s: &'a Sweep,
        (zmin, tol): (f64, f64),
        write: bool,
        undo: Option<&'a mut Vec<(u32, f32)>>,
    ) -> Pass<'a> {
        let guards = Guards::of(tool);
        let kernel = if guards.n > 0 {
            Kernel::General
        } else if s.vertical() {
            Kernel::Vertical {
                x: s.p0[0],
                y: s.p0[1],
                z: s.p0[2].min(s.p1[2]),
            }
        } else {
            match tool.kind {
                MillKind::Flat if s.level() => Kernel::LevelFlat(s.p0[2].max(zmin)),
                MillKind::Ball => match BallSweep::new(s, tool.radius) {
                    Some(_) => Kernel::Ball(BallLanes::new(s, tool.radius)),
                    None => Kernel::General,
                },
                _ => Kernel::General,
            }
        };
        Pass {
            s,
            shape: Shape::of(tool),
            guards,
            kernel,
            zmin,
            tol,
            write,
            undo,
            removed: 0.0,
            holder: 0.0,
            simd: crate::ball_row::simd(),
        }
    }

    /// The cells `h` of the row at `y` (the first, of index `idx`, centred
    /// at `x0`; `dx` apart), those at or below `floor` left alone. True
    /// when a height changed.
    #[inline]
    pub fn run(&mut self, h: &mut [f32], idx: u32, x0: f64, dx: f64, y: f64, floor: f32) -> bool {
        match self.kernel {
            Kernel::LevelFlat(z) if h.len() <= CHUNK && self.undo.is_none() => {
                #[cfg(target_arch = "x86_64")]
                let (sum, any) = if self.simd {
                    // SAFETY: the CPU has AVX2 and FMA (checked at run time).
                    unsafe { level_avx2(h, z, floor, (self.zmin, self.tol), self.write) }
                } else {
                    lower_body(h, |_| z, floor, (self.zmin, self.tol), self.write)
                };
                #[cfg(not(target_arch = "x86_64"))]
                let (sum, any) = lower_body(h, |_| z, floor, (self.zmin, self.tol), self.write);
                self.removed += sum;
                any && self.write
            }
            Kernel::LevelFlat(z) => self.level_flat(h, idx, z, floor),
            Kernel::Vertical { x, y: ya, z } => {
                let r2 = self.shape.radius * self.shape.radius;
                let dy2 = (y - ya) * (y - ya);
                let shape = self.shape;
                let zmin = self.zmin;
                self.each(h, idx, floor, |k, _| {
                    let d = x0 + k as f64 * dx - x;
                    let e2 = d * d + dy2;
                    (e2 <= r2).then(|| (z + shape.profile(e2.sqrt())).max(zmin))
                })
            }
            Kernel::Ball(ref b) => {
                let mut env = [0.0; CHUNK];
                let env = &mut env[..h.len().min(CHUNK)];
                b.envelope(&b.row(y), x0, dx, env);
                self.lower(h, idx, env, floor)
            }
            Kernel::General => {
                let (s, shape, guards, zmin) = (self.s, self.shape, self.guards, self.zmin);
                let tol = self.tol;
                let mut met = 0.0;
                let changed = self.each(h, idx, floor, |k, old| {
                    let x = x0 + k as f64 * dx;
                    for &(r, b, l) in guards.all() {
                        if let Some(z) = s.flat(x, y, r, b) {
                            if old > z + tol {
                                met += old.min(z + l) - z;
                            }
                        }
                    }
                    s.tool_above(&shape, x, y, old - tol).map(|z| z.max(zmin))
                });
                self.holder += met;
                changed
            }
        }
    }

    /// Leaves out a ball's start sphere ([`BallLanes::without_start`]):
    /// for a move that starts where the previous move of the same tool
    /// ended, nothing else having raised a height since (none can).
    pub fn without_start(mut self) -> Self {
        if let Kernel::Ball(b) = self.kernel {
            self.kernel = Kernel::Ball(b.without_start());
        }
        self
    }

    /// The ball move's row kernel, whose envelope bounds a run from
    /// below ([`BallLanes::with_slope`]), if the move has one.
    #[inline]
    pub fn ball(&self) -> Option<BallLanes> {
        match self.kernel {
            Kernel::Ball(b) => Some(b),
            _ => None,
        }
    }

    /// A level flat end mill: one height for every covered cell.
    #[inline]
    fn level_flat(&mut self, h: &mut [f32], idx: u32, z: f64, floor: f32) -> bool {
        let zf = z as f32;
        let mut removed = 0.0;
        let mut changed = false;
        for (k, v) in h.iter_mut().enumerate() {
            let old = *v as f64;
            if *v <= floor || z >= old - self.tol {
                continue;
            }
            removed += old - z;
            if self.write {
                if let Some(u) = self.undo.as_deref_mut() {
                    u.push((idx + k as u32, *v));
                }
                *v = zf;
                changed = true;
            }
        }
        self.removed += removed;
        changed
    }

    /// The cells `h` lowered to the envelope `env` (infinite where the
    /// tool does not pass) where it is lower, as [`Self::each`] does, in a
    /// loop without branches when no old heights are kept.
    #[inline]
    fn lower(&mut self, h: &mut [f32], idx: u32, env: &[f64], floor: f32) -> bool {
        let zmin = self.zmin;
        if self.undo.is_some() || h.len() > CHUNK {
            return self.each(h, idx, floor, |k, _| {
                env[k].is_finite().then(|| env[k].max(zmin))
            });
        }
        #[cfg(target_arch = "x86_64")]
        let (sum, any) = if self.simd {
            // SAFETY: the CPU has AVX2 and FMA (checked at run time).
            unsafe { lower_avx2(h, env, floor, (zmin, self.tol), self.write) }
        } else {
            let h = &mut h[..env.len().min(CHUNK)];
            lower_body(h, |k| env[k], floor, (zmin, self.tol), self.write)
        };
        #[cfg(not(target_arch = "x86_64"))]
        let (sum, any) = {
            let h = &mut h[..env.len().min(CHUNK)];
            lower_body(h, |k| env[k], floor, (zmin, self.tol), self.write)
        };
        self.removed += sum;
        any && self.write
    }

    /// Every cell above `floor` (and above the stock's bottom) lowered to
    /// `f(k, old)` where that is lower.
    #[inline]
    fn each(
        &mut self,
        h: &mut [f32],
        idx: u32,
        floor: f32,
        mut f: impl FnMut(usize, f64) -> Option<f64>,
    ) -> bool {
        let mut removed = 0.0;
        let mut changed = false;
        for (k, v) in h.iter_mut().enumerate() {
            let old = *v as f64;
            if *v <= floor || old <= self.zmin + self.tol {
                continue;
            }
            let Some(z) = f(k, old) else {
                continue;
            };
            if z >= old - self.tol {
                continue;
            }
            removed += old - z;
            if self.write {
                if let Some(u) = self.undo.as_deref_mut() {
                    u.push((idx + k as u32, *v));
                }
                *v = z as f32;
                changed = true;
            }
        }
        self.removed += removed;
        changed
    }
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
fn lower_avx2(h: &mut [f32], env: &[f64], floor: f32, zt: (f64, f64), write: bool) -> (f64, bool) {
    let h = &mut h[..env.len().min(CHUNK)];
    // A whole run as arrays: a loop of known length, unrolled.
    match (
        <&mut [f32; CHUNK]>::try_from(&mut *h),
        <&[f64; CHUNK]>::try_from(env),
    ) {
        (Ok(h), Ok(env)) => lower_body(h, |k| env[k], floor, zt, write),
        _ => lower_body(h, |k| env[k], floor, zt, write),
    }
}

/// [`lower_body`] of a level flat end mill: every cell's envelope is `z`.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
fn level_avx2(h: &mut [f32], z: f64, floor: f32, zt: (f64, f64), write: bool) -> (f64, bool) {
    lower_body(h, |_| z, floor, zt, write)
}

/// The cells of `h` (at most [`CHUNK`]) above `floor` and above the
/// stock's bottom `zmin` lowered (when `write`) to `env(k)`, not below
/// `zmin`, where that is lower by more than `tol`: Σ (old - new) in four
/// lanes, and whether a height changed.
#[inline(always)]
fn lower_body(
    h: &mut [f32],
    env: impl Fn(usize) -> f64,
    floor: f32,
    (zmin, tol): (f64, f64),
    write: bool,
) -> (f64, bool) {
    let n = h.len().min(CHUNK);
    let h = &mut h[..n];
    // `v > floor` and `old > zmin + tol` as one comparison in f64 (f32 to
    // f64 is exact and keeps the order): no f32 lanes to widen.
    let (lim, f) = (zmin + tol, floor as f64);
    let lim = if f > lim { f } else { lim };
    let mut cut = [0.0f64; CHUNK];
    let mut any = 0u32;
    for k in 0..n {
        let v = h[k];
        let old = v as f64;
        let e = env(k);
        let z = if e > zmin { e } else { zmin };
        let c = (old > lim) & (z < old - tol);
        cut[k] = if c { old - z } else { 0.0 };
        if write {
            h[k] = if c { z as f32 } else { v };
        }
        any |= c as u32;
    }
    let mut lanes = [0.0f64; 4];
    for q in cut.chunks_exact(4) {
        for j in 0..4 {
            lanes[j] += q[j];
        }
    }
    ((lanes[0] + lanes[1]) + (lanes[2] + lanes[3]), any != 0)
}
