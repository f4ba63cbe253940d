//! Hurco program structure (002 "Off-line Part Program Formats", Tables
//! 1-3, "Block Delete Code", loop commands) and the one-block codes G04,
//! G33, G53, G92 S, G96 R. Expected values by hand from 002.
mod common;
use common::*;
use kerf_canon::{Canon, Feed, ModeChange, SpindleDir};
use kerf_interp::{Run, Settings};

/// A short name for each event, in order.
fn trace(r: &Run) -> Vec<String> {
    r.events
        .iter()
        .map(|e| match &e.cmd {
            Canon::Rapid { m, .. } => format!("rapid {} {}", round(m.to[0]), round(m.to[2])),
            Canon::Feed { m, .. } => format!("feed {} {}", round(m.to[0]), round(m.to[2])),
            Canon::Thread { m, lead } => {
                format!(
                    "thread {} {} {}",
                    round(m.to[0]),
                    round(m.to[2]),
                    round(*lead)
                )
            }
            Canon::Aux { m, .. } => format!("M{m}"),
            Canon::Coolant { mist, flood } => format!("coolant {mist} {flood}"),
            Canon::Tool { tool, offset, .. } => format!("T{tool}/{offset}"),
            Canon::Spindle { dir, rpm, .. } => format!("spindle {dir:?} {}", round(*rpm)),
            Canon::Dwell {
                seconds,
                revolutions,
            } => format!("dwell {seconds} {revolutions}"),
            Canon::Mode(ModeChange::ExactStopBlock) => "G09".into(),
            Canon::Mode(m) => format!("{m:?}"),
            Canon::Stop { optional } => format!("stop {optional}"),
            Canon::Message(m) => format!("msg {m}"),
            Canon::End { code } => format!("end {code}"),
            Canon::Arc { .. } => "arc".into(),
        })
        .collect()
}

#[test]
fn table_1_order_in_one_block() {
    // Written in reverse order; executed as Table 1: job-sync M101,
    // (specific G codes: G90, G97, G01 modal), M48, M08, T0202, M03 + S500
    // (one spindle event), F, the motion, G09, M05, M00.
    let r = run_on(
        "hurco-lathe",
        "G21 G07\nN5 M00 M05 G09 G01 X10 F100 S500 M03 T0200 M08 M48 M101 G97 G90\nM30\n",
    );
    ok(&r);
    assert_eq!(
        trace(&r),
        vec![
            "M101",
            "M48",
            // For the planner: M48 uses the feed override (M49 ignores it).
            "FeedOverride(true)",
            "coolant false true",
            "T2/0",
            "spindle Cw 500",
            "feed 10 400",
            "G09",
            "spindle Stop 0",
            "stop false",
            "end 30"
        ]
    );
    // A dwell block: M08 first, then M03/S, then G04 F (seconds in G94).
    let r = run_on("hurco-lathe", "G04 F2 S300 M03 M08\nM30\n");
    ok(&r);
    assert_eq!(
        trace(&r),
        vec![
            "coolant false true",
            "spindle Cw 300",
            "dwell 2 0",
            "spindle Stop 0",
            "end 30"
        ]
    );
}

#[test]
fn block_delete_levels() {
    // 002: "/0N7 X3.0" skipped with level 0, "/1N7" with level 1, "/8/9N7"
    // with level 8 or 9. X3.0 is a diameter: radius 1.5 mm.
    let text = "G21\n/0N7 X3.0\n/1N7 X4.0\n/8/9N7 X5.0\nN8 X6.0 /2 Z-5\nM30\n";
    let xs = |levels: &[u16]| -> Vec<String> {
        let mut s = Settings::default();
        for l in levels {
            s.block_skip |= 1 << l;
        }
        trace(&run_with("hurco-lathe", s, text))
            .into_iter()
            .filter(|t| t.starts_with("rapid"))
            .collect()
    };
    // Nothing on: every block; the Z after "/2" too.
    assert_eq!(
        xs(&[]),
        vec![
            "rapid 1.5 400",
            "rapid 2 400",
            "rapid 2.5 400",
            "rapid 3 -5"
        ]
    );
    assert_eq!(xs(&[0]), vec!["rapid 2 400", "rapid 2.5 400", "rapid 3 -5"]);
    assert_eq!(
        xs(&[1]),
        vec!["rapid 1.5 400", "rapid 2.5 400", "rapid 3 -5"]
    );
    assert_eq!(xs(&[9]), vec!["rapid 1.5 400", "rapid 2 400", "rapid 3 -5"]);
    assert_eq!(xs(&[8]), vec!["rapid 1.5 400", "rapid 2 400", "rapid 3 -5"]);
    // Level 2: the rest of block N8 from "/2" is skipped (Table 1: block
    // delete codes act where they appear).
    assert_eq!(
        xs(&[2]),
        vec![
            "rapid 1.5 400",
            "rapid 2 400",
            "rapid 2.5 400",
            "rapid 3 400"
        ]
    );
}

#[test]
fn m200_and_unknown_codes() {
    let r = run_on("hurco-lathe", "M200\nM30\n");
    ok(&r);
    assert_eq!(trace(&r), vec!["M200", "end 30"]);
    // 002 "Unused Data": any unrecognised code stops.
    let r = run_on("hurco-lathe", "G0 X1\nM201\n");
    assert_eq!(alarm(&r), ("HU-011", 2, 1));
    let r = run_on("hurco-lathe", "G0 X1\nG85 Z1\n");
    assert_eq!(alarm(&r), ("HU-010", 2, 1));
    let r = run_on("hurco-lathe", "G0 X1 Y2\n");
    assert_eq!(alarm(&r), ("HU-001", 1, 7));
    // Letters only G78/G38 use, in another block.
    let r = run_on("hurco-lathe", "G01 X1 D2 F1\n");
    assert_eq!(alarm(&r), ("HU-001", 1, 8));
}

#[test]
fn stops_turn_the_spindle_off_and_m01_once() {
    // 002: M00 and M30 turn the spindle off; M01 "On (turn off)" acts once.
    let st = Settings {
        optional_stop: true,
        optional_stop_once: true,
        ..Settings::default()
    };
    let r = run_with("hurco-lathe", st, "M03 S100\nM01\nM03\nM01\nM00\nM30\n");
    ok(&r);
    assert_eq!(
        trace(&r),
        vec![
            "spindle Cw 100",
            "spindle Stop 0",
            "stop true",
            "spindle Cw 100",
            // The second M01 is ignored: the switch turned itself off.
            "spindle Stop 0",
            "stop false",
            "end 30"
        ]
    );
    // G04 takes only F.
    let r = run_on("hurco-lathe", "G04 F1 X2\n");
    assert_eq!(alarm(&r), ("HU-001", 1, 8));
}

#[test]
fn ten_codes_per_block_and_continuation() {
    // 002: 0 to 10 G codes and 0 to 10 M codes per block.
    let r = run_on(
        "hurco-lathe",
        "G90 G40 G94 G97 G98 G80 G21 G08 G01 G09 X10 F100\nM100 M101 M102 M103 M104 M105 M106 M107 M108 M109\nM30\n",
    );
    ok(&r);
    let r = run_on(
        "hurco-lathe",
        "G90 G40 G94 G97 G98 G80 G21 G08 G01 G09 G90 X10\n",
    );
    // The 11th G code: column 4 * 10 + 1.
    assert_eq!(alarm(&r), ("HU-014", 1, 41));
    let r = run_on(
        "hurco-lathe",
        "M100 M101 M102 M103 M104 M105 M106 M107 M108 M109 M110\n",
    );
    // The 11th M code: column 5 * 10 + 1.
    assert_eq!(alarm(&r), ("HU-016", 1, 51));
    // A \ at the end of a line continues the block: one feed to (5, -5).
    let r = run_on("hurco-lathe", "G21 G07 G01 X5 \\\nZ-5 F100\nM30\n");
    ok(&r);
    assert_eq!(moves(&r), vec![("feed", 5.0, 0.0, -5.0)]);
}

#[test]
fn loops_repeat_a_section() {
    // (LOOP 3) ... (END LOOP) around an incremental move: 3 x -1 mm;
    // nested (REPEAT 2) inside: 3 x 2 = 6 feeds of -0.5.
    let r = run_on(
        "hurco-lathe",
        "G21 G91 G01 F100\n(LOOP 3)\nZ-1\n(REPEAT 2 TIMES)\nZ-.5\n(END REPEAT)\n(END LOOP)\nM30\n",
    );
    ok(&r);
    let z: Vec<String> = trace(&r)
        .into_iter()
        .filter(|t| t.starts_with("feed"))
        .collect();
    // Start Z 400 (machine 0, part zero at -400).
    let mut want = Vec::new();
    let mut zc = 400.0;
    for _ in 0..3 {
        zc -= 1.0;
        want.push(format!("feed 250 {zc}"));
        for _ in 0..2 {
            zc -= 0.5;
            want.push(format!("feed 250 {zc}"));
        }
    }
    assert_eq!(z, want);
    // Loop end without a start; a count of 0.
    let r = run_on("hurco-lathe", "(END LOOP)\n");
    assert_eq!(alarm(&r).0, "HU-043");
    let r = run_on("hurco-lathe", "(LOOP 0)\n(END LOOP)\n");
    assert_eq!(alarm(&r).0, "HU-014");
}

#[test]
fn number_formats_tables_2_and_3() {
    // Geometric words: ±845.0000 in, ±21463.000 mm; E 0-9999; dwell F
    // 0.0001-999.9999; G33 lead K 0.000001-10 in.
    let cases: &[(&str, &str)] = &[
        ("G20 G01 X845.1 F1", "X845.1"),
        ("G21 G01 Z-21463.5 F1", "Z-21463.5"),
        ("G20 G01 X1 F845.5", "F845.5"),
        ("E10000", "E10000"),
        ("G04 F1000", "F1000"),
        ("G20 M03 S100\nG33 Z-1 K10.5", "K10.5"),
    ];
    for (text, at) in cases {
        let r = run_on("hurco-lathe", &format!("{text}\n"));
        let last = text.lines().last().unwrap();
        let line = text.lines().count() as u32;
        let col = last.find(at).unwrap() as u32 + 1;
        assert_eq!(alarm(&r), ("HU-014", line, col), "{text}");
    }
    // The optional formats (one place smaller): X84.6 in is out, 84.5 in.
    let r = run_with_param("hurco-lathe", "optional_format", 1.0, "G20 G01 X84.6 F1\n");
    assert_eq!(alarm(&r), ("HU-014", 1, 9));
    let r = run_with_param(
        "hurco-lathe",
        "optional_format",
        1.0,
        "G20 G07 G01 X8.45 F1\nM30\n",
    );
    ok(&r);
    // In range: X845 inch; T 9 digits (tool 0 offset 0 is fine: T000000000).
    let r = run_on("hurco-lathe", "G20 G07 G53 X0\nT000000000\nM30\n");
    ok(&r);
}

#[test]
fn g33_lead_and_longest_axis() {
    // 002: G0 X3.5 Z4 / G33 Z1 K.2 P180 / G1 X3.6 (inch, G07 radius here
    // to stay in travel). Lead K .2 in = 5.08 mm along Z, start angle
    // message 180. A taper whose X move is longer needs I.
    let r = run_on(
        "hurco-lathe",
        "G20 G07 M03 S100\nG0 X3.5 Z4\nG33 Z1 K.2 P180\nG1 X3.6 F1\nM30\n",
    );
    ok(&r);
    let t = trace(&r);
    assert!(
        t.contains(&"msg thread start angle 180".to_string()),
        "{t:?}"
    );
    assert!(t.contains(&format!(
        "thread {} {} 5.08",
        round(3.5 * 25.4),
        round(25.4)
    )));
    // X moves 2, Z moves 1: the lead must be I (X).
    let r = run_on("hurco-lathe", "G20 G07 M03 S100\nG0 X3 Z4\nG33 X1 Z3 K.2\n");
    assert_eq!(alarm(&r), ("HU-060", 3, 11));
    let r = run_on(
        "hurco-lathe",
        "G20 G07 M03 S100\nG0 X3 Z4\nG33 X1 Z3 I.2\nM30\n",
    );
    ok(&r);
    // P outside -360..360.
    let r = run_on(
        "hurco-lathe",
        "G20 G07 M03 S100\nG0 X3 Z4\nG33 Z1 K.2 P400\n",
    );
    assert_eq!(alarm(&r), ("HU-014", 3, 12));
    // No lead at all.
    let r = run_on("hurco-lathe", "G20 G07 M03 S100\nG0 X3 Z4\nG33 Z1\n");
    assert_eq!(alarm(&r), ("HU-015", 3, 1));
}

#[test]
fn g53_preconditions() {
    // G53 ignores G92, tool and fixture offsets: machine coordinates.
    let r = run_on("hurco-lathe", "G21 G07 G53 X100 Z-50\nM30\n");
    ok(&r);
    let m = r.events[0].motion().unwrap();
    assert_eq!((m.mto[0], m.mto[2]), (100.0, -50.0));
    // In G91, in G02 mode, with CRC on (G41 is issue 5's, so only G91/G02).
    let r = run_on("hurco-lathe", "G91\nG53 X100\n");
    assert_eq!(alarm(&r), ("HU-062", 2, 1));
    let r = run_on("hurco-lathe", "G0 X0 Z0\nG02 X10 Z-5 R5 F100\nG53 X100\n");
    assert_eq!(alarm(&r), ("HU-062", 3, 1));
}

#[test]
fn g96_r_and_g92_s() {
    // G96 S100 (m/min) R20 in G08: R is a diameter (Table 14): radius 10
    // mm: rpm = 100000 / (2 pi 10) = 1591.549; G92 S1000 clamps it to 1000.
    let r = run_on(
        "hurco-lathe",
        "G21 G96 R20 S100 M03\nG92 S1000\nG0 X50\nM30\n",
    );
    ok(&r);
    let rpms: Vec<f64> = r
        .events
        .iter()
        .filter_map(|e| match e.cmd {
            Canon::Spindle {
                dir: SpindleDir::Cw,
                rpm,
                ..
            } => Some(rpm),
            _ => None,
        })
        .collect();
    assert!((rpms[0] - 100_000.0 / (std::f64::consts::TAU * 10.0)).abs() < 1e-6);
    assert_eq!(rpms[1..], [1000.0]);
    // The clamp is in the canonical stream for the planner's CSS feeds.
    assert!(r
        .events
        .iter()
        .any(|e| e.cmd == Canon::Mode(ModeChange::SpindleClamp(1000.0))));
    // G07: R is a radius: R10 is the same speed.
    let r = run_on("hurco-lathe", "G21 G07 G96 R10 S100 M03\nM30\n");
    let rpm = r
        .events
        .iter()
        .find_map(|e| match e.cmd {
            Canon::Spindle { rpm, .. } => Some(rpm),
            _ => None,
        })
        .unwrap();
    assert!((rpm - 1591.549430919).abs() < 1e-6);
}

#[test]
fn g04_revolutions_in_g95_and_inverse_time_feed() {
    // G95: F in a G04 block is revolutions (002 "G04 F10" = 10 revs).
    let r = run_on("hurco-lathe", "G95\nG04 F10\nG93 G01 X10 F.25\nM30\n");
    ok(&r);
    let t = trace(&r);
    assert_eq!(t[0], "dwell 0 10");
    // G93 F.25 = a 4-minute cut (002 Example 1).
    let f = r.events.iter().find_map(|e| match e.cmd {
        Canon::Feed { feed, .. } => Some(feed),
        _ => None,
    });
    assert_eq!(f, Some(Feed::InverseTime(0.25)));
}
