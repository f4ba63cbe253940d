//! Feed functions that act on the cutter-compensated path (000 §5.3.5 G62
//! automatic corner override, §5.3.6 internal circular cutting feed
//! change). Expected times are worked by hand in the comments from the
//! motion law (docs/motion.md); none calls the planner's code.

use kerf_canon::{ArcDir, Canon, Event, Feed, ModeChange, Motion, Plane, Pos, SrcRef};
use kerf_motion::{CornerOverride, Dynamics, Planner};

const A: f64 = 2000.0; // mm/s² per axis: path acceleration A/2 = 1000 on an axis-parallel line
const J: f64 = 100_000.0; // mm/s³; T = 2·A/J = 0.04 s, two stages: stop 2T = 0.08 s

fn dynm() -> Dynamics {
    let mut d = Dynamics::uniform(
        [true, true, true, false, false, false],
        30000.0,
        A,
        J,
        10000.0,
    );
    d.path_tolerance = 0.2;
    d.corner = CornerOverride {
        angle_deg: 91.0,
        factor: 0.5,
        before: 2.0,
        after: 3.0,
        always: false,
    };
    d
}

fn p(x: f64, y: f64) -> Pos {
    [x, y, 0.0, 0.0, 0.0, 0.0]
}

/// A straight compensated move: tool centre `to`, programmed end `prog`.
fn feed(to: Pos, prog: Option<Pos>, f: f64) -> Event {
    Event {
        src: SrcRef::default(),
        tool: 0,
        cmd: Canon::Feed {
            m: Motion { to, mto: to },
            feed: Feed::PerMin(f),
        },
        prog: prog.map(Box::new),
    }
}

fn mode(m: ModeChange) -> Event {
    Event {
        src: SrcRef::default(),
        tool: 0,
        cmd: Canon::Mode(m),
        prog: None,
    }
}

fn time(d: Dynamics, start: Pos, evs: &[Event]) -> f64 {
    let mut pl = Planner::new(d, start, start[0]);
    for e in evs {
        pl.push(e);
    }
    pl.finish();
    pl.now()
}

fn close(got: f64, want: f64) {
    assert!(
        (got - want).abs() <= 1e-9 * want.max(1.0),
        "got {got}, want {want}"
    );
}

/// Programmed path (0,0) → (50,0) → (50,50) at F600 (10 mm/s), tool
/// radius 5 on the left (G41): tool centre (0,5) → (45,5) → (45,50), an
/// inside 90° corner at (45,5) for the programmed corner (50,0).
fn inside_square(f: f64) -> Vec<Event> {
    vec![
        feed(p(45.0, 5.0), Some(p(50.0, 0.0)), f),
        feed(p(45.0, 50.0), Some(p(50.0, 50.0)), f),
    ]
}

#[test]
fn g62_slows_the_inside_corner_by_hand() {
    let start = p(0.0, 5.0);
    // G64: the 90° corner is passed at the feed. Junction limits (docs/motion.md):
    // per axis (A/2)·T/1 = 40, √(1000·45) = 212; rounding
    // (0.2/√2 − T²/24·1000)/(T/6) = (0.14142 − 0.06667)/0.006667 = 11.2;
    // all above 10 mm/s. So one trapezoid 0 → 10 → 0 over 45 + 45 mm:
    // 90/10 + 10/1000 = 9.01 s, plus the stop 0.08 s.
    let g64 = time(dynm(), start, &inside_square(600.0));
    close(g64, 9.09);

    // G62: the last 2 mm before and the first 3 mm after the corner at
    // 50 % (5 mm/s). Pieces: 43 mm, 2 mm, 3 mm, 42 mm.
    //  43 mm: 0 → 10 (0.01 s, 0.05 mm), cruise, 10 → 5 (0.005 s, 0.0375 mm):
    //         0.015 + (43 − 0.0875)/10 = 4.30625 s;
    //  2 mm + 3 mm at 5 mm/s (the corner allows 11.2 as above, and
    //         √(1000·2) = 44.7 per axis): 1.0 s;
    //  42 mm: 5 → 10 (0.005 s, 0.0375 mm), cruise, 10 → 0 (0.01 s, 0.05 mm):
    //         0.015 + (42 − 0.0875)/10 = 4.20625 s.
    // Total 9.5125 s + stop 0.08 s = 9.5925 s.
    let mut evs = vec![mode(ModeChange::CornerOverride)];
    evs.extend(inside_square(600.0));
    close(time(dynm(), start, &evs), 9.5925);

    // PI 131 = 1: the same override without G62.
    let mut d = dynm();
    d.corner.always = true;
    close(time(d, start, &inside_square(600.0)), 9.5925);

    // G62 then G64 again: no override.
    let mut evs = vec![
        mode(ModeChange::CornerOverride),
        mode(ModeChange::CuttingMode),
    ];
    evs.extend(inside_square(600.0));
    close(time(dynm(), start, &evs), 9.09);
}

#[test]
fn g62_leaves_outside_corners_and_wide_angles_alone() {
    // G42 on the same programmed path: tool centre (0,-5) → (55,-5) →
    // (55,50), the corner is outside (tool centre − programmed corner =
    // (5,-5), the turn (u2 − u1) = (-1,1): negative product). No
    // override: 0 → 10 → 0 over 55 + 55 mm: 11.0 + 0.01 + 0.08 = 11.09 s.
    let evs = vec![
        mode(ModeChange::CornerOverride),
        feed(p(55.0, -5.0), Some(p(50.0, 0.0)), 600.0),
        feed(p(55.0, 50.0), Some(p(50.0, 50.0)), 600.0),
    ];
    close(time(dynm(), p(0.0, -5.0), &evs), 11.09);

    // An inside corner of 120° (a turn of 60° to the left, tool on the
    // left): above PI 130 = 91°, not overridden; with PI 130 = 130° it is.
    // Tool centre path: 40 mm along +X, then 40 mm at 60°; the
    // programmed corner is 5 mm outside the turn: (40 + 5·tan 30°, -5).
    let (c, s) = (0.5f64, 3f64.sqrt() / 2.0);
    let corner_prog = p(40.0 + 5.0 * (30f64).to_radians().tan(), -5.0);
    let evs = vec![
        mode(ModeChange::CornerOverride),
        feed(p(40.0, 0.0), Some(corner_prog), 600.0),
        feed(
            p(40.0 + 40.0 * c, 40.0 * s),
            Some(p(40.0 + 40.0 * c + 5.0 * s, 40.0 * s - 5.0 * c)),
            600.0,
        ),
    ];
    // Junction of the 60° turn: per axis du_x = 0.5, du_y = 0.866:
    // (A/2)·T/0.866 = 46.2; rounding 2·sin 30° = 1:
    // (0.2 − 0.06667)/0.006667 = 20; both above 10 mm/s, so no slowdown.
    // Path acceleration 1000 on the first move, 1000/0.866 = 1154.7 on
    // the second: 0 → 10 in 0.01 s over 0.05 mm, 10 → 0 in 10/a2 s over
    // 50/a2 mm, cruise at 10 mm/s between.
    let a2 = 1000.0 / s;
    let plain = 0.01 + 10.0 / a2 + (80.0 - 0.05 - 50.0 / a2) / 10.0 + 0.08;
    close(time(dynm(), p(0.0, 0.0), &evs), plain);
    // With PI 130 = 130°: 2 mm before at 5 mm/s, 3 mm after.
    //  38 mm: 0 → 10 → 5 at 1000: 0.015 + (38 − 0.0875)/10;
    //  5 mm at 5: 1.0 s (junction ≥ 5 as above);
    //  37 mm: 5 → 10 → 0 at 1154.7: (5 + 10)/a2 + (37 − 75/(2·a2) − 100/(2·a2))/10.
    let mut d = dynm();
    d.corner.angle_deg = 130.0;
    let want = 0.015
        + (38.0 - 0.0875) / 10.0
        + 1.0
        + 15.0 / a2
        + (37.0 - 75.0 / (2.0 * a2) - 100.0 / (2.0 * a2)) / 10.0
        + 0.08;
    close(time(d, p(0.0, 0.0), &evs), want);
}

#[test]
fn g62_without_compensation_changes_nothing() {
    // The same tool centre path with no programmed point (no cutter
    // compensation): G62 has no inside corner to find: 9.09 s as G64.
    let evs = vec![
        mode(ModeChange::CornerOverride),
        feed(p(45.0, 5.0), None, 600.0),
        feed(p(45.0, 50.0), None, 600.0),
    ];
    close(time(dynm(), p(0.0, 5.0), &evs), 9.09);
}

fn arc(to: Pos, c: Pos, prog: Option<Pos>, f: f64) -> Event {
    Event {
        src: SrcRef::default(),
        tool: 0,
        cmd: Canon::Arc {
            m: Motion { to, mto: to },
            center: c,
            mcenter: c,
            dir: ArcDir::Ccw,
            plane: Plane::XY,
            turns: 0,
            feed: Feed::PerMin(f),
        },
        prog: prog.map(Box::new),
    }
}

#[test]
fn internal_arc_feed_is_f_times_rc_over_rp() {
    // Programmed half circle of radius Rp = 20 CCW about the origin, tool
    // radius 5 on the left (G41): inside, tool centre radius Rc = 15,
    // from (15,0) to (-15,0), programmed end (-20,0). F1200 = 20 mm/s.
    // Arc limits (docs/motion.md, R = 15): √(1000·15) = 122,
    // ∛(50000·225) = 224, √(24·15·0.2/(2·0.04²)) = 150: all above the feed.
    let mut d = dynm();
    d.internal_arc_min = Some(0.1);
    let start = p(15.0, 0.0);
    let ev = arc(p(-15.0, 0.0), p(0.0, 0.0), Some(p(-20.0, 0.0)), 1200.0);
    let len = 15.0 * std::f64::consts::PI;
    // Feed 20·15/20 = 15 mm/s, path acceleration 1000: len/15 + 15/1000 + 2T.
    close(
        time(d.clone(), start, std::slice::from_ref(&ev)),
        len / 15.0 + 0.015 + 0.08,
    );
    // Lower limit PI 132 = 80 %: Rc/Rp = 0.75 is raised to 0.8: 16 mm/s.
    d.internal_arc_min = Some(0.8);
    close(
        time(d.clone(), start, std::slice::from_ref(&ev)),
        len / 16.0 + 0.016 + 0.08,
    );
    // Off (a lathe profile without the key): the tool centre runs at F.
    d.internal_arc_min = None;
    close(time(d.clone(), start, &[ev]), len / 20.0 + 0.02 + 0.08);
    // Outside (G42: Rc = 25 > Rp = 20): the tool centre runs at F.
    d.internal_arc_min = Some(0.1);
    let out = arc(p(-25.0, 0.0), p(0.0, 0.0), Some(p(-20.0, 0.0)), 1200.0);
    let len = 25.0 * std::f64::consts::PI;
    close(time(d, p(25.0, 0.0), &[out]), len / 20.0 + 0.02 + 0.08);
}

#[test]
fn degenerate_compensated_input_does_not_divide_by_zero() {
    // Programmed point on the centre (Rp = 0), zero-length moves, a
    // reversal at an inside "corner": finite times, no panic.
    let mut d = dynm();
    d.internal_arc_min = Some(0.1);
    d.corner.always = true;
    let evs = vec![
        arc(p(-15.0, 0.0), p(0.0, 0.0), Some(p(0.0, 0.0)), 1200.0),
        feed(p(-15.0, 0.0), Some(p(-20.0, 0.0)), 600.0),
        feed(p(-15.0, 10.0), Some(p(-20.0, 10.0)), 600.0),
        feed(p(-15.0, 0.0), Some(p(-20.0, 0.0)), 600.0),
    ];
    let t = time(d, p(15.0, 0.0), &evs);
    assert!(t.is_finite() && t > 0.0, "{t}");
}
