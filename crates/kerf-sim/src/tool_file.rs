//! `--tools FILE.toml`: tool geometry by tool number (docs/sim.md).
//!
//! ```toml
//! [tool.1]                 # machining center
//! kind = "bull"            # flat | ball | bull | drill | chamfer
//! diameter = 10
//! corner_radius = 1
//! flute_length = 25
//! centre_cutting = true
//! holder = [[10, 40], [40, 60]]   # [diameter, length] upward from the flutes
//!
//! [tool.3]                 # lathe
//! kind = "insert"          # insert | groove | drill
//! nose_radius = 0.8
//! shape = "C"              # or angle = 80
//! tip = 3
//! holder = [[0, 2], [30, 2], [30, 25], [0, 25]]   # [z, x] from the tip
//! ```

use std::collections::BTreeMap;

use serde::Deserialize;

use crate::tool::{default_bisector, LatheKind, LatheTool, MillKind, MillTool, Tool, ToolTable};

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct File {
    #[serde(default)]
    tool: BTreeMap<String, Entry>,
}

#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct Entry {
    kind: Option<String>,
    diameter: Option<f64>,
    corner_radius: Option<f64>,
    point_angle: Option<f64>,
    angle: Option<f64>,
    tip_diameter: Option<f64>,
    flute_length: Option<f64>,
    centre_cutting: Option<bool>,
    holder: Option<Vec<[f64; 2]>>,
    nose_radius: Option<f64>,
    shape: Option<String>,
    tip: Option<u8>,
    edge_length: Option<f64>,
    bisector: Option<f64>,
    width: Option<f64>,
    depth: Option<f64>,
}

/// Why a tool file was refused.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ToolFileError {
    /// Not TOML of the expected shape (the TOML reader's message, with its
    /// line and column).
    #[error("{0}")]
    Syntax(String),
    /// A `[tool.KEY]` whose key is not a whole number.
    #[error("[tool.{key}]: the tool number must be a whole number")]
    ToolNumber {
        /// The key as written.
        key: String,
    },
    /// A tool whose entry is refused: the key and what is wrong with it.
    #[error("[tool.{tool}]: {problem}")]
    Tool {
        /// The tool number.
        tool: u32,
        /// The key and what it must be.
        problem: ToolProblem,
    },
}

/// What is wrong with one tool's entry (the key and what it must be).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ToolProblem {
    #[error("{key} is missing")]
    Missing { key: String },
    #[error("{key} = {value} must be positive (mm, at most 10000)")]
    NotPositive { key: String, value: f64 },
    #[error("{key} = {value} must be 0 or more")]
    Negative { key: String, value: f64 },
    #[error("{key} = {value} must be between 0 and 180 degrees")]
    Angle { key: String, value: f64 },
    #[error("corner_radius = {corner} must be below the radius {radius} (use kind = \"ball\")")]
    Corner { corner: f64, radius: f64 },
    #[error("tip_diameter must be below diameter {diameter}")]
    TipDiameter { diameter: f64 },
    #[error("kind = \"{0}\" (flat, ball, bull, drill, chamfer)")]
    MillKind(String),
    #[error("shape = \"{0}\" (C, D, K, S, T, V, W, or angle = DEG)")]
    Shape(String),
    #[error("tip = {0} must be 0-9")]
    Tip(u8),
    #[error("kind = \"{0}\" (insert, groove, drill)")]
    LatheKind(String),
    #[error("nose_radius = {nose_radius} is more than half the width {width}")]
    NoseRadius { nose_radius: f64, width: f64 },
    #[error("holder points must be numbers")]
    HolderNumbers,
    #[error("holder needs at least 3 [z, x] points")]
    HolderPoints,
}

/// Reads a tool file. `lathe` selects the lathe meaning of the kinds.
/// Errors name the tool number and the key.
pub fn parse_tools(text: &str, lathe: bool) -> Result<ToolTable, ToolFileError> {
    let f: File = toml::from_str(text).map_err(|e| ToolFileError::Syntax(e.to_string()))?;
    let mut t = ToolTable::default();
    for (key, e) in f.tool {
        let n: u32 = key
            .parse()
            .map_err(|_| ToolFileError::ToolNumber { key: key.clone() })?;
        let refused = |problem| ToolFileError::Tool { tool: n, problem };
        let tool = if lathe {
            Tool::Lathe(lathe_tool(&e).map_err(refused)?)
        } else {
            Tool::Mill(mill_tool(&e).map_err(refused)?)
        };
        t.tools.insert(n, tool);
    }
    Ok(t)
}

fn need(v: Option<f64>, name: &str) -> Result<f64, ToolProblem> {
    let v = v.ok_or_else(|| missing(name))?;
    positive(v, name)
}

fn missing(key: &str) -> ToolProblem {
    ToolProblem::Missing {
        key: key.to_string(),
    }
}

fn positive(v: f64, name: &str) -> Result<f64, ToolProblem> {
    if v.is_finite() && v > 0.0 && v <= 10_000.0 {
        Ok(v)
    } else {
        Err(ToolProblem::NotPositive {
            key: name.to_string(),
            value: v,
        })
    }
}

fn non_negative(v: Option<f64>, name: &str) -> Result<f64, ToolProblem> {
    match v {
        None => Ok(0.0),
        Some(v) if v.is_finite() && (0.0..=10_000.0).contains(&v) => Ok(v),
        Some(v) => Err(ToolProblem::Negative {
            key: name.to_string(),
            value: v,
        }),
    }
}

fn angle(v: Option<f64>, name: &str, default: Option<f64>) -> Result<f64, ToolProblem> {
    let v = match (v, default) {
        (Some(v), _) => v,
        (None, Some(d)) => d,
        (None, None) => return Err(missing(name)),
    };
    if v.is_finite() && v > 0.0 && v < 180.0 {
        Ok(v)
    } else {
        Err(ToolProblem::Angle {
            key: name.to_string(),
            value: v,
        })
    }
}

fn mill_tool(e: &Entry) -> Result<MillTool, ToolProblem> {
    let kind_name = e.kind.as_deref().ok_or_else(|| missing("kind"))?;
    let radius = need(e.diameter, "diameter")? / 2.0;
    let kind = match kind_name {
        "flat" => MillKind::Flat,
        "ball" => MillKind::Ball,
        "bull" => {
            let c = need(e.corner_radius, "corner_radius")?;
            if c >= radius {
                return Err(ToolProblem::Corner { corner: c, radius });
            }
            MillKind::Bull { corner: c }
        }
        "drill" => MillKind::Drill {
            point_angle: angle(e.point_angle, "point_angle", Some(118.0))?,
        },
        "chamfer" => {
            let tip_radius = non_negative(e.tip_diameter, "tip_diameter")? / 2.0;
            if tip_radius >= radius {
                return Err(ToolProblem::TipDiameter {
                    diameter: 2.0 * radius,
                });
            }
            MillKind::Chamfer {
                angle: angle(e.angle, "angle", Some(90.0))?,
                tip_radius,
            }
        }
        k => return Err(ToolProblem::MillKind(k.to_string())),
    };
    let flute_length = match e.flute_length {
        Some(v) => positive(v, "flute_length")?,
        None => 1.0e4,
    };
    let mut holder = Vec::new();
    for (i, [d, l]) in e.holder.iter().flatten().enumerate() {
        let d = positive(*d, &format!("holder[{i}] diameter"))?;
        let l = positive(*l, &format!("holder[{i}] length"))?;
        holder.push((d / 2.0, l));
    }
    let centre_cutting = e.centre_cutting.unwrap_or(true);
    Ok(MillTool {
        kind,
        radius,
        flute_length,
        centre_cutting,
        holder,
    })
}

/// ISO insert shape letter → included angle, degrees.
fn shape_angle(s: &str) -> Result<f64, ToolProblem> {
    Ok(match s {
        "C" => 80.0,
        "D" => 55.0,
        "V" => 35.0,
        "T" => 60.0,
        "S" => 90.0,
        "W" => 80.0,
        "K" => 55.0,
        other => return Err(ToolProblem::Shape(other.to_string())),
    })
}

fn lathe_tool(e: &Entry) -> Result<LatheTool, ToolProblem> {
    let kind_name = e.kind.as_deref().unwrap_or("insert");
    let nose_radius = non_negative(e.nose_radius, "nose_radius")?;
    let tip = e.tip.unwrap_or(3);
    if tip > 9 {
        return Err(ToolProblem::Tip(tip));
    }
    let kind = match kind_name {
        "insert" => {
            let a = match (&e.shape, e.angle) {
                (_, Some(a)) => angle(Some(a), "angle", None)?,
                (Some(s), None) => shape_angle(s)?,
                (None, None) => 80.0,
            };
            LatheKind::Insert {
                angle: a,
                edge: match e.edge_length {
                    Some(v) => positive(v, "edge_length")?,
                    None => 8.0,
                },
                bisector: e.bisector.unwrap_or_else(|| default_bisector(tip)),
            }
        }
        "groove" => LatheKind::Groove {
            width: need(e.width, "width")?,
            depth: match e.depth {
                Some(v) => positive(v, "depth")?,
                None => 20.0,
            },
        },
        "drill" => LatheKind::Drill {
            diameter: need(e.diameter, "diameter")?,
            point_angle: angle(e.point_angle, "point_angle", Some(118.0))?,
            flute_length: match e.flute_length {
                Some(v) => positive(v, "flute_length")?,
                None => 1.0e4,
            },
        },
        k => return Err(ToolProblem::LatheKind(k.to_string())),
    };
    if let LatheKind::Groove { width, .. } = kind {
        if 2.0 * nose_radius > width {
            return Err(ToolProblem::NoseRadius { nose_radius, width });
        }
    }
    let holder = e
        .holder
        .iter()
        .flatten()
        .map(|[z, x]| (*z, *x))
        .collect::<Vec<_>>();
    if holder.iter().any(|(z, x)| !z.is_finite() || !x.is_finite()) {
        return Err(ToolProblem::HolderNumbers);
    }
    if !holder.is_empty() && holder.len() < 3 {
        return Err(ToolProblem::HolderPoints);
    }
    Ok(LatheTool {
        kind,
        nose_radius,
        tip,
        holder,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mill_tools_read_with_their_dimensions() {
        let t = parse_tools(
            "[tool.1]\nkind=\"bull\"\ndiameter=10\ncorner_radius=1\nflute_length=25\n\
             holder=[[10,40],[40,60]]\n[tool.2]\nkind=\"drill\"\ndiameter=8\n",
            false,
        )
        .unwrap();
        let Tool::Mill(m) = &t.tools[&1] else {
            panic!()
        };
        assert_eq!(m.kind, MillKind::Bull { corner: 1.0 });
        assert_eq!(m.radius, 5.0);
        assert_eq!(m.holder, vec![(5.0, 40.0), (20.0, 60.0)]);
        let Tool::Mill(d) = &t.tools[&2] else {
            panic!()
        };
        assert_eq!(d.kind, MillKind::Drill { point_angle: 118.0 });
    }

    #[test]
    fn lathe_tools_read_with_shape_and_tip() {
        let t = parse_tools(
            "[tool.1]\nnose_radius=0.4\nshape=\"D\"\ntip=3\n[tool.5]\nkind=\"groove\"\nwidth=3\n",
            true,
        )
        .unwrap();
        let Tool::Lathe(l) = &t.tools[&1] else {
            panic!()
        };
        match l.kind {
            LatheKind::Insert {
                angle, bisector, ..
            } => {
                assert_eq!(angle, 55.0);
                assert!((bisector - 45.0).abs() < 1e-9);
            }
            _ => panic!(),
        }
        assert!(matches!(
            t.tools[&5],
            Tool::Lathe(LatheTool {
                kind: LatheKind::Groove { .. },
                ..
            })
        ));
    }

    #[test]
    fn missing_or_negative_dimensions_are_named() {
        for (text, lathe, part) in [
            (
                "[tool.1]\nkind=\"flat\"\n",
                false,
                "[tool.1]: diameter is missing",
            ),
            (
                "[tool.2]\nkind=\"flat\"\ndiameter=-3\n",
                false,
                "[tool.2]: diameter = -3",
            ),
            (
                "[tool.3]\nkind=\"bull\"\ndiameter=6\n",
                false,
                "corner_radius is missing",
            ),
            (
                "[tool.4]\nkind=\"flat\"\ndiameter=6\nflute_length=0\n",
                false,
                "flute_length = 0",
            ),
            (
                "[tool.5]\nkind=\"saw\"\ndiameter=6\n",
                false,
                "kind = \"saw\"",
            ),
            (
                "[tool.6]\nnose_radius=-0.4\n",
                true,
                "[tool.6]: nose_radius = -0.4",
            ),
            ("[tool.7]\nkind=\"groove\"\n", true, "width is missing"),
            ("[tool.x]\nkind=\"flat\"\n", false, "whole number"),
            (
                "[tool.8]\nkind=\"flat\"\ndiameter=6\nholder=[[10,-1]]\n",
                false,
                "holder[0] length",
            ),
        ] {
            let e = parse_tools(text, lathe).unwrap_err().to_string();
            assert!(e.contains(part), "{text}: {e}");
        }
    }

    #[test]
    fn refusals_name_the_tool_and_the_key_as_values() {
        assert_eq!(
            parse_tools("[tool.x]\nkind=\"flat\"\n", false).unwrap_err(),
            ToolFileError::ToolNumber { key: "x".into() }
        );
        match parse_tools("[tool.7]\nkind=\"groove\"\n", true).unwrap_err() {
            ToolFileError::Tool { tool, problem } => {
                assert_eq!(tool, 7);
                assert_eq!(
                    problem,
                    ToolProblem::Missing {
                        key: "width".into()
                    }
                );
                assert_eq!(problem.to_string(), "width is missing");
            }
            e => panic!("{e:?}"),
        }
        assert!(matches!(
            parse_tools("[tool.1\n", false).unwrap_err(),
            ToolFileError::Syntax(_)
        ));
    }
}
