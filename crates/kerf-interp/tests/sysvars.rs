//! System variables: the HX numbering of 000 §14.2.3 (hx-mc) and the Fanuc
//! standard numbering (puma-lathe). Expected values worked out by hand
//! from the profiles (hx-mc: G54 = X-400 Y-250 Z-250, 2nd reference
//!

use kerf_canon::Canon;
use kerf_interp::{Run, Settings};

mod common;
use common::{alarm, ok, round, run_on, run_with};

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

#[test]
fn hx_positions_modal_and_work_offsets() {
    let r = run_with(
        "hx-mc",
        Settings::default(),
        "G90 G54 G00 X10. Y20. Z-5.\n\
         #1 = #6205\n\
         #2 = #6207\n\
         #3 = #4083\n\
         #4 = #2377 + #2379\n\
         #5 = #6718 * 1000 + #6720\n\
         #6 = #8000\n\
         #2386 = -300.\n\
         #2387 = -200.\n\
         #2388 = -100.\n\
         G55 G00 X0 Y0 Z0\n\
         #7 = #6205 + #6206 + #6207\n\
         G00 X[#1 + 400] Y[#2 + 300] Z[#3 - 20]\n\
         G00 X[#4 + 700] Y[#5 - 40] Z[#6 + 390]\n\
         G00 X[#7 + 620] Y0 Z0\n\
         M30\n",
    );
    ok(&r);
    // #1 = -390, #2 = -255, #3 = 10, #4 = -650, #5 = 0*1000 + 90,
    // #6 = -400, #7 = -300 - 200 - 100.
    assert_eq!(
        moves(&r),
        vec![
            (1, 10.0, 20.0, -5.0),
            (11, 0.0, 0.0, 0.0),
            (13, 10.0, 45.0, -10.0),
            (14, 50.0, 50.0, -10.0),
            (15, 20.0, 0.0, 0.0)
        ]
    );
    let r = run_with("hx-mc", Settings::default(), "#1 = 0\n#6205 = 1.\nM30\n");
    let a = r.alarm.unwrap();
    assert_eq!((a.code.as_str(), a.src.line), ("F_82200", 2));
}

#[test]
fn hx_tool_offsets_take_effect() {
    let r = run_with(
        "hx-mc",
        Settings::default(),
        "#2241 = 50.\n\
         #2113 = 5.\n\
         G90 G54 G00 X0 Y0 Z0\n\
         G00 H2 D2\n\
         #1 = #4883 * 10 + #4882\n\
         #2 = #2241 + #2113\n\
         G00 X#1 Y#2\n\
         G43 H2 Z0\n\
         #3 = #6207\n\
         G00 X[#3 + 230]\n\
         M30\n",
    );
    ok(&r);
    // #1 = 2*10 + 2 = 22, #2 = 50 + 5 = 55; G43 H2 Z0: machine Z =
    // -250 + 0 + 50 = -200, so X[-200 + 230] = X30.
    let m = moves(&r);
    assert_eq!(m[1], (7, 22.0, 55.0, 0.0));
    assert_eq!((m.last().unwrap().0, m.last().unwrap().1), (10, 30.0));
}

#[test]
fn hx_interface_signals() {
    let s = Settings {
        inputs: [0b101, 7, 0, 0],
        ..Settings::default()
    };
    let r = run_with(
        "hx-mc",
        s,
        "#1 = #7000 + #7001 * 10 + #7002 * 100\n\
         #2 = #7032 + #7033\n\
         #7503 = 1\n\
         #7532 = #7532 + 16\n\
         #3 = #7504 * 100 + #7532\n\
         G90 G54 G00 X#1 Y#2 Z-#3\n\
         #7000 = 1\n",
    );
    // #1 = 1 + 0 + 100; #2 = 5 + 7; outputs 8 + 16 = 24 with UO004 set.
    assert_eq!(moves(&r), vec![(6, 101.0, 12.0, -124.0)]);
    let a = r.alarm.unwrap();
    assert_eq!((a.code.as_str(), a.src.line), ("F_82200", 7));
}

#[test]
fn fanuc_lathe_positions_and_work_offset_write() {
    let r = run_with(
        "puma-lathe",
        Settings::default(),
        "G00 X50. Z5.\n\
         #1 = #5001\n\
         #2 = #5002\n\
         #3 = #4001\n\
         #5221 = #5221 + 10.\n\
         #6 = #5001\n\
         #3901 = 3\n\
         #7 = #3901 + #4120 + #3\n\
         #8 = #5061\n\
         G00 X[#1 + #2 + #6 + #7] Z[#8 - 40]\n\
         M30\n",
    );
    ok(&r);
    // #1 = 50 (diameter), #2 = 5, #3 = 0 (G00); G54 X moves +10 on the
    // diameter, so the same point reads X40: #6 = 40; #7 = 3 + 0 + 0;
    // #8 = 40. X[50 + 5 + 40 + 3] = X98 → radius 49; Z[40 - 40] = Z0.
    let m = moves(&r);
    assert_eq!((m[0].0, m[0].1, m[0].3), (1, 25.0, 5.0));
    assert_eq!((m[1].0, m[1].1, m[1].3), (10, 49.0, 0.0));
    // HX numbers are not variables of the Fanuc lathe.
    let r = run_with("puma-lathe", Settings::default(), "#1 = #6205\n");
    assert_eq!(r.alarm.unwrap().code, "PS115");
    // The millisecond clock runs from the start of the run and can be set.
    let r = run_with(
        "puma-lathe",
        Settings::default(),
        "#3001 = 5000\nIF [#3001 LT 5000] GOTO 9\nIF [#3001 GT 65000] GOTO 9\nG00 X10. Z0\nN9 M30\n",
    );
    ok(&r);
    assert_eq!(moves(&r).len(), 1);
}

#[test]
fn lathe_tool_offset_variables_share_the_offset_memory() {
    // Fanuc 0-T numbering: #2701+n X geometry (a diameter under diameter
    // programming), #2801+n Z, #2901+n R, #2301+n tip, #2001+n X wear.
    let text = "#2702 = 1.5\n#2802 = -0.93\n#2902 = 0.4\n#2302 = 3\n#2002 = 0.02\n\
                G00 X[#2702 + #2002] Z[#2802 * 100]\nM30\n";
    let mut it = kerf_interp::Interp::new(
        kerf_interp::Profile::builtin("puma-lathe").unwrap(),
        Settings::default(),
    );
    it.load_main(
        "t.nc",
        Box::new(std::io::Cursor::new(text.as_bytes().to_vec())),
    );
    while let kerf_interp::Step::Event(_) = it.step() {}
    let o = it.offsets().lathe(2);
    // X 1.5 diameter = 0.75 radius; wear 0.02 diameter = 0.01 radius.
    assert_eq!((o.x, o.z, o.r, o.tip), (0.75, -0.93, 0.4, 3));
    assert!((o.wear_x - 0.01).abs() < 1e-12);
    // Read back in program units: X 1.5 + 0.02 = 1.52 (diameter, so a
    // 0.76 mm radius), Z -0.93 * 100 = -93.
    let r = run_on("puma-lathe", text);
    ok(&r);
    let m = moves(&r);
    assert_eq!((m[0].1, m[0].3), (0.76, -93.0));
    // Offset 17 is beyond the PUMA's 16 offsets: an alarm on line 1.
    let r = run_on("puma-lathe", "#2717 = 1.\nM30\n");
    assert_eq!(alarm(&r).1, 1);
}
