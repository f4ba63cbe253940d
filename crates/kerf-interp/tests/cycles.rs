//! Canned cycles (000 chapter 12) and G60 (000 §4.2) on the HX. Every
//! expected sequence is worked out by hand in the comments from the six
//! actions of 000 §12.1.1 and the per-cycle rules of docs/dialects.md;
//! PI 129 (d) is 0.1 mm and the G60 overrun 1.0 mm on hx-mc.

use kerf_canon::{Canon, ModeChange, SpindleDir};
use kerf_interp::Run;

mod common;
use common::{ok, round, run_on, run_with_param};

/// The run as a compact trace: `R x y z` rapid, `F x y z` feed (work
/// coordinates), `D s` dwell, `S+ rpm`/`S- rpm`/`S0` spindle, `M19`
/// orientation, `TAP`/`CUT` modes, `STOP`.
fn trace(r: &Run) -> Vec<String> {
    let f = |v: f64| format!("{}", round(v));
    r.events
        .iter()
        .filter_map(|e| {
            Some(match &e.cmd {
                Canon::Rapid { m, .. } => {
                    format!("R {} {} {}", f(m.to[0]), f(m.to[1]), f(m.to[2]))
                }
                Canon::Feed { m, .. } => {
                    format!("F {} {} {}", f(m.to[0]), f(m.to[1]), f(m.to[2]))
                }
                Canon::Dwell { seconds, .. } => format!("D {}", f(*seconds)),
                Canon::Spindle { dir, rpm, .. } => match dir {
                    SpindleDir::Cw => format!("S+ {}", f(*rpm)),
                    SpindleDir::Ccw => format!("S- {}", f(*rpm)),
                    SpindleDir::Stop => "S0".into(),
                },
                Canon::Aux { m, .. } => format!("M{m}"),
                Canon::Mode(ModeChange::TappingMode) => "TAP".into(),
                Canon::Mode(ModeChange::CuttingMode) => "CUT".into(),
                Canon::Stop { .. } => "STOP".into(),
                _ => return None,
            })
        })
        .collect()
}

/// Start: G54 work X0 Y0 Z100 (the manual's "(G92 X0 Y0 Z100)" position).
const START: &str = "G54 G90 G00 X0 Y0 Z100.\n";

fn run(body: &str) -> Run {
    run_on("hx-mc", &format!("{START}{body}M30\n"))
}

fn t(r: &Run) -> Vec<String> {
    ok(r);
    let mut v = trace(r);
    assert_eq!(v.first().map(String::as_str), Some("R 0 0 100"));
    v.remove(0);
    v
}

fn alarm(r: &Run) -> (&str, u32) {
    let a = r.alarm.as_ref().expect("an alarm");
    (a.code.as_str(), a.src.line)
}

#[test]
fn g81_g90_g99_then_g98() {
    // Hole 1 (10,20): rapid in the plane at the initial level 100, rapid
    // to R2, feed to -5, G99 rapid back to R2. Hole 2 (30,20): positioned
    // at the R level (already there: no move to R), feed -5, G98 rapid to
    // the initial level 100.
    let r = run("G99 G81 X10. Y20. Z-5. R2. F100\nG98 X30.\n");
    assert_eq!(
        t(&r),
        [
            "R 10 20 100",
            "R 10 20 2",
            "F 10 20 -5",
            "R 10 20 2",
            "R 30 20 2",
            "F 30 20 -5",
            "R 30 20 100"
        ]
    );
}

#[test]
fn g81_g91_k_repeats_step_by_the_increment() {
    // G91: R = initial 100 + (-95) = 5; Z = R 5 + (-7) = -2. K3 steps
    // (10,5) each time: holes (10,5), (20,10), (30,15), G99 back to R5.
    let r = run("G91 G99 G81 X10. Y5. Z-7. R-95. F100 K3\n");
    assert_eq!(
        t(&r),
        [
            "R 10 5 100",
            "R 10 5 5",
            "F 10 5 -2",
            "R 10 5 5",
            "R 20 10 5",
            "F 20 10 -2",
            "R 20 10 5",
            "R 30 15 5",
            "F 30 15 -2",
            "R 30 15 5"
        ]
    );
    // G90 K2 repeats the hole in place; G98 returns to 100 each time.
    let r = run("G98 G81 X10. Z-5. R2. F100 K2\n");
    assert_eq!(
        t(&r),
        [
            "R 10 0 100",
            "R 10 0 2",
            "F 10 0 -5",
            "R 10 0 100",
            "R 10 0 2",
            "F 10 0 -5",
            "R 10 0 100"
        ]
    );
}

#[test]
fn k0_stores_the_data_and_later_blocks_drill_with_it() {
    // K0: no motion. `X20.` drills at (20, 0) with Z-5 R2 F100 stored;
    // an M08-only block and an F-only block do not drill; `Y5.` does.
    let r = run("G98 G81 X10. Y10. Z-5. R2. F100 K0\nX20.\nM08\nF50\nY5.\n");
    assert_eq!(
        t(&r),
        [
            "R 20 0 100",
            "R 20 0 2",
            "F 20 0 -5",
            "R 20 0 100",
            "R 20 5 100",
            "R 20 5 2",
            "F 20 5 -5",
            "R 20 5 100"
        ]
    );
}

#[test]
fn m98_in_cycle_mode_calls_without_drilling() {
    // K0 stores the data; `M98 P100` is a call (its P is not a dwell) and
    // drills nothing; the subprogram's X10./X20. drill two holes (G98).
    let r = run("G98 G81 X5. Z-5. R2. F100 K0\nM98 P100\nM30\nO100\nX10.\nX20.\nM99\n");
    assert_eq!(
        t(&r),
        [
            "R 10 0 100",
            "R 10 0 2",
            "F 10 0 -5",
            "R 10 0 100",
            "R 20 0 100",
            "R 20 0 2",
            "F 20 0 -5",
            "R 20 0 100"
        ]
    );
}

#[test]
fn g83_peck_depth_not_a_multiple_of_q() {
    // R2 to Z-10 is 12 mm; Q5: pecks to 2-5 = -3, 2-10 = -8, then -10.
    // G83, d = 0.1: after each peck rapid to R2, rapid down to 0.1 above
    // the last depth (-2.9, -7.9), feed on. G99: back to R2.
    let r = run("G99 G83 Z-10. R2. Q5. F100\n");
    assert_eq!(
        t(&r),
        [
            "R 0 0 2",
            "F 0 0 -3",
            "R 0 0 2",
            "R 0 0 -2.9",
            "F 0 0 -8",
            "R 0 0 2",
            "R 0 0 -7.9",
            "F 0 0 -10",
            "R 0 0 2"
        ]
    );
    // The same with PI 129 = 1 mm: rapid down to -2 and -7.
    let r = run_with_param(
        "hx-mc",
        "PI 129",
        1.0,
        &format!("{START}G98 G83 Z-10. R2. Q5. F100\nM30\n"),
    );
    assert_eq!(
        t(&r),
        [
            "R 0 0 2",
            "F 0 0 -3",
            "R 0 0 2",
            "R 0 0 -2",
            "F 0 0 -8",
            "R 0 0 2",
            "R 0 0 -7",
            "F 0 0 -10",
            "R 0 0 100"
        ]
    );
}

#[test]
fn g73_high_speed_peck() {
    // Same hole: after each peck rapid up by d = 0.1 (to -2.9, -7.9) and
    // feed on; the last peck ends at -10; G98 rapid to 100.
    let r = run("G98 G73 Z-10. R2. Q5. F100\n");
    assert_eq!(
        t(&r),
        [
            "R 0 0 2",
            "F 0 0 -3",
            "R 0 0 -2.9",
            "F 0 0 -8",
            "R 0 0 -7.9",
            "F 0 0 -10",
            "R 0 0 100"
        ]
    );
    // Q without a decimal point is in 0.001 mm: Q5000 = 5 mm, same pecks.
    let r2 = run("G98 G73 Z-10. R2. Q5000 F100\n");
    assert_eq!(t(&r2), t(&r));
}

#[test]
fn g82_dwell_g85_g89_feed_out() {
    // G82 P500: dwell 0.5 s at the bottom, rapid out.
    let r = run("G99 G82 X5. Z-5. R2. P500 F100\n");
    assert_eq!(
        t(&r),
        ["R 5 0 100", "R 5 0 2", "F 5 0 -5", "D 0.5", "R 5 0 2"]
    );
    // G85: feed in, feed out to R, G98 rapid to 100.
    let r = run("G98 G85 X5. Z-5. R2. F100\n");
    assert_eq!(
        t(&r),
        ["R 5 0 100", "R 5 0 2", "F 5 0 -5", "F 5 0 2", "R 5 0 100"]
    );
    // G89: as G85 with dwell P250 = 0.25 s at the bottom.
    let r = run("G98 G89 X5. Z-5. R2. P250 F100\n");
    assert_eq!(
        t(&r),
        [
            "R 5 0 100",
            "R 5 0 2",
            "F 5 0 -5",
            "D 0.25",
            "F 5 0 2",
            "R 5 0 100"
        ]
    );
}

#[test]
fn g84_g74_tapping_reverse_the_spindle() {
    // G84 (M03 S500): tapping mode, feed in, dwell 0.3, spindle CCW, feed
    // out to R, dwell 0.3, spindle CW, cutting mode back; G98 rapid to 100.
    let r = run("S500 M03\nG98 G84 Z-10. R5. P300 F500\n");
    assert_eq!(
        t(&r),
        [
            "S+ 500",
            "R 0 0 5",
            "TAP",
            "F 0 0 -10",
            "D 0.3",
            "S- 500",
            "F 0 0 5",
            "D 0.3",
            "S+ 500",
            "CUT",
            "R 0 0 100"
        ]
    );
    // G74 (M04): the opposite directions; G99 stays at R.
    let r = run("S500 M04\nG99 G74 Z-10. R5. F500\n");
    assert_eq!(
        t(&r),
        [
            "S- 500",
            "R 0 0 5",
            "TAP",
            "F 0 0 -10",
            "S+ 500",
            "F 0 0 5",
            "S- 500",
            "CUT"
        ]
    );
    // G84.2 rigid tapping: the same sequence as G84.
    let r = run("S500 M03\nG99 G84.2 Z-10. R5. F500\n");
    assert_eq!(
        t(&r),
        [
            "S+ 500",
            "R 0 0 5",
            "TAP",
            "F 0 0 -10",
            "S- 500",
            "F 0 0 5",
            "S+ 500",
            "CUT"
        ]
    );
}

#[test]
fn g86_g88_stop_the_spindle() {
    // G86: feed in, spindle stop, rapid out (G98: 100), spindle CW again.
    let r = run("S800 M03\nG98 G86 Z-20. R2. F100\n");
    assert_eq!(
        t(&r),
        [
            "S+ 800",
            "R 0 0 2",
            "F 0 0 -20",
            "S0",
            "R 0 0 100",
            "S+ 800"
        ]
    );
    // G88: feed in, dwell, spindle stop, program stop (manual retract),
    // then rapid to R (G99) and spindle CW.
    let r = run("S800 M03\nG99 G88 Z-20. R2. P1000 F100\n");
    assert_eq!(
        t(&r),
        [
            "S+ 800",
            "R 0 0 2",
            "F 0 0 -20",
            "D 1",
            "S0",
            "STOP",
            "R 0 0 2",
            "S+ 800"
        ]
    );
}

#[test]
fn g76_fine_boring_shifts_away_from_the_wall() {
    // Q2: shift +X (PI 70 = PI 71 = 0). Feed to -20, orient (M19), rapid
    // +2 in X, rapid out to 100, rapid back -2 in X, spindle CW.
    let r = run("S800 M03\nG98 G76 X10. Z-20. R2. Q2. F100\n");
    assert_eq!(
        t(&r),
        [
            "S+ 800",
            "R 10 0 100",
            "R 10 0 2",
            "F 10 0 -20",
            "M19",
            "R 12 0 -20",
            "R 12 0 100",
            "R 10 0 100",
            "S+ 800"
        ]
    );
    // PI 70 = 1: -X; the shift goes to X8.
    let r = run_with_param(
        "hx-mc",
        "PI 70",
        1.0,
        &format!("{START}S800 M03\nG99 G76 X10. Z-20. R2. Q2. F100\nM30\n"),
    );
    assert_eq!(
        t(&r)[4..7],
        ["M19", "R 8 0 -20", "R 8 0 2"],
        "G99: out to R2 at the shifted position"
    );
    // I/J give the shift vector: I-1. J2.
    let r = run("S800 M03\nG99 G76 X10. Z-20. R2. I-1. J2. F100\n");
    assert_eq!(t(&r)[4..8], ["M19", "R 9 2 -20", "R 9 2 2", "R 10 0 2"]);
}

#[test]
fn g87_back_boring() {
    // Initial 100, R-30 below the bore, Z-10 its top. Orient, shift +2,
    // rapid down to R, shift back, spindle CW, feed up to -10, dwell,
    // orient, shift, rapid up to 100, shift back, spindle CW.
    let r = run("S600 M03\nG98 G87 X10. Z-10. R-30. Q2. P100 F80\n");
    assert_eq!(
        t(&r),
        [
            "S+ 600",
            "R 10 0 100",
            "M19",
            "R 12 0 100",
            "R 12 0 -30",
            "R 10 0 -30",
            "S+ 600",
            "F 10 0 -10",
            "D 0.1",
            "M19",
            "R 12 0 -10",
            "R 12 0 100",
            "R 10 0 100",
            "S+ 600"
        ]
    );
    // G99 is not allowed with G87.
    let r = run("G99 G87 X10. Z-10. R-30. Q2. F80\n");
    assert_eq!(alarm(&r), ("KERF-0103", 2));
}

#[test]
fn g80_and_group_01_cancel_the_cycle() {
    // After G80 `X10.` is a G00 move (group 01 was G00).
    let r = run("G99 G81 X5. Z-5. R2. F100\nG80\nX10.\n");
    assert_eq!(
        t(&r),
        ["R 5 0 100", "R 5 0 2", "F 5 0 -5", "R 5 0 2", "R 10 0 2"]
    );
    // G01 cancels: `G01 X20.` and `Y5.` are feed moves, no hole.
    let r = run("G98 G81 X5. Z-5. R2. F100\nG01 X20.\nY5.\n");
    assert_eq!(
        t(&r),
        [
            "R 5 0 100",
            "R 5 0 2",
            "F 5 0 -5",
            "R 5 0 100",
            "F 20 0 100",
            "F 20 5 100"
        ]
    );
    // G80 clears the data: G81 X1. afterwards has no Z or R.
    let r = run("G98 G81 X5. Z-5. R2. F100\nG80\nG81 X1.\n");
    assert_eq!(alarm(&r), ("F_82008", 4));
}

#[test]
fn initial_level_is_fixed_while_the_mode_lasts() {
    // The cycle changes from G81 to G82 without G80: the initial level
    // stays 100 although the tool is at R2 when G82 starts (G99).
    let r = run("G99 G81 X5. Z-5. R2. F100\nG98 G82 X6. P100\n");
    assert_eq!(
        t(&r),
        [
            "R 5 0 100",
            "R 5 0 2",
            "F 5 0 -5",
            "R 5 0 2",
            "R 6 0 2",
            "F 6 0 -5",
            "D 0.1",
            "R 6 0 100"
        ]
    );
}

#[test]
fn g18_drills_along_y() {
    // G18: plane Z-X, drilling axis Y; the depth address is Y. Start at
    // (0, 50, 0): position X10 Z20 at Y50, rapid to R2, feed to Y-5.
    let r = run_on(
        "hx-mc",
        "G54 G90 G00 X0 Y50. Z0\nG18 G99 G81 X10. Z20. Y-5. R2. F100\nM30\n",
    );
    ok(&r);
    assert_eq!(
        trace(&r),
        [
            "R 0 50 0",
            "R 10 50 20",
            "R 10 2 20",
            "F 10 -5 20",
            "R 10 2 20"
        ]
    );
}

#[test]
fn g60_single_direction_positioning() {
    // 000 §4.2 example, overrun +1 mm on X, Y, Z: each positioning stops
    // 1 mm short (on the - side) and approaches in +.
    let r = run_on(
        "hx-mc",
        "G54 G00 X0. Y0. Z0\nG90 G60 X50.\nG60 Y50.\nG60 Z50.\nG91 G60 X-50. Y-50. Z-50.\nM30\n",
    );
    ok(&r);
    assert_eq!(
        trace(&r),
        [
            "R 0 0 0",
            "R 49 0 0",
            "R 50 0 0",
            "R 50 49 0",
            "R 50 50 0",
            "R 50 50 49",
            "R 50 50 50",
            "R -1 -1 -1",
            "R 0 0 0"
        ]
    );
    // In a canned cycle only the plane positioning uses it.
    let r = run("G60 G98 G81 X10. Y10. Z-5. R2. F100\n");
    assert_eq!(
        t(&r),
        [
            "R 9 9 100",
            "R 10 10 100",
            "R 10 10 2",
            "F 10 10 -5",
            "R 10 10 100"
        ]
    );
    // G60 is one-shot: the next block is a plain G00.
    let r = run("G60 X10.\nX20.\n");
    assert_eq!(t(&r), ["R 9 0 100", "R 10 0 100", "R 20 0 100"]);
    // With an interpolation code it is an alarm.
    let r = run("G60 G01 X10. F100\n");
    assert_eq!(alarm(&r), ("KERF-0103", 2));
}

#[test]
fn bad_cycle_input_alarms() {
    // No depth / no R.
    assert_eq!(alarm(&run("G81 X10. R2. F100\n")), ("F_82008", 2));
    assert_eq!(alarm(&run("G81 X10. Z-5. F100\n")), ("F_82008", 2));
    // G91 depth without R.
    assert_eq!(alarm(&run("G91 G81 X10. Z-5. F100\n")), ("F_82008", 2));
    // Peck cycles: missing Q, Q0, negative Q.
    assert_eq!(alarm(&run("G83 Z-5. R2. F100\n")), ("F_82008", 2));
    assert_eq!(alarm(&run("G83 Z-5. R2. Q0 F100\n")), ("F_82007", 2));
    assert_eq!(alarm(&run("G73 Z-5. R2. Q-1. F100\n")), ("F_82007", 2));
    // K out of range or not whole.
    assert_eq!(alarm(&run("G81 Z-5. R2. F100 K-1\n")), ("F_82007", 2));
    assert_eq!(alarm(&run("G81 Z-5. R2. F100 K1.5\n")), ("F_82007", 2));
    assert_eq!(alarm(&run("G81 Z-5. R2. F100 K10000\n")), ("F_82007", 2));
    // P with a decimal point.
    assert_eq!(alarm(&run("G82 Z-5. R2. P1. F100\n")), ("F_82007", 2));
    // Plane change inside the cycle mode; a cycle and G00 in one block.
    assert_eq!(
        alarm(&run("G81 Z-5. R2. F100\nG18 X5.\n")),
        ("KERF-0103", 3)
    );
    assert_eq!(alarm(&run("G00 G81 Z-5. R2. F100\n")), ("KERF-0103", 2));
    // No feedrate for the feed in.
    assert_eq!(alarm(&run("G81 Z-5. R2.\n")), ("F_84020", 2));
    // 500 mm in pecks of 0.001 mm: more moves than one block may make.
    assert_eq!(alarm(&run("G83 Z-400. R2. Q1 F100\n")), ("F_82007", 2));
    // A hole below the Z travel: overtravel, not a panic.
    assert_eq!(alarm(&run("G81 Z-300. R2. F100\n")), ("F_84100", 2));
}

#[test]
fn plane_code_in_cycle_mode() {
    // Naming the plane already in force (G17 in a G17 cycle) is no change:
    // the hole is drilled (rapid to 10,0 at 100, R2, feed -3, back to 100).
    let r = run("G98 G81 X5. Z-3. R2. F100\nG17 X10.\nG80\n");
    assert_eq!(
        t(&r),
        [
            "R 5 0 100",
            "R 5 0 2",
            "F 5 0 -3",
            "R 5 0 100",
            "R 10 0 100",
            "R 10 0 2",
            "F 10 0 -3",
            "R 10 0 100"
        ]
    );
    // A real change (G18) inside the mode is the alarm, at the G18 word.
    let r = run("G98 G81 X5. Z-3. R2. F100\nG18 X10.\nG80\n");
    assert_eq!(alarm(&r), ("KERF-0103", 3));
}
