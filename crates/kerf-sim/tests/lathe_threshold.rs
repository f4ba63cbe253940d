//! The lathe's threshold of material for the crash checks (docs/sim.md,
//! "Crash checks"): a rapid along a finished face, diameter or taper
//! meets nothing, though the boolean snaps both its region and the
//! section to a grid of 2⁻²⁴ mm and may find a sliver between them; a
//! rapid a hundredth of a millimetre into a finished diameter is
//! reported with the layer it removes, worked out by hand.

mod common;

use std::f64::consts::PI;

use common::Run;
use kerf_sim::{parse_tools, EventKind, SimEvent, ToolTable};

/// A sharp 80° insert (tip 3, bisector 45°: its edges leave the tip at
/// 5° and 85° from +Z toward +X) as tool 1, the same with a 0.8 mm nose
/// as tool 4.
fn tools() -> ToolTable {
    parse_tools(
        "[tool.1]\nnose_radius=0\ntip=3\n[tool.4]\nnose_radius=0.8\ntip=3\n",
        true,
    )
    .unwrap()
}

/// A Ø50 bar (Z0..-100), the tool in, the spindle on; merged cuts or
/// move by move.
fn bar(tool: u32, merge: bool) -> Run {
    let mut r = Run::new("bar:50,100", tools(), None).at(40.0, 0.0, 10.0);
    r.sim.set_lathe_merging(merge);
    r.tool(tool, tool);
    r.spindle(true);
    r
}

fn kinds(events: &[SimEvent]) -> Vec<(EventKind, u32)> {
    events.iter().map(|e| (e.kind, e.line)).collect()
}

#[test]
fn rapids_along_a_finished_diameter_face_and_taper_meet_nothing() {
    for (tool, merge) in [(1, true), (1, false), (4, true), (4, false)] {
        let mut r = bar(tool, merge);
        // A diameter r20 over Z2..-30 and its shoulder, then rapids down
        // onto it, along it both ways.
        r.lrapid(1, 20.0, 2.0);
        r.lfeed(2, 20.0, -30.0);
        r.lfeed(3, 26.0, -30.0);
        r.lrapid(4, 26.0, -20.0);
        r.lrapid(5, 20.0, -20.0);
        r.lrapid(6, 20.0, 2.0);
        r.lrapid(7, 20.0, -25.0);
        // A taper r20 at Z0 to r25 at Z-20, and rapids along it.
        r.lrapid(8, 26.0, 2.0);
        r.lfeed(9, 20.0, 0.0);
        r.lfeed(10, 25.0, -20.0);
        r.lfeed(11, 26.0, -20.0);
        r.lrapid(12, 25.0, -20.0);
        r.lrapid(13, 20.0, 0.0);
        r.lrapid(14, 22.5, -10.0);
        // A face at Z-1 to the axis, and rapids back along it.
        r.lrapid(15, 26.0, -1.0);
        r.lfeed(16, 0.0, -1.0);
        r.lfeed(17, 0.0, 0.0);
        r.lrapid(18, 0.0, -1.0);
        r.lrapid(19, 19.0, -1.0);
        let ev = r.sim.report().events;
        assert!(ev.is_empty(), "tool {tool}, merge {merge}: {ev:?}");
    }
}

#[test]
fn rapids_retracing_random_tapers_meet_nothing() {
    // Tapers at arbitrary (not dyadic) positions and slopes: the rapid
    // along a part of the taper retraces it within the rounding of f64,
    // and the section's vertices and the rapid's differ by the grid's
    // snapping only (a sliver of up to ~1e-5 mm³ on these, which a
    // threshold of 1 nm judged to be a collision).
    let mut seed = 12345u64;
    let mut rnd = || {
        seed = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    for k in 0..120 {
        let (tool, merge) = (if k % 2 == 0 { 1 } else { 4 }, k % 4 < 2);
        let mut r = bar(tool, merge);
        let (x0, z0) = (10.0 + 14.0 * rnd(), -5.0 - 40.0 * rnd());
        let (x1, z1) = (x0 + 3.0 * rnd(), z0 - 1.0 - 40.0 * rnd());
        r.lrapid(1, 26.0, z0 + 3.0);
        r.lfeed(2, x0, z0 + 3.0);
        r.lfeed(3, x0, z0);
        r.lfeed(4, x1, z1);
        r.lfeed(5, 26.0, z1);
        r.lrapid(6, 26.0, z0 + 3.0);
        r.lrapid(7, x0, z0 + 3.0);
        r.lrapid(8, x0, z0);
        let f = rnd();
        r.lrapid(9, x0 + (x1 - x0) * f, z0 + (z1 - z0) * f);
        r.lrapid(10, x0, z0);
        r.lrapid(11, x0, z0 + 3.0);
        let ev = r.sim.report().events;
        assert!(
            ev.is_empty(),
            "{k}: tool {tool} ({x0},{z0})->({x1},{z1}) {f}: {ev:?}"
        );
    }
}

/// Turns r20 over Z2..-30 with `tool`, then rapids in air to (19.99, 5)
/// and along Z to Z-20, 0.01 mm inside the finished diameter: the
/// rapid's events and the volume it removed.
fn rapid_a_hundredth_in(tool: u32, merge: bool) -> (Vec<SimEvent>, f64) {
    let mut r = bar(tool, merge);
    r.lrapid(1, 20.0, 2.0);
    r.lfeed(2, 20.0, -30.0);
    r.lfeed(3, 26.0, -30.0);
    r.lrapid(4, 26.0, 5.0);
    r.lrapid(5, 19.99, 5.0);
    let before = r.sim.report();
    assert!(before.events.is_empty(), "{:?}", before.events);
    r.lrapid(6, 19.99, -20.0);
    let rep = r.sim.report();
    (rep.events, rep.removed_mm3 - before.removed_mm3)
}

#[test]
fn a_rapid_a_hundredth_inside_a_finished_diameter_removes_its_layer() {
    // The material at r 19.99..20 runs from the face Z0 down (the bar is
    // r25 below Z-30). At r = 19.99 + u the sharp tool, its tip at z_t,
    // covers z from z_t + u cot 85° up; swept to z_t = -20 it leaves the
    // layer's z from -20 + u cot 85° to 0: V = 2π ∫₀^0.01 (19.99 + u)
    // (20 - u cot 85°) du.
    let c = 1.0 / 85f64.to_radians().tan();
    let h = 0.01;
    let want =
        2.0 * PI * (20.0 * (19.99 * h + h * h / 2.0) - c * (19.99 * h * h / 2.0 + h * h * h / 3.0));
    // With the 0.8 mm nose (tip 3: its centre 0.8 above and ahead of the
    // programmed point) the layer starts at -20 + 0.8 - √(1.6 u - u²):
    // 2π [19.2 ∫ (19.99 + u) du + ∫ (19.99 + u) √(1.6 u - u²) du], the
    // second integral half the nose's circular segment of height 0.01
    // (area R² acos((R - h)/R) - (R - h) √(2Rh - h²)) at r 19.995, within
    // 0.005 × its area. The nose is held as chords within 0.5 µm inside
    // the arc, which in the layer is 0.8 acos(0.79 / 0.8) = 0.127 mm
    // long: the chords remove up to 0.5e-3 × 0.127 mm² less, 2π × 20 ×
    // 6.3e-5 = 7.9e-3 mm³.
    let rn = 0.8f64;
    let seg = rn * rn * ((rn - h) / rn).acos() - (rn - h) * (2.0 * rn * h - h * h).sqrt();
    let want_nose = 2.0 * PI * (19.2 * (19.99 * h + h * h / 2.0) + 19.995 * seg / 2.0);
    // r 19.99 is held on the grid (2⁻²⁴ mm), within 3e-8 mm: 2π × 20 ×
    // 20 × 3e-8 = 7.5e-5 mm³.
    for (tool, want, below) in [(1, want, 0.0), (4, want_nose, 7.9e-3)] {
        for merge in [true, false] {
            let (ev, v) = rapid_a_hundredth_in(tool, merge);
            assert_eq!(kinds(&ev), [(EventKind::RapidIntoStock, 6)], "{ev:?}");
            assert!(
                v < want + 1e-4 && v > want - below - 1e-4,
                "tool {tool}: {v} vs {want}"
            );
            assert!((ev[0].volume_mm3 - v).abs() < 1e-9);
            // First contact: where the tool's front at the top of the
            // layer (u = 0.01) crosses the face, z_t = 0 for the sharp
            // tool (its 85° edge), z_t = -(0.8 - √(1.6 h - h²)) = -0.674
            // for the nose; the nose's chords (0.5 µm inside the arc
            // along its normal, whose slope there is w / (R - u) = 1 /
            // 6.3) put its front up to 0.5e-3 × 6.3 = 3.2 µm behind the
            // arc's. The removal must also exceed two grid steps along
            // the outline of the region clipped to the material box (its
            // part within 2⁻¹⁰ mm of the material): the sliver under the
            // front of a region that has just reached the face, some
            // 1e-3 mm long, holds 2π × 20 × 1e-3 × 1.2e-7 mm³ (1.5e-8)
            // once the front is 0.1 µm or so past it.
            let at = ev[0].at;
            let front = if tool == 1 {
                0.0
            } else {
                -(rn - (2.0 * rn * h - h * h).sqrt())
            };
            let late = if tool == 1 { 1e-5 } else { 3.2e-3 + 1e-4 };
            assert!(
                at[0] == 19.99 && at[2] < front && at[2] > front - late,
                "{at:?}"
            );
        }
    }
}
