//! The one-block G71-G76 of the Fanuc 10/11 tape format (fanuc-semantics
//! §10.2; profile parameter `tape_format_10_11`, on for the PUMA):
//! `G71/G72 P Q U W D F`, `G73 P Q I K U W D F`, `G74/G75 X Z I K D F`,
//! `G76 X Z I K D F A P Q`, the words with the control's decimal-point
//! rule. Every expected pass is worked out by hand (radius values) in the
//! comments; where the 0-T two-block form of the same cycle is tested by
//! hand in tests/lathe_mrc.rs, the passes here are the same numbers.

use kerf_canon::Canon;

mod common;
use common::lathe::{mv, trace};
use common::{alarm, ok, run_on, run_with_param};

const PUMA: &str = "puma-lathe";

/// One G71 level from Z2 with e = 0.5 (the profile's No.5133) and a G01
/// shape start (infeeds are feeds): feed to the level, cut to Z−10,
/// escape 45°, rapid back.
fn level(l: f64, f: f64) -> [(&'static str, f64, f64, f64); 4] {
    [
        mv("F", l, 2.0, f),
        mv("F", l, -10.0, f),
        mv("R", l + 0.5, -9.5, 0.0),
        mv("R", l + 0.5, 2.0, 0.0),
    ]
}

/// A = Ø70 Z2 (radius 35), the shape Ø60 (radius 30) to Z−10, no
/// allowance. D2. = Δd 2 mm: levels 33, 31, then 30 (35 − 6 = 29 is past
/// the shape's start, clamped); the semi-finish pass along the shape and
/// a rapid to A. D2000 (no decimal point, 0.001 mm) is the same; D1.
/// cuts 34, 33, 32, 31, 30. D is modal: a later G71 without it keeps 2.
#[test]
fn g71_one_block_depth_d() {
    let shape = "N1 G01 X60.\nN2 Z-10.\n";
    let want = |levels: &[f64]| {
        let mut w = vec![mv("R", 35.0, 2.0, 0.0)];
        for &l in levels {
            w.extend(level(l, 0.3));
        }
        w.extend([
            mv("F", 30.0, 2.0, 0.3),
            mv("F", 30.0, -10.0, 0.3),
            mv("R", 35.0, 2.0, 0.0),
        ]);
        w
    };
    for d in ["D2.", "D2000"] {
        let r = run_on(PUMA, &format!("G00 X70. Z2.\nG71 P1 Q2 {d} F0.3\n{shape}"));
        ok(&r);
        assert_eq!(trace(&r), want(&[33.0, 31.0, 30.0]), "{d}");
    }
    let r = run_on(PUMA, &format!("G00 X70. Z2.\nG71 P1 Q2 D1. F0.3\n{shape}"));
    ok(&r);
    assert_eq!(trace(&r), want(&[34.0, 33.0, 32.0, 31.0, 30.0]));
    // Modal: the second cycle has no D and cuts at 2 again.
    let r = run_on(
        PUMA,
        &format!("G00 X70. Z2.\nG71 P1 Q2 D2. F0.3\n{shape}G71 P1 Q2 F0.3\n"),
    );
    ok(&r);
    let one = want(&[33.0, 31.0, 30.0]);
    let mut two = one.clone();
    two.extend(one[1..].iter().copied());
    assert_eq!(trace(&r), two);
}

/// The real files' inch form: `G20 … D.02` is Δd = 0.02 in = 0.508 mm. A
/// = Ø2.0 in (radius 25.4 mm), shape Ø1.8 (radius 22.86) to Z−0.5 in
/// (−12.7 mm): five levels 25.4 − 0.508·k = 24.892, 24.384, 23.876,
/// 23.368, 22.86 (the last exactly the shape), plus the semi-finish pass
/// at 22.86. With D ignored (1 mm) there would be three.
#[test]
fn g71_one_block_inch_d() {
    let r = run_on(
        PUMA,
        "G20\nG00 X2.0 Z0.1\nG71 P1 Q2 D.02 F.01\nN1 G01 X1.8\nN2 Z-0.5\n",
    );
    ok(&r);
    let xs: Vec<f64> = trace(&r)
        .into_iter()
        .filter(|m| m.0 == "F" && m.2 == -12.7)
        .map(|m| m.1)
        .collect();
    let want: Vec<f64> = [24.892, 24.384, 23.876, 23.368, 22.86, 22.86]
        .iter()
        .map(|&x| common::round(2.0 * x))
        .collect();
    assert_eq!(xs, want);
}

/// G72 one-block: A = Ø84 Z2 (42, 2), the face N10 Z−4 / N20 X20 (to
/// radius 10). Levels in Z every D2. from 2: 0, −2, then −4 (the shape);
/// each cut along −X from X42 to the shape's end X10, escape 0.5 at 45°
/// (+X +Z), rapid back to X42; semi-finish and rapid to A. The same
/// passes as the two-block `G72 W2. R0.5` / `G72 P10 Q20 F0.2`.
#[test]
fn g72_one_block_depth_d() {
    let shape = "N10 G01 Z-4.\nN20 X20.\n";
    let r = run_on(
        PUMA,
        &format!("G00 X84. Z2.\nG72 P10 Q20 D2. F0.2\n{shape}"),
    );
    ok(&r);
    let mut want = vec![mv("R", 42.0, 2.0, 0.0)];
    for l in [0.0, -2.0, -4.0] {
        want.extend([
            mv("F", 42.0, l, 0.2),
            mv("F", 10.0, l, 0.2),
            mv("R", 10.5, l + 0.5, 0.0),
            mv("R", 42.0, l + 0.5, 0.0),
        ]);
    }
    want.extend([
        mv("F", 42.0, -4.0, 0.2),
        mv("F", 10.0, -4.0, 0.2),
        mv("R", 42.0, 2.0, 0.0),
    ]);
    assert_eq!(trace(&r), want);
    let two = run_on(
        PUMA,
        &format!("G00 X84. Z2.\nG72 W2. R0.5\nG72 P10 Q20 F0.2\n{shape}"),
    );
    assert_eq!(trace(&two), want);
}

/// G73 one-block: 001's example `G73 U3.0 W2.0 R2` / `G73 P12 Q16 U0.5
/// W0.1 F0.25` written `G73 P12 Q16 I3. K2. U0.5 W0.1 D2 F0.25` (I, K the
/// relief, radius; D the divisions, a count). Two passes, shifted by Δi +
/// Δu/2, Δk + Δw = (3.25, 2.1) and then (0.25, 0.1), as in
/// tests/lathe_mrc.rs `g73_example_001_completed`.
#[test]
fn g73_one_block() {
    let r = run_on(
        PUMA,
        "G00 X70.0 Z10.0\nG73 P12 Q16 I3. K2. U0.5 W0.1 D2 F0.25\nN12 G00 X20. Z2.\nN13 G01 Z-10.\nN14 X40. Z-20.\nN15 G02 X60. Z-30. R10.\nN16 G01 X70.\nM30\n",
    );
    ok(&r);
    let mut want = vec![mv("R", 35.0, 10.0, 0.0)];
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
    assert_eq!(trace(&r), want);
}

/// G74 one-block: `G74 X40. Z-5. I4. K2. D.3 F0.1` after `G74 R0.5` is
/// tests/lathe_mrc.rs `g74_columns_relief` (P4000 Q2000 R0.3): A = (30,
/// 1), columns at radius 30, 26, 22, 20, pecks to −1, −3, −5 with 0.5
/// back, relief 0.3 toward +X, rapid to Z1, next column; rapid to A.
#[test]
fn g74_one_block() {
    let r = run_on(
        PUMA,
        "G97 S500 M03\nG00 X60. Z1.\nG74 R0.5\nG74 X40. Z-5. I4. K2. D.3 F0.1\n",
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
    // The two forms mixed are an alarm at the 0-T word.
    let r = run_on(PUMA, "G00 X60. Z1.\nG74 X40. Z-5. P4000 K2. F0.1\n");
    assert_eq!(alarm(&r), ("PS062", 2, 15));
}

/// G75 one-block: 001's example `G75 X60.0 Z-20.0 P3000 Q20000` written
/// `I3. K20.`: A = (41, −60), grooves at Z−60, −40, −20, pecks 3 in X with
/// e = 1 (feed 38, back 39, feed 35, back 36, feed 32, back 33, feed 30),
/// rapid X41, next groove; rapid to A.
#[test]
fn g75_one_block() {
    let r = run_on(
        PUMA,
        "G97 S280 M03\nG00 X82.0 Z-60.0\nG75 R1.0\nG75 X60.0 Z-20.0 I3. K20. F0.1\n",
    );
    ok(&r);
    let mut want = vec![mv("R", 41.0, -60.0, 0.0)];
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
    want.push(mv("R", 41.0, -60.0, 0.0));
    assert_eq!(trace(&r), want);
}

/// The G74/G75 messages name the value that is missing: in G75 the peck
/// is Δi (P), the shift Δk (Q); in G74 the peck is Δk (Q).
#[test]
fn g74_g75_missing_values_named() {
    let r = run_on(PUMA, "G00 X40. Z1.\nG75 X20. Q2000 F0.1\n");
    let a = r.alarm.as_ref().expect("alarm");
    assert_eq!((a.code.as_str(), a.src.line), ("PS062", 2));
    assert!(
        a.message.contains("peck depth Δi (P) missing"),
        "{}",
        a.message
    );
    let r = run_on(PUMA, "G00 X40. Z1.\nG74 Z-10. P3000 F0.1\n");
    let a = r.alarm.as_ref().expect("alarm");
    assert!(
        a.message.contains("G74: peck depth Δk (Q) missing"),
        "{}",
        a.message
    );
    let r = run_on(PUMA, "G00 X40. Z1.\nG75 X20. Z-10. P2000 F0.1\n");
    let a = r.alarm.as_ref().expect("alarm");
    assert!(
        a.message.contains("G75: shift Δk (Q) missing"),
        "{}",
        a.message
    );
}

/// G76 one-block after the first block `G76 P021060 Q100 R0.05` (m = 2, r
/// = 10, a = 60°, Δdmin 0.1, d 0.05): `G76 X27.4 Z-30. K1.3 D.5 F2.` is
/// tests/lathe_mrc.rs `g76_every_pass` (P1300 Q500): depths 0.5·√n for n
/// = 1…6, then 1.25 (k − d), then 1.3 twice; each pass rapid to X radius
/// 13.7 + (1.3 − D), Z 5 + (1.3 − D)·tan 30°, thread to Z−28, 45° out to
/// X + 2 at Z−30, rapid X17, rapid to A. With `A0` the infeed is
/// straight (Z 5 every pass), and A stays for the next cycle. `Q180000`
/// (0.001°) is a start angle of 180°: an operator message.
#[test]
fn g76_one_block() {
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
    let want = |tan: f64| {
        let mut w = vec![mv("R", 17.0, 5.0, 0.0)];
        for d in depths {
            let x = 13.7 + (1.3 - d);
            w.extend([
                mv("R", x, 5.0 + (1.3 - d) * tan, 0.0),
                mv("T", x, -28.0, 2.0),
                mv("T", x + 2.0, -30.0, 2.0),
                mv("R", 17.0, -30.0, 0.0),
                mv("R", 17.0, 5.0, 0.0),
            ]);
        }
        w
    };
    let head = "G97 S600 M03\nG00 X34. Z5.\nG76 P021060 Q100 R0.05\n";
    let r = run_on(PUMA, &format!("{head}G76 X27.4 Z-30. K1.3 D.5 F2.\n"));
    ok(&r);
    assert_eq!(trace(&r), want(1.0 / 3f64.sqrt()));
    let r = run_on(
        PUMA,
        &format!("{head}G76 X27.4 Z-30. K1.3 D.5 F2. A0 P1 Q180000\n"),
    );
    ok(&r);
    assert_eq!(trace(&r), want(0.0));
    assert!(r
        .events
        .iter()
        .any(|e| matches!(&e.cmd, Canon::Message(m) if m == "thread start angle 180")));
    // P2 (zigzag) is not made: an alarm, not a silent single-edge cut.
    let r = run_on(PUMA, &format!("{head}G76 X27.4 Z-30. K1.3 D.5 F2. P2\n"));
    assert_eq!(alarm(&r), ("PS062", 4, 30));
}

/// With the parameter off the one-block words are alarms, never ignored.
#[test]
fn parameter_off_alarms() {
    let r = run_with_param(
        PUMA,
        "tape_format_10_11",
        0.0,
        "G00 X70. Z2.\nG71 P1 Q2 D2. F0.3\nN1 G01 X60.\nN2 Z-10.\n",
    );
    assert_eq!(alarm(&r), ("PS009", 2, 11));
    let r = run_with_param(
        PUMA,
        "tape_format_10_11",
        0.0,
        "G00 X60. Z1.\nG74 X40. Z-5. I4. K2. F0.1\n",
    );
    assert_eq!(alarm(&r), ("PS009", 2, 15));
}

/// R in the block with P and Q is read by no form of G71-G73 (it belongs
/// to the 0-T first block): PS009 at the R, not ignored.
#[test]
fn r_in_the_p_q_block_alarms() {
    let r = run_on(
        PUMA,
        "G00 X70. Z2.\nG71 P1 Q2 D2. R1. F0.3\nN1 G01 X60.\nN2 Z-10.\n",
    );
    assert_eq!(alarm(&r), ("PS009", 2, 15));
}

/// The first block `G74 R(e)` reads only R: a peck amount written there
/// (without the end point, so no cycle runs) is PS009, not ignored.
#[test]
fn g74_first_block_reads_only_r() {
    let r = run_on(PUMA, "G00 X60. Z1.\nG74 R0.5 Q2000\n");
    assert_eq!(alarm(&r), ("PS009", 2, 10));
    let r = run_on(PUMA, "G00 X60. Z1.\nG75 R0.5 K2.\n");
    assert_eq!(alarm(&r), ("PS009", 2, 10));
    // G71's first block reads U and R only, G72's W and R.
    let r = run_on(PUMA, "G00 X60. Z1.\nG71 U2. R0.5 W1.\n");
    assert_eq!(alarm(&r), ("PS009", 2, 14));
    let r = run_on(PUMA, "G00 X60. Z1.\nG72 W2. R0.5 U1.\n");
    assert_eq!(alarm(&r), ("PS009", 2, 14));
    // The same for G76's first block (P Q R only).
    let r = run_on(PUMA, "G00 X60. Z1.\nG76 P021060 Q100 D.5\n");
    assert_eq!(alarm(&r), ("PS009", 2, 18));
}
