//! RESET, alarms and their history, MDI, jog / handle / reference return,
//! and the offset, variable and parameter pages.

mod common;

use common::*;
use kerf_control::runtime::{Command, Execution, Mode, OffsetWrite, RecordKind, VarWrite};

#[test]
fn reset_returns_the_modals_as_pi_144_146_say() {
    for (pi144, want) in [(0.0, "G00"), (1.0, "G01")] {
        let mut rt = machine("hx-mc");
        rt.write_parameter("PI 144", pi144).unwrap();
        rt.command(Command::Mode { mode: Mode::Mem }).unwrap();
        rt.load_program("r.nc", "G91 G02 X-10. R5. F600\nG19\nM30\n")
            .unwrap();
        rt.command(Command::CycleStart).unwrap();
        until(&mut rt, Execution::ProgramCompleted, 10.0);
        let m = rt.state().modal;
        assert!(m.contains(&"G02".to_string()) && m.contains(&"G91".to_string()));
        assert!(m.contains(&"G19".to_string()));
        rt.command(Command::Reset).unwrap();
        let m = rt.state().modal;
        assert!(m.contains(&want.to_string()), "PI 144 = {pi144}: {m:?}");
        assert!(
            m.contains(&"G90".to_string()) && m.contains(&"G17".to_string()),
            "{m:?}"
        );
        assert!(m.contains(&"G21".to_string()));
    }
}

#[test]
fn reset_while_moving_stops_on_the_path_and_rewinds() {
    let mut rt = mem("G91 G01 X-100. F600\nM30\n");
    let x0 = rt.profile().start_position()[0];
    rt.command(Command::CycleStart).unwrap();
    rt.step(3.0);
    rt.command(Command::Reset).unwrap();
    assert_eq!(rt.execution(), Execution::Ready);
    rt.step(1.0);
    // Decelerated as a feed hold: 30.000 mm.
    assert!((mx(&rt) - (x0 - 30.0)).abs() < 1e-6, "{}", mx(&rt));
    assert_eq!(rt.state().spindle.direction, "stop");
    // Cycle start runs the program from its start (G91: another 100 mm).
    rt.command(Command::CycleStart).unwrap();
    until(&mut rt, Execution::ProgramCompleted, 30.0);
    assert!((mx(&rt) - (x0 - 130.0)).abs() < 1e-6, "{}", mx(&rt));
}

#[test]
fn an_alarm_stops_after_the_blocks_before_it_and_reset_clears_it() {
    let mut rt = mem("G91 G01 X-10. F600\nG999\nX-10.\nM30\n");
    let x0 = rt.profile().start_position()[0];
    rt.command(Command::CycleStart).unwrap();
    until(&mut rt, Execution::Stopped, 10.0);
    assert!((mx(&rt) - (x0 - 10.0)).abs() < 1e-9);
    let s = rt.state();
    let a = s.alarm.expect("alarm in force");
    assert_eq!((a.line, a.file.as_str()), (2, "test.nc"));
    let err = rt.command(Command::CycleStart).unwrap_err();
    assert_eq!(err.reason, "an alarm is in force: RESET first");
    let log = rt.alarms(0);
    assert_eq!(log.len(), 1);
    assert_eq!((log[0].seq, log[0].kind), (1, RecordKind::Alarm));
    assert_eq!(log[0].code, a.code);
    rt.command(Command::Reset).unwrap();
    assert!(rt.state().alarm.is_none());
    let log = rt.alarms(1);
    assert_eq!(log.len(), 1);
    assert_eq!((log[0].seq, log[0].kind), (2, RecordKind::Reset));
    // Any number of readers: the whole history is still there.
    assert_eq!(rt.alarms(0).len(), 2);
}

#[test]
fn messages_go_to_the_history() {
    let mut rt = mem("#3006 = 1 (CHECK THE CLAMP)\nM30\n");
    rt.command(Command::CycleStart).unwrap();
    rt.run_until_stopped(10.0);
    let log = rt.alarms(0);
    assert!(
        log.iter().any(|r| r.message.contains("CHECK THE CLAMP")),
        "{log:?} {:?}",
        rt.state()
    );
}

#[test]
fn mdi_runs_with_the_machine_modal_state() {
    let mut rt = machine("hx-mc");
    let x0 = rt.profile().start_position()[0];
    rt.command(Command::Mode { mode: Mode::Mdi }).unwrap();
    let mdi = |rt: &mut kerf_control::runtime::Runtime, t: &str| {
        rt.command(Command::Mdi { block: t.into() }).unwrap();
        until(rt, Execution::Ready, 10.0);
    };
    mdi(&mut rt, "G91");
    mdi(&mut rt, "G00 X-10.");
    mdi(&mut rt, "G00 X-10.");
    assert!((mx(&rt) - (x0 - 20.0)).abs() < 1e-9);
    assert!(rt.state().modal.contains(&"G91".to_string()));
    // Macro statements too.
    mdi(&mut rt, "#100 = 2.5\nG00 X-#100");
    assert!((mx(&rt) - (x0 - 22.5)).abs() < 1e-9);
    // Text that does not parse: refused, nothing changed.
    let before = serde_json::to_value(rt.state()).unwrap();
    let err = rt
        .command(Command::Mdi {
            block: "G00 X-1.\nG01 X(oops".into(),
        })
        .unwrap_err();
    assert!(err.reason.starts_with("line 2, column"), "{}", err.reason);
    assert_eq!(before, serde_json::to_value(rt.state()).unwrap());
}

#[test]
fn jog_handle_and_reference_return() {
    let mut rt = machine("hx-mc");
    rt.command(Command::Mode { mode: Mode::Jog }).unwrap();
    // X travels -800 .. 0 and starts at 0: +1 leaves the travel.
    let err = rt
        .command(Command::Jog {
            axis: "x".into(),
            distance: 1.0,
        })
        .unwrap_err();
    assert!(err.reason.contains("outside its travel"), "{}", err.reason);
    let err = rt
        .command(Command::Jog {
            axis: "q".into(),
            distance: 1.0,
        })
        .unwrap_err();
    assert!(err.reason.contains("no axis"));
    rt.command(Command::Jog {
        axis: "x".into(),
        distance: -20.0,
    })
    .unwrap();
    assert_eq!(rt.execution(), Execution::Active);
    // 2000 mm/min = 33.33 mm/s at 1000 mm/s²: 0.0333 s ramps, 20 mm in 0.633 s.
    rt.step(0.62);
    assert_eq!(rt.execution(), Execution::Active);
    rt.step(0.02);
    assert_eq!(rt.execution(), Execution::Ready);
    assert!((mx(&rt) + 20.0).abs() < 1e-9);
    rt.command(Command::Handle {
        axis: "X".into(),
        pulses: -150,
        increment: 0.01,
    })
    .unwrap();
    until(&mut rt, Execution::Ready, 5.0);
    assert!((mx(&rt) + 21.5).abs() < 1e-9, "{}", mx(&rt));
    assert!(rt
        .command(Command::Handle {
            axis: "x".into(),
            pulses: 1,
            increment: 0.5,
        })
        .is_err());
    rt.command(Command::Mode { mode: Mode::Ref }).unwrap();
    assert!(!rt.referenced(kerf_canon::Axis::X));
    rt.command(Command::RefReturn { axis: None }).unwrap();
    until(&mut rt, Execution::Ready, 10.0);
    assert_eq!(mx(&rt), 0.0);
    assert!(rt.referenced(kerf_canon::Axis::X) && rt.referenced(kerf_canon::Axis::Z));
    // The interpreter starts the next program from where the hands left it.
    assert_eq!(rt.interp().machine_position()[0], 0.0);
}

#[test]
fn offset_pages_write_and_refuse() {
    let mut rt = machine("hx-mc");
    rt.write_offset(OffsetWrite::H {
        n: 1,
        geom: Some(100.0),
        wear: Some(-0.25),
    })
    .unwrap();
    assert_eq!(rt.interp().offsets().h(1), 99.75);
    for bad in [
        OffsetWrite::H {
            n: 0,
            geom: Some(1.0),
            wear: None,
        },
        OffsetWrite::H {
            n: 9999,
            geom: Some(1.0),
            wear: None,
        },
        OffsetWrite::D {
            n: 1,
            geom: Some(1e6),
            wear: None,
        },
        OffsetWrite::D {
            n: 1,
            geom: Some(f64::NAN),
            wear: None,
        },
        OffsetWrite::Work {
            index: 6,
            axis: "x".into(),
            value: 0.0,
        },
        OffsetWrite::Work {
            index: 0,
            axis: "w".into(),
            value: 0.0,
        },
    ] {
        let before = rt.interp().offsets().h(1);
        assert!(rt.write_offset(bad.clone()).is_err(), "{bad:?}");
        assert_eq!(rt.interp().offsets().h(1), before);
    }
    rt.write_offset(OffsetWrite::Work {
        index: 1,
        axis: "x".into(),
        value: -321.5,
    })
    .unwrap();
    assert_eq!(rt.work_offset(1).unwrap()[0], -321.5);
    // A G55 program reads it.
    rt.command(Command::Mode { mode: Mode::Mem }).unwrap();
    rt.load_program("w.nc", "G90 G55 G00 X0.\nM30\n").unwrap();
    rt.command(Command::CycleStart).unwrap();
    until(&mut rt, Execution::ProgramCompleted, 10.0);
    assert!((mx(&rt) + 321.5).abs() < 1e-9);
    // Variables: commons and retained, not locals or system variables.
    rt.write_variable(VarWrite {
        n: 500,
        value: Some(7.0),
    })
    .unwrap();
    assert_eq!(rt.interp().macro_var(500), Some(7.0));
    assert!(rt
        .write_variable(VarWrite {
            n: 1,
            value: Some(1.0)
        })
        .is_err());
    assert!(rt
        .write_variable(VarWrite {
            n: 5021,
            value: Some(1.0)
        })
        .is_err());
    // Parameters only in EDIT/MDI.
    assert!(rt.write_parameter("PI 144", 1.0).is_err());
}

#[test]
fn a_macro_loop_without_motion_costs_bounded_work_per_step() {
    let mut rt = mem("WHILE [1 EQ 1] DO1\n#100 = #100 + 1\nEND1\nM30\n");
    rt.command(Command::CycleStart).unwrap();
    rt.step(1.0);
    // One step executes at most 20,000 blocks (counted below, not timed);
    // the axes do not move and machine time waits for the interpreter.
    assert_eq!(rt.execution(), Execution::Active);
    let n = rt.interp().macro_var(100).unwrap();
    assert!(n > 1000.0 && n <= 20_000.0, "{n}");
    // RESET ends it.
    rt.command(Command::Reset).unwrap();
    assert_eq!(rt.execution(), Execution::Ready);
}

#[test]
fn restart_by_sequence_number() {
    let text = "N10 G90 G54 G00 X-10. Y-10. Z10.\nN20 G01 Z-1. F300\nN30 X-20.\nN40 M30\n";
    let mut rt = mem(text);
    rt.command(Command::Restart {
        line: None,
        sequence: Some(30),
    })
    .unwrap();
    assert_eq!(rt.pending_restart().unwrap().line, 3);
    rt.command(Command::CycleStart).unwrap();
    until(&mut rt, Execution::ProgramCompleted, 30.0);
    let w = rt.state().position.work;
    assert!(
        (w["x"] + 20.0).abs() < 1e-9 && (w["z"] + 1.0).abs() < 1e-9,
        "{w:?}"
    );
}

#[test]
fn state_dir_keeps_offsets_across_machines() {
    let dir = std::env::temp_dir().join(format!("kerf-state-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    {
        let mut rt = machine("hx-mc");
        rt.set_state_dir(dir.clone()).unwrap();
        rt.write_offset(OffsetWrite::Work {
            index: 2,
            axis: "y".into(),
            value: -123.25,
        })
        .unwrap();
        rt.write_offset(OffsetWrite::D {
            n: 3,
            geom: Some(4.0),
            wear: Some(-0.01),
        })
        .unwrap();
        rt.write_variable(VarWrite {
            n: 501,
            value: Some(-2.5),
        })
        .unwrap();
    }
    let mut rt = machine("hx-mc");
    rt.set_state_dir(dir.clone()).unwrap();
    assert_eq!(rt.work_offset(2).unwrap()[1], -123.25);
    assert_eq!(rt.interp().offsets().d(3), 3.99);
    assert_eq!(rt.interp().macro_var(501), Some(-2.5));
    // A torn or foreign file is an error naming it, not a panic.
    std::fs::write(dir.join("hx-mc.work"), "0 1 2\n").unwrap();
    let mut rt = machine("hx-mc");
    let err = rt.set_state_dir(dir.clone()).unwrap_err().to_string();
    assert!(err.contains("hx-mc.work:1"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn feed_hold_stops_a_jog_on_its_trapezoid() {
    let mut rt = machine("hx-mc");
    rt.command(Command::Mode { mode: Mode::Jog }).unwrap();
    rt.command(Command::Jog {
        axis: "x".into(),
        distance: -20.0,
    })
    .unwrap();
    // 33.33 mm/s after 0.0333 s (0.5556 mm): 9.4444 mm at 0.3 s, and
    // v²/2a = 0.5556 mm to stop: 10.000 mm.
    rt.step(0.3);
    rt.command(Command::FeedHold).unwrap();
    assert_eq!(rt.execution(), Execution::Ready);
    rt.step(1.0);
    assert!((mx(&rt) + 10.0).abs() < 1e-9, "{}", mx(&rt));
    assert!((rt.interp().machine_position()[0] + 10.0).abs() < 1e-9);
}

#[test]
fn reset_plane_and_distance_modes_follow_pi_145_146() {
    for (p145, p146, plane, dist) in [
        (0.0, 0.0, "G17", "G90"),
        (1.0, 1.0, "G18", "G91"),
        (2.0, 0.0, "G19", "G90"),
    ] {
        let mut rt = machine("hx-mc");
        rt.write_parameter("PI 145", p145).unwrap();
        rt.write_parameter("PI 146", p146).unwrap();
        rt.command(Command::Mode { mode: Mode::Mem }).unwrap();
        rt.load_program("r.nc", "G17 G90 G00 X-1.\nM30\n").unwrap();
        rt.command(Command::CycleStart).unwrap();
        until(&mut rt, Execution::ProgramCompleted, 10.0);
        rt.command(Command::Reset).unwrap();
        let m = rt.state().modal;
        assert!(
            m.contains(&plane.to_string()) && m.contains(&dist.to_string()),
            "PI 145 {p145} PI 146 {p146}: {m:?}"
        );
    }
}

#[test]
fn single_block_stops_at_macro_statements_only_as_the_parameter_says() {
    for (param, first_stop_line, moved) in [(0.0, 2, true), (1.0, 1, false)] {
        let mut rt = machine("hx-mc");
        rt.write_parameter("single_block_macro", param).unwrap();
        rt.command(Command::Mode { mode: Mode::Mem }).unwrap();
        rt.load_program("s.nc", "#100 = 1\nG91 G01 X-1. F600\nM30\n")
            .unwrap();
        rt.command(Command::Switch {
            single_block: Some(true),
            optional_stop: None,
            dry_run: None,
            block_skip: None,
        })
        .unwrap();
        rt.command(Command::CycleStart).unwrap();
        until(&mut rt, Execution::Interrupted, 10.0);
        assert_eq!(
            rt.interp().block_at().0.line,
            first_stop_line,
            "param {param}"
        );
        assert_eq!(mx(&rt) != 0.0, moved, "param {param}");
    }
}

#[test]
fn the_m00_comment_goes_to_the_history() {
    let mut rt = mem("G91 G01 X-1. F600\nM00 (TURN THE PART OVER)\nM30\n");
    rt.command(Command::CycleStart).unwrap();
    until(&mut rt, Execution::ProgramStopped, 10.0);
    let log = rt.alarms(0);
    let last = log.last().expect("a record");
    assert_eq!(
        (last.kind, last.message.as_str(), last.line),
        (RecordKind::Message, "TURN THE PART OVER", 2)
    );
}

#[test]
fn programs_up_to_512_mib_load_and_larger_are_refused() {
    use kerf_control::runtime::MAX_PROGRAM_BYTES;
    assert_eq!(MAX_PROGRAM_BYTES, 512 * 1024 * 1024);
    let mut rt = machine("hx-mc");
    rt.command(Command::Mode { mode: Mode::Mem }).unwrap();
    // 65 MiB (over the 64 MiB this runtime took before): 8-byte blocks.
    let block = "G00 X1.\n";
    let big = block.repeat((65 << 20) / block.len());
    rt.load_program("big.nc", &big).unwrap();
    drop(big);
    // One byte over the limit: refused, and the program before stays.
    let over = "\n".repeat(MAX_PROGRAM_BYTES + 1);
    let e = rt.load_program("over.nc", &over).unwrap_err();
    assert!(e.to_string().contains("programs up to 512 MiB"), "{e}");
    assert_eq!(rt.state().program.name, "big.nc");
}
