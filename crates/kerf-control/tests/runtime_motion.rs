//! Machine time, feed hold, single block, M00/M01, block skip, dry run,
//! overrides: numbers worked out by hand from the trapezoid (path
//! acceleration 1000 mm/s² on a straight cut, see tests/common).

mod common;

use common::*;
use kerf_control::runtime::{Command, Execution, Mode};

fn start(rt: &mut kerf_control::runtime::Runtime) -> f64 {
    rt.command(Command::CycleStart).unwrap();
    rt.profile().start_position()[0]
}

#[test]
fn feed_hold_stops_on_the_trapezoid_and_resume_finishes_the_move() {
    let mut rt = mem("G91 G01 X-100. F600\nM30\n");
    let x0 = start(&mut rt);
    rt.step(3.0);
    // Accelerating 0.01 s (0.05 mm), then 10 mm/s: 29.95 mm at 3 s.
    assert!((mx(&rt) - (x0 - 29.95)).abs() < 1e-6, "{}", mx(&rt));
    assert!((rt.state().feed - 600.0).abs() < 1e-6);
    rt.command(Command::FeedHold).unwrap();
    assert_eq!(rt.execution(), Execution::FeedHold);
    rt.step(0.005);
    // Half way through the 0.01 s deceleration: 29.95 + 0.05 − 0.0125.
    assert!((mx(&rt) - (x0 - 29.9875)).abs() < 1e-6, "{}", mx(&rt));
    rt.step(2.0);
    assert!((mx(&rt) - (x0 - 30.0)).abs() < 1e-6, "{}", mx(&rt));
    assert_eq!(rt.state().feed, 0.0);
    assert_eq!(rt.state().program.line, 1);
    assert!((rt.state().position.distance_to_go["x"] + 70.0).abs() < 1e-6);
    // Resume at 5.005 s: 70 mm from rest, 0.01 + 6.99 + 0.01 s.
    let t = rt.time();
    rt.command(Command::CycleStart).unwrap();
    rt.step(7.0);
    assert!((mx(&rt) - (x0 - 99.95)).abs() < 1e-6, "{}", mx(&rt));
    rt.step(0.02);
    assert_eq!(rt.execution(), Execution::ProgramCompleted);
    assert!((mx(&rt) - (x0 - 100.0)).abs() < 1e-9);
    assert!(rt.time() - t > 7.01);
}

#[test]
fn hold_near_a_block_end_stops_in_the_next_block() {
    // Two collinear 10 mm cuts: the junction is passed at 10 mm/s.
    let mut rt = mem("G91 G01 X-10. F600\nX-10.\nM30\n");
    let x0 = start(&mut rt);
    // Block 1 ends at 0.01 + 9.95/10 = 1.005 s; 0.02 mm before at 1.003 s.
    rt.step(1.003);
    assert!((mx(&rt) - (x0 - 9.98)).abs() < 1e-6, "{}", mx(&rt));
    rt.command(Command::FeedHold).unwrap();
    rt.step(1.0);
    assert!((mx(&rt) - (x0 - 10.03)).abs() < 1e-6, "{}", mx(&rt));
    assert_eq!(rt.state().program.line, 2);
    rt.command(Command::CycleStart).unwrap();
    until(&mut rt, Execution::ProgramCompleted, 10.0);
    assert!((mx(&rt) - (x0 - 20.0)).abs() < 1e-9);
}

#[test]
fn hold_during_a_thread_finishes_the_thread() {
    let mut rt = machine("puma-lathe");
    rt.command(Command::Mode { mode: Mode::Mem }).unwrap();
    rt.load_program(
        "thread.nc",
        "G00 X20. Z5.\nM03 S500\nG32 Z-30. F2.\nG00 X30.\nM30\n",
    )
    .unwrap();
    rt.command(Command::CycleStart).unwrap();
    let mut guard = 0;
    while rt.state().program.line != 3 {
        rt.step(0.01);
        guard += 1;
        assert!(guard < 10_000);
    }
    // 2 mm/rev × 500 rpm = 1000 mm/min: 35 mm take 2.1 s; hold after 0.5 s.
    rt.step(0.5);
    let z_mid = rt.state().position.work["z"];
    assert!(z_mid < 4.0 && z_mid > -25.0, "{z_mid}");
    rt.command(Command::FeedHold).unwrap();
    assert_eq!(rt.execution(), Execution::FeedHold);
    rt.step(5.0);
    let s = rt.state();
    assert_eq!(s.execution, Execution::FeedHold);
    assert!(
        (s.position.work["z"] + 30.0).abs() < 1e-6,
        "{:?}",
        s.position
    );
    // X (radius 10) still at the thread: the retract of block 4 waits.
    assert!(
        (s.position.work["x"] - 10.0).abs() < 1e-6,
        "{:?}",
        s.position
    );
    rt.command(Command::CycleStart).unwrap();
    until(&mut rt, Execution::ProgramCompleted, 20.0);
    assert!((rt.state().position.work["x"] - 15.0).abs() < 1e-6);
}

#[test]
fn hold_during_a_tap_waits_for_the_return_to_r() {
    let mut rt =
        mem("G90 G54 G00 X-100. Y-100. Z10.\nM03 S500\nG84 Z-20. R5. F500\nG80 G00 Z50.\nM30\n");
    rt.command(Command::CycleStart).unwrap();
    let mut guard = 0;
    while rt.state().program.line != 3 || rt.state().position.work["z"] > 0.0 {
        rt.step(0.01);
        guard += 1;
        assert!(guard < 10_000);
    }
    rt.command(Command::FeedHold).unwrap();
    rt.step(10.0);
    let s = rt.state();
    assert_eq!(s.execution, Execution::FeedHold);
    // The tap goes to Z-20 and back to R (5) before the axes stop.
    assert!(
        (s.position.work["z"] - 5.0).abs() < 1e-6,
        "{:?}",
        s.position
    );
    rt.command(Command::CycleStart).unwrap();
    until(&mut rt, Execution::ProgramCompleted, 20.0);
    assert!((rt.state().position.work["z"] - 50.0).abs() < 1e-6);
}

#[test]
fn single_block_stops_after_every_block() {
    let mut rt = mem("G91 G01 X-10. F600\nX-10.\nG90\nM30\n");
    rt.command(Command::Switch {
        single_block: Some(true),
        optional_stop: None,
        dry_run: None,
        block_skip: None,
    })
    .unwrap();
    let x0 = start(&mut rt);
    for (want, line) in [(x0 - 10.0, 1), (x0 - 20.0, 2), (x0 - 20.0, 3)] {
        until(&mut rt, Execution::Interrupted, 10.0);
        assert!((mx(&rt) - want).abs() < 1e-9, "{} vs {want}", mx(&rt));
        assert_eq!(rt.interp().block_at().0.line, line);
        rt.command(Command::CycleStart).unwrap();
    }
    until(&mut rt, Execution::ProgramCompleted, 10.0);
}

#[test]
fn m00_stops_m01_only_with_its_switch() {
    let prog = "G91 G01 X-10. F600\nM01\nX-10.\nM00\nX-10.\nM30\n";
    let mut rt = mem(prog);
    let x0 = start(&mut rt);
    until(&mut rt, Execution::ProgramStopped, 30.0);
    assert!((mx(&rt) - (x0 - 20.0)).abs() < 1e-9);
    rt.command(Command::CycleStart).unwrap();
    until(&mut rt, Execution::ProgramCompleted, 30.0);
    assert!((mx(&rt) - (x0 - 30.0)).abs() < 1e-9);

    let mut rt = mem(prog);
    rt.command(Command::Switch {
        single_block: None,
        optional_stop: Some(true),
        dry_run: None,
        block_skip: None,
    })
    .unwrap();
    let x0 = start(&mut rt);
    until(&mut rt, Execution::OptionalStop, 30.0);
    assert!((mx(&rt) - (x0 - 10.0)).abs() < 1e-9);
    rt.command(Command::CycleStart).unwrap();
    until(&mut rt, Execution::ProgramStopped, 30.0);
}

#[test]
fn block_skip_levels() {
    let prog = "G91 G01 X-10. F6000\n/X-10.\n/2 X-10.\nM30\n";
    for (levels, travel) in [
        (vec![], 30.0),
        (vec![1], 20.0),
        (vec![1, 2], 10.0),
        (vec![2], 20.0),
    ] {
        let mut rt = mem(prog);
        rt.command(Command::Switch {
            single_block: None,
            optional_stop: None,
            dry_run: None,
            block_skip: Some(levels.clone()),
        })
        .unwrap();
        let x0 = start(&mut rt);
        until(&mut rt, Execution::ProgramCompleted, 30.0);
        assert!((mx(&rt) - (x0 - travel)).abs() < 1e-9, "{levels:?}");
    }
}

#[test]
fn dry_run_and_feed_override() {
    // F60: 10 mm take 10 s; dry run moves at the dry-run feed (10 m/min).
    let mut rt = mem("G91 G01 X-10. F60\nM30\n");
    rt.command(Command::Switch {
        single_block: None,
        optional_stop: None,
        dry_run: Some(true),
        block_skip: None,
    })
    .unwrap();
    start(&mut rt);
    let t = until(&mut rt, Execution::ProgramCompleted, 30.0);
    assert!(t < 1.0, "{t}");

    // 50 %: 5 mm/s, accelerating 0.005 s (0.0125 mm): 14.9875 mm at 3 s.
    let mut rt = mem("G91 G01 X-100. F600\nM30\n");
    rt.command(Command::Override {
        feed: Some(50.0),
        rapid: None,
    })
    .unwrap();
    let x0 = start(&mut rt);
    rt.step(3.0);
    assert!((mx(&rt) - (x0 - 14.9875)).abs() < 1e-6, "{}", mx(&rt));
    assert!((rt.state().feed - 300.0).abs() < 1e-6);
}

#[test]
fn override_acts_from_the_next_block_read() {
    // 40 blocks of 1 mm at F600 (0.1 s each).
    let mut prog = String::from("G91 G01 F600\n");
    for _ in 0..40 {
        prog.push_str("X-1.\n");
    }
    prog.push_str("M30\n");
    let mut rt = mem(&prog);
    start(&mut rt);
    rt.step(0.3);
    let read = rt.interp().block_at().0.line;
    rt.command(Command::Override {
        feed: Some(200.0),
        rapid: None,
    })
    .unwrap();
    // The blocks already read (the look-ahead) keep 600 mm/min.
    rt.step(0.05);
    assert!((rt.state().feed - 600.0).abs() < 1e-6);
    // Once the axes reach the blocks read after the change: 1200.
    let mut guard = 0;
    while rt.state().program.line <= read + 1 {
        rt.step(0.01);
        guard += 1;
        assert!(guard < 1000);
    }
    rt.step(0.05);
    assert!(
        (rt.state().feed - 1200.0).abs() < 1e-6,
        "{}",
        rt.state().feed
    );
}

#[test]
fn rate_runs_machine_time_faster() {
    let mut rt = mem("G91 G01 X-100. F600\nM30\n");
    rt.set_rate(10.0).unwrap();
    let x0 = start(&mut rt);
    rt.advance(0.3); // 3 s of machine time
    assert!((mx(&rt) - (x0 - 29.95)).abs() < 1e-6);
    assert!(rt.set_rate(0.0).is_err());
}

#[test]
fn hurco_m200_lets_block_delete_act_on_the_blocks_after_it() {
    for (sync, want) in [(true, 20.0), (false, 30.0)] {
        let mut rt = machine("hurco-lathe");
        rt.command(Command::Mode { mode: Mode::Mem }).unwrap();
        let mid = if sync { "M200" } else { "G04 F0.1" };
        rt.load_program(
            "m200.nc",
            &format!("G21 G91 G94 G01 Z-10. F600\n{mid}\n/Z-10.\nZ-10.\nM30\n"),
        )
        .unwrap();
        rt.command(Command::CycleStart).unwrap();
        rt.step(0.5);
        // Block delete switched on during the first move (1 s long).
        rt.command(Command::Switch {
            single_block: None,
            optional_stop: None,
            dry_run: None,
            block_skip: Some(vec![1]),
        })
        .unwrap();
        until(&mut rt, Execution::ProgramCompleted, 30.0);
        // M200 empties the look-ahead (002 Table 15): the / block read
        // after it is skipped; without it the block was read already.
        let z = rt.state().position.machine["z"];
        assert!((z + want).abs() < 1e-9, "M200 {sync}: z {z}");
    }
}

#[test]
fn single_block_in_compensation_stops_where_each_block_ends() {
    let text = "G90 G54 G00 X0. Y0. Z10.\nG41 D1 G01 X10. F600\nY10.\nX0.\nG40 G00 X-10.\nM30\n";
    // The interpreter's own toolpath: the end of each line's last motion.
    let mut it = kerf_interp::Interp::new(
        kerf_interp::Profile::builtin("hx-mc").unwrap(),
        Default::default(),
    );
    it.offsets_mut().d_mut(1).unwrap().geom = 5.0;
    let run = kerf_interp::run_interp(it, "t.nc", text);
    assert!(run.alarm.is_none());
    let end_of = |line: u32| {
        run.events
            .iter()
            .rev()
            .find(|e| e.src.line == line && e.motion().is_some())
            .map(|e| e.motion().unwrap().mto)
    };
    let mut rt = mem(text);
    rt.write_offset(kerf_control::runtime::OffsetWrite::D {
        n: 1,
        geom: Some(5.0),
        wear: None,
    })
    .unwrap();
    rt.command(Command::Switch {
        single_block: Some(true),
        optional_stop: None,
        dry_run: None,
        block_skip: None,
    })
    .unwrap();
    rt.command(Command::CycleStart).unwrap();
    let mut stops = Vec::new();
    while rt.execution() != Execution::ProgramCompleted {
        until(&mut rt, Execution::Interrupted, 30.0);
        let s = rt.state();
        stops.push((s.program.line, s.position.machine.clone()));
        rt.command(Command::CycleStart).unwrap();
        rt.step(0.01);
        if stops.len() > 20 {
            panic!("{stops:?}");
        }
        if rt.execution() == Execution::Active {
            rt.run_until_stopped(30.0);
        }
    }
    // One stop per block with motion (1-5; M30 completes), each at the
    // end of that block's last move.
    let lines: Vec<u32> = stops.iter().map(|s| s.0).collect();
    assert_eq!(lines, [1, 2, 3, 4, 5], "{stops:?}");
    for (line, pos) in &stops {
        let want = end_of(*line).unwrap();
        for (k, a) in ["x", "y", "z"].iter().enumerate() {
            assert!(
                (pos[*a] - want[k]).abs() < 1e-9,
                "line {line}: {pos:?} vs {want:?}"
            );
        }
    }
}

#[test]
fn hold_in_a_dwell_keeps_the_time_left() {
    let mut rt = mem("G04 X2.\nG91 G01 X-10. F600\nM30\n");
    let x0 = start(&mut rt);
    rt.step(0.5);
    rt.command(Command::FeedHold).unwrap();
    rt.step(3.0);
    assert_eq!(rt.execution(), Execution::FeedHold);
    assert_eq!(mx(&rt), x0);
    rt.command(Command::CycleStart).unwrap();
    // 1.5 s of dwell left, then the 10 mm move (1.01 s).
    rt.step(1.49);
    assert_eq!(mx(&rt), x0);
    rt.step(0.51);
    assert!((mx(&rt) - (x0 - 4.95)).abs() < 1e-6, "{}", mx(&rt));
}

#[test]
fn hold_in_a_rapid_stops_on_its_trapezoid() {
    // Rapid 10 m/min = 166.67 mm/s, accel 2000 mm/s² (rapids use the
    // axis rapid acceleration in full): cruise after 0.0833 s / 6.944 mm.
    let mut rt = mem("G91 G00 X-200.\nM30\n");
    let x0 = start(&mut rt);
    rt.step(0.5);
    let v: f64 = 10_000.0 / 60.0;
    let s_hold = v * v / (2.0 * 2000.0) + v * (0.5 - v / 2000.0);
    assert!(
        (mx(&rt) - (x0 - s_hold)).abs() < 1e-6,
        "{} vs {}",
        mx(&rt),
        x0 - s_hold
    );
    rt.command(Command::FeedHold).unwrap();
    rt.step(1.0);
    let stop = s_hold + v * v / (2.0 * 2000.0);
    assert!(
        (mx(&rt) - (x0 - stop)).abs() < 1e-6,
        "{} vs {}",
        mx(&rt),
        x0 - stop
    );
}

#[test]
fn the_toolpath_as_it_is_made_has_each_motion_once() {
    let mut rt = mem("G91 G00 X-5.\nG01 X-100. F600\nM30\n");
    let x0 = start(&mut rt);
    rt.step(2.0);
    rt.command(Command::FeedHold).unwrap();
    rt.step(1.0);
    rt.command(Command::CycleStart).unwrap();
    until(&mut rt, Execution::ProgramCompleted, 30.0);
    let m = rt.motions_since(0);
    let got: Vec<(u64, u32, &str)> = m.iter().map(|r| (r.seq, r.line, r.kind.as_str())).collect();
    assert_eq!(got, [(1, 1, "rapid"), (2, 2, "feed")]);
    assert!((m[1].mto["x"] - (x0 - 105.0)).abs() < 1e-9);
    assert_eq!(rt.motions_since(1).len(), 1);
}

#[test]
fn hold_and_resume_on_an_arc_stay_on_the_circle() {
    // Half circle R50 about (-50, 0) from X0 to X-100 at F600 (10 mm/s).
    let mut rt = mem("G90 G54 G00 X0. Y0.\nG17 G02 X-100. Y0. R50. F600\nM30\n");
    rt.command(Command::CycleStart).unwrap();
    let mut guard = 0;
    while rt.state().program.line != 2 {
        rt.step(0.01);
        guard += 1;
        assert!(guard < 10_000);
    }
    let on_circle = |rt: &kerf_control::runtime::Runtime| {
        let w = rt.state().position.work;
        let r = ((w["x"] + 50.0).powi(2) + w["y"].powi(2)).sqrt();
        assert!((r - 50.0).abs() < 1e-6, "off the circle: r = {r} at {w:?}");
        w
    };
    rt.step(4.0);
    on_circle(&rt);
    rt.command(Command::FeedHold).unwrap();
    rt.step(0.5);
    let held = on_circle(&rt);
    rt.step(1.0);
    assert_eq!(rt.state().position.work, held);
    rt.command(Command::CycleStart).unwrap();
    for _ in 0..5 {
        rt.step(1.0);
        on_circle(&rt);
    }
    until(&mut rt, Execution::ProgramCompleted, 30.0);
    let w = on_circle(&rt);
    assert!((w["x"] + 100.0).abs() < 1e-9 && w["y"].abs() < 1e-9);
}

#[test]
fn feed_hold_waits_while_the_program_disables_it() {
    // #3004 bit 0: feed hold does not act (fanuc-semantics §7.8; on the
    // Fanuc numbering: the PUMA).
    let mut rt = machine("puma-lathe");
    rt.command(Command::Mode { mode: Mode::Mem }).unwrap();
    rt.load_program(
        "h.nc",
        "#3004 = 1\nG98 G01 W-10. F600\n#3004 = 0\nW-10.\nM30\n",
    )
    .unwrap();
    let z0 = rt.profile().start_position()[2];
    rt.command(Command::CycleStart).unwrap();
    rt.step(0.5);
    rt.command(Command::FeedHold).unwrap();
    assert_eq!(rt.execution(), Execution::FeedHold);
    rt.step(3.0);
    // The hold acts where the move that ran with feed hold disabled ends
    // (passed at 10 mm/s into the next): v²/2a = 0.05 mm further (the
    // record's end is half a smoothing delay, 4 µs, after the junction).
    let z = rt.state().position.machine["z"];
    assert!((z - (z0 - 10.05)).abs() < 1e-4, "{z}");
    rt.command(Command::CycleStart).unwrap();
    until(&mut rt, Execution::ProgramCompleted, 10.0);
}

#[test]
fn the_program_can_switch_the_feed_override_off() {
    // #3004 bit 1 (Fanuc numbering): 100 % whatever the dial says.
    for (v3004, want) in [(0, 14.9875), (2, 29.95)] {
        let mut rt = machine("puma-lathe");
        rt.command(Command::Mode { mode: Mode::Mem }).unwrap();
        rt.load_program(
            "o.nc",
            &format!("#3004 = {v3004}\nG98 G01 W-100. F600\nM30\n"),
        )
        .unwrap();
        rt.command(Command::Override {
            feed: Some(50.0),
            rapid: None,
        })
        .unwrap();
        let z0 = rt.profile().start_position()[2];
        rt.command(Command::CycleStart).unwrap();
        rt.step(3.0);
        let z = rt.state().position.machine["z"];
        assert!((z - (z0 - want)).abs() < 1e-6, "#3004 = {v3004}: {z}");
    }
}
