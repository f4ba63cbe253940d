//! Operating modes and execution states (the names of design.md
//! "Runtime and browser screen"; execution states are MTConnect
//! `Execution` values).

use serde::{Deserialize, Serialize};

/// The operating mode selected on the panel.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Mode {
    /// Program editing: programs are loaded, parameters written.
    #[serde(rename = "EDIT")]
    Edit,
    /// Memory (automatic) operation of the loaded program.
    #[serde(rename = "MEM")]
    Mem,
    /// Manual data input: blocks typed and executed.
    #[serde(rename = "MDI")]
    Mdi,
    /// Jog and manual pulse generator (handle).
    #[serde(rename = "JOG")]
    Jog,
    /// Manual reference (zero) return.
    #[serde(rename = "REF")]
    Ref,
}

impl Mode {
    /// Every mode, in panel order.
    pub const ALL: [Mode; 5] = [Mode::Edit, Mode::Mem, Mode::Mdi, Mode::Jog, Mode::Ref];

    /// The panel name (`"EDIT"` …).
    pub fn name(self) -> &'static str {
        match self {
            Mode::Edit => "EDIT",
            Mode::Mem => "MEM",
            Mode::Mdi => "MDI",
            Mode::Jog => "JOG",
            Mode::Ref => "REF",
        }
    }

    /// The mode for a panel name (case-insensitive).
    pub fn parse(s: &str) -> Option<Mode> {
        Mode::ALL
            .into_iter()
            .find(|m| m.name().eq_ignore_ascii_case(s.trim()))
    }
}

/// The execution state (MTConnect `Execution`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "SCREAMING_SNAKE_CASE")]
pub enum Execution {
    /// Idle, ready for a cycle start (after power-on or RESET).
    Ready,
    /// Executing: the axes move, dwell or wait for an M/S/T function.
    Active,
    /// Feed hold: the axes decelerate on the path and stand still; cycle
    /// start resumes from there.
    FeedHold,
    /// Stopped by an alarm; RESET clears it.
    Stopped,
    /// Stopped at M01 with the optional stop switch on.
    OptionalStop,
    /// Stopped at M00 (or Hurco M200 and the like).
    ProgramStopped,
    /// The program reached M02/M30 or its end.
    ProgramCompleted,
    /// Stopped at the end of a block by single block.
    Interrupted,
}

impl Execution {
    /// Every state, in the order of the contract.
    pub const ALL: [Execution; 8] = [
        Execution::Ready,
        Execution::Active,
        Execution::FeedHold,
        Execution::Stopped,
        Execution::OptionalStop,
        Execution::ProgramStopped,
        Execution::ProgramCompleted,
        Execution::Interrupted,
    ];

    /// The MTConnect name (`"READY"` …).
    pub fn name(self) -> &'static str {
        match self {
            Execution::Ready => "READY",
            Execution::Active => "ACTIVE",
            Execution::FeedHold => "FEED_HOLD",
            Execution::Stopped => "STOPPED",
            Execution::OptionalStop => "OPTIONAL_STOP",
            Execution::ProgramStopped => "PROGRAM_STOPPED",
            Execution::ProgramCompleted => "PROGRAM_COMPLETED",
            Execution::Interrupted => "INTERRUPTED",
        }
    }

    /// A program stopped between blocks that cycle start continues
    /// (M00, M01, single block).
    pub fn is_stop_between_blocks(self) -> bool {
        matches!(
            self,
            Execution::OptionalStop | Execution::ProgramStopped | Execution::Interrupted
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_serialise_as_the_contract_says() {
        for m in Mode::ALL {
            assert_eq!(
                serde_json::to_string(&m).unwrap(),
                format!("\"{}\"", m.name())
            );
            assert_eq!(Mode::parse(&m.name().to_lowercase()), Some(m));
        }
        for e in Execution::ALL {
            assert_eq!(
                serde_json::to_string(&e).unwrap(),
                format!("\"{}\"", e.name())
            );
        }
        assert_eq!(Mode::parse("AUTO"), None);
    }
}
