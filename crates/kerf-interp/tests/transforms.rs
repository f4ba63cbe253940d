//! HX coordinate transforms and coordinate-system codes: G52, G10 L2,
//! G15/G16 polar coordinates, G50/G51 scaling and mirror image, G68/G69
//! rotation (000 §7.3, §8.3, §15.2-15.4). Expected values are worked out
//! by hand in the comments (cos 60° = 0.5, sin 60° = 0.8660254037844386).

use kerf_canon::{ArcDir, Canon, Motion, Pos};
use kerf_interp::Run;

mod common;
use common::{alarm, moves, ok, round, run_on};

/// The first arc of a run: its motion, centre and direction.
fn first_arc(r: &Run) -> (&Motion, &Pos, ArcDir) {
    r.events
        .iter()
        .find_map(|e| match &e.cmd {
            Canon::Arc { m, center, dir, .. } => Some((m, center, *dir)),
            _ => None,
        })
        .expect("an arc")
}

/// 000 §15.4 example N1-N8, numbers with decimal points (the manual prints
/// `G68 X70 Y30 R60` and its comment reads "X 70. Y 30. … 60°"). A G53
/// line first puts the tool where the square stays inside travel.
#[test]
fn rotation_example_of_000_15_4() {
    let r = run_on(
        "hx-mc",
        "G53 X-500. Y-300.\n\
         N1 G92 X-50. Y-50. G69 G17\n\
         N2 G68 X70. Y30. R60.\n\
         N3 G90 G01 X0 Y0 F200\n\
         N4 G91 X100.\n\
         N5 G01 Y100.\n\
         N6 X-100.\n\
         N7 Y-100.\n\
         N8 G69 G90 X-50. Y-50. M30\n",
    );
    ok(&r);
    // p' = c + R60 (p - c), c = (70, 30):
    // (0,0):    d (-70,-30) → (-35 + 25.980762, -60.621778 - 15) → (60.980762, -45.621778)
    // (100,0):  d (30,-30)  → (15 + 25.980762, 25.980762 - 15)   → (110.980762, 40.980762)
    // (100,100): d (30,70)  → (15 - 60.621778, 25.980762 + 35)   → (24.378222, 90.980762)
    // (0,100):  d (-70,70)  → (-35 - 60.621778, -60.621778 + 35) → (-25.621778, 4.378222)
    let m = moves(&r);
    assert_eq!(
        &m[1..],
        &[
            ("feed", 60.980762, -45.621778, 250.0),
            ("feed", 110.980762, 40.980762, 250.0),
            ("feed", 24.378222, 90.980762, 250.0),
            ("feed", -25.621778, 4.378222, 250.0),
            ("feed", 60.980762, -45.621778, 250.0),
            ("feed", -50.0, -50.0, 250.0),
        ]
    );
}

/// `R` without a decimal point is in 0.001° (decimal-point rule); G91 adds
/// the angle to the rotation in force; without a centre the current
/// position is the centre.
#[test]
fn rotation_angle_units_and_incremental_angle() {
    // Centre (0,0); R90000 = 90°: (10,0) → (0,10).
    let r = run_on("hx-mc", "G00 X0 Y0\nG68 X0 Y0 R90000\nG01 X10. F100\n");
    ok(&r);
    assert_eq!(moves(&r)[1], ("feed", 0.0, 10.0, 250.0));
    // 30° then G91 R60. → 90°.
    let r = run_on(
        "hx-mc",
        "G00 X0 Y0\nG68 R30.\nG91 G68 R60.\nG90 G01 X10. F100\n",
    );
    ok(&r);
    assert_eq!(moves(&r)[1], ("feed", 0.0, 10.0, 250.0));
    // Centre omitted: the current position (10, 0); (20, 0) by 90° → (10, 10).
    let r = run_on("hx-mc", "G00 X10. Y0\nG68 R90.\nG01 X20. F100\n");
    ok(&r);
    assert_eq!(moves(&r)[1], ("feed", 10.0, 10.0, 250.0));
}

/// Arcs rotate with their centre: G02 from (0,0) to (20,0) centre (10,0)
/// rotated 90° about (0,0) ends at (0,20), centre (0,10).
#[test]
fn rotation_turns_arcs() {
    let r = run_on(
        "hx-mc",
        "G00 X0 Y0\nG68 X0 Y0 R90.\nG02 X20. Y0 I10. F100\n",
    );
    ok(&r);
    let (m, center, dir) = first_arc(&r);
    assert_eq!((round(m.to[0]), round(m.to[1])), (0.0, 20.0));
    assert_eq!((round(center[0]), round(center[1])), (0.0, 10.0));
    assert_eq!(dir, ArcDir::Cw);
}

/// 000 §15.2.2 as printed: `G51 X0. Y0. Z0. I2000. J1000.` ("X 2, Y 1")
/// then `G02 X100. Y0. R100.` from (0, 100): the factors are 1/1000 with
/// or without the decimal point (§15.2.1 "1/1000 (2 = P2000, 0.5 =
/// P500)"), so X is doubled, Y kept, and the end is (200, 0) as the
/// manual's comment "X200. Y0." says. With unequal
/// factors R takes the larger factor (R 200): centre on the right of the
/// chord (0,100)→(200,0): midpoint (100, 50), half chord √12500, offset
/// √(40000 - 12500) = 165.831240 along (-0.447214, -0.894427) →
/// (25.838015, -98.323970).
#[test]
fn scaling_example_of_000_15_2_2() {
    for g51 in [
        "G51 X0. Y0. Z0. I2000. J1000.",
        "G51 X0. Y0. Z0. I2000 J1000",
    ] {
        let r = run_on(
            "hx-mc",
            &format!("G90 G00 X0. Y100.\n{g51}\nG02 X100. Y0. R100. F500.\n"),
        );
        ok(&r);
        let (m, center, dir) = first_arc(&r);
        assert_eq!((round(m.to[0]), round(m.to[1])), (200.0, 0.0), "{g51}");
        assert_eq!((round(center[0]), round(center[1])), (25.838015, -98.32397));
        assert_eq!(dir, ArcDir::Cw);
    }
}

/// 000 §15.2 / §15.3 pattern examples: a subprogram O1234 (kerf's: the
/// manual's figure is lost) run at a G52 origin unscaled, then scaled
/// ×1.5, then mirrored ×-1.5 in X and Y; the G51 blocks as 000 prints
/// them (`I1000. J1000.`, `I1500. J1500.`, `I-1500. J-1500.`: 1/1000).
#[test]
fn scaling_and_mirror_with_a_subprogram() {
    let sub = "O1234\nG01 X20. Y0 F300\nX20. Y10.\nX0 Y0\nM99\n";
    let r = run_on(
        "hx-mc",
        &format!(
            "O0001\nG90 G00 X0 Y0\nG52 X22. Y22.\nG51 X0. Y0. I1000. J1000.\nG00 X0 Y0\nM98 P1234\n\
             G52 X85. Y50.\nG51 X0. Y0. I1500. J1500.\nG00 X0 Y0\nM98 P1234\n\
             G51 X0. Y0. I-1500. J-1500.\nG00 X0 Y0\nM98 P1234\nG50\nG52 X0 Y0\nM30\n{sub}"
        ),
    );
    ok(&r);
    let m = moves(&r);
    // ×1 about local (22,22): (22,22) (42,22) (42,32) (22,32)… back (22,22).
    // ×1.5 about local (85,50): (85,50) (115,50) (115,65) (85,50).
    // ×-1.5: (85,50) (55,50) (55,35) (85,50).
    assert_eq!(
        &m[1..],
        &[
            ("rapid", 22.0, 22.0, 250.0),
            ("feed", 42.0, 22.0, 250.0),
            ("feed", 42.0, 32.0, 250.0),
            ("feed", 22.0, 22.0, 250.0),
            ("rapid", 85.0, 50.0, 250.0),
            ("feed", 115.0, 50.0, 250.0),
            ("feed", 115.0, 65.0, 250.0),
            ("feed", 85.0, 50.0, 250.0),
            // G00 X0 Y0 where the tool already is: a zero-length rapid.
            ("rapid", 85.0, 50.0, 250.0),
            ("feed", 55.0, 50.0, 250.0),
            ("feed", 55.0, 35.0, 250.0),
            ("feed", 85.0, 50.0, 250.0),
        ]
    );
}

/// Mirroring one plane axis reverses G02/G03 (000 §15.3): mirrored in X
/// about 0, a CW half circle from (0,0) to (10,0) becomes CCW to (-10,0)
/// about (-5,0).
#[test]
fn mirror_reverses_arc_direction() {
    let r = run_on(
        "hx-mc",
        "G00 X0 Y0\nG51 X0 Y0 I-1000 J1000\nG02 X10. Y0 I5. F100\n",
    );
    ok(&r);
    let (m, center, dir) = first_arc(&r);
    assert_eq!((round(m.to[0]), round(m.to[1])), (-10.0, 0.0));
    assert_eq!((round(center[0]), round(center[1])), (-5.0, 0.0));
    assert_eq!(dir, ArcDir::Ccw);
}

/// P scales every axis (P500 = ×0.5), Z included, about the given centre.
#[test]
fn uniform_scaling_with_p() {
    let r = run_on(
        "hx-mc",
        "G00 X0 Y0 Z0\nG51 X10. Y10. Z0 P500\nG01 X30. Y-10. Z-20. F100\nG50\nG01 X30. Y-10.\n",
    );
    ok(&r);
    // (30,-10,-20) about (10,10,0) ×0.5 → (20, 0, -10); after G50 (30,-10,-10).
    let m = moves(&r);
    assert_eq!(m[1], ("feed", 20.0, 0.0, -10.0));
    assert_eq!(m[2], ("feed", 30.0, -10.0, -10.0));
}

/// 000 §8.3 bolt circles (G01 here; the manual's G81 versions are in the
/// canned-cycle examples). Radius 20 about (60, 44): 0°, 120°, 240° →
/// (80, 44), (50, 61.320508), (50, 26.679492).
#[test]
fn polar_bolt_circle_absolute_and_incremental_radius() {
    // G90 radius: origin = the (local) program origin.
    let r = run_on(
        "hx-mc",
        "G00 X0 Y0\nG52 X60. Y44.\nG16 G17\nG01 X20. Y0 F100\nY120.\nY240.\nG15\n",
    );
    ok(&r);
    let m = moves(&r);
    assert_eq!(
        &m[1..],
        &[
            ("feed", 80.0, 44.0, 250.0),
            ("feed", 50.0, 61.320508, 250.0),
            ("feed", 50.0, 26.679492, 250.0),
        ]
    );
    // G91 radius: origin = the current position (60, 44); angles added.
    let r = run_on(
        "hx-mc",
        "G90 G00 X60. Y44. Z10.\nG16 G17\nG91 G01 X20. Y0 F100\nY120.\nY120.\nG15\n",
    );
    ok(&r);
    let m = moves(&r);
    assert_eq!(
        &m[1..],
        &[
            ("feed", 80.0, 44.0, 10.0),
            ("feed", 50.0, 61.320508, 10.0),
            ("feed", 50.0, 26.679492, 10.0),
        ]
    );
}

/// 000 §8.3 bolt hole cycle (30°, 150°, 270° at radius 100), both radius
/// and angle absolute, then the G91-angle version: (86.602540, 50),
/// (-86.602540, 50), (0, -100).
#[test]
fn polar_bolt_hole_angles() {
    let want = [
        ("feed", 86.60254, 50.0, 250.0),
        ("feed", -86.60254, 50.0, 250.0),
        ("feed", 0.0, -100.0, 250.0),
    ];
    let r = run_on(
        "hx-mc",
        "G00 X0 Y0\nG17 G90 G16\nG01 X100. Y30. F200.\nY150.\nY270.\nG15\n",
    );
    ok(&r);
    assert_eq!(&moves(&r)[1..], &want);
    let r = run_on(
        "hx-mc",
        "G00 X0 Y0\nG17 G16\nG90 G01 X100. Y30. F200.\nG91 Y120.\nY120.\nG15\n",
    );
    ok(&r);
    assert_eq!(&moves(&r)[1..], &want);
}

/// Polar in G18: Z is the radius, X the angle. Z10. X90. → Z 0, X 10
/// (angle from +Z toward +X).
#[test]
fn polar_in_the_zx_plane() {
    let r = run_on("hx-mc", "G00 X0 Y0 Z0\nG18 G16\nG01 Z10. X90. F100\n");
    ok(&r);
    assert_eq!(moves(&r)[1], ("feed", 10.0, 0.0, 0.0));
}

/// 000 §7.3: G52 in each work system (the manual's numbers have no decimal
/// point; with points here). G52 shifts programmed coordinates; the event
/// `to` stays in the work system: G54 local (50,-100) → X0 Y0 is work
/// (50, -100). G92 clears the local offset of the axes it names.
#[test]
fn local_coordinates_g52() {
    let r = run_on(
        "hx-mc",
        "G90 G54 G00 X0 Y0\nG52 X50. Y-100.\nG00 X0 Y0\nG00 X10. Y10.\n\
         G55\nG52 X60. Y-120.\nG00 X0 Y0\nG52 X0 Y0\nG00 X0 Y0\n",
    );
    ok(&r);
    let m = moves(&r);
    assert_eq!(
        m,
        vec![
            ("rapid", 0.0, 0.0, 250.0),
            ("rapid", 50.0, -100.0, 250.0),
            ("rapid", 60.0, -90.0, 250.0),
            ("rapid", 60.0, -120.0, 250.0),
            ("rapid", 0.0, 0.0, 250.0),
        ]
    );
    // Machine coordinates: G54 = (-400, -250): local (50,-100) → (-350, -350).
    let mto = r.events[1].motion().unwrap().mto;
    assert_eq!((round(mto[0]), round(mto[1])), (-350.0, -350.0));
}

/// `G10 L2 P2` sets G55 (machine coordinates of its zero); G91 adds; P0 is
/// the work shift applied to every system.
#[test]
fn work_offset_setting_g10_l2() {
    let r = run_on(
        "hx-mc",
        "G10 L2 P2 X-100. Y-50. Z-20.\nG55 G00 X0 Y0 Z0\nG91 G10 L2 P2 X-10.\nG90 G00 X0\n\
         G10 L2 P0 X5.\nG00 X0\n",
    );
    ok(&r);
    let mto: Vec<_> = r
        .events
        .iter()
        .filter_map(|e| e.motion())
        .map(|m| (round(m.mto[0]), round(m.mto[1]), round(m.mto[2])))
        .collect();
    assert_eq!(
        mto,
        vec![
            (-100.0, -50.0, -20.0),
            (-110.0, -50.0, -20.0),
            (-105.0, -50.0, -20.0)
        ]
    );
}

#[test]
fn transform_alarms() {
    // G28 in rotation mode (000 §15.4: cancel with G69 first).
    let r = run_on("hx-mc", "G68 X0 Y0 R30.\nG28 X0\n");
    assert_eq!(alarm(&r), ("F_82210", 2, 1));
    // G92 in scaling mode.
    let r = run_on("hx-mc", "G51 X0 Y0 P2000\nG92 X0 Y0\n");
    assert_eq!(alarm(&r), ("F_82210", 2, 1));
    // Plane change in rotation mode.
    let r = run_on("hx-mc", "G68 X0 Y0 R30.\nG18\n");
    assert_eq!(alarm(&r), ("F_82210", 2, 1));
    // Scale factor 0 and rotation angle beyond 360°.
    let r = run_on("hx-mc", "G51 X0 Y0 P0\n");
    assert_eq!(alarm(&r), ("F_82007", 1, 11));
    let r = run_on("hx-mc", "G68 X0 Y0 R400.\n");
    assert_eq!(alarm(&r), ("F_82007", 1, 11));
    // G10 L2 with P out of range; G10 without L.
    let r = run_on("hx-mc", "G10 L2 P7 X0\n");
    assert_eq!(alarm(&r), ("F_82007", 1, 8));
    let r = run_on("hx-mc", "G10 P1 X0\n");
    assert_eq!(alarm(&r), ("F_82008", 1, 1));
    // G69 in the same block makes G28 legal.
    let r = run_on("hx-mc", "G68 X0 Y0 R30.\nG69 G28 X0\n");
    ok(&r);
}

/// 000 §15.5.3 area A, `G22 X-120 Y-100 I-190 J-150` (machine
/// coordinates; with decimal points here): X -190…-120, Y -150…-100.
/// Work = machine + (400, 250) on G54.
const AREA_A: &str = "G22 X-120. Y-100. I-190. J-150.\n";

#[test]
fn stroke_check_follows_the_non_linear_rapid() {
    // G53 X-300 Y-125 from machine (0,0): both axes at 24000 mm/min, so
    // the tool runs diagonally to (-125,-125) — inside the area — before X
    // goes on alone. (A straight line would pass at y = -50 … -79.)
    let r = run_on("hx-mc", &format!("{AREA_A}G53 X-300. Y-125.\n"));
    assert_eq!(alarm(&r), ("F_84100", 2, 1));
    // Rapid to the same point in two moves around the area: fine.
    let r = run_on(
        "hx-mc",
        &format!("{AREA_A}G53 Y-80.\nG53 X-300.\nG53 Y-125.\n"),
    );
    ok(&r);
    // G23 switches the check off.
    let r = run_on("hx-mc", &format!("{AREA_A}G23\nG53 X-300. Y-125.\n"));
    ok(&r);
}

#[test]
fn stroke_check_on_feed_lines_and_arcs() {
    // Round the area to work (0, 125), then feed across along machine
    // y = -125 to work x 300.
    let r = run_on(
        "hx-mc",
        &format!("{AREA_A}G00 Y200.\nX0\nY125.\nG01 X300. F1000\n"),
    );
    assert_eq!(alarm(&r), ("F_84100", 5, 1));
    // Half circle from work (200,160) to (290,160) about (245,160), r 45:
    // G03 dips to (245,115) = machine (-155,-135), inside; the chord
    // (y = -90 machine) and the end points are outside. G02 bulges up.
    let arc = |g: &str| format!("{AREA_A}G00 X200. Y160.\n{g} X290. I45. F1000\n");
    let r = run_on("hx-mc", &arc("G03"));
    assert_eq!(alarm(&r), ("F_84100", 3, 1));
    let r = run_on("hx-mc", &arc("G02"));
    ok(&r);
}

#[test]
fn stroke_check_alarms_at_setup_inside_the_area() {
    // The tool at machine (-150, -125) when G22 defines the area round it.
    let r = run_on("hx-mc", &format!("G53 X-150. Y-125.\n{AREA_A}"));
    assert_eq!(alarm(&r), ("F_84100", 2, 1));
    // Lower corner above the upper one.
    let r = run_on("hx-mc", "G22 X-200. I-100.\n");
    assert_eq!(alarm(&r), ("F_82007", 1, 12));
}

/// 000 §4.8: `G33 Z0. F5.` from Z100 with the spindle on: one threading
/// move, lead 5 mm/rev; without the spindle it alarms.
#[test]
fn g33_thread_on_the_mill() {
    let r = run_on(
        "hx-mc",
        "G90 G54 G00 X0. Y0. Z0.\nZ100.\nS300 M03\nG33 Z0. F5.\nM30\n",
    );
    ok(&r);
    let t: Vec<_> = r
        .events
        .iter()
        .filter_map(|e| match &e.cmd {
            Canon::Thread { m, lead } => Some((round(m.to[2]), *lead)),
            _ => None,
        })
        .collect();
    assert_eq!(t, vec![(0.0, 5.0)]);
    let r = run_on("hx-mc", "G90 G00 X0. Y0. Z100.\nG33 Z0. F5.\n");
    assert_eq!(alarm(&r), ("F_84020", 2, 1));
}

/// G63.1/G63.2 (000 §15.6) reach the canon stream as mode changes.
#[test]
fn stitch_mode_is_recorded() {
    let r = run_on("hx-mc", "G63.1\nG01 X1. F100\nG63.2\n");
    ok(&r);
    let modes: Vec<_> = r
        .events
        .iter()
        .filter_map(|e| match e.cmd {
            Canon::Mode(m) => Some(m),
            _ => None,
        })
        .collect();
    assert_eq!(
        modes,
        vec![
            kerf_canon::ModeChange::Stitch(true),
            kerf_canon::ModeChange::Stitch(false)
        ]
    );
}

/// Scaling applies to the hole position and the R and Z levels but not to
/// the peck depth Q (000 §15.2). ×2 about the origin: R2. → 4, Z-10. →
/// -20, so 24 mm of pecking in steps of Q = 4: feed bottoms 0, -4, -8,
/// -12, -16, -20 at X 20.
#[test]
fn scaling_leaves_the_peck_depth_alone() {
    let r = run_on(
        "hx-mc",
        "G00 X0 Y0 Z10.\nG51 X0 Y0 Z0 P2000\nG83 G99 X10. Y0 Z-10. R2. Q4. F100\nG80\n",
    );
    ok(&r);
    let feeds: Vec<_> = moves(&r)
        .into_iter()
        .filter(|m| m.0 == "feed")
        .map(|m| (m.1, m.3))
        .collect();
    assert_eq!(
        feeds,
        vec![
            (20.0, 0.0),
            (20.0, -4.0),
            (20.0, -8.0),
            (20.0, -12.0),
            (20.0, -16.0),
            (20.0, -20.0)
        ]
    );
}

/// 000 §8.3 first example (decimal points added): G92 makes the reference
/// position read (150, 150, 150); G52 puts the local origin at (60, 44);
/// G16 G81 drills at radius 20, angles 0°, 120°, 240°: (80, 44),
/// (50, 61.320508), (50, 26.679492), each: rapid in the plane at the
/// initial level 150, rapid to R3, feed to Z-15, rapid back to R3 (G99).
#[test]
fn polar_bolt_circle_example_with_g81() {
    let r = run_on(
        "hx-mc",
        "N1 G40 G80\nN2 G28 G91 X0 Y0 Z0\nN3 G92 G90 X150. Y150. Z150.\nN50 G52 X60. Y44.\n\
         N51 G16 G17\nN52 G81 G90 G99 X20. Y0 Z-15. R3. F100\nN53 Y120.\nN54 Y240.\n\
         N55 G15 G00 Z50. M09\n",
    );
    ok(&r);
    let m = moves(&r);
    let mut want = vec![];
    for (x, y) in [(80.0, 44.0), (50.0, 61.320508), (50.0, 26.679492)] {
        let z0 = if want.is_empty() { 150.0 } else { 3.0 };
        want.push(("rapid", x, y, z0));
        if z0 != 3.0 {
            want.push(("rapid", x, y, 3.0));
        }
        want.push(("feed", x, y, -15.0));
        want.push(("rapid", x, y, 3.0));
    }
    want.push(("rapid", 50.0, 26.679492, 50.0));
    // G28 from the power-on position (the reference position) makes no move.
    assert_eq!(m, want);
}

/// A bolt circle in polar coordinates under scaling and rotation, drilled
/// with a G91 angle step repeated by K. By hand: radius 10 scaled ×2 about
/// the origin = 20; program angles 0, 90, then 90 + 120 = 210 and
/// 210 + 120 = 330 (each repeat turns by the angle again, as the repeated
/// block would), plus the 30° rotation: 30°, 120°, 240°, 360° →
/// (17.3205, 10), (-10, 17.3205), (-10, -17.3205), (20, 0). Z is scaled
/// about the current Z50 (the omitted centre axis): R2 → 50 + 2·(2 − 50)
/// = -46, Z-5 → 50 + 2·(-5 − 50) = -60.
#[test]
fn polar_bolt_circle_with_scaling_rotation_and_k() {
    let r = run_on(
        "hx-mc",
        "G10 L2 P1 X-400. Y-300. Z-250.\n\
         G54 G17 G90 G00 X0 Y0 Z50.\n\
         G51 X0 Y0 P2000\n\
         G68 X0 Y0 R30.\n\
         G16\n\
         G99 G81 X10. Y0 Z-5. R2. F100\n\
         Y90.\n\
         G91 Y120. K2\n\
         G90 G80 G15 G69 G50\n\
         M30\n",
    );
    ok(&r);
    let holes: Vec<_> = moves(&r)
        .into_iter()
        .filter(|m| m.0 == "feed")
        .map(|m| (m.1, m.2, m.3))
        .collect();
    let s = 17.320508;
    let want = [(s, 10.0), (-10.0, s), (-10.0, -s), (20.0, 0.0)];
    assert_eq!(holes.len(), 4, "{holes:?}");
    for (h, w) in holes.iter().zip(want) {
        assert!(
            (h.0 - w.0).abs() < 1e-5 && (h.1 - w.1).abs() < 1e-5,
            "{holes:?}"
        );
        assert!((h.2 + 60.0).abs() < 1e-9, "{holes:?}");
    }
    // The return level of G99 is the scaled R.
    let rapids_at_r = moves(&r)
        .iter()
        .filter(|m| m.0 == "rapid" && (m.3 + 46.0).abs() < 1e-9)
        .count();
    assert_eq!(rapids_at_r, 8);
}
