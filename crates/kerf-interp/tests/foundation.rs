//! Foundation behaviour of the interpreter, with expected values worked
//! out by hand from the manuals' rules (not from kerf's output).

use kerf_canon::{ArcDir, Canon, Event, Feed, SpindleDir};
use kerf_interp::{run_text, Profile, Run, Settings};

mod common;
use common::{alarm, moves, ok, round, run_on, run_with, run_with_param};

#[test]
fn least_input_increment_and_decimal_point() {
    // 0.001 mm per digit without a decimal point: X1000 = 1 mm, Z-500 = -0.5 mm.
    let r = run_on("hx-mc", "G90 G00 X1000 Y100. Z-500\nM30\n");
    ok(&r);
    assert_eq!(moves(&r), vec![("rapid", 1.0, 100.0, -0.5)]);
    // Inch: 0.0001 in per digit; X10000 = 1 in = 25.4 mm; X.5 = 12.7 mm.
    let r = run_on("hx-mc", "G20 G90 G00 X10000 Y.5\n");
    ok(&r);
    assert_eq!(
        moves(&r),
        vec![("rapid", 25.4, 12.7, 250.0)],
        "Z stays at the reference: work Z 250"
    );
}

#[test]
fn hurco_reads_numbers_as_whole_units() {
    // 002 "N40 Z3 (rapid to Z)": Z3 is 3 units. G07 radius, G08 diameter.
    let r = run_on("hurco-lathe", "G21 G90 G07 G00 X2 Z3\nG08 X10\n");
    ok(&r);
    assert_eq!(
        moves(&r),
        vec![("rapid", 2.0, 0.0, 3.0), ("rapid", 5.0, 0.0, 3.0)]
    );
}

#[test]
fn puma_diameter_and_uw_incremental() {
    // X40 diameter = 20 radius; U-10 diameter = -5 radius; W-5 in Z.
    let r = run_on("puma-lathe", "G00 X40. Z2.\nG01 U-10. W-5. F0.2\n");
    ok(&r);
    assert_eq!(
        moves(&r),
        vec![("rapid", 20.0, 0.0, 2.0), ("feed", 15.0, 0.0, -3.0)]
    );
    // G99 (feed per revolution) is the power-on default.
    assert!(
        matches!(r.events.iter().find_map(|e| match e.cmd { Canon::Feed { feed, .. } => Some(feed), _ => None }), Some(Feed::PerRev(f)) if (f - 0.2).abs() < 1e-12)
    );
    // X and U together are an error.
    let r = run_on("puma-lathe", "G00 X40. U2.\n");
    assert_eq!(alarm(&r).0, "PS009");
}

#[test]
fn incremental_mode_on_the_mill() {
    let r = run_on("hx-mc", "G90 G00 X10. Y10. Z0\nG91 X5. Y-20.\nG90 X0\n");
    ok(&r);
    assert_eq!(
        moves(&r),
        vec![
            ("rapid", 10.0, 10.0, 0.0),
            ("rapid", 15.0, -10.0, 0.0),
            ("rapid", 0.0, -10.0, 0.0)
        ]
    );
}

#[test]
fn g92_makes_the_current_position_read_as_given() {
    let r = run_on("hx-mc", "G90 G00 X10. Y20. Z0\nG92 X0 Y0\nG00 X5.\n");
    ok(&r);
    let m = moves(&r);
    assert_eq!(m[1], ("rapid", 5.0, 0.0, 0.0));
    // The machine moved 5 mm further in X: G54 X zero is machine -400.
    let last = r.events.iter().rev().find_map(|e| e.motion()).unwrap();
    assert!((last.mto[0] - (-400.0 + 15.0)).abs() < 1e-9);
}

#[test]
fn puma_g50_sets_coordinates_in_diameter() {
    // After G50 X100. Z50. the tool is at diameter 100 (radius 50), Z 50;
    // G00 X50. moves it 25 mm towards the centre line.
    let r = run_on("puma-lathe", "G00 X80. Z10.\nG50 X100. Z50.\nG00 X50. Z0\n");
    ok(&r);
    let last = r.events.iter().rev().find_map(|e| e.motion()).unwrap();
    assert!((last.to[0] - 25.0).abs() < 1e-9 && last.to[2].abs() < 1e-9);
    // Machine: started X radius 40, now 40 - 25 = 15; Z from 10 to -40 in the part frame.
    assert!((last.mto[0] - 15.0).abs() < 1e-9);
    let z0 = Profile::builtin("puma-lathe").unwrap().work_offsets["g54"]["z"];
    assert!((last.mto[2] - (z0 + 10.0 - 50.0)).abs() < 1e-9);
}

#[test]
fn g53_moves_in_machine_coordinates() {
    let r = run_on("hx-mc", "G90 G53 G00 X-100. Y-50. Z-10.\n");
    ok(&r);
    let m = r.events[0].motion().unwrap();
    assert_eq!(m.mto[..3], [-100.0, -50.0, -10.0]);
    // Work = machine - G54 origin (-400, -250, -250).
    assert_eq!(m.to[..3], [300.0, 200.0, 240.0]);
}

#[test]
fn work_offsets_select_the_origin() {
    let mut p = Profile::builtin("hx-mc").unwrap();
    p.work_offsets
        .get_mut("g55")
        .unwrap()
        .insert("x".into(), -300.0);
    let r = run_text(p, Settings::default(), "t", "G55 G90 G00 X10. Y0 Z0\n");
    ok(&r);
    assert!((r.events[0].motion().unwrap().mto[0] - (-290.0)).abs() < 1e-9);
}

#[test]
fn arcs_by_centre_and_by_radius() {
    // Quarter circle from (10,0) to (0,10) about the origin, CCW.
    let r = run_on(
        "hx-mc",
        "G90 G00 X10. Y0\nG03 X0 Y10. I-10. F100.\nG02 X10. Y0 R-10.\n",
    );
    ok(&r);
    let arcs: Vec<_> = r
        .events
        .iter()
        .filter_map(|e| match &e.cmd {
            Canon::Arc { center, dir, .. } => Some((round(center[0]), round(center[1]), *dir)),
            _ => None,
        })
        .collect();
    // Second arc: CW from (0,10) to (10,0) with R-10 (> 180°): centre (10,10)
    // would be the minor arc's CCW side... worked out: chord midpoint (5,5),
    // minor CW centre on the right of the chord = (0,0); R<0 flips to (10,10).
    assert_eq!(
        arcs,
        vec![(0.0, 0.0, ArcDir::Ccw), (10.0, 10.0, ArcDir::Cw)]
    );
}

#[test]
fn full_circle_and_helix() {
    let r = run_on(
        "hx-mc",
        "G90 G00 X0 Y0 Z0\nG02 I10. F200.\nG17 G03 X-10. Y10. Z-5. I-10. J0\n",
    );
    ok(&r);
    let m = moves(&r);
    assert_eq!(m[1], ("arc", 0.0, 0.0, 0.0));
    assert_eq!(m[2], ("arc", -10.0, 10.0, -5.0));
}

#[test]
fn arc_errors_are_positioned() {
    // End point 0.5 mm off the circle.
    let r = run_on("hx-mc", "G90 G00 X10. Y0\nG03 X0 Y10.5 I-10. F100.\n");
    assert_eq!(alarm(&r), ("F_82112", 2, 14));
    // R smaller than half the 20 mm chord.
    let r = run_on("hx-mc", "G90 G00 X0 Y0\nG02 X20. R5. F100.\n");
    assert_eq!(alarm(&r), ("F_82100", 2, 10));
    // No centre at all.
    let r = run_on("hx-mc", "G90 G02 X20. F100.\n");
    assert_eq!(alarm(&r).0, "F_82102");
}

#[test]
fn cutting_without_feed_is_an_alarm() {
    let r = run_on("hx-mc", "G90 G00 X0\nN2 G01 X10.\n");
    assert_eq!(alarm(&r), ("F_84020", 2, 4));
    let r = run_on("puma-lathe", "G01 X10.\n");
    assert_eq!(alarm(&r).0, "PS011");
}

#[test]
fn unknown_codes_and_axes() {
    assert_eq!(alarm(&run_on("hx-mc", "G90\nG05 X1.\n")), ("F_82030", 2, 1));
    assert_eq!(alarm(&run_on("hx-mc", "M77\n")), ("F_82031", 1, 1));
    assert_eq!(alarm(&run_on("puma-lathe", "G00 Y10.\n")), ("PS009", 1, 5));
    assert_eq!(alarm(&run_on("hx-mc", "G00 X1. X2.\n")).0, "F_82006");
    assert_eq!(alarm(&run_on("hx-mc", "G00 X\n")), ("F_82004", 1, 5));
    assert_eq!(alarm(&run_on("hx-mc", "G00 (open\n")), ("F_82001", 1, 5));
    assert_eq!(alarm(&run_on("hx-mc", "G00 X1234567890123\n")).0, "F_82002");
}

#[test]
fn overtravel_is_caught_before_the_move() {
    // G54 X zero is machine -400 and X travel ends at 0: X500. is 100 mm beyond.
    let r = run_on("hx-mc", "G90 G00 X100.\nG00 X500.\n");
    assert_eq!(alarm(&r), ("F_84100", 2, 1));
    assert_eq!(moves(&r).len(), 1);
}

#[test]
fn hurco_range_tables() {
    // Inch geometric entries are limited to ±845.0000 (002 Table 2).
    let r = run_on("hurco-lathe", "G20 G00 X900.\n");
    assert_eq!(alarm(&r).0, "HU-014");
}

#[test]
fn block_delete_switches() {
    let text = "G90 G00 X0 Y0 Z0\n/G00 X10.\n/2 G00 Y10.\nG00 X1. /3 Y5.\n";
    let r = run_on("hx-mc", text);
    ok(&r);
    assert_eq!(
        moves(&r),
        vec![
            ("rapid", 0.0, 0.0, 0.0),
            ("rapid", 10.0, 0.0, 0.0),
            ("rapid", 10.0, 10.0, 0.0),
            ("rapid", 1.0, 5.0, 0.0)
        ]
    );
    let s = Settings {
        block_skip: (1 << 1) | (1 << 3),
        ..Settings::default()
    };
    let r = run_with("hx-mc", s, text);
    ok(&r);
    assert_eq!(
        moves(&r),
        vec![
            ("rapid", 0.0, 0.0, 0.0),
            ("rapid", 0.0, 10.0, 0.0),
            ("rapid", 1.0, 10.0, 0.0)
        ]
    );
}

#[test]
fn optional_stop_and_end() {
    let text = "M01\nM00\nM30\nG00 X10.\n";
    let stops = |r: &Run| {
        r.events
            .iter()
            .filter(|e| matches!(e.cmd, Canon::Stop { .. }))
            .count()
    };
    let r = run_on("hx-mc", text);
    ok(&r);
    assert_eq!(stops(&r), 1);
    assert!(moves(&r).is_empty(), "nothing runs after M30");
    assert!(matches!(
        r.events.last().unwrap().cmd,
        Canon::End { code: 30 }
    ));
    let r = run_with(
        "hx-mc",
        Settings {
            optional_stop: true,
            ..Settings::default()
        },
        text,
    );
    assert_eq!(stops(&r), 2);
}

#[test]
fn dwell_units_per_control() {
    let secs = |r: &Run| -> Vec<(f64, f64)> {
        r.events
            .iter()
            .filter_map(|e| match e.cmd {
                Canon::Dwell {
                    seconds,
                    revolutions,
                } => Some((round(seconds), round(revolutions))),
                _ => None,
            })
            .collect()
    };
    // HX: X in 0.001 s without a point, seconds with one; P in ms.
    let r = run_on("hx-mc", "G04 X10000\nG04 X1.5\nG04 P2500\n");
    ok(&r);
    assert_eq!(secs(&r), vec![(10.0, 0.0), (1.5, 0.0), (2.5, 0.0)]);
    // PUMA: U like X.
    let r = run_on("puma-lathe", "G04 U0.5\n");
    assert_eq!(secs(&r), vec![(0.5, 0.0)]);
    // Hurco: F seconds in G94, revolutions in G95 (002 G04).
    let r = run_on("hurco-lathe", "G94 G04 F2\nG95 G04 F3\n");
    ok(&r);
    assert_eq!(secs(&r), vec![(2.0, 0.0), (0.0, 3.0)]);
}

fn kinds(evs: &[Event]) -> Vec<&'static str> {
    evs.iter()
        .map(|e| match e.cmd {
            Canon::Rapid { .. } => "rapid",
            Canon::Feed { .. } => "feed",
            Canon::Spindle {
                dir: SpindleDir::Stop,
                ..
            } => "spindle-stop",
            Canon::Spindle { .. } => "spindle",
            Canon::Coolant { .. } => "coolant",
            Canon::Tool { .. } => "tool",
            Canon::End { .. } => "end",
            _ => "other",
        })
        .collect()
}

#[test]
fn hurco_block_order_follows_table_1() {
    // Written in a scrambled order; executed as 002 Table 1 says:
    // M07/M08, T, M03/M04, S, motion, M05, M30.
    let r = run_on("hurco-lathe", "M30 M05 X1 G00 S500 M03 T0202 M08\n");
    ok(&r);
    assert_eq!(
        kinds(&r.events),
        vec!["coolant", "tool", "spindle", "rapid", "spindle-stop", "end"]
    );
}

#[test]
fn fanuc_block_order() {
    // Fanuc: T, S with M03, M08 before motion; M05 and M09 after, end last.
    let r = run_on("hx-mc", "G00 X1. M08 S1000 M03\nM05 M09 M30\n");
    ok(&r);
    assert_eq!(
        kinds(&r.events),
        vec![
            "spindle",
            "coolant",
            "rapid",
            "spindle-stop",
            "coolant",
            "end"
        ]
    );
}

#[test]
fn macro_values_in_words_and_vacant_words() {
    // #1 = 10; X#1 is 10 mm (expressions are not in increments); X#2 is vacant and omitted.
    let r = run_on("hx-mc", "#1=10\nG90 G00 X#1 Y[#1*2+1] Z0\nG00 X#2 Y0\n");
    ok(&r);
    assert_eq!(
        moves(&r),
        vec![("rapid", 10.0, 21.0, 0.0), ("rapid", 10.0, 0.0, 0.0)]
    );
}

#[test]
fn while_loop_and_goto() {
    let text = "G90 G00 X0 Y0 Z0\n#1=0\nWHILE[#1LT3]DO1\nG91 G00 X1.\n#1=#1+1\nEND1\nIF[#1EQ3]GOTO 9\nG00 Y100.\nN9 G00 Y1.\n";
    let r = run_on("hx-mc", text);
    ok(&r);
    assert_eq!(
        moves(&r),
        vec![
            ("rapid", 0.0, 0.0, 0.0),
            ("rapid", 1.0, 0.0, 0.0),
            ("rapid", 2.0, 0.0, 0.0),
            ("rapid", 3.0, 0.0, 0.0),
            ("rapid", 3.0, 1.0, 0.0)
        ]
    );
    let r = run_on("hx-mc", "GOTO 77\n");
    assert_eq!(alarm(&r).0, "F_82021");
    let r = run_on("hx-mc", "END1\n");
    assert_eq!(alarm(&r).0, "F_82202");
}

#[test]
fn hurco_loop_command_repeats() {
    let r = run_on(
        "hurco-lathe",
        "G90 G07 G00 X0 Z0\n(LOOP 3)\nG91 G00 Z-1\n(END LOOP)\nG90\n",
    );
    ok(&r);
    assert_eq!(moves(&r).len(), 4);
    assert_eq!(moves(&r)[3], ("rapid", 0.0, 0.0, -3.0));
}

#[test]
fn reference_return_via_intermediate_point() {
    // G91 G28 Z0: intermediate = here, then Z to the reference (machine 0).
    let r = run_on(
        "hx-mc",
        "G90 G00 X10. Y10. Z10.\nG91 G28 Z0\nG90 G28 X20. Y20.\n",
    );
    ok(&r);
    let m: Vec<_> = r
        .events
        .iter()
        .filter_map(|e| e.motion())
        .map(|m| (round(m.mto[0]), round(m.mto[1]), round(m.mto[2])))
        .collect();
    assert_eq!(
        m,
        vec![
            (-390.0, -240.0, -240.0),
            (-390.0, -240.0, 0.0),
            (-380.0, -230.0, 0.0),
            (0.0, 0.0, 0.0)
        ]
    );
}

#[test]
fn tool_length_offset_shifts_the_control_point() {
    let p = Profile::builtin("hx-mc").unwrap();
    let mut it = kerf_interp::Interp::new(p, Settings::default());
    it.set_h(1, 50.0);
    it.load_main(
        "t",
        Box::new(std::io::Cursor::new(
            b"G90 G43 H1 G00 Z60.\nG49 Z60.\n".to_vec(),
        )),
    );
    let mut z = Vec::new();
    while let kerf_interp::Step::Event(e) = it.step() {
        if let Some(m) = e.motion() {
            z.push((round(m.to[2]), round(m.mto[2])));
        }
    }
    // G43 H1 (50 mm): the tip is at Z60 (`to`, what the ABSOLUTE page
    // shows, 000 §13.1.1) so the gauge line is 50 above it in machine
    // coordinates; after G49 the gauge line itself goes to Z60.
    assert_eq!(z, vec![(60.0, -140.0), (60.0, -190.0)]);
}

#[test]
fn endless_loops_end_in_an_alarm() {
    // An endless WHILE: stopped by the repeat budget, positioned at a block.
    let r = run_with_param(
        "hx-mc",
        "max_repeat_blocks",
        1000.0,
        "G90 G00 X0 Y0 Z0\nWHILE[1]DO1\nG91 G00 X0\nG00 Y0\nEND1\n",
    );
    let a = r.alarm.expect("loop guard");
    assert_eq!(a.code, "KERF-0101");
    assert!(a.src.line >= 2 && a.src.line <= 5);
    // A GOTO back to itself as well.
    let r = run_with_param("hx-mc", "max_jumps", 50.0, "N1 GOTO 1\n");
    assert_eq!(r.alarm.expect("loop guard").code, "KERF-0101");
}

#[test]
fn goto_searches_forward_first_then_from_the_start() {
    // Two blocks carry N5. From line 5 the forward search finds line 7
    // first (Fanuc searches ahead, then wraps), so the loop never repeats.
    let text = "G90 G00 X0 Y0 Z0\n#1=0\nN5 #1=#1+1\nIF[#1 GE 3] GOTO 9\nGOTO 5\nN9 G00 X1.\nN5 G00 X2.\nM30\n";
    let r = run_on("hx-mc", text);
    ok(&r);
    assert_eq!(
        moves(&r),
        vec![("rapid", 0.0, 0.0, 0.0), ("rapid", 2.0, 0.0, 0.0)]
    );
    // With a single N5 the search wraps to the start: three passes, then N9.
    let text = "G90 G00 X0 Y0 Z0\n#1=0\nN5 #1=#1+1\nIF[#1 GE 3] GOTO 9\nG91 G00 X1.\nG90\nGOTO 5\nN9 G00 Y1.\nM30\n";
    let r = run_on("hx-mc", text);
    ok(&r);
    assert_eq!(
        moves(&r),
        vec![
            ("rapid", 0.0, 0.0, 0.0),
            ("rapid", 1.0, 0.0, 0.0),
            ("rapid", 2.0, 0.0, 0.0),
            ("rapid", 2.0, 1.0, 0.0)
        ]
    );
}

#[test]
fn goto_loops_end_quickly_in_the_loop_guard() {
    // fuzz/regressions/interp-goto-loop-2blocks.nc with a small jump budget.
    let r = run_with_param(
        "hx-mc",
        "max_jumps",
        10_000.0,
        "%\nO1\n#1=0\nN20 #3=1\nIF [#1 EQ 0] GOTO 20\nM30\n",
    );
    let a = r.alarm.expect("loop guard");
    assert_eq!((a.code.as_str(), a.src.line), ("KERF-0101", 5));
}

#[test]
fn remaining_alarm_kinds_are_positioned() {
    // Expression missing its right operand: the ']' at column 9.
    assert_eq!(alarm(&run_on("hx-mc", "G00 X[1+]\n")), ("F_82005", 1, 9));
    // Cutter compensation (issue 5) now runs: G41 with D1 = 0 ends at
    // the programmed point (tests/cutter_comp.rs has the geometry).
    let r = run_on("hx-mc", "G90 G00 X0 Y0 Z0\nG41 D1 X1.\n");
    assert!(r.alarm.is_none(), "{:?}", r.alarm);
    // G29 with no G28/G30 intermediate point stored.
    assert_eq!(alarm(&run_on("hx-mc", "G90 G29 X10.\n")), ("F_82008", 1, 5));
    // Hurco G04 needs F (seconds or revolutions).
    assert_eq!(alarm(&run_on("hurco-lathe", "G04\n")).0, "HU-015");
    // Division by zero in a statement.
    assert_eq!(
        alarm(&run_on("hx-mc", "#1=0\n#2=1/#1\n")),
        ("F_82201", 2, 1)
    );
    assert_eq!(alarm(&run_on("puma-lathe", "#1=1/0\n")).0, "PS112");
}

#[test]
fn g27_checks_the_reference_position() {
    // G54 zero is machine (-400, -250, -250): work (400, 250, 250) is the
    // reference position (machine 0), so this check passes.
    ok(&run_on("hx-mc", "G90 G27 X400. Y250. Z250.\n"));
    // X10. is machine -390, not the reference: alarm after the move.
    let r = run_on("hx-mc", "G90 G00 X0 Y0 Z0\nG27 X10.\n");
    assert_eq!(alarm(&r), ("F_82209", 2, 1));
    assert_eq!(moves(&r).last().unwrap(), &("rapid", 10.0, 0.0, 0.0));
}
