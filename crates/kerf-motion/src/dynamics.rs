//! Machine dynamics the planner needs, and their validation.

use kerf_canon::{Axis, NAXES};

pub use crate::dynamics_error::DynamicsLimitError;

/// Acceleration/deceleration after interpolation (000 §5.5: PM 598
/// linear, PM 599 bell-shaped).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AccelType {
    /// One moving-average stage of width `T`: acceleration is bounded,
    /// jerk is not.
    Linear,
    /// Two moving-average stages of width `T` each (bell-shaped): both
    /// acceleration and jerk are bounded.
    Bell,
}

/// G62 automatic corner override (000 §5.3.5, PI 124-126, 130, 131).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CornerOverride {
    /// Inside corners whose angle (between the two paths at the corner,
    /// 180° = straight on) is from 2° up to this are overridden, degrees
    /// (PI 130, 2-178; `motion.corner_override_angle_deg`).
    pub angle_deg: f64,
    /// The override, fraction (PI 125 %; `motion.corner_override_pct`).
    pub factor: f64,
    /// Distance before the corner over which the feed is reduced, mm
    /// (PI 124; `motion.corner_override_before_mm`).
    pub before: f64,
    /// Distance after the corner, mm (PI 126; `motion.corner_override_after_mm`).
    pub after: f64,
    /// Override in every mode, not only G62 (PI 131 = 1;
    /// `motion.corner_override_always`).
    pub always: bool,
}

impl Default for CornerOverride {
    fn default() -> Self {
        CornerOverride {
            angle_deg: 91.0,
            factor: 0.5,
            before: 1.0,
            after: 1.0,
            always: false,
        }
    }
}

/// The machine data the planner needs (built from the profile by the CLI;
/// every field is named after its profile key in [`Dynamics::validate`]).
#[derive(Clone, Debug)]
pub struct Dynamics {
    /// Axis present per slot.
    pub present: [bool; NAXES],
    /// Rapid rate per axis slot, mm/min (deg/min) (`axes.*.rapid`).
    pub rapid: [f64; NAXES],
    /// Rapid acceleration per axis, mm/s² (`motion.axes.*.rapid_accel`).
    pub rapid_accel: [f64; NAXES],
    /// Cutting acceleration per axis, mm/s² (`motion.axes.*.accel`).
    pub accel: [f64; NAXES],
    /// Jerk per axis, mm/s³ (`motion.axes.*.jerk`).
    pub jerk: [f64; NAXES],
    /// In-position width per axis, mm (`motion.axes.*.in_position_mm`).
    pub in_position: [f64; NAXES],
    /// Maximum cutting feed, mm/min (`feed.max_cutting`).
    pub max_feed: f64,
    /// Tool change / turret index time, s (`tools.change_time_s`).
    pub tool_change_s: f64,
    /// Acc/dec type after interpolation (`motion.accel_type`).
    pub accel_type: AccelType,
    /// Look-ahead window, blocks (`motion.lookahead`).
    pub lookahead: usize,
    /// Look-ahead window in high-speed mode G10.3 (`motion.lookahead_high_speed`).
    pub lookahead_high_speed: usize,
    /// Path tolerance at corners and arcs, mm (`motion.path_tolerance_mm`).
    pub path_tolerance: f64,
    /// Spindle acceleration, rpm/s (`motion.spindle_accel_rpm_s`).
    pub spindle_accel: f64,
    /// M/S/T function handshake time, s (`motion.aux_time_s`).
    pub aux_time_s: f64,
    /// Feed used for cutting moves with dry run on, mm/min
    /// (`motion.dry_run_feed`).
    pub dry_run_feed: f64,
    /// Feed override, fraction (1.0 = 100 %).
    pub feed_override: f64,
    /// Rapid override, fraction (1.0 = 100 %).
    pub rapid_override: f64,
    /// Dry run switch.
    pub dry_run: bool,
    /// G62 automatic corner override.
    pub corner: CornerOverride,
    /// Internal circular cutting feed change (000 §5.3.6): the lower
    /// limit of `Rc/Rp`, fraction (PI 132 %; `motion.internal_arc_min_pct`);
    /// `None`: no change (the feed is the tool centre's).
    pub internal_arc_min: Option<f64>,
    /// Position loop gain of the servos, 1/s (`motion.position_gain`): the
    /// following error decays as `exp(−gain·t)`; infinite = an ideal servo
    /// (no in-position wait).
    pub position_gain: f64,
}

impl Dynamics {
    /// Dynamics for tests and examples: every axis in `present` gets the
    /// same limits.
    pub fn uniform(
        present: [bool; NAXES],
        rapid: f64,
        accel: f64,
        jerk: f64,
        max_feed: f64,
    ) -> Dynamics {
        let v = |x: f64| {
            let mut a = [0.0; NAXES];
            for i in 0..NAXES {
                if present[i] {
                    a[i] = x;
                }
            }
            a
        };
        Dynamics {
            present,
            rapid: v(rapid),
            rapid_accel: v(accel),
            accel: v(accel),
            jerk: v(jerk),
            in_position: v(0.01),
            max_feed,
            tool_change_s: 2.0,
            accel_type: AccelType::Bell,
            lookahead: 16,
            lookahead_high_speed: 100,
            path_tolerance: 0.01,
            spindle_accel: 2000.0,
            aux_time_s: 0.0,
            dry_run_feed: max_feed,
            feed_override: 1.0,
            rapid_override: 1.0,
            dry_run: false,
            corner: CornerOverride::default(),
            internal_arc_min: None,
            position_gain: f64::INFINITY,
        }
    }

    /// Checks every limit; the error names the profile parameter.
    pub fn validate(&self) -> Result<(), DynamicsLimitError> {
        let pos = |name: String, v: f64| -> Result<(), DynamicsLimitError> {
            if v.is_finite() && v > 0.0 {
                Ok(())
            } else {
                Err(DynamicsLimitError::NotPositive(name, v))
            }
        };
        let nonneg = |name: &str, v: f64| -> Result<(), DynamicsLimitError> {
            if v.is_finite() && v >= 0.0 {
                Ok(())
            } else {
                Err(DynamicsLimitError::Negative(name.to_string(), v))
            }
        };
        for a in Axis::ALL {
            let i = a as usize;
            if !self.present[i] {
                continue;
            }
            let n = a.name();
            pos(format!("axes.{n}.rapid"), self.rapid[i])?;
            pos(format!("motion.axes.{n}.rapid_accel"), self.rapid_accel[i])?;
            pos(format!("motion.axes.{n}.accel"), self.accel[i])?;
            pos(format!("motion.axes.{n}.jerk"), self.jerk[i])?;
            pos(
                format!("motion.axes.{n}.in_position_mm"),
                self.in_position[i],
            )?;
        }
        pos("feed.max_cutting".into(), self.max_feed)?;
        nonneg("tools.change_time_s", self.tool_change_s)?;
        if self.lookahead == 0 {
            return Err(DynamicsLimitError::NoBlocks("motion.lookahead"));
        }
        if self.lookahead_high_speed == 0 {
            return Err(DynamicsLimitError::NoBlocks("motion.lookahead_high_speed"));
        }
        pos("motion.path_tolerance_mm".into(), self.path_tolerance)?;
        pos("motion.spindle_accel_rpm_s".into(), self.spindle_accel)?;
        nonneg("motion.aux_time_s", self.aux_time_s)?;
        pos("motion.dry_run_feed".into(), self.dry_run_feed)?;
        pos("feed_override".into(), self.feed_override)?;
        pos("rapid_override".into(), self.rapid_override)?;
        let c = &self.corner;
        if !(2.0..=178.0).contains(&c.angle_deg) {
            return Err(DynamicsLimitError::CornerAngle(c.angle_deg));
        }
        if !(0.01..=1.0).contains(&c.factor) {
            return Err(DynamicsLimitError::CornerPct(c.factor * 100.0));
        }
        nonneg("motion.corner_override_before_mm", c.before)?;
        nonneg("motion.corner_override_after_mm", c.after)?;
        if let Some(m) = self.internal_arc_min {
            if !(m > 0.0 && m <= 1.0) {
                return Err(DynamicsLimitError::InternalArcPct(m * 100.0));
            }
        }
        if self.position_gain.is_nan() || self.position_gain <= 0.0 {
            return Err(DynamicsLimitError::NotPositive(
                "motion.position_gain".into(),
                self.position_gain,
            ));
        }
        Ok(())
    }

    /// Number of moving-average stages after interpolation.
    pub fn stages(&self) -> usize {
        match self.accel_type {
            AccelType::Linear => 1,
            AccelType::Bell => 2,
        }
    }

    /// Width `T` of each smoothing stage, s: the largest of
    /// `accel/jerk` and `2·rapid_accel/jerk` over the axes, so that the
    /// smoothed jerk stays within every axis's limit.
    pub fn smoothing_time(&self) -> f64 {
        let mut t: f64 = 0.0;
        for i in 0..NAXES {
            if self.present[i] && self.jerk[i] > 0.0 {
                t = t.max(self.accel[i] / self.jerk[i]);
                t = t.max(2.0 * self.rapid_accel[i] / self.jerk[i]);
            }
        }
        t
    }
}
