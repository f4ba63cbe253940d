//! The lowest point of a milling tool swept along a straight move, on the
//! vertical line through a point: the exact envelope that the height
//! field evaluates at its cell centres.
//!
//! The tool's lower surface is `z_tip + f(rho)` for `rho <= R` (see
//! [`MillTool::profile`]). Along a move `P(t) = P0 + t (P1 - P0)`, the
//! height reached over a point q is `g(t) = z(t) + f(|q - P(t)|)` on the
//! interval of t where the tool covers q. `f` is convex and non-decreasing
//! and `|q - P(t)|` is convex in t, so g is convex: the minimum is found
//! in closed form for the flat, ball and drill shapes and by bisection on
//! the derivative for the others.

use crate::shape::Shape;
use crate::tool::{MillKind, MillTool};

/// A straight move of the tool tip, prepared for envelope queries.
#[derive(Clone, Copy, Debug)]
pub struct Sweep {
    pub p0: [f64; 3],
    pub p1: [f64; 3],
    /// Horizontal displacement and its squared length.
    d: [f64; 2],
    l2: f64,
    inv_l2: f64,
    /// |d| and |P1 - P0|.
    l: f64,
    l3: f64,
    dz: f64,
}

impl Sweep {
    /// The move from `p0` to `p1` (tool tip, mm).
    pub fn new(p0: [f64; 3], p1: [f64; 3]) -> Sweep {
        let d = [p1[0] - p0[0], p1[1] - p0[1]];
        let l2 = d[0] * d[0] + d[1] * d[1];
        let dz = p1[2] - p0[2];
        Sweep {
            p0,
            p1,
            d,
            l2,
            inv_l2: if l2 > 0.0 { 1.0 / l2 } else { 0.0 },
            l: l2.sqrt(),
            l3: (l2 + dz * dz).sqrt(),
            dz,
        }
    }

    /// True when the move has (almost) no horizontal component.
    pub fn vertical(&self) -> bool {
        self.l2 < 1e-18
    }

    /// True when the move keeps its height.
    pub fn level(&self) -> bool {
        self.dz.abs() < 1e-12
    }

    /// The t interval over which a disc of radius `r` about the tool axis
    /// covers the point (x, y), and the closest-approach parameter `b` and
    /// squared distance `e2` from the point to the move's line.
    #[inline]
    pub fn cover(&self, x: f64, y: f64, r: f64) -> Option<(f64, f64, f64, f64)> {
        let w = [x - self.p0[0], y - self.p0[1]];
        let ww = w[0] * w[0] + w[1] * w[1];
        if self.vertical() {
            return (ww <= r * r).then_some((0.0, 1.0, 0.0, ww));
        }
        let b = (w[0] * self.d[0] + w[1] * self.d[1]) * self.inv_l2;
        let e2 = (ww - b * b * self.l2).max(0.0);
        let disc = (r * r - e2) * self.inv_l2;
        if disc < 0.0 {
            return None;
        }
        let s = disc.sqrt();
        let (t0, t1) = ((b - s).max(0.0), (b + s).min(1.0));
        (t0 <= t1).then_some((t0, t1, b, e2))
    }

    /// Lowest height a flat disc of radius `r` at `offset` above the tip
    /// reaches over (x, y) along the move.
    #[inline]
    pub fn flat(&self, x: f64, y: f64, r: f64, offset: f64) -> Option<f64> {
        let (t0, t1, _, _) = self.cover(x, y, r)?;
        let z0 = self.p0[2] + t0 * self.dz;
        let z1 = self.p0[2] + t1 * self.dz;
        Some(z0.min(z1) + offset)
    }

    /// Lowest height of the tool's cutting surface over (x, y).
    #[inline]
    pub fn tool(&self, tool: &MillTool, x: f64, y: f64) -> Option<f64> {
        self.tool_above(&Shape::of(tool), x, y, f64::INFINITY)
    }

    /// As [`Self::tool`], but None as soon as the envelope is known to be
    /// at or above `old` (nothing to cut there).
    #[inline]
    pub fn tool_above(&self, tool: &Shape, x: f64, y: f64, old: f64) -> Option<f64> {
        let r = tool.radius;
        let (t0, t1, b, e2) = self.cover(x, y, r)?;
        if !matches!(tool.kind, MillKind::Flat) {
            // g(t) >= lowest tip height + f(distance to the XY segment).
            let d2 = if self.vertical() || (0.0..=1.0).contains(&b) {
                e2
            } else {
                let t = b.clamp(0.0, 1.0);
                (t - b) * (t - b) * self.l2 + e2
            };
            let low = self.p0[2].min(self.p1[2]) + tool.profile(d2.sqrt().min(r));
            if low >= old {
                return None;
            }
        }
        let z = |t: f64| self.p0[2] + t * self.dz;
        if matches!(tool.kind, MillKind::Flat) {
            return Some(z(t0).min(z(t1)));
        }
        let rho = |t: f64| ((t - b) * (t - b) * self.l2 + e2).max(0.0).sqrt();
        if self.vertical() {
            return Some(self.p0[2].min(self.p1[2]) + tool.profile(e2.sqrt().min(r)));
        }
        let g = |t: f64| z(t) + tool.profile(rho(t).min(r));
        if self.level() {
            return Some(g(b.clamp(t0, t1)));
        }
        let t = match tool.kind {
            MillKind::Ball => {
                // s = t - b minimises s dz - sqrt(A - L² s²), A = R² - e².
                let a = (r * r - e2).max(0.0);
                b - self.dz * a.sqrt() / (self.l * self.l3)
            }
            MillKind::Drill { .. } => {
                // g = s dz + k sqrt(e² + L² s²), k = 1/tan(half angle).
                let k = tool.slope(r);
                let l = self.l;
                let q = k * k * self.l2 - self.dz * self.dz;
                if q <= 0.0 {
                    if self.dz < 0.0 {
                        t1
                    } else {
                        t0
                    }
                } else {
                    b - self.dz * e2.sqrt() / (l * q.sqrt())
                }
            }
            _ => bisect_min(t0, t1, |t| {
                let p = rho(t);
                let dr = if p > 1e-12 {
                    self.l2 * (t - b) / p
                } else {
                    0.0
                };
                self.dz + tool.slope(p.min(r)) * dr
            }),
        };
        // g is convex: its minimiser clamped to the interval is the minimum.
        Some(g(t.clamp(t0, t1)))
    }
}

/// Minimiser of a convex function on [a, b] from the sign of its
/// derivative `dg`.
fn bisect_min(mut a: f64, mut b: f64, dg: impl Fn(f64) -> f64) -> f64 {
    for _ in 0..48 {
        if b - a < 1e-12 {
            break;
        }
        let m = 0.5 * (a + b);
        if dg(m) > 0.0 {
            b = m;
        } else {
            a = m;
        }
    }
    0.5 * (a + b)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Brute force: the minimum of g over 200,001 samples of t.
    fn brute(tool: &MillTool, s: &Sweep, x: f64, y: f64) -> Option<f64> {
        let mut best: Option<f64> = None;
        for i in 0..=200_000 {
            let t = i as f64 / 200_000.0;
            let p = [
                s.p0[0] + t * (s.p1[0] - s.p0[0]),
                s.p0[1] + t * (s.p1[1] - s.p0[1]),
                s.p0[2] + t * (s.p1[2] - s.p0[2]),
            ];
            let rho = (x - p[0]).hypot(y - p[1]);
            if rho <= tool.radius {
                let v = p[2] + tool.profile(rho);
                best = Some(best.map_or(v, |b: f64| b.min(v)));
            }
        }
        best
    }

    #[test]
    fn closed_forms_match_a_brute_force_minimum() {
        let tools = [
            MillTool::flat(3.0),
            MillTool {
                kind: MillKind::Ball,
                ..MillTool::flat(3.0)
            },
            MillTool {
                kind: MillKind::Bull { corner: 1.0 },
                ..MillTool::flat(3.0)
            },
            MillTool {
                kind: MillKind::Drill { point_angle: 118.0 },
                ..MillTool::flat(3.0)
            },
            MillTool {
                kind: MillKind::Chamfer {
                    angle: 90.0,
                    tip_radius: 0.5,
                },
                ..MillTool::flat(3.0)
            },
        ];
        let moves = [
            ([0.0, 0.0, 0.0], [10.0, 2.0, -4.0]),
            ([0.0, 0.0, -1.0], [10.0, 0.0, 3.0]),
            ([0.0, 0.0, 0.0], [0.3, 0.1, -8.0]),
            ([0.0, 0.0, -2.0], [8.0, -3.0, -2.0]),
        ];
        for tool in &tools {
            for (a, b) in moves {
                let s = Sweep::new(a, b);
                for (x, y) in [(1.0, 0.5), (5.0, -2.5), (9.9, 2.0), (-2.0, 0.3), (4.0, 2.9)] {
                    let got = s.tool(tool, x, y);
                    let want = brute(tool, &s, x, y);
                    match (got, want) {
                        (Some(g), Some(w)) => {
                            assert!(
                                (g - w).abs() < 2e-4,
                                "{tool:?} {a:?}->{b:?} at ({x},{y}): {g} vs {w}"
                            )
                        }
                        (None, None) => {}
                        other => panic!("{tool:?} {a:?}->{b:?} at ({x},{y}): {other:?}"),
                    }
                }
            }
        }
    }
}
