//! PUMA (001, Fanuc 0-T) G32 threading and the single cycles G90, G92,
//! G94. The 001 example programs run as printed (OCR'd minus signs `Ð`
//! written `-`); every expected point is worked out by hand in the
//! comments from the program text and the four-move rectangles of 001's
//! figures (fanuc-semantics §2). Points are compared as X diameters and Z,
//! the way the programs write them.

use kerf_canon::Canon;
use kerf_interp::Run;

mod common;
use common::{alarm, ok, round, run_on};

/// (kind, X diameter, Z) of every move: `R` rapid, `F` feed, `A` arc,
/// `T` thread (with its lead in the fourth field; 0 for the others).
pub fn trace(r: &Run) -> Vec<(&'static str, f64, f64, f64)> {
    r.events
        .iter()
        .filter_map(|e| {
            let (k, lead) = match e.cmd {
                Canon::Rapid { .. } => ("R", 0.0),
                Canon::Feed { .. } => ("F", 0.0),
                Canon::Arc { .. } => ("A", 0.0),
                Canon::Thread { lead, .. } => ("T", lead),
                _ => return None,
            };
            let m = e.motion().unwrap();
            Some((k, round(2.0 * m.to[0]), round(m.to[2]), round(lead)))
        })
        .collect()
}

/// The moves after the first `skip` ones.
fn from(r: &Run, skip: usize) -> Vec<(&'static str, f64, f64, f64)> {
    trace(r)[skip..].to_vec()
}

const PUMA: &str = "puma-lathe";

/// 001 G32 example 1 (straight thread, absolute): lead 3, two cuts at
/// X48 and X46 from Z5 to Z-71.5; F is modal for the second G32.
#[test]
fn g32_straight_example_001() {
    let r = run_on(
        PUMA,
        "G50 T0100 ;\nG97 S800 M03 ;\nG00 X90.0 Z5.0 T0101 M8 ;\nX48.0 ;\nG32 Z-71.5 F3.0 ;\nG00 X90.0 ;\nZ5.0 ;\nX46.0 ;\nG32 Z-71.5 ;\nG00 X90.0 ;\nZ5.0\nX150.0 Z150.0 T0100 ;\nM30 ;\n",
    );
    ok(&r);
    assert_eq!(
        trace(&r),
        vec![
            ("R", 90.0, 5.0, 0.0),
            ("R", 48.0, 5.0, 0.0),
            ("T", 48.0, -71.5, 3.0),
            ("R", 90.0, -71.5, 0.0),
            ("R", 90.0, 5.0, 0.0),
            ("R", 46.0, 5.0, 0.0),
            ("T", 46.0, -71.5, 3.0),
            ("R", 90.0, -71.5, 0.0),
            ("R", 90.0, 5.0, 0.0),
            ("R", 150.0, 150.0, 0.0),
        ]
    );
    // 001's incomplete-thread allowances at n = 800 rpm, L = 3 mm:
    // d1 = 3.6·L·n/1800 = 3.6·3·800/1800 = 4.8 mm, d2 = L·n/1800 = 1.333 mm.
    // The thread starts 5 mm before the face (Z0) and runs 1.5 mm past
    // the 70 mm length: both allowances are covered.
    let (d1, d2) = (3.6 * 3.0 * 800.0 / 1800.0, 3.0 * 800.0 / 1800.0);
    assert!((d1 - 4.8f64).abs() < 1e-12 && (d2 - 4.0 / 3.0f64).abs() < 1e-12);
    let t = trace(&r);
    for i in (1..t.len()).filter(|&i| t[i].0 == "T") {
        // Run-in from the start Z (the point before the cut) to the face
        // Z0, run-out from the end of the 70 mm thread to the cut's end.
        assert!(t[i - 1].2 - 0.0 >= d1);
        assert!(-70.0 - t[i].2 >= d2);
    }
}

/// 001 G32 example (taper thread, absolute): both axes move in G32.
#[test]
fn g32_taper_example_001_absolute() {
    let r = run_on(
        PUMA,
        "G50 S800 T0100 ;\nG97 S800 M03 ;\nG00 X90.0 Z5.0 T0101 ;\nX22.026 ;\nG32 X49.562 Z-71.5 F3.0 ;\nG00 X90.0 ;\nZ5.0 ;\nX21.052 ;\nG32 X48.588 Z-71.5 ;\nG00 X90.0 ;\nZ5.0 ;\nX150.0 Z150.0 T0100 ;\nM30 ;\n",
    );
    ok(&r);
    assert_eq!(
        trace(&r),
        vec![
            ("R", 90.0, 5.0, 0.0),
            ("R", 22.026, 5.0, 0.0),
            ("T", 49.562, -71.5, 3.0),
            ("R", 90.0, -71.5, 0.0),
            ("R", 90.0, 5.0, 0.0),
            ("R", 21.052, 5.0, 0.0),
            ("T", 48.588, -71.5, 3.0),
            ("R", 90.0, -71.5, 0.0),
            ("R", 90.0, 5.0, 0.0),
            ("R", 150.0, 150.0, 0.0),
        ]
    );
}

/// 001 G32 example (taper thread, incremental) as printed. Its numbers
/// do not match the absolute version (U27.321 from X22.026 ends at
/// X49.347, not X49.562; G00 U40.438 ends at X89.785): kerf executes
/// what is written (docs/dialects.md). By hand: 90 − 67.974 = 22.026;
/// 22.026 + 27.321 = 49.347, Z 5 − 76.5 = −71.5; 49.347 + 40.438 =
/// 89.785; Z −71.5 + 76.5 = 5; 89.785 − 68.948 = 20.837; 20.837 + 27.321
/// = 48.158.
#[test]
fn g32_taper_example_001_incremental() {
    let r = run_on(
        PUMA,
        "G50 S800 T0100 ;\nG97 S800 M03 ;\nG00 X90.0 Z5.0 T0101 ;\nU-67.974 ;\nG32 U27.321 W-76.5 F3.0 ;\nG00 U40.438 ;\nW76.5 ;\nU-68.948 ;\nG32 U27.321 W-76.5 ;\nG00 X90.0 ;\nW76.5 ;\nX150.0 Z150.0 T0100 ;\nM30 ;\n",
    );
    ok(&r);
    assert_eq!(
        trace(&r),
        vec![
            ("R", 90.0, 5.0, 0.0),
            ("R", 22.026, 5.0, 0.0),
            ("T", 49.347, -71.5, 3.0),
            ("R", 89.785, -71.5, 0.0),
            ("R", 89.785, 5.0, 0.0),
            ("R", 20.837, 5.0, 0.0),
            ("T", 48.158, -71.5, 3.0),
            ("R", 90.0, -71.5, 0.0),
            ("R", 90.0, 5.0, 0.0),
            ("R", 150.0, 150.0, 0.0),
        ]
    );
}

#[test]
fn g32_alarms() {
    // No lead ever given: PS011 at the G32 block.
    let r = run_on(PUMA, "G97 S500 M03\nG00 X40. Z5.\nG32 Z-20.\n");
    assert_eq!(alarm(&r), ("PS011", 3, 1));
    // Taper thread in G96: kerf's rule (docs/dialects.md).
    let r = run_on(
        PUMA,
        "G50 S1500\nG96 S100 M03\nG00 X40. Z5.\nG32 X44. Z-20. F2.\n",
    );
    assert_eq!(alarm(&r), ("KERF-0168", 4, 1));
    // A straight thread in G96 is cut (the rpm cannot change).
    let r = run_on(
        PUMA,
        "G50 S1500\nG96 S100 M03\nG00 X40. Z5.\nG32 Z-20. F2.\n",
    );
    ok(&r);
}

/// 001 G90 "Example 1) When the taper is R": the program as printed.
/// Start after `G00 X61. Z2.`: A = (X61, Z2). `W-42.` ends at Z −40.
/// Each cycle: rapid X to the cut start (X_end + 2R at Z2), feed to the
/// end point, feed X back to 61, rapid back to Z2.
/// The last block `Z-40 R-5.25` has no decimal point: on the Fanuc 0-T
/// (IS-B) that is Z −0.040 mm (docs/dialects.md); `X40` stays from the
/// blocks before. Cut start diameters: 40 + 2·(−1.75) = 36.5,
/// 40 + 2·(−3.5) = 33, 40 + 2·(−5.25) = 29.5.
#[test]
fn g90_taper_example_001() {
    let r = run_on(
        PUMA,
        "G30 U0 W0 ;\nG50 S2000 T0100 ;\nG96 S200 M03 ;\nG00 X61.0 Z2.0 T0101 M8 ;\nG90 X55.0 W-42.0 F0.25 ;\nX50.0 ;\nX45.0 ;\nX40.0 ;\nZ-12.0 R-1.75 ;\nZ-26.0 R-3.5 ;\nZ-40 R-5.25 ;\nG30 U0 W0 ;\nM30 ;\n",
    );
    ok(&r);
    let t = trace(&r);
    // G30 from the start (already at the 2nd reference: no move).
    let k = t.iter().position(|m| m.1 == 61.0).unwrap();
    let mut want = vec![("R", 61.0, 2.0, 0.0)];
    for x in [55.0, 50.0, 45.0, 40.0] {
        want.extend([
            ("R", x, 2.0, 0.0),
            ("F", x, -40.0, 0.0),
            ("F", 61.0, -40.0, 0.0),
            ("R", 61.0, 2.0, 0.0),
        ]);
    }
    for (xs, z) in [(36.5, -12.0), (33.0, -26.0), (29.5, -0.04)] {
        want.extend([
            ("R", xs, 2.0, 0.0),
            ("F", 40.0, z, 0.0),
            ("F", 61.0, z, 0.0),
            ("R", 61.0, 2.0, 0.0),
        ]);
    }
    assert_eq!(t[k..k + want.len()].to_vec(), want);
    // Then G30 U0 W0: the 2nd reference X200 Z300 (001 N735/N736).
    assert_eq!(
        t[k + want.len()..].last().unwrap(),
        &("R", 200.0, 300.0, 0.0)
    );
}

/// The same taper with the Z word as the drawing means it (Z-40.0): the
/// cut start Ø29.5 at Z2 lies on the taper line of the drawing (Ø30 at Z0
/// to Ø40 at Z−40: slope 10/40 in diameter, so at Z2 Ø30 − 2·0.25 = 29.5).
#[test]
fn g90_taper_as_drawn() {
    let r = run_on(
        PUMA,
        "G97 S500 M03\nG00 X61.0 Z2.0\nG90 X40. Z-40.0 R-5.25 F0.25\n",
    );
    ok(&r);
    let xs = 30.0 - 2.0 * (10.0 / 40.0);
    assert_eq!(xs, 29.5);
    assert_eq!(
        from(&r, 1),
        vec![
            ("R", xs, 2.0, 0.0),
            ("F", 40.0, -40.0, 0.0),
            ("F", 61.0, -40.0, 0.0),
            ("R", 61.0, 2.0, 0.0),
        ]
    );
}

/// 001 G90 example 2: straight turning X51 … X30 from X56 Z2, W-32 → Z−30.
#[test]
fn g90_straight_example_001() {
    let r = run_on(
        PUMA,
        "G30 U0 W0 :\nG50 S2000 T0100 :\nG96 S200 M03 :\nG00 X56.0 Z2.0 T0101 M08 :\nG90 X51.0 W-32.0 F0.25 :\nX46.0 :\nX41.0 :\nX36.0 :\nX31.0 :\nX30.0 :\nG30 U0 W0 :\nM30 :\n"
            .replace(" :", " ;")
            .as_str(),
    );
    ok(&r);
    let t = trace(&r);
    let k = t.iter().position(|m| m.1 == 56.0).unwrap();
    let mut want = vec![("R", 56.0, 2.0, 0.0)];
    for x in [51.0, 46.0, 41.0, 36.0, 31.0, 30.0] {
        want.extend([
            ("R", x, 2.0, 0.0),
            ("F", x, -30.0, 0.0),
            ("F", 56.0, -30.0, 0.0),
            ("R", 56.0, 2.0, 0.0),
        ]);
    }
    assert_eq!(t[k..k + want.len()].to_vec(), want);
}

/// The four sign cases of 001's G90 figure, A and R chosen by hand.
#[test]
fn g90_four_sign_cases() {
    // 1. U<0 W<0 R<0: A Ø60 Z2, end Ø40 Z−20, R−2 → start Ø36.
    // 2. U>0 W<0 R>0 (bore): A Ø10 Z2, end Ø30 Z−20, R2 → start Ø34.
    // 3. U<0 W<0 R>0, |R| ≤ |U/2|: A Ø60, end Ø40, R4 → start Ø48.
    // 4. U>0 W<0 R<0, |R| ≤ |U/2|: A Ø10, end Ø30, R−4 → start Ø22.
    for (ax, ex, rr, xs) in [
        (60.0, 40.0, -2.0, 36.0),
        (10.0, 30.0, 2.0, 34.0),
        (60.0, 40.0, 4.0, 48.0),
        (10.0, 30.0, -4.0, 22.0),
    ] {
        let prog = format!("G97 S500 M03\nG00 X{ax:.1} Z2.\nG90 X{ex:.1} Z-20. R{rr:.1} F0.2\n");
        let r = run_on(PUMA, &prog);
        ok(&r);
        assert_eq!(
            from(&r, 1),
            vec![
                ("R", xs, 2.0, 0.0),
                ("F", ex, -20.0, 0.0),
                ("F", ax, -20.0, 0.0),
                ("R", ax, 2.0, 0.0),
            ],
            "{prog}"
        );
    }
    // Case 3 with |R| > |U/2| (R12 > 10): the cut would start behind A.
    let r = run_on(
        PUMA,
        "G97 S500 M03\nG00 X60. Z2.\nG90 X40. Z-20. R12. F0.2\n",
    );
    assert_eq!(alarm(&r), ("KERF-0168", 3, 16));
}

/// 001 G92 "Example) M50 x 1.5" as printed (the `-` lines of the print
/// are left out). A = Ø70 Z5; the taper R−6.166 puts every cut start at
/// X_end − 12.332 (diameter) at Z5; steps 1, 3, 4 rapid.
#[test]
fn g92_example_001() {
    let r = run_on(
        PUMA,
        "G30 U0 W0 ;\nG50 S1000 T0100 ;\nG97 S1000 M03 ;\nG00 X70.0 Z5.0 T0101 M08 ;\nG92 X49.4 Z-32.0 R-6.166 F1.5 ;\nX49.0 ;\nX48.7 ;\nX48.5 ;\nG30 U0 W0 ;\nM30 ;\n",
    );
    ok(&r);
    let t = trace(&r);
    let k = t.iter().position(|m| m.1 == 70.0).unwrap();
    let mut want = vec![("R", 70.0, 5.0, 0.0)];
    for x in [49.4f64, 49.0, 48.7, 48.5] {
        want.extend([
            ("R", round(x - 12.332), 5.0, 0.0),
            ("T", x, -32.0, 1.5),
            ("R", 70.0, -32.0, 0.0),
            ("R", 70.0, 5.0, 0.0),
        ]);
    }
    assert_eq!(t[k..k + want.len()].to_vec(), want);
}

/// M76 thread chamfering (001 note 4: one lead by parameter): the cut ends
/// 1.5 mm (= 1·L) before Z−32 and pulls out at 45° by 1.5 mm in Z and
/// radius (3 mm in diameter), still threading; M77 switches it off.
#[test]
fn g92_thread_chamfer_m76() {
    let r = run_on(
        PUMA,
        "G97 S1000 M03\nG00 X70. Z5.\nM76\nG92 X49.4 Z-32. F1.5\nM77\nX49.\n",
    );
    ok(&r);
    assert_eq!(
        from(&r, 1),
        vec![
            ("R", 49.4, 5.0, 0.0),
            ("T", 49.4, -30.5, 1.5),
            ("T", 52.4, -32.0, 1.5),
            ("R", 70.0, -32.0, 0.0),
            ("R", 70.0, 5.0, 0.0),
            ("R", 49.0, 5.0, 0.0),
            ("T", 49.0, -32.0, 1.5),
            ("R", 70.0, -32.0, 0.0),
            ("R", 70.0, 5.0, 0.0),
        ]
    );
}

/// G94 (the face cycle, 001's section printed with "G92" in its format
/// line): A Ø62 Z2. Rapid Z to the cut start, feed X to the end, feed Z
/// back to Z2, rapid X back. Then Z−4 alone repeats; a taper R−3 starts
/// the cut at Z(end) − 3 on Ø62.
#[test]
fn g94_face_cycle() {
    let r = run_on(
        PUMA,
        "G97 S500 M03\nG00 X62. Z2.\nG94 X20. Z-2. F0.2\nZ-4.\nZ-6. R-3.\nG00 X80.\n",
    );
    ok(&r);
    assert_eq!(
        from(&r, 1),
        vec![
            ("R", 62.0, -2.0, 0.0),
            ("F", 20.0, -2.0, 0.0),
            ("F", 20.0, 2.0, 0.0),
            ("R", 62.0, 2.0, 0.0),
            ("R", 62.0, -4.0, 0.0),
            ("F", 20.0, -4.0, 0.0),
            ("F", 20.0, 2.0, 0.0),
            ("R", 62.0, 2.0, 0.0),
            ("R", 62.0, -9.0, 0.0),
            ("F", 20.0, -6.0, 0.0),
            ("F", 20.0, 2.0, 0.0),
            ("R", 62.0, 2.0, 0.0),
            ("R", 80.0, 2.0, 0.0),
        ]
    );
}

/// G96 with the G50 S clamp: the rpm follows X. By hand, n = 1000·v /
/// (π·D): S200 at Ø61 → 200000 / (π·61) = 1043.63 rpm; at Ø40 →
/// 1591.55; at Ø20 → 3183.1, clamped to G50 S2000. A move that does not
/// change X (Z only) makes no new spindle event.
#[test]
fn g96_rpm_follows_x() {
    let r = run_on(
        PUMA,
        "G00 X61. Z2.\nG50 S2000\nG96 S200 M03\nG01 Z-10. F0.2\nX40.\nX20.\nZ-20.\n",
    );
    ok(&r);
    let seq: Vec<(String, f64)> = r
        .events
        .iter()
        .filter_map(|e| match &e.cmd {
            Canon::Spindle { rpm, css, .. } => {
                assert_eq!(*css, Some(200.0));
                Some(("S".to_string(), round(*rpm)))
            }
            Canon::Feed { m, .. } => Some(("F".to_string(), round(2.0 * m.to[0]))),
            _ => None,
        })
        .collect();
    let rpm = |d: f64| round((200_000.0 / (std::f64::consts::PI * d)).min(2000.0));
    assert_eq!(
        seq,
        vec![
            ("S".to_string(), rpm(61.0)),
            ("F".to_string(), 61.0),
            ("S".to_string(), rpm(40.0)),
            ("F".to_string(), 40.0),
            ("S".to_string(), 2000.0),
            ("F".to_string(), 20.0),
            ("F".to_string(), 20.0),
        ]
    );
    assert_eq!(rpm(40.0), round(1591.549431));
}

/// 001's M63/M64/M65: the spindle and the coolant together (the list:
/// "MAIN-SPDL CW & COOLANT ON", "MAIN-SPDL & COOLANT OFF").
#[test]
fn m63_m65_spindle_and_coolant() {
    let r = run_on(PUMA, "G97 S600 M63\nG00 X50. Z5.\nM65\nM64\nM65\n");
    ok(&r);
    let seq: Vec<String> = r
        .events
        .iter()
        .filter_map(|e| match &e.cmd {
            Canon::Spindle { dir, rpm, .. } => Some(format!("S {dir:?} {rpm}")),
            Canon::Coolant { flood, .. } => Some(format!("C {flood}")),
            _ => None,
        })
        .collect();
    assert_eq!(
        seq,
        vec![
            "S Cw 600",
            "C true",
            "S Stop 0",
            "C false",
            "S Ccw 600",
            "C true",
            "S Stop 0",
            "C false"
        ]
    );
}
