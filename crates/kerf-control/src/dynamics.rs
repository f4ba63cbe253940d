//! The `[motion]` table of a machine profile → kerf-motion's `Dynamics`.
//! Every key is documented in docs/formats.md; a missing or non-positive
//! limit is an error naming the parameter.

use kerf_canon::{Axis, NAXES};
use kerf_interp::Profile;
use kerf_motion::{AccelType, Dynamics};

const AXIS_KEYS: &[&str] = &["accel", "jerk", "rapid_accel", "in_position_mm"];
const KEYS: &[&str] = &[
    "accel_type",
    "lookahead",
    "lookahead_high_speed",
    "path_tolerance_mm",
    "spindle_accel_rpm_s",
    "aux_time_s",
    "dry_run_feed",
    "corner_override_angle_deg",
    "corner_override_pct",
    "corner_override_before_mm",
    "corner_override_after_mm",
    "corner_override_always",
    "internal_arc_min_pct",
    "position_gain",
    "axes",
];

/// A `[motion]` table the planner cannot run with; each message names the
/// profile parameter (`motion.axes.x.jerk`).
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum DynamicsError {
    /// The profile has no `[motion]` table.
    #[error("profile has no [motion] table (planner limits; see docs/formats.md)")]
    NoMotionTable,
    /// A key that is not a parameter.
    #[error("unknown profile parameter {0}")]
    Unknown(String),
    /// A required parameter that is not given.
    #[error("profile parameter {0} is missing")]
    Missing(String),
    /// A parameter that must be a number.
    #[error("profile parameter {0} must be a number")]
    NotNumber(String),
    /// A parameter that must be a table.
    #[error("profile parameter {0} must be a table")]
    NotTable(String),
    /// `[motion.axes.K]` for an axis the machine does not have.
    #[error("motion.axes.{0}: the machine has no axis '{0}'")]
    NoSuchAxis(String),
    /// `accel_type` other than `"linear"` or `"bell"`.
    #[error("profile parameter motion.accel_type must be \"linear\" or \"bell\"")]
    AccelType,
    /// A look-ahead window that is not 1-100000 blocks.
    #[error("profile parameter {0} must be a whole number of blocks, 1-100000")]
    Blocks(String),
    /// A parameter that must be true or false.
    #[error("profile parameter {0} must be true or false")]
    NotBool(String),
    /// A limit out of range, as kerf-motion's `Dynamics::validate` names it.
    #[error("{0}")]
    Limit(#[from] kerf_motion::DynamicsLimitError),
}

impl From<DynamicsError> for String {
    fn from(e: DynamicsError) -> String {
        e.to_string()
    }
}

fn num(t: &toml::Table, key: &str, name: &str) -> Result<Option<f64>, DynamicsError> {
    match t.get(key) {
        None => Ok(None),
        Some(toml::Value::Float(v)) => Ok(Some(*v)),
        Some(toml::Value::Integer(v)) => Ok(Some(*v as f64)),
        Some(_) => Err(DynamicsError::NotNumber(name.to_string())),
    }
}

fn req(t: &toml::Table, key: &str, name: &str) -> Result<f64, DynamicsError> {
    num(t, key, name)?.ok_or_else(|| DynamicsError::Missing(name.to_string()))
}

/// Builds and validates the planner's dynamics; `feed_override` and
/// `rapid_override` are percentages.
pub fn dynamics_of(
    p: &Profile,
    feed_override: f64,
    rapid_override: f64,
    dry_run: bool,
) -> Result<Dynamics, DynamicsError> {
    let m = p.motion.as_ref().ok_or(DynamicsError::NoMotionTable)?;
    for k in m.keys() {
        if !KEYS.contains(&k.as_str()) {
            return Err(DynamicsError::Unknown(format!("motion.{k}")));
        }
    }
    let empty = toml::Table::new();
    let axes = match m.get("axes") {
        None => &empty,
        Some(toml::Value::Table(t)) => t,
        Some(_) => return Err(DynamicsError::NotTable("motion.axes".into())),
    };
    let mut d = Dynamics::uniform([false; NAXES], 0.0, 0.0, 0.0, p.feed.max_cutting);
    for k in axes.keys() {
        match kerf_interp::machine::axis_by_name(k) {
            Some(a) if p.has_axis(a) => {}
            _ => return Err(DynamicsError::NoSuchAxis(k.clone())),
        }
    }
    for a in Axis::ALL {
        let Some(ad) = p.axis(a) else { continue };
        let i = a as usize;
        let n = a.name();
        d.present[i] = true;
        d.rapid[i] = ad.rapid;
        let t = match axes.get(n) {
            Some(toml::Value::Table(t)) => t,
            Some(_) => return Err(DynamicsError::NotTable(format!("motion.axes.{n}"))),
            None => return Err(DynamicsError::Missing(format!("motion.axes.{n}"))),
        };
        for k in t.keys() {
            if !AXIS_KEYS.contains(&k.as_str()) {
                return Err(DynamicsError::Unknown(format!("motion.axes.{n}.{k}")));
            }
        }
        d.accel[i] = req(t, "accel", &format!("motion.axes.{n}.accel"))?;
        d.jerk[i] = req(t, "jerk", &format!("motion.axes.{n}.jerk"))?;
        d.rapid_accel[i] = req(t, "rapid_accel", &format!("motion.axes.{n}.rapid_accel"))?;
        d.in_position[i] = req(
            t,
            "in_position_mm",
            &format!("motion.axes.{n}.in_position_mm"),
        )?;
    }
    d.accel_type = match m.get("accel_type").and_then(|v| v.as_str()) {
        Some("bell") => AccelType::Bell,
        Some("linear") => AccelType::Linear,
        None if m.get("accel_type").is_none() => {
            return Err(DynamicsError::Missing("motion.accel_type".into()))
        }
        _ => return Err(DynamicsError::AccelType),
    };
    let count = |key: &str| -> Result<usize, DynamicsError> {
        let name = format!("motion.{key}");
        let v = req(m, key, &name)?;
        if v.fract() != 0.0 || !(1.0..=100_000.0).contains(&v) {
            return Err(DynamicsError::Blocks(name));
        }
        Ok(v as usize)
    };
    d.lookahead = count("lookahead")?;
    d.lookahead_high_speed = count("lookahead_high_speed")?;
    d.path_tolerance = req(m, "path_tolerance_mm", "motion.path_tolerance_mm")?;
    d.spindle_accel = req(m, "spindle_accel_rpm_s", "motion.spindle_accel_rpm_s")?;
    d.aux_time_s = req(m, "aux_time_s", "motion.aux_time_s")?;
    d.dry_run_feed = num(m, "dry_run_feed", "motion.dry_run_feed")?.unwrap_or(p.feed.max_cutting);
    corner_override(m, &mut d.corner)?;
    d.internal_arc_min = match num(m, "internal_arc_min_pct", "motion.internal_arc_min_pct")? {
        Some(v) => Some(v / 100.0),
        // Mills: on with 000's lower limit; lathes (001, 002 describe no
        // such change, and the nose radius's imaginary tip is not the
        // tool centre) only when the key is given.
        None if p.kind == kerf_interp::machine::MachineKind::Mill => Some(0.1),
        None => None,
    };
    d.position_gain = num(m, "position_gain", "motion.position_gain")?.unwrap_or(30.0);
    d.tool_change_s = p.tools.change_time_s;
    d.feed_override = feed_override / 100.0;
    d.rapid_override = rapid_override / 100.0;
    d.dry_run = dry_run;
    d.validate().map_err(DynamicsError::Limit)?;
    Ok(d)
}

/// G62 / PI 131 automatic corner override and the internal circular
/// cutting feed change (000 §5.3.5-5.3.6) from the `[motion]` table `m`;
/// 000 prints no values: the defaults are documented in docs/formats.md.
fn corner_override(
    m: &toml::Table,
    c: &mut kerf_motion::CornerOverride,
) -> Result<(), DynamicsError> {
    if let Some(v) = num(
        m,
        "corner_override_angle_deg",
        "motion.corner_override_angle_deg",
    )? {
        c.angle_deg = v;
    }
    if let Some(v) = num(m, "corner_override_pct", "motion.corner_override_pct")? {
        c.factor = v / 100.0;
    }
    if let Some(v) = num(
        m,
        "corner_override_before_mm",
        "motion.corner_override_before_mm",
    )? {
        c.before = v;
    }
    if let Some(v) = num(
        m,
        "corner_override_after_mm",
        "motion.corner_override_after_mm",
    )? {
        c.after = v;
    }
    match m.get("corner_override_always") {
        None => {}
        Some(toml::Value::Boolean(b)) => c.always = *b,
        Some(_) => {
            return Err(DynamicsError::NotBool(
                "motion.corner_override_always".into(),
            ))
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn with_motion(edit: impl Fn(&mut toml::Table)) -> Result<Dynamics, DynamicsError> {
        let mut p = Profile::builtin("hx-mc").unwrap();
        edit(p.motion.as_mut().unwrap());
        dynamics_of(&p, 100.0, 100.0, false)
    }

    fn axis_x(m: &mut toml::Table) -> &mut toml::Table {
        let axes = m.get_mut("axes").and_then(|v| v.as_table_mut()).unwrap();
        axes.get_mut("x").and_then(|v| v.as_table_mut()).unwrap()
    }

    #[test]
    fn each_problem_names_its_parameter() {
        assert!(with_motion(|_| {}).is_ok());
        let e = with_motion(|m| {
            axis_x(m).remove("jerk");
        });
        assert_eq!(
            e.err(),
            Some(DynamicsError::Missing("motion.axes.x.jerk".into()))
        );
        let e = with_motion(|m| {
            m.insert("lookahead".into(), toml::Value::Float(2.5));
        })
        .err()
        .unwrap();
        assert_eq!(
            e.to_string(),
            "profile parameter motion.lookahead must be a whole number of blocks, 1-100000"
        );
        let e = with_motion(|m| {
            m.insert("bogus".into(), toml::Value::Integer(1));
        });
        assert_eq!(e.err(), Some(DynamicsError::Unknown("motion.bogus".into())));
        // A zero limit is kerf-motion's check, its message kept.
        let e = with_motion(|m| {
            axis_x(m).insert("jerk".into(), toml::Value::Float(0.0));
        })
        .err()
        .unwrap();
        assert!(
            matches!(&e, DynamicsError::Limit(l) if l.names("motion.axes.x.jerk")),
            "{e}"
        );
    }
}
