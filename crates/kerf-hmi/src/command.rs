//! The commands of `POST /api/command`: `{"cmd": NAME, ...}` parsed and
//! checked into [`Command`], so the runtime behind the server only ever sees
//! well-formed values. Every way a body can be wrong is an [`ApiError`]
//! with a message naming the field.

use serde::Deserialize;

use crate::error::ApiError;
use crate::state::Mode;

/// Longest MDI entry accepted, characters.
pub const MAX_MDI_CHARS: usize = 1024;

/// Largest relative preset, mm (the counters' eight digits).
pub const MAX_PRESET: f64 = 99_999.999;

/// A checked operator command.
#[derive(Clone, Debug, PartialEq)]
pub enum Command {
    /// CYCLE START (also resumes from feed hold, M00/M01 and single block).
    CycleStart,
    /// FEED HOLD.
    FeedHold,
    /// RESET.
    Reset,
    /// The mode selector.
    Mode(Mode),
    /// Run one MDI entry (one or more blocks separated by newlines).
    Mdi(String),
    /// Program restart at a 1-based line of the main program, or at the
    /// block with a sequence number (N).
    Restart(RestartAt),
    /// Switches: each field that is `Some` is set.
    Switch(SwitchChange),
    /// Jog an axis by a distance, mm (JOG mode).
    Jog {
        /// Axis letter.
        axis: String,
        /// Signed distance, mm.
        distance: f64,
    },
    /// Manual pulse generator: `pulses` × `increment` mm (JOG mode).
    Handle {
        /// Axis letter.
        axis: String,
        /// Signed pulse count.
        pulses: i64,
        /// 0.001, 0.01 or 0.1 mm per pulse.
        increment: f64,
    },
    /// Reference return of one axis or all (REF mode).
    RefReturn(Option<String>),
    /// ORIGIN / PRESET: the relative counters of one axis (every axis
    /// when `axis` is `None`) set to `value` (0 for ORIGIN) here.
    Origin {
        /// Axis letter, or every axis.
        axis: Option<String>,
        /// The value the counter reads here, mm (lathe X a radius).
        value: f64,
    },
    /// Overrides: each field that is `Some` is set, percent.
    Override {
        /// Feed override, 0-200 %.
        feed: Option<f64>,
        /// Rapid override, 0-100 %.
        rapid: Option<f64>,
    },
}

/// Where a restart starts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RestartAt {
    /// A 1-based line of the main program.
    Line(u32),
    /// The block with this sequence number.
    Sequence(u32),
}

/// The switches one `switch` command changes.
#[derive(Clone, Debug, Default, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SwitchChange {
    /// Single block.
    pub single_block: Option<bool>,
    /// Optional stop.
    pub optional_stop: Option<bool>,
    /// Dry run.
    pub dry_run: Option<bool>,
    /// The block skip levels switched on (replaces the set).
    pub block_skip: Option<Vec<u8>>,
}

#[derive(Deserialize)]
#[serde(tag = "cmd", rename_all = "snake_case", deny_unknown_fields)]
enum Raw {
    CycleStart {},
    FeedHold {},
    Reset {},
    Mode {
        mode: Mode,
    },
    Mdi {
        block: String,
    },
    Restart {
        line: Option<u32>,
        sequence: Option<u32>,
    },
    Jog {
        axis: String,
        distance: f64,
    },
    Handle {
        axis: String,
        pulses: i64,
        increment: f64,
    },
    RefReturn {
        axis: Option<String>,
    },
    Origin {
        axis: Option<String>,
        value: Option<f64>,
    },
    Switch {
        single_block: Option<bool>,
        optional_stop: Option<bool>,
        dry_run: Option<bool>,
        block_skip: Option<Vec<u8>>,
    },
    Override {
        feed: Option<f64>,
        rapid: Option<f64>,
    },
}

/// Parses and checks a command body.
pub fn parse(body: &[u8]) -> Result<Command, ApiError> {
    let raw: Raw = crate::error::parse_json(body)?;
    let bad = |m: String| Err(ApiError::bad_request(m));
    Ok(match raw {
        Raw::CycleStart {} => Command::CycleStart,
        Raw::FeedHold {} => Command::FeedHold,
        Raw::Reset {} => Command::Reset,
        Raw::Mode { mode } => Command::Mode(mode),
        Raw::Mdi { block } => {
            if block.trim().is_empty() {
                return bad("mdi: block is empty".into());
            }
            if block.chars().count() > MAX_MDI_CHARS {
                return bad(format!("mdi: block longer than {MAX_MDI_CHARS} characters"));
            }
            Command::Mdi(block)
        }
        Raw::Restart { line, sequence } => match (line, sequence) {
            (Some(0), _) => return bad("restart: line is 1-based".into()),
            (Some(l), None) => Command::Restart(RestartAt::Line(l)),
            (None, Some(n)) => Command::Restart(RestartAt::Sequence(n)),
            _ => return bad("restart: give line or sequence (one of them)".into()),
        },
        Raw::Jog { axis, distance } => {
            if !distance.is_finite() || distance.abs() > 10_000.0 {
                return bad(format!("jog: distance {distance} mm is not within ±10000"));
            }
            Command::Jog {
                axis: axis_name(&axis)?,
                distance,
            }
        }
        Raw::Handle {
            axis,
            pulses,
            increment,
        } => Command::Handle {
            axis: axis_name(&axis)?,
            pulses,
            increment,
        },
        Raw::RefReturn { axis } => Command::RefReturn(axis.as_deref().map(axis_name).transpose()?),
        Raw::Origin { axis, value } => {
            let value = value.unwrap_or(0.0);
            if !value.is_finite() || value.abs() > MAX_PRESET {
                return bad(format!("origin: value {value} is not within ±{MAX_PRESET}"));
            }
            Command::Origin {
                axis: axis.as_deref().map(axis_name).transpose()?,
                value,
            }
        }
        Raw::Switch {
            single_block,
            optional_stop,
            dry_run,
            block_skip,
        } => {
            if let Some(levels) = &block_skip {
                if let Some(l) = levels.iter().find(|l| !(1..=9).contains(*l)) {
                    return bad(format!("switch: block_skip level {l} is not 1-9"));
                }
            }
            let c = SwitchChange {
                single_block,
                optional_stop,
                dry_run,
                block_skip,
            };
            if c == SwitchChange::default() {
                return bad(
                    "switch: give at least one of single_block, optional_stop, dry_run, block_skip"
                        .into(),
                );
            }
            Command::Switch(c)
        }
        Raw::Override { feed, rapid } => {
            if feed.is_none() && rapid.is_none() {
                return bad("override: give feed and/or rapid (percent)".into());
            }
            if let Some(f) = feed.filter(|f| !(0.0..=200.0).contains(f)) {
                return bad(format!("override: feed {f} % is not 0-200"));
            }
            if let Some(r) = rapid.filter(|r| !(0.0..=100.0).contains(r)) {
                return bad(format!("override: rapid {r} % is not 0-100"));
            }
            Command::Override { feed, rapid }
        }
    })
}

/// An axis letter, upper case.
fn axis_name(a: &str) -> Result<String, ApiError> {
    let u = a.trim().to_ascii_uppercase();
    if matches!(u.as_str(), "X" | "Y" | "Z" | "A" | "B" | "C") {
        Ok(u)
    } else {
        Err(ApiError::bad_request(format!(
            "axis '{a}': one of X Y Z A B C"
        )))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn err(body: &str) -> String {
        match parse(body.as_bytes()) {
            Err(e) => e.message,
            Ok(c) => panic!("{body} parsed as {c:?}"),
        }
    }

    #[test]
    fn every_command_of_the_contract_parses() {
        let ok = |b: &str| parse(b.as_bytes()).unwrap();
        assert_eq!(ok(r#"{"cmd":"cycle_start"}"#), Command::CycleStart);
        assert_eq!(ok(r#"{"cmd":"feed_hold"}"#), Command::FeedHold);
        assert_eq!(ok(r#"{"cmd":"reset"}"#), Command::Reset);
        assert_eq!(
            ok(r#"{"cmd":"mode","mode":"MDI"}"#),
            Command::Mode(Mode::MDI)
        );
        assert_eq!(
            ok(r#"{"cmd":"mdi","block":"G00 X10."}"#),
            Command::Mdi("G00 X10.".into())
        );
        assert_eq!(
            ok(r#"{"cmd":"restart","line":12}"#),
            Command::Restart(RestartAt::Line(12))
        );
        assert_eq!(
            ok(r#"{"cmd":"restart","sequence":40}"#),
            Command::Restart(RestartAt::Sequence(40))
        );
        assert_eq!(
            ok(r#"{"cmd":"jog","axis":"x","distance":-1.5}"#),
            Command::Jog {
                axis: "X".into(),
                distance: -1.5
            }
        );
        assert_eq!(ok(r#"{"cmd":"ref_return"}"#), Command::RefReturn(None));
        assert_eq!(
            ok(r#"{"cmd":"origin"}"#),
            Command::Origin {
                axis: None,
                value: 0.0
            }
        );
        assert_eq!(
            ok(r#"{"cmd":"origin","axis":"z","value":-12.5}"#),
            Command::Origin {
                axis: Some("Z".into()),
                value: -12.5
            }
        );
        assert_eq!(
            ok(r#"{"cmd":"switch","block_skip":[1,2]}"#),
            Command::Switch(SwitchChange {
                block_skip: Some(vec![1, 2]),
                ..Default::default()
            })
        );
        assert_eq!(
            ok(r#"{"cmd":"override","feed":120}"#),
            Command::Override {
                feed: Some(120.0),
                rapid: None
            }
        );
    }

    #[test]
    fn bad_commands_say_what_is_wrong() {
        assert!(err(r#"{"cmd":"fly"}"#).contains("unknown variant `fly`"));
        assert!(err(r#"{"mode":"MEM"}"#).contains("missing field `cmd`"));
        assert!(err(r#"{"cmd":"mode","mode":"AUTO"}"#).contains("unknown variant `AUTO`"));
        assert!(err(r#"{"cmd":"reset","x":1}"#).contains("unknown field `x`"));
        assert!(err(r#"{"cmd":"restart","line":0}"#).contains("1-based"));
        assert!(err(r#"{"cmd":"restart","line":-3}"#).contains("expected u32"));
        assert!(err(r#"{"cmd":"switch"}"#).contains("at least one"));
        assert!(err(r#"{"cmd":"restart"}"#).contains("one of them"));
        assert!(err(r#"{"cmd":"jog","axis":"Q","distance":1}"#).contains("axis 'Q'"));
        assert!(err(r#"{"cmd":"switch","block_skip":[0]}"#).contains("level 0"));
        assert!(err(r#"{"cmd":"override","feed":250}"#).contains("0-200"));
        assert!(err(r#"{"cmd":"override","rapid":101}"#).contains("0-100"));
        assert!(err(r#"{"cmd":"mdi","block":"  "}"#).contains("empty"));
        assert!(err(r#"{"cmd":"origin","value":1e6}"#).contains("±99999.999"));
        assert!(err(r#"{"cmd":"origin","axis":"W"}"#).contains("axis 'W'"));
        assert!(err("{\"cmd\":").contains("line 1"));
        assert!(err("[1,2]").contains("expected"));
    }
}
