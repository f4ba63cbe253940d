//! Helpers shared by the interpreter's integration tests.
#![allow(dead_code)] // each test crate uses a different subset

use kerf_interp::{run_text, Profile, Run, Settings};

pub mod gen;
pub mod lathe;

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

/// Work-coordinate end points of the motions: (kind, x, y, z), rounded.
pub fn moves(r: &Run) -> Vec<(&'static str, f64, f64, f64)> {
    use kerf_canon::Canon;
    r.events
        .iter()
        .filter_map(|e| {
            let k = match e.cmd {
                Canon::Rapid { .. } => "rapid",
                Canon::Feed { .. } => "feed",
                Canon::Arc { .. } => "arc",
                _ => return None,
            };
            let m = e.motion().unwrap();
            Some((k, round(m.to[0]), round(m.to[1]), round(m.to[2])))
        })
        .collect()
}

/// The stopping alarm's code, line and column.
pub fn alarm(r: &Run) -> (&str, u32, u32) {
    let a = r.alarm.as_ref().expect("an alarm");
    (a.code.as_str(), a.src.line, a.src.col)
}
