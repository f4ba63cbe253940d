//! Program restart fidelity: for every block of every example program,
//! the state the restart rebuilds at that block equals the state a run
//! from the start has there (the interpreter's whole modal state, the
//! tool, spindle and coolant the re-entry sets up), and the restarted run
//! ends as the full run does.

mod common;

use std::collections::BTreeMap;
use std::path::Path;

use common::*;
use kerf_canon::{Canon, SpindleDir};
use kerf_control::runtime::{Command, Execution, Mode};
use kerf_interp::{BlockStep, Interp, InterpSnapshot, Profile, Settings};

/// What the full run has at the start of a block.
#[derive(Clone, Debug)]
struct At {
    snap: InterpSnapshot,
    rpm: f64,
    dir: &'static str,
    coolant: (bool, bool),
}

struct Full {
    at: BTreeMap<u32, At>,
    end: Result<[f64; 6], String>,
}

fn full_run(machine: &str, text: &str) -> Full {
    let mut it = Interp::new(Profile::builtin(machine).unwrap(), Settings::default());
    it.load_text("test.nc", text);
    let main = it.next_block_at().unwrap().0;
    let mut at = BTreeMap::new();
    let (mut rpm, mut dir, mut coolant) = (0.0, "stop", (false, false));
    let end = loop {
        let (f, l, depth) = it.next_block_at().unwrap();
        if f == main && depth == 0 && !it.holds_motion() {
            at.entry(l).or_insert_with(|| At {
                snap: it.snapshot(),
                rpm,
                dir,
                coolant,
            });
        }
        let step = it.step_block();
        while let Some(e) = it.take_event() {
            match e.cmd {
                Canon::Spindle { dir: d, rpm: r, .. } => {
                    dir = match d {
                        SpindleDir::Cw => "cw",
                        SpindleDir::Ccw => "ccw",
                        SpindleDir::Stop => "stop",
                    };
                    rpm = if d == SpindleDir::Stop { 0.0 } else { r };
                }
                Canon::Coolant { mist, flood } => coolant = (mist, flood),
                _ => {}
            }
        }
        match step {
            BlockStep::Block => {}
            BlockStep::End => break Ok(it.machine_position()),
            BlockStep::Alarm(a) => break Err(a.code),
        }
    };
    Full { at, end }
}

fn examples() -> Vec<(String, &'static str)> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples");
    let mut v = Vec::new();
    for (dir, machine) in [
        ("hx", "hx-mc"),
        ("puma", "puma-lathe"),
        ("hurco", "hurco-lathe"),
    ] {
        let mut files: Vec<_> = std::fs::read_dir(root.join(dir))
            .unwrap()
            .map(|e| e.unwrap().path())
            .filter(|p| p.extension().is_some_and(|e| e == "nc"))
            .collect();
        files.sort();
        for f in files {
            v.push((std::fs::read_to_string(&f).unwrap(), machine));
        }
    }
    assert!(v.len() > 50);
    v
}

#[test]
fn restart_at_every_block_of_the_examples_equals_the_full_run() {
    let (mut restarted, mut refused) = (0, 0);
    for (text, machine) in examples() {
        let full = full_run(machine, &text);
        let lines: Vec<&str> = text.lines().collect();
        for (&line, want) in &full.at {
            match lines.get(line as usize - 1) {
                Some(t) if !t.trim().is_empty() => {}
                _ => continue,
            }
            let mut rt = common::machine(machine);
            rt.command(Command::Mode { mode: Mode::Mem }).unwrap();
            rt.load_program("test.nc", &text).unwrap();
            match rt.command(Command::Restart {
                line: Some(line),
                sequence: None,
            }) {
                Ok(()) => {}
                Err(r) => {
                    // Only the refusals the control makes.
                    assert!(
                        r.reason.contains("inside") || r.reason.contains("not executed"),
                        "{machine} line {line}: {}",
                        r.reason
                    );
                    refused += 1;
                    continue;
                }
            }
            assert_eq!(
                rt.interp().snapshot(),
                want.snap,
                "{machine} line {line}:\n{text}"
            );
            let plan = rt.pending_restart().expect("plan").clone();
            assert_eq!(plan.line, line);
            assert_eq!(plan.spindle_direction, want.dir, "{machine} line {line}");
            assert!(
                (plan.spindle_rpm - want.rpm).abs() < 1e-9,
                "{machine} line {line}"
            );
            assert_eq!(
                (plan.mist, plan.flood),
                want.coolant,
                "{machine} line {line}"
            );
            // The restarted run ends as the full run.
            rt.command(Command::CycleStart).unwrap();
            rt.run_until_stopped(100_000.0);
            // M00 / M01 stop the run: continue as the operator does.
            while matches!(
                rt.execution(),
                Execution::ProgramStopped | Execution::OptionalStop | Execution::Interrupted
            ) {
                rt.command(Command::CycleStart).unwrap();
                rt.run_until_stopped(100_000.0);
            }
            match &full.end {
                Ok(p) => {
                    assert_eq!(
                        rt.execution(),
                        Execution::ProgramCompleted,
                        "{machine} {line}"
                    );
                    let m = rt.interp().machine_position();
                    for i in 0..6 {
                        assert!(
                            (m[i] - p[i]).abs() < 1e-6,
                            "{machine} line {line}: {m:?} {p:?}"
                        );
                    }
                }
                Err(code) => {
                    assert_eq!(rt.state().alarm.map(|a| a.code).as_ref(), Some(code));
                }
            }
            restarted += 1;
        }
    }
    eprintln!("{restarted} blocks restarted, {refused} refused");
    assert!(restarted > 300, "{restarted} restarted, {refused} refused");
}

#[test]
fn reentry_path_retracts_positions_and_plunges() {
    let text = "G90 G54 G00 X-100. Y-100. Z50.\nM03 S1000\nM08\nG01 Z-5. F300\nX-50.\nY-50.\nM30\n";
    let mut rt = mem(text);
    rt.command(Command::Restart {
        line: Some(6),
        sequence: None,
    })
    .unwrap();
    let plan = rt.pending_restart().unwrap().clone();
    assert_eq!(
        (plan.spindle_direction.as_str(), plan.spindle_rpm),
        ("cw", 1000.0)
    );
    assert!(plan.flood);
    assert!(plan.modal.contains(&"G01".to_string()));
    assert_eq!(plan.feed, Some(300.0));
    let kinds: Vec<&str> = plan.path.iter().map(|l| l.kind.as_str()).collect();
    // The axes are at the top of Z already: no retract leg.
    assert_eq!(kinds, ["rapid", "rapid", "feed"]);
    // Block 6 starts at work (-50, -100, -5); the G54 zero is the profile's.
    let g54 = rt.work_offset(0).unwrap();
    let last = &plan.path[2].to;
    assert!((last["x"] - (g54[0] - 50.0)).abs() < 1e-9);
    assert!((last["y"] - (g54[1] - 100.0)).abs() < 1e-9);
    assert!((last["z"] - (g54[2] - 5.0)).abs() < 1e-9);
    // Over at the top of Z (0), down to 5 mm above, feed in.
    assert_eq!(plan.path[0].to["z"], 0.0);
    assert!((plan.path[1].to["z"] - (g54[2])).abs() < 1e-9);
    rt.command(Command::CycleStart).unwrap();
    rt.step(30.0);
    assert_eq!(rt.execution(), Execution::ProgramCompleted);
    let s = rt.state();
    assert!((s.position.work["y"] + 50.0).abs() < 1e-9);

    // From a machine that was jogged down after a broken tool: the
    // retract comes first.
    let mut rt = mem(text);
    rt.command(Command::Mode { mode: Mode::Jog }).unwrap();
    rt.command(Command::Jog {
        axis: "z".into(),
        distance: -100.0,
    })
    .unwrap();
    until(&mut rt, Execution::Ready, 30.0);
    rt.command(Command::Mode { mode: Mode::Mem }).unwrap();
    rt.command(Command::Restart {
        line: Some(6),
        sequence: None,
    })
    .unwrap();
    let plan = rt.pending_restart().unwrap();
    let kinds: Vec<&str> = plan.path.iter().map(|l| l.kind.as_str()).collect();
    assert_eq!(kinds, ["rapid", "rapid", "rapid", "feed"]);
    assert_eq!(plan.path[0].to["z"], 0.0);
    assert_eq!(plan.path[0].to["x"], 0.0);
    // The spindle starts at the retract height, before positioning.
    rt.command(Command::CycleStart).unwrap();
    let mut guard = 0;
    while rt.state().position.machine["z"] < -1e-9 {
        rt.step(0.01);
        guard += 1;
        assert!(guard < 5000);
    }
    // The spindle ramps to 1000 rpm in 0.5 s (2000 rpm/s), then the
    // axes position.
    rt.step(1.0);
    let s = rt.state();
    assert_eq!(s.spindle.direction, "cw");
    assert!(
        s.position.machine["x"] < -1.0,
        "positioning after the spindle: {:?}",
        s.position
    );
    until(&mut rt, Execution::ProgramCompleted, 60.0);
}

#[test]
fn restart_refusals_leave_the_machine_as_it_was() {
    let text = "O1000\nG90 G00 X-10.\n\nM98 P2000\nGOTO 7\nX-20.\nN7 M30\nO2000\nG00 X-30.\nM99\n";
    let mut rt = mem(text);
    let before = serde_json::to_value(rt.state()).unwrap();
    for (line, seq, why) in [
        (Some(99), None, "no line 99"),
        (Some(3), None, "empty"),
        (None, Some(55), "no block N55"),
        (Some(9), None, "subprogram"),
        (Some(6), None, "not executed"),
    ] {
        let err = rt
            .command(Command::Restart {
                line,
                sequence: seq,
            })
            .unwrap_err();
        assert!(err.reason.contains(why), "{line:?}: {}", err.reason);
        assert_eq!(before, serde_json::to_value(rt.state()).unwrap());
    }
    // Not in MDI.
    rt.command(Command::Mode { mode: Mode::Mdi }).unwrap();
    assert!(rt
        .command(Command::Restart {
            line: Some(2),
            sequence: None
        })
        .is_err());
}

const G71_PROG: &str = "G97 S500 M03
G00 X82. Z2.
G71 U2. R0.5
G71 P10 Q60 U0.4 W0.1 F0.25
N10 G00 X30.
N20 G01 Z-20. F0.1
N30 X40. Z-30.
N40 G02 X60. Z-40. R10.
N50 G01 X78.
N60 Z-60.
G70 P10 Q60
G00 X100. Z50.
M30
";

#[test]
fn shape_blocks_are_refused_and_g70_restarts_with_its_shape() {
    let mut rt = common::machine("puma-lathe");
    rt.command(Command::Mode { mode: Mode::Mem }).unwrap();
    rt.load_program("g71.nc", G71_PROG).unwrap();
    let err = rt
        .command(Command::Restart {
            line: None,
            sequence: Some(20),
        })
        .unwrap_err();
    assert!(err.reason.contains("not executed"), "{}", err.reason);
    // At G70 (line 11): the finishing pass runs from the restart and the
    // program ends where the full run ends.
    let full = full_run("puma-lathe", G71_PROG);
    let want = full.at[&11].snap.clone();
    rt.command(Command::Restart {
        line: Some(11),
        sequence: None,
    })
    .unwrap();
    assert_eq!(rt.interp().snapshot(), want);
    let plan = rt.pending_restart().unwrap().clone();
    assert_eq!(
        (plan.spindle_direction.as_str(), plan.spindle_rpm),
        ("cw", 500.0)
    );
    rt.command(Command::CycleStart).unwrap();
    rt.run_until_stopped(1000.0);
    assert_eq!(rt.execution(), Execution::ProgramCompleted);
    let end = full.end.unwrap();
    assert!((rt.interp().machine_position()[2] - end[2]).abs() < 1e-9);
}

#[test]
fn restart_inside_cutter_compensation_is_refused() {
    let text = "G90 G54 G00 X0. Y0. Z10.\nG41 D1 G01 X10. F500\nY10.\nX0.\nG40 G00 X-10.\nM30\n";
    let mut rt = mem(text);
    rt.write_offset(kerf_control::runtime::OffsetWrite::D {
        n: 1,
        geom: Some(5.0),
        wear: None,
    })
    .unwrap();
    for line in [3, 4] {
        let err = rt
            .command(Command::Restart {
                line: Some(line),
                sequence: None,
            })
            .unwrap_err();
        assert!(err.reason.contains("compensation"), "{}", err.reason);
    }
    rt.command(Command::Restart {
        line: Some(2),
        sequence: None,
    })
    .unwrap();
}

#[test]
fn a_mode_change_drops_a_prepared_restart() {
    let text = "G90 G54 G00 X-10. Y-10. Z10.\nG01 Z-1. F300\nX-20.\nM30\n";
    let mut rt = mem(text);
    rt.command(Command::Restart {
        line: Some(3),
        sequence: None,
    })
    .unwrap();
    assert!(rt.pending_restart().is_some());
    rt.command(Command::Mode { mode: Mode::Jog }).unwrap();
    assert!(rt.pending_restart().is_none());
    rt.command(Command::Mode { mode: Mode::Mem }).unwrap();
    // Cycle start now runs the program from its start.
    rt.command(Command::CycleStart).unwrap();
    until(&mut rt, Execution::ProgramCompleted, 60.0);
    let w = rt.state().position.work;
    assert!(
        (w["x"] + 20.0).abs() < 1e-9 && (w["z"] + 1.0).abs() < 1e-9,
        "{w:?}"
    );
}
