//! Tool geometry: milling cutters as a profile of revolution about the
//! spindle axis with a holder of stacked cylinders, lathe tools as a
//! convex outline in the (Z, radius) half plane.

use std::collections::BTreeMap;
use std::f64::consts::PI;

use crate::shape::Shape;

/// Cutting shape of a milling tool.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum MillKind {
    /// Flat end mill.
    Flat,
    /// Ball end mill (corner radius = radius).
    Ball,
    /// Bull nose: corner radius below the radius.
    Bull { corner: f64 },
    /// Drill with a point of `angle` degrees included.
    Drill { point_angle: f64 },
    /// Chamfer (spot, countersink) tool: cone of `angle` degrees included
    /// above a flat tip of radius `tip_radius`.
    Chamfer { angle: f64, tip_radius: f64 },
}

/// A milling tool: cutting part, flute length and holder.
#[derive(Clone, Debug, PartialEq)]
pub struct MillTool {
    pub kind: MillKind,
    /// Cutting radius, mm.
    pub radius: f64,
    /// Height of the cutting part above the tip, mm.
    pub flute_length: f64,
    /// Whether the tool may cut at its centre (plunge).
    pub centre_cutting: bool,
    /// Non-cutting cylinders stacked upward from the top of the flutes:
    /// (radius, length), mm. The first is usually the shank.
    pub holder: Vec<(f64, f64)>,
}

impl MillTool {
    /// A flat end mill of radius `r` with long flutes and no holder (the
    /// tool simulated from an offset).
    pub fn flat(r: f64) -> MillTool {
        MillTool {
            kind: MillKind::Flat,
            radius: r,
            flute_length: 1.0e4,
            centre_cutting: true,
            holder: Vec::new(),
        }
    }

    /// Height of the tool's lower surface above the tip at distance `rho`
    /// from the axis (`rho <= radius`); [`Shape`] for inner loops.
    pub fn profile(&self, rho: f64) -> f64 {
        Shape::of(self).profile(rho)
    }

    /// Slope d(profile)/d(rho) at `rho`.
    pub fn slope(&self, rho: f64) -> f64 {
        Shape::of(self).slope(rho)
    }

    /// Largest radius of the tool or its holder, mm.
    pub fn reach(&self) -> f64 {
        self.holder.iter().fold(self.radius, |m, h| m.max(h.0))
    }
}

/// Shape of a lathe tool, in the tool's own frame.
#[derive(Clone, Debug, PartialEq)]
pub enum LatheKind {
    /// Turning, boring or threading insert: nose radius, included angle
    /// (degrees), cutting edge length and the direction of the insert's
    /// bisector from the nose into the body (degrees from +Z toward +X).
    Insert {
        angle: f64,
        edge: f64,
        bisector: f64,
    },
    /// Grooving or part-off blade: width along Z (toward +Z from the
    /// reference corner) and blade depth along +X.
    Groove { width: f64, depth: f64 },
    /// Drill on the spindle axis pointing toward -Z.
    Drill {
        diameter: f64,
        point_angle: f64,
        flute_length: f64,
    },
}

/// A lathe tool: shape, nose radius, tip direction and holder outline.
#[derive(Clone, Debug, PartialEq)]
pub struct LatheTool {
    pub kind: LatheKind,
    /// Nose (corner) radius, mm.
    pub nose_radius: f64,
    /// Imaginary tip direction 0-9 as the compensation uses it
    /// (001 p.29): where the programmed point lies seen from the nose
    /// centre.
    pub tip: u8,
    /// Holder outline, (z, x) points relative to the programmed point,
    /// mm; its convex hull is what is checked.
    pub holder: Vec<(f64, f64)>,
}

impl LatheTool {
    /// An 80° insert (ISO C) with 8 mm edges oriented by the tip
    /// direction: the tool simulated from an offset.
    pub fn from_offset(nose_radius: f64, tip: u8) -> LatheTool {
        LatheTool {
            kind: LatheKind::Insert {
                angle: 80.0,
                edge: 8.0,
                bisector: default_bisector(tip),
            },
            nose_radius,
            tip,
            holder: Vec::new(),
        }
    }
}

/// The insert bisector pointing away from the tip: opposite the tip
/// direction's vector (tip 0/9 and unknown: +X, the body above the tip).
pub fn default_bisector(tip: u8) -> f64 {
    let (z, x) = tip_vector(tip);
    if z == 0.0 && x == 0.0 {
        90.0
    } else {
        (-x).atan2(-z) * 180.0 / PI
    }
}

/// Vector from the nose centre to the imaginary tip per unit of nose
/// radius, (Z, X) (001 p.29): the compensation's own table, so the
/// simulated insert and the compensated path agree by construction.
pub use kerf_geom::comp::tip_vector;

/// Any tool of the file.
#[derive(Clone, Debug, PartialEq)]
pub enum Tool {
    Mill(MillTool),
    Lathe(LatheTool),
}

/// Offsets of the control at the start of the run, used for the tools
/// the tool file does not describe: mill D values (radius) and lathe
/// nose radius and tip, by offset number.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct OffsetData {
    /// D number → cutter radius, mm.
    pub radius: BTreeMap<u32, f64>,
    /// Lathe offset number → (nose radius, tip direction).
    pub nose: BTreeMap<u32, (f64, u8)>,
}

/// Tools by number.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ToolTable {
    pub tools: BTreeMap<u32, Tool>,
    pub offsets: OffsetData,
}
