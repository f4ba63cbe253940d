//! Lathe: removed volumes of revolution against their formulas, the
//! profile left, and the crash checks.

mod common;

use std::f64::consts::PI;

use common::Run;
use kerf_canon::Plane;
use kerf_sim::{parse_tools, EventKind, Model, ToolTable};

/// A sharp 80° insert (tip 3, OD) as tool 1, a sharp boring insert
/// (tip 2) as tool 2, a 3 mm grooving blade as tool 3.
fn tools() -> ToolTable {
    parse_tools(
        "[tool.1]\nnose_radius=0\ntip=3\n[tool.2]\nnose_radius=0\ntip=2\n\
         [tool.3]\nkind=\"groove\"\nwidth=3\ntip=3\n[tool.4]\nnose_radius=0.8\ntip=3\n",
        true,
    )
    .unwrap()
}

fn run(stock: &str) -> Run {
    let mut r = Run::new(stock, tools(), None).at(40.0, 0.0, 10.0);
    r.tool(1, 1);
    r.spindle(true);
    r
}

fn close(got: f64, want: f64, tol: f64) {
    assert!((got - want).abs() <= tol, "{got} vs {want} ± {tol}");
}

/// The material's outer radius at z.
fn outer(r: &Run, z: f64) -> f64 {
    let Model::Lathe(s) = r.sim.model() else {
        panic!()
    };
    s.intervals_at(z).last().map_or(0.0, |iv| iv.1)
}

#[test]
fn facing_a_tube_removes_pi_r2_minus_r2_times_the_depth() {
    let mut r = run("tube:50,20,100");
    r.lrapid(1, 27.0, -2.0);
    r.lfeed(2, 5.0, -2.0);
    // pi (25² - 10²) * 2; the face at Z-2 falls on a column edge (100 / 0.005).
    let rep = r.sim.report();
    close(rep.removed_mm3, PI * (625.0 - 100.0) * 2.0, 1e-6);
    assert!(rep.events.is_empty(), "{:?}", rep.events);
    // The section is exact; the resolution is the arcs' chord tolerance.
    assert_eq!(rep.resolution_mm, 0.0005);
}

#[test]
fn a_turned_step_and_a_taper() {
    let mut r = run("bar:50,100");
    r.lrapid(1, 20.0, 2.0);
    r.lfeed(2, 20.0, -30.0);
    r.lfeed(3, 26.0, -30.0);
    close(
        r.sim.report().removed_mm3,
        PI * (625.0 - 400.0) * 30.0,
        1e-6,
    );
    close(outer(&r, -15.0), 20.0, 1e-9);
    close(outer(&r, -30.01), 25.0, 1e-9);
    // Taper from r 20 at Z-40 to r 25 at Z-60 (fresh material from -30):
    let mut r = run("bar:50,100");
    r.lrapid(1, 20.0, -40.0 + 0.0);
    let mut r2 = run("bar:50,100");
    r2.lrapid(1, 26.0, 2.0);
    r2.lfeed(2, 20.0, 0.0);
    r2.lfeed(3, 25.0, -20.0);
    r2.lfeed(4, 26.0, -20.0);
    // pi ∫ (25² - r²) dz with r linear 20..25 over 20: 20 (400+500+625)/3.
    let want = PI * (625.0 * 20.0 - 20.0 * 1525.0 / 3.0);
    // The midpoint rule on r² is exact to dz² r'² L: below 1e-3 mm³.
    close(r2.sim.report().removed_mm3, want, 1e-3);
    // The profile: r = 20 + 5 (-z) / 20 within 1 µm at any column centre.
    for z in [-1.0025, -7.5025, -13.3375, -19.9975] {
        close(outer(&r2, z), 20.0 - z / 4.0, 1e-6);
    }
    drop(r);
}

#[test]
fn a_bore_in_a_tube() {
    let mut r = run("tube:60,20,100");
    r.tool(2, 2);
    r.lrapid(1, 15.0, 2.0);
    r.lfeed(2, 15.0, -25.0);
    r.lfeed(3, 10.0, -25.0);
    r.lrapid(4, 10.0, 2.0);
    let rep = r.sim.report();
    close(rep.removed_mm3, PI * (225.0 - 100.0) * 25.0, 1e-6);
    assert!(rep.events.is_empty(), "{:?}", rep.events);
}

#[test]
fn a_groove_is_its_width_by_its_depth() {
    let mut r = run("bar:50,100");
    r.tool(3, 3);
    r.lrapid(1, 27.0, -10.0);
    r.lfeed(2, 20.0, -10.0);
    r.lfeed(3, 27.0, -10.0);
    close(r.sim.report().removed_mm3, PI * (625.0 - 400.0) * 3.0, 1e-6);
    close(outer(&r, -8.5), 20.0, 1e-9);
    close(outer(&r, -10.01), 25.0, 1e-9);
}

#[test]
fn a_nose_radius_leaves_its_corner_radius() {
    // OD pass at tip radius 20 to a shoulder at Z-20 with a 0.8 nose: the
    // corner left is a quarter circle of 0.8 centred at (z -19.2, r 20.8).
    let mut r = run("bar:50,100");
    r.tool(4, 4);
    r.lrapid(1, 20.0, 2.0);
    r.lfeed(2, 20.0, -20.0);
    r.lfeed(3, 26.0, -20.0);
    // The nose is chorded within 0.5 µm: the profile's distance from the
    // corner's centre is 0.8 less at most that.
    for z in [-19.2025, -19.5025, -19.9025] {
        let d = (z + 19.2f64).hypot(outer(&r, z) - 20.8);
        assert!((0.8 - 0.5e-3..=0.8).contains(&d), "{z}: {d}");
    }
    close(outer(&r, -10.0025), 20.0, 1e-9);
}

#[test]
fn a_rapid_into_the_bar_is_reported_at_its_line_and_contact() {
    let mut r = run("bar:50,100");
    // Z-10.0025 is a column centre (columns of 0.005 from Z-100).
    r.lrapid(1, 30.0, -10.0025);
    r.lrapid(5, 20.0, -10.0025);
    let rep = r.sim.report();
    assert_eq!(rep.events.len(), 1, "{:?}", rep.events);
    let e = &rep.events[0];
    assert_eq!((e.kind, e.line), (EventKind::RapidIntoStock, 5));
    // The sharp tip touches the OD (r 25) half way; Z is the move's. The
    // contact is where the removal exceeds two grid steps (2⁻²⁴ mm) along
    // the outline of the region clipped to the material box (the tip's
    // triangle up to 2⁻¹⁰ mm above the OD, its edges at 5° and 85°: some
    // 0.023 mm, so 2π × 25 × 0.023 × 1.2e-7 = 4.3e-7 mm³); the triangle
    // of depth d under the OD, d² (cot 5° - cot 85°) / 2 = 5.67 d² mm²,
    // holds that from d = 2.2e-5 mm: the tip within 3e-5 mm inside the
    // OD, and the time within 3e-6 s (10 mm in 1 s).
    assert!(e.at[0] < 25.0 && e.at[0] > 25.0 - 3e-5, "{:?}", e.at);
    close(e.at[2], -10.0025, 1e-12);
    close(e.t, 1.5, 3e-6);
    assert!(rep.collided());
}

#[test]
fn cutting_with_the_spindle_stopped_and_a_holder_that_hits() {
    let mut r = run("bar:50,100");
    r.spindle(false);
    r.lrapid(1, 26.0, -10.0);
    r.lfeed(7, 24.0, -10.0);
    let rep = r.sim.report();
    assert_eq!(rep.events.len(), 1);
    assert_eq!(
        (rep.events[0].kind, rep.events[0].line),
        (EventKind::SpindleOffCut, 7)
    );

    // A 4 mm deep blade with a holder 7 mm wide (Z-2..5 from the tip) from
    // 5 mm above the tip: the holder meets the OD (r 25) beside the groove
    // once the tip is at r 20.
    let tt = parse_tools(
        "[tool.9]\nkind=\"groove\"\nwidth=3\ndepth=4\ntip=3\n\
         holder=[[-2,5],[5,5],[5,30],[-2,30]]\n",
        true,
    )
    .unwrap();
    let mut r = Run::new("bar:50,100", tt, None).at(40.0, 0.0, 10.0);
    r.tool(9, 9);
    r.spindle(true);
    r.lrapid(1, 27.0, -10.0);
    r.lfeed(2, 21.0, -10.0);
    assert!(r.sim.report().events.is_empty());
    r.lfeed(3, 19.0, -10.0);
    let rep = r.sim.report();
    assert_eq!(rep.events.len(), 1, "{:?}", rep.events);
    assert_eq!(
        (rep.events[0].kind, rep.events[0].line),
        (EventKind::HolderCollision, 3)
    );
    close(rep.events[0].at[0], 20.0, 1e-6);
}

#[test]
fn a_tool_without_geometry_is_its_offset_and_a_warning() {
    let mut r = Run::new("bar:50,100", ToolTable::default(), None).at(40.0, 0.0, 10.0);
    r.tool(6, 6);
    r.spindle(true);
    r.lrapid(1, 20.0, 2.0);
    r.lfeed(2, 20.0, -30.0);
    r.lfeed(3, 26.0, -30.0);
    let rep = r.sim.report();
    assert_eq!(rep.events.len(), 1);
    assert_eq!(rep.events[0].kind, EventKind::ToolUnknown);
    assert!(!rep.collided());
    close(rep.removed_mm3, PI * (625.0 - 400.0) * 30.0, 1e-6);
}

#[test]
fn a_hemispherical_end_is_within_half_a_micrometre_and_its_pappus_volume() {
    // A sharp insert with 30 mm edges (its body reaches the bar's corner,
    // 20 (√2 - 1) = 8.3 mm from the sphere) turns a hemisphere R 20 centred
    // on the axis at Z-20 from the pole (r 0, Z0) to the equator, on a
    // bar r 20 with its face at Z0.
    let tt = parse_tools("[tool.5]\nnose_radius=0\ntip=3\nedge_length=30\n", true).unwrap();
    let mut r = Run::new("bar:40,100", tt, None).at(40.0, 0.0, 10.0);
    r.tool(5, 5);
    r.spindle(true);
    r.lrapid(1, 0.0, 1.0);
    r.lfeed(2, 0.0, 0.0);
    r.arc(3, [20.0, 0.0, -20.0], [0.0, 0.0, -20.0], true, Plane::ZX, 0);
    r.lfeed(4, 21.0, -20.0);
    assert!(r.sim.report().events.is_empty());
    // The profile's distance from the centre, every degree from the pole
    // to the equator: the chords (0.5 µm) lie inside the sphere.
    for deg in 1..90 {
        let a = (deg as f64).to_radians();
        let z = -20.0 + 20.0 * a.cos();
        let d = (z + 20.0).hypot(outer(&r, z));
        assert!(
            (20.0 - 0.5e-3 - 1e-6..=20.0 + 1e-6).contains(&d),
            "{deg}°: {d}"
        );
    }
    close(outer(&r, -20.5), 20.0, 1e-9);
    // Pappus: the hemisphere 2/3 π R³ and the 80 mm of bar below it; the
    // chords take at most 0.5 µm off its 31.4 mm arc at radii up to 20.
    let want = 2.0 / 3.0 * PI * 8000.0 + PI * 400.0 * 80.0;
    let chords = 0.5e-3 * (PI * 10.0) * 2.0 * PI * 20.0;
    let got = r.sim.report().remaining_mm3;
    assert!(
        (want - chords..=want).contains(&got),
        "{got} vs {want} - {chords}"
    );
}

#[test]
fn a_holder_just_ahead_of_the_insert_is_caught_along_the_whole_move() {
    // A holder block 0.05-0.3 mm ahead (-Z) of a sharp insert's tip, r
    // 0.2-3 above it: on an OD pass at r 24 along -Z it ploughs the bar
    // (r 25, face Z0) before the insert cuts there. The contact: its
    // front reaches the face when the tip is at Z0.3, 1.7 of the move's
    // 12 mm; it meets z -10.3..0, r 24.2..25 (the insert's sweep ahead
    // of its start counts: the holder gets there first).
    let tt = parse_tools(
        "[tool.1]\nnose_radius=0\ntip=3\n\
         holder=[[-0.3,0.2],[-0.05,0.2],[-0.05,3],[-0.3,3]]\n",
        true,
    )
    .unwrap();
    let mut r = Run::new("bar:50,100", tt, None).at(40.0, 0.0, 10.0);
    r.tool(1, 1);
    r.spindle(true);
    r.lrapid(1, 24.0, 2.0);
    r.lfeed(2, 24.0, -10.0);
    let rep = r.sim.report();
    assert_eq!(rep.events.len(), 1, "{:?}", rep.events);
    let e = &rep.events[0];
    assert_eq!((e.kind, e.line), (EventKind::HolderCollision, 2));
    close(e.at[2], 0.3, 1e-6);
    close(e.at[0], 24.0, 1e-9);
    close(e.volume_mm3, PI * (625.0 - 24.2 * 24.2) * 10.3, 1e-3);
    // The block on the tip's +Z side instead, plunged at Z-10 and then
    // run along +Z: on every line of either move the insert's front is
    // ahead of the block's (the insert's edges at 5° and 85° reach past
    // it: at 0.2 above the tip the 85° edge is 0.017 from it in z and the
    // 5° edge 2.3 beyond it), so the block only passes through the
    // insert's own cut: no event, and the insert's volume alone.
    let tt = parse_tools(
        "[tool.1]\nnose_radius=0\ntip=3\n\
         holder=[[0.05,0.2],[0.3,0.2],[0.3,3],[0.05,3]]\n",
        true,
    )
    .unwrap();
    let mut r = Run::new("bar:50,100", tt, None).at(40.0, 0.0, 10.0);
    r.tool(1, 1);
    r.spindle(true);
    r.lrapid(1, 26.0, -10.0);
    r.lfeed(2, 24.0, -10.0);
    r.lfeed(3, 24.0, 2.0);
    let rep = r.sim.report();
    assert!(rep.events.is_empty(), "{:?}", rep.events);
    // The plunge's sharp tip leaves r 24 from Z-10 on.
    close(rep.removed_mm3, PI * (625.0 - 576.0) * 10.0, 1e-3);
}
