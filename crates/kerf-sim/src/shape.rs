//! A milling tool's cutting profile prepared for the height field's inner
//! loops: the height `f(ρ)` of the lower surface above the tip and its
//! slope, with the constants (the cone's cotangent, the corner's centre)
//! worked out once per tool instead of per cell.

use crate::tool::{MillKind, MillTool};

/// The profile of revolution of a milling tool's cutting part.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Shape {
    /// Which profile (the tool's kind).
    pub kind: MillKind,
    /// Cutting radius, mm.
    pub radius: f64,
    /// Radius of the flat part at the tip: the bull's `R - rc`, the
    /// chamfer's tip radius, 0 for a drill or ball, R for a flat.
    flat: f64,
    /// Corner radius (ball: R; bull: rc), mm.
    corner: f64,
    /// dz/dρ of a cone (drill, chamfer): 1 / tan(half angle).
    cot: f64,
}

impl Shape {
    /// The profile of `t`.
    pub fn of(t: &MillTool) -> Shape {
        let r = t.radius;
        let cone = |a: f64| 1.0 / (a.to_radians() / 2.0).tan();
        let (flat, corner, cot) = match t.kind {
            MillKind::Flat => (r, 0.0, 0.0),
            MillKind::Ball => (0.0, r, 0.0),
            MillKind::Bull { corner } => (r - corner, corner, 0.0),
            MillKind::Drill { point_angle } => (0.0, 0.0, cone(point_angle)),
            MillKind::Chamfer { angle, tip_radius } => (tip_radius, 0.0, cone(angle)),
        };
        Shape {
            kind: t.kind,
            radius: r,
            flat,
            corner,
            cot,
        }
    }

    /// Height of the lower surface above the tip at distance `rho` from
    /// the axis (`rho <= radius`).
    #[inline]
    pub fn profile(&self, rho: f64) -> f64 {
        match self.kind {
            MillKind::Flat => 0.0,
            MillKind::Ball | MillKind::Bull { .. } => {
                let d = rho - self.flat;
                if d <= 0.0 {
                    0.0
                } else {
                    let c = self.corner;
                    c - (c * c - d * d).max(0.0).sqrt()
                }
            }
            MillKind::Drill { .. } | MillKind::Chamfer { .. } => {
                (rho - self.flat).max(0.0) * self.cot
            }
        }
    }

    /// Slope d(profile)/d(rho) at `rho`.
    #[inline]
    pub fn slope(&self, rho: f64) -> f64 {
        match self.kind {
            MillKind::Flat => 0.0,
            MillKind::Ball | MillKind::Bull { .. } => {
                let d = rho - self.flat;
                if d <= 0.0 {
                    0.0
                } else {
                    let c = self.corner;
                    d / (c * c - d * d).max(1e-12).sqrt()
                }
            }
            MillKind::Drill { .. } => self.cot,
            MillKind::Chamfer { .. } => {
                if rho > self.flat {
                    self.cot
                } else {
                    0.0
                }
            }
        }
    }
}
