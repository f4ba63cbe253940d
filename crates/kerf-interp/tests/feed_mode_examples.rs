//! The feed-function examples of the TurboTek HX manual (000 §5.3.1 G09,
//! §5.3.2 G61, §5.3.3 G64, §5.3.4 G63), run as printed apart from the
//! extraction's letter O for zero (`GO0`, `YO0.`, `XO0.` → G00, Y0.,
//! X0.). Each moves a 100 mm square corner from G54 X0 Y0 Z0 at F500;
//! what differs is the mode the planner gets: G09 exact stop for its own
//! block only, G61 exact stop until G62/G63/G64 (the G61 example goes back
//! to G64 on its third move), G64 cutting mode until G61 (and the reverse
//! in the G64 example), G63 tapping mode (override and feed hold off).
//! The expected sequences follow the text: a mode code is reported before
//! the motion of its block.

mod common;
use common::{ok, round, run_on};
use kerf_canon::{Canon, ModeChange};

/// What the planner receives, in order: ("mode", line, name) or a motion
/// ("G00"/"G01", line, "x y z").
fn seq(text: &str) -> Vec<(&'static str, u32, String)> {
    let r = run_on("hx-mc", text);
    ok(&r);
    r.events
        .iter()
        .filter_map(|e| {
            let line = e.src.line;
            match &e.cmd {
                Canon::Mode(m) => Some(("mode", line, format!("{m:?}"))),
                Canon::Rapid { .. } | Canon::Feed { .. } => {
                    let k = if matches!(e.cmd, Canon::Rapid { .. }) {
                        "G00"
                    } else {
                        "G01"
                    };
                    let t = e.motion().unwrap().to;
                    Some((
                        k,
                        line,
                        format!("{} {} {}", round(t[0]), round(t[1]), round(t[2])),
                    ))
                }
                _ => None,
            }
        })
        .collect()
}

fn mv(k: &'static str, line: u32, xyz: &str) -> (&'static str, u32, String) {
    (k, line, xyz.to_string())
}

fn mode(line: u32, m: ModeChange) -> (&'static str, u32, String) {
    ("mode", line, format!("{m:?}"))
}

/// §5.3.1: G09 stops exactly at X100 only; the Y100 and X0 moves blend.
#[test]
fn g09_exact_stop_is_one_shot() {
    let got = seq("G54 G00 X0. Y0. Z0.\nG09 G01 X100. F500.\nY100.\nX0.\nM30\n");
    assert_eq!(
        got,
        vec![
            mv("G00", 1, "0 0 0"),
            mode(2, ModeChange::ExactStopBlock),
            mv("G01", 2, "100 0 0"),
            mv("G01", 3, "100 100 0"),
            mv("G01", 4, "0 100 0"),
        ]
    );
}

/// §5.3.2: G61 holds for X100 and Y100; `G64 X0.` returns to cutting
/// mode for the last two moves.
#[test]
fn g61_exact_stop_mode_until_g64() {
    let got = seq("G54 G00 X0. Y0. Z0.\nG61 G01 X100. F500.\nY100.\nG64 X0.\nY0.\nM30\n");
    assert_eq!(
        got,
        vec![
            mv("G00", 1, "0 0 0"),
            mode(2, ModeChange::ExactStopMode(true)),
            mv("G01", 2, "100 0 0"),
            mv("G01", 3, "100 100 0"),
            mode(4, ModeChange::CuttingMode),
            mv("G01", 4, "0 100 0"),
            mv("G01", 5, "0 0 0"),
        ]
    );
}

/// §5.3.3: the reverse, G64 first and `G61 X0.` for the last two moves.
#[test]
fn g64_cutting_mode_until_g61() {
    let got = seq("G54 G00 X0. Y0. Z0.\nG64 G01 X100. F500.\nY100.\nG61 X0.\nY0.\nM30\n");
    assert_eq!(
        got,
        vec![
            mv("G00", 1, "0 0 0"),
            mode(2, ModeChange::CuttingMode),
            mv("G01", 2, "100 0 0"),
            mv("G01", 3, "100 100 0"),
            mode(4, ModeChange::ExactStopMode(true)),
            mv("G01", 4, "0 100 0"),
            mv("G01", 5, "0 0 0"),
        ]
    );
}

/// §5.3.4: G63 tapping mode from the X100 move on.
#[test]
fn g63_tapping_mode() {
    let got = seq("G54 G00 X0. Y0. Z0.\nG63 G01 X100. F500.\nY100.\nM30\n");
    assert_eq!(
        got,
        vec![
            mv("G00", 1, "0 0 0"),
            mode(2, ModeChange::TappingMode),
            mv("G01", 2, "100 0 0"),
            mv("G01", 3, "100 100 0"),
        ]
    );
}
