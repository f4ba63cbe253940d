//! The raw stock: `--stock box:…`, `bar:…`, `tube:…` in the work
//! coordinates of the first work offset in force, mm (docs/sim.md).

use std::f64::consts::PI;

/// Largest stock dimension accepted, mm (a sanity bound: 10 m).
pub const MAX_DIM: f64 = 10_000.0;

/// A stock shape.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Stock {
    /// Machining center block: min and max corners (x, y, z).
    Box { min: [f64; 3], max: [f64; 3] },
    /// Lathe bar or tube on the spindle axis: outer and inner radius
    /// (0 for a bar), Z of the face and of the far end (`z_end < z_face`).
    Turn {
        r_out: f64,
        r_in: f64,
        z_face: f64,
        z_end: f64,
    },
}

/// A stock spec that could not be read; the message names the value.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("--stock {spec}: {problem}")]
pub struct StockError {
    /// The spec as given.
    pub spec: String,
    /// What is wrong with it.
    pub problem: StockProblem,
}

/// What is wrong with a stock spec (values numbered from 1).
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum StockProblem {
    #[error("expected box:…, bar:… or tube:…")]
    NoKind,
    #[error("value {index} '{text}' is not a number")]
    NotANumber { index: usize, text: String },
    #[error("value {index} '{text}' is out of range (|v| <= {MAX_DIM} mm)")]
    OutOfRange { index: usize, text: String },
    #[error("{axis}MAX {hi} is not above {axis}MIN {lo}")]
    Empty { axis: char, lo: f64, hi: f64 },
    #[error("box needs 6 values XMIN,YMIN,ZMIN,XMAX,YMAX,ZMAX")]
    BoxValues,
    #[error("bar needs DIAMETER,LENGTH[,FACE_Z]")]
    BarValues,
    #[error("tube needs OD,ID,LENGTH[,FACE_Z]")]
    TubeValues,
    #[error("unknown stock kind '{0}' (box, bar, tube)")]
    UnknownKind(String),
    #[error("diameter {0} must be positive")]
    Diameter(f64),
    #[error("length {0} must be positive")]
    Length(f64),
    #[error("inner diameter {id} must be 0 or more and below {od}")]
    InnerDiameter { id: f64, od: f64 },
}

impl Stock {
    /// Parses `box:XMIN,YMIN,ZMIN,XMAX,YMAX,ZMAX`,
    /// `bar:DIAMETER,LENGTH[,FACE_Z]` or `tube:OD,ID,LENGTH[,FACE_Z]`.
    pub fn parse(spec: &str) -> Result<Stock, StockError> {
        Self::read(spec).map_err(|problem| StockError {
            spec: spec.to_string(),
            problem,
        })
    }

    fn read(spec: &str) -> Result<Stock, StockProblem> {
        let (kind, rest) = spec.split_once(':').ok_or(StockProblem::NoKind)?;
        let mut nums = Vec::new();
        for (i, s) in rest.split(',').enumerate() {
            let (index, text) = (i + 1, s.to_string());
            let v: f64 = s.trim().parse().map_err(|_| StockProblem::NotANumber {
                index,
                text: text.clone(),
            })?;
            if !v.is_finite() || v.abs() > MAX_DIM {
                return Err(StockProblem::OutOfRange { index, text });
            }
            nums.push(v);
        }
        match (kind.trim(), nums.as_slice()) {
            ("box", &[x0, y0, z0, x1, y1, z1]) => {
                for (axis, lo, hi) in [('X', x0, x1), ('Y', y0, y1), ('Z', z0, z1)] {
                    if hi <= lo {
                        return Err(StockProblem::Empty { axis, lo, hi });
                    }
                }
                Ok(Stock::Box {
                    min: [x0, y0, z0],
                    max: [x1, y1, z1],
                })
            }
            ("box", _) => Err(StockProblem::BoxValues),
            ("bar", &[d, l]) => Self::turn(d, 0.0, l, 0.0),
            ("bar", &[d, l, f]) => Self::turn(d, 0.0, l, f),
            ("bar", _) => Err(StockProblem::BarValues),
            ("tube", &[od, id, l]) => Self::turn(od, id, l, 0.0),
            ("tube", &[od, id, l, f]) => Self::turn(od, id, l, f),
            ("tube", _) => Err(StockProblem::TubeValues),
            (k, _) => Err(StockProblem::UnknownKind(k.to_string())),
        }
    }

    fn turn(od: f64, id: f64, len: f64, face: f64) -> Result<Stock, StockProblem> {
        if od <= 0.0 {
            return Err(StockProblem::Diameter(od));
        }
        if len <= 0.0 {
            return Err(StockProblem::Length(len));
        }
        if id < 0.0 || id >= od {
            return Err(StockProblem::InnerDiameter { id, od });
        }
        Ok(Stock::Turn {
            r_out: od / 2.0,
            r_in: id / 2.0,
            z_face: face,
            z_end: face - len,
        })
    }

    /// True for a lathe stock (bar or tube).
    pub fn is_turned(&self) -> bool {
        matches!(self, Stock::Turn { .. })
    }

    /// Volume, mm³.
    pub fn volume(&self) -> f64 {
        match *self {
            Stock::Box { min, max } => (max[0] - min[0]) * (max[1] - min[1]) * (max[2] - min[2]),
            Stock::Turn {
                r_out,
                r_in,
                z_face,
                z_end,
            } => PI * (r_out * r_out - r_in * r_in) * (z_face - z_end),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn box_bar_tube_parse_with_their_volumes() {
        let b = Stock::parse("box:-150,-100,-50,150,100,0").unwrap();
        assert_eq!(b.volume(), 300.0 * 200.0 * 50.0);
        let s = Stock::parse("bar:50,100").unwrap();
        assert_eq!(
            s,
            Stock::Turn {
                r_out: 25.0,
                r_in: 0.0,
                z_face: 0.0,
                z_end: -100.0
            }
        );
        assert!((s.volume() - PI * 625.0 * 100.0).abs() < 1e-9);
        let t = Stock::parse("tube:60,40,80,2").unwrap();
        assert!((t.volume() - PI * (900.0 - 400.0) * 80.0).abs() < 1e-9);
        assert_eq!(
            t,
            Stock::Turn {
                r_out: 30.0,
                r_in: 20.0,
                z_face: 2.0,
                z_end: -78.0
            }
        );
    }

    #[test]
    fn bad_specs_name_the_value() {
        for (spec, part) in [
            ("cube:1,2,3", "unknown stock kind 'cube'"),
            ("box:0,0,0,10,10", "6 values"),
            ("box:0,0,0,10,abc,5", "value 5 'abc'"),
            ("box:0,0,5,10,10,5", "ZMAX 5 is not above ZMIN 5"),
            ("bar:-5,10", "diameter -5"),
            ("bar:50,0", "length 0"),
            ("tube:50,60,10", "inner diameter 60"),
            ("bar:1e9,10", "out of range"),
            ("bar50", "expected box"),
        ] {
            let e = Stock::parse(spec).unwrap_err().to_string();
            assert!(e.starts_with(&format!("--stock {spec}: ")), "{e}");
            assert!(e.contains(part), "{spec}: {e}");
        }
    }
}
