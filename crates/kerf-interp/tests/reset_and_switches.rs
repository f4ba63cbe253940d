//! `Interp::reset` (000 §14.4 (5), fanuc-semantics §7.9), the #3003/#3004
//! switches (fanuc-semantics §7.8) and HX #4018 (000 §14.2.3). Expected
//! values are worked out by hand.

use kerf_canon::Canon;
use kerf_interp::{Interp, MacroSwitches, Profile, Settings, Step};

mod common;
use common::{round, run_on, run_with_param};

fn interp(machine: &str, settings: Settings, text: &str) -> Interp {
    let mut it = Interp::new(Profile::builtin(machine).unwrap(), settings);
    it.load_main(
        "t.nc",
        Box::new(std::io::Cursor::new(text.as_bytes().to_vec())),
    );
    it
}

/// Steps to the next feed move: (line, work X).
fn next_feed(it: &mut Interp) -> (u32, f64) {
    loop {
        match it.step() {
            Step::Event(e) => {
                if let Canon::Feed { m, .. } = &e.cmd {
                    return (e.src.line, round(m.to[0]));
                }
            }
            other => panic!("no feed: {other:?}"),
        }
    }
}

/// A main program that records its group 3 modal code (#6720) in #150,
/// sets locals, commons and a retained variable, switches to G91 and calls
/// a macro that feeds X-1 for ever.
const PROG: &str = "#150=#6720\n\
                    #1=5\n\
                    #100=7\n\
                    #210=9\n\
                    G91 G01 F100\n\
                    G65 P100 A2.\n\
                    M30\n\
                    O100\n\
                    WHILE [#1 GT 0] DO1\n\
                    X-1.\n\
                    END1\n\
                    M99\n";

#[test]
fn reset_clears_variables_calls_loops_and_modes_and_restarts() {
    let mut it = interp("hx-mc", Settings::default(), PROG);
    for _ in 0..3 {
        assert_eq!(next_feed(&mut it).0, 10);
    }
    // Inside the macro: its #1 is the argument A2.; the main level's #1 = 5
    // is saved in the call frame.
    assert_eq!(it.macro_var(1), Some(2.0));
    assert_eq!(it.macro_var(150), Some(90.0));
    let x = round(it.work_position()[0]);
    it.reset();
    assert_eq!(it.macro_var(1), None, "locals cleared");
    assert_eq!(it.macro_var(100), None, "commons cleared");
    assert_eq!(it.macro_var(150), None, "commons cleared");
    assert_eq!(it.macro_var(210), Some(9.0), "retained kept");
    // The program runs again from its first block: #150 reads G90 again
    // (reset went back from G91 to the power-on G90), and the first move
    // is X-1 from where the machine stopped (positions are kept).
    let (line, x1) = next_feed(&mut it);
    assert_eq!((line, x1), (10, round(x - 1.0)));
    assert_eq!(it.macro_var(150), Some(90.0));
    assert_eq!(it.macro_var(210), Some(9.0));
}

#[test]
fn reset_keeps_commons_when_the_profile_says_so() {
    let mut p = Profile::builtin("hx-mc").unwrap();
    p.params.insert("clear_commons_on_reset".into(), 0.0);
    p.params.insert("clear_locals_on_reset".into(), 0.0);
    let mut it = Interp::new(p, Settings::default());
    it.load_main(
        "t.nc",
        Box::new(std::io::Cursor::new(PROG.as_bytes().to_vec())),
    );
    next_feed(&mut it);
    it.reset();
    assert_eq!(it.macro_var(100), Some(7.0));
    // The main level's own locals are back (the macro level is gone).
    assert_eq!(it.macro_var(1), Some(5.0));
}

#[test]
fn reset_after_an_alarm_runs_the_program_again() {
    // #3000 alarm on the first run (#500 counts the runs: retained).
    let text = "#500=#500+1\nG01 X#500 F100\nIF [#500 EQ 1] THEN #3000=1 (FIRST RUN)\nM30\n";
    let mut it = interp("puma-lathe", Settings::default(), text);
    let (line, x) = next_feed(&mut it);
    assert_eq!((line, x), (2, 0.5)); // X1 on a diameter lathe: radius 0.5
    match it.step() {
        Step::Alarm(a) => assert_eq!((a.code.as_str(), a.src.line), ("3001", 3)),
        other => panic!("expected the #3000 alarm, got {other:?}"),
    }
    assert_eq!(it.step(), Step::End);
    it.reset();
    let (line, x) = next_feed(&mut it);
    assert_eq!((line, x), (2, 1.0)); // X2: radius 1
    assert!(matches!(it.step(), Step::Event(e) if matches!(e.cmd, Canon::End { code: 30 })));
}

#[test]
fn switches_3003_and_3004_are_recorded_and_cleared_by_reset() {
    let text = "G00 X10.\n\
                #3003=1\n\
                #3004=5\n\
                G00 X20.\n\
                #1=#3003*10+#3004\n\
                #3003=2\n\
                #3004=2\n\
                G00 X30.\n\
                M30\n";
    let sb = Settings {
        single_block: true,
        ..Settings::default()
    };
    let mut it = interp("puma-lathe", sb, text);
    let rapid = |it: &mut Interp| loop {
        match it.step() {
            Step::Event(e) if e.motion().is_some() => break e.src.line,
            Step::Event(_) => {}
            other => panic!("{other:?}"),
        }
    };
    assert_eq!(rapid(&mut it), 1);
    assert_eq!(it.macro_switches(), MacroSwitches::default());
    assert!(it.single_block_stop());
    assert_eq!(rapid(&mut it), 4);
    // #3003 = 1: bit 0; #3004 = 5: bits 0 and 2.
    assert_eq!(
        it.macro_switches(),
        MacroSwitches {
            single_block_suppressed: true,
            no_fin_wait: false,
            feed_hold_disabled: true,
            override_disabled: false,
            exact_stop_disabled: true,
        }
    );
    assert!(!it.single_block_stop());
    assert_eq!(rapid(&mut it), 8);
    // Read back as 1*10 + 5 = 15; then #3003 = 2 (FIN), #3004 = 2 (override).
    assert_eq!(it.macro_var(1), Some(15.0));
    assert_eq!(
        it.macro_switches(),
        MacroSwitches {
            no_fin_wait: true,
            override_disabled: true,
            ..MacroSwitches::default()
        }
    );
    assert!(it.single_block_stop());
    it.reset();
    assert_eq!(it.macro_switches(), MacroSwitches::default());
}

#[test]
fn switch_values_out_of_range_alarm() {
    for (text, line) in [
        ("#3003=4\nM30\n", 1),
        ("G00 X1.\n#3004=8\nM30\n", 2),
        ("#3004=1.5\n", 1),
    ] {
        let r = run_on("puma-lathe", text);
        let a = r.alarm.expect("alarm");
        assert_eq!((a.code.as_str(), a.src.line), ("PS003", line), "{text}");
    }
}

#[test]
fn single_block_stop_follows_the_switch_without_3003() {
    let mut it = interp("puma-lathe", Settings::default(), "G00 X10.\nM30\n");
    let _ = it.step();
    assert!(!it.single_block_stop());
}

#[test]
fn hx_4018_reads_the_tpg_state() {
    let r = run_on("hx-mc", "#1=#4018\nG90 G01 X#1 F100\nM30\n");
    assert!(r.alarm.is_none());
    // Not in TPG: 0. The profile parameter `tpg` = 1 runs as in TPG.
    let text = "#1=#4018\nIF [#1 EQ 1] GOTO 9\n#3000=1 (NOT TPG)\nN9 M30\n";
    let r = run_with_param("hx-mc", "tpg", 1.0, text);
    assert!(r.alarm.is_none(), "{:?}", r.alarm);
    let r = run_on("hx-mc", text);
    assert_eq!(r.alarm.expect("not TPG").src.line, 3);
    // Read-only.
    let r = run_on("hx-mc", "#4018=1\nM30\n");
    assert_eq!(r.alarm.expect("read-only").code, "F_82200");
    // The labels of #4721 and #6716 are lost in 000: not variables.
    for t in ["#1=#4721\n", "#1=#6716\n"] {
        assert_eq!(
            run_on("hx-mc", t).alarm.expect("not modelled").code,
            "F_82200"
        );
    }
}
