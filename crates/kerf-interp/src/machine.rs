//! Machine profiles: dialect + machine data, loaded from TOML. The built-in
//! profiles live in `machines/*.toml` at the workspace root and are
//! embedded in the binary.

use std::collections::BTreeMap;

use kerf_canon::{Axis, Pos, NAXES};
use serde::Deserialize;

use crate::dialect::DialectId;

/// Mill or lathe: decides plane defaults, plot view and X semantics.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum MachineKind {
    Mill,
    Lathe,
}

/// One axis of the machine.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AxisData {
    /// Lower software travel limit, machine coordinates (mm / deg;
    /// lathe X as a radius).
    pub min: f64,
    /// Upper software travel limit.
    pub max: f64,
    /// Rapid traverse rate, mm/min (deg/min for rotary axes).
    pub rapid: f64,
    /// Machine coordinate of the (first) reference position.
    #[serde(default)]
    pub reference: f64,
    /// Machine position at power-on / program start (defaults to the
    /// reference position: the machine has been homed).
    pub start: Option<f64>,
    /// Cutting-feed acceleration, mm/s² (used by the planner).
    #[serde(default = "default_accel")]
    pub accel: f64,
}

fn default_accel() -> f64 {
    2000.0
}

/// Per-axis values keyed by lower-case axis name.
pub type AxisMap = BTreeMap<String, f64>;

/// Feed limits.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FeedData {
    /// Maximum cutting feed, mm/min.
    pub max_cutting: f64,
}

/// Spindle data.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SpindleData {
    /// Highest speed, rpm.
    pub max_rpm: f64,
    /// Lowest speed, rpm.
    #[serde(default)]
    pub min_rpm: f64,
}

/// Tool changer / turret.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ToolData {
    /// Number of pockets / turret stations.
    pub count: u32,
    /// Tool change or index time, seconds.
    #[serde(default)]
    pub change_time_s: f64,
    /// Hurco: offsets of a T code take effect at once (true) or with the
    /// next motion (false).
    #[serde(default = "yes")]
    pub immediate_offsets: bool,
    /// Highest tool offset number (H/D on mills, tool offsets on lathes);
    /// 128 unless the profile says otherwise.
    #[serde(default = "default_offsets")]
    pub offsets: u32,
}

fn default_offsets() -> u32 {
    128
}

fn yes() -> bool {
    true
}

/// A complete machine profile.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Profile {
    /// Name used with `--machine`.
    pub name: String,
    /// One line for `kerf machines`.
    pub description: String,
    /// Which control's language.
    pub dialect: DialectId,
    pub kind: MachineKind,
    /// "Calculator-type decimal point" input: `X100` means 100 mm (or inch)
    /// rather than 100 least input increments.
    #[serde(default)]
    pub calculator_decimal: bool,
    /// Longest block the control accepts, characters.
    #[serde(default = "default_block_chars")]
    pub max_block_chars: usize,
    /// Most digits in one number.
    #[serde(default = "default_digits")]
    pub max_digits: u8,
    /// Axes the machine has, by lower-case name (`x`, `y`, `z`, `c` …).
    pub axes: BTreeMap<String, AxisData>,
    pub feed: FeedData,
    pub spindle: SpindleData,
    pub tools: ToolData,
    /// 2nd, 3rd, 4th reference positions in machine coordinates.
    #[serde(default)]
    pub reference: BTreeMap<String, AxisMap>,
    /// Work coordinate systems: `g54` … `g59` (Hurco: `e1` …), the machine
    /// coordinates of each work zero.
    #[serde(default)]
    pub work_offsets: BTreeMap<String, AxisMap>,
    /// Control parameters the manuals name (`"PI 144" = 0`, `"PM 2097"` …).
    #[serde(default)]
    pub params: BTreeMap<String, f64>,
    /// Motion planner data (`[motion]`): read by the CLI into kerf-motion's
    /// `Dynamics` and validated there (docs/formats.md).
    #[serde(default)]
    pub motion: Option<toml::Table>,
}

fn default_block_chars() -> usize {
    256
}

fn default_digits() -> u8 {
    12
}

/// The built-in profiles: (name, TOML text).
pub const BUILTIN: &[(&str, &str)] = &[
    ("hx-mc", include_str!("../../../machines/hx-mc.toml")),
    (
        "puma-lathe",
        include_str!("../../../machines/puma-lathe.toml"),
    ),
    (
        "hurco-lathe",
        include_str!("../../../machines/hurco-lathe.toml"),
    ),
];

/// Why a profile's TOML text was refused.
#[derive(Debug, thiserror::Error)]
pub enum ProfileError {
    /// Not TOML, or not a profile's fields and types.
    #[error("{0}")]
    Toml(#[from] toml::de::Error),
    /// An `[axes.NAME]` table that is not an axis.
    #[error("unknown axis '{0}' (use x y z a b c)")]
    UnknownAxis(String),
    /// An axis whose travel or rapid rate is not usable.
    #[error("axis '{0}': need min <= max and rapid > 0")]
    BadAxis(String),
    /// A work offset or reference table naming an axis the machine lacks.
    #[error("'{table}' names axis '{axis}' the machine does not have")]
    MissingAxis {
        /// The table (`g54`, `second` …).
        table: String,
        /// The axis it names.
        axis: String,
    },
    /// `[feed] max_cutting` is not a positive number.
    #[error("feed.max_cutting must be > 0")]
    FeedMax,
}

impl Profile {
    /// Parses a profile from TOML text.
    pub fn from_toml(text: &str) -> Result<Profile, ProfileError> {
        let p: Profile = toml::from_str(text)?;
        p.validate()?;
        Ok(p)
    }

    /// A built-in profile by name.
    pub fn builtin(name: &str) -> Option<Profile> {
        BUILTIN
            .iter()
            .find(|(n, _)| *n == name)
            .map(|(_, t)| Profile::from_toml(t).expect("built-in profile is valid"))
    }

    fn validate(&self) -> Result<(), ProfileError> {
        for (k, a) in &self.axes {
            if axis_by_name(k).is_none() {
                return Err(ProfileError::UnknownAxis(k.clone()));
            }
            if a.min.is_nan()
                || a.max.is_nan()
                || a.min > a.max
                || a.rapid.is_nan()
                || a.rapid <= 0.0
            {
                return Err(ProfileError::BadAxis(k.clone()));
            }
        }
        for (w, m) in self.work_offsets.iter().chain(self.reference.iter()) {
            for k in m.keys() {
                if !self.axes.contains_key(k) {
                    return Err(ProfileError::MissingAxis {
                        table: w.clone(),
                        axis: k.clone(),
                    });
                }
            }
        }
        if self.feed.max_cutting.is_nan() || self.feed.max_cutting <= 0.0 {
            return Err(ProfileError::FeedMax);
        }
        Ok(())
    }

    /// True when the machine has this axis.
    pub fn has_axis(&self, a: Axis) -> bool {
        self.axes.contains_key(a.name())
    }

    /// Data of an axis, if the machine has it.
    pub fn axis(&self, a: Axis) -> Option<&AxisData> {
        self.axes.get(a.name())
    }

    /// A named parameter, or `default`.
    pub fn param(&self, name: &str, default: f64) -> f64 {
        self.params.get(name).copied().unwrap_or(default)
    }

    /// Converts a per-axis map to a position (missing axes 0).
    pub fn pos_of(map: &AxisMap) -> Pos {
        let mut p = [0.0; NAXES];
        for (k, v) in map {
            if let Some(a) = axis_by_name(k) {
                p[a as usize] = *v;
            }
        }
        p
    }

    /// Machine position at program start.
    pub fn start_position(&self) -> Pos {
        let mut p = [0.0; NAXES];
        for (k, a) in &self.axes {
            if let Some(ax) = axis_by_name(k) {
                p[ax as usize] = a.start.unwrap_or(a.reference);
            }
        }
        p
    }
}

/// The axis for a lower-case name.
pub fn axis_by_name(n: &str) -> Option<Axis> {
    Axis::ALL.iter().copied().find(|a| a.name() == n)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn builtin_profiles_load() {
        for (n, _) in BUILTIN {
            let p = Profile::builtin(n).unwrap();
            assert_eq!(&p.name, n);
            assert!(p.has_axis(Axis::X) && p.has_axis(Axis::Z));
        }
    }

    #[test]
    fn bad_profile_is_an_error() {
        let e = Profile::from_toml("name = 'x'").unwrap_err();
        assert!(matches!(e, ProfileError::Toml(_)), "{e:?}");
        assert!(e.to_string().contains("missing"), "{e}");
    }

    #[test]
    fn a_profile_naming_an_axis_it_lacks_is_refused() {
        let text = BUILTIN[0].1.to_string() + "\n[work_offsets.extra]\nw = 1.0\n";
        let e = Profile::from_toml(&text).unwrap_err();
        assert!(
            matches!(&e, ProfileError::MissingAxis { table, axis } if table == "extra" && axis == "w"),
            "{e:?}"
        );
        assert_eq!(
            e.to_string(),
            "'extra' names axis 'w' the machine does not have"
        );
    }
}
