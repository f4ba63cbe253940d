//! Tool offsets: G45-G48 tool position offset (000 §13.3) and G10 offset
//! data setting. Expected points worked out by hand in the comments.

mod common;
use common::{alarm, moves, ok, run_on};
use kerf_canon::Canon;

/// 000 §13.3's program (D01 = 10), written with decimal points (000's
/// extraction drops them; the original Fanuc example has them).
const G45_EXAMPLE: &str = "#2112 = 10.\n\
    G90 G54 G00 X0 Y0 Z0\n\
    N1 G91 G46 G00 X80. Y50. D01\n\
    N2 G47 G01 X50. F120.\n\
    N3 Y40.\n\
    N4 G48 X40.\n\
    N5 Y-40.\n\
    N6 G45 X30.\n\
    N7 G45 G03 X30. Y30. J30.\n\
    N8 G45 G01 Y20.\n\
    N9 G46 X0\n\
    N10 G46 G02 X-30. Y30. J30.\n\
    N11 G45 G01 Y0\n\
    N12 G47 X-120.\n\
    N13 G47 Y-80.\n\
    N14 G46 G00 X-80. Y-50.\n\
    M30\n";

#[test]
fn manual_13_3_tool_offset_example() {
    let r = run_on("hx-mc", G45_EXAMPLE);
    ok(&r);
    let m = moves(&r);
    // Each move amount ± D (10) or ± 2D along its own direction:
    // N1 G46 X80 Y50 -> X70 Y40            (70, 40)
    // N2 G47 X50 -> X70                      (140, 40)
    // N3 Y40 (no offset)                     (140, 80)
    // N4 G48 X40 -> X20                      (160, 80)
    // N5 Y-40                                (160, 40)
    // N6 G45 X30 -> X40                      (200, 40)
    // N7 G45 G03 X30 Y30 J30 -> X40 Y40 J40  (240, 80), centre (200, 80)
    // N8 G45 Y20 -> Y30                      (240, 110)
    // N9 G46 X0 -> X-10 (zero counts as +)   (230, 110)
    // N10 G46 G02 X-30 Y30 J30 -> X-20 Y20 J20 (210, 130), centre (230, 130)
    // N11 G45 Y0 -> Y+10                     (210, 140)
    // N12 G47 X-120 -> X-140                 (70, 140)
    // N13 G47 Y-80 -> Y-100                  (70, 40)
    // N14 G46 G00 X-80 Y-50 -> X-70 Y-40     (0, 0): the path closes.
    let xy: Vec<(&str, f64, f64)> = m[1..].iter().map(|&(k, x, y, _)| (k, x, y)).collect();
    assert_eq!(
        xy,
        vec![
            ("rapid", 70.0, 40.0),
            ("feed", 140.0, 40.0),
            ("feed", 140.0, 80.0),
            ("feed", 160.0, 80.0),
            ("feed", 160.0, 40.0),
            ("feed", 200.0, 40.0),
            ("arc", 240.0, 80.0),
            ("feed", 240.0, 110.0),
            ("feed", 230.0, 110.0),
            ("arc", 210.0, 130.0),
            ("feed", 210.0, 140.0),
            ("feed", 70.0, 140.0),
            ("feed", 70.0, 40.0),
            ("rapid", 0.0, 0.0),
        ]
    );
    // The arcs' centres: (200, 80) radius 40, and (230, 130) radius 20.
    let centres: Vec<(f64, f64)> = r
        .events
        .iter()
        .filter_map(|e| match e.cmd {
            Canon::Arc { center, .. } => Some((center[0], center[1])),
            _ => None,
        })
        .collect();
    assert_eq!(centres, vec![(200.0, 80.0), (230.0, 130.0)]);
}

#[test]
fn tool_offset_in_absolute_and_with_negative_d() {
    // G90: the move amount (end - start) changes. From X10 to X50 is +40;
    // G45 with D2 = -5 (negative reverses) makes it +35: X45.
    let r = run_on(
        "hx-mc",
        "#2113 = -5.\nG90 G54 G00 X10. Y0 Z0\nG45 G01 X50. D2 F100.\nM30\n",
    );
    ok(&r);
    assert_eq!(moves(&r)[1], ("feed", 45.0, 0.0, 0.0));
}

#[test]
fn tool_offset_alarms() {
    // D beyond D128: positioned at the D word ("G45 G01 X10. " is 13
    // characters, so column 14 of line 2).
    let r = run_on("hx-mc", "G91 G00 X0 Y0\nG45 G01 X10. D129 F100.\n");
    assert_eq!(alarm(&r), ("F_82007", 2, 14));
    // G45 in G33 mode (not G00-G03).
    let r = run_on("hx-mc", "G91 G33 F1.\nG45 X10.\n");
    assert_eq!(alarm(&r).0, "F_82106");
    // G45 with G41 in force (000 §13.3: not with cutter compensation), at
    // the G45 code: line 3, column 1.
    let r = run_on(
        "hx-mc",
        "#2112 = 5.\nG90 G17 G00 X0 Y0\nG45 G41 G01 X10. D1 F100.\n",
    );
    assert_eq!(alarm(&r), ("F_82106", 3, 1));
}

#[test]
fn hx_g10_sets_h_and_d_geometry_and_wear() {
    // 000 §13.1.3: G10 G90 L10 P1 R100 -> H1 = 100; G10 L12 P1 R20 ->
    // D1 = 20; G10 G91 L10 P1 R-0.5 -> H1 = 99.5. Then L11 (H wear) adds
    // -0.25: H1 in force 99.25. G43 H1 Z0 from the G54 Z origin -250 puts
    // machine Z at -250 + 99.25 = -150.75. D1 = 20 is read back through
    // #2112 (D1 geometry) into an X move: X20.
    let r = run_on(
        "hx-mc",
        "G10 G90 L10 P1 R100.\n\
         G10 L12 P1 R20.\n\
         G10 G91 L10 P1 R-0.5\n\
         G10 G91 L11 P1 R-0.25\n\
         G90 G54 G43 G00 X#2112 Y0 Z0 H1\n\
         M30\n",
    );
    ok(&r);
    let m = r
        .events
        .iter()
        .find_map(|e| e.motion().map(|m| m.mto))
        .unwrap();
    assert!((m[2] - -150.75).abs() < 1e-9, "{m:?}");
    assert_eq!(moves(&r)[0].1, 20.0);
    // P beyond H128, and no R: positioned alarms.
    let r = run_on("hx-mc", "G10 L10 P129 R1.\n");
    assert_eq!(alarm(&r), ("F_82007", 1, 9));
    let r = run_on("hx-mc", "G10 L12 P1\n");
    assert_eq!(alarm(&r).0, "F_82008");
}

#[test]
fn puma_t_code_applies_geometry_plus_wear_and_t00_cancels() {
    // G10 P10002 X1.5 Z-0.93: geometry of offset 2 (X a diameter: 0.75 mm
    // of radius); G10 P2 U0.1: X wear +0.1 diameter (0.05 radius).
    // T0202 with G00 X40. Z2.: the tool tip at radius 20, Z2 (`to`), the
    // turret 0.75 + 0.05 = 0.8 further out in X and 0.93 lower in Z than
    // with T0200 (cancelled) at the same programmed point.
    let r = run_on(
        "puma-lathe",
        "G10 P10002 X1.5 Z-0.93 R0.4 Q3\n\
         G10 P2 U0.1\n\
         G00 X40. Z2. T0202\n\
         G00 X40. Z2. T0200\n\
         M30\n",
    );
    ok(&r);
    let m = moves(&r);
    assert_eq!((m[0].1, m[0].3), (20.0, 2.0), "{m:?}");
    assert_eq!((m[1].1, m[1].3), (20.0, 2.0), "{m:?}");
    let mto: Vec<_> = r
        .events
        .iter()
        .filter_map(|e| e.motion().map(|m| m.mto))
        .collect();
    assert!(
        (mto[0][0] - mto[1][0] - 0.8).abs() < 1e-9 && (mto[0][2] - mto[1][2] + 0.93).abs() < 1e-9,
        "{mto:?}"
    );
    assert_eq!((m[1].1, m[1].3), (20.0, 2.0));
    // Offset 17 on the PUMA's 16-offset page: alarm at the T word.
    let r = run_on("puma-lathe", "G00 X40. T0217\n");
    assert_eq!(alarm(&r), ("PS003", 1, 10));
    // G10 P with a bad tip direction, X and U together.
    let r = run_on("puma-lathe", "G10 P1 Q12\n");
    assert_eq!(alarm(&r), ("PS003", 1, 8));
    let r = run_on("puma-lathe", "G10 P1 X1. U1.\n");
    assert_eq!(alarm(&r).0, "PS009");
}

#[test]
fn tool_length_offset_on_the_axis_normal_to_the_plane() {
    // hx-mc G54 = machine X-400 Y-250 Z-250; H1 = 25 (#2240, 000 §14.2.3).
    // G18 G43 H1 Y0: the offset goes on Y: machine Y = -250 + 25 = -225,
    // Z stays at the G54 origin -250. G19 G44 H1 X0: on X, negative:
    // machine X = -400 - 25 = -425, and Y loses its offset: -250.
    let r = run_on(
        "hx-mc",
        "#2240 = 25.\n\
         G90 G54 G00 X0 Y0 Z0\n\
         G18 G43 H1 Y0\n\
         G19 G44 H1 X0 Y0\n\
         M30\n",
    );
    ok(&r);
    let m: Vec<[f64; 3]> = r
        .events
        .iter()
        .filter_map(|e| e.motion().map(|m| [m.mto[0], m.mto[1], m.mto[2]]))
        .collect();
    assert_eq!(m[1], [-400.0, -225.0, -250.0]);
    assert_eq!(m[2], [-425.0, -250.0, -250.0]);
}

/// 000 §13.1.1's example: G54 Z offset −150 (the manual's "=150.000 mm"
/// below the reference), H1 = 10 mm. By hand, machine Z = G54 offset +
/// work Z (+ H in G43): `G54 G90 Z100.` → −150 + 100 = −50;
/// `G43 G90 G00 Z50. H01` → −150 + 50 + 10 = −90 (the tool 10 mm longer
/// stops 10 mm higher); `G90 G49 G00 Z150.` → −150 + 150 = 0.
#[test]
fn manual_13_1_1_tool_length_example() {
    let r = run_on(
        "hx-mc",
        "G10 L2 P1 Z-150.\n\
         G10 L10 P1 R10.\n\
         G54 G90 G00 Z100.\n\
         G43 G90 G00 Z50. H01\n\
         G90 G49 G00 Z150.\n\
         M30\n",
    );
    ok(&r);
    let z: Vec<(f64, f64)> = r
        .events
        .iter()
        .filter_map(|e| e.motion().map(|m| (m.to[2], m.mto[2])))
        .collect();
    // (work Z, machine Z) of the three positionings.
    assert_eq!(z, vec![(100.0, -50.0), (50.0, -90.0), (150.0, 0.0)]);
}
