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

/// 000 §14.2.3's macro O9300, which reads the block end point #5001-#5003
/// and the machine position #5021-#5023 (fanuc-semantics §6.7), as printed
/// except: `#1 = #5001,` ends with `;`, `X#H24` is `X#24` (OCR), and the
/// manual's placeholders Xp, Yp, Zp (a point in machine coordinates) are
/// −380., −220., −240. By hand, from G54 (−400, −250, −250): the tool at
/// work (10, 20, 30) = machine (−390, −230, −220); #1-#3 = 10, 20, 30; G00
/// X50. Y40. → machine (−350, −210, −220); G91 by (−380 + 350, −220 + 210,
/// −240 + 220) = (−30, −10, −20) → machine (−380, −220, −240) = work (20,
/// 30, 10); then, still G91, by (50, 40, −10) → (70, 70, 0), by (10, 20)
/// → (80, 90, 0), by Z 30 → (80, 90, 30).
#[test]
fn o9300_of_000_14_2_3_reads_5001_and_5021() {
    let prog = "G54 G90 G00 X10. Y20. Z30.\nG65 P9300 X50. Y40. Z-10.\nM30\n\
                O9300\n#1 = #5001;\n#2 = #5002;\n#3 = #5003;\nG00 X#24 Y#25;\nG04;\n\
                G91 X[-380. - #5021] Y[-220. - #5022] Z[-240. - #5023];\n\
                X#24 Y#25 Z#26;\nX#1 Y#2;\nZ#3;\nM99\n";
    let r = run_on("hx-mc", prog);
    ok(&r);
    assert_eq!(
        moves(&r),
        vec![
            ("rapid", 10.0, 20.0, 30.0),
            ("rapid", 50.0, 40.0, 30.0),
            ("rapid", 20.0, 30.0, 10.0),
            ("rapid", 70.0, 70.0, 0.0),
            ("rapid", 80.0, 90.0, 0.0),
            ("rapid", 80.0, 90.0, 30.0),
        ]
    );
}

/// 000 §5.4's dwell example as printed (OCR `GO0`/`GO01`/`MO3` read as
/// G00/G01/M03, the lost comments dropped), with a last `G04 P1` added
/// after the restore. `#3120` is PI 120 (the parameter window #3000+n):
/// the program saves it (0 on hx-mc), sets 1 so that `G04 P1` in G95
/// counts spindle revolutions (P in 1/1000: 0.001 rev), and restores it,
/// after which `G04 P1` is 1 ms again. `G04 X3` (no point) is 3 ms.
#[test]
fn dwell_example_of_000_5_4_with_pi_120() {
    use kerf_canon::Canon;
    let prog = "G54 G00 X0. Y0. Z0.\nG94 G01 X10. F500.\nG04 X3\nX20.\nG95 M03 S60. F5.\nY10.\n\
                #100 = #3120\n#3120 =1\nG04 P1\n#3120 = #100\nG04 P1\nM30\n";
    let r = run_on("hx-mc", prog);
    ok(&r);
    let dwells: Vec<(f64, f64)> = r
        .events
        .iter()
        .filter_map(|e| match e.cmd {
            Canon::Dwell {
                seconds,
                revolutions,
            } => Some((round(seconds), round(revolutions))),
            _ => None,
        })
        .collect();
    assert_eq!(dwells, vec![(0.003, 0.0), (0.0, 0.001), (0.001, 0.0)]);
    // #3000 and #3006 keep their alarm/message meaning beside the window.
    let r = run_on(
        "hx-mc",
        "#3006 = 1 (HELLO)\n#1 = #3129\nIF [#1 NE 0.1] GOTO 9\n#3000 = 7 (STOP)\nN9 M30\n",
    );
    let a = r.alarm.as_ref().expect("the #3000 alarm: PI 129 reads 0.1");
    assert!(a.message.contains("STOP"), "{}", a.message);
}
