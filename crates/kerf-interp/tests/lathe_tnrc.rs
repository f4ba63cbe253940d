//! Tool nose radius compensation in the PUMA (001, Fanuc 0-T) multiple
//! repetitive cycles (fanuc-semantics §1.1, §1.5, §1.9, §4.9): G70 runs the
//! finishing shape with G40/G41/G42 as written there (or in force before
//! it), G71-G73 rough to the shape offset by the nose radius (the
//! imaginary tip's path). Every compensated point is worked out by hand in
//! the comments in (Z, X radius) coordinates; the programs write X as a
//! diameter and the checks compare diameters.
//!
//! Common facts for nose radius r, tip 3 (centre → tip = (−r, −r) in
//! (Z, X), 001 p.29), G42 (tool right of travel; for a direction (u, v)
//! in (Z, X) the right normal is (v, −u): −Z travel → +X):
//! - a cut along −Z at X = x: centre X = x + r, tip X = x (the tip path is
//!   the contour); a face cut along +X at Z = z: centre Z = z + r, tip
//!   Z = z (the contour again);
//! - a 45° chamfer along (−1, 1)/√2: right normal (1, 1)/√2, centre line
//!   = contour + r(1, 1)/√2, tip line = contour + r(1/√2 − 1)(1, 1):
//!   X + Z falls by 2r(1 − 1/√2) = r(2 − √2): the chamfer's tip line is
//!   the contour shifted along one axis by b = r(2 − √2) = r(1 − tan 22.5°)
//!   (tan 22.5° = √2 − 1), 001 p.27-28's correction (0.468 for R0.8).

use kerf_canon::Canon;
use kerf_interp::{Interp, Profile, Run, Settings};

mod common;
use common::lathe::{g71_level, mv, trace};
use common::{alarm, ok, round};

const R: f64 = 0.8;

/// The chamfer shift b = r(1 − tan 22.5°) = r(2 − √2).
fn b() -> f64 {
    R * (1.0 - 22.5f64.to_radians().tan())
}

/// The perpendicular part of the chamfer shift: a = r(1 − 1/√2) = b / 2.
fn a() -> f64 {
    R * (1.0 - 1.0 / 2f64.sqrt())
}

/// Runs `text` on the PUMA with wide travel and offset 1 = nose radius
/// `R`, tip `tip`.
fn run(tip: u8, text: &str) -> Run {
    let mut p = Profile::builtin("puma-lathe").unwrap();
    for ax in p.axes.values_mut() {
        ax.min = -1e4;
        ax.max = 1e4;
    }
    let mut it = Interp::new(p, Settings::default());
    let o = it.offsets_mut().lathe_mut(1).unwrap();
    o.r = R;
    o.tip = tip;
    kerf_interp::run_interp(it, "t.nc", text)
}

fn same(got: &[(&str, f64, f64, f64)], want: &[(&str, f64, f64, f64)]) {
    assert_eq!(got.len(), want.len(), "got {got:#?}\nwanted {want:#?}");
    for (g, w) in got.iter().zip(want) {
        assert!(
            g.0 == w.0 && (g.1 - w.1).abs() < 2e-6 && (g.2 - w.2).abs() < 2e-6 && g.3 == w.3,
            "got {g:?}, wanted {w:?}\nall: {got:#?}"
        );
    }
}

/// G70 with `G42` in block ns and `G40` in block nf, tip 3, r = 0.8; the
/// shape after M30 (searched by N). Contour (Z, X radius): A = (5, 30) →
/// N10 (1, 7) → N20 chamfer 45° to (−2, 10) → N30 (−20, 10) → N40 face
/// to (−20, 20) → N50 (−35, 20) → N60 G40 to (−35, 30).
/// - N10 start-up (type A): ends on the vector perpendicular to N20 at
///   its start: centre (1, 7) + r(1, 1)/√2, tip = (1 − a, 7 − a),
///   a = r(1 − 1/√2) = 0.234315 → Ø13.531371, Z0.765685 (rapid: N10 is
///   G00);
/// - N20 → N30: left turn, outer obtuse → the offset lines meet; tip
///   lines X + Z = 8 − 2a and X = 10 → Z = −2 − 2a = −2 − b
///   (b = r(1 − tan 22.5°) = 0.468629) → Ø20 Z−2.468629;
/// - N30 → N40: right turn, inner → intersection, centre (−19.2, 10.8),
///   tip (−20, 10) → Ø20 Z−20;
/// - N40 → N50: left turn 90°, outer → intersection, centre
///   (−19.2, 20.8), tip (−20, 20) → Ø40 Z−20;
/// - N50 before the G40 block: cancel type A ends N50 on its own
///   perpendicular vector: centre (−35, 20.8), tip (−35.8, 20) → Ø40
///   Z−35.8;
/// - N60 G40 (G01 from N20): to the programmed point Ø60 Z−35;
/// - then the rapid back to A (Ø60 Z5).
#[test]
fn g70_with_g42_in_the_shape() {
    let prog = "G00 X60. Z5. T0101 F0.2\n\
                G70 P10 Q60\n\
                M30\n\
                N10 G00 G42 X14. Z1.\n\
                N20 G01 X20. Z-2.\n\
                N30 Z-20.\n\
                N40 X40.\n\
                N50 Z-35.\n\
                N60 G40 X60.\n";
    let r = run(3, prog);
    ok(&r);
    let (a, b) = (a(), b());
    same(
        &trace(&r),
        &[
            mv("R", 30.0, 5.0, 0.0),
            mv("R", 7.0 - a, 1.0 - a, 0.0),
            mv("F", 10.0, -2.0 - b, 0.2),
            mv("F", 10.0, -20.0, 0.2),
            mv("F", 20.0, -20.0, 0.2),
            mv("F", 20.0, -35.0 - R, 0.2),
            mv("F", 30.0, -35.0, 0.2),
            mv("R", 30.0, 5.0, 0.0),
        ],
    );
    // The check is not the contour itself.
    assert!((b - 0.468629).abs() < 1e-6 && (a - 0.234315).abs() < 1e-6);
}

/// The same shape without G40/G41/G42, with `G42` commanded before G70
/// (in a block without a move): compensation stays on through the shape,
/// the first block is the start-up, and N60 (+X, no G40) is an ordinary
/// offset block:
/// - N50 → N60: right turn, inner → intersection, centre (−34.2, 20.8),
///   tip (−35, 20) → Ø40 Z−35;
/// - N60 is the last block: it ends on its perpendicular vector (+X
///   travel, right normal +Z): centre (−34.2, 30), tip (−35, 29.2) →
///   Ø58.4 Z−35;
/// - the rapid back to A is not compensated; G42 is still in force after
///   G70 (the next move starts up again), so `G40 G00 X80.` cancels from
///   the programmed A straight to Ø80 Z5.
#[test]
fn g70_with_g42_before_the_cycle() {
    let prog = "G00 X60. Z5. T0101 F0.2\n\
                G42\n\
                G70 P10 Q60\n\
                G40 G00 X80.\n\
                M30\n\
                N10 G00 X14. Z1.\n\
                N20 G01 X20. Z-2.\n\
                N30 Z-20.\n\
                N40 X40.\n\
                N50 Z-35.\n\
                N60 X60.\n";
    let r = run(3, prog);
    ok(&r);
    let (a, b) = (a(), b());
    same(
        &trace(&r),
        &[
            mv("R", 30.0, 5.0, 0.0),
            mv("R", 7.0 - a, 1.0 - a, 0.0),
            mv("F", 10.0, -2.0 - b, 0.2),
            mv("F", 10.0, -20.0, 0.2),
            mv("F", 20.0, -20.0, 0.2),
            mv("F", 20.0, -35.0, 0.2),
            mv("F", 30.0 - R, -35.0, 0.2),
            mv("R", 30.0, 5.0, 0.0),
            mv("R", 40.0, 5.0, 0.0),
        ],
    );
}

/// G71 type I with `G42` before the cycle (the start-up on the move to
/// A), tip 3, r = 0.8, Δd = 2 (radius), e = 0.5, no allowance, F0.25.
/// A = (Z2, X21). Contour: N10 G00 to (2, 7), N20 chamfer 45° to (−1, 10),
/// N30 (−20, 10), N40 face to (−20, 20).
/// - The start-up move Ø50 Z10 → Ø42 Z2 is held; the G71 first block
///   breaks the look-ahead: it ends on its own perpendicular vector.
///   Direction (Z, X) (−8, −4)/√80, right normal (−4, 8)/√80 =
///   (−1, 2)/√5: centre (2 − r/√5, 21 + 2r/√5), tip − (r, r):
///   Z = 2 − 0.357771 − 0.8 = 0.842229, X = 21 + 0.715542 − 0.8 =
///   20.915542.
/// - The tip path (shape offset before the levels): A′ = start-up end on
///   N20's perpendicular = (2 − a, 7 − a) = (1.765685, 6.765685); the
///   chamfer's tip line X + Z = 9 − 2a = 8.531371; it meets X = 10 at
///   Z = −1.468629; N30/N40 inner corner (−20, 10) exact; N40 is the last
///   block: its perpendicular vector (+X travel → +Z): centre
///   (−19.2, 20), tip (−20, 19.2).
/// - Levels X = 19, 17, 15, 13, 11 end on the face Z−20; X = 9 on the tip
///   chamfer: Z = 8.531371 − 9 = −0.468629 (the contour would give Z0);
///   X = 7: Z = 1.531371 (the contour: Z2, no cut at all); the last level
///   is A′'s X 6.765685, cut to A′'s Z 1.765685. Each: rapid in at Z2,
///   feed, 45° escape by 0.5, rapid back to Z2.
/// - Semi-finish: rapid to A′, feeds along the tip path, rapid to A.
/// - `G40 G00 X60.` then cancels from A (Ø60 Z2).
#[test]
fn g71_with_g42_before_the_cycle_roughs_to_the_tip_path() {
    let prog = "G00 X50. Z10. T0101\n\
                G42 G00 X42. Z2.\n\
                G71 U2. R0.5\n\
                G71 P10 Q40 U0 W0 F0.25\n\
                N10 G00 X14.\n\
                N20 G01 X20. Z-1.\n\
                N30 Z-20.\n\
                N40 X40.\n\
                G40 G00 X60.\n\
                M30\n";
    let r = run(3, prog);
    ok(&r);
    let a = a();
    let s5 = 5f64.sqrt();
    let f = 0.25;
    let mut want = vec![
        mv("R", 25.0, 10.0, 0.0),
        mv("R", 21.0 + 2.0 * R / s5 - R, 2.0 - R / s5 - R, 0.0),
    ];
    let level = |want: &mut Vec<_>, l: f64, z: f64| want.extend(g71_level(l, z, f));
    for l in [19.0, 17.0, 15.0, 13.0, 11.0] {
        level(&mut want, l, -20.0);
    }
    let tipline = 9.0 - 2.0 * a; // X + Z on the chamfer's tip path
    level(&mut want, 9.0, tipline - 9.0);
    level(&mut want, 7.0, tipline - 7.0);
    level(&mut want, 7.0 - a, 2.0 - a);
    want.extend([
        mv("R", 7.0 - a, 2.0 - a, 0.0),
        mv("F", 10.0, tipline - 10.0, f),
        mv("F", 10.0, -20.0, f),
        mv("F", 20.0 - R, -20.0, f),
        mv("R", 21.0, 2.0, 0.0),
        mv("R", 30.0, 2.0, 0.0),
    ]);
    same(&trace(&r), &want);
    // Hand values of two level ends.
    assert!((tipline - 9.0 - -0.468629).abs() < 1e-6);
    assert!((tipline - 7.0 - 1.531371).abs() < 1e-6);
}

/// The same roughing with `G42` in block ns and `G40` in block nf (the
/// usual way of writing the shape once for G71 and G70): the start-up is
/// the shape's first block, and for the roughing the G40 does not cancel
/// (the whole contour is offset, docs/dialects.md), so the levels and the
/// semi-finish pass are those of the previous test; A was reached
/// uncompensated.
#[test]
fn g71_with_g42_in_the_shape() {
    let prog = "G00 X42. Z2. T0101\n\
                G71 U2. R0.5\n\
                G71 P10 Q40 U0 W0 F0.25\n\
                N10 G00 G42 X14.\n\
                N20 G01 X20. Z-1.\n\
                N30 Z-20.\n\
                N40 G40 X40.\n\
                G00 X60.\n\
                M30\n";
    let r = run(3, prog);
    ok(&r);
    let t = trace(&r);
    let a = a();
    let tipline = 9.0 - 2.0 * a;
    // Level X9 (the 6th level: after the first rapid, 5 levels of 4 moves).
    let i = 1 + 5 * 4;
    same(
        &t[i..i + 2],
        &[mv("R", 9.0, 2.0, 0.0), mv("F", 9.0, tipline - 9.0, 0.25)],
    );
    // The semi-finish pass and the return.
    let n = t.len();
    same(
        &t[n - 6..],
        &[
            mv("R", 7.0 - a, 2.0 - a, 0.0),
            mv("F", 10.0, tipline - 10.0, 0.25),
            mv("F", 10.0, -20.0, 0.25),
            mv("F", 20.0 - R, -20.0, 0.25),
            mv("R", 21.0, 2.0, 0.0),
            mv("R", 30.0, 2.0, 0.0),
        ],
    );
}

/// Without compensation the same G71 cuts the levels to the contour: the
/// level X9 ends at Z0 (checks that the tests above see the offset).
#[test]
fn g71_without_compensation_cuts_to_the_contour() {
    let prog = "G00 X42. Z2. T0101\n\
                G71 U2. R0.5\n\
                G71 P10 Q40 U0 W0 F0.25\n\
                N10 G00 X14.\n\
                N20 G01 X20. Z-1.\n\
                N30 Z-20.\n\
                N40 X40.\n\
                M30\n";
    let r = run(3, prog);
    ok(&r);
    let t = trace(&r);
    let i = 1 + 5 * 4;
    same(
        &t[i..i + 2],
        &[mv("R", 9.0, 2.0, 0.0), mv("F", 9.0, 0.0, 0.25)],
    );
}

/// A concave corner arc R0.5 in the shape, smaller than the nose radius
/// 0.8: G42 puts the tool on the centre's side (−Z travel, the centre
/// above in +X), so the offset arc would have radius 0.5 − 0.8 < 0 —
/// interference, positioned at the arc block (line 6, its X word), for
/// G71 (offsetting the shape) and for G70.
#[test]
fn interference_in_the_shape_is_positioned() {
    for cycle in ["G71 P10 Q40 U0 W0 F0.25", "G70 P10 Q40"] {
        let prog = format!(
            "G00 X42. Z2. T0101 F0.2\n\
             G71 U2. R0.5\n\
             {cycle}\n\
             N10 G00 G42 X20.\n\
             N20 G01 Z-10.\n\
             N30 G02 X21. Z-10.5 R0.5\n\
             N40 G01 X40.\n\
             M30\n"
        );
        let r = run(3, &prog);
        let (code, line, col) = alarm(&r);
        assert_eq!((line, col), (6, 9), "{cycle}: {:?}", r.alarm);
        assert!(
            r.alarm.as_ref().unwrap().message.contains("interference"),
            "{cycle}: {code} {:?}",
            r.alarm
        );
    }
}

/// A PUMA direct chamfer `X30. C2.` (001 p.10) in offset mode: the
/// chamfer goes into the programmed contour, then every piece is
/// compensated. The contour is that of 001 p.28's example (face at Z0 to
/// Ø26, 45° chamfer to Ø30 Z−2, Z−30), r = 0.8, tip 3, G42:
/// - start-up along −Z at X10 (radius), type A: ends perpendicular to the
///   face (+X travel, right normal +Z): centre (0.8, 10), tip (0, 9.2) →
///   Ø18.4 Z0;
/// - face → chamfer: left turn, outer → intersection of the tip lines
///   Z = 0 and X + Z = 13 − b (b = r(1 − tan 22.5°), see the header) →
///   X = 13 − b → Ø(26 − 2b) Z0;
/// - chamfer → Z−30: X = 15 and X + Z = 13 − b → Z = −2 − b, Ø30;
/// - Z−30 before the G40 block (type A): its perpendicular: centre
///   (−30, 15.8), tip (−30.8, 15) → Ø30 Z−30.8; then Ø40 Z−30.
///
/// (The same numbers as tests/cutter_comp.rs's 001 p.28 example written
/// with the chamfer as a move.)
#[test]
fn direct_chamfer_in_offset_mode() {
    let prog = "G00 X20. Z1. T0101\nG42 G01 Z0 F0.2\nX30. C2.\nZ-30.\nG40 G00 X40.\nM30\n";
    let r = run(3, prog);
    ok(&r);
    let b = b();
    same(
        &trace(&r),
        &[
            mv("R", 10.0, 1.0, 0.0),
            mv("F", 10.0 - R, 0.0, 0.2),
            mv("F", 13.0 - b, 0.0, 0.2),
            mv("F", 15.0, -2.0 - b, 0.2),
            mv("F", 15.0, -30.0 - R, 0.2),
            mv("R", 20.0, -30.0, 0.0),
        ],
    );
}

/// A direct corner R `X30. R-2.` in offset mode (the sign of R is the
/// direction of the next move, −Z). Contour: face at Z0 from X10 to the
/// corner, arc R2 (left turn, G03) from (Z0, X13) to (Z−2, X15) about
/// (Z−2, X13), Z−30. G42, r = 0.8, tip 3:
/// - the face's centre path Z = 0.8 is tangent to the arc's offset
///   circle, radius 2 + 0.8 (outside of a left-turning arc); the face
///   ends at centre (0.8, 13), tip (0, 12.2) → Ø24.4 Z0;
/// - the arc ends at centre (−2, 15.8), tip (−2.8, 15) → Ø30 Z−2.8,
///   about the centre shifted by the tip: (Z−2.8, X12.2);
/// - Z−30 then as in the chamfer test.
#[test]
fn direct_corner_r_in_offset_mode() {
    let prog = "G00 X20. Z1. T0101\nG42 G01 Z0 F0.2\nX30. R-2.\nZ-30.\nG40 G00 X40.\nM30\n";
    let r = run(3, prog);
    ok(&r);
    same(
        &trace(&r),
        &[
            mv("R", 10.0, 1.0, 0.0),
            mv("F", 10.0 - R, 0.0, 0.2),
            mv("F", 13.0 - R, 0.0, 0.2),
            mv("A", 15.0, -2.0 - R, 0.2),
            mv("F", 15.0, -30.0 - R, 0.2),
            mv("R", 20.0, -30.0, 0.0),
        ],
    );
    let c: Vec<_> = r
        .events
        .iter()
        .filter_map(|e| match &e.cmd {
            Canon::Arc { center, .. } => Some((round(center[0]), round(center[2]))),
            _ => None,
        })
        .collect();
    assert_eq!(c, vec![(round(13.0 - R), round(-2.0 - R))]);
}
