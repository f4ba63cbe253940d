//! G31 skip and G37 tool length measurement on the HX against a simulated
//! skip signal (000 §4.9, §4.10). Expected values worked out by hand.

use kerf_canon::Canon;
use kerf_interp::{run_text, Profile, Run, Settings};

mod common;
use common::{alarm, moves, ok, round};

/// Runs on hx-mc with skip signals: (signal 0-4, axis slot, value).
fn run_skip(trips: &[(usize, usize, f64)], text: &str) -> Run {
    let mut s = Settings::default();
    for &(n, ax, v) in trips {
        s.skip[n][ax] = Some(v);
    }
    run_text(Profile::builtin("hx-mc").unwrap(), s, "t.nc", text)
}

/// 000 §4.9 second example: G31, G31.2, G31.3, G31.4 round a square,
/// each stopped by its own signal: X at 60, then Y at 40 (signal 2), X at
/// 10 (signal 3), Y at 5 (signal 4). #6319/#6320 read the last skip
/// position.
#[test]
fn multi_step_skip_example() {
    let r = run_skip(
        &[(0, 0, 60.0), (2, 1, 40.0), (3, 0, 10.0), (4, 1, 5.0)],
        "G90 G54 G00 X0. Y0. Z0.\nG31 X100. F500.\n#100 = #6319\nG31.2 Y100.\n\
         G31.3 X0.\nG31.4 Y0.\n#101 = #6319\n#102 = #6320\nG00 X#100 Y#101 Z#102\nM30\n",
    );
    ok(&r);
    assert_eq!(
        moves(&r),
        vec![
            ("rapid", 0.0, 0.0, 0.0),
            ("feed", 60.0, 0.0, 0.0),
            ("feed", 60.0, 40.0, 0.0),
            ("feed", 10.0, 40.0, 0.0),
            ("feed", 10.0, 5.0, 0.0),
            // #100 = 60 (after G31), #101 = 10, #102 = 5 (after G31.4).
            ("rapid", 60.0, 10.0, 5.0),
        ]
    );
}

/// 000 §4.9 first example: `G31 G91 X200.0 F100` then `X300.0 Y100.0`:
/// the incremental block after the skip counts from where the skip came.
/// From X-200 with the signal at X-50: skip at (-50, 0), then (250, 100).
#[test]
fn incremental_move_after_skip_starts_at_the_skip_position() {
    let r = run_skip(
        &[(0, 0, -50.0)],
        "G90 G00 X-200. Y0\nG31 G91 X200.0 F100\nX300.0 Y100.0\n",
    );
    ok(&r);
    let m = moves(&r);
    assert_eq!(m[1], ("feed", -50.0, 0.0, 250.0));
    assert_eq!(m[2], ("rapid", 250.0, 100.0, 250.0));
}

#[test]
fn skip_without_contact_alarms() {
    let r = run_skip(&[(0, 0, 150.0)], "G00 X0 Y0\nG31 X100. F500.\n");
    assert_eq!(alarm(&r), ("F_84022", 2, 1));
    // No signal declared at all.
    let r = run_skip(&[], "G00 X0 Y0\nG31 X100. F500.\n");
    assert_eq!(alarm(&r), ("F_84022", 2, 1));
}

/// G37 Z-10. with H1 = 0 and the probe touching at Z-10.4: rapid to
/// r = 10 before (Z0), measuring feed down, contact at -10.4; H1 becomes
/// (#2240) 0 + (-10.4 - -10) = -0.4 and the tool then reads Z-10: a G00 Z0 goes
/// to machine -250 - 0.4.
#[test]
fn g37_measures_the_tool_length() {
    let r = run_skip(
        &[(0, 2, -10.4)],
        "G90 G00 X0 Y0 Z50.\nG43 H1 Z50.\nG37 Z-10.\nIF [ABS[#2240 + 0.4] GT 0.000001] THEN #3000 = 1 (H1 NOT UPDATED)\nG00 Z-10.\nG00 Z0\nM30\n",
    );
    ok(&r);
    let ev: Vec<_> = r
        .events
        .iter()
        .filter_map(|e| match &e.cmd {
            Canon::Rapid { m, .. } => Some(("rapid", round(m.to[2]), round(m.mto[2]))),
            Canon::Feed { m, feed } => {
                assert_eq!(*feed, kerf_canon::Feed::PerMin(100.0));
                Some(("feed", round(m.to[2]), round(m.mto[2])))
            }
            _ => None,
        })
        .collect();
    assert_eq!(
        ev,
        vec![
            ("rapid", 50.0, -200.0),
            ("rapid", 50.0, -200.0),
            ("rapid", 0.0, -250.0),
            ("feed", -10.4, -260.4),
            // The tool reads Z-10 after the measurement: G00 Z-10. does not move.
            ("rapid", -10.0, -260.4),
            ("rapid", 0.0, -250.4),
        ]
    );
}

#[test]
fn g37_alarms() {
    // Contact before the range: Z-8 is 2 above the measurement position.
    let r = run_skip(&[(0, 2, -8.0)], "G00 Z50.\nG43 H1\nG37 Z-10.\n");
    assert_eq!(alarm(&r), ("F_84022", 3, 1));
    // No H number active.
    let r = run_skip(&[(0, 2, -10.2)], "G00 Z50.\nG37 Z-10.\n");
    assert_eq!(alarm(&r), ("F_82008", 2, 1));
    // Without Z.
    let r = run_skip(&[(0, 2, -10.2)], "G43 H1\nG37\n");
    assert_eq!(alarm(&r), ("F_82008", 2, 1));
}
