//! Macro sample programs of 000 §14.5 run as printed (edits noted per
//! test), positions computed independently in the tests.

mod common;
use common::{alarm, moves, ok, round, run_on};

/// 000 §14.5.3 WHILE circle drill, as printed except: the margin note
/// `:G98 G81 …` is left out (the program drills with G0/G1/G0 itself) and
/// the lost Korean comments are dropped. Holes at angles 0°, 45° … 315°
/// (WHILE #100 ≤ 360 − 45) and radii 50, 40 … 10 (WHILE #101 ≥ 10), at
/// X = sin(a)·r, Y = cos(a)·r, each: rapid there, feed to Z-20, rapid to
/// Z10. Positions computed here with f64 trigonometry, independently of
/// the macro evaluator.
#[test]
fn while_circle_drill_of_000_14_5_3() {
    let prog = "G40 G49 G80\nG28 G91 Z0.\nG28 X0.Y0.\nG90 G92 X150. Y150. Z200.\nG00 Z10.\n\
                G00 X0 Y0\nG00 X0 Y0\n#100 = 0.\n#101 = 50\n#102 = 45.\n\
                N150 WHILE [#100 LE [360.-#102]] DO 210\nN200 WHILE [#101 GE 10.] DO 220\n\
                G0 X[SIN[#100] * #101] Y[COS[#100] * #101]\nG1 Z-20. F100.\nG0 Z10.\n\
                #101 = #101 - 10.\nEND 220\n#100 = #100 + #102\n#101 = 50.\nEND 210\n\
                G91 G0 Y50.\nX50.\nG90 G49 G00 Z200. M05\nM02\n";
    let r = run_on("hx-mc", prog);
    ok(&r);
    let m = moves(&r);
    // G00 Z10, G00 X0 Y0 twice, then 8 × 5 holes of 3 moves, then 3 moves.
    assert_eq!(m.len(), 3 + 40 * 3 + 3);
    let mut k = 3;
    let mut last = (0.0, 0.0);
    for a in 0..8 {
        for r_i in 0..5 {
            let (deg, rad) = (45.0 * a as f64, 50.0 - 10.0 * r_i as f64);
            let (x, y) = (
                round(deg.to_radians().sin() * rad),
                round(deg.to_radians().cos() * rad),
            );
            // The address value is rounded to the 0.001 mm increment.
            let (x, y) = ((x * 1000.0).round() / 1000.0, (y * 1000.0).round() / 1000.0);
            assert_eq!(m[k], ("rapid", x, y, 10.0), "hole a={deg} r={rad}");
            assert_eq!(m[k + 1], ("feed", x, y, -20.0));
            assert_eq!(m[k + 2], ("rapid", x, y, 10.0));
            last = (x, y);
            k += 3;
        }
    }
    // G91 Y50. then X50. from the last hole (315°, r 10).
    assert_eq!(m[k], ("rapid", last.0, round(last.1 + 50.0), 10.0));
    assert_eq!(
        m[k + 1],
        ("rapid", round(last.0 + 50.0), round(last.1 + 50.0), 10.0)
    );
}

/// 000 §14.5.2 circle: `G1 X[SIN[#100] * #101] Y[COS[#100] * #101]` for
/// #100 = 0 … 360 (IF … LE 360 GOTO 20), radius 50. As printed the G1 has
/// no F (the control alarms: no feed); with `F200.` added it makes 361
/// feeds, the last back at (0, 50) (sin 360 = 0, cos 360 = 1). The
/// printed program then leaves G91 on, so `G49 G00 Z200.` climbs 200 mm
/// from machine Z -150 to +50: past the top of travel, the overtravel
/// alarm on that block (the real machine would stop there too).
#[test]
fn macro_circle_of_000_14_5_2() {
    let prog = |f: &str| {
        format!(
            "G40 G49 G80\nG28 G91 Z0.\nG28 X0.Y0.\nG90 G92 X150. Y150. Z200.\nZ50.\nG0 X0 Y0\n\
             #100=0.\n#101 =50.\nN20\nG1 X[SIN[#100] * #101] Y[COS[#100] * #101]{f}\n\
             #100 = #100 + 1\nIF [#100 LE 360.0 ] GOTO 20\nG91 G0 Y50.\nX50.\n\
             G49 G00 Z200. M05\nM02\n"
        )
    };
    let r = run_on("hx-mc", &prog(""));
    assert_eq!(alarm(&r), ("F_84020", 10, 1));
    let r = run_on("hx-mc", &prog(" F200."));
    assert_eq!(alarm(&r), ("F_84100", 15, 5));
    let feeds: Vec<_> = moves(&r).into_iter().filter(|m| m.0 == "feed").collect();
    assert_eq!(feeds.len(), 361);
    assert_eq!(feeds[0], ("feed", 0.0, 50.0, 50.0));
    // 90°: (50, 0); 30°: (25, 43.301) (cos 30 · 50 = 43.30127, rounded to 0.001).
    assert_eq!(feeds[90], ("feed", 50.0, 0.0, 50.0));
    assert_eq!(feeds[30], ("feed", 25.0, 43.301, 50.0));
    assert_eq!(feeds[360], ("feed", 0.0, 50.0, 50.0));
}
