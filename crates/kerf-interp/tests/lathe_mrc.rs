//! PUMA (001, Fanuc 0-T) multiple repetitive cycles G70-G76. Every pass
//! end point is worked out by hand in the comments (radius values, from
//! fanuc-semantics §1 and its Appendix A) and compared with X as a
//! diameter, the way the programs write it. 001 prints complete programs
//! only for G74 and G75; its G71 and G76 pages give the formats, its G73
//! example stops before the shape blocks N12-N16 — those tests complete
//! the programs with the shapes written here (docs/dialects.md).

use kerf_canon::Canon;
use kerf_interp::Run;

mod common;
use common::lathe::{g71_level, mv, trace};
use common::{alarm, ok, round, run_on};

const PUMA: &str = "puma-lathe";

/// The arc centres (X radius, Z) of the run's arcs.
fn centres(r: &Run) -> Vec<(f64, f64)> {
    r.events
        .iter()
        .filter_map(|e| match &e.cmd {
            Canon::Arc { center, .. } => Some((round(center[0]), round(center[2]))),
            _ => None,
        })
        .collect()
}

const G71_PROG: &str = "G97 S500 M03
G00 X82. Z2.
G71 U2. R0.5
G71 P10 Q60 U0.4 W0.1 F0.25
N10 G00 X30.
N20 G01 Z-20. F0.1
N30 X40. Z-30.
N40 G02 X60. Z-40. R10.
N50 G01 X78.
N60 Z-60.
G70 P10 Q60
G00 X100. Z50.
M30
";

/// G71 type I on a shape with a straight, a taper, a concave arc, a
/// shoulder and a last straight. By hand (radius): A = (41, 2); the
/// shape shifted by (Δu/2, Δw) = (0.2, 0.1) starts at (15.2, 2.1) and
/// runs (15.2, −19.9) → (20.2, −29.9) → arc about (30.2, −29.9) R10 to
/// (30.2, −39.9) → (39.2, −39.9) → (39.2, −59.9). Levels 41 − 2k: 39 …
/// 17, then the last one clamped to 15.2. A cut at level L ends where
/// the shape rises above L: on the shoulder (Z −39.9) for L ≥ 31, on the
/// arc (Z = −29.9 − √(100 − (L − 30.2)²)) for 21 ≤ L ≤ 29, on the taper
/// (Z = −19.9 − 2(L − 15.2)) for L = 19, 17, at the taper's start (Z −19.9)
/// for 15.2. Infeed rapid (N10 is G00), cut at F0.25 (the F of N20 is
/// for G70 only), escape 0.5 at 45°, rapid back to Z2; then the
/// semi-finish pass along the shifted shape and a rapid to A.
#[test]
fn g71_type1_every_pass() {
    let r = run_on(PUMA, G71_PROG);
    ok(&r);
    let t = trace(&r);
    let mut want = vec![mv("R", 41.0, 2.0, 0.0)];
    let mut levels: Vec<f64> = (1..=12).map(|k| 41.0 - 2.0 * k as f64).collect();
    levels.push(15.2);
    for &l in &levels {
        let z: f64 = if l >= 31.0 {
            -39.9
        } else if l >= 21.0 {
            -29.9 - (100.0 - (l - 30.2) * (l - 30.2)).sqrt()
        } else if l > 15.2 {
            -19.9 - 2.0 * (l - 15.2)
        } else {
            -19.9
        };
        want.extend(g71_level(l, z, 0.25));
    }
    want.extend([
        mv("R", 15.2, 2.1, 0.0),
        mv("F", 15.2, -19.9, 0.25),
        mv("F", 20.2, -29.9, 0.25),
        mv("A", 30.2, -39.9, 0.25),
        mv("F", 39.2, -39.9, 0.25),
        mv("F", 39.2, -59.9, 0.25),
        mv("R", 41.0, 2.0, 0.0),
    ]);
    // G70: the shape itself, N10 rapid, then at the F of N20 (0.1), and a
    // rapid back to A; then the block after G70.
    want.extend([
        mv("R", 15.0, 2.0, 0.0),
        mv("F", 15.0, -20.0, 0.1),
        mv("F", 20.0, -30.0, 0.1),
        mv("A", 30.0, -40.0, 0.1),
        mv("F", 39.0, -40.0, 0.1),
        mv("F", 39.0, -60.0, 0.1),
        mv("R", 41.0, 2.0, 0.0),
        mv("R", 50.0, 50.0, 0.0),
    ]);
    assert_eq!(t, want);
    // The arc's centre: G02 from (20, −30) to (30, −40) R10 bulges toward
    // −X/+Z: centre (30, −30), shifted (30.2, −29.9) in the roughing pass.
    assert_eq!(centres(&r), vec![(30.2, -29.9), (30.0, -30.0)]);
}

/// The first-block values are modal: a second G71 without its first block
/// cuts at the same Δd (2) and e (0.5). Shape: one straight Ø60 to Z−10
/// from A = Ø70 Z2, no allowance: levels 33, 31 (clamped to 30 is the
/// shape's start: 35 − 2·3 = 29 < 30 → 30).
#[test]
fn g71_first_block_modal() {
    let r = run_on(
        PUMA,
        "G97 S500 M03\nG00 X70. Z2.\nG71 U2. R0.5\nG71 P1 Q2 F0.3\nN1 G01 X60.\nN2 Z-10.\nG71 P1 Q2 F0.3\n",
    );
    ok(&r);
    let t = trace(&r);
    let mut one = Vec::new();
    for l in [33.0, 31.0, 30.0] {
        one.extend([
            mv("F", l, 2.0, 0.3),
            mv("F", l, -10.0, 0.3),
            mv("R", l + 0.5, -9.5, 0.0),
            mv("R", l + 0.5, 2.0, 0.0),
        ]);
    }
    // N1 is G01: infeeds and the approach to the shape are feeds.
    one.extend([
        mv("F", 30.0, 2.0, 0.3),
        mv("F", 30.0, -10.0, 0.3),
        mv("R", 35.0, 2.0, 0.0),
    ]);
    // The approach to (30, 2) from (30.5, 2) is the "F 30 2" above.
    let mut want = vec![mv("R", 35.0, 2.0, 0.0)];
    want.extend(one.clone());
    want.extend(one);
    assert_eq!(t, want);
}

/// G72 type I (facing): A = Ø84 Z2 = (42, 2); shape N10 Z−10, N20 X80,
/// N30 X60 Z−6, N40 Z−2, N50 X20 Z0, shifted by (0, Δw 0.2): (42, −9.8) →
/// (40, −9.8) → (30, −5.8) → (30, −1.8) → (10, 0.2). Levels in Z 2 − 2k: 0,
/// −2, −4, −6, −8, then −9.8. A cut along −X at level L ends where the
/// shape rises above L: L = 0 on the last taper, X = 30 − 20·(L + 1.8)/2 =
/// 12; L = −2, −4 on the face X30; L = −6, −8 on the taper X = 40 −
/// 10·(L + 9.8)/4 = 30.5, 35.5; L = −9.8 at (40, −9.8). Escape 0.5 at 45°
/// (+X, +Z), rapid back to X42.
#[test]
fn g72_type1_every_pass() {
    let r = run_on(
        PUMA,
        "G97 S500 M03\nG00 X84. Z2.\nG72 W2. R0.5\nG72 P10 Q50 U0 W0.2 F0.2\nN10 G00 Z-10.\nN20 G01 X80.\nN30 X60. Z-6.\nN40 Z-2.\nN50 X20. Z0.\nG00 X100.\n",
    );
    ok(&r);
    let mut want = vec![mv("R", 42.0, 2.0, 0.0)];
    for (l, x) in [
        (0.0, 12.0),
        (-2.0, 30.0),
        (-4.0, 30.0),
        (-6.0, 30.5),
        (-8.0, 35.5),
        (-9.8, 40.0),
    ] {
        want.extend([
            mv("R", 42.0, l, 0.0),
            mv("F", x, l, 0.2),
            mv("R", x + 0.5, l + 0.5, 0.0),
            mv("R", 42.0, l + 0.5, 0.0),
        ]);
    }
    want.extend([
        mv("R", 42.0, -9.8, 0.0),
        mv("F", 40.0, -9.8, 0.2),
        mv("F", 30.0, -5.8, 0.2),
        mv("F", 30.0, -1.8, 0.2),
        mv("F", 10.0, 0.2, 0.2),
        mv("R", 42.0, 2.0, 0.0),
        mv("R", 50.0, 2.0, 0.0),
    ]);
    assert_eq!(trace(&r), want);
}

/// 001's G73 example (its lines as printed) completed with a shape N12-N16
/// of our own: N12 G00 X20 Z2, N13 G01 Z−10, N14 X40 Z−20, N15 G02 X60
/// Z−30 R10, N16 G01 X70. Δi = 3, Δk = 2, d = 2, Δu/2 = 0.25, Δw = 0.1.
/// Pass 1 shifted by (3.25, 2.1), pass 2 by (0.25, 0.1) (fanuc-semantics
/// A.2: relief·(d − n)/(d − 1) + allowance); each approached by rapid (N12
/// is G00), followed at F0.25, then a rapid to A = (35, 10). The arc
/// (20, −20) → (30, −30) CW R10 has its centre at (30, −20).
#[test]
fn g73_example_001_completed() {
    let r = run_on(
        PUMA,
        "N10 G50 S2000 T0300 ;\nG96 S200 M03 ;\nG00 X35.0 Z5.0 T0303 ;\nZ0 ;\nG01 X-1.6 F0.2 ;\nG00 X70.0 Z10.0 ;\nG73 U3.0 W2.0 R2 ;\nG73 P12 Q16 U0.5 W0.1 F0.25 ;\nN12 G00 X20. Z2. ;\nN13 G01 Z-10. ;\nN14 X40. Z-20. ;\nN15 G02 X60. Z-30. R10. ;\nN16 G01 X70. ;\nG70 P12 Q16 ;\nG00 X100. Z50. ;\nM30 ;\n",
    );
    ok(&r);
    let t = trace(&r);
    let k = t.iter().position(|m| m.1 == 70.0 && m.2 == 10.0).unwrap();
    let mut want = vec![];
    for (dx, dz) in [(3.25, 2.1), (0.25, 0.1)] {
        want.extend([
            mv("R", 10.0 + dx, 2.0 + dz, 0.0),
            mv("F", 10.0 + dx, -10.0 + dz, 0.25),
            mv("F", 20.0 + dx, -20.0 + dz, 0.25),
            mv("A", 30.0 + dx, -30.0 + dz, 0.25),
            mv("F", 35.0 + dx, -30.0 + dz, 0.25),
            mv("R", 35.0, 10.0, 0.0),
        ]);
    }
    // G70 at the modal F (0.25: no F in the shape).
    want.extend([
        mv("R", 10.0, 2.0, 0.0),
        mv("F", 10.0, -10.0, 0.25),
        mv("F", 20.0, -20.0, 0.25),
        mv("A", 30.0, -30.0, 0.25),
        mv("F", 35.0, -30.0, 0.25),
        mv("R", 35.0, 10.0, 0.0),
        mv("R", 50.0, 50.0, 0.0),
    ]);
    assert_eq!(t[k + 1..].to_vec(), want);
    assert_eq!(
        centres(&r),
        vec![(33.25, -17.9), (30.25, -19.9), (30.0, -20.0)]
    );
}

/// 001's G74 example (one groove at Ø20: X and P omitted): A = (10, 1),
/// e = 1, Δk = 3, bottom Z−10. Pecks: feed to −2, back 1 to −1, feed to
/// −5, back to −4, feed to −8, back to −7, feed to −10; no relief; rapid
/// back to Z1 (= A).
#[test]
fn g74_example_001() {
    let r = run_on(
        PUMA,
        "N10 G50 S500 T0200 ;\nG97 S280 M03 ;\nN10 G00 X20.0 Z1.0 ;\nG74 R1.0 ;\nG74 Z-10.0 Q3000 F0.1 ;\nG00 X200.0 Z200.0 ;\nM30 ;\n",
    );
    ok(&r);
    assert_eq!(
        trace(&r),
        vec![
            mv("R", 10.0, 1.0, 0.0),
            mv("F", 10.0, -2.0, 0.1),
            mv("R", 10.0, -1.0, 0.0),
            mv("F", 10.0, -5.0, 0.1),
            mv("R", 10.0, -4.0, 0.0),
            mv("F", 10.0, -8.0, 0.1),
            mv("R", 10.0, -7.0, 0.0),
            mv("F", 10.0, -10.0, 0.1),
            mv("R", 10.0, 1.0, 0.0),
            mv("R", 100.0, 200.0, 0.0),
        ]
    );
}

/// G74 face grooving with columns and a relief: A = (30, 1), end X40 →
/// 20, Z−5, Δi = 4 (P4000), Δk = 2 (Q2000), Δd = 0.3, e = 0.5. Columns at
/// 30, 26, 22, then 20 (clamped); each: pecks to −1, −3, −5 with 0.5
/// back, relief 0.3 toward A's side (+X), rapid to Z1, rapid to the next
/// column; finally rapid to A.
#[test]
fn g74_columns_relief() {
    let r = run_on(
        PUMA,
        "G97 S500 M03\nG00 X60. Z1.\nG74 R0.5\nG74 X40. Z-5. P4000 Q2000 R0.3 F0.1\n",
    );
    ok(&r);
    let mut want = vec![mv("R", 30.0, 1.0, 0.0)];
    for (i, x) in [30.0, 26.0, 22.0, 20.0].into_iter().enumerate() {
        if i > 0 {
            want.push(mv("R", x, 1.0, 0.0));
        }
        want.extend([
            mv("F", x, -1.0, 0.1),
            mv("R", x, -0.5, 0.0),
            mv("F", x, -3.0, 0.1),
            mv("R", x, -2.5, 0.0),
            mv("F", x, -5.0, 0.1),
            mv("R", x + 0.3, -5.0, 0.0),
            mv("R", x + 0.3, 1.0, 0.0),
        ]);
    }
    want.push(mv("R", 30.0, 1.0, 0.0));
    assert_eq!(trace(&r), want);
}

/// 001's G75 example (`G97 S_` printed without a value: S280 here). A =
/// (41, −60); grooves at Z−60, −40, −20 (Q20000 = 20 mm), pecks in X of 3
/// (P3000) with e = 1: feed 38, back 39, feed 35, back 36, feed 32, back
/// 33, feed 30; rapid X41; rapid to the next groove; finally rapid to A.
#[test]
fn g75_example_001() {
    let r = run_on(
        PUMA,
        "N10 G50 S500 T0100 ;\nG97 S280 M03 ;\nG00 X90.0 Z1.0 T0101 ;\nX82.0 Z-60.0 ;\nG75 R1.0 ;\nG75 X60.0 Z-20.0 P3000 Q20000 F0.1 ;\nG00 X90.0\nX200.0 Z200.0 T0100 ;\nM30 ;\n",
    );
    ok(&r);
    let mut want = vec![mv("R", 45.0, 1.0, 0.0), mv("R", 41.0, -60.0, 0.0)];
    for (i, z) in [-60.0, -40.0, -20.0].into_iter().enumerate() {
        if i > 0 {
            want.push(mv("R", 41.0, z, 0.0));
        }
        want.extend([
            mv("F", 38.0, z, 0.1),
            mv("R", 39.0, z, 0.0),
            mv("F", 35.0, z, 0.1),
            mv("R", 36.0, z, 0.0),
            mv("F", 32.0, z, 0.1),
            mv("R", 33.0, z, 0.0),
            mv("F", 30.0, z, 0.1),
            mv("R", 41.0, z, 0.0),
        ]);
    }
    want.extend([
        mv("R", 41.0, -60.0, 0.0),
        mv("R", 45.0, -60.0, 0.0),
        mv("R", 100.0, 200.0, 0.0),
    ]);
    assert_eq!(trace(&r), want);
}

/// G76 in 001's two-block format: `G76 P021060 Q100 R0.05` (m = 2 finishing
/// passes, r = 10 → run-out 1.0·L = 2 mm, a = 60°, Δdmin 0.1, d 0.05),
/// `G76 X27.4 Z-30. P1300 Q500 F2.` (root Ø27.4, k = 1.3, Δd = 0.5, L 2).
/// Depths 0.5·√n for n = 1…6 (0.5, 0.7071, 0.8660, 1.0, 1.1180, 1.2247;
/// each step ≥ Δdmin 0.1), n = 7 gives 1.3229 ≥ k − d = 1.25 → 1.25, then
/// 1.3 twice. Pass at depth D: rapid to X radius 13.7 + (1.3 − D), Z 5 +
/// (1.3 − D)·tan 30°, thread to Z−28 (2 mm before the end), pull out at
/// 45° to X + 2 at Z−30, rapid to X17, rapid to A (17, 5).
#[test]
fn g76_every_pass() {
    let r = run_on(
        PUMA,
        "G97 S600 M03\nG00 X34. Z5.\nG76 P021060 Q100 R0.05\nG76 X27.4 Z-30. P1300 Q500 F2.\n",
    );
    ok(&r);
    let depths = [
        0.5,
        0.5 * 2f64.sqrt(),
        0.5 * 3f64.sqrt(),
        1.0,
        0.5 * 5f64.sqrt(),
        0.5 * 6f64.sqrt(),
        1.25,
        1.3,
        1.3,
    ];
    let tan30 = 1.0 / 3f64.sqrt();
    let mut want = vec![mv("R", 17.0, 5.0, 0.0)];
    for d in depths {
        let x = 13.7 + (1.3 - d);
        want.extend([
            mv("R", x, 5.0 + (1.3 - d) * tan30, 0.0),
            mv("T", x, -28.0, 2.0),
            mv("T", x + 2.0, -30.0, 2.0),
            mv("R", 17.0, -30.0, 0.0),
            mv("R", 17.0, 5.0, 0.0),
        ]);
    }
    assert_eq!(trace(&r), want);
}

/// G76 taper (R i = −1: the root starts 1 mm lower in radius at Z of A)
/// with no run-out (r = 0) and a = 0 (straight infeed): one finishing
/// pass. Root line from (10 − 1, 2) to (10, −18); Δd 0.4, k 0.6, d 0,
/// Δdmin 0.05: depths 0.4, 0.5657 (0.4·√2), then 0.6 (clamp), then 0.6.
/// Each cut from (root(2) + 0.6 − D, 2) to (10 + 0.6 − D, −18).
#[test]
fn g76_taper_straight_infeed() {
    let r = run_on(
        PUMA,
        "G97 S600 M03\nG00 X30. Z2.\nG76 P010000 Q50 R0\nG76 X20. Z-18. R-1. P600 Q400 F1.5\n",
    );
    ok(&r);
    let mut want = vec![mv("R", 15.0, 2.0, 0.0)];
    for d in [0.4, 0.4 * 2f64.sqrt(), 0.6, 0.6] {
        want.extend([
            mv("R", 9.0 + 0.6 - d, 2.0, 0.0),
            mv("T", 10.0 + 0.6 - d, -18.0, 1.5),
            mv("R", 15.0, -18.0, 0.0),
            mv("R", 15.0, 2.0, 0.0),
        ]);
    }
    assert_eq!(trace(&r), want);
}

#[test]
fn mrc_alarms() {
    let head = "G97 S500 M03\nG00 X82. Z2.\nG71 U2. R0.5\n";
    // P without Q: PS061 at P.
    let r = run_on(PUMA, &format!("{head}G71 P10 U0.4 F0.2\nN10 G00 X30.\n"));
    assert_eq!(alarm(&r), ("PS061", 4, 5));
    // ns not in the program: PS063 at P.
    let r = run_on(PUMA, &format!("{head}G71 P99 Q100 F0.2\nN10 G00 X30.\n"));
    assert_eq!(alarm(&r), ("PS063", 4, 5));
    // nf not found before the end: PS063 at Q.
    let r = run_on(
        PUMA,
        &format!("{head}G71 P10 Q100 F0.2\nN10 G00 X30.\nZ-10.\n"),
    );
    assert_eq!(alarm(&r), ("PS063", 4, 9));
    // First shape block without G00/G01: PS065 on that block.
    let r = run_on(
        PUMA,
        &format!("{head}G71 P10 Q20 F0.2\nN10 X30.\nN20 G01 Z-10.\n"),
    );
    assert_eq!(alarm(&r), ("PS065", 5, 1));
    // A type I shape that turns back in X (a pocket): PS064 at P.
    let r = run_on(
        PUMA,
        &format!(
            "{head}G71 P10 Q40 F0.2\nN10 G00 X30.\nN20 G01 Z-10.\nN30 X20. Z-20.\nN40 Z-30.\n"
        ),
    );
    assert_eq!(alarm(&r), ("PS064", 4, 5));
    // A shape ending with a chamfer: PS069 at C.
    let r = run_on(
        PUMA,
        &format!("{head}G71 P10 Q20 F0.2\nN10 G00 X30.\nN20 G01 Z-10. C1.\n"),
    );
    assert_eq!(alarm(&r), ("PS069", 6, 15));
    // G28 inside the shape: PS066 at the G word.
    let r = run_on(
        PUMA,
        &format!("{head}G71 P10 Q30 F0.2\nN10 G00 X30.\nN20 G28 U0\nN30 G01 Z-10.\n"),
    );
    assert_eq!(alarm(&r), ("PS066", 6, 5));
    // Δd = 0: PS062 at U.
    let r = run_on(PUMA, "G00 X82. Z2.\nG71 U0 R0.5\n");
    assert_eq!(alarm(&r), ("PS062", 2, 5));
    // G76 without any lead: PS011; Δd (Q) = 0: PS062.
    let r = run_on(
        PUMA,
        "G97 S600 M03\nG00 X34. Z5.\nG76 X27.4 Z-30. P1300 Q500\n",
    );
    assert_eq!(alarm(&r), ("PS011", 3, 1));
    let r = run_on(
        PUMA,
        "G97 S600 M03\nG00 X34. Z5.\nG76 X27.4 Z-30. P1300 Q0 F2.\n",
    );
    assert_eq!(alarm(&r), ("PS062", 3, 1));
    // G74 without a peck depth: PS062 at Q.
    let r = run_on(PUMA, "G97 S600 M03\nG00 X20. Z1.\nG74 Z-10. F0.1\n");
    assert_eq!(alarm(&r), ("PS062", 3, 1));
}

/// A shape longer than the documented bound (2,000 blocks) stops with
/// KERF-0168 instead of growing without limit.
#[test]
fn shape_is_bounded() {
    let mut p =
        String::from("G97 S500 M03\nG00 X82. Z2.\nG71 U2. R0.5\nG71 P1 Q9999 F0.2\nN1 G01 X30.\n");
    for i in 0..2100 {
        p.push_str(&format!("Z-{}.\n", i + 1));
    }
    p.push_str("N9999 Z-3000.\n");
    let r = run_on(PUMA, &p);
    assert_eq!(alarm(&r), ("KERF-0168", 4, 8));
}

/// G71 in a bore (the allowance Δu negative, stock left toward −X):
/// A = Ø20 Z2 = (10, 2); shape N10 X60 (A′), N20 Z−15, N30 X40 Z−25, N40
/// Z−40, shifted by (−0.2, 0.1): (29.8, 2.1) → (29.8, −14.9) → (19.8,
/// −24.9) → (19.8, −39.9). Levels 10 + 2k: 12 … 28, then 29.8 (30 passes
/// it). A cut at L ends where the shape comes below L: never for L ≤ 18
/// (to the end, Z−39.9), on the taper Z = −14.9 − (29.8 − L) for 20 … 28,
/// at the taper's start (−14.9) for 29.8. Escape toward −X and +Z.
#[test]
fn g71_bore_every_pass() {
    let r = run_on(
        PUMA,
        "G97 S500 M03\nG00 X20. Z2.\nG71 U2. R0.5\nG71 P10 Q40 U-0.4 W0.1 F0.2\nN10 G00 X60.\nN20 G01 Z-15.\nN30 X40. Z-25.\nN40 Z-40.\nG00 Z50.\n",
    );
    ok(&r);
    let mut want = vec![mv("R", 10.0, 2.0, 0.0)];
    let mut levels: Vec<f64> = (1..=9).map(|k| 10.0 + 2.0 * k as f64).collect();
    levels.push(29.8);
    for l in levels {
        let z = if l <= 19.8 { -39.9 } else { -14.9 - (29.8 - l) };
        want.extend([
            mv("R", l, 2.0, 0.0),
            mv("F", l, z, 0.2),
            mv("R", l - 0.5, z + 0.5, 0.0),
            mv("R", l - 0.5, 2.0, 0.0),
        ]);
    }
    want.extend([
        mv("R", 29.8, 2.1, 0.0),
        mv("F", 29.8, -14.9, 0.2),
        mv("F", 19.8, -24.9, 0.2),
        mv("F", 19.8, -39.9, 0.2),
        mv("R", 10.0, 2.0, 0.0),
        mv("R", 10.0, 50.0, 0.0),
    ]);
    assert_eq!(trace(&r), want);
}

/// G76 for an internal thread: A inside (Ø26 Z3), root at Ø30 (X30 =
/// the major diameter of the nut), k 0.9, Δd 0.35, Δdmin 0.1, d 0.1, m 1,
/// r 0, a 0 (radial infeed). Depths 0.35, 0.4950 (0.35·√2), 0.6062
/// (0.35·√3); then 0.35·√4 = 0.7 is less than 0.6062 + Δdmin = 0.7062, so
/// the floor gives 0.7062; next max(0.35·√5 = 0.7826, 0.8062) = 0.8062 ≥
/// k − d = 0.8, so the last rough pass is 0.8; then 0.9. The infeed is
/// toward +X: pass X radius 15 − (0.9 − D).
#[test]
fn g76_internal_thread() {
    let r = run_on(
        PUMA,
        "G97 S400 M03\nG00 X26. Z3.\nG76 P010000 Q100 R0.1\nG76 X30. Z-20. P900 Q350 F1.5\n",
    );
    ok(&r);
    let mut want = vec![mv("R", 13.0, 3.0, 0.0)];
    let s = |n: f64| 0.35 * n.sqrt();
    for d in [s(1.0), s(2.0), s(3.0), s(3.0) + 0.1, 0.8, 0.9] {
        let x = 15.0 - (0.9 - d);
        want.extend([
            mv("R", x, 3.0, 0.0),
            mv("T", x, -20.0, 1.5),
            mv("R", 13.0, -20.0, 0.0),
            mv("R", 13.0, 3.0, 0.0),
        ]);
    }
    assert_eq!(trace(&r), want);
}

/// G71 type II (N10 moves X and Z: `W0`) on a shape with a groove: A =
/// (41, 2), Δd 2, e 0.5, no allowance. Shape (radius): (20, 2) → (20,
/// −10) → taper into the groove (15, −15) → (15, −20) → wall up (20,
/// −20) → (20, −30) → shoulder (35, −30) → (35, −40).
/// The start side, as type I: levels 39, 37, 35 cut to the end (Z−40: the
/// shape never rises above them), 33 … 21 and the clamp 20 (the shape's
/// start) to the shoulder Z−30. Then the groove, which separates below
/// level 21: levels 19, 17, 15 (the deepest point), cut from the entry
/// taper (x = 20 − (z + 10)·(−1): Z−11 for 19, Z−13 for 17, Z−15 for 15)
/// to the wall Z−20. The tool travels at the escape height of level 21
/// (21.5) to Z−11, feeds in, cuts, escapes 45°, goes to the next
/// level's entry at the escape height of the level just cut, …; then
/// rapid to X of A, to Z of A, and the semi-finish pass.
#[test]
fn g71_type2_groove() {
    let r = run_on(
        PUMA,
        "G97 S500 M03\nG00 X82. Z2.\nG71 U2. R0.5\nG71 P10 Q80 U0 W0 F0.2\nN10 G00 X40. W0\nN20 G01 Z-10.\nN30 X30. Z-15.\nN40 Z-20.\nN50 X40.\nN60 Z-30.\nN70 X70.\nN80 Z-40.\n",
    );
    ok(&r);
    let mut want = vec![mv("R", 41.0, 2.0, 0.0)];
    let mut main: Vec<(f64, f64)> = [39.0, 37.0, 35.0].iter().map(|&l| (l, -40.0)).collect();
    for k in 0..7 {
        main.push((33.0 - 2.0 * k as f64, -30.0));
    }
    main.push((20.0, -30.0));
    for (l, z) in main {
        want.extend(g71_level(l, z, 0.2));
    }
    // The groove.
    want.extend([mv("R", 21.5, 2.0, 0.0), mv("R", 21.5, -11.0, 0.0)]);
    let levels = [(19.0, -11.0), (17.0, -13.0), (15.0, -15.0)];
    for (i, &(l, z0)) in levels.iter().enumerate() {
        if i > 0 {
            // Up to the escape height of the level above (already there),
            // then along to this level's entry point.
            let h = levels[i - 1].0 + 0.5;
            want.push(mv("R", h, z0, 0.0));
        }
        want.extend([
            mv("F", l, z0, 0.2),
            mv("F", l, -20.0, 0.2),
            mv("R", l + 0.5, -19.5, 0.0),
        ]);
    }
    want.extend([
        mv("R", 41.0, -19.5, 0.0),
        mv("R", 41.0, 2.0, 0.0),
        // Semi-finish pass (N10 is G00).
        mv("R", 20.0, 2.0, 0.0),
        mv("F", 20.0, -10.0, 0.2),
        mv("F", 15.0, -15.0, 0.2),
        mv("F", 15.0, -20.0, 0.2),
        mv("F", 20.0, -20.0, 0.2),
        mv("F", 20.0, -30.0, 0.2),
        mv("F", 35.0, -30.0, 0.2),
        mv("F", 35.0, -40.0, 0.2),
        mv("R", 41.0, 2.0, 0.0),
    ]);
    assert_eq!(trace(&r), want);
}

/// G71 type II with two pockets, the first a half-circle groove (G02 R4
/// from (20, −10) to (20, −18), centre (20, −14), bottom at radius 16),
/// the second a square groove (17, −25 … −28). A = (41, 2), Δd 2, e 0.5.
/// The start side: levels 39, 37, 35 to Z−40, 33 … 21 and 20 to the
/// shoulder Z−35. The arc pocket (first in the cutting direction): level
/// 19 from Z −14 + √(16 − 1) to −14 − √15, level 17 ±√(16 − 9) = ±√7;
/// level 16 only touches the arc's bottom (nothing cut). The square
/// groove: levels 19 and 17 from Z−25 to −28. Travel between pockets at
/// the escape height of level 21.
#[test]
fn g71_type2_two_pockets_with_arc() {
    let r = run_on(
        PUMA,
        "G97 S500 M03\nG00 X82. Z2.\nG71 U2. R0.5\nG71 P10 Q99 U0 W0 F0.2\nN10 G00 X40. W0\nN20 G01 Z-10.\nN30 G02 X40. Z-18. R4.\nN40 G01 Z-25.\nN50 X34.\nN60 Z-28.\nN70 X40.\nN80 Z-35.\nN90 X70.\nN99 Z-40.\n",
    );
    ok(&r);
    let mut want = vec![mv("R", 41.0, 2.0, 0.0)];
    let mut main: Vec<(f64, f64)> = [39.0, 37.0, 35.0].iter().map(|&l| (l, -40.0)).collect();
    for k in 0..7 {
        main.push((33.0 - 2.0 * k as f64, -35.0));
    }
    main.push((20.0, -35.0));
    for (l, z) in main {
        want.extend(g71_level(l, z, 0.2));
    }
    let (s15, s7) = (15f64.sqrt(), 7f64.sqrt());
    // Arc pocket.
    want.extend([
        mv("R", 21.5, 2.0, 0.0),
        mv("R", 21.5, -14.0 + s15, 0.0),
        mv("F", 19.0, -14.0 + s15, 0.2),
        mv("F", 19.0, -14.0 - s15, 0.2),
        mv("R", 19.5, -14.0 - s15 + 0.5, 0.0),
        mv("R", 19.5, -14.0 + s7, 0.0),
        mv("F", 17.0, -14.0 + s7, 0.2),
        mv("F", 17.0, -14.0 - s7, 0.2),
        mv("R", 17.5, -14.0 - s7 + 0.5, 0.0),
    ]);
    // Square groove.
    want.extend([
        mv("R", 21.5, -14.0 - s7 + 0.5, 0.0),
        mv("R", 21.5, -25.0, 0.0),
        mv("F", 19.0, -25.0, 0.2),
        mv("F", 19.0, -28.0, 0.2),
        mv("R", 19.5, -27.5, 0.0),
        mv("R", 19.5, -25.0, 0.0),
        mv("F", 17.0, -25.0, 0.2),
        mv("F", 17.0, -28.0, 0.2),
        mv("R", 17.5, -27.5, 0.0),
        mv("R", 41.0, -27.5, 0.0),
        mv("R", 41.0, 2.0, 0.0),
        mv("R", 20.0, 2.0, 0.0),
        mv("F", 20.0, -10.0, 0.2),
        mv("A", 20.0, -18.0, 0.2),
        mv("F", 20.0, -25.0, 0.2),
        mv("F", 17.0, -25.0, 0.2),
        mv("F", 17.0, -28.0, 0.2),
        mv("F", 20.0, -28.0, 0.2),
        mv("F", 20.0, -35.0, 0.2),
        mv("F", 35.0, -35.0, 0.2),
        mv("F", 35.0, -40.0, 0.2),
        mv("R", 41.0, 2.0, 0.0),
    ]);
    assert_eq!(trace(&r), want);
}

/// Direct corner R and chamfer inside the shape (001 p.10 words in
/// N20/N30): N10 X20 (A′ radius 10, Z2), N20 Z−20 R5 (+X next), N30 X60
/// K−2 (−Z next), N40 Z−40. The expanded shape (radius): (10, 2) → (10,
/// −15) → arc R5 about (15, −15), clockwise, to (15, −20) → (28, −20) →
/// chamfer to (30, −22) → (30, −40). G71 from (41, 2), Δd 2: levels 39 … 31
/// run to Z−40; 29 meets the chamfer at Z −20 − (29 − 28) = −21; 27 … 15
/// meet the face at Z−20; 13 and 11 the arc at Z −15 − √(25 − (L − 15)²)
/// (−19.582576, −18); the clamp 10 leaves at the arc's start, Z−15. G70
/// follows the expanded shape.
#[test]
fn shape_with_direct_chamfer_and_corner_r() {
    let r = run_on(
        PUMA,
        "G97 S500 M03\nG00 X82. Z2.\nG71 U2. R0.5\nG71 P10 Q40 F0.2\nN10 G00 X20.\nN20 G01 Z-20. R5.\nN30 X60. K-2.\nN40 Z-40.\nG70 P10 Q40\n",
    );
    ok(&r);
    let mut want = vec![mv("R", 41.0, 2.0, 0.0)];
    let mut levels: Vec<f64> = (1..=15).map(|k| 41.0 - 2.0 * k as f64).collect();
    levels.push(10.0);
    for l in levels {
        let z = if l > 30.0 {
            -40.0
        } else if l > 28.0 {
            -20.0 - (l - 28.0)
        } else if l >= 15.0 {
            -20.0
        } else if l > 10.0 {
            -15.0 - (25.0 - (l - 15.0) * (l - 15.0)).sqrt()
        } else {
            -15.0
        };
        want.extend(g71_level(l, z, 0.2));
    }
    let pass = [
        mv("R", 10.0, 2.0, 0.0),
        mv("F", 10.0, -15.0, 0.2),
        mv("A", 15.0, -20.0, 0.2),
        mv("F", 28.0, -20.0, 0.2),
        mv("F", 30.0, -22.0, 0.2),
        mv("F", 30.0, -40.0, 0.2),
        mv("R", 41.0, 2.0, 0.0),
    ];
    want.extend(pass);
    want.extend(pass);
    assert_eq!(trace(&r), want);
    assert_eq!(centres(&r), vec![(15.0, -15.0), (15.0, -15.0)]);
    let cw = r
        .events
        .iter()
        .filter(|e| {
            matches!(
                e.cmd,
                Canon::Arc {
                    dir: kerf_canon::ArcDir::Cw,
                    ..
                }
            )
        })
        .count();
    assert_eq!(cw, 2);
    // A corner R whose next block turns the other way: PS052 on it.
    let r = run_on(
        PUMA,
        "G97 S500 M03\nG00 X82. Z2.\nG71 U2. R0.5\nG71 P10 Q40 F0.2\nN10 G00 X20.\nN20 G01 Z-20. R-5.\nN30 X60.\nN40 Z-40.\n",
    );
    assert_eq!(alarm(&r), ("PS052", 7, 1));
}

/// S inside ns-nf is for G70 only (fanuc-semantics §1.1): G71 roughs at
/// the S500 in force; G70 turns at S800 from N20 on and the S500 comes
/// back after the cycle (G97, so the rpm is the S).
#[test]
fn shape_s_for_g70_only() {
    let r = run_on(
        PUMA,
        "G97 S500 M03\nG00 X70. Z2.\nG71 U2. R0.5\nG71 P1 Q3 F0.3\nN1 G01 X60.\nN2 Z-10. S800\nN3 X68.\nG70 P1 Q3\nG00 X80.\n",
    );
    ok(&r);
    let seq: Vec<String> = r
        .events
        .iter()
        .filter_map(|e| match &e.cmd {
            Canon::Spindle { rpm, .. } => Some(format!("S{}", round(*rpm))),
            Canon::Feed { m, .. } => Some(format!("F{},{}", round(2.0 * m.to[0]), round(m.to[2]))),
            _ => None,
        })
        .collect();
    let g70_start = seq.iter().rposition(|s| s == "F60,2").unwrap();
    // Before G70 only the S500 of the first block.
    assert_eq!(seq.iter().filter(|s| s.starts_with('S')).count(), 3);
    assert_eq!(seq[0], "S500");
    assert_eq!(
        seq[g70_start..].to_vec(),
        vec!["F60,2", "S800", "F60,-10", "F68,-10", "S500"]
    );
}
