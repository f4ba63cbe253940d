//! Subprograms (M98/M99, 000 §2.4), simple macro calls (G65, 000 §14.1.1),
//! the program store (O numbers in the file, `--lib` folders) and the
//! `#3000`/`#3006` system variables. Every expected position is worked out
//! by hand from the manuals, never taken from kerf's output.

use std::path::PathBuf;

use kerf_canon::{Canon, Event};
use kerf_interp::{Interp, Profile, Run, Settings, Step};

mod common;
use common::{ok, round, run_on, run_with_param};

/// Work-coordinate end points of the motions: (kind, line, x, y, z).
fn moves(r: &Run) -> Vec<(&'static str, u32, f64, f64, f64)> {
    moves_of(&r.events)
}

fn moves_of(ev: &[Event]) -> Vec<(&'static str, u32, f64, f64, f64)> {
    ev.iter()
        .filter_map(|e| {
            let k = match e.cmd {
                Canon::Rapid { .. } => "rapid",
                Canon::Feed { .. } => "feed",
                Canon::Arc { .. } => "arc",
                _ => return None,
            };
            let m = e.motion().unwrap();
            Some((
                k,
                e.src.line,
                round(m.to[0]),
                round(m.to[1]),
                round(m.to[2]),
            ))
        })
        .collect()
}

fn alarm(r: &Run) -> (&str, u32) {
    let a = r.alarm.as_ref().expect("an alarm");
    (a.code.as_str(), a.src.line)
}

/// 000 §2.4.3: the main program calls O0010 from N1 to N2 twice
/// (`M98 P10 Q1 R2 L2`), then the whole of O0010 once (`M98 P10`).
const MAIN_SUB_2_4_3: &str = "\
O0001
G54 G00 X0. Y0. Z0.
X20. Y40.
M98 P10 Q1 R2 L2
X70. Y20.
M98 P10
G91 G28 X0. Y0. M05
M30

O0010
N1 G90 G00 Z5.
G01 Z-10. F20.
Z-25. F100
N2 G00 Z50.
M99
";

#[test]
fn main_and_subprogram_of_2_4_3() {
    let r = run_on("hx-mc", MAIN_SUB_2_4_3);
    ok(&r);
    let sub = |x: f64, y: f64| {
        vec![
            ("rapid", 11, x, y, 5.0),
            ("feed", 12, x, y, -10.0),
            ("feed", 13, x, y, -25.0),
            ("rapid", 14, x, y, 50.0),
        ]
    };
    let mut want = vec![("rapid", 2, 0.0, 0.0, 0.0), ("rapid", 3, 20.0, 40.0, 0.0)];
    want.extend(sub(20.0, 40.0)); // L2: N1..N2 twice
    want.extend(sub(20.0, 40.0));
    want.push(("rapid", 5, 70.0, 20.0, 50.0));
    want.extend(sub(70.0, 20.0)); // M98 P10: the whole program, to M99
                                  // G91 G28 X0 Y0: the intermediate point is here; machine X0 Y0 is
                                  // work X400 Y250 (G54 = -400, -250).
    want.push(("rapid", 7, 400.0, 250.0, 50.0));
    assert_eq!(moves(&r), want);
    // Feeds: F20 then F100 (F without a decimal point is mm/min).
    let feeds: Vec<f64> = r
        .events
        .iter()
        .filter_map(|e| match e.cmd {
            Canon::Feed { feed, .. } => Some(match feed {
                kerf_canon::Feed::PerMin(f) => f,
                _ => -1.0,
            }),
            _ => None,
        })
        .collect();
    assert_eq!(feeds, vec![20.0, 100.0, 20.0, 100.0, 20.0, 100.0]);
    assert!(matches!(
        r.events.last().unwrap().cmd,
        Canon::End { code: 30 }
    ));
}

/// 000 §2.4.4: `M99 P1 L3` runs the main program from N1 three times in
/// all (kerf's reading, docs/dialects.md), then M30.
#[test]
fn main_program_repeat_of_2_4_4() {
    let text = "\
G54 G00 X0. Y0. Z0.
N1 G91 G01 Z5. F500.
X100.
Y100.
X-100.
Y-100.
M99 P1 L3
M30
";
    let r = run_on("hx-mc", text);
    ok(&r);
    let mut want = vec![("rapid", 1, 0.0, 0.0, 0.0)];
    for k in 1..=3 {
        let z = 5.0 * k as f64;
        want.push(("feed", 2, 0.0, 0.0, z));
        want.push(("feed", 3, 100.0, 0.0, z));
        want.push(("feed", 4, 100.0, 100.0, z));
        want.push(("feed", 5, 0.0, 100.0, z));
        want.push(("feed", 6, 0.0, 0.0, z));
    }
    assert_eq!(moves(&r), want);
    assert!(matches!(
        r.events.last().unwrap().cmd,
        Canon::End { code: 30 }
    ));
}

/// Plain M99 at the end of a main program (a bar-feed loop) restarts it
/// until the operator resets the control. kerf runs one pass by default
/// and ends (status 0) with a note; `main_passes` runs N (here 3: 3 × 2
/// moves); a count beyond the loop guard still stops with KERF-0101
/// instead of hanging.
#[test]
fn main_m99_runs_its_passes() {
    let text = "%\nG54 G91 G00 X-1.\nX1.\nM99\n%\n";
    let r = run_on("hx-mc", text);
    ok(&r);
    assert_eq!(moves(&r).len(), 2);
    assert!(r.events.iter().any(|e| matches!(&e.cmd,
        Canon::Message(m) if m.starts_with("M99 in the main program: ended after 1 pass "))));
    assert!(matches!(
        r.events.last().unwrap().cmd,
        Canon::End { code: 99 }
    ));
    let with = |passes: u32, key: &str, v: f64, text: &str| {
        let mut p = Profile::builtin(if key == "max_jumps" {
            "hx-mc"
        } else {
            "puma-lathe"
        })
        .unwrap();
        p.params.insert(key.into(), v);
        let s = Settings {
            main_passes: passes,
            ..Settings::default()
        };
        kerf_interp::run_text(p, s, "t.nc", text)
    };
    let r = with(3, "max_jumps", 500.0, text);
    ok(&r);
    assert_eq!(moves(&r).len(), 6);
    let r = with(1_000_000, "max_jumps", 500.0, text);
    assert_eq!(alarm(&r), ("KERF-0101", 4));
    assert_eq!(moves(&r).len(), 2 * 501);
    // With the default guard too (max_repeat_blocks), on a tiny budget.
    let r = with(
        1_000_000,
        "max_repeat_blocks",
        300.0,
        "G00 W-1.\nW1.\nM99\n",
    );
    assert_eq!(alarm(&r).0, "KERF-0101");
}

/// The G65 example of 000 §14.1.1: `G65 A1.0 B2.0 I3.0 I4.0 D5.0 P1000`
/// gives #1 = 1, #2 = 2, #4 = 3 (I1), #7 = 5 (D, written after I4.0 = I2
/// which also names #7), #3, #5, #6 vacant.
#[test]
fn g65_argument_binding_of_14_1_1() {
    let text = "\
G54 G90 G00 X0. Y0. Z0.
#1 = 7.
G65 A1.0 B2.0 I3.0 I4.0 D5.0 P1000
G00 X#1 Y0.
M30
O1000
G00 X#1 Y#2
G00 X#4 Y#7
IF [#3 EQ #0] THEN #100 = 1.
IF [#5 EQ #0] THEN #101 = 1.
IF [#6 EQ #0] THEN #102 = 1.
G00 X#100 Y#101 Z-#102
M99
";
    let r = run_on("hx-mc", text);
    ok(&r);
    assert_eq!(
        moves(&r),
        vec![
            ("rapid", 1, 0.0, 0.0, 0.0),
            ("rapid", 7, 1.0, 2.0, 0.0),
            ("rapid", 8, 3.0, 5.0, 0.0),
            ("rapid", 12, 1.0, 1.0, -1.0),
            // Back at level 0: the caller's #1 = 7 is restored.
            ("rapid", 4, 7.0, 0.0, -1.0),
        ]
    );
}

/// Argument specification II: A B C, then sets of I J K → #4-#33; a
/// repeated letter starts the next set. Arguments without a decimal point
/// follow the least input increment of their address (X10 = 0.010).
#[test]
fn g65_argument_specification_ii_and_increments() {
    let text = "\
G54 G90 G00 X0. Y0. Z0.
G65 P2000 I1. J2. K3. I4. K6. J8. Z-2. X10 L1
M30
O2000
G00 X#4 Y#5 Z#6
G00 X#7 Y#9 Z#26
G00 X#11 Y#8 Z#0
G00 X#24
M99
";
    let r = run_on("hx-mc", text);
    ok(&r);
    // Sets: (I1 J2 K3) (I4 _ K6) (_ J8 _): #4..#6 = 1 2 3, #7 = 4, #8 vacant,
    // #9 = 6, #11 = 8. Z-2. → #26 = -2; X10 → #24 = 0.010.
    assert_eq!(
        moves(&r),
        vec![
            ("rapid", 1, 0.0, 0.0, 0.0),
            ("rapid", 5, 1.0, 2.0, 3.0),
            ("rapid", 6, 4.0, 6.0, -2.0),
            // Y#8 vacant and Z#0: omitted.
            ("rapid", 7, 8.0, 6.0, -2.0),
            ("rapid", 8, 0.01, 6.0, -2.0),
        ]
    );
}

/// M98 subprograms share the caller's locals; G65 L repeats the macro.
#[test]
fn m98_shares_locals_and_g65_repeats() {
    let text = "\
G54 G90 G00 X0. Y0. Z0.
#1 = 1.
M98 P3
G00 X#1
G65 P4 L3 A2.
G00 Y#1
M30
O3
#1 = 9.
M99
O4
#102 = #102 + #1
G91 G00 Z-#102
G90
M99
";
    let r = run_on("hx-mc", text);
    ok(&r);
    assert_eq!(
        moves(&r),
        vec![
            ("rapid", 1, 0.0, 0.0, 0.0),
            ("rapid", 4, 9.0, 0.0, 0.0),
            ("rapid", 13, 9.0, 0.0, -2.0),
            ("rapid", 13, 9.0, 0.0, -6.0),
            ("rapid", 13, 9.0, 0.0, -12.0),
            ("rapid", 6, 9.0, 9.0, -12.0),
        ]
    );
}

/// `M99 P n` returns to sequence number n of the caller.
#[test]
fn m99_p_returns_to_a_sequence_number() {
    let text = "\
G54 G90 G00 X0. Y0. Z0.
M98 P2
N10 X1.
N20 X2.
M30
O2
Y5.
M99 P20
";
    let r = run_on("hx-mc", text);
    ok(&r);
    assert_eq!(
        moves(&r),
        vec![
            ("rapid", 1, 0.0, 0.0, 0.0),
            ("rapid", 7, 0.0, 5.0, 0.0),
            ("rapid", 4, 2.0, 5.0, 0.0),
        ]
    );
    // A missing return sequence number.
    let r = run_on("hx-mc", "M98 P2\nM30\nO2\nM99 P77\n");
    assert_eq!(alarm(&r), ("F_82021", 4));
}

/// HX: G65 4 levels, M98 + G65 + G66 8 in all (000 §14.1.7 (5));
/// Fanuc 0-T: 4 subprogram levels (PS077).
#[test]
fn nesting_limits() {
    // Each O1 calls itself: levels 1-4 run, the 5th G65 alarms.
    let r = run_on("hx-mc", "G65 P1\nM30\nO1\n#100 = #100 + 1.\nG65 P1\nM99\n");
    assert_eq!(alarm(&r), ("F_82023", 5));
    // M98: 8 levels on the HX.
    let r = run_on(
        "hx-mc",
        "G54 G90 G00 X0.\nM98 P1\nM30\nO1\nG91 G00 X-1.\nM98 P1\nM99\n",
    );
    assert_eq!(alarm(&r), ("F_82023", 6));
    assert_eq!(moves(&r).len(), 1 + 8);
    // Four G65 plus four M98: fine; one more of either: the 8-level total.
    let r = run_on(
        "hx-mc",
        "G65 P1\nM30\nO1\nIF [#1 GE 3] GOTO 5\nG65 P1 A[#1+1]\nM99\nN5 M98 P2\nM99\nO2\n#100 = #100 + 1.\nIF [#100 GE 5] GOTO 9\nM98 P2\nN9 M99\n",
    );
    assert_eq!(alarm(&r), ("F_82023", 12));
    // The lathe: 4 subprogram levels.
    let r = run_on("puma-lathe", "M98 P1\nM30\nO1\nM98 P1\nM99\n");
    assert_eq!(alarm(&r), ("PS077", 4));
    // The limits are profile parameters.
    let r = run_with_param(
        "puma-lathe",
        "max_sub_nesting",
        1.0,
        "M98 P1\nM30\nO1\nM98 P2\nM99\nO2\nM99\n",
    );
    assert_eq!(alarm(&r), ("PS077", 4));
}

#[test]
fn missing_programs_and_sequences() {
    let r = run_on("hx-mc", "G00 X0.\nM98 P1234\nM30\n");
    assert_eq!(alarm(&r), ("F_82109", 2));
    let r = run_on("puma-lathe", "G00 W0.\nM98 P1234\nM30\n");
    assert_eq!(alarm(&r), ("PS078", 2));
    let r = run_on("puma-lathe", "G65 A1.\nM30\n");
    assert_eq!(alarm(&r), ("PS076", 1));
    let r = run_on("hx-mc", "M98 L2\nM30\n");
    assert_eq!(alarm(&r), ("F_82109", 1));
    // Q names a sequence number the called program does not have.
    let r = run_on("hx-mc", "M30\n").alarm;
    assert!(r.is_none());
    let r = run_on("hx-mc", "M98 P5 Q3\nM30\nO5\nN1 G00 X0.\nM99\nO6\nN3 M99\n");
    assert_eq!(alarm(&r), ("F_82021", 1));
    // A called program that ends without M99.
    let r = run_on("hx-mc", "M98 P5\nM30\nO5\nG00 X0.\n");
    assert_eq!(alarm(&r).0, "F_82024");
    let r = run_on("hx-mc", "M98 P5\nM30\nO5\nG00 X0.\nO6\nM99\n");
    assert_eq!(alarm(&r), ("F_82024", 5));
}

/// The main program ends at the next O header even without M30; GOTO does
/// not search past the end of its own program.
#[test]
fn programs_in_one_file_are_separate() {
    let r = run_on("hx-mc", "O1\nG54 G90 G00 X0. Y0. Z0.\nO2\nX5.\nM99\n");
    ok(&r);
    assert_eq!(moves(&r), vec![("rapid", 2, 0.0, 0.0, 0.0)]);
    let r = run_on("hx-mc", "O1\nGOTO 5\nM30\nO2\nN5 M99\n");
    assert_eq!(alarm(&r), ("F_82021", 2));
}

/// Fanuc 0-T: `M98 Pxxxxyyyy`, count xxxx and program yyyy.
#[test]
fn fanuc_eight_digit_p() {
    let text = "G00 X100. Z0.\nM98 P30010\nM98 P10 L2\nM30\nO0010\nG00 W-1.\nM99\n";
    let r = run_on("puma-lathe", text);
    ok(&r);
    let z: Vec<f64> = moves(&r).iter().map(|m| m.4).collect();
    assert_eq!(z, vec![0.0, -1.0, -2.0, -3.0, -4.0, -5.0]);
}

fn temp_dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("kerf-calls-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn run_interp(mut it: Interp) -> (Vec<Event>, Option<kerf_canon::Alarm>, Interp) {
    let mut ev = Vec::new();
    loop {
        match it.step() {
            Step::Event(e) => ev.push(e),
            Step::End => return (ev, None, it),
            Step::Alarm(a) => return (ev, Some(a), it),
        }
    }
}

/// Programs from `--lib` folders: `O0100.nc`, `200.nc`, `O300` (no
/// extension); events name the library file.
#[test]
fn library_folders() {
    let a = temp_dir("a");
    let b = temp_dir("b");
    std::fs::write(a.join("O0100.nc"), "O0100\nG00 X1.\nM98 P200\nM99\n").unwrap();
    std::fs::write(b.join("200.nc"), "G00 X2.\nM99\n").unwrap();
    std::fs::write(
        b.join("O300"),
        "%\nO0300 (no extension)\nG00 X#24\nM99\n%\n",
    )
    .unwrap();
    let mut it = Interp::new(Profile::builtin("hx-mc").unwrap(), Settings::default());
    it.add_lib_dir(a.clone());
    it.add_lib_dir(b.clone());
    let main = "G54 G90 G00 X0. Y0. Z0.\nM98 P100\nG65 P300 X3.\nM98 P100\nM30\n";
    it.load_main(
        "main.nc",
        Box::new(std::io::Cursor::new(main.as_bytes().to_vec())),
    );
    let (ev, al, it) = run_interp(it);
    assert!(al.is_none(), "{al:?}");
    let m = moves_of(&ev);
    let xs: Vec<(u32, f64)> = m.iter().map(|m| (m.1, m.2)).collect();
    assert_eq!(
        xs,
        vec![(1, 0.0), (2, 1.0), (1, 2.0), (3, 3.0), (2, 1.0), (1, 2.0)]
    );
    let files: Vec<String> = ev
        .iter()
        .filter(|e| e.motion().is_some())
        .map(|e| {
            let n = it.file_name(e.src.file);
            std::path::Path::new(n)
                .file_name()
                .unwrap()
                .to_string_lossy()
                .to_string()
        })
        .collect();
    assert_eq!(
        files,
        vec!["main.nc", "O0100.nc", "200.nc", "O300", "O0100.nc", "200.nc"]
    );
    // An alarm inside a library program points at that file.
    std::fs::write(a.join("O0400.nc"), "G00 X1.\nG01 X2.\nM99\n").unwrap();
    let mut it = Interp::new(Profile::builtin("hx-mc").unwrap(), Settings::default());
    it.add_lib_dir(a.clone());
    it.load_main(
        "main.nc",
        Box::new(std::io::Cursor::new(b"M98 P400\nM30\n".to_vec())),
    );
    let (_, al, it) = run_interp(it);
    let al = al.expect("no feed alarm");
    assert_eq!((al.code.as_str(), al.src.line), ("F_84020", 2));
    assert!(it.file_name(al.src.file).ends_with("O0400.nc"));
    let _ = std::fs::remove_dir_all(&a);
    let _ = std::fs::remove_dir_all(&b);
}

/// `#3000 = n (MESSAGE)`: alarm 3000+n with the message; `#3006 = n
/// (MESSAGE)`: a message and a stop, then the program goes on.
#[test]
fn user_alarm_and_message_stop() {
    let r = run_on("hx-mc", "G00 X0.\n#3000 = 12 (TOOL BROKEN)\nM30\n");
    let a = r.alarm.as_ref().unwrap();
    assert_eq!(
        (a.code.as_str(), a.message.as_str(), a.src.line),
        ("3012", "TOOL BROKEN", 2)
    );
    let r = run_on("puma-lathe", "#3000 = 1 (BAR END)\n");
    assert_eq!(r.alarm.as_ref().unwrap().code, "3001");
    let r = run_on("hx-mc", "#3006 = 1 (CHECK PART)\nG00 X0.\nM30\n");
    ok(&r);
    let kinds: Vec<String> = r
        .events
        .iter()
        .map(|e| match &e.cmd {
            Canon::Message(m) => format!("msg {m}"),
            Canon::Stop { optional } => format!("stop {optional}"),
            Canon::Rapid { .. } => "rapid".into(),
            Canon::End { code } => format!("end {code}"),
            _ => "other".into(),
        })
        .collect();
    assert_eq!(
        kinds,
        vec!["msg CHECK PART", "stop false", "rapid", "end 30"]
    );
}

/// WHILE loops belong to their call level; a macro called inside a loop
/// does not disturb it.
#[test]
fn loops_and_calls() {
    let text = "\
G54 G90 G00 X0. Y0. Z0.
#1 = 0
WHILE [#1 LT 3] DO1
#1 = #1 + 1
G65 P7 A#1
END1
M30
O7
#2 = 0
WHILE [#2 LT #1] DO1
#2 = #2 + 1
END1
G00 X#2
M99
";
    let r = run_on("hx-mc", text);
    ok(&r);
    let xs: Vec<f64> = moves(&r).iter().map(|m| m.2).collect();
    assert_eq!(xs, vec![0.0, 1.0, 2.0, 3.0]);
}

/// Many library programs: files beyond the few kept open are closed and
/// reopened when called again.
#[test]
fn many_library_programs() {
    let d = temp_dir("many");
    let mut main = String::from("G54 G90 G00 X0. Y0. Z0.\n");
    let mut want = vec![0.0];
    for pass in 0..2 {
        for i in 0..20u32 {
            if pass == 0 {
                std::fs::write(
                    d.join(format!("O{}.nc", 1000 + i)),
                    format!("G00 X{i}.\nM99\n"),
                )
                .unwrap();
            }
            main.push_str(&format!("M98 P{}\n", 1000 + i));
            want.push(i as f64);
        }
    }
    main.push_str("M30\n");
    let mut it = Interp::new(Profile::builtin("hx-mc").unwrap(), Settings::default());
    it.add_lib_dir(d.clone());
    it.load_main("main.nc", Box::new(std::io::Cursor::new(main.into_bytes())));
    let (ev, al, _) = run_interp(it);
    assert!(al.is_none(), "{al:?}");
    let xs: Vec<f64> = moves_of(&ev).iter().map(|m| m.2).collect();
    assert_eq!(xs, want);
    let _ = std::fs::remove_dir_all(&d);
}

/// An M98 block's motion runs before the call; `M98 Q_ R_` without P
/// runs a section of the current program (HX).
#[test]
fn m98_with_motion_and_sections_of_the_current_program() {
    let text = "\
G54 G90 G00 X0. Y0. Z0.
X5. M98 P2
M98 Q10 R20
M30
N10 X1.
N20 X2.
X3.
M99
O2
Y7.
M99
";
    let r = run_on("hx-mc", text);
    ok(&r);
    assert_eq!(
        moves(&r),
        vec![
            ("rapid", 1, 0.0, 0.0, 0.0),
            ("rapid", 2, 5.0, 0.0, 0.0),
            ("rapid", 10, 5.0, 7.0, 0.0),
            ("rapid", 5, 1.0, 7.0, 0.0),
            ("rapid", 6, 2.0, 7.0, 0.0),
        ]
    );
}

/// A library file opened by `%` with no O header is the program.
#[test]
fn library_file_with_percent_and_no_header() {
    let d = temp_dir("pct");
    std::fs::write(d.join("9010.nc"), "%\nG00 X#24 Y#25\nM99\n%\n").unwrap();
    let mut it = Interp::new(Profile::builtin("hx-mc").unwrap(), Settings::default());
    it.add_lib_dir(d.clone());
    let main = "G54 G90 G00 X0. Y0. Z0.\nG65 P9010 X4. Y-3.\nM30\n";
    it.load_main(
        "main.nc",
        Box::new(std::io::Cursor::new(main.as_bytes().to_vec())),
    );
    let (ev, al, _) = run_interp(it);
    assert!(al.is_none(), "{al:?}");
    assert_eq!(
        moves_of(&ev),
        vec![("rapid", 1, 0.0, 0.0, 0.0), ("rapid", 2, 4.0, -3.0, 0.0)]
    );
    let _ = std::fs::remove_dir_all(&d);
}

/// An endless call loop through `M99 P` is stopped by the loop guard.
#[test]
fn m99_p_loop_is_bounded() {
    let r = run_with_param("hx-mc", "max_jumps", 200.0, "N1 M98 P2\nM30\nO2\nM99 P1\n");
    assert_eq!(alarm(&r), ("KERF-0101", 4));
}

/// 000 §14.1.8: nested G66 modal calls. A move of the main program calls
/// the newest G66's macro; a move inside that macro calls the next outer
/// G66's macro; moves of the outermost macro call nothing. Order: 1-1, 2-1,
/// 1-2, 3-1, 2-1, 3-2, 2-1, 1-3. Numbers without a decimal point are
/// 0.001 mm; no work offset is programmed, so G54 (-400, -250, -250) holds
/// and the start (machine 0) is work (400, 250, 250).
#[test]
fn nested_modal_calls_of_14_1_8() {
    let text = "\
G66 P9100
Z1000
G66 P9200
Z15000
G67
G67
Z-25000
M30
O9100
X5000
M99
O9200
Z6000
Z7000
M99
";
    let r = run_on("hx-mc", text);
    ok(&r);
    assert_eq!(
        moves(&r),
        vec![
            ("rapid", 2, 400.0, 250.0, 1.0), // 1-1
            ("rapid", 10, 5.0, 250.0, 1.0),  // 2-1
            ("rapid", 4, 5.0, 250.0, 15.0),  // 1-2
            ("rapid", 13, 5.0, 250.0, 6.0),  // 3-1
            ("rapid", 10, 5.0, 250.0, 6.0),  // 2-1
            ("rapid", 14, 5.0, 250.0, 7.0),  // 3-2
            ("rapid", 10, 5.0, 250.0, 7.0),  // 2-1
            ("rapid", 7, 5.0, 250.0, -25.0), // 1-3
        ]
    );
}

/// G66 passes its arguments to every call; blocks without a move, the
/// G66 block itself and blocks after G67 do not call.
#[test]
fn g66_arguments_and_cancel() {
    let text = "\
G54 G90 G00 X0. Y0. Z0.
G66 P9082 R2. Z-5. L1
X10.
#100 = 1.
G04 P100
Y10.
G67
X20.
M30
O9082
G00 Z#18
G01 Z#26 F100.
G00 Z#18
M99
";
    let r = run_on("hx-mc", text);
    ok(&r);
    let mut want = vec![("rapid", 1, 0.0, 0.0, 0.0)];
    want.push(("rapid", 3, 10.0, 0.0, 0.0));
    want.push(("rapid", 11, 10.0, 0.0, 2.0));
    want.push(("feed", 12, 10.0, 0.0, -5.0));
    want.push(("rapid", 13, 10.0, 0.0, 2.0));
    want.push(("rapid", 6, 10.0, 10.0, 2.0));
    want.push(("rapid", 11, 10.0, 10.0, 2.0));
    want.push(("feed", 12, 10.0, 10.0, -5.0));
    want.push(("rapid", 13, 10.0, 10.0, 2.0));
    want.push(("rapid", 8, 20.0, 10.0, 2.0));
    assert_eq!(moves(&r), want);
}
