//! The offset, parameter and macro-variable pages: read any time, written
//! when the mode table allows it, each accepted write saved to `--state`
//! before it is acknowledged.

use kerf_canon::{Axis, NAXES};
use kerf_interp::machine::axis_by_name;
use serde::{Deserialize, Serialize};

use super::command::{Op, Refusal};
use super::offset_error::OffsetError;
use super::persist::Part;
use super::Runtime;

/// Largest offset value accepted, mm (geometry); wear is limited to
/// [`MAX_WEAR`].
pub const MAX_GEOMETRY: f64 = 9999.999;
/// Largest wear offset accepted, mm.
pub const MAX_WEAR: f64 = 999.999;

/// One write to the offset pages. Values are mm (lathe X a radius).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "page", rename_all = "snake_case")]
pub enum OffsetWrite {
    /// Tool length offset H`n`.
    H {
        n: usize,
        #[serde(default)]
        geom: Option<f64>,
        #[serde(default)]
        wear: Option<f64>,
    },
    /// Cutter radius offset D`n`.
    D {
        n: usize,
        #[serde(default)]
        geom: Option<f64>,
        #[serde(default)]
        wear: Option<f64>,
    },
    /// Lathe tool offset `n`: X (radius), Z, nose radius, tip, wears.
    Lathe {
        n: usize,
        #[serde(default)]
        x: Option<f64>,
        #[serde(default)]
        z: Option<f64>,
        #[serde(default)]
        r: Option<f64>,
        #[serde(default)]
        tip: Option<u8>,
        #[serde(default)]
        wear_x: Option<f64>,
        #[serde(default)]
        wear_z: Option<f64>,
        #[serde(default)]
        wear_r: Option<f64>,
    },
    /// Work offset G54+`index` (0-5): machine coordinate of its zero on
    /// one axis.
    Work {
        index: usize,
        axis: String,
        value: f64,
    },
}

/// One write to the macro variable page.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct VarWrite {
    /// Variable number: common #100-#199 or retained (#500-#999 Fanuc,
    /// #200-#699 HX).
    pub n: usize,
    /// The value; None makes it vacant.
    pub value: Option<f64>,
}

fn check(v: Option<f64>, max: f64, what: &'static str) -> Result<(), OffsetError> {
    match v {
        Some(x) if !x.is_finite() || x.abs() > max => Err(OffsetError::Range {
            what,
            value: x,
            max,
        }),
        _ => Ok(()),
    }
}

impl Runtime {
    /// Writes the offset pages. The value acts when the program next
    /// selects the offset (as on the control); it is saved to `--state`
    /// before this returns Ok.
    pub fn write_offset(&mut self, w: OffsetWrite) -> Result<(), Refusal> {
        let op = Op::WriteOffset;
        self.check(op)?;
        self.validate_offset(&w)
            .map_err(|r| self.refuse(op, r.to_string()))?;
        let part = match w {
            OffsetWrite::Work { .. } => Part::Work,
            _ => Part::Tools,
        };
        self.apply_offset(w);
        self.save_state_now(part)
            .map_err(|e| self.refuse(op, e.to_string()))
    }

    /// Applies a validated write.
    pub(super) fn apply_offset(&mut self, w: OffsetWrite) {
        let it = &mut self.interp;
        match w {
            OffsetWrite::H { n, geom, wear } | OffsetWrite::D { n, geom, wear } => {
                let is_h = matches!(w, OffsetWrite::H { .. });
                let o = it.offsets_mut();
                let e = if is_h { o.h_mut(n) } else { o.d_mut(n) }.expect("validated");
                if let Some(g) = geom {
                    e.geom = g;
                }
                if let Some(g) = wear {
                    e.wear = g;
                }
            }
            OffsetWrite::Lathe {
                n,
                x,
                z,
                r,
                tip,
                wear_x,
                wear_z,
                wear_r,
            } => {
                let e = it.offsets_mut().lathe_mut(n).expect("validated");
                let set = |dst: &mut f64, v: Option<f64>| {
                    if let Some(v) = v {
                        *dst = v
                    }
                };
                set(&mut e.x, x);
                set(&mut e.z, z);
                set(&mut e.r, r);
                set(&mut e.wear_x, wear_x);
                set(&mut e.wear_z, wear_z);
                set(&mut e.wear_r, wear_r);
                if let Some(t) = tip {
                    e.tip = t;
                }
            }
            OffsetWrite::Work {
                index,
                ref axis,
                value,
            } => {
                let a = axis_by_name(&axis.to_ascii_lowercase()).expect("validated");
                let mut p = it.work_offset(index).expect("validated");
                p[a as usize] = value;
                it.set_work_offset(index, p);
            }
        }
    }

    pub(super) fn validate_offset(&self, w: &OffsetWrite) -> Result<(), OffsetError> {
        let count = self.interp.offsets().count();
        let num = |n: usize| {
            if (1..=count).contains(&n) {
                Ok(())
            } else {
                Err(OffsetError::Number { n, count })
            }
        };
        match w {
            OffsetWrite::H { n, geom, wear } | OffsetWrite::D { n, geom, wear } => {
                num(*n)?;
                check(*geom, MAX_GEOMETRY, "geometry")?;
                check(*wear, MAX_WEAR, "wear")
            }
            OffsetWrite::Lathe {
                n,
                x,
                z,
                r,
                tip,
                wear_x,
                wear_z,
                wear_r,
            } => {
                num(*n)?;
                for v in [x, z, r] {
                    check(*v, MAX_GEOMETRY, "geometry")?;
                }
                for v in [wear_x, wear_z, wear_r] {
                    check(*v, MAX_WEAR, "wear")?;
                }
                if r.is_some_and(|r| r < 0.0) {
                    return Err(OffsetError::NegativeRadius);
                }
                match tip {
                    Some(t) if *t > 9 => Err(OffsetError::Tip(*t)),
                    _ => Ok(()),
                }
            }
            OffsetWrite::Work { index, axis, value } => {
                if *index >= 6 {
                    return Err(OffsetError::WorkIndex(*index));
                }
                match axis_by_name(&axis.to_ascii_lowercase()) {
                    Some(a) if self.profile.has_axis(a) => {}
                    _ => return Err(OffsetError::NoAxis(axis.clone())),
                }
                check(Some(*value), 99_999.999, "work offset")
            }
        }
    }

    /// Writes a macro variable from the variable page.
    pub fn write_variable(&mut self, w: VarWrite) -> Result<(), Refusal> {
        let op = Op::WriteVariable;
        self.check(op)?;
        if w.value.is_some_and(|v| !v.is_finite() || v.abs() > 1e15) {
            return Err(self.refuse(op, "value out of range (|v| ≤ 1e15)"));
        }
        if !self.interp.set_common_var(w.n, w.value) {
            return Err(self.refuse(
                op,
                format!(
                    "#{}: the page writes common (#100-#199) and retained variables",
                    w.n
                ),
            ));
        }
        self.save_state_now(Part::Vars)
            .map_err(|e| self.refuse(op, e.to_string()))
    }

    /// Writes a parameter (EDIT or MDI mode, control idle). Parameters the
    /// control reads at reset (PI 144-150) act from the next RESET.
    pub fn write_parameter(&mut self, name: &str, value: f64) -> Result<(), Refusal> {
        let op = Op::WriteParameter;
        self.check(op)?;
        let name = name.trim();
        if name.is_empty() || name.len() > 64 || !value.is_finite() {
            return Err(self.refuse(op, "a parameter name and a finite value"));
        }
        self.interp.set_param(name, value);
        self.profile.params.insert(name.to_string(), value);
        Ok(())
    }

    /// The value of parameter `name` as the control reads it.
    pub fn parameter(&self, name: &str) -> Option<f64> {
        self.interp.profile().params.get(name).copied()
    }

    /// A work offset (machine coordinates of the zero of G54+`index`).
    pub fn work_offset(&self, index: usize) -> Option<[f64; NAXES]> {
        self.interp.work_offset(index)
    }

    /// The machine's axes in slot order.
    pub fn axes(&self) -> Vec<Axis> {
        Axis::ALL
            .into_iter()
            .filter(|&a| self.profile.has_axis(a))
            .collect()
    }
}
