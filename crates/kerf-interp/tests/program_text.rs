//! What real programs written for Fanuc-family controls do with the text
//! around the blocks (issue 15): tape leader before the first `%`, a
//! comment inside `[ ]`, leading zeros, and the calculator-type decimal
//! point as a profile switch. Expected positions by hand.

use kerf_interp::{run_text, Profile, Settings};

mod common;
use common::{alarm, moves, ok, run_on};

/// Text before the first `%` is tape leader (a title line, a comment):
/// the program starts after that `%` and ends at the next one. Before,
/// the leader's comment made the first `%` the end: nothing ran.
#[test]
fn tape_leader_before_the_first_percent() {
    for text in [
        "(PART 12 OP1)\n%\nO1000\nG54 G00 X10. Y20. Z30.\nM30\n%\n",
        "\n(PART 12)\n(REV B)\n\n%\nG54 G00 X10. Y20. Z30.\n%\n",
    ] {
        let r = run_on("hx-mc", text);
        ok(&r);
        assert_eq!(moves(&r), vec![("rapid", 10.0, 20.0, 30.0)], "{text:?}");
    }
    // Without a leader, a % after the program still ends it.
    let r = run_on("hx-mc", "G54 G00 X10. Y20. Z30.\n%\nX99.\n");
    ok(&r);
    assert_eq!(moves(&r).len(), 1);
}

/// `#1 = [1 + (ONE) 2]` is 3: the comment is skipped inside the
/// brackets. X[#1 (HALF) / 2.] with #1 = 3 moves to X1.5.
#[test]
fn comment_inside_brackets_is_skipped() {
    let r = run_on(
        "hx-mc",
        "#1 = [1 + (ONE) 2]\nG54 G00 X[#1 (HALF) / 2.] Y0 Z0\nM30\n",
    );
    ok(&r);
    assert_eq!(moves(&r), vec![("rapid", 1.5, 0.0, 0.0)]);
}

/// The PUMA reads 8 digits; `X0.42928932` (a leading zero and 8 digits)
/// is read like `X.42928932`: radius 0.21464466.
#[test]
fn leading_zero_is_not_a_digit() {
    for x in ["X0.42928932", "X.42928932"] {
        let r = run_on("puma-lathe", &format!("G00 {x} Z0\nM30\n"));
        ok(&r);
        assert_eq!(moves(&r), vec![("rapid", 0.214645, 0.0, 0.0)], "{x}");
    }
    let r = run_on("puma-lathe", "G00 X1.42928932 Z0\n");
    assert_eq!(alarm(&r), ("PS003", 1, 5));
}

/// The calculator-type decimal point (`--set calculator_decimal=on`):
/// `X40 Z-2` is 40 mm (diameter, radius 20) and −2 mm rather than 0.040 /
/// −0.002; numbers with a point are the same either way.
#[test]
fn calculator_decimal_point() {
    let text = "G00 X40 Z-2\nX30. Z5\nM30\n";
    let r = run_on("puma-lathe", text);
    ok(&r);
    assert_eq!(
        moves(&r),
        vec![("rapid", 0.02, 0.0, -0.002), ("rapid", 15.0, 0.0, 0.005)]
    );
    let mut p = Profile::builtin("puma-lathe").unwrap();
    p.calculator_decimal = true;
    let r = run_text(p, Settings::default(), "t.nc", text);
    ok(&r);
    assert_eq!(
        moves(&r),
        vec![("rapid", 20.0, 0.0, -2.0), ("rapid", 15.0, 0.0, 5.0)]
    );
}

/// M29 before G84 is Fanuc's rigid tapping; the HX has no M29 (000 §11.1
/// lists none) and taps rigidly with G84.2/G84.3 (§12.3.5-12.3.6): the
/// alarm stays and says so.
#[test]
fn m29_points_to_g84_2() {
    let r = run_on("hx-mc", "G54 G00 X0 Y0 Z10.\nM29 S500\nG84 Z-10. R2. F1.\n");
    let a = r.alarm.as_ref().expect("alarm");
    assert_eq!((a.code.as_str(), a.src.line, a.src.col), ("F_82031", 2, 1));
    assert!(
        a.message.contains("rigid tapping on this control is G84.2"),
        "{}",
        a.message
    );
}
