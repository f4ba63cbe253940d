//! Cycle time against an independent computation, and the sampled
//! command against the path and the limits.
//!
//! The references here do not call the planner's code: single moves use
//! the closed-form trapezoid written out below; chains of segments are
//! integrated with a forward-Euler step of 10 µs under the speed limits
//! the motion law (docs/motion.md) gives (cruise limit, junction limit,
//! braking curves), and the sampled command is checked against geometry
//! computed here.

use kerf_canon::{ArcDir, Canon, Event, Feed, ModeChange, Motion, Plane, Pos, SpindleDir, SrcRef};
use kerf_motion::{Dynamics, Planner, Sampler};

const A: f64 = 2000.0; // mm/s² per axis
const J: f64 = 100_000.0; // mm/s³
const TOL: f64 = 0.05; // mm
                       // T = 2·rapid_accel/jerk = 0.04 s, two stages (bell).
const T: f64 = 0.04;

fn dynm() -> Dynamics {
    let mut d = Dynamics::uniform(
        [true, true, true, false, false, false],
        30000.0,
        A,
        J,
        10000.0,
    );
    d.path_tolerance = TOL;
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

fn p(x: f64, y: f64) -> Pos {
    [x, y, 0.0, 0.0, 0.0, 0.0]
}

fn feed(x: f64, y: f64, f: f64) -> Canon {
    Canon::Feed {
        m: Motion {
            to: p(x, y),
            mto: p(x, y),
        },
        feed: Feed::PerMin(f),
    }
}

/// Runs events from the origin; returns the cycle time and the samples.
fn run(cmds: &[Canon], d: Dynamics, dt: Option<f64>) -> (f64, Vec<(f64, Pos)>) {
    let mut pl = Planner::new(d, [0.0; 6], 0.0);
    let mut samples = Vec::new();
    let mut sm = dt.map(|dt| {
        pl.keep_pieces();
        Sampler::new(dt, pl.stages(), pl.smoothing_time(), [0.0; 6])
    });
    for c in cmds {
        pl.push(&ev(c.clone()));
    }
    pl.push(&ev(Canon::End { code: 30 }));
    pl.finish();
    if let Some(s) = sm.as_mut() {
        let mut end = 0.0;
        while let Some(pc) = pl.next_piece() {
            end = pc.t0 + pc.duration();
            s.add(pc);
        }
        s.run(end, &mut |t, q| samples.push((t, *q)));
    }
    (pl.now(), samples)
}

/// Closed-form trapezoid from rest to rest.
fn trap_time(len: f64, v: f64, a: f64) -> f64 {
    if len >= v * v / a {
        len / v + v / a
    } else {
        2.0 * (len / a).sqrt()
    }
}

fn close(got: f64, want: f64, rel: f64) {
    assert!(
        (got - want).abs() <= rel * want,
        "got {got}, want {want} (±{:.2} %)",
        rel * 100.0
    );
}

/// Forward-Euler path-speed integration over a chain of segments:
/// `segs` = (length, cruise limit, path acceleration), `junctions[k]` the
/// speed limit between segment k and k+1. Starts and ends at rest.
fn euler(segs: &[(f64, f64, f64)], junctions: &[f64]) -> f64 {
    let n = segs.len();
    // Limit at the end of each segment (0 at the end of the chain), then
    // the braking bound: what can still slow down to every later limit.
    let mut w_end = vec![0.0; n];
    w_end[..n - 1].copy_from_slice(&junctions[..n - 1]);
    for k in (0..n - 1).rev() {
        let (l, _, a) = segs[k + 1];
        w_end[k] = w_end[k].min((w_end[k + 1] * w_end[k + 1] + 2.0 * a * l).sqrt());
    }
    let dt = 1e-5;
    let (mut t, mut v) = (0.0, 0.0);
    for k in 0..n {
        let (l, vmax, a) = segs[k];
        let mut s = 0.0;
        while s < l {
            let allow = vmax.min((w_end[k] * w_end[k] + 2.0 * a * (l - s).max(0.0)).sqrt());
            let nv = (v + a * dt).min(allow);
            // Trapezoidal rule for the distance of this step.
            let ds = 0.5 * (v + nv) * dt;
            if s + ds >= l {
                let frac = if ds > 0.0 { (l - s) / ds } else { 1.0 };
                t += frac * dt;
                v = nv;
                break;
            }
            s += ds;
            v = nv;
            t += dt;
        }
    }
    t
}

/// The junction limit of docs/motion.md for two straight XY segments with
/// unit directions u1, u2, the shorter length `lmin`, feed f (mm/s) and the
/// larger path acceleration `acc`; `None` = exact stop.
fn junction(u1: (f64, f64), u2: (f64, f64), lmin: f64, f: f64, acc: f64) -> Option<f64> {
    let mut v = f;
    for du in [(u2.0 - u1.0).abs(), (u2.1 - u1.1).abs()] {
        if du > 1e-9 {
            v = v.min(0.5 * A * T / du).min((0.5 * A * lmin / du).sqrt());
        }
    }
    let c = (u1.0 * u2.0 + u1.1 * u2.1).clamp(-1.0, 1.0);
    // Corner-to-rounded-path distance factor 2·sin(θ/2).
    let s = 2.0 * (c.acos() / 2.0).sin();
    if s > 1e-9 {
        let room = TOL / s - T * T / 24.0 * acc;
        if room <= 0.0 {
            return None;
        }
        v = v.min(room / (T / 6.0));
    }
    let th = c.acos();
    if th > 1e-9 {
        v = v.min((24.0 * (lmin / th) * TOL / (2.0 * T * T)).sqrt());
    }
    Some(v)
}

#[test]
fn single_lines_closed_form() {
    // (dx, dy, F mm/min): long, short (triangle), diagonal.
    for (dx, dy, f) in [
        (100.0, 0.0, 3000.0),
        (0.5, 0.0, 3000.0),
        (60.0, 80.0, 6000.0),
        (10.0, 3.0, 9000.0),
    ] {
        let (t, _) = run(&[feed(dx, dy, f)], dynm(), None);
        let len = (dx * dx + dy * dy).sqrt();
        let umax = (dx / len).abs().max((dy / len).abs());
        let a = 0.5 * A / umax;
        let want = trap_time(len, f / 60.0, a) + 2.0 * T;
        close(t, want, 0.005);
    }
}

fn corner_program(angle_deg: f64, f: f64) -> (Vec<Canon>, (f64, f64), (f64, f64)) {
    // 40 mm along +X, then 40 mm turning by `angle_deg`.
    let th = angle_deg.to_radians();
    let u2 = (th.cos(), th.sin());
    let c = vec![feed(40.0, 0.0, f), feed(40.0 + 40.0 * u2.0, 40.0 * u2.1, f)];
    (c, (1.0, 0.0), u2)
}

#[test]
fn corners_10_to_170_degrees_against_euler() {
    // Every 10° step, and 45°/135°.
    let angles = (1..=17).map(|k| k as f64 * 10.0).chain([45.0, 135.0]);
    for deg in angles {
        let f = 3000.0;
        let (cmds, u1, u2) = corner_program(deg, f);
        let (t, _) = run(&cmds, dynm(), None);
        let a1 = 0.5 * A;
        let a2 = 0.5 * A / u2.0.abs().max(u2.1.abs());
        let (s1, s2) = ((40.0, f / 60.0, a1), (40.0, f / 60.0, a2));
        let want = match junction(u1, u2, 40.0, f / 60.0, a1.max(a2)) {
            Some(vj) => euler(&[s1, s2], &[vj]) + 2.0 * T,
            None => euler(&[s1], &[]) + euler(&[s2], &[]) + 4.0 * T,
        };
        close(t, want, 0.005);
    }
}

#[test]
fn exact_stop_versus_cutting_mode() {
    let f = 2400.0;
    let square = [
        feed(30.0, 0.0, f),
        feed(30.0, 30.0, f),
        feed(0.0, 30.0, f),
        feed(0.0, 0.0, f),
    ];
    // G61: four moves from rest to rest, each followed by a stop of 2T.
    let mut g61 = vec![Canon::Mode(ModeChange::ExactStopMode(true))];
    g61.extend(square.iter().cloned());
    let (t61, _) = run(&g61, dynm(), None);
    close(
        t61,
        4.0 * (trap_time(30.0, f / 60.0, 0.5 * A) + 2.0 * T),
        0.005,
    );
    // G64: one chain with three 90° junctions. With 0.05 mm the smoothing
    // of the braking alone (A·T²/24·√2 = 0.094 mm) would leave the
    // tolerance and the corners would stop; with 0.2 mm they are passed at
    // speed.
    let mut d = dynm();
    d.path_tolerance = 0.2;
    let (t64, _) = run(&square, d.clone(), None);
    let vj = {
        let room = 0.2 / 2f64.sqrt() - T * T / 24.0 * 0.5 * A;
        (f / 60.0)
            .min(0.5 * A * T)
            .min((0.5 * A * 30.0).sqrt())
            .min(room / (T / 6.0))
            .min((24.0 * (30.0 / std::f64::consts::FRAC_PI_2) * 0.2 / (2.0 * T * T)).sqrt())
    };
    let seg = (30.0, f / 60.0, 0.5 * A);
    let want = euler(&[seg, seg, seg, seg], &[vj, vj, vj]) + 2.0 * T;
    close(t64, want, 0.005);
    assert!(t64 < t61);
    // G09 on the second block only: two chains.
    let mut g09 = vec![square[0].clone(), Canon::Mode(ModeChange::ExactStopBlock)];
    g09.extend(square[1..].iter().cloned());
    let (t09, _) = run(&g09, d, None);
    let want = euler(&[seg, seg], &[vj]) + euler(&[seg, seg], &[vj]) + 4.0 * T;
    close(t09, want, 0.005);
}

fn arc(to: (f64, f64), c: (f64, f64), f: f64) -> Canon {
    Canon::Arc {
        m: Motion {
            to: p(to.0, to.1),
            mto: p(to.0, to.1),
        },
        center: p(c.0, c.1),
        mcenter: p(c.0, c.1),
        dir: ArcDir::Ccw,
        plane: Plane::XY,
        turns: 0,
        feed: Feed::PerMin(f),
    }
}

#[test]
fn arcs_of_several_radii() {
    for r in [0.5, 2.0, 10.0, 50.0] {
        let f = 6000.0;
        // Half circle from (0,0) about (r,0) to (2r,0).
        let (t, _) = run(&[arc((2.0 * r, 0.0), (r, 0.0), f)], dynm(), None);
        let v = (f / 60.0)
            .min((0.5 * A * r).sqrt())
            .min((0.5 * J * r * r).cbrt())
            .min((24.0 * r * TOL / (2.0 * T * T)).sqrt());
        let len = std::f64::consts::PI * r;
        close(t, trap_time(len, v, 0.5 * A) + 2.0 * T, 0.005);
    }
}

#[test]
fn per_rev_feed_with_css() {
    // Lathe facing from X50 to X5 (radius) at 0.2 mm/rev, 200 m/min,
    // spindle clamped at 3000 rpm.
    let mut d = Dynamics::uniform(
        [true, false, true, false, false, false],
        20000.0,
        A,
        J,
        10000.0,
    );
    d.path_tolerance = TOL;
    d.spindle_accel = 1e9;
    let mut pl = Planner::new(d, [50.0, 0.0, 0.0, 0.0, 0.0, 0.0], 50.0);
    pl.max_rpm = 3000.0;
    pl.push(&ev(Canon::Spindle {
        dir: SpindleDir::Cw,
        rpm: 636.6,
        css: Some(200.0),
    }));
    let to = [5.0, 0.0, 0.0, 0.0, 0.0, 0.0];
    pl.push(&ev(Canon::Feed {
        m: Motion { to, mto: to },
        feed: Feed::PerRev(0.2),
    }));
    pl.finish();
    // Independent: ∫ dx / v(x), v = 0.2 · min(3000, 200000/(2πx)) / 60,
    // by the midpoint rule on 100 000 steps; plus the stop 2T; the
    // ramps at ≤ 0.2·3000/60 = 10 mm/s with 1000 mm/s² cost < 0.01 s.
    let n = 100_000;
    let h = 45.0 / n as f64;
    let mut want = 0.0;
    for k in 0..n {
        let x = 5.0 + (k as f64 + 0.5) * h;
        let rpm = (200_000.0 / (std::f64::consts::TAU * x)).min(3000.0);
        want += h / (0.2 * rpm / 60.0);
    }
    want += 2.0 * T;
    close(pl.time.cutting, want, 0.005);
}

/// Distance from q to the segment a-b (XY).
fn seg_dist(q: &Pos, a: (f64, f64), b: (f64, f64)) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let l2 = dx * dx + dy * dy;
    let u = if l2 > 0.0 {
        (((q[0] - a.0) * dx + (q[1] - a.1) * dy) / l2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (q[0] - a.0 - u * dx).hypot(q[1] - a.1 - u * dy)
}

/// Largest per-axis |v|, |a|, |j| over the samples (finite differences).
fn derivs(s: &[(f64, Pos)], dt: f64) -> [f64; 3] {
    let mut m = [0.0f64; 3];
    for w in s.windows(4) {
        for i in 0..3 {
            let x: Vec<f64> = w.iter().map(|(_, q)| q[i]).collect();
            let v = (x[1] - x[0]) / dt;
            let a = (x[2] - 2.0 * x[1] + x[0]) / (dt * dt);
            let j = (x[3] - 3.0 * x[2] + 3.0 * x[1] - x[0]) / (dt * dt * dt);
            m[0] = m[0].max(v.abs());
            m[1] = m[1].max(a.abs());
            m[2] = m[2].max(j.abs());
        }
    }
    m
}

#[test]
fn sampled_corners_stay_on_path_and_within_limits() {
    let dt = 0.001;
    let angles = (1..=17).map(|k| k as f64 * 10.0).chain([5.0, 45.0, 135.0]);
    for deg in angles {
        let f = 6000.0;
        let (cmds, _, u2) = corner_program(deg, f);
        let (_, s) = run(&cmds, dynm(), Some(dt));
        let (a, b, c) = ((0.0, 0.0), (40.0, 0.0), (40.0 + 40.0 * u2.0, 40.0 * u2.1));
        let dev = s
            .iter()
            .map(|(_, q)| seg_dist(q, a, b).min(seg_dist(q, b, c)))
            .fold(0.0, f64::max);
        assert!(dev <= TOL, "{deg}°: path deviation {dev} mm");
        // And the path comes within the tolerance of the corner.
        // (distance from the corner to the polyline through the samples)
        let reach = s
            .windows(2)
            .map(|w| {
                seg_dist(
                    &[b.0, b.1, 0.0, 0.0, 0.0, 0.0],
                    (w[0].1[0], w[0].1[1]),
                    (w[1].1[0], w[1].1[1]),
                )
            })
            .fold(f64::MAX, f64::min);
        assert!(reach <= TOL, "{deg}°: corner missed by {reach} mm");
        let [v, acc, j] = derivs(&s, dt);
        assert!(v <= f / 60.0 * 1.0001, "{deg}°: axis speed {v}");
        assert!(acc <= A * 1.0001, "{deg}°: axis acceleration {acc}");
        assert!(j <= J * 1.0001, "{deg}°: axis jerk {j}");
        // The end point is reached.
        let last = s.last().unwrap().1;
        assert!((last[0] - c.0).abs() < 1e-9 && (last[1] - c.1).abs() < 1e-9);
    }
}

#[test]
fn sampled_arcs_stay_on_path_and_within_limits() {
    let dt = 0.001;
    for r in [2.0, 10.0, 50.0] {
        let (_, s) = run(&[arc((2.0 * r, 0.0), (r, 0.0), 6000.0)], dynm(), Some(dt));
        let dev = s
            .iter()
            .map(|(_, q)| ((q[0] - r).hypot(q[1]) - r).abs())
            .fold(0.0, f64::max);
        assert!(dev <= TOL, "r {r}: radial deviation {dev} mm");
        let [v, acc, j] = derivs(&s, dt);
        assert!(v <= 100.0 * 1.0001, "r {r}: axis speed {v}");
        assert!(acc <= A * 1.0001, "r {r}: axis acceleration {acc}");
        assert!(j <= J * 1.0001, "r {r}: axis jerk {j}");
    }
}

/// The in-position wait by numeric integration, independent of the
/// planner's closed form: the position loop `dx/dt = K·(c − x)` of every
/// axis driven by the sampled smoothed command `c` (integrated exactly
/// for `c` linear between samples), continued at the end point until
/// every axis's error is within `w`; returns that moment minus the last
/// sample's time (the command's arrival).
fn servo_wait(s: &[(f64, Pos)], dt: f64, k: f64, w: f64) -> f64 {
    let e = (-k * dt).exp();
    let mut x = s[0].1;
    for win in s.windows(2) {
        let (c0, c1) = (win[0].1, win[1].1);
        for i in 0..6 {
            let slope = (c1[i] - c0[i]) / dt;
            // x(dt) = c1 − slope/K + (x0 − c0 + slope/K)·e^(−K·dt)
            x[i] = c1[i] - slope / k + (x[i] - c0[i] + slope / k) * e;
        }
    }
    let end = s.last().unwrap().1;
    let err = |x: &Pos| (0..6).map(|i| (end[i] - x[i]).abs()).fold(0.0, f64::max);
    let h = 1e-6;
    let eh = (-k * h).exp();
    let mut t = 0.0;
    let mut prev = err(&x);
    while prev > w {
        for i in 0..6 {
            x[i] = end[i] + (x[i] - end[i]) * eh;
        }
        let now = err(&x);
        t += h;
        if now <= w {
            // Linear interpolation inside the last step.
            t -= h * (w - now) / (prev - now);
            break;
        }
        prev = now;
        assert!(t < 10.0, "no settling");
    }
    t
}

#[test]
fn in_position_wait_by_hand() {
    // X 20 mm at F1200 (20 mm/s), path acceleration A/2 = 1000 mm/s²,
    // T = 0.04 s (two stages), position gain K = 30/s, width 0.01 mm.
    // In the cruise the loop lags v/K = 0.666667 mm; braking 0.02 s
    // (x = K·0.02 = 0.6, E = e^-0.6 = 0.548812):
    // 0.666667·E + 20·(1 − E)/30 − 1000·(0.6 − (1 − E))/900 = 0.501320 mm.
    // When the smoothed command arrives the error is that times
    // ((1 − e^-1.2)/1.2)² = 0.339118: 0.170007 mm; it decays as e^(−30 t)
    // to 0.01 mm in ln(17.0007)/30 = 0.094442 s.
    let mut d = dynm();
    d.position_gain = 30.0;
    let (t, _) = run(&[feed(20.0, 0.0, 1200.0)], d, None);
    let want = trap_time(20.0, 20.0, 1000.0) + 2.0 * T + 0.094442;
    assert!((t - want).abs() < 2e-6, "{t} vs {want}");
    // An ideal servo (infinite gain) waits nothing.
    let (t, _) = run(&[feed(20.0, 0.0, 1200.0)], dynm(), None);
    assert!((t - (want - 0.094442)).abs() < 1e-12);
}

/// Half a turn of radius 10 about (10, 0) from the origin, rising 8 mm.
fn helix_from_origin() -> Canon {
    let to = [20.0, 0.0, 8.0, 0.0, 0.0, 0.0];
    Canon::Arc {
        m: Motion { to, mto: to },
        center: p(10.0, 0.0),
        mcenter: p(10.0, 0.0),
        dir: ArcDir::Ccw,
        plane: Plane::XY,
        turns: 0,
        feed: Feed::PerMin(3000.0),
    }
}

#[test]
fn in_position_wait_against_numeric_servo() {
    const K: f64 = 30.0;
    const W: f64 = 0.01;
    let dt = 1e-4;
    let square = vec![
        feed(30.0, 0.0, 2400.0),
        feed(30.0, 30.0, 2400.0),
        feed(0.0, 30.0, 2400.0),
        feed(0.0, 0.0, 2400.0),
    ];
    let rapid = Canon::Rapid {
        m: Motion {
            to: p(100.0, 30.0),
            mto: p(100.0, 30.0),
        },
        linear: false,
    };
    let cases: Vec<(&str, Vec<Canon>)> = vec![
        ("line", vec![feed(20.0, 0.0, 1200.0)]),
        ("diagonal", vec![feed(30.0, 40.0, 3000.0)]),
        ("short", vec![feed(0.3, 0.0, 3000.0)]),
        ("square", square),
        ("half circle", vec![arc((20.0, 0.0), (10.0, 0.0), 3000.0)]),
        (
            "quarter circle r 40",
            vec![arc((40.0, 40.0), (40.0, 0.0), 4800.0)],
        ),
        ("helix", vec![helix_from_origin()]),
        ("rapid", vec![rapid]),
    ];
    for (name, cmds) in cases {
        let mut d = dynm();
        d.path_tolerance = 0.2;
        let (ideal, s) = run(&cmds, d.clone(), Some(dt));
        d.position_gain = K;
        for w in d.in_position.iter_mut() {
            *w = W;
        }
        let (with_servo, _) = run(&cmds, d, None);
        let want = servo_wait(&s, dt, K, W);
        let got = with_servo - ideal;
        // The wait is tens of ms: within 1 % of it (0.3 ms), the cycle
        // time within 0.5 %.
        assert!(
            (got - want).abs() <= 0.01 * want,
            "{name}: wait {got} s, numeric {want} s"
        );
        close(with_servo, ideal + want, 0.005);
    }
}

#[test]
fn css_facing_under_the_g50_clamp_by_hand() {
    // PUMA-style facing under G96: radius 40 → 5 mm at 0.2 mm/rev,
    // Vc = 200 m/min, machine limit 3000 rpm, program clamp G50 S2000.
    // rpm(x) = 200000/(2π·x), clamped at 2000 below
    // x_c = 200000/(2π·2000) = 15.9155 mm. Time = ∫ dx / (0.2·rpm/60):
    //  x in [x_c, 40]: ∫ 60·2π·x/(0.2·200000) dx = 0.0094248·(40² − x_c²)/2
    //                 = 0.0094248·673.35 = 6.3462 s;
    //  x in [5, x_c]:  (15.9155 − 5)/(0.2·2000/60) = 1.6373 s;
    // 7.9835 s, plus the stop 2T = 0.08 s. Without the clamp (3000 rpm,
    // x_c' = 10.6103): 0.0094248·(1600 − 112.58)/2 + 5.6103/10 = 7.5703 s.
    let x_c = 200_000.0 / (std::f64::consts::TAU * 2000.0);
    let clamped = 0.0094248 * (1600.0 - x_c * x_c) / 2.0 + (x_c - 5.0) / (0.2 * 2000.0 / 60.0);
    assert!((clamped - 7.9835).abs() < 1e-3, "{clamped}");
    for (clamp, want) in [(Some(2000.0), 7.9835 + 2.0 * T), (None, 7.5703 + 2.0 * T)] {
        let mut d = Dynamics::uniform(
            [true, false, true, false, false, false],
            20000.0,
            A,
            J,
            10000.0,
        );
        d.path_tolerance = TOL;
        d.spindle_accel = 1e9;
        // Start at radius 60 and position to 40 at rapid first: the facing
        // starts from the rapid's end (the rapid's time is not cutting).
        let mut pl = Planner::new(d, [60.0, 0.0, 0.0, 0.0, 0.0, 0.0], 60.0);
        pl.max_rpm = 3000.0;
        let at40 = [40.0, 0.0, 0.0, 0.0, 0.0, 0.0];
        pl.push(&ev(Canon::Rapid {
            m: Motion {
                to: at40,
                mto: at40,
            },
            linear: false,
        }));
        if let Some(c) = clamp {
            pl.push(&ev(Canon::Mode(ModeChange::SpindleClamp(c))));
        }
        pl.push(&ev(Canon::Spindle {
            dir: SpindleDir::Cw,
            rpm: 795.8,
            css: Some(200.0),
        }));
        let to = [5.0, 0.0, 0.0, 0.0, 0.0, 0.0];
        pl.push(&ev(Canon::Feed {
            m: Motion { to, mto: to },
            feed: Feed::PerRev(0.2),
        }));
        pl.finish();
        // The ramps between the 16 pieces (≤ 6.7 mm/s at 1000 mm/s²) add
        // a few ms: within 0.5 %.
        close(pl.time.cutting, want, 0.005);
    }
}

/// A CCW helix from (r, 0, 0) about the origin through `sweep_deg`,
/// rising `dz`.
fn helix(r: f64, sweep_deg: f64, dz: f64, f: f64) -> Canon {
    let th = sweep_deg.to_radians();
    let to = [r * th.cos(), r * th.sin(), dz, 0.0, 0.0, 0.0];
    Canon::Arc {
        m: Motion { to, mto: to },
        center: p(0.0, 0.0),
        mcenter: p(0.0, 0.0),
        dir: ArcDir::Ccw,
        plane: Plane::XY,
        turns: 0,
        feed: Feed::PerMin(f),
    }
}

fn run_from(start: Pos, cmds: &[Canon], dt: f64) -> (f64, Vec<(f64, Pos)>) {
    let mut pl = Planner::new(dynm(), start, start[0]);
    pl.keep_pieces();
    let mut sm = Sampler::new(dt, pl.stages(), pl.smoothing_time(), start);
    for c in cmds {
        pl.push(&ev(c.clone()));
    }
    pl.finish();
    let mut end = 0.0;
    while let Some(pc) = pl.next_piece() {
        end = pc.t0 + pc.duration();
        sm.add(pc);
    }
    let mut out = Vec::new();
    sm.run(end, &mut |t, q| out.push((t, *q)));
    (pl.now(), out)
}

#[test]
fn helical_arcs_closed_form_and_on_the_helix() {
    // Helices of radius 5, 20 and 40 through 270°, rising 10 mm, at
    // F6000 (100 mm/s). Motion law (docs/motion.md): path acceleration
    // A/2 = 1000; cruise limit min(F, √(A/2·R), ∛(J/2·R²),
    // √(24·R·tol/(2T²))) with the plane radius R; length
    // √((R·θ)² + dz²); one trapezoid from rest to rest plus 2T.
    let dt = 0.001;
    for r in [5.0, 20.0, 40.0] {
        let c = helix(r, 270.0, 10.0, 6000.0);
        let (t, s) = run_from([r, 0.0, 0.0, 0.0, 0.0, 0.0], &[c], dt);
        let v = 100f64
            .min((0.5 * A * r).sqrt())
            .min((0.5 * J * r * r).cbrt())
            .min((24.0 * r * TOL / (2.0 * T * T)).sqrt());
        let th = 270f64.to_radians();
        let len = ((r * th).powi(2) + 100.0).sqrt();
        close(t, trap_time(len, v, 0.5 * A) + 2.0 * T, 0.005);
        // Every sample on the helix within the tolerance: radial error in
        // the plane, and Z against the height of the helix at the
        // sample's angle (z = 10·φ/θ, φ in [0, θ]).
        let mut dev: f64 = 0.0;
        for (_, q) in &s {
            let mut phi = q[1].atan2(q[0]);
            if phi < -0.5 {
                phi += std::f64::consts::TAU;
            }
            let phi = phi.clamp(0.0, th);
            let dr = q[0].hypot(q[1]) - r;
            let dz = q[2] - 10.0 * phi / th;
            dev = dev.max(dr.hypot(dz));
        }
        assert!(dev <= TOL, "r {r}: helix deviation {dev} mm");
        let [vx, ax, jx] = derivs(&s, dt);
        assert!(vx <= 100.0 * 1.0001, "r {r}: axis speed {vx}");
        assert!(ax <= A * 1.0001, "r {r}: axis acceleration {ax}");
        assert!(jx <= J * 1.0001, "r {r}: axis jerk {jx}");
    }
}

#[test]
fn inverse_time_feed_g93() {
    // G93: F is 1/min per block: F2 on a 30 mm move = 60 mm/min = 1 mm/s
    // (30 s of cruise; the ramps 0 → 1 → 0 at 1000 mm/s² add 1/1000 s),
    // plus 2T. F0.5 on a 3-4-5 move of 50 mm: 25 mm/min.
    let inv = |x: f64, y: f64, f: f64| Canon::Feed {
        m: Motion {
            to: p(x, y),
            mto: p(x, y),
        },
        feed: Feed::InverseTime(f),
    };
    let (t, _) = run(&[inv(30.0, 0.0, 2.0)], dynm(), None);
    close(t, 30.0 + 0.001 + 2.0 * T, 0.005);
    let (t, _) = run(&[inv(30.0, 40.0, 0.5)], dynm(), None);
    let v = 25.0 / 60.0;
    // Path acceleration (A/2)/max|u_i| = 1000/0.8.
    close(t, trap_time(50.0, v, 1250.0) + 2.0 * T, 0.005);
}
