//! The cutter compensation sample program of the Hurco MAX turning manual
//! (002), run as printed: "Example—G90 Absolute Dimensions", "Example: G91
//! Incremental Dimensions" and the G41/G42 "Examples" (Figures 14/15). All
//! three are the same part ("lathe doc sample, abs G42, tool radius 0.1"):
//! radius programming (G07), `N125 G42`, a taper, two faces, two turns,
//! `G00 G40` out.
//!
//! The programs write no G20, so kerf reads them in its power-on mm
//! (docs/dialects.md §4); the geometry does not depend on the unit, and
//! the tool radius 0.1 is given in the same unit, so every point below is
//! the manual's inch point. Tool 1 offset 1: radius 0.1, no lengths, tip 0
//! (002's G41/G42 offset the tool centre, "similar to those used for
//! milling"). The Hurco default is "activate and exit normal" on and
//! circular joining off (`comp_exit_normal = 1`, `comp_circular_joining =
//! 0`): Fanuc type A start-up and cancel, sharp corners.
//!
//! Hand computation in (Z, X radius); G42 puts the tool right of travel:
//! for a direction (u, v) in (Z, X) the right normal is (v, −u).
//! - N130 start-up from (4, 0) to (3, 0.5): type A ends on the normal of
//!   N160 at its start. N160 runs (3, 0.5) → (2, 1), direction (−2, 1)/√5,
//!   normal (1, 2)/√5: (3 + 0.1/√5, 0.5 + 0.2/√5) = (3.044721, 0.589443).
//! - N160 → N170 (face +X at Z2, normal (1, 0)): a right turn, inner
//!   corner: offset lines Z + 2X = 3 + 2·0.5 + 0.1·√5 (N160's line Z + 2X =
//!   4 moved by r along its normal: +r·√5) and Z = 2.1 → X = (4 + 0.1√5 −
//!   2.1)/2 = 1.061803 (= 1 + 0.1·(√5 − 1)/2).
//! - N170 → N180 (turn −Z, normal (0, 1)): left turn of 90°, outer
//!   obtuse: lines Z = 2.1 and X = 1.8 → (2.1, 1.8).
//! - N180 → N190 (face +X): right turn, inner: X = 1.8, Z = 0.3 + 0.1 →
//!   (0.4, 1.8).
//! - N190 → N200 (turn −Z): outer 90°: Z = 0.4, X = 2.0 → (0.4, 2.0).
//! - N230 `G00 G40 X2.5`: type A cancel ends N200 on its own normal at its
//!   end, (0, 1.9) + (0, 0.1) = (0, 2.0); then straight to (0, 2.5).

mod common;
use common::round;
use kerf_canon::Canon;
use kerf_interp::{Interp, Profile, Run, Settings};

/// 002 "Example—G90 Absolute Dimensions", exactly as printed (the
/// comment continuation lines included).
const ABS: &str = "\
N10                                (msg, lathe doc sample, abs G42, tool radius 0.1)
N20 G90 G40 G94 T0000             (absolute mode, CRC off, offset 0)
N30 G07 G00 X2.5 T0101           (radius programming,)
                                   (rapid to X, tool 1 offset 1)
N40 Z3                            (rapid to Z)
N60 X.5                           (rapid to X)
N70 G96 S350 M03                 (CSS, X axis at .5in,)
                                   (350 SFM and clockwise)
N80 G01 G95 F.01 X0              (face, IPR 0.01)
N120 G00 Z4                       (rapid to Z)
N125 G42                          (CRC right, skip if block del on)
N130 X.5 Z3                       (rapid to XZ)
N160 G01 X1 Z2                   (taper)
N170 X1.7                         (face)
N180 Z0.3                         (turn)
N190 X1.9                         (face)
N200 Z0                           (turn)
N230 G00 G40 X2.5                (CRC off, rapid to X, skip if)
                                   (block del on)
N240 Z3                           (rapid to Z)
N900 M30                          (end of program, rewind)
";

/// 002 "Example: G91 Incremental Dimensions", exactly as printed (the
/// blank line before N900 included).
const INC: &str = "\
N10                                (msg, lathe doc sample inc G42 tool rad 0.1)
N20 G90 G40 G94 T0000              (absolute mode, CRC off, offset 0)
N30 G07 G00 X2.5 T0101             (radius programming,)
                                   (rapid to X, tool 1 offset 1)
N40 Z3                             (rapid to Z)
N60 G91 X-2                        (incremental mode, rapid to X)
N70 G96 S350 M03                   (CSS, X axis at .5in,)
                                   (spindle speed 350 and clockwise)
N80 G01 G95 F.01 X-.5              (face, RPM 0.01)
N120 G00 Z1                        (rapid to Z)
N125 G42                           (CRC right, skip if block del on)
N130 X.5 Z-1                       (rapid to XZ)
N160 G01 X.5 Z-1                   (taper)
N170 X.7                           (face)
N180 Z-1.7                         (turn)
N190 X.2                           (face)
N200 Z-.3                          (turn)
/N230 G00 G40 X.6                  (CRC off, rapid to X, skip if)
                                   (block del on)
N240 Z3                             (rapid to Z)

N900 M30                           (end of program, rewind)
";

/// 002's G41/G42 "Examples" printing (Figures 14/15): the N30 comment
/// "(radius programming," is not closed on its line.
const FIG15: &str = "\
N10                               (msg, lathe doc sample, abs G42, tool rad 0.1)
N20 G90 G40 G94 T0000           (absolute mode, CRC off, offset 0)
N30 G07 G00 X2.5 T0101           (radius programming,
                                (rapid to X, tool 1 offset 1)

N40 Z3                             (rapid to Z)
N60 X.5                             (rapid to X)
N70 G96 R.5 S350 M03             (CSS, axis at .5in.,)
                                (350 SFM and clockwise)

N80 G01 G95 F.01 X0              (face, IPR 0.01)
N120 G00 Z4                       (rapid to Z)
N125 G42                         (Cutter Comp Right)
N130 X.5 Z3                       (rapid to XZ)
N160 G01 X1 Z2                   (taper)
N170 X1.7                         (face)
N180 Z0.3                         (turn)
N190 X1.9                         (face)
N200 Z0                           (turn)
N230 G00 G40 X2.5                (CRC off, rapid to X)
N240 Z3                           (rapid to Z)
N900 M30                          (end of program, rewind)
";

/// Runs `text` on hurco-lathe with tool offset 1 = radius 0.1, tip 0,
/// and the given block delete switches (bit n = `/n`).
fn run(block_skip: u16, text: &str) -> Run {
    let p = Profile::builtin("hurco-lathe").unwrap();
    let s = Settings {
        block_skip,
        ..Settings::default()
    };
    let mut it = Interp::new(p, s);
    let o = it.offsets_mut().lathe_mut(1).unwrap();
    o.r = 0.1;
    o.tip = 0;
    kerf_interp::run_interp(it, "t.nc", text)
}

/// (line, kind, X radius, Z) of every motion from the given line on.
fn path(r: &Run, from_line: u32) -> Vec<(u32, &'static str, f64, f64)> {
    r.events
        .iter()
        .filter_map(|e| {
            let k = match e.cmd {
                Canon::Rapid { .. } => "R",
                Canon::Feed { .. } => "F",
                Canon::Arc { .. } => "A",
                _ => return None,
            };
            let m = e.motion()?;
            Some((e.src.line, k, round(m.to[0]), round(m.to[2])))
        })
        .filter(|m| m.0 >= from_line)
        .collect()
}

/// The compensated profile N130-N200 (module comment), with the lines of
/// N130 … N200 in the program text.
fn profile(n130: u32) -> Vec<(u32, &'static str, f64, f64)> {
    let s5 = 5f64.sqrt();
    vec![
        (n130, "R", round(0.5 + 0.2 / s5), round(3.0 + 0.1 / s5)),
        (n130 + 1, "F", round(1.0 + 0.1 * (s5 - 1.0) / 2.0), 2.1),
        (n130 + 2, "F", 1.8, 2.1),
        (n130 + 3, "F", 1.8, 0.4),
        (n130 + 4, "F", 2.0, 0.4),
        (n130 + 5, "F", 2.0, 0.0),
    ]
}

/// The moves before the start-up: N40 Z3, N60 to X.5, N80 face to X0,
/// N120 to Z4 (lines 5, 6, 9, 10 in both printings).
fn lead_in() -> Vec<(u32, &'static str, f64, f64)> {
    vec![
        (5, "R", 2.5, 3.0),
        (6, "R", 0.5, 3.0),
        (9, "F", 0.0, 3.0),
        (10, "R", 0.0, 4.0),
    ]
}

#[test]
fn g90_absolute_example_with_g42() {
    let r = run(0, ABS);
    assert!(r.alarm.is_none(), "{:?}", r.alarm);
    let mut want = lead_in();
    want.extend(profile(12));
    want.push((18, "R", 2.5, 0.0));
    want.push((20, "R", 2.5, 3.0));
    assert_eq!(path(&r, 5), want);
}

/// The incremental printing draws the same part: every G91 step added up
/// by hand (X 2.5 − 2 = 0.5, − 0.5 = 0; Z 3 + 1 = 4; (0.5, 3), (1, 2),
/// X 1.7, Z 0.3, X 1.9, Z 0; N230 X 1.9 + 0.6 = 2.5; N240 Z 0 + 3 = 3).
#[test]
fn g91_incremental_example_with_g42() {
    let r = run(0, INC);
    assert!(r.alarm.is_none(), "{:?}", r.alarm);
    let mut want = lead_in();
    want.extend(profile(12));
    want.push((18, "R", 2.5, 0.0));
    want.push((20, "R", 2.5, 3.0));
    assert_eq!(path(&r, 5), want);
}

/// Block delete on skips `/N230 G00 G40 X.6` only: N125 G42 has no slash
/// in the print, though its comment says "skip if block del on". So G42
/// stays in force and N240 `Z3` is a G01 (the skipped block's G00 never
/// ran) going back along +Z. N200 → N240 is a full reversal, α = 0, an
/// outer acute corner (fanuc-semantics §4.2/§4.4): N200 is extended by r
/// past its end, (0, 2.0) → (−0.1, 2.0); a straight move to the point r
/// before N240's start on its offset line, (−0.1, 1.8) (the right normal
/// of +Z travel is −X); then N240 on X 1.8 to Z 3. M30 cancels without a
/// move.
#[test]
fn g91_incremental_example_with_block_delete_keeps_g42() {
    let r = run(1 << 1, INC);
    assert!(r.alarm.is_none(), "{:?}", r.alarm);
    let mut want = lead_in();
    want.extend(profile(12));
    want.pop();
    want.push((17, "F", 2.0, -0.1));
    want.push((17, "F", 1.8, -0.1));
    want.push((20, "F", 1.8, 3.0));
    assert_eq!(path(&r, 5), want);
}

/// The Figures 14/15 printing as extracted: the comment opened on N30
/// is closed only on the next line, and a Hurco comment ends with its
/// line, so the control stops there (HU-004 at the '(' of line 3,
/// column 34) before any move.
#[test]
fn figure_15_printing_alarms_at_the_unclosed_comment() {
    let r = run(0, FIG15);
    let a = r.alarm.as_ref().expect("an alarm");
    assert_eq!((a.code.as_str(), a.src.line, a.src.col), ("HU-004", 3, 34));
    assert!(path(&r, 0).is_empty());
}

/// The same printing with its N30 comment closed on its line (as the
/// other two printings have it) runs the part of the G90 example; its
/// `G96 R.5` names the CSS reference position and moves nothing.
#[test]
fn figure_15_printing_with_the_comment_closed() {
    let text = FIG15.replace("(radius programming,\n", "(radius programming,)\n");
    let r = run(0, &text);
    assert!(r.alarm.is_none(), "{:?}", r.alarm);
    let got = path(&r, 6);
    // Lines: N40 6, N60 7, N80 11, N120 12, N130 14 … N200 19, N230 20,
    // N240 21.
    let mut want = vec![
        (6, "R", 2.5, 3.0),
        (7, "R", 0.5, 3.0),
        (11, "F", 0.0, 3.0),
        (12, "R", 0.0, 4.0),
    ];
    want.extend(profile(14));
    want.push((20, "R", 2.5, 0.0));
    want.push((21, "R", 2.5, 3.0));
    assert_eq!(got, want);
}
