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

fn num(t: &toml::Table, key: &str, name: &str) -> Result<Option<f64>, String> {
    match t.get(key) {
        None => Ok(None),
        Some(toml::Value::Float(v)) => Ok(Some(*v)),
        Some(toml::Value::Integer(v)) => Ok(Some(*v as f64)),
        Some(_) => Err(format!("profile parameter {name} must be a number")),
    }
}

fn req(t: &toml::Table, key: &str, name: &str) -> Result<f64, String> {
    num(t, key, name)?.ok_or_else(|| format!("profile parameter {name} is missing"))
}

/// Builds and validates the planner's dynamics; `feed_override` and
/// `rapid_override` are percentages.
pub fn dynamics_of(
    p: &Profile,
    feed_override: f64,
    rapid_override: f64,
    dry_run: bool,
) -> Result<Dynamics, String> {
    let m = p.motion.as_ref().ok_or_else(|| {
        "profile has no [motion] table (planner limits; see docs/formats.md)".to_string()
    })?;
    for k in m.keys() {
        if !KEYS.contains(&k.as_str()) {
            return Err(format!("unknown profile parameter motion.{k}"));
        }
    }
    let empty = toml::Table::new();
    let axes = match m.get("axes") {
        None => &empty,
        Some(toml::Value::Table(t)) => t,
        Some(_) => return Err("profile parameter motion.axes must be a table".into()),
    };
    let mut d = Dynamics::uniform([false; NAXES], 0.0, 0.0, 0.0, p.feed.max_cutting);
    for k in axes.keys() {
        match kerf_interp::machine::axis_by_name(k) {
            Some(a) if p.has_axis(a) => {}
            _ => return Err(format!("motion.axes.{k}: the machine has no axis '{k}'")),
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
            Some(_) => return Err(format!("profile parameter motion.axes.{n} must be a table")),
            None => return Err(format!("profile parameter motion.axes.{n} is missing")),
        };
        for k in t.keys() {
            if !AXIS_KEYS.contains(&k.as_str()) {
                return Err(format!("unknown profile parameter motion.axes.{n}.{k}"));
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
            return Err("profile parameter motion.accel_type is missing".into())
        }
        _ => {
            return Err("profile parameter motion.accel_type must be \"linear\" or \"bell\"".into())
        }
    };
    let count = |key: &str| -> Result<usize, String> {
        let name = format!("motion.{key}");
        let v = req(m, key, &name)?;
        if v.fract() != 0.0 || !(1.0..=100_000.0).contains(&v) {
            return Err(format!(
                "profile parameter {name} must be a whole number of blocks, 1-100000"
            ));
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
    d.validate()?;
    Ok(d)
}

/// G62 / PI 131 automatic corner override and the internal circular
/// cutting feed change (000 §5.3.5-5.3.6) from the `[motion]` table `m`;
/// 000 prints no values: the defaults are documented in docs/formats.md.
fn corner_override(m: &toml::Table, c: &mut kerf_motion::CornerOverride) -> Result<(), String> {
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
            return Err(
                "profile parameter motion.corner_override_always must be true or false".into(),
            )
        }
    }
    Ok(())
}
