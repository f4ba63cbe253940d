//! G-code system B on the PUMA (001 G-code table, "special G code"
//! column; note 2: selected by a parameter — profile `gcode_system_b =
//! 1`). Every position by hand from puma-lathe.toml's G54 (X 0, Z −529),
//! X programmed as a diameter, shown as a radius.

use kerf_canon::{Canon, Feed};
use kerf_interp::Run;

mod common;
use common::{alarm, ok, round, run_on, run_with_param};

const PUMA: &str = "puma-lathe";

fn run_b(text: &str) -> Run {
    run_with_param(PUMA, "gcode_system_b", 1.0, text)
}

/// (kind, X radius, Z, feed/lead) of the motions.
fn trace(r: &Run) -> Vec<(&'static str, f64, f64, f64)> {
    r.events
        .iter()
        .filter_map(|e| {
            let f = |f: &Feed| match *f {
                Feed::PerRev(v) | Feed::PerMin(v) | Feed::InverseTime(v) => v,
            };
            let (k, v) = match &e.cmd {
                Canon::Rapid { .. } => ("R", 0.0),
                Canon::Feed { feed, .. } => ("F", f(feed)),
                Canon::Thread { lead, .. } => ("T", *lead),
                _ => return None,
            };
            let m = e.motion()?;
            Some((k, round(m.to[0]), round(m.to[2]), round(v)))
        })
        .collect()
}

/// G90/G91 choose absolute/incremental: `G91 G01 X-10. Z-20.` from Ø50 Z5
/// goes to radius 25 − 5 = 20, Z −15; G77 is the turning cycle (system A's
/// G90): from (30, 5) to Ø40 Z−30: rapid to X20, cut to Z−30, cut out to
/// X30, rapid back to Z5 — the same in G91 written `X-20. Z-35.`. G33 is
/// the thread (A's G32), F the lead; G95/G94 feed per revolution/minute.
#[test]
fn system_b_motion_and_cycles() {
    let r = run_b(
        "G21 G90 G95\nG97 S500 M03\nG00 X50. Z5.\nG91 G01 X-10. Z-20. F0.2\n\
         G90 G00 X60. Z5.\nG77 X40. Z-30. F0.25\nG91 G77 X-20. Z-35.\nG90 G00 X30. Z5.\n\
         G33 Z-20. F1.5\nG00 X40.\nG94 G01 Z10. F300.\nM30\n",
    );
    ok(&r);
    let cycle = [
        ("R", 20.0, 5.0, 0.0),
        ("F", 20.0, -30.0, 0.25),
        ("F", 30.0, -30.0, 0.25),
        ("R", 30.0, 5.0, 0.0),
    ];
    let mut want = vec![
        ("R", 25.0, 5.0, 0.0),
        ("F", 20.0, -15.0, 0.2),
        ("R", 30.0, 5.0, 0.0),
    ];
    want.extend(cycle);
    want.extend(cycle);
    want.extend([
        ("R", 15.0, 5.0, 0.0),
        ("T", 15.0, -20.0, 1.5),
        ("R", 20.0, -20.0, 0.0),
        ("F", 20.0, 10.0, 300.0),
    ]);
    assert_eq!(trace(&r), want);
    assert!(r.events.iter().any(|e| matches!(e.cmd,
        Canon::Feed { feed: Feed::PerMin(f), .. } if f == 300.0)));
}

/// G92 is coordinate setting (A's G50): at Ø50 Z5, `G92 X100. Z50.` makes
/// the tool read Ø100 Z50, so `G00 X80. Z40.` moves radius −10, Z −10;
/// `G92 S1800` is the spindle clamp. #4001 and #4003 read the system-B
/// numbers (G77 → 77, G91 → 91).
#[test]
fn system_b_coordinate_setting_and_modal_variables() {
    let r = run_b(
        "G00 X50. Z5.\nG92 X100. Z50.\nG00 X80. Z40.\nG92 S1800\n\
         G77 X70. Z30. F0.2\nG91\n#1 = #4001\n#3 = #4003\n\
         IF [#1 NE 77] GOTO 9\nIF [#3 NE 91] GOTO 9\nG90 G00 X80. Z40.\nN9 M30\n",
    );
    ok(&r);
    let t = trace(&r);
    assert_eq!(t[0], ("R", 25.0, 5.0, 0.0));
    assert_eq!(t[1], ("R", 40.0, 40.0, 0.0), "work coordinates after G92");
    assert!(r.events.iter().any(|e| matches!(e.cmd,
        Canon::Mode(kerf_canon::ModeChange::SpindleClamp(v)) if v == 1800.0)));
    // The last move exists only if #4001 = 77 and #4003 = 91.
    assert_eq!(t.last(), Some(&("R", 40.0, 40.0, 0.0)));
    assert_eq!(t.len(), 2 + 4 + 1);
}

/// System A's numbers that system B does not have alarm PS010 (G32, G50,
/// G98/G99); in system A the internal G900/G901 are not codes either;
/// X and U in one G91 block are both incremental X: PS009.
#[test]
fn system_b_refuses_system_a_codes() {
    for (text, col) in [
        ("G32 Z-10. F1.\n", 1),
        ("G00 X50. Z5.\nG50 S2000\n", 1),
        ("G99\n", 1),
    ] {
        let r = run_b(text);
        let line = text.lines().count() as u32;
        assert_eq!(alarm(&r), ("PS010", line, col), "{text}");
    }
    let r = run_on(PUMA, "G900 X10.\n");
    assert_eq!(alarm(&r), ("PS010", 1, 1));
    let r = run_b("G91 G00 X10. U5.\n");
    assert_eq!(alarm(&r), ("PS009", 1, 14));
}
