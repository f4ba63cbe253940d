//! kerf-interp: executes NC part programs as the real control would.
//!
//! The [`Interp`] is a resumable step machine: each [`Interp::step`] call
//! reads and executes blocks until it has the next canonical command
//! ([`kerf_canon::Event`]), an alarm, or the end. A batch run is a loop over
//! `step()`; single block, feed hold and the like fall out of that shape.
//! [`Interp::step_into`] runs the same loop a batch at a time, the events
//! pushed straight onto the caller's vector.
//!
//! Module map:
//! - [`dialect`]: per-control G/M tables and language switches (data);
//! - [`machine`]: machine profiles (TOML) and the built-in ones;
//! - [`interp`]: the step machine, modal state, motion, coordinates;
//!   its `calls` part holds the program store and the call stack (M98/M99,
//!   G65, `--lib` folders);
//! - [`words`]: a block's evaluated words in fixed tables;
//! - `arc`, `comp`, `corner`, `rotary`, `stroke`, `turning`, `xform`:
//!   the pure geometry, re-exported from the kerf-geom crate;
//! - [`macros`]: variables and expression evaluation;
//! - [`state`]: retained variables kept across runs (`--state DIR`);
//! - [`alarms`]: every alarm and its code per control.

// Axis arithmetic indexes several parallel position arrays by slot.
#![allow(clippy::needless_range_loop)]

pub mod alarms;
pub mod dialect;
pub mod interp;
pub mod machine;
pub mod macros;
pub mod offsets;
pub mod state;
pub mod words;

// The pure geometry lives in kerf-geom; these paths keep `crate::arc` …
// resolving for the interpreter modules.
pub use kerf_geom::{arc, comp, corner, rotary, stroke, turning, xform};

pub use dialect::{Dialect, DialectId};
pub use interp::{BlockStep, Filled, Interp, InterpSnapshot, MacroSwitches, Settings, Step};
pub use machine::{MachineKind, Profile};

use kerf_canon::{Alarm, Event};

/// The outcome of running a whole program in memory (tests, tools).
#[derive(Debug)]
pub struct Run {
    /// Every canonical command in execution order.
    pub events: Vec<Event>,
    /// The alarm that stopped the run, if any.
    pub alarm: Option<Alarm>,
    /// Blocks executed.
    pub blocks: u64,
}

/// Runs program text to its end on a built-in or given profile.
pub fn run_text(profile: Profile, settings: Settings, name: &str, text: &str) -> Run {
    run_interp(Interp::new(profile, settings), name, text)
}

/// Runs program text to its end on an interpreter the caller has prepared
/// (offset memory, variables, ...), collecting every event.
pub fn run_interp(mut it: Interp, name: &str, text: &str) -> Run {
    it.load_main(
        name,
        Box::new(std::io::Cursor::new(text.as_bytes().to_vec())),
    );
    let mut events = Vec::new();
    loop {
        match it.step() {
            Step::Event(e) => events.push(e),
            Step::End => {
                return Run {
                    events,
                    alarm: None,
                    blocks: it.blocks(),
                }
            }
            Step::Alarm(a) => {
                return Run {
                    events,
                    alarm: Some(a),
                    blocks: it.blocks(),
                }
            }
        }
    }
}
