//! The height field cut by one thread and by two (the worker owning the
//! odd bands, pipe.rs): random mill programs give the same heights, the
//! same removed volume and the same events, bit for bit, with the default
//! queue and with one short enough to fill at every move.

mod common;

use common::Run;
use kerf_canon::Plane;
use kerf_sim::{parse_tools, Model, SimReport};
use proptest::prelude::*;

/// Four tools: a ball, a flat end mill with a holder, a bull that does not
/// cut at its centre, a drill.
const TOOLS: &str = r#"
[tool.1]
kind = "ball"
diameter = 6
[tool.2]
kind = "flat"
diameter = 4
flute_length = 3
holder = [[8, 10]]
[tool.3]
kind = "bull"
diameter = 5
corner_radius = 1
centre_cutting = false
[tool.4]
kind = "drill"
diameter = 3
"#;

/// One step of a program.
#[derive(Clone, Debug)]
enum Step {
    Feed([f64; 3]),
    Rapid([f64; 3]),
    /// A quarter or half circle in XY around a centre offset from here.
    Arc {
        dx: f64,
        dy: f64,
        z: f64,
        ccw: bool,
    },
    Spindle(bool),
    Tool(u32),
}

fn point() -> impl Strategy<Value = [f64; 3]> {
    (-3.0f64..43.0, -3.0f64..33.0, -6.0f64..2.0).prop_map(|(x, y, z)| [x, y, z])
}

fn step() -> impl Strategy<Value = Step> {
    prop_oneof![
        8 => point().prop_map(Step::Feed),
        2 => point().prop_map(Step::Rapid),
        2 => (-8.0f64..8.0, -8.0f64..8.0, -5.0f64..1.0, any::<bool>())
            .prop_map(|(dx, dy, z, ccw)| Step::Arc { dx, dy, z, ccw }),
        1 => any::<bool>().prop_map(Step::Spindle),
        1 => (1u32..5).prop_map(Step::Tool),
    ]
}

/// The heights and the report after `steps` on `threads` threads with a
/// queue of `queue` moves.
fn run(steps: &[Step], threads: usize, queue: usize) -> (Vec<f32>, SimReport) {
    let tools = parse_tools(TOOLS, false).unwrap();
    let mut r = Run::new("box:0,0,-5,40,30,0", tools, Some(0.2)).at(20.0, 15.0, 5.0);
    r.sim.set_threads(threads);
    r.sim.set_queue(queue);
    r.spindle(true);
    r.tool(1, 1);
    for (k, s) in steps.iter().enumerate() {
        let line = k as u32 + 2;
        match *s {
            Step::Feed(p) => r.feed(line, p[0], p[1], p[2]),
            Step::Rapid(p) => r.rapid(line, p[0], p[1], p[2]),
            Step::Arc { dx, dy, z, ccw } => {
                let (x, y) = (r.pos[0], r.pos[1]);
                let c = [x + dx, y + dy, z];
                // A half turn: the point opposite across the centre.
                let to = [x + 2.0 * dx, y + 2.0 * dy, z];
                r.arc(line, to, c, ccw, Plane::XY, 1);
            }
            Step::Spindle(on) => r.spindle(on),
            Step::Tool(n) => r.tool(n, n),
        }
    }
    let rep = r.sim.report();
    let Model::Mill(z) = r.sim.model() else {
        unreachable!("a box is a height field")
    };
    (z.h.clone(), rep)
}

fn same(a: &(Vec<f32>, SimReport), b: &(Vec<f32>, SimReport)) -> Result<(), TestCaseError> {
    let bits = |h: &[f32]| h.iter().map(|v| v.to_bits()).collect::<Vec<_>>();
    prop_assert!(bits(&a.0) == bits(&b.0), "heights differ");
    prop_assert_eq!(a.1.removed_mm3.to_bits(), b.1.removed_mm3.to_bits());
    prop_assert_eq!(a.1.remaining_mm3.to_bits(), b.1.remaining_mm3.to_bits());
    prop_assert_eq!(&a.1.events, &b.1.events);
    prop_assert_eq!(a.1.collisions, b.1.collisions);
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]
    /// Feeds, arcs as chords, rapids into the stock, the spindle stopped,
    /// a tool with a holder, tool changes: one thread and two (a queue of
    /// 4,096 moves and one of 1) give the same heights, volumes and events.
    #[test]
    fn two_threads_give_what_one_gives(steps in prop::collection::vec(step(), 1..40)) {
        let one = run(&steps, 1, 4096);
        same(&one, &run(&steps, 2, 4096))?;
        same(&one, &run(&steps, 2, 1))?;
    }
}

/// A long program of plain feeds fills a short queue many times (the
/// caller waits for the worker) and ends with the same heights and volume.
#[test]
fn a_full_queue_waits_for_the_worker() {
    let steps: Vec<Step> = (0..400)
        .map(|k| {
            let x = if k % 2 == 0 { 2.0 } else { 38.0 };
            Step::Feed([x, 2.0 + k as f64 * 0.065, -1.0 - (k % 7) as f64 * 0.3])
        })
        .collect();
    let one = run(&steps, 1, 4096);
    for q in [1, 2, 3, 17] {
        same(&one, &run(&steps, 2, q)).unwrap();
    }
    assert!(one.1.removed_mm3 > 0.0);
}
