//! The mode table, walked: every reachable (mode, state) pair is set up on
//! a real runtime and every operation applied; the result must be the
//! table's (docs/runtime.md), and a refused operation must leave the state
//! (the whole state JSON and the history) as it was.

mod common;

use common::*;
use kerf_control::runtime::{
    decide, mode_table_markdown, reachable, Command, Execution, Mode, OffsetWrite, Op, Runtime,
    VarWrite, Verdict,
};

const LONG: &str = "G91 G01 X-50. F600\nM30\n";

/// A runtime in mode `m`, state `x`.
fn reach(m: Mode, x: Execution) -> Runtime {
    let mut rt = machine("hx-mc");
    let prog = match x {
        Execution::Stopped => "G91 G01 X-1. F600\nG999\n",
        Execution::OptionalStop => "M01\nG91 G01 X-1. F600\nM30\n",
        Execution::ProgramStopped => "M00\nG91 G01 X-1. F600\nM30\n",
        Execution::ProgramCompleted => "M30\n",
        _ => LONG,
    };
    rt.load_program("t.nc", prog).unwrap();
    let go = |rt: &mut Runtime, c: Command| rt.command(c).unwrap();
    match m {
        Mode::Mem => {
            go(&mut rt, Command::Mode { mode: Mode::Mem });
            match x {
                Execution::Ready => {}
                Execution::Interrupted => {
                    go(&mut rt, sw_single(true));
                    go(&mut rt, Command::CycleStart);
                    until(&mut rt, x, 30.0);
                }
                Execution::OptionalStop => {
                    go(&mut rt, sw_opt(true));
                    go(&mut rt, Command::CycleStart);
                    until(&mut rt, x, 30.0);
                }
                Execution::Active | Execution::FeedHold => {
                    go(&mut rt, Command::CycleStart);
                    rt.step(1.0);
                    if x == Execution::FeedHold {
                        go(&mut rt, Command::FeedHold);
                    }
                }
                _ => {
                    go(&mut rt, Command::CycleStart);
                    until(&mut rt, x, 30.0);
                }
            }
        }
        Mode::Mdi => {
            go(&mut rt, Command::Mode { mode: Mode::Mdi });
            let text = match x {
                Execution::Stopped => "G999",
                Execution::OptionalStop => "M01\nG91 G01 X-1. F600",
                Execution::ProgramStopped => "M00\nG91 G01 X-1. F600",
                Execution::Interrupted => "G91 G01 X-1. F600\nX-1.",
                _ => "G91 G01 X-50. F600",
            };
            if x == Execution::OptionalStop {
                go(&mut rt, sw_opt(true));
            }
            if x == Execution::Interrupted {
                go(&mut rt, sw_single(true));
            }
            if x != Execution::Ready {
                go(&mut rt, Command::Mdi { block: text.into() });
                rt.step(1.0);
                if x == Execution::FeedHold {
                    go(&mut rt, Command::FeedHold);
                } else if x != Execution::Active {
                    until(&mut rt, x, 30.0);
                }
            }
        }
        Mode::Edit | Mode::Jog | Mode::Ref => {
            if x == Execution::Stopped {
                go(&mut rt, Command::Mode { mode: Mode::Mem });
                go(&mut rt, Command::CycleStart);
                until(&mut rt, x, 30.0);
            }
            go(&mut rt, Command::Mode { mode: m });
            if x == Execution::Active {
                if m == Mode::Jog {
                    go(
                        &mut rt,
                        Command::Jog {
                            axis: "x".into(),
                            distance: -50.0,
                        },
                    );
                } else {
                    // Away first, then back to the reference.
                    go(&mut rt, Command::Mode { mode: Mode::Jog });
                    go(
                        &mut rt,
                        Command::Jog {
                            axis: "x".into(),
                            distance: -50.0,
                        },
                    );
                    until(&mut rt, Execution::Ready, 30.0);
                    go(&mut rt, Command::Mode { mode: Mode::Ref });
                    go(&mut rt, Command::RefReturn { axis: None });
                }
                rt.step(0.2);
            }
        }
    }
    assert_eq!(
        (rt.mode(), rt.execution()),
        (m, x),
        "could not reach {m:?} {x:?}"
    );
    rt
}

fn sw_single(on: bool) -> Command {
    Command::Switch {
        single_block: Some(on),
        optional_stop: None,
        dry_run: None,
        block_skip: None,
    }
}

fn sw_opt(on: bool) -> Command {
    Command::Switch {
        single_block: None,
        optional_stop: Some(on),
        dry_run: None,
        block_skip: None,
    }
}

/// Applies `op` with valid data; Err(reason) when refused.
fn apply(rt: &mut Runtime, op: Op) -> Result<(), String> {
    let r = match op {
        Op::CycleStart => rt.command(Command::CycleStart),
        Op::FeedHold => rt.command(Command::FeedHold),
        Op::Reset => rt.command(Command::Reset),
        Op::Mode(m) => rt.command(Command::Mode { mode: m }),
        Op::Mdi => rt.command(Command::Mdi {
            block: "G91 G01 X-1. F600".into(),
        }),
        Op::Restart => rt.command(Command::Restart {
            line: Some(1),
            sequence: None,
        }),
        Op::Switch => rt.command(Command::Switch {
            single_block: None,
            optional_stop: None,
            dry_run: Some(false),
            block_skip: None,
        }),
        Op::Override => rt.command(Command::Override {
            feed: Some(100.0),
            rapid: None,
        }),
        Op::Jog => rt.command(Command::Jog {
            axis: "x".into(),
            distance: -1.0,
        }),
        Op::Handle => rt.command(Command::Handle {
            axis: "x".into(),
            pulses: -10,
            increment: 0.01,
        }),
        Op::RefReturn => rt.command(Command::RefReturn { axis: None }),
        Op::LoadProgram => rt.load_program("u.nc", LONG),
        Op::WriteOffset => rt.write_offset(OffsetWrite::H {
            n: 1,
            geom: Some(10.0),
            wear: None,
        }),
        Op::WriteParameter => rt.write_parameter("PI 144", 0.0),
        Op::WriteVariable => rt.write_variable(VarWrite {
            n: 100,
            value: Some(1.0),
        }),
    };
    r.map_err(|e| e.reason)
}

#[test]
fn every_triple_gives_the_table_result() {
    let mut checked = 0;
    for m in Mode::ALL {
        for x in Execution::ALL {
            if !reachable(m, x) {
                continue;
            }
            for op in Op::all() {
                let mut rt = reach(m, x);
                let before = serde_json::to_value(rt.state()).unwrap();
                let alarms = rt.alarms(0).len();
                let got = apply(&mut rt, op);
                match decide(m, x, op) {
                    Verdict::Refuse(reason) => {
                        assert_eq!(got, Err(reason.to_string()), "{m:?} {x:?} {op:?}");
                        let after = serde_json::to_value(rt.state()).unwrap();
                        assert_eq!(
                            before, after,
                            "refused {op:?} changed the state in {m:?} {x:?}"
                        );
                        assert_eq!(rt.alarms(0).len(), alarms);
                    }
                    Verdict::Allow(next) => {
                        assert_eq!(got, Ok(()), "{m:?} {x:?} {op:?}");
                        let want = next.unwrap_or(x);
                        assert_eq!(rt.execution(), want, "{m:?} {x:?} {op:?}");
                        if let Op::Mode(to) = op {
                            assert_eq!(rt.mode(), to);
                        } else {
                            assert_eq!(rt.mode(), m);
                        }
                    }
                }
                checked += 1;
            }
        }
    }
    // 5 modes: MEM 8 states, MDI 7, EDIT 2, JOG 3, REF 3 = 23 pairs × 19.
    assert_eq!(checked, 23 * 19);
}

#[test]
fn docs_print_the_table() {
    let doc = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../docs/runtime.md"
    ))
    .expect("docs/runtime.md");
    let table = mode_table_markdown();
    assert!(
        doc.contains(table.trim()),
        "docs/runtime.md does not hold the mode table; regenerate it:\n{table}"
    );
}
