//! A scripted operator at random: 3,000 commands of every kind (valid and
//! not) with random waits, on the three machines. Nothing may panic, a
//! refused command changes nothing, STOPPED always carries an alarm, and
//! the axes stay inside their travel.

mod common;

use common::*;
use kerf_control::runtime::{Command, Execution, Mode, OffsetWrite, Runtime, VarWrite};

struct Lcg(u64);

impl Lcg {
    fn next(&mut self) -> u64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        self.0 >> 33
    }
    fn pick<T: Clone>(&mut self, v: &[T]) -> T {
        v[(self.next() as usize) % v.len()].clone()
    }
}

const MILL: &str = "G90 G54 G00 X-100. Y-100. Z10.\nM03 S1000\nM08\nG01 Z-2. F300\nG41 D1 X-50.\nY-50.\nG40 X-100.\nM01\nG81 X-20. Y-20. Z-5. R2. F100\nX-30.\nG80\n#100 = #100 + 1\nM00 (CHECK)\nG00 Z50.\nM30\n";
const LATHE: &str = "G00 X80. Z5.\nM03 S500\nG01 X60. F0.2\nZ-20.\nG32 Z-40. F2.\nG00 X100.\nM30\n";

fn command(r: &mut Lcg, axes: &[&str]) -> Command {
    let axis = r.pick(axes).to_string();
    match r.next() % 12 {
        0 | 1 => Command::CycleStart,
        2 => Command::FeedHold,
        3 => Command::Reset,
        4 => Command::Mode {
            mode: r.pick(&Mode::ALL),
        },
        5 => Command::Mdi {
            block: r
                .pick(&[
                    "G91 G00 X-1.",
                    "G01 X(",
                    "#100 = 3",
                    "G999",
                    "M00",
                    "G04 X0.2",
                ])
                .into(),
        },
        6 => Command::Restart {
            line: Some((r.next() % 18) as u32),
            sequence: None,
        },
        7 => Command::Switch {
            single_block: Some(r.next().is_multiple_of(2)),
            optional_stop: Some(r.next().is_multiple_of(2)),
            dry_run: Some(r.next().is_multiple_of(4)),
            block_skip: Some(vec![(r.next() % 11) as u8]),
        },
        8 => Command::Override {
            feed: Some((r.next() % 250) as f64),
            rapid: Some((r.next() % 120) as f64),
        },
        9 => Command::Jog {
            axis,
            distance: (r.next() % 200) as f64 - 150.0,
        },
        10 => Command::Handle {
            axis,
            pulses: (r.next() % 400) as i64 - 300,
            increment: r.pick(&[0.001, 0.01, 0.1, 0.5]),
        },
        _ => Command::RefReturn {
            axis: if r.next().is_multiple_of(2) {
                None
            } else {
                Some(axis)
            },
        },
    }
}

fn walk(name: &str, prog: &str, seed: u64) -> std::collections::HashSet<Execution> {
    let mut seen = std::collections::HashSet::new();
    let mut r = Lcg(seed);
    let mut rt: Runtime = machine(name);
    let axes: Vec<&str> = if rt.profile().kind == kerf_interp::MachineKind::Lathe {
        vec!["x", "z", "y"]
    } else {
        vec!["x", "y", "z", "q"]
    };
    rt.load_program("walk.nc", prog).unwrap();
    for _ in 0..1000 {
        let before = serde_json::to_value(rt.state()).unwrap();
        let res = match r.next() % 10 {
            0 => rt.load_program("walk.nc", prog),
            1 => rt.write_offset(OffsetWrite::D {
                n: (r.next() % 140) as usize,
                geom: Some((r.next() % 20) as f64 * 0.5),
                wear: None,
            }),
            2 => rt.write_variable(VarWrite {
                n: (r.next() % 1100) as usize,
                value: Some(1.0),
            }),
            _ => rt.command(command(&mut r, &axes)),
        };
        if res.is_err() {
            let after = serde_json::to_value(rt.state()).unwrap();
            assert_eq!(before, after, "refused {res:?} changed the state");
        }
        rt.step((r.next() % 3000) as f64 / 1000.0);
        let s = rt.state();
        seen.insert(s.execution);
        assert_eq!(
            s.execution == Execution::Stopped,
            s.alarm.is_some(),
            "{s:?}"
        );
        for a in rt.axes() {
            let d = rt.profile().axis(a).unwrap();
            let v = s.position.machine[a.name()];
            assert!(
                v >= d.min - 1e-6 && v <= d.max + 1e-6,
                "{} = {v} outside travel",
                a.name()
            );
        }
    }
    seen
}

#[test]
fn random_operator_on_the_mill() {
    let seen = walk("hx-mc", MILL, 1);
    // The walk gets around: running, held, stopped by alarm and between blocks.
    for x in [
        Execution::Ready,
        Execution::Active,
        Execution::FeedHold,
        Execution::Stopped,
    ] {
        assert!(seen.contains(&x), "{x:?} never reached: {seen:?}");
    }
    assert!(seen.len() >= 6, "{seen:?}");
}

#[test]
fn random_operator_on_the_lathes() {
    let seen = walk("puma-lathe", LATHE, 2);
    assert!(seen.len() >= 4, "{seen:?}");
    walk(
        "hurco-lathe",
        "G21 G00 X80. Z5.\nM03 S500\nG01 X60. F0.2\nZ-20.\nM00\nG00 X100.\nM30\n",
        3,
    );
}
