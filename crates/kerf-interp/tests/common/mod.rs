//! Helpers shared by the interpreter's integration tests.
#![allow(dead_code)] // each test crate uses a different subset

use kerf_interp::{run_text, Profile, Run, Settings};

/// Runs program text on a built-in machine with default switches.
pub fn run_on(machine: &str, text: &str) -> Run {
    run_with(machine, Settings::default(), text)
}

/// Runs program text on a built-in machine with the given switches.
pub fn run_with(machine: &str, s: Settings, text: &str) -> Run {
    run_text(Profile::builtin(machine).unwrap(), s, "t.nc", text)
}

/// Rounds to 1 nm and turns -0 into 0, for exact comparisons.
pub fn round(v: f64) -> f64 {
    let r = (v * 1e6).round() / 1e6;
    if r == 0.0 {
        0.0
    } else {
        r
    }
}

/// Asserts the run ended without an alarm.
pub fn ok(r: &Run) {
    assert!(r.alarm.is_none(), "unexpected alarm {:?}", r.alarm);
}

/// Runs program text on a built-in machine with one profile parameter set
/// (loop guards, nesting limits, ...).
pub fn run_with_param(machine: &str, key: &str, value: f64, text: &str) -> Run {
    let mut p = Profile::builtin(machine).unwrap();
    p.params.insert(key.into(), value);
    run_text(p, Settings::default(), "t.nc", text)
}
