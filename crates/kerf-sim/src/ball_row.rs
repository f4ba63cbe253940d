//! A ball end mill's capsule over a run of cells of one row, in loops
//! without branches that the compiler turns into vector code: the
//! capsule's lower envelope as its cylinder and its two end spheres, each
//! worked out for every cell of the run and the lowest kept.
//!
//! Over a vertical line at (x, y) the lowest point of the ball swept from
//! centre `c0` along `d` is, with `b` the parameter of the point's
//! projection on the move's XY line and `e` its signed distance from it
//! (both linear in x along a row), `a = R² - e²`, `L` and `L3` the move's
//! horizontal and whole lengths:
//!
//! - on the cylinder, where `t = b - dz √a / (L L3)` is in [0, 1]:
//!   `c0z + b dz - (L3 / L) √a` (the minimum of `z(t) + R - √(R² - ρ(t)²)`,
//!   envelope.rs);
//! - otherwise on the end sphere it covers: `c0z - √(R² - |q - c0|²)` or
//!   `c0z + dz - √(R² - |q - c1|²)`.
//!
//! Where the cylinder's point is valid it is the lowest of the three (it
//! is the minimum over the whole move; the spheres are its ends), so the
//! minimum of the three, each infinite where it does not apply, is the
//! envelope ([`crate::ball::BallSweep::lowest`] within rounding). A sphere
//! is worked out only on the runs where it can be the answer: `t < 0`
//! needs `b < max(κ, 0) R` (κ = dz / (L L3)), `t > 1` needs
//! `b > 1 + min(κ, 0) R`.

use crate::envelope::Sweep;
use crate::zmap::CHUNK;

/// A ball end mill's straight move prepared for the row kernel.
#[derive(Clone, Copy, Debug)]
pub struct BallLanes {
    /// The ball's centre at the start and the move.
    c0: [f64; 3],
    d: [f64; 3],
    r2: f64,
    /// b = (wx d0 + wy d1) / L², e = (wx d1 - wy d0) / L.
    bx: f64,
    by: f64,
    ex: f64,
    ey: f64,
    /// κ = dz / (L L3) and L3 / L.
    kappa: f64,
    l3_l: f64,
    /// The b beyond which no cell is on the start sphere, and below which
    /// none is on the end sphere.
    b0_max: f64,
    b1_min: f64,
    /// The CPU has AVX2 and FMA ([`avx2`], looked up once a move rather
    /// than once a run).
    simd: bool,
    /// The start sphere is left out ([`Self::without_start`]).
    trimmed: bool,
}

/// The terms of one row (constant y).
#[derive(Clone, Copy, Debug)]
pub struct LaneRow {
    b: f64,
    e: f64,
    wy2: f64,
    wy1: f64,
}

/// 0, 1, 2, ... as f64 (a conversion per cell is not vector code).
const IDX: [f64; CHUNK] = {
    let mut t = [0.0; CHUNK];
    let mut k = 0;
    while k < CHUNK {
        t[k] = k as f64;
        k += 1;
    }
    t
};

/// Margin on the b bounds of the spheres (rounding of b and of √a).
const B_MARGIN: f64 = 1e-9;

impl BallLanes {
    /// A ball of radius `r` along `s` (a move with a horizontal component;
    /// see [`crate::ball::MIN_RUN`]).
    pub fn new(s: &Sweep, r: f64) -> BallLanes {
        let d = [s.p1[0] - s.p0[0], s.p1[1] - s.p0[1], s.p1[2] - s.p0[2]];
        let l2 = d[0] * d[0] + d[1] * d[1];
        let l = l2.sqrt();
        let l3 = (l2 + d[2] * d[2]).sqrt();
        let kappa = d[2] / (l * l3);
        BallLanes {
            c0: [s.p0[0], s.p0[1], s.p0[2] + r],
            d,
            r2: r * r,
            bx: d[0] / l2,
            by: d[1] / l2,
            ex: d[1] / l,
            ey: -d[0] / l,
            kappa,
            l3_l: l3 / l,
            b0_max: if kappa > 0.0 { kappa * r } else { 0.0 } + B_MARGIN,
            b1_min: 1.0 + if kappa < 0.0 { kappa * r } else { 0.0 } - B_MARGIN,
            simd: simd(),
            trimmed: false,
        }
    }

    /// The same move without its start sphere, for a move that starts
    /// where the previous move of the same tool ended, with nothing
    /// written to the heights in between but moves (heights only go
    /// down). That move left every cell at or below the ball there, within
    /// the height field's threshold (its stored height is its envelope, at
    /// most the ball's at its end, rounded to f32), so wherever the start
    /// sphere is this move's lowest point the cell stays as it is: the
    /// envelope less the start sphere lowers the same cells to the same
    /// heights, and the cells only the start sphere covers need not be
    /// visited ([`Self::trim_cols`]). The bounds ([`Self::slope_on`]) stay
    /// those of the whole capsule, below the envelope without it.
    pub fn without_start(mut self) -> BallLanes {
        self.b0_max = f64::NEG_INFINITY;
        self.trimmed = true;
        self
    }

    /// The columns `a..=b` of the row at `y` (`row` its terms) of grid
    /// `g` narrowed to those the move without its start sphere can cover
    /// (all of them when the start sphere is kept), or None when none
    /// are. A cell of the cylinder has `t = b - κ √a` in [0, 1] with
    /// √a in [0, R], so `b >= min(κ R, 0)`; the others are on the end
    /// sphere's disc or on the start sphere alone.
    #[inline]
    pub fn trim_cols(
        &self,
        row: &LaneRow,
        g: &crate::grid::Grid,
        (a, b): (usize, usize),
        y: f64,
    ) -> Option<(usize, usize)> {
        if !self.trimmed {
            return Some((a, b));
        }
        let bmin = (self.kappa * self.r2.sqrt()).min(0.0) - B_MARGIN;
        let c1x = self.c0[0] + self.d[0];
        let wy1 = y - (self.c0[1] + self.d[1]);
        // The end disc's half width on the row, if it reaches the row.
        let disc = self.r2 - wy1 * wy1;
        let w = (disc >= 0.0).then(|| disc.sqrt());
        // Column of a cell centre x, as f64 (clamped before any rounding).
        let col = |x: f64| ((x - g.x0) / g.dx - 0.5).clamp(-1.0, g.nx as f64);
        // The first column kept, at the start of its run: each run's
        // first cell is then the one it has with the start sphere, and so
        // is the order of its sums (lower_body's lanes), bit for bit.
        let first = |x: f64| ((col(x).ceil() - 1.0).max(0.0) as usize) / CHUNK * CHUNK;
        if self.bx.abs() < 1e-300 {
            // A move along Y: b is the row's.
            if row.b >= bmin {
                return Some((a, b));
            }
            let w = w?;
            let hi = col(c1x + w).floor() + 1.0;
            let (a, b) = (a.max(first(c1x - w)), b.min(hi.max(0.0) as usize));
            return (a <= b).then_some((a, b));
        }
        // b(x) = (x - c0x) bx + row.b reaches bmin at xb.
        let xb = self.c0[0] + (bmin - row.b) / self.bx;
        let (a, b) = if self.bx > 0.0 {
            let lo = w.map_or(xb, |w| xb.min(c1x - w));
            (a.max(first(lo)), b)
        } else {
            let hi = w.map_or(xb, |w| xb.max(c1x + w));
            (a, b.min((col(hi).floor() + 1.0).max(0.0) as usize))
        };
        (a <= b).then_some((a, b))
    }

    /// The row at `y`.
    #[inline]
    pub fn row(&self, y: f64) -> LaneRow {
        let wy = y - self.c0[1];
        let wy1 = wy - self.d[1];
        LaneRow {
            b: wy * self.by,
            e: wy * self.ey,
            wy2: wy * wy,
            wy1: wy1 * wy1,
        }
    }

    /// The envelope over the cells at `x0 + k dx`, `k < out.len()` (at most
    /// [`CHUNK`]), into `out`: infinite where the ball does not pass.
    #[inline]
    pub fn envelope(&self, row: &LaneRow, x0: f64, dx: f64, out: &mut [f64]) {
        let n = out.len().min(CHUNK);
        let out = &mut out[..n];
        #[cfg(target_arch = "x86_64")]
        if self.simd {
            // SAFETY: the CPU has AVX2 and FMA (checked at run time).
            unsafe { self.envelope_avx2(row, x0, dx, out) };
            return;
        }
        self.envelope_body(row, x0, dx, out);
    }

    /// The envelope and its slope along the row at (x, y), or None where
    /// the ball does not pass over the point or passes over it only at
    /// its rim.
    #[inline]
    pub fn with_slope(&self, y: f64, x: f64) -> Option<(f64, f64)> {
        self.slope_on(&self.row(y), x)
    }

    /// [`Self::with_slope`] on a row worked out before ([`Self::row`]).
    #[inline]
    pub fn slope_on(&self, row: &LaneRow, x: f64) -> Option<(f64, f64)> {
        let wx = x - self.c0[0];
        let b = wx * self.bx + row.b;
        let e = wx * self.ex + row.e;
        let a = self.r2 - e * e;
        if a <= 0.0 {
            return None;
        }
        let sa = a.sqrt();
        let t = b - self.kappa * sa;
        if (0.0..=1.0).contains(&t) {
            let z = self.c0[2] + b * self.d[2] - self.l3_l * sa;
            return Some((z, self.bx * self.d[2] + self.l3_l * e * self.ex / sa));
        }
        // The end sphere nearest the minimum (t < 0: the start).
        let (wx, wy2, cz) = if t < 0.0 {
            (wx, row.wy2, self.c0[2])
        } else {
            (wx - self.d[0], row.wy1, self.c0[2] + self.d[2])
        };
        let q = self.r2 - (wx * wx + wy2);
        if q <= 0.0 {
            return None;
        }
        let sq = q.sqrt();
        Some((cz - sq, wx / sq))
    }

    /// A lower bound of the envelope over the row at `y` from `xa` to
    /// `xb` (`xa <= xb`), or minus infinity when the ball does not pass
    /// over the whole interval: [`floor_between`] of the two ends.
    pub fn floor_over(&self, y: f64, xa: f64, xb: f64) -> f64 {
        floor_between(xa, self.with_slope(y, xa), xb, self.with_slope(y, xb))
    }

    /// Whether every height `h[k]` (the cells at `x0 + k dx`, at most
    /// [`CHUNK`]) is at or below both tangents of the envelope at the two
    /// ends `xa` and `xb` of the row (`a` and `b`, [`Self::slope_on`];
    /// false when either is unknown): the envelope is convex along the
    /// row, above each tangent, so no such cell is above it. Sharper than
    /// [`floor_between`] against the greatest height where the heights
    /// follow the envelope's slope (a pass beside a sloped surface).
    #[inline]
    pub fn under_tangents(
        &self,
        h: &[f32],
        (x0, dx): (f64, f64),
        (xa, a): (f64, Option<(f64, f64)>),
        (xb, b): (f64, Option<(f64, f64)>),
    ) -> bool {
        let (Some(a), Some(b)) = (a, b) else {
            return false;
        };
        let h = &h[..h.len().min(CHUNK)];
        let at = ((x0, dx), (xa, a), (xb, b));
        #[cfg(target_arch = "x86_64")]
        if self.simd {
            // SAFETY: the CPU has AVX2 and FMA (checked at run time).
            return unsafe { under_avx2(h, at) };
        }
        under_body(h, at)
    }

    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,fma")]
    fn envelope_avx2(&self, row: &LaneRow, x0: f64, dx: f64, out: &mut [f64]) {
        // A whole run as an array: loops of known length, unrolled.
        match <&mut [f64; CHUNK]>::try_from(&mut *out) {
            Ok(run) => self.envelope_body(row, x0, dx, run),
            Err(_) => self.envelope_body(row, x0, dx, out),
        }
    }

    /// The capsule's cylinder over the cells at `wx0 + k dx` (x less the
    /// start's), `root(wx)` giving `a = R² - e²` and `√a` there: infinite
    /// where the contact point is not between the move's ends.
    #[inline(always)]
    fn cylinder(
        &self,
        row: &LaneRow,
        (wx0, dx): (f64, f64),
        out: &mut [f64],
        root: impl Fn(f64) -> (f64, f64),
    ) {
        let (c0z, dz, bx, kappa, l3_l) = (self.c0[2], self.d[2], self.bx, self.kappa, self.l3_l);
        for (o, &k) in out.iter_mut().zip(&IDX) {
            let wx = wx0 + k * dx;
            let b = wx * bx + row.b;
            let (a, sa) = root(wx);
            let t = b - kappa * sa;
            let cyl = c0z + b * dz - l3_l * sa;
            let ok = a >= 0.0 && (0.0..=1.0).contains(&t);
            *o = if ok { cyl } else { f64::INFINITY };
        }
    }

    #[inline(always)]
    fn envelope_body(&self, row: &LaneRow, x0: f64, dx: f64, out: &mut [f64]) {
        let n = out.len();
        let wx0 = x0 - self.c0[0];
        let wxn = wx0 + (n as u32 as f64 - 1.0) * dx;
        let (ba, bb) = (wx0 * self.bx + row.b, wxn * self.bx + row.b);
        let (blo, bhi) = if ba < bb { (ba, bb) } else { (bb, ba) };
        let (r2, c0z, dz) = (self.r2, self.c0[2], self.d[2]);
        let ex = self.ex;
        // a = R² - e² and √a.
        let root = |e: f64| {
            let a = r2 - e * e;
            (a, if a > 0.0 { a } else { 0.0 }.sqrt())
        };
        if ex == 0.0 {
            // A move along X: e is the row's at every cell (wx 0 + e is
            // e exactly), and so are a and √a, worked out once.
            let at = root(row.e);
            self.cylinder(row, (wx0, dx), out, |_| at);
        } else {
            self.cylinder(row, (wx0, dx), out, |wx| root(wx * ex + row.e));
        }
        if blo < self.b0_max && row.wy2 <= r2 {
            for (o, &k) in out.iter_mut().zip(&IDX) {
                let wx = wx0 + k * dx;
                let q = r2 - (wx * wx + row.wy2);
                let s = c0z - if q > 0.0 { q } else { 0.0 }.sqrt();
                let s = if q >= 0.0 { s } else { f64::INFINITY };
                *o = if s < *o { s } else { *o };
            }
        }
        if bhi > self.b1_min && row.wy1 <= r2 {
            let (dx0, c1z) = (self.d[0], c0z + dz);
            for (o, &k) in out.iter_mut().zip(&IDX) {
                let wx = wx0 + k * dx - dx0;
                let q = r2 - (wx * wx + row.wy1);
                let s = c1z - if q > 0.0 { q } else { 0.0 }.sqrt();
                let s = if q >= 0.0 { s } else { f64::INFINITY };
                *o = if s < *o { s } else { *o };
            }
        }
    }
}

/// A lower bound over [xa, xb] of a convex function whose value and slope
/// at the ends are `a` and `b` (minus infinity when either is unknown):
/// the function is above the tangents at both ends, so the bound is the
/// lowest point of the greater of the two. The lower envelope of a convex
/// body (the capsule) is such a function on its convex footprint.
#[inline]
pub fn floor_between(xa: f64, a: Option<(f64, f64)>, xb: f64, b: Option<(f64, f64)>) -> f64 {
    let (Some((za, sa)), Some((zb, sb))) = (a, b) else {
        return f64::NEG_INFINITY;
    };
    let low = if sa >= 0.0 {
        za
    } else if sb <= 0.0 {
        zb
    } else {
        // sa < 0 < sb: the tangents cross inside the interval.
        let x = (zb - za + sa * xa - sb * xb) / (sa - sb);
        za + sa * (x.clamp(xa, xb) - xa)
    };
    // The rounding of the two evaluations, with room to spare.
    low - 1e-9 * (1.0 + low.abs())
}

/// The lowest point over [xa, xb] (`xa <= xb`) of the line through
/// `(xm, zm)` with slope `sm`, a tangent of a convex function (so a lower
/// bound of it everywhere), less a margin for the rounding.
#[inline]
pub fn under_line((xm, zm, sm): (f64, f64, f64), xa: f64, xb: f64) -> f64 {
    let x = if sm >= 0.0 { xa } else { xb };
    let dz = sm * (x - xm);
    let low = zm + dz;
    low - 1e-9 * (1.0 + zm.abs() + dz.abs())
}

/// The ends of a run and the tangents at the two ends of a row's span
/// ([`BallLanes::under_tangents`]).
type Tangents = ((f64, f64), (f64, (f64, f64)), (f64, (f64, f64)));

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
fn under_avx2(h: &[f32], at: Tangents) -> bool {
    // A whole run as an array: a loop of known length, unrolled.
    match <&[f32; CHUNK]>::try_from(h) {
        Ok(run) => under_body(run, at),
        Err(_) => under_body(h, at),
    }
}

#[inline(always)]
fn under_body(h: &[f32], ((x0, dx), (xa, (za, sa)), (xb, (zb, sb))): Tangents) -> bool {
    // The rounding of the two evaluations over the run, with room to
    // spare, once.
    let reach = (sa.abs() + sb.abs()) * ((xb - xa).abs() + CHUNK as f64 * dx);
    let margin = 1e-9 * (1.0 + za.abs() + zb.abs() + reach);
    let mut above = 0u32;
    for (&v, &k) in h.iter().zip(&IDX) {
        let x = x0 + k * dx;
        let ta = za + sa * (x - xa);
        let tb = zb + sb * (x - xb);
        let t = if ta > tb { ta } else { tb };
        above |= (v as f64 > t - margin) as u32;
    }
    above == 0
}

/// [`avx2`] where it exists, else false.
#[inline]
pub fn simd() -> bool {
    #[cfg(target_arch = "x86_64")]
    return avx2();
    #[cfg(not(target_arch = "x86_64"))]
    false
}

/// True when the CPU has AVX2 and FMA (checked once).
#[cfg(target_arch = "x86_64")]
#[inline]
pub fn avx2() -> bool {
    use std::sync::atomic::{AtomicU8, Ordering};
    static HAS: AtomicU8 = AtomicU8::new(0);
    match HAS.load(Ordering::Relaxed) {
        1 => false,
        2 => true,
        _ => {
            let has = std::arch::is_x86_feature_detected!("avx2")
                && std::arch::is_x86_feature_detected!("fma");
            HAS.store(if has { 2 } else { 1 }, Ordering::Relaxed);
            has
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ball::BallSweep;
    use proptest::prelude::*;

    /// A ball of radius `r` from `p0` by `d`, as the per-point capsule and
    /// as the row kernel; None where the capsule does not apply.
    fn ball_move(p0: [f64; 3], d: [f64; 3], r: f64) -> Option<(BallSweep, BallLanes)> {
        let s = Sweep::new(p0, [p0[0] + d[0], p0[1] + d[1], p0[2] + d[2]]);
        Some((BallSweep::new(&s, r)?, BallLanes::new(&s, r)))
    }

    #[test]
    fn a_level_slot_by_hand() {
        // R 3 along X at z 0 from x 0 to 10: 2 mm off the path the
        // ball's surface is 3 - √5 above the tip; 1 mm past the end on
        // the path, the end sphere: 3 - √8 above it; 3.01 mm off the
        // path, nothing; nor 8 mm past the end.
        let s = Sweep::new([0.0, 0.0, 0.0], [10.0, 0.0, 0.0]);
        let b = BallLanes::new(&s, 3.0);
        let mut out = [0.0; 2];
        b.envelope(&b.row(2.0), 5.0, 13.0, &mut out);
        assert!((out[0] - (3.0 - 5f64.sqrt())).abs() < 1e-12, "{out:?}");
        assert_eq!(out[1], f64::INFINITY);
        b.envelope(&b.row(0.0), 11.0, 1.0, &mut out);
        assert!((out[0] - (3.0 - 8f64.sqrt())).abs() < 1e-12, "{out:?}");
        assert!((out[1] - (3.0 - 5f64.sqrt())).abs() < 1e-12, "{out:?}");
        b.envelope(&b.row(3.01), 5.0, 1.0, &mut out);
        assert_eq!(out, [f64::INFINITY; 2]);
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(3000))]
        /// The bound over an interval of a row is at or below the envelope
        /// at 64 points of it (the brute-force minimum).
        #[test]
        fn the_floor_over_an_interval_is_below_every_point(
            p0 in prop::array::uniform3(-10.0f64..10.0),
            d in prop::array::uniform3(-6.0f64..6.0),
            q in prop::array::uniform2(-16.0f64..16.0),
            w in 0.0f64..3.0,
            r in 0.2f64..6.0,
        ) {
            let Some((one, lanes)) = ball_move(p0, d, r) else { return Ok(()); };
            let low = lanes.floor_over(q[1], q[0], q[0] + w);
            for k in 0..=63 {
                let x = q[0] + w * k as f64 / 63.0;
                if let Some(z) = one.lowest(&one.row(q[1]), x) {
                    prop_assert!(low <= z, "{low} above {z} at {x}");
                }
            }
        }
    }

    #[test]
    fn the_floor_of_a_level_slot_by_hand() {
        // R 3 along X at z 0 from x 0 to 10; on the row 2 mm off the
        // path the envelope is 3 - √5 everywhere over x 2..8, and the
        // bound is that; over x 11..12 (the end sphere, rising with x)
        // it is the height at x 11: 3 - √(9 - 1 - 4).
        let s = Sweep::new([0.0, 0.0, 0.0], [10.0, 0.0, 0.0]);
        let b = BallLanes::new(&s, 3.0);
        let z = b.floor_over(2.0, 2.0, 8.0);
        assert!((z - (3.0 - 5f64.sqrt())).abs() < 1e-8, "{z}");
        let z = b.floor_over(2.0, 11.0, 12.0);
        assert!((z - 1.0).abs() < 1e-8, "{z}");
        // Past the rim at x 13.0: no bound.
        assert_eq!(b.floor_over(0.0, 12.0, 13.5), f64::NEG_INFINITY);
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(3000))]
        /// On random moves and runs of cells the row kernel gives what
        /// the capsule's per-point evaluation gives (ball.rs, itself
        /// checked against the general envelope).
        #[test]
        fn agrees_with_the_capsule(
            p0 in prop::array::uniform3(-10.0f64..10.0),
            d in prop::array::uniform3(-6.0f64..6.0),
            q in prop::array::uniform2(-16.0f64..16.0),
            dx in 0.01f64..1.0,
            r in 0.2f64..6.0,
            along_x in any::<bool>(),
        ) {
            // Half the moves along X (the row's e the same at every cell).
            let d = if along_x { [d[0], 0.0, d[2]] } else { d };
            let Some((one, lanes)) = ball_move(p0, d, r) else { return Ok(()); };
            let mut out = [0.0; CHUNK];
            lanes.envelope(&lanes.row(q[1]), q[0], dx, &mut out);
            for (k, &z) in out.iter().enumerate() {
                let x = q[0] + k as f64 * dx;
                let want = one.lowest(&one.row(q[1]), x).unwrap_or(f64::INFINITY);
                if z.is_finite() && want.is_finite() {
                    prop_assert!((z - want).abs() < 1e-9, "{k}: {z} vs {want}");
                } else if z != want {
                    // Only on the rim may one see the ball and not the
                    // other: the point within 1e-6 of R from the segment.
                    let l2 = d[0] * d[0] + d[1] * d[1];
                    let (wx, wy) = (x - p0[0], q[1] - p0[1]);
                    let t = ((wx * d[0] + wy * d[1]) / l2).clamp(0.0, 1.0);
                    let e = (wx - t * d[0]).hypot(wy - t * d[1]);
                    prop_assert!((e - r).abs() < 1e-6, "{k}: {z} vs {want} at {e} of {r}");
                }
            }
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(2000))]
        /// The columns a move without its start sphere leaves out of a
        /// row are those where its envelope is nowhere: on a grid, every
        /// cell of the row outside them is infinite.
        #[test]
        fn the_trimmed_columns_hold_every_cell_the_trimmed_move_covers(
            p0 in prop::array::uniform3(-10.0f64..10.0),
            d in prop::array::uniform3(-6.0f64..6.0),
            y in -16.0f64..16.0,
            dx in 0.05f64..0.7,
            r in 0.2f64..6.0,
            along in 0u8..3,
        ) {
            let mut d = d;
            match along {
                0 => d[0] = 0.0,
                1 => d[1] = 0.0,
                _ => {}
            }
            let Some((_, lanes)) = ball_move(p0, d, r) else { return Ok(()); };
            let lanes = lanes.without_start();
            let g = crate::grid::Grid { x0: -20.0, y0: -20.0, dx, dy: dx, nx: (40.0 / dx) as usize, ny: 1 };
            let row = lanes.row(y);
            let kept = lanes.trim_cols(&row, &g, (0, g.nx - 1), y);
            for i in 0..g.nx {
                if kept.is_some_and(|(a, b)| (a..=b).contains(&i)) {
                    continue;
                }
                let mut out = [0.0];
                lanes.envelope(&row, g.centre(i, 0).0, dx, &mut out);
                prop_assert_eq!(out[0], f64::INFINITY, "cell {} of {:?}", i, kept);
            }
        }
    }

    #[test]
    fn heights_under_the_tangents_of_a_slot_by_hand() {
        // R 3 along X at z 0 from x 0 to 10, the row 2 mm off the path:
        // the envelope is 3 - √5 = 0.7639 over x 2..8 (both tangents
        // flat). Heights of 0.76 there are under it, one of 0.77 is not;
        // nor is anything where an end is off the ball's footprint.
        let s = Sweep::new([0.0, 0.0, 0.0], [10.0, 0.0, 0.0]);
        let b = BallLanes::new(&s, 3.0);
        let row = b.row(2.0);
        let ends = (b.slope_on(&row, 2.0), b.slope_on(&row, 8.0));
        let mut h = [0.76f32; 16];
        assert!(b.under_tangents(&h, (2.0, 0.4), (2.0, ends.0), (8.0, ends.1)));
        h[9] = 0.77;
        assert!(!b.under_tangents(&h, (2.0, 0.4), (2.0, ends.0), (8.0, ends.1)));
        let off = b.slope_on(&row, 13.5);
        assert!(!b.under_tangents(&[0.0; 4], (12.0, 0.5), (12.0, ends.1), (13.5, off)));
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(3000))]
        /// Heights near the envelope along a run: when they are found
        /// under the tangents, none is above the envelope (the per-point
        /// capsule, ball.rs).
        #[test]
        fn heights_under_the_tangents_are_under_the_envelope(
            p0 in prop::array::uniform3(-10.0f64..10.0),
            d in prop::array::uniform3(-6.0f64..6.0),
            q in prop::array::uniform2(-16.0f64..16.0),
            dx in 0.01f64..0.5,
            r in 0.2f64..6.0,
            below in prop::collection::vec(-0.3f64..0.002, 16),
        ) {
            let Some((one, lanes)) = ball_move(p0, d, r) else { return Ok(()); };
            let row = lanes.row(q[1]);
            let xe = q[0] + 16.0 * dx;
            let (a, b) = (lanes.slope_on(&row, q[0]), lanes.slope_on(&row, xe));
            let mut h = [0.0f32; 16];
            let mut env = [f64::INFINITY; 16];
            for k in 0..16 {
                let x = q[0] + k as f64 * dx;
                env[k] = one.lowest(&one.row(q[1]), x).unwrap_or(f64::INFINITY);
                h[k] = if env[k].is_finite() { (env[k] + below[k]) as f32 } else { 0.0 };
            }
            if lanes.under_tangents(&h, (q[0], dx), (q[0], a), (xe, b)) {
                for k in 0..16 {
                    prop_assert!(h[k] as f64 <= env[k] + 1e-7, "{} above {} at {}", h[k], env[k], k);
                }
            }
        }
    }

    #[test]
    fn the_lowest_point_of_a_tangent_over_an_interval_by_hand() {
        // Through (2, 1) with slope 0.5 the lowest point over x 0..4 is
        // at x 0: 0; with slope -0.5 at x 4: 0; level: 1. Each a hair
        // below (the rounding margin), never above.
        for (s, want) in [(0.5, 0.0), (-0.5, 0.0), (0.0, 1.0)] {
            let low = under_line((2.0, 1.0, s), 0.0, 4.0);
            assert!(low <= want && low > want - 1e-8, "{s}: {low}");
        }
        // A ball's tangent on a row bounds its envelope at every cell.
        let s = Sweep::new([0.0, 0.0, 0.0], [10.0, 0.0, 3.0]);
        let b = BallLanes::new(&s, 3.0);
        let row = b.row(1.0);
        let (z, sl) = b.slope_on(&row, 5.0).unwrap();
        let mut out = [0.0; 16];
        b.envelope(&row, -2.0, 1.0, &mut out);
        for (k, &e) in out.iter().enumerate() {
            let x = -2.0 + k as f64;
            assert!(under_line((5.0, z, sl), x, x) <= e, "{x}");
        }
    }
}
