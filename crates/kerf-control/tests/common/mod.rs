//! Shared helpers of the runtime tests: machines with simple dynamics
//! (every axis the same limits, so the numbers can be worked by hand).
#![allow(dead_code)]

use kerf_control::runtime::{Command, Execution, Mode, Runtime};
use kerf_interp::Profile;
use kerf_motion::Dynamics;

/// Axis acceleration of the test dynamics, mm/s²; a straight cutting
/// move's path acceleration is half of it (docs/motion.md), 1000 mm/s².
pub const ACCEL: f64 = 2000.0;

/// A runtime on a built-in profile with uniform dynamics: rapid 10 m/min,
/// acceleration 2000 mm/s², jerk so high the smoothing is negligible
/// (T = 4 µs), ideal servos (no in-position wait), no M/S/T handshake.
pub fn machine(name: &str) -> Runtime {
    let profile = Profile::builtin(name).expect("built-in");
    let mut present = [false; 6];
    for a in kerf_canon::Axis::ALL {
        present[a as usize] = profile.has_axis(a);
    }
    let mut d = Dynamics::uniform(present, 10_000.0, ACCEL, 1e9, 10_000.0);
    d.tool_change_s = 2.0;
    Runtime::new(profile, d).expect("valid dynamics")
}

/// The HX machining center in MEM mode with `text` loaded.
pub fn mem(text: &str) -> Runtime {
    let mut rt = machine("hx-mc");
    rt.command(Command::Mode { mode: Mode::Mem }).unwrap();
    rt.load_program("test.nc", text).unwrap();
    rt
}

/// Machine X at the state's instant.
pub fn mx(rt: &Runtime) -> f64 {
    rt.state().position.machine["x"]
}

/// Steps in small increments until the execution state is `x` (or `max`
/// machine seconds pass); returns the machine time then.
pub fn until(rt: &mut Runtime, x: Execution, max: f64) -> f64 {
    let t0 = rt.time();
    while rt.execution() != x && rt.time() - t0 < max {
        rt.step(0.01);
    }
    assert_eq!(rt.execution(), x, "state {:?} after {max} s", rt.state());
    rt.time()
}
