//! Stored stroke check 2 (G22, 000 §15.5.3) in every way the HX moves:
//! the same forbidden area alarms F_84100 whatever mode makes the move,
//! and the alarm comes before the block moves (none of its events is
//! handed out; the last move is the block before's).
//!
//! The areas are machine coordinates; on the hx-mc profile work =
//! machine + (400, 250, 250) (G54), and the tool starts at machine
//! (0, 0, 0) = work (400, 250, 250). The modes: G00-G03, canned cycles,
//! `,C`/`,R`, cutter compensation, G112/G107, G31/G37, G33, G28/G29,
//! G45-G48, G60 and G53. (The lathe cycles and the Hurco
//! cycles, whose controls have no G22, are checked through the same seam
//! in the unit tests of interp/mover.rs.)

mod common;
use common::*;
use kerf_interp::{run_interp, Interp, Profile, Settings};

/// 000 §15.5.3 area A: machine X -190…-120, Y -150…-100, every Z; in
/// work coordinates X 210…280, Y 100…150.
const AREA_XY: &str = "G22 X-120. Y-100. I-190. J-150.\n";

/// The same in X and Y, machine Z -200…-100: work Z 50…150.
const AREA_XYZ: &str = "G22 X-120. Y-100. Z-100. I-190. J-150. K-200.\n";

/// Runs `text` on the hx-mc; asserts a stored stroke alarm at `line`
/// (column 1; `alarms_with` takes the column) and that the last move
/// handed out ends at work `last`.
fn alarms_at(text: &str, line: u32, last: (f64, f64, f64)) {
    alarms_with(Settings::default(), text, (line, 1), last)
}

fn alarms_with(s: Settings, text: &str, at: (u32, u32), last: (f64, f64, f64)) {
    let r = run_with("hx-mc", s, text);
    assert_eq!(alarm(&r), ("F_84100", at.0, at.1), "{text}");
    let m = moves(&r);
    let end = m.last().map(|m| (m.1, m.2, m.3));
    assert_eq!(end, Some(last), "{text}");
}

/// Work (400, 250) → (300, 125) as the HX rapid goes (X and Y at 24000
/// mm/min: a diagonal to (300, 150), then Y alone), outside the area;
/// then along work Y125 (machine -125, inside Y -150…-100) to X200,
/// which crosses machine X -120…-190.
#[test]
fn rapid_and_feed() {
    let to = "G00 X300. Y125.\n";
    alarms_at(
        &format!("{AREA_XY}{to}G00 X200.\n"),
        3,
        (300.0, 125.0, 250.0),
    );
    alarms_at(
        &format!("{AREA_XY}{to}G01 X200. F1000\n"),
        3,
        (300.0, 125.0, 250.0),
    );
    // Without the area, the same moves run.
    ok(&run_on("hx-mc", &format!("{to}G01 X200. F1000\n")));
}

/// G02 from work (300, 160) to (200, 160), R50: centre (250, 160), the
/// arc dips to (250, 110), inside X 210…280 / Y 100…150, while its chord
/// (Y160) and both ends are outside. G03 bulges the other way: fine.
#[test]
fn arcs_by_their_path() {
    let to = "G00 X300. Y160.\n";
    alarms_at(
        &format!("{AREA_XY}{to}G02 X200. R50. F1000\n"),
        3,
        (300.0, 160.0, 250.0),
    );
    ok(&run_on(
        "hx-mc",
        &format!("{AREA_XY}{to}G03 X200. R50. F1000\n"),
    ));
}

/// G81 at work X245 Y125 from (300, 125): the positioning rapid runs
/// along Y125 into the area (every Z is forbidden) before the hole.
#[test]
fn canned_cycle() {
    alarms_at(
        &format!("{AREA_XY}G00 X300. Y125. Z100.\nG81 X245. Y125. Z-10. R5. F100\n"),
        3,
        (300.0, 125.0, 100.0),
    );
}

/// A chamfer between two moves that stay outside: along work Y160 to
/// X290, then down X290 to Y100. `,C30.` cuts from (260, 160) to
/// (290, 130), the line x + y = 420, through (275, 145): inside. The
/// chamfer is committed when the second move is known, as a piece of the
/// ,C block (line 3); the held first move has not been handed out.
#[test]
fn chamfer_corner() {
    let to = "G00 X200. Y160.\n";
    alarms_at(
        &format!("{AREA_XY}{to}G01 X290. ,C30. F1000\nY100.\n"),
        3,
        (200.0, 160.0, 250.0),
    );
    // Without the chamfer the corner stays outside.
    ok(&run_on(
        "hx-mc",
        &format!("{AREA_XY}{to}G01 X290. F1000\nY100.\n"),
    ));
}

/// Cutter compensation G41 D1 = 15 on a move in -X along Y160: the
/// compensated path is 15 to the left, Y145, inside the area, while the
/// programmed path is outside. The compensated move is committed at the
/// G40 block.
#[test]
fn cutter_compensation() {
    let text = format!("{AREA_XY}G00 X320. Y160.\nG41 G01 X300. D1 F1000\nX200.\nG40 X180.\n");
    let mut it = Interp::new(Profile::builtin("hx-mc").unwrap(), Settings::default());
    it.offsets_mut().d_mut(1).unwrap().geom = 15.0;
    let r = run_interp(it, "t.nc", &text);
    let a = r.alarm.as_ref().expect("an alarm");
    assert_eq!(a.code, "F_84100");
    assert_eq!(a.src.line, 4, "alarms at the move whose offset path enters");
    // No compensated move along Y145 was handed out.
    assert!(moves(&r).iter().all(|m| m.2 != 145.0 || m.1 >= 280.0));
}

/// G112 (the bug this check fixes): from work (300, 125), C0, a G01 X200
/// in the virtual plane is a straight chord chain along X at Y125 in
/// the machine axes, through the area; it alarms before the first chord.
#[test]
fn polar_interpolation() {
    alarms_at(
        &format!("{AREA_XY}G00 X300. Y125. C0. Z0.\nG112\nG01 X200. F100.\n"),
        4,
        (300.0, 125.0, 0.0),
    );
}

/// G107 on a cylinder of radius 10: from work (250, 125, 200) (machine
/// Z -50, above the area's Z -200…-100), a G02 in Z-C from Z200 to Z0
/// runs down through work Z 150…50 with X and Y inside the area.
#[test]
fn cylindrical_interpolation() {
    alarms_at(
        &format!("G00 Z200.\nX250. Y125.\n{AREA_XYZ}G18 G107 C10.\nG02 Z0. C114.592 R150. F100.\n"),
        5,
        (250.0, 125.0, 200.0),
    );
}

/// G31 X200 from (300, 125) with the skip signal at work X205: the move
/// to the contact crosses the area. G37 Z-10. from Z200 rapids to Z0 (its r of
/// 10) through work Z 150…50 at X250 Y125.
#[test]
fn skip_and_measurement() {
    let mut s = Settings::default();
    s.skip[0][0] = Some(205.0);
    alarms_with(
        s,
        &format!("{AREA_XY}G00 X300. Y125.\nG31 X200. F100.\n"),
        (3, 1),
        (300.0, 125.0, 250.0),
    );
    // The r-point rapid's alarm points at the Z word (column 5).
    alarms_with(
        Settings::default(),
        &format!("G00 Z200.\nX250. Y125.\n{AREA_XYZ}G43 H1\nG37 Z-10.\n"),
        (5, 5),
        (250.0, 125.0, 200.0),
    );
}

/// G33 from work Z200 to Z0 at X250 Y125 crosses work Z 150…50.
#[test]
fn threading() {
    alarms_at(
        &format!("G00 Z200.\nX250. Y125.\n{AREA_XYZ}S300 M03\nG33 Z0. F5.\n"),
        5,
        (250.0, 125.0, 200.0),
    );
}

/// G28: the intermediate point work X200 from (300, 125) crosses; from
/// (200, 125), reached round the area, the return to the X reference
/// (machine X0) along machine Y -125 crosses it.
#[test]
fn reference_return() {
    alarms_at(
        &format!("{AREA_XY}G00 X300. Y125.\nG28 X200.\n"),
        3,
        (300.0, 125.0, 250.0),
    );
    alarms_at(
        &format!("{AREA_XY}G00 X200.\nY125.\nG28 X200.\n"),
        4,
        (200.0, 125.0, 250.0),
    );
}

/// G45 with D1 = 15 from work (300, 125): `G01 X290.` is a move of -10,
/// lengthened by D to -25 (000 §13.3), ending at X275, inside X 210…280.
/// The same block without G45 ends at X290, outside.
#[test]
fn tool_offset_increase() {
    let text = format!("{AREA_XY}G00 X300. Y125.\nG45 G01 X290. D1 F1000\n");
    let mut it = Interp::new(Profile::builtin("hx-mc").unwrap(), Settings::default());
    it.offsets_mut().d_mut(1).unwrap().geom = 15.0;
    let r = run_interp(it, "t.nc", &text);
    // At the block's motion code (column 5).
    assert_eq!(alarm(&r), ("F_84100", 3, 5), "{text}");
    let end = moves(&r).last().map(|m| (m.1, m.2, m.3));
    assert_eq!(end, Some((300.0, 125.0, 250.0)));
    let plain = format!("{AREA_XY}G00 X300. Y125.\nG01 X290. D1 F1000\n");
    ok(&run_on("hx-mc", &plain));
}

/// G60 X200 from (300, 125): a rapid along Y125 through the area (the
/// hx-mc has no overrun, so the approach is the move itself).
#[test]
fn single_direction_positioning() {
    alarms_at(
        &format!("{AREA_XY}G00 X300. Y125.\nG60 X200.\n"),
        3,
        (300.0, 125.0, 250.0),
    );
}

/// G53 X-200. from work (300, 125) = machine (-100, -125): a rapid along
/// machine Y -125 from X -100 to X -200 crosses X -120…-190.
#[test]
fn machine_coordinates() {
    alarms_at(
        &format!("{AREA_XY}G00 X300. Y125.\nG53 X-200.\n"),
        3,
        (300.0, 125.0, 250.0),
    );
}

/// G29 X200. Y125. after `G28 X300. Y160.` (intermediate point work
/// (300, 160), reference = work (400, 250)): back through (300, 160),
/// then the HX rapid's diagonal towards (200, 125) reaches (265, 125),
/// entering the area at X280, Y140. Nothing of the G29 block is handed
/// out: the last move is the G28's, at the reference.
#[test]
fn return_from_reference() {
    alarms_at(
        &format!("{AREA_XY}G00 X300. Y160.\nG28 X300. Y160.\nG29 X200. Y125.\n"),
        4,
        (400.0, 250.0, 250.0),
    );
}
