//! The parsed-block cache (interp/block_cache.rs): text executed again is
//! replayed from the cache, with the same results, block numbers, alarms
//! and loop guards as when it is read and parsed again; a straight-line
//! program caches nothing; the cache stays bounded. Expected values are
//! worked out by hand.

use kerf_canon::Canon;
use kerf_interp::{Interp, Profile, Settings, Step};

mod common;
use common::{ok, round, run_on, run_with, run_with_param};

/// Runs `text` on hx-mc and returns the interpreter after the end.
fn finish(text: &str) -> (Interp, Option<kerf_canon::Alarm>) {
    let mut it = Interp::new(Profile::builtin("hx-mc").unwrap(), Settings::default());
    it.load_main(
        "t.nc",
        Box::new(std::io::Cursor::new(text.as_bytes().to_vec())),
    );
    loop {
        match it.step() {
            Step::Event(_) => {}
            Step::End => return (it, None),
            Step::Alarm(a) => return (it, Some(a)),
        }
    }
}

/// (line, work X) of each feed move.
fn feeds(r: &kerf_interp::Run) -> Vec<(u32, f64)> {
    feeds_on(r, 0)
}

/// (line, work coordinate `axis`) of each feed move.
fn feeds_on(r: &kerf_interp::Run, axis: usize) -> Vec<(u32, f64)> {
    r.events
        .iter()
        .filter(|e| matches!(e.cmd, Canon::Feed { .. }))
        .map(|e| (e.src.line, round(e.motion().unwrap().to[axis])))
        .collect()
}

#[test]
fn a_straight_line_program_caches_nothing() {
    let mut text = String::from("G90 G01 F100\n");
    for i in 1..=50 {
        text.push_str(&format!("#1=#1+{i}\nX[#1/100]\n"));
    }
    text.push_str("M30\n");
    let (it, alarm) = finish(&text);
    assert!(alarm.is_none());
    assert_eq!(it.cached_blocks(), 0);
    // 1 + 100 + 1 blocks; #1 = 1 + 2 + ... + 50 = 1275.
    assert_eq!(it.blocks(), 102);
    assert_eq!(it.macro_var(1), Some(1275.0));
}

#[test]
fn a_loop_body_is_cached_and_runs_as_read() {
    // Four passes: X = 1, 3, 6, 10 (the running sum of 1..4).
    let text = "G90 G01 F100\n\
                #1=0\n\
                #2=0\n\
                WHILE [#1 LT 4] DO1\n\
                #1=#1+1\n\
                #2=#2+#1\n\
                X#2\n\
                END1\n\
                M30\n";
    let r = run_on("hx-mc", text);
    ok(&r);
    assert_eq!(feeds(&r), vec![(7, 1.0), (7, 3.0), (7, 6.0), (7, 10.0)]);
    // 3 + 5 passes of the WHILE (4 entering, 1 leaving) + 4 x 4 body
    // blocks ... counted: lines 1-3 (3), WHILE x5, body 3 x 4, END1 x4,
    // M30 = 3 + 5 + 12 + 4 + 1 = 25.
    assert_eq!(r.blocks, 25);
    let (it, _) = finish(text);
    // WHILE, the three body blocks and END1 were read again.
    assert_eq!(it.cached_blocks(), 5);
}

#[test]
fn an_alarm_in_a_cached_block_has_its_line_and_column() {
    // #1 = 1, 2, 3: 10/[3-#1] divides by zero on the third pass, when the
    // block comes from the cache. The statement starts at column 4.
    let text = "#1=0\n\
                WHILE [#1 LT 5] DO1\n\
                #1=#1+1\n   #2=10/[3-#1]\n\
                END1\n\
                M30\n";
    let r = run_on("hx-mc", text);
    let a = r.alarm.expect("math alarm");
    assert_eq!((a.code.as_str(), a.src.line, a.src.col), ("F_82201", 4, 4));
    // The same block alarming on its first reading (not cached).
    let r = run_on("hx-mc", "#1=2\n#1=#1+1\n#1=#1\n   #2=10/[3-#1]\nM30\n");
    let a = r.alarm.expect("math alarm");
    assert_eq!((a.code.as_str(), a.src.line, a.src.col), ("F_82201", 4, 4));
}

#[test]
fn loop_guards_count_cached_blocks() {
    let text = "#1=0\nWHILE [#1 LT 100] DO1\n#1=#1+1\nEND1\nM30\n";
    // Blocks read again: 2, 3, 4, 2, 3, 4, 2, 3, 4, 2, 3 - the 11th
    // (line 3) is over a budget of 10.
    let r = run_with_param("hx-mc", "max_repeat_blocks", 10.0, text);
    let a = r.alarm.expect("loop guard");
    assert_eq!((a.code.as_str(), a.src.line), ("KERF-0101", 3));
    // Backward jumps: END1 jumps on each of passes 1..; the 4th is over 3.
    let r = run_with_param("hx-mc", "max_jumps", 3.0, text);
    let a = r.alarm.expect("loop guard");
    assert_eq!((a.code.as_str(), a.src.line), ("KERF-0101", 4));
}

#[test]
fn block_delete_applies_to_cached_blocks() {
    let text = "G90 G01 F100\n\
                #1=0\n\
                WHILE [#1 LT 3] DO1\n\
                #1=#1+1\n\
                /X#1\n\
                Y#1\n\
                END1\n\
                M30\n";
    let on = Settings {
        block_skip: 0b10,
        ..Settings::default()
    };
    let r = run_with("hx-mc", on, text);
    ok(&r);
    // Only the Y moves (line 6): Y 1, 2, 3.
    assert_eq!(feeds_on(&r, 1), vec![(6, 1.0), (6, 2.0), (6, 3.0)]);
    let r = run_on("hx-mc", text);
    ok(&r);
    assert_eq!(
        feeds(&r),
        vec![(5, 1.0), (6, 1.0), (5, 2.0), (6, 2.0), (5, 3.0), (6, 3.0)]
    );
}

#[test]
fn goto_back_and_repeated_subprogram_calls_replay_the_same() {
    // GOTO back three times, then a subprogram of the same file called
    // with L3: X 1, 2, 3 from the GOTO loop, then 13, 23, 33 (G91 +10 in
    // the subprogram on top of the first three).
    let text = "G90 G01 F100\n\
                #1=0\n\
                N10 #1=#1+1\n\
                X#1\n\
                IF [#1 LT 3] GOTO10\n\
                G91\n\
                M98 P200 L3\n\
                M30\n\
                O200\n\
                X10.\n\
                M99\n";
    let r = run_on("hx-mc", text);
    ok(&r);
    assert_eq!(
        feeds(&r),
        vec![
            (4, 1.0),
            (4, 2.0),
            (4, 3.0),
            (10, 13.0),
            (10, 23.0),
            (10, 33.0)
        ]
    );
}

#[test]
fn the_cache_stays_bounded_and_correct_beyond_its_size() {
    // A loop body of 5,000 blocks (more than the cache holds), 3 passes.
    let mut text = String::from("#1=0\n#2=0\nWHILE [#1 LT 3] DO1\n#1=#1+1\n");
    for _ in 0..5000 {
        text.push_str("#2=#2+1\n");
    }
    text.push_str("END1\nM30\n");
    let (it, alarm) = finish(&text);
    assert!(alarm.is_none(), "{alarm:?}");
    assert_eq!(it.macro_var(2), Some(15_000.0));
    assert!(it.cached_blocks() <= 4096, "{}", it.cached_blocks());
    // 2 + 4 WHILE + 3 x (1 + 5000) + 3 END1 + M30.
    assert_eq!(it.blocks(), 2 + 4 + 3 * 5001 + 3 + 1);
}
