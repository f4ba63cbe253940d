//! Chamfer `,C` and corner R `,R` on the HX (000 §4.3.1-4.3.2, Fanuc):
//! the emitted moves, worked out by hand (trigonometry, circle-circle
//! intersection), and every alarm with its position.

use kerf_canon::{ArcDir, Canon, Feed, Pos};
use kerf_interp::{run_text, Interp, Profile, Run, Settings, Step};

mod common;
use common::{ok, run_on};

/// One emitted motion: kind, source line, end (x, y), arc centre and
/// direction, feed (mm/min).
#[derive(Debug)]
struct Mv {
    kind: &'static str,
    line: u32,
    to: (f64, f64),
    center: Option<((f64, f64), ArcDir)>,
    feed: Option<f64>,
}

fn xy(p: &Pos) -> (f64, f64) {
    (p[0], p[1])
}

fn path(r: &Run) -> Vec<Mv> {
    r.events
        .iter()
        .filter_map(|e| {
            let feed = |f: &Feed| match f {
                Feed::PerMin(v) => Some(*v),
                _ => None,
            };
            let (kind, center, feed) = match &e.cmd {
                Canon::Rapid { .. } => ("rapid", None, None),
                Canon::Feed { feed: f, .. } => ("feed", None, feed(f)),
                Canon::Arc {
                    center,
                    dir,
                    feed: f,
                    ..
                } => ("arc", Some((xy(center), *dir)), feed(f)),
                _ => return None,
            };
            Some(Mv {
                kind,
                line: e.src.line,
                to: xy(&e.motion()?.to),
                center,
                feed,
            })
        })
        .collect()
}

fn near(a: (f64, f64), b: (f64, f64)) -> bool {
    (a.0 - b.0).abs() < 1e-6 && (a.1 - b.1).abs() < 1e-6
}

/// Checks a motion: kind, line, end point and (for arcs) centre and
/// direction.
#[track_caller]
fn check(m: &Mv, kind: &str, line: u32, to: (f64, f64), arc: Option<((f64, f64), ArcDir)>) {
    assert_eq!((m.kind, m.line), (kind, line), "{m:?}");
    assert!(near(m.to, to), "{m:?}: end, want {to:?}");
    match (arc, m.center) {
        (None, None) => {}
        (Some((c, d)), Some((mc, md))) => {
            assert!(near(mc, c), "{m:?}: centre, want {c:?}");
            assert_eq!(md, d, "{m:?}");
        }
        _ => panic!("{m:?}: arc centre mismatch, want {arc:?}"),
    }
}

fn dist(a: (f64, f64), b: (f64, f64)) -> f64 {
    (a.0 - b.0).hypot(a.1 - b.1)
}

/// A corner arc about `fillet` touches a circle about `circle` at `tp`
/// tangentially: the two centres and the point are collinear.
#[track_caller]
fn assert_tangent_to_circle(tp: (f64, f64), fillet: (f64, f64), circle: (f64, f64)) {
    let (u, v) = (
        (tp.0 - fillet.0, tp.1 - fillet.1),
        (circle.0 - fillet.0, circle.1 - fillet.1),
    );
    assert!(
        (u.0 * v.1 - u.1 * v.0).abs() < 1e-6,
        "not tangent at {tp:?}"
    );
}

/// A corner arc about `fillet` touches a line of direction `dir` at `tp`
/// tangentially: the radius to the point is perpendicular to the line.
#[track_caller]
fn assert_tangent_to_line(tp: (f64, f64), fillet: (f64, f64), dir: (f64, f64)) {
    let u = (tp.0 - fillet.0, tp.1 - fillet.1);
    assert!(
        (u.0 * dir.0 + u.1 * dir.1).abs() < 1e-6,
        "not tangent at {tp:?}"
    );
}

#[track_caller]
fn alarm(r: &Run) -> (&str, u32, u32) {
    let a = r.alarm.as_ref().expect("an alarm");
    (a.code.as_str(), a.src.line, a.src.col)
}

const START: &str = "G90 G54 G17 G00 X0. Y0. Z0.\n";

fn run(body: &str) -> Run {
    run_on("hx-mc", &format!("{START}{body}"))
}

#[test]
fn line_line_right_angle_chamfer() {
    // From (0,0): G01 X50 ,C5 then Y50. The chamfer runs from 5 before the
    // corner (45,0) to 5 after it (50,5), at the ,C block's feed (300),
    // both parts on its line; the M08 block in between keeps the
    // look-ahead open and its coolant event comes after the chamfer.
    let r = run("G01 X50. ,C5. F300.\nM08\nY50. F100.\nM30\n");
    ok(&r);
    let p = path(&r);
    assert_eq!(p.len(), 4);
    check(&p[0], "rapid", 1, (0.0, 0.0), None);
    check(&p[1], "feed", 2, (45.0, 0.0), None);
    check(&p[2], "feed", 2, (50.0, 5.0), None);
    check(&p[3], "feed", 4, (50.0, 50.0), None);
    assert_eq!(
        (p[1].feed, p[2].feed, p[3].feed),
        (Some(300.0), Some(300.0), Some(100.0))
    );
    let kinds: Vec<_> = r
        .events
        .iter()
        .map(|e| match e.cmd {
            Canon::Coolant { .. } => "coolant",
            Canon::End { .. } => "end",
            _ if e.motion().is_some() => "move",
            _ => "other",
        })
        .collect();
    assert_eq!(kinds, ["move", "move", "move", "coolant", "move", "end"]);
}

#[test]
fn line_line_right_angle_corner_r() {
    // ,R5 at the same corner: the fillet touches 5 before and after it;
    // a left turn, so CCW about (45,5).
    let r = run("G01 X50. ,R5. F300.\nY50.\n");
    ok(&r);
    let p = path(&r);
    check(&p[1], "feed", 2, (45.0, 0.0), None);
    check(
        &p[2],
        "arc",
        2,
        (50.0, 5.0),
        Some(((45.0, 5.0), ArcDir::Ccw)),
    );
    check(&p[3], "feed", 3, (50.0, 50.0), None);
    // Turning right (Y-50): CW about (45,-5).
    let r = run("G01 X50. ,R5. F300.\nY-50.\n");
    ok(&r);
    let p = path(&r);
    check(
        &p[2],
        "arc",
        2,
        (50.0, -5.0),
        Some(((45.0, -5.0), ArcDir::Cw)),
    );
}

#[test]
fn incremental_words_and_least_input_increment() {
    // G91: the next block's Y50 adds to the virtual corner (50,0).
    let r = run("G91 G01 X50. ,C5. F300.\nY50.\n");
    ok(&r);
    let p = path(&r);
    check(&p[1], "feed", 2, (45.0, 0.0), None);
    check(&p[2], "feed", 2, (50.0, 5.0), None);
    check(&p[3], "feed", 3, (50.0, 50.0), None);
    // Without a decimal point ,C is in 0.001 mm: ,C5000 = 5 mm, ,C5 = 0.005.
    let r = run("G01 X50000 ,C5000 F300.\nY50000\n");
    ok(&r);
    check(&path(&r)[2], "feed", 2, (50.0, 5.0), None);
    let r = run("G01 X50. ,C5 F300.\nY50.\n");
    ok(&r);
    let p = path(&r);
    check(&p[1], "feed", 2, (49.995, 0.0), None);
    check(&p[2], "feed", 2, (50.0, 0.005), None);
}

#[test]
fn line_line_other_angles() {
    // (0,0) → K (10,0) → (13,4): the direction turns by θ with cos θ = 0.6,
    // sin θ = 0.8, so tan(θ/2) = sin θ / (1 + cos θ) = 0.5. R4: tangent
    // length 4·0.5 = 2: p1 = (8,0), p2 = K + 2·(0.6,0.8) = (11.2,1.6),
    // centre p1 + (0,4) = (8,4) (|p2 - c| = |(3.2,-2.4)| = 4).
    let r = run("G01 X10. ,R4. F200.\nX13. Y4.\n");
    ok(&r);
    let p = path(&r);
    check(&p[1], "feed", 2, (8.0, 0.0), None);
    check(
        &p[2],
        "arc",
        2,
        (11.2, 1.6),
        Some(((8.0, 4.0), ArcDir::Ccw)),
    );
    check(&p[3], "feed", 3, (13.0, 4.0), None);
    assert_tangent_to_line((11.2, 1.6), (8.0, 4.0), (0.6, 0.8));
    // C2.5: (7.5,0) and K + 2.5·(0.6,0.8) = (11.5,2).
    let r = run("G01 X10. ,C2.5 F200.\nX13. Y4.\n");
    ok(&r);
    let p = path(&r);
    check(&p[1], "feed", 2, (7.5, 0.0), None);
    check(&p[2], "feed", 2, (11.5, 2.0), None);
    // An acute corner: K (10,0) → (7,4), direction (-0.6,0.8), a turn of
    // θ with cos θ = -0.6: tan(θ/2) = 0.8 / 0.4 = 2. R1: tangent length 2:
    // p1 = (8,0), p2 = K + 2·(-0.6,0.8) = (8.8,1.6), centre (8,1).
    let r = run("G01 X10. ,R1. F200.\nX7. Y4.\n");
    ok(&r);
    let p = path(&r);
    check(&p[1], "feed", 2, (8.0, 0.0), None);
    check(&p[2], "arc", 2, (8.8, 1.6), Some(((8.0, 1.0), ArcDir::Ccw)));
    assert!((dist((8.8, 1.6), (8.0, 1.0)) - 1.0).abs() < 1e-9);
}

#[test]
fn line_then_arc() {
    // Line to K (10,0), then G02 about K + (10,0) = (20,0), radius 10, to
    // (20,10): the arc leaves K heading +Y (left turn of 90°). I/J are
    // read from the virtual corner.
    //
    // R2: the fillet centre is on y = 2 (above the line) and, outside the
    // circle (its centre is on the right of CW travel), at 12 from (20,0):
    // (x-20)² + 4 = 144, x = 20 - √140. Tangent points: (x,0) on the line;
    // on the circle, (20,0) + 10/12·((x,2) - (20,0)).
    let x = 20.0 - 140f64.sqrt();
    let p2 = (20.0 + (x - 20.0) * 10.0 / 12.0, 2.0 * 10.0 / 12.0);
    let r = run("G01 X10. ,R2. F200.\nG02 X20. Y10. I10.\n");
    ok(&r);
    let p = path(&r);
    assert_eq!(p.len(), 4);
    check(&p[1], "feed", 2, (x, 0.0), None);
    check(&p[2], "arc", 2, p2, Some(((x, 2.0), ArcDir::Ccw)));
    check(
        &p[3],
        "arc",
        3,
        (20.0, 10.0),
        Some(((20.0, 0.0), ArcDir::Cw)),
    );
    assert!((dist(p2, (x, 2.0)) - 2.0).abs() < 1e-9);
    assert_tangent_to_line((x, 0.0), (x, 2.0), (1.0, 0.0));
    assert_tangent_to_circle(p2, (x, 2.0), (20.0, 0.0));
    // C2: (8,0) on the line; on the arc, circle (K,2) ∩ circle ((20,0),10):
    // x = 10 + 4/20 = 10.2, y = √(4 - 0.04) (the arc goes up).
    let r = run("G01 X10. ,C2. F200.\nG02 X20. Y10. I10.\n");
    ok(&r);
    let p = path(&r);
    check(&p[1], "feed", 2, (8.0, 0.0), None);
    check(&p[2], "feed", 2, (10.2, 3.96f64.sqrt()), None);
    check(
        &p[3],
        "arc",
        3,
        (20.0, 10.0),
        Some(((20.0, 0.0), ArcDir::Cw)),
    );
}

#[test]
fn arc_then_line() {
    // G03 about (0,0), radius 10, from (10,0) to K (0,10) (arriving
    // heading -X), then a line up to (0,30): a right turn of 90°.
    // R3: the fillet is on the right: on x = 3 and outside the circle at
    // 13 from (0,0): 9 + y² = 169, y = √160. Tangent points: (0,y) on the
    // line, 10/13·(3,y) on the circle. CW.
    let y = 160f64.sqrt();
    let p1 = (30.0 / 13.0, 10.0 * y / 13.0);
    let r = run_on(
        "hx-mc",
        "G90 G54 G00 X10. Y0. Z0.\nG03 X0. Y10. I-10. ,R3. F200.\nG01 Y30.\n",
    );
    ok(&r);
    let p = path(&r);
    check(&p[1], "arc", 2, p1, Some(((0.0, 0.0), ArcDir::Ccw)));
    check(&p[2], "arc", 2, (0.0, y), Some(((3.0, y), ArcDir::Cw)));
    check(&p[3], "feed", 3, (0.0, 30.0), None);
    assert_tangent_to_circle(p1, (3.0, y), (0.0, 0.0));
    assert_tangent_to_line((0.0, y), (3.0, y), (0.0, 1.0));
    // C4: (0,14) on the line; on the arc, circle (K,4) ∩ circle ((0,0),10):
    // y = 10 - 16/20 = 9.2, x = +√(16 - 0.64) (before K, x > 0).
    let r = run_on(
        "hx-mc",
        "G90 G54 G00 X10. Y0. Z0.\nG03 X0. Y10. R10. ,C4. F200.\nG01 Y30.\n",
    );
    ok(&r);
    let p = path(&r);
    check(
        &p[1],
        "arc",
        2,
        (15.36f64.sqrt(), 9.2),
        Some(((0.0, 0.0), ArcDir::Ccw)),
    );
    check(&p[2], "feed", 2, (0.0, 14.0), None);
    check(&p[3], "feed", 3, (0.0, 30.0), None);
}

#[test]
fn arc_then_arc() {
    // G02 about (0,0), radius 10, from (0,10) to K (10,0) (arriving
    // heading -Y); G03 about K + (0,10) = (10,10), radius 10, to (20,10)
    // (leaving heading +X): a left turn.
    // R2: the fillet centre is at 12 from (0,0) (outside the CW arc) and
    // at 8 from (10,10) (inside the CCW arc). Circle-circle intersection:
    // the centres are √200 apart, the chord foot at 140/√200 from (0,0)
    // is (7,7), the half chord √(144 - 98) = √46 along (-1,1)/√2, i.e.
    // ±√23·(-1,1); near K: c = (7 + √23, 7 - √23).
    let s = 23f64.sqrt();
    let c = (7.0 + s, 7.0 - s);
    let p1 = (c.0 * 10.0 / 12.0, c.1 * 10.0 / 12.0);
    let p2 = (
        10.0 + (c.0 - 10.0) * 10.0 / 8.0,
        10.0 + (c.1 - 10.0) * 10.0 / 8.0,
    );
    let r = run_on(
        "hx-mc",
        "G90 G54 G00 X0. Y10. Z0.\nG02 X10. Y0. J-10. ,R2. F200.\nG03 X20. Y10. J10.\n",
    );
    ok(&r);
    let p = path(&r);
    check(&p[1], "arc", 2, p1, Some(((0.0, 0.0), ArcDir::Cw)));
    check(&p[2], "arc", 2, p2, Some((c, ArcDir::Ccw)));
    check(
        &p[3],
        "arc",
        3,
        (20.0, 10.0),
        Some(((10.0, 10.0), ArcDir::Ccw)),
    );
    assert!((dist(p1, c) - 2.0).abs() < 1e-9 && (dist(p2, c) - 2.0).abs() < 1e-9);
    assert_tangent_to_circle(p1, c, (0.0, 0.0));
    assert_tangent_to_circle(p2, c, (10.0, 10.0));
}

#[test]
fn chained_corners_round_a_rectangle() {
    // A 50 × 50 square with R5 at three corners: each block is trimmed at
    // both ends; the corner arcs are CCW about (45,5), (45,45), (5,45).
    let r = run("G01 X50. ,R5. F300.\nY50. ,R5.\nX0. ,R5.\nY0.\n");
    ok(&r);
    let p = path(&r);
    assert_eq!(p.len(), 8);
    check(&p[1], "feed", 2, (45.0, 0.0), None);
    check(
        &p[2],
        "arc",
        2,
        (50.0, 5.0),
        Some(((45.0, 5.0), ArcDir::Ccw)),
    );
    check(&p[3], "feed", 3, (50.0, 45.0), None);
    check(
        &p[4],
        "arc",
        3,
        (45.0, 50.0),
        Some(((45.0, 45.0), ArcDir::Ccw)),
    );
    check(&p[5], "feed", 4, (5.0, 50.0), None);
    check(
        &p[6],
        "arc",
        4,
        (0.0, 45.0),
        Some(((5.0, 45.0), ArcDir::Ccw)),
    );
    check(&p[7], "feed", 5, (0.0, 0.0), None);
    // C4 uses up the whole 4 mm of the Y block: its own ,C2 has no path
    // left to cut; the moves up to the first chamfer are made.
    let r = run("G01 X10. ,C4. F300.\nY4. ,C2.\nX14.\n");
    assert_eq!(alarm(&r), ("F_82104", 3, 5));
    let p = path(&r);
    assert_eq!(p.len(), 3);
    check(&p[1], "feed", 2, (6.0, 0.0), None);
    check(&p[2], "feed", 2, (10.0, 4.0), None);
}

#[test]
fn blocks_in_between_keep_the_look_ahead() {
    // A comment, a macro statement, a GOTO and an M code between the ,R
    // block and its next move; the next move reads #1.
    let r = run("G01 X50. ,R5. F300.\n(COMMENT)\n#1 = 50.\nGOTO 7\nX99.\nN7 M09\nY#1\n");
    ok(&r);
    let p = path(&r);
    check(
        &p[2],
        "arc",
        2,
        (50.0, 5.0),
        Some(((45.0, 5.0), ArcDir::Ccw)),
    );
    check(&p[3], "feed", 8, (50.0, 50.0), None);
    // The ,C block's own after-motion M05 comes after the chamfer.
    let r = run("S1000 M03\nG01 X50. ,C5. F300. M05\nY50.\n");
    ok(&r);
    let order: Vec<_> = r
        .events
        .iter()
        .filter_map(|e| match e.cmd {
            Canon::Spindle { .. } => Some((e.src.line, "spindle")),
            Canon::Feed { .. } => Some((e.src.line, "feed")),
            _ => None,
        })
        .collect();
    assert_eq!(
        order,
        [
            (2, "spindle"),
            (3, "feed"),
            (3, "feed"),
            (3, "spindle"),
            (4, "feed")
        ]
    );
}

#[test]
fn next_block_must_move_in_the_plane() {
    // The alarm points at the ,C/,R word (column 10 of line 2).
    let at = ("F_82103", 2, 10);
    for next in [
        "G00 Y50.\n",      // rapid
        "M30\n",           // end of program
        "M02\n",           //
        "",                // end of text
        "Z-5.\n",          // off the plane
        "Y50. Z-5.\n",     // a move with another axis
        "G18 Z-5. X60.\n", // another plane
        "G04 X1.\n",       // dwell
        "G28 Z0.\n",       // reference return
        "G92 X0.\n",       // coordinate setting
        "G53 Z0.\n",       // machine coordinates
        "M98 P100\n",      // call
        "M99\n",           // return (main program: jump to the start)
        "G65 P100\n",      // macro call
    ] {
        let r = run(&format!("G01 X50. ,R5. F300.\n{next}O100\nM99\n"));
        assert_eq!(alarm(&r), at, "next block {next:?}");
        // Nothing of the held move was emitted.
        assert_eq!(path(&r).len(), 1, "next block {next:?}");
    }
}

#[test]
fn a_corner_block_must_be_a_plane_move() {
    // ,C in a G00 block, in a block without a move, with a Z move, in a
    // G04 block, in a G65 block: at the ,C word.
    assert_eq!(alarm(&run("G00 X50. ,C5.\nY50.\n")), ("F_82103", 2, 10));
    assert_eq!(alarm(&run("G01 F100. ,C5.\nY50.\n")), ("F_82103", 2, 11));
    assert_eq!(
        alarm(&run("G01 X50. Z-1. ,C5. F100.\nY50.\n")),
        ("F_82103", 2, 15)
    );
    assert_eq!(alarm(&run("G04 X1. ,C5.\n")), ("F_82103", 2, 9));
    assert_eq!(alarm(&run("G65 P100 ,C5.\n")), ("F_82103", 2, 10));
    // Both ,C and ,R; ,C twice; a negative value.
    assert_eq!(
        alarm(&run("G01 X50. ,C5. ,R5. F100.\nY50.\n")),
        ("F_82105", 2, 15)
    );
    assert_eq!(
        alarm(&run("G01 X50. ,C5. ,C5. F100.\nY50.\n")),
        ("F_82006", 2, 15)
    );
    assert_eq!(
        alarm(&run("G01 X50. ,C-5. F100.\nY50.\n")),
        ("F_82007", 2, 10)
    );
    // ,C0 is no chamfer: a plain move, nothing held.
    let r = run("G01 X50. ,C0 F100.\nM30\n");
    ok(&r);
    check(&path(&r)[1], "feed", 2, (50.0, 0.0), None);
    // The lathes have no ,C/,R (G01 I/K/R chamfers are another function).
    assert_eq!(
        alarm(&run_on("puma-lathe", "G01 X50. ,C5. F1.\n")),
        ("PS009", 1, 10)
    );
}

#[test]
fn corner_must_fit() {
    let at = ("F_82104", 2, 10);
    // C5 longer than the 4 mm first block, or than the 4 mm next block.
    assert_eq!(alarm(&run("G01 X4. ,C5. F100.\nY50.\n")), ("F_82104", 2, 9));
    assert_eq!(alarm(&run("G01 X50. ,C5. F100.\nY4.\n")), at);
    // R5 at a right angle needs 5 mm of each.
    assert_eq!(alarm(&run("G01 X50. ,R5. F100.\nY4.\n")), at);
    // Straight on: no corner.
    assert_eq!(alarm(&run("G01 X50. ,R5. F100.\nX60.\n")), at);
    // A chord longer than the diameter of the next arc (radius 1).
    assert_eq!(alarm(&run("G01 X50. ,C3. F100.\nG02 X52. I1.\n")), at);
    // Exactly the length of the next block fits.
    ok(&run("G01 X50. ,C4. F100.\nY4.\n"));
}

#[test]
fn tool_or_coordinate_change_in_between() {
    let r = run("T2\nG01 X50. ,C5. F300.\nM06\nY50.\n");
    assert_eq!(alarm(&r), ("F_82105", 3, 10));
    // Another work system with another origin in between.
    let mut it = Interp::new(Profile::builtin("hx-mc").unwrap(), Settings::default());
    it.set_work_offset(1, [-300.0, -200.0, -250.0, 0.0, 0.0, 0.0]);
    it.load_main(
        "t.nc",
        Box::new(std::io::Cursor::new(
            format!("{START}G01 X50. ,C5. F300.\nG55\nY50.\n").into_bytes(),
        )),
    );
    let a = loop {
        match it.step() {
            Step::Event(_) => {}
            Step::End => panic!("no alarm"),
            Step::Alarm(a) => break a,
        }
    };
    assert_eq!((a.code.as_str(), a.src.line, a.src.col), ("F_82105", 2, 10));
}

#[test]
fn overtravel_of_the_trimmed_move_points_at_its_block() {
    // Work X400 is machine X0, the + end of travel: the first part of the
    // chamfered move ends at X403.
    let r = run_text(
        Profile::builtin("hx-mc").unwrap(),
        Settings::default(),
        "t.nc",
        "G90 G54 G00 X390. Y0. Z0.\nG01 X405. ,C2. F100.\nY-50.\n",
    );
    let a = r.alarm.expect("overtravel");
    assert_eq!((a.code.as_str(), a.src.line), ("F_84100", 2));
}
