//! G96 constant surface speed: the interpreter emits a spindle event
//! before each lathe move whose end point needs another rpm (the speed
//! the spindle reaches there). The spindle follows X along the moves
//! (docs/motion.md): such a following event costs no time and does not
//! stop the motion; a new surface speed, a start or a stop is a speed
//! change as any other. Found by the outside reference
//! (tools/motion_reference.py): before, every following event stopped
//! the motion and added a ramp and a handshake. Expected times by hand.

use kerf_canon::{Canon, Event, Feed, Motion, Pos, SpindleDir, SrcRef};
use kerf_motion::{Dynamics, Planner};

// Uniform X/Z: accel 2000 mm/s² (path acceleration 1000 on an axis),
// jerk 100 000: T = 2·2000/100 000 = 0.04 s, bell: stop 2T = 0.08 s;
// ideal servo (no in-position wait); spindle 2000 rpm/s; handshake 0.1 s.
fn dynm() -> Dynamics {
    let mut d = Dynamics::uniform(
        [true, false, true, false, false, false],
        30000.0,
        2000.0,
        100_000.0,
        10000.0,
    );
    d.aux_time_s = 0.1;
    d
}

fn ev(cmd: Canon) -> Event {
    Event {
        src: SrcRef::default(),
        tool: 0,
        cmd,
        prog: None,
    }
}

fn x(v: f64) -> Pos {
    [v, 0.0, 0.0, 0.0, 0.0, 0.0]
}

fn feed(to: f64) -> Event {
    ev(Canon::Feed {
        m: Motion {
            to: x(to),
            mto: x(to),
        },
        feed: Feed::PerMin(600.0),
    })
}

fn spindle(rpm: f64, css: f64) -> Event {
    ev(Canon::Spindle {
        dir: SpindleDir::Cw,
        rpm,
        css: Some(css),
    })
}

/// rpm for surface speed `vc` m/min at radius `r` mm.
fn rpm(vc: f64, r: f64) -> f64 {
    vc * 1000.0 / (std::f64::consts::TAU * r)
}

fn run(evs: &[Event]) -> Planner {
    let mut pl = Planner::new(dynm(), x(50.0), 50.0);
    pl.max_rpm = 4000.0;
    for e in evs {
        pl.push(e);
    }
    pl.finish();
    pl
}

fn close(got: f64, want: f64) {
    assert!((got - want).abs() <= 1e-9, "got {got}, want {want}");
}

/// G96 S100 M03 at X50, then X40 and X30 at F600 (10 mm/s), each move
/// preceded by the interpreter's following event, then a dwell of 10
/// revolutions.
///
/// - start: rpm(100, 50) = 318.3099 rpm, 318.3099/2000 + 0.1 = 0.2591549 s;
/// - the two collinear moves are one run of 20 mm at 10 mm/s, path
///   acceleration 1000: 20/10 + 10/1000 = 2.01 s, then the stop 0.08 s;
/// - the dwell at the rpm in force at X30, rpm(100, 30) = 530.5165 rpm:
///   10/530.5165·60 = 1.1309734 s.
#[test]
fn css_following_events_do_not_stop_the_motion() {
    let r50 = rpm(100.0, 50.0);
    let r40 = rpm(100.0, 40.0);
    let r30 = rpm(100.0, 30.0);
    let pl = run(&[
        spindle(r50, 100.0),
        spindle(r40, 100.0),
        feed(40.0),
        spindle(r30, 100.0),
        feed(30.0),
        ev(Canon::Dwell {
            seconds: 0.0,
            revolutions: 10.0,
        }),
    ]);
    close(pl.time.other, r50 / 2000.0 + 0.1);
    close(pl.time.cutting, 2.01 + 0.08);
    close(pl.time.dwell, 10.0 / r30 * 60.0);
    close(
        pl.now(),
        0.1591549430918953 + 0.1 + 2.09 + 1.1309733552923256,
    );
}

/// A new surface speed between the moves (G96 S120) is a speed change:
/// the first move stops (10 mm: 10/10 + 0.01 = 1.01 s, stop 0.08 s), the
/// spindle ramps from the rpm in force, the last following one,
/// rpm(100, 40) = 397.8874, to rpm(120, 40) = 477.4648: 79.5775/2000 +
/// 0.1 = 0.1397887 s; then the second move alone (1.09 s).
#[test]
fn a_new_surface_speed_is_a_speed_change() {
    let pl = run(&[
        spindle(rpm(100.0, 50.0), 100.0),
        spindle(rpm(100.0, 40.0), 100.0),
        feed(40.0),
        spindle(rpm(120.0, 40.0), 120.0),
        feed(30.0),
    ]);
    close(pl.time.cutting, 2.0 * 1.09);
    close(
        pl.time.other,
        rpm(100.0, 50.0) / 2000.0 + 0.1 + (rpm(120.0, 40.0) - rpm(100.0, 40.0)) / 2000.0 + 0.1,
    );
    close(
        pl.time.other,
        0.1591549430918953 + 0.1 + 0.0397887357729738 + 0.1,
    );
}
