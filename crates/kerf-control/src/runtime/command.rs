//! Operator commands (the `{"cmd": ...}` bodies of `POST /api/command`)
//! and refusals.

use serde::{Deserialize, Serialize};

use super::mode::{Execution, Mode};

/// One operator command. Serde form is the contract's JSON:
/// `{"cmd":"cycle_start"}`, `{"cmd":"mode","mode":"MEM"}`,
/// `{"cmd":"mdi","block":"G00 X10."}`, `{"cmd":"restart","line":12}`,
/// `{"cmd":"switch","single_block":true}`, `{"cmd":"switch","block_skip":[1,2]}`,
/// `{"cmd":"override","feed":120,"rapid":50}`, and the manual commands
/// `{"cmd":"jog","axis":"x","distance":-10}`,
/// `{"cmd":"handle","axis":"z","pulses":5,"increment":0.01}`,
/// `{"cmd":"ref_return"}` (all axes) or `{"cmd":"ref_return","axis":"z"}`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "cmd", rename_all = "snake_case", deny_unknown_fields)]
pub enum Command {
    /// CYCLE START: run, resume after feed hold, continue after a stop.
    CycleStart,
    /// FEED HOLD: decelerate on the path and stand still.
    FeedHold,
    /// RESET: stop everything, clear the alarm, return the modals.
    Reset,
    /// Select an operating mode.
    Mode { mode: Mode },
    /// Execute MDI text (one or more blocks) in MDI mode.
    Mdi { block: String },
    /// Program restart at a line or at a sequence number (000 §2.3.4).
    Restart {
        #[serde(default, skip_serializing_if = "Option::is_none")]
        line: Option<u32>,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        sequence: Option<u32>,
    },
    /// Switch the panel switches (those given).
    Switch {
        #[serde(default, skip_serializing_if = "Option::is_none")]
        single_block: Option<bool>,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        optional_stop: Option<bool>,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        dry_run: Option<bool>,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        block_skip: Option<Vec<u8>>,
    },
    /// Turn the override dials (those given), percent.
    Override {
        #[serde(default, skip_serializing_if = "Option::is_none")]
        feed: Option<f64>,
        #[serde(default, skip_serializing_if = "Option::is_none")]
        rapid: Option<f64>,
    },
    /// Jog an axis by a distance at the jog feed (JOG mode).
    Jog { axis: String, distance: f64 },
    /// Manual pulse generator: `pulses` × `increment` mm (0.001, 0.01, 0.1).
    Handle {
        axis: String,
        pulses: i64,
        increment: f64,
    },
    /// Reference return of one axis or all (REF mode).
    RefReturn {
        #[serde(default, skip_serializing_if = "Option::is_none")]
        axis: Option<String>,
    },
}

/// What a command is, for the mode table (docs/runtime.md).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Op {
    CycleStart,
    FeedHold,
    Reset,
    /// Select this mode.
    Mode(Mode),
    Mdi,
    Restart,
    Switch,
    Override,
    Jog,
    Handle,
    RefReturn,
    /// Load a program (`POST /api/program`).
    LoadProgram,
    /// Write a tool or work offset.
    WriteOffset,
    /// Write a parameter.
    WriteParameter,
    /// Write a macro variable.
    WriteVariable,
}

impl Op {
    /// Every operation, in the column order of the table.
    pub fn all() -> Vec<Op> {
        let mut v = vec![Op::CycleStart, Op::FeedHold, Op::Reset];
        v.extend(Mode::ALL.iter().map(|&m| Op::Mode(m)));
        v.extend([
            Op::Mdi,
            Op::Restart,
            Op::Switch,
            Op::Override,
            Op::Jog,
            Op::Handle,
            Op::RefReturn,
            Op::LoadProgram,
            Op::WriteOffset,
            Op::WriteParameter,
            Op::WriteVariable,
        ]);
        v
    }

    /// The column name.
    pub fn name(self) -> String {
        match self {
            Op::CycleStart => "cycle_start".into(),
            Op::FeedHold => "feed_hold".into(),
            Op::Reset => "reset".into(),
            Op::Mode(m) => format!("mode {}", m.name()),
            Op::Mdi => "mdi".into(),
            Op::Restart => "restart".into(),
            Op::Switch => "switch".into(),
            Op::Override => "override".into(),
            Op::Jog => "jog".into(),
            Op::Handle => "handle".into(),
            Op::RefReturn => "ref_return".into(),
            Op::LoadProgram => "load program".into(),
            Op::WriteOffset => "write offset".into(),
            Op::WriteParameter => "write parameter".into(),
            Op::WriteVariable => "write variable".into(),
        }
    }
}

impl Command {
    /// The operation of the table this command is.
    pub fn op(&self) -> Op {
        match self {
            Command::CycleStart => Op::CycleStart,
            Command::FeedHold => Op::FeedHold,
            Command::Reset => Op::Reset,
            Command::Mode { mode } => Op::Mode(*mode),
            Command::Mdi { .. } => Op::Mdi,
            Command::Restart { .. } => Op::Restart,
            Command::Switch { .. } => Op::Switch,
            Command::Override { .. } => Op::Override,
            Command::Jog { .. } => Op::Jog,
            Command::Handle { .. } => Op::Handle,
            Command::RefReturn { .. } => Op::RefReturn,
        }
    }
}

/// A command the control does not carry out, and why. Nothing of it was
/// done.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Refusal {
    /// The command (its table name).
    pub command: String,
    pub mode: Mode,
    pub execution: Execution,
    /// Why, in the operator's words.
    pub reason: String,
}

impl std::fmt::Display for Refusal {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{} refused in {} / {}: {}",
            self.command,
            self.mode.name(),
            self.execution.name(),
            self.reason
        )
    }
}

impl std::error::Error for Refusal {}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn contract_json_bodies_parse() {
        let c: Command = serde_json::from_str(r#"{"cmd":"cycle_start"}"#).unwrap();
        assert_eq!(c, Command::CycleStart);
        let c: Command = serde_json::from_str(r#"{"cmd":"mode","mode":"MDI"}"#).unwrap();
        assert_eq!(c, Command::Mode { mode: Mode::Mdi });
        let c: Command = serde_json::from_str(r#"{"cmd":"mdi","block":"G00 X10."}"#).unwrap();
        assert_eq!(
            c,
            Command::Mdi {
                block: "G00 X10.".into()
            }
        );
        let c: Command = serde_json::from_str(r#"{"cmd":"restart","line":7}"#).unwrap();
        assert_eq!(
            c,
            Command::Restart {
                line: Some(7),
                sequence: None
            }
        );
        let c: Command = serde_json::from_str(r#"{"cmd":"switch","block_skip":[1,2]}"#).unwrap();
        assert!(matches!(c, Command::Switch { block_skip: Some(ref v), .. } if v == &[1, 2]));
        let c: Command = serde_json::from_str(r#"{"cmd":"override","feed":120}"#).unwrap();
        assert_eq!(
            c,
            Command::Override {
                feed: Some(120.0),
                rapid: None
            }
        );
        assert!(serde_json::from_str::<Command>(r#"{"cmd":"mode","mode":"AUTO"}"#).is_err());
        assert!(serde_json::from_str::<Command>(r#"{"cmd":"launch"}"#).is_err());
        assert_eq!(Op::all().len(), 19);
    }
}
