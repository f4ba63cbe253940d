//! The height field's threshold of material (docs/sim.md, "Crash
//! checks"): a rapid that only retraces what is already cut removes
//! nothing, whatever the f32 rounding of the heights it passes over; a
//! rapid a hundredth of a millimetre (or ten nanometres) below a cut
//! surface removes that layer and is reported. Heights near Z50 are
//! stored to 2⁻¹⁸ mm (3.8 nm), so these are the cases in which a
//! threshold of 1 nm judged rounding to be material.

mod common;

use common::Run;
use kerf_sim::{parse_tools, EventKind, ToolTable};

const BALL10: &str = "[tool.1]\nkind=\"ball\"\ndiameter=10\n";
const FLAT10: &str = "[tool.1]\nkind=\"flat\"\ndiameter=10\n";

fn tools(t: &str) -> ToolTable {
    parse_tools(t, false).unwrap()
}

/// A 40 × 30 × 50 block at 0.05 mm cells (800 × 600), the spindle on.
fn block(tool: &str, at: [f64; 3]) -> Run {
    let mut r = Run::new("box:0,0,0,40,30,50", tools(tool), Some(0.05)).at(at[0], at[1], at[2]);
    r.spindle(true);
    r
}

fn removed(r: &Run) -> f64 {
    r.sim.report().removed_mm3
}

#[test]
fn rapids_out_of_and_back_along_a_ball_cut_remove_nothing() {
    // A slot at Z45 from outside the block to X20, a ramp up to Z46.3 at
    // X30, the surface_1m program's own steps of 6.2292 mm at Z37..43
    // (its lines 2997-3000, shifted), then rapids: straight up out of
    // the cut, straight down back into it, back along the ramp and the
    // slot, and up again.
    let mut r = block(BALL10, [-10.0, 15.0, 60.0]);
    r.feed(1, -10.0, 15.0, 45.0);
    r.feed(2, 20.0, 15.0, 45.0);
    r.feed(3, 30.0, 15.0, 46.3);
    r.feed(4, 30.0, 22.0, 46.3);
    for (line, x, z) in [
        (5, 12.0, 38.0201),
        (6, 18.2292, 39.4114),
        (7, 24.4584, 41.2374),
        (8, 30.6875, 43.0009),
    ] {
        r.feed(line, x, 22.0, z);
    }
    let cut = removed(&r);
    assert!(cut > 1000.0, "{cut}");
    r.rapid(9, 30.6875, 22.0, 60.0);
    r.rapid(10, 30.6875, 22.0, 43.0009);
    r.rapid(11, 24.4584, 22.0, 41.2374);
    r.rapid(12, 30.6875, 22.0, 43.0009);
    r.rapid(13, 30.6875, 22.0, 60.0);
    r.rapid(14, 30.0, 15.0, 60.0);
    r.rapid(15, 30.0, 15.0, 46.3);
    r.rapid(16, 20.0, 15.0, 45.0);
    r.rapid(17, -10.0, 15.0, 45.0);
    r.rapid(18, -10.0, 15.0, 60.0);
    let rep = r.sim.report();
    assert!(rep.events.is_empty(), "{:?}", rep.events);
    assert_eq!(rep.removed_mm3, cut);
}

/// A ball slot at Z45 along Y15 right across the block, then a rapid
/// across it `depth` below the slot: the layer removed, and the event.
fn slot_and_rapid_below(depth: f64) -> (f64, Vec<kerf_sim::SimEvent>) {
    let mut r = block(BALL10, [-10.0, 15.0, 45.0]);
    r.feed(1, 50.0, 15.0, 45.0);
    r.rapid(2, 50.0, 15.0, 60.0);
    r.rapid(3, -10.0, 15.0, 60.0);
    r.rapid(4, -10.0, 15.0, 45.0 - depth);
    let before = removed(&r);
    r.rapid(5, 50.0, 15.0, 45.0 - depth);
    let rep = r.sim.report();
    (rep.removed_mm3 - before, rep.events)
}

#[test]
fn a_rapid_a_hundredth_below_a_ball_slot_removes_the_layer() {
    // Over the slot every column within 5 mm of Y15 (the cell centres
    // Y10.025..19.975: 200 rows, 10 mm) is at Z50 - √(25 - dy²); the
    // rapid's ball, 0.01 lower on the same line, leaves 49.99 - √(25 -
    // dy²): 0.01 mm more under each of them, over the block's 40 mm:
    // 0.01 × 10 × 40 = 4 mm³ (the heights are f32, 3.8 nm at Z45-50:
    // 160,000 cells × 0.0025 mm² × 1.9e-6 mm bounds the rounding).
    let (v, events) = slot_and_rapid_below(0.01);
    assert!((v - 4.0).abs() < 1e-3, "{v}");
    assert_eq!(events.len(), 1, "{events:?}");
    let e = &events[0];
    assert_eq!((e.kind, e.line), (EventKind::RapidIntoStock, 5));
    assert!((e.volume_mm3 - v).abs() < 1e-12, "{} vs {v}", e.volume_mm3);
    // First contact: the first column of cells (X0.025, Y15 ± 0.025, at
    // Z50 - s with s = √(25 - 0.025²)) is lowered once the ball's front
    // sphere, centred at Z49.99 and dx behind it, is below it: s - √(s² -
    // dx²) < 0.01 ⟺ dx² < 0.02 s - 0.0001; the tip is then at 0.025 - dx.
    // The cell's stored height is within half an f32 step (1.9e-6 mm) of
    // Z50 - s, a lowering must exceed one step (3.8e-6) to count, and dx
    // moves by (s - 0.01) / dx = 15.8 times a change of that depth:
    // within 16 × 5.7e-6 = 9.1e-5 mm.
    let s = (25.0f64 - 0.025 * 0.025).sqrt();
    let dx = (0.02 * s - 0.0001).sqrt();
    let x = 0.025 - dx;
    assert!(((s - 0.01) / dx - 15.8).abs() < 0.05);
    assert!((e.at[0] - x).abs() < 9.1e-5, "{:?} vs {x}", e.at);
    assert!((e.at[2] - 44.99).abs() < 1e-12, "{:?}", e.at);
}

#[test]
fn a_rapid_ten_nanometres_below_a_ball_slot_is_reported_too() {
    // 1e-5 mm is above the model's resolution at Z50 (an f32 step,
    // 3.8e-6): 1e-5 × 10 × 40 = 4e-3 mm³, each cell's removal rounded
    // by up to 1.9e-6 mm (some 20 % of it at worst, far less summed).
    let (v, events) = slot_and_rapid_below(1e-5);
    assert!((v - 4e-3).abs() < 4e-4, "{v}");
    assert_eq!(events.len(), 1, "{events:?}");
    assert_eq!(events[0].kind, EventKind::RapidIntoStock);
}

#[test]
fn a_rapid_at_the_height_of_a_level_flat_cut_removes_nothing() {
    // A height whose f32 is above it by more than 1e-6 mm: the cells cut
    // to it are stored higher than the tool, and a rapid at the same
    // height meets nothing all the same.
    let z = (0..1000)
        .map(|k| 45.0 + k as f64 * 1e-4)
        .find(|&z| (z as f32) as f64 - z > 1.2e-6)
        .unwrap();
    let mut r = block(FLAT10, [-10.0, 15.0, z]);
    r.feed(1, 50.0, 15.0, z);
    let cut = removed(&r);
    r.rapid(2, -10.0, 15.0, z);
    r.rapid(3, 50.0, 15.0, z);
    let rep = r.sim.report();
    assert!(rep.events.is_empty(), "{:?}", rep.events);
    assert_eq!(rep.removed_mm3, cut);
    // 0.01 lower across the block: a layer of 0.01 mm over the 200 rows
    // of cell centres within 5 mm of Y15 (10 mm) and 40 mm: 4 mm³.
    r.rapid(4, 50.0, 15.0, z - 0.01);
    r.rapid(5, -10.0, 15.0, z - 0.01);
    let rep = r.sim.report();
    assert_eq!(rep.events.len(), 1, "{:?}", rep.events);
    let v = rep.removed_mm3 - cut;
    assert!((v - 4.0).abs() < 1e-3, "{v}");
}
