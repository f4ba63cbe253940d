//! Custom macro control flow (000 §14.2.5, Fanuc standard where the HX
//! text is unreadable), ROUND in addresses and BIN/BCD (000 §14.2.4).
//! Every expected value is worked out by hand.

use kerf_canon::Canon;
use kerf_interp::Run;

mod common;
use common::{ok, round, run_on};

fn hx(text: &str) -> Run {
    run_on("hx-mc", text)
}

/// (line, x, y, z) of each motion end point in work coordinates.
fn moves(r: &Run) -> Vec<(u32, f64, f64, f64)> {
    r.events
        .iter()
        .filter(|e| matches!(e.cmd, Canon::Rapid { .. } | Canon::Feed { .. }))
        .map(|e| {
            let m = e.motion().unwrap();
            (e.src.line, round(m.to[0]), round(m.to[1]), round(m.to[2]))
        })
        .collect()
}

fn alarm(r: &Run) -> (&str, u32) {
    let a = r.alarm.as_ref().expect("an alarm");
    (a.code.as_str(), a.src.line)
}

#[test]
fn crossing_loops_alarm_at_the_crossing_end() {
    let r = hx("#1=0\n\
                WHILE [#1 LT 2] DO1\n\
                WHILE [#1 LT 2] DO2\n\
                #1=#1+1\n\
                END1\n\
                END2\n\
                M30\n");
    assert_eq!(alarm(&r), ("F_82202", 5));
    // Also when the inner loop is never entered.
    let r = hx("#1=0\n\
                WHILE [#1 LT 2] DO1\n\
                WHILE [#1 GT 2] DO2\n\
                #1=#1+1\n\
                END1\n\
                END2\n\
                M30\n");
    assert_eq!(alarm(&r), ("F_82202", 5));
}

#[test]
fn goto_into_a_loop_alarms_at_its_end() {
    let r = hx("G90 G00 X0 Y0 Z0\n\
                #1=0\n\
                GOTO 5\n\
                WHILE [#1 LT 2] DO1\n\
                N5 #1=#1+1\n\
                END1\n\
                M30\n");
    assert_eq!(alarm(&r), ("F_82202", 6));
}

#[test]
fn missing_end_alarms_at_the_while() {
    let r = hx("G90 G00 X0 Y0 Z0\nWHILE [1] DO1\nG00 X1.\nM30\n");
    assert_eq!(alarm(&r), ("F_82202", 2));
    // False condition: the skip finds no END either.
    let r = hx("G90 G00 X0 Y0 Z0\nWHILE [0] DO1\nG00 X1.\nM30\n");
    assert_eq!(alarm(&r), ("F_82202", 2));
    // The END of the next program does not count.
    let r = hx("O1\nWHILE [0] DO1\nM30\nO2\nEND1\nM99\n");
    assert_eq!(alarm(&r), ("F_82202", 2));
    // Nor does an END after the closing %.
    let r = hx("%\nWHILE [0] DO1\nM30\n%\nEND1\n");
    assert_eq!(alarm(&r), ("F_82202", 2));
    // A loop entered many times (inner loop, scan remembered) still
    // checks: the same inner loop inside two different outer labels.
    let r = hx("G90 G00 X0 Y0 Z0\n\
                #1 = 0\n\
                #3 = 0\n\
                WHILE [#1 LT 3] DO1\n\
                #2 = 0\n\
                WHILE [#2 LT 2] DO2\n\
                #2 = #2 + 1\n\
                #3 = #3 + 1\n\
                END2\n\
                #1 = #1 + 1\n\
                END1\n\
                G00 X#3\n\
                M30\n");
    ok(&r);
    assert_eq!(moves(&r)[1], (12, 6.0, 0.0, 0.0));
}

#[test]
fn loop_labels_per_profile() {
    // HX: arbitrary labels (sample 14.5.3 uses DO 210 / DO 220).
    let r = hx("G90 G00 X0 Y0 Z0\n\
                #1=0\n\
                WHILE [#1 LT 2] DO 210\n\
                #2=0\n\
                WHILE [#2 LT 2] DO 220\n\
                #2=#2+1\n\
                G00 X#1 Y#2\n\
                END 220\n\
                #1=#1+1\n\
                END 210\n\
                M30\n");
    ok(&r);
    assert_eq!(
        moves(&r),
        vec![
            (1, 0.0, 0.0, 0.0),
            (7, 0.0, 1.0, 0.0),
            (7, 0.0, 2.0, 0.0),
            (7, 1.0, 1.0, 0.0),
            (7, 1.0, 2.0, 0.0)
        ]
    );
    let r = hx("WHILE [0] DO 10000\nEND 10000\nM30\n");
    assert_eq!(alarm(&r), ("F_82202", 1));
    let r = hx("WHILE [0] DO0\nEND0\nM30\n");
    assert_eq!(alarm(&r), ("F_82202", 1));
    // Fanuc lathe: DO1-DO3 only (PS0126 family, code PS128 here).
    let r = run_on("puma-lathe", "WHILE [0] DO4\nEND4\nM30\n");
    assert_eq!(alarm(&r), ("PS128", 1));
    let r = run_on(
        "puma-lathe",
        "#1=0\nWHILE [#1 LT 2] DO3\n#1=#1+1\nEND3\nM30\n",
    );
    ok(&r);
}

#[test]
fn nesting_more_than_three_deep_alarms() {
    let r = hx("WHILE [1] DO1\n\
                WHILE [1] DO2\n\
                WHILE [1] DO3\n\
                WHILE [1] DO4\n\
                END4\nEND3\nEND2\nEND1\nM30\n");
    assert_eq!(alarm(&r), ("F_82202", 4));
    // The same label inside an open loop.
    let r = hx("WHILE [1] DO1\nWHILE [1] DO1\nEND1\nEND1\nM30\n");
    assert_eq!(alarm(&r), ("F_82202", 2));
    // Three deep is fine; labels may be reused by loops that follow.
    let r = hx("G90 G00 X0 Y0 Z0\n\
                #1=0\n\
                WHILE [#1 LT 1] DO1\n\
                WHILE [#1 LT 1] DO2\n\
                WHILE [#1 LT 1] DO3\n\
                #1=#1+1\n\
                END3\nEND2\nEND1\n\
                WHILE [#1 LT 2] DO1\n\
                #1=#1+1\n\
                END1\n\
                G00 X#1\n\
                M30\n");
    ok(&r);
    assert_eq!(moves(&r), vec![(1, 0.0, 0.0, 0.0), (13, 2.0, 0.0, 0.0)]);
}

#[test]
fn goto_out_of_a_loop_leaves_it() {
    // Jumping out of DO1 and opening another DO1 afterwards is legal.
    let r = hx("G90 G00 X0 Y0 Z0\n\
                WHILE [1] DO1\n\
                G00 X1.\n\
                GOTO 5\n\
                END1\n\
                N5 #1=0\n\
                WHILE [#1 LT 2] DO1\n\
                #1=#1+1\n\
                G00 Y#1\n\
                END1\n\
                M30\n");
    ok(&r);
    assert_eq!(
        moves(&r),
        vec![
            (1, 0.0, 0.0, 0.0),
            (3, 1.0, 0.0, 0.0),
            (9, 1.0, 1.0, 0.0),
            (9, 1.0, 2.0, 0.0)
        ]
    );
    // Leaving three nested loops by a backward GOTO, five times over.
    let r = hx("G90 G00 X0 Y0 Z0\n\
                #2=0\n\
                N1 #2=#2+1\n\
                IF [#2 GT 5] GOTO 20\n\
                WHILE [1] DO1\n\
                WHILE [1] DO2\n\
                WHILE [1] DO3\n\
                G91 G00 X1.\n\
                GOTO 1\n\
                END3\nEND2\nEND1\n\
                N20 M30\n");
    ok(&r);
    let m = moves(&r);
    assert_eq!(m.len(), 1 + 5);
    assert_eq!(m[5], (8, 5.0, 0.0, 0.0));
}

#[test]
fn do_without_while_loops_until_goto() {
    let r = hx("G90 G00 X0 Y0 Z0\n\
                #1=0\n\
                DO1\n\
                #1=#1+1\n\
                G00 X#1\n\
                IF [#1 GE 3] GOTO 9\n\
                END1\n\
                N9 M30\n");
    ok(&r);
    assert_eq!(
        moves(&r),
        vec![
            (1, 0.0, 0.0, 0.0),
            (5, 1.0, 0.0, 0.0),
            (5, 2.0, 0.0, 0.0),
            (5, 3.0, 0.0, 0.0)
        ]
    );
}

#[test]
fn if_then_assigns_only_when_true() {
    let r = hx("#1=1\n\
                IF [#1 EQ 1] THEN #2=5\n\
                IF [#1 EQ 0] THEN #3=7\n\
                IF [#3 EQ #0] THEN #4=[#2*2]\n\
                G00 X#2 Y#4 Z#3\n\
                M30\n");
    ok(&r);
    // #3 vacant: Z is omitted and stays at the start position.
    let z0 = hx("G00 X0\nM30\n");
    let z = moves(&z0)[0].3;
    assert_eq!(moves(&r), vec![(5, 5.0, 10.0, z)]);
    // THEN takes one assignment, not GOTO or an NC block.
    let r = hx("IF [1] THEN GOTO 5\nM30\n");
    assert_eq!(r.alarm.as_ref().expect("alarm").src.line, 1);
}

/// 000 §14.2.4: an address value is rounded to the least input increment,
/// so the three moves are 1.235, 2.346 and -3.580 and the tool does not
/// come back to X0 (0.001 remains).
#[test]
fn address_values_round_to_the_least_increment_14_2_4() {
    let r = hx("G90 G00 X0 Y0 Z0\n\
                N1 #1 = 1.2345;\n\
                N2 #2 = 2.3456;\n\
                N3 G91 G01 X#1 F100;\n\
                N4 X#2;\n\
                N5 X-[#1 + #2];\n\
                M30\n");
    ok(&r);
    assert_eq!(
        moves(&r),
        vec![
            (1, 0.0, 0.0, 0.0),
            (4, 1.235, 0.0, 0.0),
            (5, 3.581, 0.0, 0.0),
            (6, 0.001, 0.0, 0.0)
        ]
    );
    // ROUND inside the address rounds each term to 0.001 first:
    // -(1.235 + 2.346) = -3.581 brings the tool back to X0.
    let r = hx("G90 G00 X0 Y0 Z0\n\
                #1 = 1.2345\n\
                #2 = 2.3456\n\
                G91 G01 X#1 F100\n\
                X#2\n\
                X-[ROUND[#1]+ROUND[#2]]\n\
                M30\n");
    ok(&r);
    assert_eq!(moves(&r)[3], (6, 0.0, 0.0, 0.0));
}

#[test]
fn round_in_an_address_and_in_a_statement() {
    let r = hx("G90 G00 X0 Y0 Z0\n\
                #1 = 1.4567\n\
                #2 = 3.567\n\
                #3 = ROUND[1.2345]\n\
                G00 X[ROUND[#1]] Y#3\n\
                IF [#1 LE ROUND[#2]] GOTO 8\n\
                G00 Z-5.\n\
                N8 G20 G00 X#4 Y[ROUND[#5]]\n\
                M30\n");
    ok(&r);
    // X1.457 (1.4567 to 0.001), Y1 (ROUND[1.2345] = 1); 1.4567 <= 4 skips
    // the Z move; X#4 (vacant) is omitted, ROUND of the vacant #5 is 0: Y0.
    assert_eq!(
        moves(&r),
        vec![
            (1, 0.0, 0.0, 0.0),
            (5, 1.457, 1.0, 0.0),
            (8, 1.457, 0.0, 0.0)
        ]
    );
    // Inch: 0.0001 in.
    let r = hx("G20 G90 G00 X0 Y0 Z0\n#5 = 1.23456\nX#5 Y[ROUND[#5]]\nM30\n");
    ok(&r);
    assert_eq!(moves(&r)[1], (3, 31.35884, 31.35884, 0.0));
}

#[test]
fn bin_and_bcd() {
    // BCD[25] = 0x25 = 37, BIN[37] = 25, BIN[0x1234 = 4660] = 1234.
    let r = hx("G90 G00 X[BCD[25]-30] Y[BIN[37]-20] Z[BIN[4660]-1234+BCD[0]]\nM30\n");
    ok(&r);
    assert_eq!(moves(&r), vec![(1, 7.0, 5.0, 0.0)]);
    let r =
        hx("#1 = BCD[99999999]\n#2 = BIN[#1]\nIF [#2 NE 99999999] GOTO 9\nG00 X0 Y0 Z0\nN9 M30\n");
    ok(&r);
    assert_eq!(moves(&r).len(), 1);
    // 0x1A is not BCD; negative arguments alarm.
    assert_eq!(alarm(&hx("#1 = 1\n#1 = BIN[26]\nM30\n")).1, 2);
    assert_eq!(alarm(&hx("#1 = BCD[-1]\nM30\n")).1, 1);
    assert_eq!(alarm(&hx("#1 = BCD[1.5]\nM30\n")).1, 1);
}

#[test]
fn bracket_nesting_limit() {
    // HX: 10 levels (000 §14.2.4); the Fanuc lathe: 5 levels.
    let r = hx("#1 = [[[[[[[[[[1]]]]]]]]]]\nM30\n");
    ok(&r);
    let r = hx("#1 = 1\n#1 = [[[[[[[[[[[1]]]]]]]]]]]\nM30\n");
    assert_eq!(alarm(&r).1, 2);
    let r = run_on("puma-lathe", "#1 = SIN[[[[[1]]]]]\nM30\n");
    ok(&r);
    let r = run_on("puma-lathe", "#1 = 1\n#1 = SIN[[[[[[1]]]]]]\nM30\n");
    assert_eq!(alarm(&r).1, 2);
}

/// 000 §14.2.3: on the HX #34-#99 are local too (one set per macro level);
/// the retained range is #200-#699 there and #500-#999 on the lathe.
#[test]
fn hx_locals_34_to_99_and_variable_ranges() {
    let r = hx("#40 = 5\n\
                G65 P100 A1.\n\
                G90 G00 X#40 Y0 Z0\n\
                M30\n\
                O100\n\
                IF [#40 NE #0] GOTO 9\n\
                #40 = #1 + 1\n\
                G90 G00 X#40 Y0 Z0\n\
                N9 M99\n");
    ok(&r);
    assert_eq!(moves(&r), vec![(8, 2.0, 0.0, 0.0), (3, 5.0, 0.0, 0.0)]);
    ok(&hx("#99 = 1\n#200 = 1\n#699 = 2\nM30\n"));
    assert_eq!(alarm(&hx("#1 = 0\n#700 = 1\nM30\n")), ("F_82200", 2));
    assert_eq!(alarm(&hx("#1 = 0\n#1 = #999\nM30\n")), ("F_82200", 2));
    ok(&run_on("puma-lathe", "#500 = 1\n#999 = 2\nM30\n"));
    assert_eq!(alarm(&run_on("puma-lathe", "#1 = 0\n#34 = 1\nM30\n")).1, 2);
    assert_eq!(alarm(&run_on("puma-lathe", "#1 = 0\n#200 = 1\nM30\n")).1, 2);
}
