//! Fuzz target `pipeline`: arbitrary bytes run as a main program on every
//! built-in machine, every event pushed through the motion planner (with
//! the sampler's piece queue on) until the end, an alarm or a step cap.
//! Neither the interpreter nor the planner may panic, loop or produce a
//! time that is not a finite number (issue 8: "no input makes the planner
//! loop or divide by zero").
#![no_main]

use kerf_interp::{Interp, Settings, Step};
use kerf_motion::{Dynamics, Planner};
use libfuzzer_sys::fuzz_target;

mod machines;
use machines::profiles;

/// Most canonical commands taken from one run before we stop it.
const MAX_STEPS: usize = 3_000;
/// The interpreter's own loop guard (blocks executed).
const MAX_BLOCKS: u64 = 3_000;

fn check(t: f64, what: &str) {
    assert!(t.is_finite() && t >= 0.0, "{what}: {t}");
}

fuzz_target!(|data: &[u8]| {
    for profile in profiles() {
        let settings = Settings {
            max_blocks: MAX_BLOCKS,
            ..Settings::default()
        };
        let mut it = Interp::new(profile.clone(), settings);
        it.load_main("fuzz.nc", Box::new(std::io::Cursor::new(data.to_vec())));
        // Rapid 20 m/min, 2 m/s² (1 m/s² cutting), jerk 50 m/s³, 10 m/min clamp.
        let mut present = [false; kerf_canon::NAXES];
        for (p, a) in present.iter_mut().zip(kerf_canon::Axis::ALL) {
            *p = profile.has_axis(a);
        }
        let mut d = Dynamics::uniform(present, 20_000.0 / 60.0, 2_000.0, 50_000.0, 10_000.0);
        d.lookahead = 8;
        let mut pl = Planner::new(d, it.machine_position(), it.work_position()[0]);
        pl.keep_pieces();
        for _ in 0..MAX_STEPS {
            match it.step() {
                Step::Event(e) => {
                    pl.push(&e);
                    while let Some(done) = pl.next_done() {
                        check(done.t_end, "t_end");
                    }
                    while let Some(p) = pl.next_piece() {
                        check(p.duration(), "piece duration");
                    }
                }
                Step::End | Step::Alarm(_) => break,
            }
        }
        pl.finish();
        while let Some(done) = pl.next_done() {
            check(done.t_end, "t_end");
        }
        while pl.next_piece().is_some() {}
        check(pl.now(), "cycle time");
    }
});
