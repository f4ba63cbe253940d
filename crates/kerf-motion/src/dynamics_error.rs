//! [`DynamicsLimitError`]: a limit of the machine dynamics out of range,
//! as [`crate::Dynamics::validate`] finds it. Each variant names the
//! profile parameter; the messages are those of the profile reference
//! (docs/formats.md).

/// A dynamics limit out of range, named by its profile parameter.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum DynamicsLimitError {
    /// A parameter that must be a finite number above zero (name, value).
    #[error("profile parameter {0} must be a number > 0 (is {1})")]
    NotPositive(String, f64),
    /// A parameter that must be a finite number of zero or more (name,
    /// value).
    #[error("profile parameter {0} must be a number >= 0 (is {1})")]
    Negative(String, f64),
    /// A look-ahead window of zero blocks (the parameter's name).
    #[error("profile parameter {0} must be >= 1")]
    NoBlocks(&'static str),
    /// The corner override angle outside 2-178°, degrees.
    #[error("profile parameter motion.corner_override_angle_deg must be 2-178 (is {0})")]
    CornerAngle(f64),
    /// The corner override outside 1-100 %, per cent.
    #[error("profile parameter motion.corner_override_pct must be 1-100 (is {0})")]
    CornerPct(f64),
    /// The internal arc feed clamp outside (0, 100] %, per cent.
    #[error("profile parameter motion.internal_arc_min_pct must be > 0 and <= 100 (is {0})")]
    InternalArcPct(f64),
}

impl DynamicsLimitError {
    /// True when the error is about the profile parameter `name`.
    pub fn names(&self, name: &str) -> bool {
        match self {
            DynamicsLimitError::NotPositive(n, _) | DynamicsLimitError::Negative(n, _) => n == name,
            DynamicsLimitError::NoBlocks(n) => *n == name,
            DynamicsLimitError::CornerAngle(_) => name == "motion.corner_override_angle_deg",
            DynamicsLimitError::CornerPct(_) => name == "motion.corner_override_pct",
            DynamicsLimitError::InternalArcPct(_) => name == "motion.internal_arc_min_pct",
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn messages_name_the_parameter_and_value() {
        assert_eq!(
            DynamicsLimitError::NotPositive("motion.axes.y.jerk".into(), 0.0).to_string(),
            "profile parameter motion.axes.y.jerk must be a number > 0 (is 0)"
        );
        assert_eq!(
            DynamicsLimitError::Negative("tools.change_time_s".into(), -1.5).to_string(),
            "profile parameter tools.change_time_s must be a number >= 0 (is -1.5)"
        );
        assert_eq!(
            DynamicsLimitError::NoBlocks("motion.lookahead").to_string(),
            "profile parameter motion.lookahead must be >= 1"
        );
        assert_eq!(
            DynamicsLimitError::CornerPct(0.5).to_string(),
            "profile parameter motion.corner_override_pct must be 1-100 (is 0.5)"
        );
        assert!(DynamicsLimitError::CornerAngle(1.0).names("motion.corner_override_angle_deg"));
        assert!(!DynamicsLimitError::CornerAngle(1.0).names("motion.corner_override_pct"));
    }
}
