//! Why a program restart (000 §13.4) is refused: the block to restart at
//! does not exist or cannot be reached as a block of the main program, or
//! the re-entry move cannot be made. The message is the refusal's reason.

use super::moves::MoveError;

/// A restart the runtime refuses.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub(super) enum RestartError {
    /// No program is loaded.
    #[error("no program loaded")]
    NoProgram,
    /// No block with the sequence number.
    #[error("no block N{n} in {name}")]
    NoSequence { n: u32, name: String },
    /// A line past the end of the program.
    #[error("{name} has {lines} lines, no line {line}")]
    NoLine { name: String, lines: u32, line: u32 },
    /// An empty line.
    #[error("line {0} is empty")]
    EmptyLine(u32),
    /// The line is first read inside a call.
    #[error("line {0} is reached inside a subprogram or macro call: the control restarts in the main program")]
    InCall(u32),
    /// The line is read while compensation or a corner holds a move.
    #[error("line {0} is inside cutter / nose radius compensation or after a ,C/,R corner: restart at a block before G41/G42 or after G40")]
    InCompensation(u32),
    /// The search ran out of its block budget.
    #[error("line {line} not reached in {blocks} blocks")]
    NotReached { line: u32, blocks: u64 },
    /// The line is passed over (a G70-G73 shape, a jump).
    #[error(
        "line {0} is not executed as a block of its own (inside a G70-G73 shape, or jumped over)"
    )]
    NotABlock(u32),
    /// The program ends first.
    #[error("the program ends before line {0}")]
    EndsBefore(u32),
    /// The program alarms first.
    #[error("the program alarms at line {at} before line {line}: {code} {message}")]
    AlarmBefore {
        at: u32,
        line: u32,
        code: String,
        message: String,
    },
    /// The re-entry move.
    #[error(transparent)]
    Move(#[from] MoveError),
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn messages_name_the_line() {
        let e = RestartError::NoLine {
            name: "O1".into(),
            lines: 12,
            line: 40,
        };
        assert_eq!(e.to_string(), "O1 has 12 lines, no line 40");
        let e = RestartError::AlarmBefore {
            at: 3,
            line: 9,
            code: "F_84020".into(),
            message: "no feed".into(),
        };
        assert_eq!(
            e.to_string(),
            "the program alarms at line 3 before line 9: F_84020 no feed"
        );
        assert_eq!(RestartError::Move(MoveError::NoMove).to_string(), "no move");
    }
}
