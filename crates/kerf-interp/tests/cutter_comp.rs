//! Cutter radius compensation C on the HX (000 §13.2.2) and tool nose
//! radius compensation on the lathes: the compensated points worked out by
//! hand in the comments (offset lines, circle radii ± r, unit normals),
//! the alarms with their positions, and property tests against an
//! independent distance computation.

use kerf_canon::{ArcDir, Canon, Event};
use kerf_interp::{Interp, Profile, Run, Settings};

mod common;
use common::{alarm, ok, run_on};

/// Runs `text` on a built-in machine after setting D offsets (mill) or
/// lathe offsets (n, r, tip).
fn run_d(machine: &str, d: &[(usize, f64)], lathe: &[(usize, f64, u8)], text: &str) -> Run {
    run_p(wide(machine), d, lathe, text)
}

/// A built-in profile with travel wide enough for any test contour.
fn wide(machine: &str) -> Profile {
    let mut p = Profile::builtin(machine).unwrap();
    for a in p.axes.values_mut() {
        a.min = -1e4;
        a.max = 1e4;
    }
    p
}

fn run_p(p: Profile, d: &[(usize, f64)], lathe: &[(usize, f64, u8)], text: &str) -> Run {
    let mut it = Interp::new(p, Settings::default());
    for &(n, v) in d {
        it.offsets_mut().d_mut(n).unwrap().geom = v;
    }
    for &(n, r, tip) in lathe {
        let o = it.offsets_mut().lathe_mut(n).unwrap();
        o.r = r;
        o.tip = tip;
    }
    kerf_interp::run_interp(it, "t.nc", text)
}

/// A motion: kind, line, end (work X, Y, Z), arc centre (X, Y) and CW?
#[derive(Debug, Clone)]
struct Mv {
    kind: &'static str,
    line: u32,
    to: [f64; 3],
    center: Option<(f64, f64, bool)>,
}

fn path(r: &Run) -> Vec<Mv> {
    r.events.iter().filter_map(mv).collect()
}

fn mv(e: &Event) -> Option<Mv> {
    let (kind, center) = match &e.cmd {
        Canon::Rapid { .. } => ("rapid", None),
        Canon::Feed { .. } => ("feed", None),
        Canon::Arc { center, dir, .. } => ("arc", Some((center[0], center[1], *dir == ArcDir::Cw))),
        _ => return None,
    };
    let m = e.motion()?;
    Some(Mv {
        kind,
        line: e.src.line,
        to: [m.to[0], m.to[1], m.to[2]],
        center,
    })
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() < 1e-6
}

/// Checks the moves' kinds and plane end points (X, Y) in order.
fn check_xy(got: &[Mv], want: &[(&str, f64, f64)]) {
    assert_eq!(got.len(), want.len(), "moves: {got:#?}\nwanted {want:#?}");
    for (i, (g, w)) in got.iter().zip(want).enumerate() {
        assert!(
            g.kind == w.0 && close(g.to[0], w.1) && close(g.to[1], w.2),
            "move {i}: got {g:?}, wanted {w:?}"
        );
    }
}

/// 000 §13.2.2 example N1-N12 (D08 = 5 here; the manual's value is not
/// readable). Programmed contour from (0,0): N1 to (20,20), N3 (20,60),
/// N5 (60,80), N7 CW R40 to (100,40) — centre (60,40): the chord
/// (40,-40) has its midpoint (80,60), half-length 20√2, and the centre
/// lies 20√2 to its right, at (60,40) —, N8 CW R20 to (80,20) — centre
/// (80,40) likewise —, N9 to (20,20), N11 back to (0,0). G41, r = 5,
/// s = 1/√5:
/// - N1 start-up, inner corner (left turn of 45° with G41): ends on the
///   vector perpendicular to N3 at its start: (20-5, 20) = (15, 20);
/// - N2 Z-25 there; N3 to (15, 60) (offset line x = 15);
/// - G39 (direction (40,20)): CW arc about (20,60) from (15,60) to
///   (20,60) + 5·(-1,2)s = (17.763932, 64.472136);
/// - N5 to (60,80) + 5·(-1,2)s = (57.763932, 84.472136);
/// - G39 (direction (40,-20)): CW arc about (60,80) to (60,80) +
///   5·(1,2)s = (62.236068, 84.472136), then straight to N7's start
///   vector (60, 85);
/// - N7 CW about (60,40), radius 45, to (105, 40); N8 tangent: about
///   (80,40) radius 25 from (105,40) to (80, 15);
/// - N9 to (20, 15); N10 Z+25 there; N11 cancel: the corner N9 → N11
///   turns left (inner for G41): N9 ends on its perpendicular vector, N11
///   runs to (0, 0) uncompensated.
#[test]
fn manual_example_13_2_2() {
    let prog = "G92 X0. Y0. Z0.\n\
        N1 G91 G17 G00 G41 X20. Y20. D08\n\
        N2 G01 Z-25. F100\n\
        N3 Y40. F250\n\
        N4 G39 X40. Y20.\n\
        N5 X40. Y20.\n\
        N6 G39 X40. Y-20.\n\
        N7 G02 X40. Y-40. R40.\n\
        N8 X-20. Y-20. R20.\n\
        N9 G01 X-60.\n\
        N10 G00 Z25.\n\
        N11 G40 X-20. Y-20.\n\
        N12 M30\n";
    let r = run_d("hx-mc", &[(8, 5.0)], &[], prog);
    ok(&r);
    let s = 1.0 / 5f64.sqrt();
    let p = path(&r);
    check_xy(
        &p,
        &[
            ("rapid", 15.0, 20.0),
            ("feed", 15.0, 20.0),
            ("feed", 15.0, 60.0),
            ("arc", 20.0 - 5.0 * s, 60.0 + 10.0 * s),
            ("feed", 60.0 - 5.0 * s, 80.0 + 10.0 * s),
            ("arc", 60.0 + 5.0 * s, 80.0 + 10.0 * s),
            ("feed", 60.0, 85.0),
            ("arc", 105.0, 40.0),
            ("arc", 80.0, 15.0),
            ("feed", 20.0, 15.0),
            ("rapid", 20.0, 15.0),
            ("rapid", 0.0, 0.0),
        ],
    );
    // Z: down at N2, up at N10.
    assert!(close(p[1].to[2], -25.0) && close(p[10].to[2], 0.0));
    // Arc centres and directions: G39 arcs about the programmed corners,
    // N7/N8 about their own centres, all CW.
    let c: Vec<_> = p.iter().filter_map(|m| m.center).collect();
    let want = [(20.0, 60.0), (60.0, 80.0), (60.0, 40.0), (80.0, 40.0)];
    assert_eq!(c.len(), 4);
    for (g, w) in c.iter().zip(want) {
        assert!(close(g.0, w.0) && close(g.1, w.1) && g.2, "{g:?} vs {w:?}");
    }
    // Attribution: N1's rapid is line 2, N2's Z move line 3, N11's move
    // line 12.
    assert_eq!((p[0].line, p[1].line, p[11].line), (2, 3, 12));
    // The programmed points ride along (Event::prog): N3 ends at (20,60),
    // N2's Z move at (20,20,-25); the cancel move's end is programmed
    // as it is, so it carries none.
    let moves: Vec<_> = r.events.iter().filter(|e| e.motion().is_some()).collect();
    let pr = |i: usize| *moves[i].prog.clone().expect("a programmed point");
    assert!(close(pr(2)[0], 20.0) && close(pr(2)[1], 60.0));
    assert!(close(pr(1)[0], 20.0) && close(pr(1)[1], 20.0) && close(pr(1)[2], -25.0));
    assert!(moves[11].prog.is_none());
}

/// Square pocket-free outside contour, G41 and G42, with start-up and
/// cancel (type A, the HX default PI 128 = 0).
#[test]
fn square_outside_g42_and_inside_g41() {
    // CCW square (0,0)-(40,0)-(40,30)-(0,30) from (-10,-10): G42 puts the
    // tool outside (right of a CCW contour), r = 4.
    // Start-up N2 → N3 (+X): S direction (10,10): turn −45° (right), G42:
    // inner → perpendicular to N3 at (0,0): right normal (0,-1) → (0,-4).
    // Corners outside (left turns, tool on the right): offset lines
    // y=-4 & x=44 → (44,-4); x=44 & y=34 → (44,34); y=34 & x=-4 →
    // (-4,34); the last side x=-4 down to the cancel: N7 G40 to (-10,-10)
    // turns ... (0,-1) → (-10,-10)-(0,0) = (-1,-1): turn −45° → right,
    // G42 side −1: inner → N6 ends on its perpendicular (-4, 0).
    let prog = "G92 X-10. Y-10.\nG90 G00 G42 X0. Y0. D1\nG01 X40. F500\nY30.\nX0.\nY0.\nG40 G00 X-10. Y-10.\nM30\n";
    let r = run_d("hx-mc", &[(1, 4.0)], &[], prog);
    ok(&r);
    check_xy(
        &path(&r),
        &[
            ("rapid", 0.0, -4.0),
            ("feed", 44.0, -4.0),
            ("feed", 44.0, 34.0),
            ("feed", -4.0, 34.0),
            ("feed", -4.0, 0.0),
            ("rapid", -10.0, -10.0),
        ],
    );
    // G41 on the same contour: inside; corners are the offset lines'
    // intersections (4,4)... first side y=4 from the start-up point.
    // Start-up: turn −45° with G41 (side +1): outer (right turn, tool on
    // the left) obtuse; type A: perpendicular to N3: (0, 4).
    let prog = "G92 X-10. Y-10.\nG90 G00 G41 X0. Y0. D1\nG01 X40. F500\nY30.\nX0.\nY0.\nG40 G00 X-10. Y-10.\nM30\n";
    let r = run_d("hx-mc", &[(1, 4.0)], &[], prog);
    ok(&r);
    // Cancel: N6 direction (0,-1) → (-1,-1): right turn, G41: outer;
    // type A: N6 ends on its perpendicular (0+4, 0) = (4, 0).
    check_xy(
        &path(&r),
        &[
            ("rapid", 0.0, 4.0),
            ("feed", 36.0, 4.0),
            ("feed", 36.0, 26.0),
            ("feed", 4.0, 26.0),
            ("feed", 4.0, 0.0),
            ("rapid", -10.0, -10.0),
        ],
    );
}

/// Type B start-up (PI 128 = 1) on an outer obtuse corner: the start-up
/// line's offset line and the next block's offset line meet.
#[test]
fn type_b_startup_and_cancel() {
    // From (-10,-10) to (0,0) then +X, G41 r = 4: right turn of 45°, tool
    // on the left: outer obtuse. S's offset line: through (0,0) +
    // 4·(-1,1)/√2 with direction (1,1)/√2, i.e. y = x + 4√2; N3's offset
    // line y = 4 → x = 4 − 4√2.
    let mut p = wide("hx-mc");
    p.params.insert("PI 128".into(), 1.0);
    let prog = "G92 X-10. Y-10.\nG90 G01 G41 X0. Y0. D1 F500\nX40.\nG40 X50. Y-10.\nM30\n";
    let r = run_p(p, &[(1, 4.0)], &[], prog);
    ok(&r);
    let q = 4.0 * 2f64.sqrt();
    // Cancel N3 (+X) → (10,-10): right turn 45°, G41: outer obtuse, type
    // B: N3's offset line y = 4 meets the G40 line's offset line: the
    // G40 line from (40,0) direction (1,-1)/√2 offset left by 4 →
    // through (40,0) + 4·(1,1)/√2; points (40+2√2+t, 2√2−t): y = 4 at
    // t = 2√2 − 4 → x = 40 + 4√2 − 4.
    check_xy(
        &path(&r),
        &[
            ("feed", 4.0 - q, 4.0),
            ("feed", 40.0 + q - 4.0, 4.0),
            ("feed", 50.0, -10.0),
        ],
    );
}

/// Acute outside corner: the two extension vectors.
#[test]
fn acute_corner_extension_vectors() {
    // (0,0) → (40,0) → (0,20): the turn at (40,0) is to the left by
    // 180° − atan(20/40); G42 (tool right, outside), r = 2.
    // t1 = (1,0), t2 = (-40,20)/√2000 = (-2,1)/√5.
    // P1 = (40,-2); E1 = P1 + 2·t1 = (42,-2). P2 = (40,0) + 2·right(t2)
    // = (40,0) + 2·(1,2)/√5; E2 = P2 − 2·t2 = (40 + 2/√5 + 4/√5,
    // 4/√5 − 2/√5) = (40 + 6/√5, 2/√5).
    let s = 1.0 / 5f64.sqrt();
    let prog = "G92 X0. Y-10.\nG90 G01 G42 X0. Y0. D1 F500\nX40.\nX0. Y20.\nG40 X0. Y40.\nM30\n";
    let r = run_d("hx-mc", &[(1, 2.0)], &[], prog);
    ok(&r);
    let p = path(&r);
    // Start-up: (0,-10) → (0,0) then +X: right turn 90°, G42 (side −1):
    // inner → perpendicular to N3: (0,-2).
    assert!(close(p[0].to[0], 0.0) && close(p[0].to[1], -2.0), "{p:?}");
    assert!(close(p[1].to[0], 42.0) && close(p[1].to[1], -2.0), "{p:?}");
    assert!(
        close(p[2].to[0], 40.0 + 6.0 * s) && close(p[2].to[1], 2.0 * s),
        "{p:?}"
    );
}

/// Alarms: start-up in G02, plane change, D out of range, inside arc
/// smaller than the offset, G39 outside offset mode.
#[test]
fn alarms() {
    let a = |r: &Run| {
        let a = r.alarm.as_ref().expect("an alarm");
        (a.code.clone(), a.src.line, a.src.col)
    };
    // Start-up in a G02 block: at the G02 (line 2, column 1).
    let r = run_d(
        "hx-mc",
        &[(1, 2.0)],
        &[],
        "G92 X0. Y0.\nG02 G41 X10. Y0. R5. D1 F100\nM30\n",
    );
    assert_eq!(a(&r), ("F_82120".into(), 2, 1));
    // Plane change in offset mode: at the G18 (line 3, column 1).
    let r = run_d(
        "hx-mc",
        &[(1, 2.0)],
        &[],
        "G92 X0. Y0.\nG01 G41 X10. D1 F100\nG18 X20.\nM30\n",
    );
    assert_eq!(a(&r), ("F_82121".into(), 3, 1));
    // D out of range (HX has 128): at the D word, column 14.
    let r = run_d(
        "hx-mc",
        &[],
        &[],
        "G92 X0. Y0.\nG01 G41 X10. D200 F100\nM30\n",
    );
    assert_eq!(a(&r).1, 2);
    assert_eq!(a(&r).2, 14);
    // Inside arc of radius 5 with offset 6: G41 on a CCW arc (centre on
    // the left, the tool inside): at the G03 block's motion word.
    let r = run_d(
        "hx-mc",
        &[(1, 6.0)],
        &[],
        "G92 X0. Y0.\nG01 G41 X10. D1 F100\nG03 X20. R5.\nG01 X30.\nM30\n",
    );
    assert_eq!(a(&r), ("F_82122".into(), 3, 1));
    // A groove narrower than the tool: 4 wide, r = 3, G41 inside it —
    // (0,0)→(10,0)→(10,4)→(0,4): N4's compensated move would run +X.
    let r = run_d(
        "hx-mc",
        &[(1, 3.0)],
        &[],
        "G92 X-10. Y0.\nG01 G42 X0. Y0. D1 F100\nX10.\nY-4.\nX0.\nG40 X-10.\nM30\n",
    );
    assert_eq!(a(&r).0, "F_82122");
    // G39 outside offset mode: at the G39.
    let r = run_d("hx-mc", &[], &[], "G92 X0. Y0.\nG39 I1. J0.\nM30\n");
    assert_eq!(a(&r), ("F_82124".into(), 2, 1));
    // PUMA codes: start-up in G02 is PS034.
    let r = run_d(
        "puma-lathe",
        &[],
        &[(1, 0.8, 3)],
        "T0101\nG02 G42 X20. Z-10. R10. F0.2\nM30\n",
    );
    assert_eq!(a(&r).0, "PS034");
}

// ---- properties ------------------------------------------------------------

use proptest::prelude::*;

/// Distance from `p` to the segment a-b (independent of the code under
/// test: projection clamped to the segment).
fn seg_dist(p: (f64, f64), a: (f64, f64), b: (f64, f64)) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let l2 = dx * dx + dy * dy;
    let t = (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / l2).clamp(0.0, 1.0);
    (p.0 - a.0 - t * dx).hypot(p.1 - a.1 - t * dy)
}

/// Distance from `p` to the infinite line through a-b.
fn line_dist(p: (f64, f64), a: (f64, f64), b: (f64, f64)) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    ((p.0 - a.0) * dy - (p.1 - a.1) * dx).abs() / dx.hypot(dy)
}

/// Even-odd point-in-polygon.
fn inside(p: (f64, f64), poly: &[(f64, f64)]) -> bool {
    let mut c = false;
    for i in 0..poly.len() {
        let (a, b) = (poly[i], poly[(i + 1) % poly.len()]);
        if (a.1 > p.1) != (b.1 > p.1) && p.0 < a.0 + (p.1 - a.1) * (b.0 - a.0) / (b.1 - a.1) {
            c = !c;
        }
    }
    c
}

/// A star-shaped polygon, counter-clockwise: vertex i at angle
/// 2πi/n + jitter and radius 30..60 (concave where a radius dips).
fn polygon() -> impl Strategy<Value = Vec<(f64, f64)>> {
    (5usize..10).prop_flat_map(|n| {
        prop::collection::vec((30.0f64..60.0, -0.25f64..0.25), n).prop_map(move |v| {
            v.iter()
                .enumerate()
                .map(|(i, (r, j))| {
                    let a = (i as f64 + j) * std::f64::consts::TAU / n as f64;
                    (r * a.cos(), r * a.sin())
                })
                .collect()
        })
    })
}

/// A program that goes twice round `poly` (in the given order) with
/// G41/G42 D1, from a start point far outside.
fn contour_prog(poly: &[(f64, f64)], g: u32) -> String {
    let mut s = String::from("G92 X100. Y0.\nG90 G01 F1000\n");
    let v0 = poly[0];
    s += &format!("G{g} X{:.6} Y{:.6} D1\n", v0.0, v0.1);
    for _ in 0..2 {
        for p in poly.iter().skip(1).chain(std::iter::once(&v0)) {
            s += &format!("X{:.6} Y{:.6}\n", p.0, p.1);
        }
    }
    s += "G40 X100. Y0.\nM30\n";
    s
}

/// The compensated points of a run at the contour's corners: the first
/// move (start-up), the last contour block's end (its vector belongs to
/// the cancel, perpendicular to that block) and the cancel move left out.
fn comp_points(r: &Run) -> Vec<(f64, f64)> {
    let p = path(r);
    p[1..p.len() - 2]
        .iter()
        .map(|m| (m.to[0], m.to[1]))
        .collect()
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

    /// Every compensated vertex is at least r from the contour, at
    /// exactly r from the line of one of its edges, and on the correct
    /// side (G41 on a CCW contour: inside; G42: outside) — unless the
    /// control stopped with its interference alarm before the move.
    #[test]
    fn offset_keeps_distance_and_side(poly in polygon(), r in 0.5f64..3.0, left in any::<bool>()) {
        let g = if left { 41 } else { 42 };
        let run = run_d("hx-mc", &[(1, r)], &[], &contour_prog(&poly, g));
        if let Some(a) = &run.alarm {
            prop_assert_eq!(a.code.as_str(), "F_82122");
            return Ok(());
        }
        let n = poly.len();
        for p in comp_points(&run) {
            let d = (0..n).map(|i| seg_dist(p, poly[i], poly[(i + 1) % n])).fold(f64::INFINITY, f64::min);
            prop_assert!(d >= r - 1e-6, "{:?} at {} < r {}", p, d, r);
            let on_line = (0..n).any(|i| (line_dist(p, poly[i], poly[(i + 1) % n]) - r).abs() < 1e-6);
            prop_assert!(on_line, "{:?} is on no offset line", p);
            prop_assert_eq!(inside(p, &poly), left, "{:?} on the wrong side", p);
        }
    }

    /// G41 on a contour makes the same corner points as G42 on the
    /// reversed contour (vertices other than the start).
    #[test]
    fn g41_equals_g42_reversed(poly in polygon(), r in 0.5f64..3.0) {
        let mut rev = poly.clone();
        rev[1..].reverse();
        let a = run_d("hx-mc", &[(1, r)], &[], &contour_prog(&poly, 41));
        let b = run_d("hx-mc", &[(1, r)], &[], &contour_prog(&rev, 42));
        prop_assert_eq!(a.alarm.is_some(), b.alarm.is_some());
        if a.alarm.is_some() {
            return Ok(());
        }
        let v0 = poly[0];
        let away = |p: &(f64, f64)| (p.0 - v0.0).hypot(p.1 - v0.1) > 4.0 * r;
        let pa: Vec<_> = comp_points(&a).into_iter().filter(away).collect();
        let pb: Vec<_> = comp_points(&b).into_iter().filter(away).collect();
        let has = |v: &[(f64, f64)], p: &(f64, f64)| v.iter().any(|q| (q.0 - p.0).hypot(q.1 - p.1) < 1e-6);
        for p in &pa {
            prop_assert!(has(&pb, p), "{:?} missing from the G42 run", p);
        }
        for p in &pb {
            prop_assert!(has(&pa, p), "{:?} missing from the G41 run", p);
        }
    }

    /// Arcs: a line, a random arc (CW or CCW, radius 10..40), a line; the
    /// compensated arc ends on the circle of radius R ∓ r about the same
    /// centre (computed here from the chord), at the perpendicular
    /// points.
    #[test]
    fn arc_offset_radius(rad in 10.0f64..40.0, ccw in any::<bool>(), left in any::<bool>(), r in 0.5f64..5.0) {
        // Arc from (0,0) to (2R·sin45°, 0)... a quarter-ish chord: end at
        // (R, R) relative to the start with radius R (centre on the
        // chosen side).
        let (g2, gside) = (if ccw { 3 } else { 2 }, if left { 41 } else { 42 });
        let prog = format!(
            "G92 X0. Y-20.\nG90 G01 G{gside} X0. Y0. D1 F1000\nG{g2} X{:.6} Y{:.6} R{:.6}\nG01 X{:.6} Y{:.6}\nG40 X100. Y100.\nM30\n",
            rad, rad, rad, rad + 5.0, rad + 5.0
        );
        let run = run_d("hx-mc", &[(1, r)], &[], &prog);
        // Centre of the minor arc from (0,0) to (R,R) of radius R: (R,0)
        // or (0,R) (both at distance R from the two points); CW turns
        // right of the chord direction (1,1), i.e. towards (R,0); CCW
        // left, towards (0,R).
        let c = if ccw { (0.0, rad) } else { (rad, 0.0) };
        // A left offset shrinks a CCW arc (the centre on the left).
        let rho = if ccw == left { rad - r } else { rad + r };
        if let Some(a) = &run.alarm {
            prop_assert_eq!(a.code.as_str(), "F_82122");
            return Ok(());
        }
        let p = path(&run);
        let arc = p.iter().find(|m| m.kind == "arc").expect("an arc");
        let ac = arc.center.unwrap();
        prop_assert!(close(ac.0, c.0) && close(ac.1, c.1));
        prop_assert!(((arc.to[0] - c.0).hypot(arc.to[1] - c.1) - rho).abs() < 1e-6);
    }
}

// ---- lathe tool nose radius compensation -------------------------------------

/// 001's chamfer C2 on Ø30 (p.67 "Example 2": G42, the a/b values) with
/// nose R 0.5 and 0.8, tip 3 (OD turning towards the chuck). Contour
/// (Z, X radius): face up Z0 from Ø20 to Ø26, chamfer to (Z-2, Ø30),
/// Z-30, G40 out. Worked by hand in (Z, X) coordinates, G42 = right of
/// travel, tip 3 = the imaginary tip at centre + r·(−1, −1):
/// - start-up (−Z) then +X: a right turn with the tool on the right,
///   inner → the perpendicular vector of the face: centre (r, 10), tip
///   (0, 10 − r) → Ø(20 − 2r);
/// - face → chamfer: left turn, outer obtuse → offset lines Z = r and
///   Z + X − 13 = r√2 meet at X = 13 + r√2 − r; tip X = 13 − r(2 − √2)
///   → Ø(26 − a) with a = 2r(1 − tan 22.5°) (001: 0.937 for R0.8);
/// - chamfer → Z-30: left turn, outer obtuse → X = 15 + r and the chamfer
///   line give Z = −2 − r + r√2; tip Z = −2 − b, b = r(1 − tan 22.5°)
///   (001: 0.468 for R0.8), X = Ø30;
/// - cancel (+X after −Z): right turn, inner → perpendicular: centre
///   (−30, 15 + r), tip (−30 − r, 15); then the rapid to Ø40 at Z−30.
#[test]
fn puma_chamfer_example_nose_radius() {
    let t = (22.5f64).to_radians().tan();
    // 001's table (printed truncated to 3 decimals), against the formula
    // used below.
    assert!((2.0 * 0.8 * (1.0 - t) - 0.937).abs() < 1e-3);
    assert!((0.8 * (1.0 - t) - 0.468).abs() < 1e-3);
    for r in [0.5, 0.8] {
        let prog =
            "G00 X20. Z1. T0101\nG42 G01 Z0 F0.2\nX26.\nX30. Z-2.\nZ-30.\nG40 G00 X40.\nM30\n";
        let run = run_d("puma-lathe", &[], &[(1, r, 3)], prog);
        ok(&run);
        let p = path(&run);
        let (a, b) = (2.0 * r * (1.0 - t), r * (1.0 - t));
        // (diameter X, Z) of each move after the approach.
        let want = [
            (20.0 - 2.0 * r, 0.0),
            (26.0 - a, 0.0),
            (30.0, -2.0 - b),
            (30.0, -30.0 - r),
            (40.0, -30.0),
        ];
        assert_eq!(p.len(), 6, "{p:#?}");
        for (m, w) in p[1..].iter().zip(want) {
            // Motion X is a radius inside kerf.
            assert!(
                close(2.0 * m.to[0], w.0) && close(m.to[2], w.1),
                "r {r}: got {m:?}, wanted Ø{} Z{}",
                w.0,
                w.1
            );
        }
    }
}

/// Tip 0 (and 9): the programmed point is the nose centre; tip 8 (−X):
/// only X shifts. A straight Z cut at Ø30 with G42, r = 0.4, from Z0 to
/// Z-10 after a start-up in −X from Ø40: the start-up turns from −X to
/// −Z (a right turn: (Z,X) (0,−1) → (−1,0), cross = −1), G42: inner →
/// perpendicular to the Z cut: centre (0, 15.4); the cut ends at
/// (−10, 15.4) before the cancel (+X: right turn again, inner).
#[test]
fn tip_directions_shift_the_control_point() {
    for (tip, dz, dx) in [
        (0u8, 0.0, 0.0),
        (9, 0.0, 0.0),
        (8, 0.0, -0.4),
        (3, -0.4, -0.4),
    ] {
        let prog = "G00 X40. Z0 T0101\nG42 G01 X30. F0.2\nZ-10.\nG40 G00 X50.\nM30\n";
        let run = run_d("puma-lathe", &[], &[(1, 0.4, tip)], prog);
        ok(&run);
        let p = path(&run);
        let z_cut = &p[2];
        assert!(
            close(z_cut.to[0], 15.4 + dx) && close(z_cut.to[2], -10.0 + dz),
            "tip {tip}: {z_cut:?}"
        );
    }
}

/// 000 §15.4.2 (N1-N8): rotation commanded and cancelled in offset mode.
/// D01 = 100 here (the manual's value is not readable). G42 (right of
/// travel), r = 100, type A start-up and cancel. N3 rotates by −30°
/// about the current point (1000, 1000); c = cos 30° = √3/2, s = 1/2.
/// Worked in the program frame relative to (1000, 1000), then rotated
/// (u, v) → (u·c + v·s, −u·s + v·c) + (1000, 1000):
/// - N2 start-up (0,0) → (1000,1000), the next block is N4: type A ends
///   on the vector perpendicular to N4 at its start: N4 runs along
///   (c, −s) in the work frame, its right normal is (−s, −c), so
///   (1000 − 50, 1000 − 50√3) = (950, 913.397460);
/// - N4 (program (0,0) → (2000,0) in the frame) and N5 (CCW semicircle
///   about (2000,500), radius 500, starting at its bottom moving +u) are
///   tangent: the offset line v = −100 meets the offset circle (radius
///   500 + 100: right of a CCW arc is outside) at (2000, −100) →
///   (2000c − 50, −1000 − 50√3) + (1000,1000) = (2682.050808, −86.602540);
/// - N5 ends on its circle at the top (2000, 1100), tangent to N6 (−u):
///   → (2000c + 550, −1000 + 1100c) + (1000,1000)
///   = (3282.050808, 952.627944), about the rotated centre
///   (2000c + 250, −1000 + 250√3) + (1000,1000) = (2982.050808, 433.012702);
/// - N6 → N7 turns left (−u then −v) with the tool on the right: outer
///   obtuse (90°): the offset lines v = 1100 and u = −100 meet at
///   (−100, 1100) → (−50√3 + 550, 50 + 1100c) + (1000,1000)
///   = (1463.397460, 2002.627944);
/// - N8 cancels (G69 in the same block: the G40 line runs unrotated to
///   (0,0)); type A: N7 ends on its perpendicular vector at (−100, 0) in
///   the frame → (1000 − 50√3, 1000 + 50) = (913.397460, 1050), then the
///   straight move to (0, 0).
#[test]
fn manual_15_4_2_rotation_in_offset_mode() {
    let prog = "N1 G92 X0 Y0 G69 G01\n\
        N2 G42 G90 X1000. Y1000. F100 D01\n\
        N3 G68 R-30.0\n\
        N4 G91 X2000.0\n\
        N5 G3 Y1000.0 J500.\n\
        N6 G1 X-2000.\n\
        N7 Y-1000.\n\
        N8 G69 G40 G90 X0 Y0 M30\n";
    let r = run_d("hx-mc", &[(1, 100.0)], &[], prog);
    ok(&r);
    let h = 50.0 * 3f64.sqrt();
    let c = 3f64.sqrt() / 2.0;
    let p = path(&r);
    check_xy(
        &p,
        &[
            ("feed", 950.0, 1000.0 - h),
            ("feed", 1000.0 + 2000.0 * c - 50.0, -h),
            ("arc", 2000.0 + 2000.0 * c + 550.0 - 1000.0, 1100.0 * c),
            ("feed", 1550.0 - h, 1050.0 + 1100.0 * c),
            ("feed", 1000.0 - h, 1050.0),
            ("feed", 0.0, 0.0),
        ],
    );
    let (cx, cy, cw) = p[2].center.unwrap();
    assert!(close(cx, 1000.0 + 2000.0 * c + 250.0) && close(cy, 250.0 * 3f64.sqrt()) && !cw);
    // Attribution: the arc is N5 (line 5), the cancel move N8 (line 8).
    assert_eq!((p[2].line, p[5].line), (5, 8));
}

/// Scaling before G41/G42 (000 §15.4.2 order): the path is scaled, the
/// offset is not. The square of `square_outside_g42_and_inside_g41`
/// programmed at half size under ×2 about (0,0) gives exactly that test's
/// points for r = 4 (the offset lines 4 from the scaled sides).
#[test]
fn scaling_scales_the_path_not_the_offset() {
    let prog = "G92 X-10. Y-10.\nG51 X0 Y0 P2000\nG90 G00 G42 X0. Y0. D1\nG01 X20. F500\nY15.\nX0.\nY0.\nG40 G00 X-5. Y-5.\nG50\nM30\n";
    let r = run_d("hx-mc", &[(1, 4.0)], &[], prog);
    ok(&r);
    let want = [
        ("rapid", 0.0, -4.0),
        ("feed", 44.0, -4.0),
        ("feed", 44.0, 34.0),
        ("feed", -4.0, 34.0),
        ("feed", -4.0, 0.0),
        ("rapid", -10.0, -10.0),
    ];
    check_xy(&path(&r), &want);
    // Mirror image of X (I-1000, 000 §15.3) reverses the side: the
    // contour (0,0) → (−40,0) → (−40,30) → (0,30) → (0,0) is clockwise,
    // G41 puts the tool outside it; mirrored it is the CCW square above
    // with the tool outside, i.e. the same points as G42 there.
    let prog = "G92 X-10. Y-10.\nG51 X0 Y0 I-1000 J1000\nG90 G00 G41 X0. Y0. D1\nG01 X-40. F500\nY30.\nX0.\nY0.\nG40 G00 X10. Y-10.\nG50\nM30\n";
    let r = run_d("hx-mc", &[(1, 4.0)], &[], prog);
    ok(&r);
    check_xy(&path(&r), &want);
}

#[test]
fn transform_alarms_in_offset_mode() {
    // Scaling commanded inside G41/G42 breaks 000 §15.4.2's order (G51
    // before G41, G50 after G40): F_82210 at the G51 (line 4, column 1).
    let r = run_on(
        "hx-mc",
        "#2112 = 5.\nG90 G54 G00 X0 Y0 Z0\nG42 G01 X100. Y100. D1 F100.\nG51 X0 Y0 P2000\n",
    );
    assert_eq!(alarm(&r), ("F_82210", 4, 1));
    let r = run_on(
        "hx-mc",
        "#2112 = 5.\nG51 X0 Y0 P2000\nG01 G41 X10. Y0 D1 F100.\nX20.\nG50\n",
    );
    assert_eq!(alarm(&r), ("F_82210", 5, 1));
    // G50 with the G40 in the same block is in order.
    let r = run_on(
        "hx-mc",
        "#2112 = 5.\nG51 X0 Y0 P2000\nG01 G41 X10. Y0 D1 F100.\nX20.\nG50 G40 X30.\nM30\n",
    );
    assert!(r.alarm.is_none(), "{:?}", r.alarm);
    // G28 in rotation stays refused (000 §15.4.1) also in offset mode.
    let r = run_on(
        "hx-mc",
        "#2112 = 5.\nG68 X0 Y0 R90.\nG41 G01 X10. D1 F100.\nG28 X0\n",
    );
    assert_eq!(alarm(&r), ("F_82210", 4, 1));
}

// ---- ,C / ,R in offset mode (000 §4.3) ----------------------------------------

/// The chamfer is cut in the programmed contour, then compensated like any
/// other path. Contour from (0,0): +X to (40,0) with ,C5, +Y to (40,30),
/// −X to (0,30); G41 (inside this CCW contour), r = 2, type A.
/// Programmed chamfer: (35,0) → (40,5), direction (1,1)/√2, left normal
/// (−1,1)/√2, so its offset line is x − y = 35 − 2√2.
/// - start-up (0,−10) → (0,0), then +X: a right turn with the tool on the
///   left (outer), type A: perpendicular to the next block: (0, 2);
/// - first side y = 2 meets the chamfer's offset line (left turn of 45°,
///   inner): x = 37 − 2√2 = 34.171573;
/// - the chamfer's offset line meets x = 38 (inner): y = 3 + 2√2;
/// - x = 38 meets y = 28 (inner): (38, 28);
/// - cancel G40 to (0,40): +Y after −X is a right turn, tool left: outer,
///   type A: the −X side ends on its perpendicular (0, 28).
#[test]
fn chamfer_in_offset_mode() {
    let prog = "G92 X0. Y-10.\nG90 G01 G41 X0. Y0. D1 F500\nX40. ,C5.\nY30.\nX0.\nG40 Y40.\nM30\n";
    let r = run_d("hx-mc", &[(1, 2.0)], &[], prog);
    ok(&r);
    let q = 2.0 * 2f64.sqrt();
    let p = path(&r);
    check_xy(
        &p,
        &[
            ("feed", 0.0, 2.0),
            ("feed", 37.0 - q, 2.0),
            ("feed", 38.0, 3.0 + q),
            ("feed", 38.0, 28.0),
            ("feed", 0.0, 28.0),
            ("feed", 0.0, 40.0),
        ],
    );
    // The chamfer belongs to its block (line 3), the side after it to
    // line 4.
    assert_eq!((p[2].line, p[3].line), (3, 4));
}

/// Corner R in offset mode: the programmed fillet ,R5 at (40,0) has its
/// centre (35,5) and tangent points (35,0), (40,5) (CCW quarter). Same
/// contour as `chamfer_in_offset_mode`, r = 2:
/// - G41 (inside, the fillet centre's side): the fillet's offset circle
///   has radius 5 − 2 = 3; y = 2 touches it at (35, 2), x = 38 at (38, 5);
///   then (38, 28), (0, 28) as before;
/// - G42 (outside): radius 5 + 2 = 7: (35, −2), arc to (42, 5); the side
///   x = 42 meets y = 32 (left turn, tool right: outer obtuse) at
///   (42, 32); the cancel (+Y after −X, right turn, tool right: inner)
///   ends the top on its perpendicular (0, 32). Start-up: right turn with
///   the tool on the right (inner): perpendicular (0, −2).
#[test]
fn corner_round_in_offset_mode() {
    for (g, want) in [
        (
            41,
            [
                ("feed", 0.0, 2.0),
                ("feed", 35.0, 2.0),
                ("arc", 38.0, 5.0),
                ("feed", 38.0, 28.0),
                ("feed", 0.0, 28.0),
                ("feed", 0.0, 40.0),
            ],
        ),
        (
            42,
            [
                ("feed", 0.0, -2.0),
                ("feed", 35.0, -2.0),
                ("arc", 42.0, 5.0),
                ("feed", 42.0, 32.0),
                ("feed", 0.0, 32.0),
                ("feed", 0.0, 40.0),
            ],
        ),
    ] {
        let prog = format!(
            "G92 X0. Y-10.\nG90 G01 G{g} X0. Y0. D1 F500\nX40. ,R5.\nY30.\nX0.\nG40 Y40.\nM30\n"
        );
        let r = run_d("hx-mc", &[(1, 2.0)], &[], &prog);
        ok(&r);
        let p = path(&r);
        check_xy(&p, &want);
        let (cx, cy, cw) = p[2].center.unwrap();
        assert!(close(cx, 35.0) && close(cy, 5.0) && !cw, "G{g}: {:?}", p[2]);
    }
}

/// ,C/,R alarms in offset mode, at the ,C/,R word: the next block a G00
/// (CornerNoMove F_82103), a chamfer that uses up the next side
/// (CornerTooLarge F_82104), a ,C on the G40 block, the end of the
/// program after the ,C block.
#[test]
fn corner_alarms_in_offset_mode() {
    let a = |prog: &str| {
        let r = run_d("hx-mc", &[(1, 2.0)], &[], prog);
        let a = r.alarm.as_ref().expect("an alarm");
        (a.code.clone(), a.src.line, a.src.col)
    };
    let head = "G92 X0. Y-10.\nG90 G01 G41 X0. Y0. D1 F500\n";
    assert_eq!(
        a(&format!("{head}X40. ,C5.\nG00 Y30.\nM30\n")),
        ("F_82103".into(), 3, 6)
    );
    // Y3.: the chamfer's 5 mm do not fit on a 3 mm side.
    assert_eq!(
        a(&format!("{head}X40. ,C5.\nY3.\nX0.\nM30\n")),
        ("F_82104".into(), 3, 6)
    );
    // Exactly the side's length: fits in the contour but leaves no side
    // to offset.
    assert_eq!(
        a(&format!("{head}X40. ,C5.\nY5.\nX0.\nM30\n")),
        ("F_82104".into(), 3, 6)
    );
    assert_eq!(
        a(&format!("{head}X40.\nG40 Y-10. ,C2.\nM30\n")),
        ("F_82103".into(), 4, 11)
    );
    assert_eq!(
        a(&format!("{head}X40. ,R5.\nM30\n")),
        ("F_82103".into(), 3, 6)
    );
}

// ---- offset changes in offset mode ---------------------------------------------

/// A new offset value in offset mode applies from the end of the next
/// compensated block: that block runs slanted from the old vector to the
/// new one (000 §13.2.2; Fanuc "change of offset value"). Square contour
/// (0,0) → (40,0) → (40,30) → (0,30), G41 (inside), D1 = 2, then 4 for
/// the +Y side, given three ways: a D word on the block, `G10 L12 P1 R4.`
/// in a block of its own, and D2 (= 4) on a block of its own (the D word
/// and G10 blocks run the compensation codes, so these worked before the
/// value was read on every move; the lathe test below did not).
/// - start-up from (0,−10): right turn with the tool left (outer), type
///   A: (0, 2);
/// - the +X side ends at the inner corner with r = 2 (the corner at the
///   start of the changed block uses the old value): (38, 2);
/// - the +Y side ends at the inner corner with r = 4: x = 36, y = 26;
/// - the −X side (y = 26) ends on its perpendicular for the type-A cancel
///   (+Y after −X: right turn, outer): (0, 26); then (0, 40).
#[test]
fn offset_value_change_in_offset_mode() {
    let want = [
        ("feed", 0.0, 2.0),
        ("feed", 38.0, 2.0),
        ("feed", 36.0, 26.0),
        ("feed", 0.0, 26.0),
        ("feed", 0.0, 40.0),
    ];
    let head = "G92 X0. Y-10.\nG90 G01 G41 X0. Y0. D1 F500\nX40.\n";
    for mid in ["Y30. D2\n", "G10 L12 P1 R4.\nY30.\n", "D2\nY30.\n"] {
        let prog = format!("{head}{mid}X0.\nG40 Y40.\nM30\n");
        let r = run_d("hx-mc", &[(1, 2.0), (2, 4.0)], &[], &prog);
        ok(&r);
        check_xy(&path(&r), &want);
    }
}

/// Lathe: a T code changing the offset number in nose radius
/// compensation. T0101 (nose R 0.4) then T0102 (R 0.8), both tip 3, no
/// position offsets, G42 on a straight Z cut at Ø30 (X radius 15). The
/// imaginary tip of tip 3 is the centre + R·(−1, −1) in (Z, X); on a
/// straight −Z cut the centre runs at X = 15 + R, so the tip stays on
/// Ø30 and only Z shifts by −R at each end:
/// - the first cut ends at the straight-on joint with R 0.4: centre
///   (−10, 15.4), tip (−10.4, 15) → Z −10.4, X Ø30;
/// - the second cut (after T0102) ends with R 0.8 on the cancel's
///   perpendicular (+X after −Z with the tool on the right: inner):
///   centre (−20, 15.8), tip (−20.8, 15) → Z −20.8, Ø30.
#[test]
fn lathe_offset_change_in_offset_mode() {
    let prog = "G00 X40. Z0 T0101\nG42 G01 X30. F0.2\nZ-10.\nT0102\nZ-20.\nG40 G00 X50.\nM30\n";
    let r = run_d("puma-lathe", &[], &[(1, 0.4, 3), (2, 0.8, 3)], prog);
    ok(&r);
    let p: Vec<_> = path(&r).into_iter().filter(|m| m.kind == "feed").collect();
    // Feeds (X in `to` is the radius): the start-up −X then the −Z cut:
    // a right turn with the tool on the right, inner: the perpendicular
    // to the cut, centre (0, 15.4), tip (−0.4, 15); then the two cuts.
    // (Before the fix the second cut kept R 0.4 and ended at Z −20.4.)
    assert_eq!(p.len(), 3, "{p:?}");
    for (m, z) in p.iter().zip([-0.4, -10.4, -20.8]) {
        assert!(
            close(m.to[0], 15.0) && close(m.to[2], z),
            "{m:?} wanted X15 (radius) Z{z}"
        );
    }
}

// ---- G28 / G92 / G53 in offset mode (000 §13.2.2 figures) -------------------------

/// 000 §13.2.2's G92 figure (N5-N8, G41), here with D1 = 5 and a start-up
/// N4 before it. G92 in offset mode keeps the vector: the block before
/// it ends on its perpendicular vector, the block after it starts from
/// that vector in the new coordinates. Unit normals (left of travel):
/// N4 +X; N5 (70,30): d5 = (7,3)/√58, n5 = (−3,7)/√58; N6 (60,−30):
/// d6 = (2,−1)/√5, n6 = (1,2)/√5; N8 (60,30) in the new frame:
/// d8 = (2,1)/√5, n8 = (−1,2)/√5.
/// - N4 → N5 turns left with the tool left (inner), type A start-up:
///   (20,0) + 5·n5;
/// - N5 → N6 turns right (outer obtuse): the offset lines meet at
///   K + r·(n5 + n6)/(1 + n5·n6), K = (90,30), n5·n6 = 11/√290;
/// - N6 ends on its perpendicular (150,0) + 5·n6 = (150 + √5, 2√5)
///   (before the G92, in the old frame);
/// - N7 G92 X20 Y10 makes the programmed point (150,0) read (20,10);
/// - N8 ends at the type-A cancel vector (N9 +X after N8: right turn,
///   outer): (80,40) + 5·n8 = (80 − √5, 40 + 2√5); N9 to (100,40).
#[test]
fn g92_in_offset_mode_keeps_the_vector() {
    let prog = "G92 X0 Y0\nN4 G91 G01 G41 X20. D1 F100\nN5 X70.0 Y30.0\nN6 X60.0 Y-30.0\nN7 G92 X20.0 Y10.0\nN8 G90 G01 X80.0 Y40.0\nN9 G40 X100.\nM30\n";
    let r = run_d("hx-mc", &[(1, 5.0)], &[], prog);
    ok(&r);
    let s58 = 58f64.sqrt();
    let s5 = 5f64.sqrt();
    let n5 = (-3.0 / s58, 7.0 / s58);
    let n6 = (1.0 / s5, 2.0 / s5);
    let k = 5.0 / (1.0 + 11.0 / 290f64.sqrt());
    check_xy(
        &path(&r),
        &[
            ("feed", 20.0 + 5.0 * n5.0, 5.0 * n5.1),
            ("feed", 90.0 + k * (n5.0 + n6.0), 30.0 + k * (n5.1 + n6.1)),
            ("feed", 150.0 + s5, 2.0 * s5),
            ("feed", 80.0 - s5, 40.0 + 2.0 * s5),
            ("feed", 100.0, 40.0),
        ],
    );
}

/// G28 in offset mode (000 §13.2.2's G28 figure, Fanuc "temporary
/// cancel"): the block before it ends on its perpendicular vector, the
/// G28 moves (intermediate point, reference) are uncompensated, and the
/// next move starts the offset again (type A start-up). CCW square, G41
/// (inside), r = 2:
/// - start-up (0,−10) → (0,0), then +X: outer, type A: (0, 2);
/// - +X side ends on its perpendicular: (40, 2);
/// - `G91 G28 Z0`: intermediate point = the programmed point (40, 0),
///   then the reference (Z only moves: X/Y stay (40, 0));
/// - `Y30.` is a start-up from (40,0): the next block runs −X, so it ends
///   on that block's perpendicular: (40,30) + 2·(0,−1) = (40, 28);
/// - −X side ends on its perpendicular for the cancel (+Y after −X:
///   right turn, outer, type A): (0, 28); then (0, 40).
#[test]
fn g28_in_offset_mode_cancels_and_restarts() {
    let prog = "G92 X0. Y-10. Z0.\nG00 Z-20.\nG90 G01 G41 X0. Y0. D1 F500\nX40.\nG91 G28 Z0.\nG90 Y30.\nX0.\nG40 Y40.\nM30\n";
    let r = run_d("hx-mc", &[(1, 2.0)], &[], prog);
    ok(&r);
    let p = path(&r);
    let xy: Vec<_> = p
        .iter()
        .map(|m| (m.kind, m.to[0], m.to[1], m.line))
        .collect();
    // (The first rapid is `G00 Z-20.`; the G28's move to the intermediate
    // point is zero and not emitted, its move to the reference is.)
    let want = [
        ("rapid", 0.0, -10.0, 2),
        ("feed", 0.0, 2.0, 3),
        ("feed", 40.0, 2.0, 4),
        ("rapid", 40.0, 0.0, 5),
        ("feed", 40.0, 28.0, 6),
        ("feed", 0.0, 28.0, 7),
        ("feed", 0.0, 40.0, 8),
    ];
    assert_eq!(xy.len(), want.len(), "{xy:?}");
    assert!(close(p[3].to[2], 0.0) && close(p[2].to[2], -20.0), "{p:?}");
    for (g, w) in xy.iter().zip(want) {
        assert!(
            g.0 == w.0 && close(g.1, w.1) && close(g.2, w.2) && g.3 == w.3,
            "{g:?} vs {w:?}"
        );
    }
}

/// G41/G42 in a G28 or G53 block: the offset starts in G00/G01 moves only
/// (000 §13.2.1), F_82120 at the G41/G42 code; G40 with G28 cancels.
#[test]
fn g41_with_g28_or_g53_alarms() {
    let a = |prog: &str| {
        let r = run_d("hx-mc", &[(1, 2.0)], &[], prog);
        let a = r.alarm.as_ref().expect("an alarm");
        (a.code.clone(), a.src.line, a.src.col)
    };
    assert_eq!(
        a("G92 X0. Y0. Z0.\nG91 G28 G41 X0. Y0. D1\nM30\n"),
        ("F_82120".into(), 2, 9)
    );
    assert_eq!(
        a("G92 X0. Y0. Z0.\nG90 G53 G42 X0. Y0. D1\nM30\n"),
        ("F_82120".into(), 2, 9)
    );
    // G40 with G28: the +X side ends on its perpendicular (40, 2), the
    // G28 moves are uncompensated, nothing is left in force.
    let r = run_d(
        "hx-mc",
        &[(1, 2.0)],
        &[],
        "G92 X0. Y-10. Z0.\nG90 G01 G41 X0. Y0. D1 F500\nX40.\nG91 G28 G40 Z0.\nG90 G01 Y30.\nM30\n",
    );
    ok(&r);
    let p = path(&r);
    let last = p.last().unwrap();
    assert!(close(p[1].to[0], 40.0) && close(p[1].to[1], 2.0), "{p:?}");
    assert!(close(last.to[0], 40.0) && close(last.to[1], 30.0), "{p:?}");
}

// ---- property tests on arc chains ---------------------------------------------

/// One block of a closed contour: the end point and, for an arc, its
/// radius (R word, minor arc) and direction.
#[derive(Clone, Copy, Debug)]
struct Edge {
    to: (f64, f64),
    arc: Option<(f64, bool)>,
}

/// Rounds to the 6 decimals the program text carries, so the test's own
/// geometry uses the numbers the interpreter reads.
fn r6(v: f64) -> f64 {
    format!("{v:.6}").parse().unwrap()
}

/// A closed contour around the origin (counter-clockwise star polygon,
/// radii 30..60) whose edges are lines or arcs: convex arcs (CCW, centre
/// inside) of 15°..100°, concave arcs (CW, bulging inwards) of 10°..40°.
fn arc_chain() -> impl Strategy<Value = (f64, f64, Vec<Edge>)> {
    (5usize..9).prop_flat_map(|n| {
        prop::collection::vec((30.0f64..60.0, -0.2f64..0.2, 0u8..3, 0.0f64..1.0), n).prop_map(
            move |v| {
                let pts: Vec<(f64, f64)> = v
                    .iter()
                    .enumerate()
                    .map(|(i, (r, j, _, _))| {
                        let a = (i as f64 + j) * std::f64::consts::TAU / n as f64;
                        (r6(r * a.cos()), r6(r * a.sin()))
                    })
                    .collect();
                let edges = (0..n)
                    .map(|i| {
                        let (a, b) = (pts[i], pts[(i + 1) % n]);
                        let chord = (b.0 - a.0).hypot(b.1 - a.1);
                        let (_, _, kind, t) = v[i];
                        let arc = match kind {
                            0 => None,
                            1 => Some(((15.0 + 85.0 * t), true)),
                            _ => Some(((10.0 + 30.0 * t), false)),
                        }
                        .map(|(deg, ccw): (f64, bool)| {
                            (r6(chord / (2.0 * (deg.to_radians() / 2.0).sin())), ccw)
                        });
                        Edge { to: b, arc }
                    })
                    .collect();
                (pts[0].0, pts[0].1, edges)
            },
        )
    })
}

/// The centre of the minor arc from `a` to `b` of radius `r`: on the left
/// of the chord for CCW, the right for CW, √(r² − (c/2)²) from its middle.
fn minor_center(a: (f64, f64), b: (f64, f64), r: f64, ccw: bool) -> (f64, f64) {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let c = dx.hypot(dy);
    let d = (r * r - c * c / 4.0).max(0.0).sqrt();
    let s = if ccw { 1.0 } else { -1.0 };
    (
        (a.0 + b.0) / 2.0 - s * d * dy / c,
        (a.1 + b.1) / 2.0 + s * d * dx / c,
    )
}

/// A contour element for the distance checks: a line or an arc (centre,
/// radius, CCW).
#[derive(Clone, Copy, Debug)]
enum El {
    Line((f64, f64), (f64, f64)),
    Arc((f64, f64), (f64, f64), (f64, f64), f64, bool),
}

fn elements(start: (f64, f64), edges: &[Edge]) -> Vec<El> {
    let mut a = start;
    edges
        .iter()
        .map(|e| {
            let el = match e.arc {
                None => El::Line(a, e.to),
                Some((r, ccw)) => El::Arc(a, e.to, minor_center(a, e.to, r, ccw), r, ccw),
            };
            a = e.to;
            el
        })
        .collect()
}

/// The counter-clockwise angle from `a` to `b` about `c`, in [0, 2π).
fn ccw_angle(a: (f64, f64), b: (f64, f64), c: (f64, f64)) -> f64 {
    let t = (b.1 - c.1).atan2(b.0 - c.0) - (a.1 - c.1).atan2(a.0 - c.0);
    t.rem_euclid(std::f64::consts::TAU)
}

/// True distance from `p` to an element (arc: the radial distance where
/// `p` lies within the arc's sweep, else the nearer end point).
fn el_dist(p: (f64, f64), e: &El) -> f64 {
    match *e {
        El::Line(a, b) => seg_dist(p, a, b),
        El::Arc(a, b, c, r, ccw) => {
            let (from, to) = if ccw { (a, b) } else { (b, a) };
            if ccw_angle(from, p, c) <= ccw_angle(from, to, c) {
                ((p.0 - c.0).hypot(p.1 - c.1) - r).abs()
            } else {
                (p.0 - a.0)
                    .hypot(p.1 - a.1)
                    .min((p.0 - b.0).hypot(p.1 - b.1))
            }
        }
    }
}

/// The program: start-up from (100, 0) to the start, twice round, G40 back.
fn chain_prog(start: (f64, f64), edges: &[Edge], g: u32) -> String {
    let mut s = String::from("G92 X100. Y0.\nG90 G01 F1000\n");
    s += &format!("G{g} X{:.6} Y{:.6} D1\n", start.0, start.1);
    for _ in 0..2 {
        for e in edges {
            match e.arc {
                None => s += &format!("G01 X{:.6} Y{:.6}\n", e.to.0, e.to.1),
                Some((r, ccw)) => {
                    s += &format!(
                        "G0{} X{:.6} Y{:.6} R{:.6}\n",
                        if ccw { 3 } else { 2 },
                        e.to.0,
                        e.to.1,
                        r
                    )
                }
            }
        }
    }
    s += "G40 G01 X100. Y0.\nM30\n";
    s
}

/// The reversed contour: the same elements run backwards (arcs change
/// direction, keep their centre and radius), starting at the same point.
fn reversed(start: (f64, f64), edges: &[Edge]) -> Vec<Edge> {
    let n = edges.len();
    let from = |i: usize| if i == 0 { start } else { edges[i - 1].to };
    (0..n)
        .rev()
        .map(|i| Edge {
            to: from(i),
            arc: edges[i].arc.map(|(r, ccw)| (r, !ccw)),
        })
        .collect()
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

    /// Arc chains, convex and concave, G41 or G42: the compensated path
    /// stays at least r from the contour at every vertex (no gouge); every
    /// compensated arc is concentric with a programmed arc at radius
    /// R ∓ r on the correct side (left of a CCW arc = towards the centre)
    /// and its middle is exactly r from the contour; every programmed line
    /// has a compensated line on its offset line (signed distance ±r)
    /// whose middle is exactly r from the contour. Only the interference
    /// alarms are accepted instead (offset larger than an inside arc,
    /// offset paths that do not meet).
    #[test]
    fn arc_chain_offset_keeps_distance_and_side(
        (sx, sy, edges) in arc_chain(),
        r in 0.5f64..3.0,
        left in any::<bool>(),
    ) {
        let start = (sx, sy);
        let g = if left { 41 } else { 42 };
        let run = run_d("hx-mc", &[(1, r)], &[], &chain_prog(start, &edges, g));
        if let Some(a) = &run.alarm {
            prop_assert!(matches!(a.code.as_str(), "F_82122" | "F_82123"), "{:?}", a);
            return Ok(());
        }
        let els = elements(start, &edges);
        let side = if left { 1.0 } else { -1.0 };
        let dist = |p: (f64, f64)| els.iter().map(|e| el_dist(p, e)).fold(f64::INFINITY, f64::min);
        let p = path(&run);
        // Moves 1..len-2: the start-up and the last block (ending on the
        // cancel's vector) and the cancel itself left out.
        let (mut lines, mut arcs) = (0usize, 0usize);
        for i in 1..p.len() - 2 {
            let (a, b) = ((p[i - 1].to[0], p[i - 1].to[1]), (p[i].to[0], p[i].to[1]));
            prop_assert!(dist(b) >= r - 1e-6, "vertex {:?} only {} from the contour (r {})", b, dist(b), r);
            match p[i].center {
                Some((cx, cy, cw)) => {
                    let c = (cx, cy);
                    let hit = els.iter().any(|e| match *e {
                        El::Arc(_, _, pc, pr, ccw) => {
                            let want = if ccw { pr - side * r } else { pr + side * r };
                            (pc.0 - c.0).hypot(pc.1 - c.1) < 1e-6
                                && ccw != cw
                                && ((b.0 - c.0).hypot(b.1 - c.1) - want).abs() < 1e-6
                        }
                        _ => false,
                    });
                    prop_assert!(hit, "arc to {:?} about {:?} matches no programmed arc", b, c);
                    // Its middle: half the sweep from the start.
                    let sw = if cw { ccw_angle(b, a, c) } else { ccw_angle(a, b, c) };
                    let a0 = (a.1 - c.1).atan2(a.0 - c.0) + if cw { -sw / 2.0 } else { sw / 2.0 };
                    let rho = (a.0 - c.0).hypot(a.1 - c.1);
                    let m = (c.0 + rho * a0.cos(), c.1 + rho * a0.sin());
                    prop_assert!((dist(m) - r).abs() < 1e-6, "arc middle {:?} at {}", m, dist(m));
                    arcs += 1;
                }
                None => {
                    let len = (b.0 - a.0).hypot(b.1 - a.1);
                    let on = els.iter().any(|e| match *e {
                        El::Line(u, v) => {
                            let (dx, dy) = (v.0 - u.0, v.1 - u.1);
                            let l = dx.hypot(dy);
                            let sd = |q: (f64, f64)| (dx * (q.1 - u.1) - dy * (q.0 - u.0)) / l;
                            len > 1e-6
                                && (sd(a) - side * r).abs() < 1e-6
                                && (sd(b) - side * r).abs() < 1e-6
                                && (dx * (b.0 - a.0) + dy * (b.1 - a.1)) > 0.0
                        }
                        _ => false,
                    });
                    if on {
                        let m = ((a.0 + b.0) / 2.0, (a.1 + b.1) / 2.0);
                        prop_assert!((dist(m) - r).abs() < 1e-6, "line middle {:?} at {}", m, dist(m));
                        lines += 1;
                    }
                }
            }
        }
        // Twice round, less the last block: every programmed line and arc
        // of the first round at least once.
        let n_lines = edges.iter().filter(|e| e.arc.is_none()).count();
        let n_arcs = edges.len() - n_lines;
        prop_assert!(lines >= n_lines && arcs >= n_arcs, "{} lines / {} arcs for {} / {}", lines, arcs, n_lines, n_arcs);
    }

    /// G41 on an arc chain makes the same points as G42 on the reversed
    /// chain (vertices away from the start, where the start-up and cancel
    /// differ).
    #[test]
    fn arc_chain_g41_equals_g42_reversed((sx, sy, edges) in arc_chain(), r in 0.5f64..3.0) {
        let start = (sx, sy);
        let a = run_d("hx-mc", &[(1, r)], &[], &chain_prog(start, &edges, 41));
        let b = run_d("hx-mc", &[(1, r)], &[], &chain_prog(start, &reversed(start, &edges), 42));
        prop_assert_eq!(a.alarm.is_some(), b.alarm.is_some(), "{:?} vs {:?}", a.alarm, b.alarm);
        if a.alarm.is_some() {
            return Ok(());
        }
        let away = |p: &(f64, f64)| (p.0 - start.0).hypot(p.1 - start.1) > 4.0 * r;
        let pa: Vec<_> = comp_points(&a).into_iter().filter(away).collect();
        let pb: Vec<_> = comp_points(&b).into_iter().filter(away).collect();
        let has = |v: &[(f64, f64)], p: &(f64, f64)| v.iter().any(|q| (q.0 - p.0).hypot(q.1 - p.1) < 1e-6);
        for p in &pa {
            prop_assert!(has(&pb, p), "{:?} missing from the G42 run", p);
        }
        for p in &pb {
            prop_assert!(has(&pa, p), "{:?} missing from the G41 run", p);
        }
    }
}

// ---- lathe tip directions 2, 3, 8 with offsets set by G10 -------------------------

/// The feed end points of a lathe run as (Z, X radius).
fn lathe_feeds(r: &Run) -> Vec<(f64, f64)> {
    path(r)
        .into_iter()
        .filter(|m| m.kind == "feed")
        .map(|m| (m.to[2], m.to[0]))
        .collect()
}

fn check_zx(got: &[(f64, f64)], want: &[(f64, f64)]) {
    assert_eq!(got.len(), want.len(), "{got:?} vs {want:?}");
    for (g, w) in got.iter().zip(want) {
        assert!(close(g.0, w.0) && close(g.1, w.1), "{got:?} vs {want:?}");
    }
}

/// Tip 8 (the imaginary tip at −X of the nose centre, 001 p.29) on 001's
/// C2 chamfer (face up Z0 to Ø26, chamfer to Z−2 Ø30, Z−30), G42, nose R
/// 0.8 and tip set by `G10 P10001 R0.8 Q8`. Worked in (Z, X radius): the
/// nose centre path is the same as for any tip (offset lines Z = 0.8,
/// Z + X = 13 + 0.8√2, X = 15.8), the tip is centre + (0, −0.8):
/// - start-up (−Z then +X, a right turn with the tool on the right:
///   inner) on the face's perpendicular: centre (0.8, 10) → tip (0.8, 9.2);
/// - face → chamfer (left turn, outer obtuse): centre (0.8, 12.2 + 0.8√2)
///   → tip (0.8, 11.4 + 0.8√2);
/// - chamfer → Z cut (left turn, outer obtuse): centre (−2.8 + 0.8√2,
///   15.8) → tip (−2.8 + 0.8√2, 15): on Ø30, as a tip-8 tool must be on a
///   Z cut;
/// - the cancel (+X after −Z, right turn, inner): the Z cut ends on its
///   perpendicular, centre (−30, 15.8) → tip (−30, 15).
#[test]
fn lathe_tip_8_chamfer_with_g10() {
    let q = 0.8 * 2f64.sqrt();
    let prog = "G10 P10001 R0.8 Q8\nG00 X20. Z2. T0101\nG42 G01 Z0. F0.2\nX26.\nX30. Z-2.\nZ-30.\nG40 G00 X40.\nM30\n";
    let r = run_d("puma-lathe", &[], &[], prog);
    ok(&r);
    check_zx(
        &lathe_feeds(&r),
        &[(0.8, 9.2), (0.8, 11.4 + q), (-2.8 + q, 15.0), (-30.0, 15.0)],
    );
}

/// Tip 3 on the same chamfer (001 p.28's a = 0.937, b = 0.468 for R0.8),
/// then `G10 P10001 R0.4` in offset mode before the Z cut: the Z cut
/// starts on the R0.8 vector (the chamfer → Z-cut corner keeps 0.8:
/// tip (−2.8 + 0.8√2 − 0.8, 15)) and ends with R0.4 on the cancel's
/// perpendicular: centre (−30, 15.4), tip 3 = centre + 0.4·(−1, −1)
/// = (−30.4, 15). Start-up and face → chamfer as worked in
/// `puma_chamfer_example_nose_radius`: tips (0, 9.2) and
/// (0, 12.2 + 0.8√2 − 0.8).
#[test]
fn lathe_tip_3_radius_changed_by_g10_in_offset_mode() {
    let q = 0.8 * 2f64.sqrt();
    let prog = "G10 P10001 R0.8 Q3\nG00 X20. Z2. T0101\nG42 G01 Z0. F0.2\nX26.\nX30. Z-2.\nG10 P10001 R0.4\nZ-30.\nG40 G00 X40.\nM30\n";
    let r = run_d("puma-lathe", &[], &[], prog);
    ok(&r);
    check_zx(
        &lathe_feeds(&r),
        &[(0.0, 9.2), (0.0, 11.4 + q), (-3.6 + q, 15.0), (-30.4, 15.0)],
    );
    // 001's a and b, printed cut to 3 decimals: 26 − Ø(2·(11.4 + 0.8√2))
    // = 0.937258 → 0.937, −2 − Z = 0.468629 → 0.468.
    let p = lathe_feeds(&r);
    let a = 26.0 - 2.0 * p[1].1;
    let b = -2.0 - p[2].0;
    assert!(
        (0.937..0.938).contains(&a) && (0.468..0.469).contains(&b),
        "{a} {b}"
    );
}

/// Tip 2 (boring towards the chuck: the tip at −Z, +X of the centre), G41
/// inside a bore, nose R 0.4 from `G10 P10002 R0.4 Q2`, changed to 0.8
/// by G10 before the shoulder. Contour (Z, X radius): mouth chamfer
/// (0,12) → (−2,10), bore X = 10 to Z−20, shoulder down to X = 8, G40
/// out along +Z. G41 = left of travel (−X side on a −Z cut: inside the
/// hole). Tip vector 2: (−1, +1)·R.
/// - start-up −Z then the chamfer (−1,−1)/√2: a left turn, tool left:
///   inner → the chamfer's perpendicular at its start: centre
///   (0,12) + 0.4·(1,−1)/√2 = (0.2√2, 12 − 0.2√2) → tip (0.2√2 − 0.4,
///   12.4 − 0.2√2);
/// - chamfer → bore, a right turn (outer obtuse): offset lines
///   X − Z = 12 − 0.4√2 and X = 9.6 → Z = −2.4 + 0.4√2; tip Z − 0.4,
///   X = 10;
/// - bore → shoulder, a left turn (inner): X = 9.6 and Z = −19.6 (the
///   corner keeps R0.4, the new value is for the shoulder's end) → tip
///   (−20, 10), the programmed corner;
/// - shoulder → cancel (+Z after −X: left turn, inner): the shoulder ends
///   on its perpendicular with R0.8: centre (−19.2, 8) → tip (−20, 8.8)
///   (R0.4 would give 8.4).
#[test]
fn lathe_tip_2_bore_with_g10_change() {
    let s = 0.2 * 2f64.sqrt();
    let prog = "G10 P10002 R0.4 Q2\nG00 X24. Z2. T0202\nG41 G01 Z0. F0.1\nX20. Z-2.\nZ-20.\nG10 P10002 R0.8\nX16.\nG40 G00 Z2.\nM30\n";
    let r = run_d("puma-lathe", &[], &[], prog);
    ok(&r);
    check_zx(
        &lathe_feeds(&r),
        &[
            (s - 0.4, 12.4 - s),
            (-2.8 + 2.0 * s, 10.0),
            (-20.0, 10.0),
            (-20.0, 8.8),
        ],
    );
    // The cancel rapid ends at the programmed (Z2, Ø16).
    let last = path(&r).last().unwrap().clone();
    assert!(close(last.to[2], 2.0) && close(last.to[0], 8.0), "{last:?}");
}

/// 000 §15.4.2 (3): a subprogram drawn eight times, rotated 45° each time
/// by O2200's `G68 X0 Y0 G91 R45.0`. O2100 starts G42 at the middle of the
/// octagon's bottom side (0, −10), runs to the corner (4.142, −10) and on
/// to the middle of the next side (7.071, −7.071) (the manual's rounded
/// numbers), then cancels with a G40 block without a move. The manual's
/// `G01 F200 H01` is read as D01 (H selects a length offset on the HX and
/// G42 needs a radius; the value is not printed): D01 = 1 here. A G53
/// move first puts the G92 origin inside the travel.
///
/// By hand, in O2100's own frame (G42 travelling +X: the tool on −Y):
/// start-up ends at (0, −11); the corner of the offset lines y = −11 and
/// the 45° side moved out by 1 is at x = 4.142 + 1·tan 22.5° =
/// 4.142 + (√2 − 1); the side ends at (7.071, −7.071) + (1, −1)/√2. Pass k
/// (k = 0..7) is the same rotated by 45°·k about the origin: a closed
/// octagon outside the programmed one, each vertex 11 / cos 22.5° from
/// the centre.
#[test]
fn manual_15_4_2_rotated_subprogram_octagon() {
    let prog = "G53 G00 X-400. Y-300.\n\
        G92 X0 Y0 G69 G17\n\
        G01 F200 D01\n\
        M98 P2100\n\
        M98 P2200 L7\n\
        G00 G90 X0 Y0\n\
        M30\n\
        O2200\n\
        G68 X0 Y0 G91 R45.0\n\
        G90 M98 P2100\n\
        M99\n\
        O2100\n\
        G90 G1 G42 X0 Y-10.0\n\
        X4.142\n\
        X7.071 Y-7.071\n\
        G40\n\
        M99\n";
    let r = run_d("hx-mc", &[(1, 1.0)], &[], prog);
    ok(&r);
    let h = std::f64::consts::FRAC_1_SQRT_2;
    let rot = |k: usize, (x, y): (f64, f64)| {
        let a = (45.0 * k as f64).to_radians();
        (x * a.cos() - y * a.sin(), x * a.sin() + y * a.cos())
    };
    let pass = [
        (0.0, -11.0),
        (4.142 + 2f64.sqrt() - 1.0, -11.0),
        (7.071 + h, -7.071 - h),
    ];
    // The feed moves of lines 13-15 (O2100), in order; the rapid before
    // and the final G00 are not part of the octagon.
    let p: Vec<_> = path(&r)
        .into_iter()
        .filter(|m| (13..=15).contains(&m.line))
        .collect();
    assert_eq!(p.len(), 24, "{p:#?}");
    for (i, m) in p.iter().enumerate() {
        let (k, j) = (i / 3, i % 3);
        let (x, y) = rot(k, pass[j]);
        assert!(
            m.kind == "feed" && close(m.to[0], x) && close(m.to[1], y),
            "pass {k} move {j}: {m:?}, wanted ({x}, {y})"
        );
    }
    // Every vertex of the compensated octagon is 11 / cos 22.5° out.
    let rv = 11.0 / 22.5f64.to_radians().cos();
    for m in p.iter().skip(1).step_by(3) {
        assert!((m.to[0].hypot(m.to[1]) - rv).abs() < 1e-3, "{m:?}");
    }
}
