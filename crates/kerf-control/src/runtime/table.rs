//! The mode table: the result of every (mode, execution state, operation)
//! triple. docs/runtime.md prints it ([`markdown`]); the runtime consults
//! [`decide`] before doing anything, so a refused command changes nothing.

use super::command::Op;
use super::mode::{Execution, Mode};

use Execution as X;

/// The result of an operation in a state.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Verdict {
    /// Carried out; the execution state becomes the one given (None:
    /// unchanged).
    Allow(Option<Execution>),
    /// Refused, with the reason.
    Refuse(&'static str),
}

/// Whether a (mode, state) pair can happen at all.
pub fn reachable(m: Mode, x: Execution) -> bool {
    match m {
        Mode::Mem => true,
        Mode::Mdi => x != X::ProgramCompleted,
        Mode::Edit => matches!(x, X::Ready | X::Stopped),
        Mode::Jog | Mode::Ref => matches!(x, X::Ready | X::Active | X::Stopped),
    }
}

const RUNNING: &str = "the program is running: feed hold or RESET first";
const INTERRUPTED: &str = "a program is interrupted: cycle start continues it, RESET ends it";
const ALARM: &str = "an alarm is in force: RESET first";
const NOT_MOVING: &str = "nothing is moving";
const AUTO_ONLY: &str = "cycle start runs programs in MEM or MDI mode";
const MDI_EMPTY: &str = "nothing typed: the mdi command executes its blocks";
const MOVING: &str = "the axes are moving";

/// The result of `op` in mode `m`, state `x`.
pub fn decide(m: Mode, x: Execution, op: Op) -> Verdict {
    use Verdict::*;
    let busy = |x: Execution| -> Option<&'static str> {
        match x {
            X::Active if matches!(m, Mode::Jog | Mode::Ref) => Some(MOVING),
            X::Active | X::FeedHold => Some(RUNNING),
            X::Interrupted | X::ProgramStopped | X::OptionalStop => Some(INTERRUPTED),
            _ => None,
        }
    };
    match op {
        Op::Reset => Allow(Some(X::Ready)),
        Op::Switch | Op::Override | Op::WriteOffset => Allow(None),
        Op::Mode(to) => match busy(x) {
            Some(r) => Refuse(r),
            None if to == m => Allow(None),
            None if x == X::ProgramCompleted => Allow(Some(X::Ready)),
            None => Allow(None),
        },
        Op::CycleStart => match (m, x) {
            (Mode::Mem | Mode::Mdi, X::Active) => Refuse("already running"),
            (Mode::Mem | Mode::Mdi, X::Stopped) => Refuse(ALARM),
            (Mode::Mdi, X::Ready) => Refuse(MDI_EMPTY),
            (Mode::Mem | Mode::Mdi, _) => Allow(Some(X::Active)),
            _ => Refuse(AUTO_ONLY),
        },
        Op::FeedHold => match (m, x) {
            (Mode::Mem | Mode::Mdi, X::Active) => Allow(Some(X::FeedHold)),
            (Mode::Jog | Mode::Ref, X::Active) => Allow(Some(X::Ready)),
            _ => Refuse(NOT_MOVING),
        },
        Op::Mdi => match (m, x) {
            (Mode::Mdi, X::Ready) => Allow(Some(X::Active)),
            (Mode::Mdi, X::Stopped) => Refuse(ALARM),
            (Mode::Mdi, x) => Refuse(busy(x).unwrap_or(RUNNING)),
            _ => Refuse("select MDI mode"),
        },
        Op::Restart => match (m, x) {
            (Mode::Mem, X::Ready | X::ProgramCompleted) => Allow(Some(X::Ready)),
            (Mode::Mem, X::Stopped) => Refuse(ALARM),
            (Mode::Mem, x) => Refuse(busy(x).unwrap_or(RUNNING)),
            _ => Refuse("program restart is done in MEM mode"),
        },
        Op::Jog | Op::Handle => match (m, x) {
            (Mode::Jog, X::Ready) => Allow(Some(X::Active)),
            (Mode::Jog, X::Active) => Refuse(MOVING),
            (Mode::Jog, _) => Refuse(ALARM),
            _ => Refuse("select JOG mode"),
        },
        Op::RefReturn => match (m, x) {
            (Mode::Ref, X::Ready) => Allow(Some(X::Active)),
            (Mode::Ref, X::Active) => Refuse(MOVING),
            (Mode::Ref, _) => Refuse(ALARM),
            _ => Refuse("select REF mode"),
        },
        Op::LoadProgram => match (m, x) {
            (Mode::Edit | Mode::Mem, X::Ready | X::Stopped | X::ProgramCompleted) => {
                Allow(Some(if x == X::Stopped {
                    X::Stopped
                } else {
                    X::Ready
                }))
            }
            (Mode::Edit | Mode::Mem, x) => Refuse(busy(x).unwrap_or(RUNNING)),
            _ => Refuse("programs are loaded in EDIT or MEM mode"),
        },
        Op::WriteParameter => match (m, x) {
            (Mode::Edit | Mode::Mdi, X::Ready | X::Stopped) => Allow(None),
            (Mode::Edit | Mode::Mdi, x) => Refuse(busy(x).unwrap_or(RUNNING)),
            _ => Refuse("parameters are written in EDIT or MDI mode"),
        },
        Op::WriteVariable => match x {
            X::Active => {
                Refuse("the program is running and the interpreter reads ahead: hold or stop first")
            }
            _ => Allow(None),
        },
    }
}

/// The table as markdown: one table per mode, a row per state, a column
/// per operation; a cell is the new state, `=` (done, state unchanged)
/// or `R<n>` (refused, reason n below).
pub fn markdown() -> String {
    let ops = Op::all();
    let mut reasons: Vec<&'static str> = Vec::new();
    let mut out = String::new();
    for m in Mode::ALL {
        out.push_str(&format!("\n#### {} mode\n\n| state |", m.name()));
        for op in &ops {
            out.push_str(&format!(" {} |", op.name()));
        }
        out.push_str("\n|---|");
        for _ in &ops {
            out.push_str("---|");
        }
        out.push('\n');
        for x in Execution::ALL {
            if !reachable(m, x) {
                continue;
            }
            out.push_str(&format!("| {} |", x.name()));
            for &op in &ops {
                let cell = match decide(m, x, op) {
                    Verdict::Allow(None) => "=".to_string(),
                    Verdict::Allow(Some(n)) if n == x => "=".to_string(),
                    Verdict::Allow(Some(n)) => n.name().to_string(),
                    Verdict::Refuse(r) => {
                        let i = match reasons.iter().position(|&q| q == r) {
                            Some(i) => i,
                            None => {
                                reasons.push(r);
                                reasons.len() - 1
                            }
                        };
                        format!("R{}", i + 1)
                    }
                };
                out.push_str(&format!(" {cell} |"));
            }
            out.push('\n');
        }
    }
    out.push_str("\nReasons:\n\n");
    for (i, r) in reasons.iter().enumerate() {
        out.push_str(&format!("- R{}: {r}\n", i + 1));
    }
    out
}
