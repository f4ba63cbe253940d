//! The feed-function examples of the TurboTek HX manual (000 §5.3.1 G09,
//! §5.3.2 G61, §5.3.3 G64, §5.3.4 G63), run as printed apart from the
//! extraction's letter O for zero (`GO0`, `YO0.`, `XO0.` → G00, Y0.,
//! X0.). Each moves a 100 mm square corner from G54 X0 Y0 Z0 at F500;
//! what differs is the mode the planner gets: G09 exact stop for its own
//! block only, G61 exact stop until G62/G63/G64 (the G61 example goes back
//! to G64 on its third move), G64 cutting mode until G61 (and the reverse
//! in the G64 example), G63 tapping mode (override and feed hold off).
//! The expected sequences follow the text: a mode code is reported before
//! the motion of its block. §5.3.5's G62 example runs with cutter
//! compensation; its D1 value is not printed (kerf takes 5 mm).

mod common;
use common::{ok, round, run_on};
use kerf_canon::{Canon, ModeChange};
use kerf_interp::{Interp, Profile, Run, Settings};

/// What the planner receives, in order: ("mode", line, name) or a motion
/// ("G00"/"G01", line, "x y z").
fn seq(text: &str) -> Vec<(&'static str, u32, String)> {
    events(&run_on("hx-mc", text))
}

/// [`seq`] of a finished run.
fn events(r: &Run) -> Vec<(&'static str, u32, String)> {
    ok(r);
    r.events
        .iter()
        .filter_map(|e| {
            let line = e.src.line;
            match &e.cmd {
                Canon::Mode(m) => Some(("mode", line, format!("{m:?}"))),
                Canon::Rapid { .. } | Canon::Feed { .. } | Canon::Arc { .. } => {
                    let k = match e.cmd {
                        Canon::Rapid { .. } => "G00",
                        Canon::Feed { .. } => "G01",
                        _ => "arc",
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

/// §5.3.5 (l.1860): `G41 D1`, `G62 G01 X100.`, `G03 X130. Y30. R30.`,
/// `G01 X0.`, `Y100.`, with D1 = 5 mm (not printed). By hand, G41 = left
/// of travel:
/// - start-up X100 (type A) ends on the arc's start normal: the arc
///   starts along +X, left normal +Y → (100, 5);
/// - the CCW arc about (100, 30) has the tool inside: offset radius 25;
///   its end meets the next block, `X0.` along −X at Y30, whose left
///   normal is −Y (offset line Y25): a left turn, the inner corner G62
///   slows down; the circle (x − 100)² + (y − 30)² = 25² meets Y25 at
///   x = 100 + √(625 − 25) = 124.494897;
/// - −X then +Y is a right turn, outer 90°: the lines Y25 and X−5 meet
///   at (−5, 25);
/// - Y100 ends on its own normal at M30: (−5, 100).
#[test]
fn g62_example_with_cutter_compensation() {
    let mut it = Interp::new(Profile::builtin("hx-mc").unwrap(), Settings::default());
    it.offsets_mut().d_mut(1).unwrap().geom = 5.0;
    let r = kerf_interp::run_interp(
        it,
        "t.nc",
        "G54 G00 X0. Y0. Z0.\nG41 D1\nG62 G01 X100. F500.\nG03 X130. Y30. R30.\nG01 X0.\nY100.\nM30\n",
    );
    let x = round(100.0 + 600f64.sqrt());
    assert_eq!(
        events(&r),
        vec![
            mv("G00", 1, "0 0 0"),
            mode(3, ModeChange::CornerOverride),
            mv("G01", 3, "100 5 0"),
            mv("arc", 4, &format!("{x} 25 0")),
            mv("G01", 5, "-5 25 0"),
            mv("G01", 6, "-5 100 0"),
        ]
    );
}
