//! The lathe's merged and batched cuts (deferred.rs) against the
//! move-by-move path: random programs of feed chains (collinear pieces
//! and turns), arcs, rapids (into the bar or not), the spindle stopped
//! and started, and tools with and without a holder leave the same
//! section, the same volumes and the same events, at the same block,
//! position and time.

mod common;

use common::Run;
use kerf_canon::Plane;
use kerf_sim::{parse_tools, Model, SimReport, ToolTable};
use proptest::prelude::*;

/// A sharp 80° insert (1), a 0.8 mm-nose insert (4), a grooving blade
/// with a holder 7 mm wide from 5 mm above its tip (9).
fn tools() -> ToolTable {
    parse_tools(
        "[tool.1]\nnose_radius=0\ntip=3\n[tool.4]\nnose_radius=0.8\ntip=3\n\
         [tool.9]\nkind=\"groove\"\nwidth=3\ndepth=4\ntip=3\n\
         holder=[[-2,5],[5,5],[5,30],[-2,30]]\n",
        true,
    )
    .unwrap()
}

#[derive(Clone, Debug)]
enum Op {
    /// Feed to (x radius, z) in this many equal collinear pieces.
    Chain(f64, f64, u32),
    /// Feed by (dx, dz), short (a turn off the last move's line).
    Nudge(f64, f64),
    /// A quarter-ish arc in ZX to (x, z) about its midpoint offset.
    Arc(f64, f64, bool),
    Rapid(f64, f64),
    Spindle(bool),
    Tool(u32),
}

fn op() -> impl Strategy<Value = Op> {
    prop_oneof![
        4 => (0.0f64..30.0, -105.0f64..5.0, 1u32..6).prop_map(|(x, z, n)| Op::Chain(x, z, n)),
        3 => (-1.0f64..1.0, -2.0f64..2.0).prop_map(|(x, z)| Op::Nudge(x, z)),
        1 => (5.0f64..28.0, -100.0f64..0.0, any::<bool>()).prop_map(|(x, z, c)| Op::Arc(x, z, c)),
        2 => (0.0f64..32.0, -105.0f64..5.0).prop_map(|(x, z)| Op::Rapid(x, z)),
        1 => any::<bool>().prop_map(Op::Spindle),
        1 => prop_oneof![Just(1u32), Just(4), Just(9)].prop_map(Op::Tool),
    ]
}

/// Runs the program; returns the report and the section's radius
/// intervals on a few lines z = const.
fn simulate(ops: &[Op], merge: bool) -> (SimReport, Vec<Vec<(f64, f64)>>) {
    let mut r = Run::new("bar:50,100", tools(), None).at(40.0, 0.0, 10.0);
    r.sim.set_lathe_merging(merge);
    r.tool(4, 4);
    r.spindle(true);
    for (i, o) in ops.iter().enumerate() {
        let line = i as u32 + 1;
        let (x0, z0) = (r.pos[0], r.pos[2]);
        match *o {
            Op::Chain(x, z, n) => {
                for k in 1..=n {
                    let f = k as f64 / n as f64;
                    r.lfeed(line, x0 + (x - x0) * f, z0 + (z - z0) * f);
                }
            }
            Op::Nudge(dx, dz) => r.lfeed(line, (x0 + dx).max(0.0), z0 + dz),
            Op::Arc(x, z, ccw) => {
                // About the chord's midpoint moved off it by a quarter of
                // its length: a real arc, less than a half circle.
                let (mx, mz) = ((x0 + x) / 2.0, (z0 + z) / 2.0);
                let (c_x, c_z) = (mx + (z - z0) / 4.0, mz - (x - x0) / 4.0);
                r.arc(line, [x, 0.0, z], [c_x, 0.0, c_z], ccw, Plane::ZX, 0);
            }
            Op::Rapid(x, z) => r.lrapid(line, x, z),
            Op::Spindle(on) => r.spindle(on),
            Op::Tool(n) => r.tool(n, n),
        }
    }
    let rep = r.sim.report();
    let Model::Lathe(s) = r.sim.model() else {
        panic!("a lathe model")
    };
    let zs = (0..24).map(|k| -103.7 + 4.5 * k as f64);
    (rep, zs.map(|z| s.intervals_at(z)).collect())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]
    #[test]
    fn merged_cuts_leave_what_move_by_move_cuts_leave(
        ops in proptest::collection::vec(op(), 1..16),
    ) {
        let (a, sa) = simulate(&ops, true);
        let (b, sb) = simulate(&ops, false);
        // Volumes to within the grid's snapping (intersections land on a
        // 6e-8 mm grid, in a different order on the two paths).
        prop_assert!((a.removed_mm3 - b.removed_mm3).abs() < 1e-3, "{} {}", a.removed_mm3, b.removed_mm3);
        prop_assert!((a.remaining_mm3 - b.remaining_mm3).abs() < 1e-3);
        prop_assert_eq!(a.events.len(), b.events.len(), "{:?} vs {:?}", a.events, b.events);
        prop_assert_eq!(a.collisions, b.collisions);
        for (e, f) in a.events.iter().zip(&b.events) {
            prop_assert_eq!((e.kind, e.line, e.tool), (f.kind, f.line, f.tool));
            // The first contact is found by bisection on the two stocks,
            // which differ by the grid's snapping (about 6e-8 mm) and by
            // slivers thinner than that which one boolean leaves and the
            // other does not: where the move grazes them, the contact
            // moves along it: the contact is the first point of the move
            // past which it removes more than VOL_EPS, and a move meeting
            // the stock at an angle θ puts that point 1/sin θ further along
            // for the same difference across the surface (0.17 µm seen on
            // most cases; 1.01 µm on a rapid 3.8° off the axis). Along the
            // move within 10 µm; the volumes and the stocks left are held
            // to the tighter bounds above and below.
            prop_assert!((e.t - f.t).abs() < 1e-2, "{e:?} vs {f:?}");
            for k in 0..3 {
                prop_assert!((e.at[k] - f.at[k]).abs() < 1e-2, "{e:?} vs {f:?}");
            }
            prop_assert!((e.volume_mm3 - f.volume_mm3).abs() < 1e-3, "{e:?} vs {f:?}");
        }
        for (p, q) in sa.iter().zip(&sb) {
            prop_assert_eq!(p.len(), q.len(), "{:?} vs {:?}", p, q);
            for (u, v) in p.iter().zip(q) {
                prop_assert!((u.0 - v.0).abs() < 1e-6 && (u.1 - v.1).abs() < 1e-6, "{p:?} vs {q:?}");
            }
        }
    }
}

/// A G71-style roughing in 0.5 mm moves and its retracts: merged, the
/// passes are one region each; the removed volume is still the bar less
/// the shape, worked out by hand.
#[test]
fn roughing_in_short_moves_removes_the_bar_down_to_the_passes() {
    for merge in [true, false] {
        let mut r = Run::new("bar:50,100", tools(), None).at(40.0, 0.0, 10.0);
        r.sim.set_lathe_merging(merge);
        r.tool(1, 1);
        r.spindle(true);
        // Sharp insert: passes at r 24, 23, 22 from Z1 past the bar's end
        // (Z-100) to Z-101, each in 204 pieces, lifted 0.5 and back by
        // rapid.
        for k in 0..3 {
            let x = 24.0 - k as f64;
            r.lrapid(1, x, 1.0);
            for i in 1..=204 {
                r.lfeed(2, x, 1.0 - 0.5 * i as f64);
            }
            r.lrapid(3, x + 0.5, -101.0);
            r.lrapid(4, x + 0.5, 1.0);
        }
        let rep = r.sim.report();
        assert!(rep.events.is_empty(), "{:?}", rep.events);
        // π (25² - 22²) 100
        let want = std::f64::consts::PI * (625.0 - 484.0) * 100.0;
        assert!((rep.removed_mm3 - want).abs() < 1e-6, "{}", rep.removed_mm3);
    }
}
