//! Cutter compensation compared with LinuxCNC's interpreter. The rs274
//! numbers below were obtained once by running LinuxCNC's stand-alone
//! interpreter, `rs274` from the Debian package linuxcnc-uspace
//! 2.9.0~pre1+git20230208.f1270d6ed7-1+deb12u2, as
//! `rs274 -g -t tt.tbl FILE.ngc /dev/stdout < /dev/null` with the tool
//! table line `T1 P1 Z0 D0.5` (rs274's stand-alone tool table is in
//! inches: a 0.5 in = 12.7 mm diameter, radius 6.35 mm), and copying its
//! STRAIGHT_FEED / ARC_FEED lines from the G41/G42 block to the G40 move
//! (ARC_FEED(x, y, cx, cy, rotation, ...): rotation 1 = CCW, −1 = CW).
//! rs274 prints 4 decimals, so the comparisons allow 1e-4 mm. The test
//! does not need rs274 at run time.
//!
//! The programs are the same text for both (kerf's HX reads `T1 M6`,
//! `G94`, `D1`; the D1 value is set to 6.35 here). LinuxCNC differs from
//! Fanuc type C in three places (docs/dialects.md):
//! - outside corners: LinuxCNC inserts an arc of radius r about the
//!   programmed corner; Fanuc/kerf join the offset lines at their
//!   intersection (or extension vectors);
//! - the entry move ends on the vector perpendicular to the entry move
//!   itself (then a corner as in offset mode); kerf's type A ends on the
//!   vector perpendicular to the next block. The programs enter along
//!   the first side, where both agree;
//! - the exit: both end the last block on its perpendicular vector here.
//!
//! What must agree and is checked: every inside-corner intersection and
//! offset segment end point LinuxCNC makes away from outside corners (the
//! `same` lists), every LinuxCNC straight run lies on a kerf offset line
//! (same line, same direction), every compensated programmed arc has the
//! same centre, radius and direction. The kerf points at the outside
//! corners are worked by hand in the comments.

use kerf_canon::{ArcDir, Canon};
use kerf_interp::{Interp, Profile, Settings, Step};

const R: f64 = 6.35;
const TOL: f64 = 1e-4;

/// A move of the compensated path: end point and, for an arc, its centre
/// and CCW.
#[derive(Clone, Copy, Debug)]
struct M {
    to: (f64, f64),
    arc: Option<((f64, f64), bool)>,
}

const fn l(x: f64, y: f64) -> M {
    M {
        to: (x, y),
        arc: None,
    }
}
const fn a(x: f64, y: f64, cx: f64, cy: f64, rot: i32) -> M {
    M {
        to: (x, y),
        arc: Some(((cx, cy), rot == 1)),
    }
}

/// kerf's plane moves from `first_line` on (the G41/G42 block).
fn kerf_path(text: &str, first_line: u32) -> Vec<M> {
    let mut p = Profile::builtin("hx-mc").unwrap();
    for ax in p.axes.values_mut() {
        ax.min = -1e4;
        ax.max = 1e4;
    }
    let mut it = Interp::new(p, Settings::default());
    it.offsets_mut().d_mut(1).unwrap().geom = R;
    it.load_main(
        "t.ngc",
        Box::new(std::io::Cursor::new(text.as_bytes().to_vec())),
    );
    let mut out = Vec::new();
    loop {
        match it.step() {
            Step::Event(e) => {
                if e.src.line < first_line {
                    continue;
                }
                let Some(m) = e.motion() else { continue };
                let to = (m.to[0], m.to[1]);
                match &e.cmd {
                    Canon::Arc { center, dir, .. } => out.push(M {
                        to,
                        arc: Some(((center[0], center[1]), *dir == ArcDir::Ccw)),
                    }),
                    Canon::Feed { .. } | Canon::Rapid { .. } => out.push(M { to, arc: None }),
                    _ => {}
                }
            }
            Step::End => return out,
            Step::Alarm(a) => panic!("{a:?}"),
        }
    }
}

fn near(p: (f64, f64), q: (f64, f64)) -> bool {
    (p.0 - q.0).hypot(p.1 - q.1) < TOL
}

/// Distance of `p` from the line through `a` with direction `d` (unit).
fn off_line(p: (f64, f64), a: (f64, f64), d: (f64, f64)) -> f64 {
    ((p.0 - a.0) * d.1 - (p.1 - a.1) * d.0).abs()
}

/// The checks described at the top. `start`: the point before the first
/// move (the entry move's start); `prog_arcs`: centres of the programmed
/// arcs; `kerf_only`: kerf's points at the outside corners.
fn compare(
    text: &str,
    start: (f64, f64),
    lc: &[M],
    same: &[(f64, f64)],
    prog_arcs: &[(f64, f64)],
    kerf_only: &[(f64, f64)],
) {
    let k = kerf_path(text, 5);
    let has = |p: (f64, f64)| k.iter().any(|m| near(m.to, p));
    for &p in same {
        assert!(
            lc.iter().any(|m| near(m.to, p)),
            "{p:?} not in the rs274 list"
        );
        assert!(has(p), "rs274 point {p:?} missing from kerf's path {k:#?}");
    }
    for &p in kerf_only {
        assert!(has(p), "kerf corner {p:?} missing from {k:#?}");
    }
    // kerf's straight moves as (start, unit direction).
    let mut klines = Vec::new();
    let mut prev = start;
    for m in &k {
        if m.arc.is_none() {
            let (dx, dy) = (m.to.0 - prev.0, m.to.1 - prev.1);
            let len = dx.hypot(dy);
            if len > 1e-9 {
                klines.push((prev, (dx / len, dy / len)));
            }
        }
        prev = m.to;
    }
    // LinuxCNC's straight runs in offset mode (not the entry, first, nor
    // the exit, last) lie on kerf offset lines.
    let mut prev = lc[0].to;
    for m in &lc[1..lc.len() - 1] {
        if m.arc.is_none() {
            let (dx, dy) = (m.to.0 - prev.0, m.to.1 - prev.1);
            let len = dx.hypot(dy);
            let d = (dx / len, dy / len);
            let on = klines.iter().any(|&(p, u)| {
                off_line(prev, p, u) < TOL
                    && off_line(m.to, p, u) < TOL
                    && (u.0 * d.0 + u.1 * d.1) > 0.999_999
            });
            assert!(on, "rs274 run {prev:?} → {:?} is on no kerf line", m.to);
        }
        prev = m.to;
    }
    // Compensated programmed arcs: same centre, radius, direction.
    for m in lc {
        let Some((c, ccw)) = m.arc else { continue };
        if !prog_arcs.iter().any(|&p| near(p, c)) {
            continue; // a LinuxCNC outside-corner arc
        }
        let rho = (m.to.0 - c.0).hypot(m.to.1 - c.1);
        let ok = k.iter().any(|q| match q.arc {
            Some((kc, kccw)) => {
                near(kc, c)
                    && kccw == ccw
                    && ((q.to.0 - kc.0).hypot(q.to.1 - kc.1) - rho).abs() < TOL
            }
            None => false,
        });
        assert!(
            ok,
            "rs274 arc about {c:?} radius {rho} not in kerf's path {k:#?}"
        );
    }
}

/// Pocket (G41 inside) with a tangent semicircle, three small inside
/// corners and one outside corner pointing into the pocket.
#[test]
fn pocket_with_semicircle_and_inside_corners() {
    let text = "G21 G17 G90 G94\nT1 M6\nG00 X25. Y0.\nG01 Z-1. F500\nG41 D1 X40. Y0.\nX80.\nG03 X80. Y40. I0. J20.\nG01 X30.\nY25.\nX0.\nY0.\nX40.\nG40 X40. Y15.\nM30\n";
    let lc = [
        l(40.0, 6.35),
        l(80.0, 6.35),
        a(80.0, 33.65, 80.0, 20.0, 1),
        l(36.35, 33.65),
        l(36.35, 25.0),
        a(30.0, 18.65, 30.0, 25.0, -1),
        l(6.35, 18.65),
        l(6.35, 6.35),
        l(40.0, 6.35),
        l(40.0, 15.0),
    ];
    // Outside corner at (30,25) (−Y then −X, a right turn with the tool
    // on the left): kerf joins x = 36.35 and y = 18.65 at (36.35, 18.65)
    // where rs274 goes round (30,25) from (36.35,25) to (30,18.65).
    compare(
        text,
        (25.0, 0.0),
        &lc,
        &[
            (40.0, 6.35),
            (80.0, 6.35),
            (80.0, 33.65),
            (36.35, 33.65),
            (6.35, 18.65),
            (6.35, 6.35),
            (40.0, 15.0),
        ],
        &[(80.0, 20.0)],
        &[(36.35, 18.65)],
    );
}

/// Island (G42 outside a CCW contour) with a semicircle, a notch (one
/// inside corner) and three outside corners.
#[test]
fn island_with_notch() {
    let text = "G21 G17 G90 G94\nT1 M6\nG00 X5. Y0.\nG01 Z-1. F500\nG42 D1 X25. Y0.\nX50.\nG03 X50. Y30. I0. J15.\nG01 X20.\nY15.\nX0.\nY0.\nX25.\nG40 X25. Y-20.\nM30\n";
    let lc = [
        l(25.0, -6.35),
        l(50.0, -6.35),
        a(50.0, 36.35, 50.0, 15.0, 1),
        l(20.0, 36.35),
        a(13.65, 30.0, 20.0, 30.0, 1),
        l(13.65, 21.35),
        l(0.0, 21.35),
        a(-6.35, 15.0, 0.0, 15.0, 1),
        l(-6.35, 0.0),
        a(0.0, -6.35, 0.0, 0.0, 1),
        l(25.0, -6.35),
        l(25.0, -20.0),
    ];
    // Outside corners (left turns, tool on the right), the offset lines'
    // intersections: (20,30): y = 36.35 and x = 13.65; (0,15): y = 21.35
    // and x = −6.35; (0,0): x = −6.35 and y = −6.35.
    compare(
        text,
        (5.0, 0.0),
        &lc,
        &[
            (25.0, -6.35),
            (50.0, -6.35),
            (50.0, 36.35),
            (13.65, 21.35),
            (25.0, -20.0),
        ],
        &[(50.0, 15.0)],
        &[(13.65, 36.35), (-6.35, 21.35), (-6.35, -6.35)],
    );
}

/// Pocket with a rounded corner (G03, inside the arc: radius 20 − r) and
/// a CW semicircular bump into it (outside that arc: radius 10 + r) met
/// by straight sides at inside corners: the line y = 60 − r cuts the
/// circle of radius 16.35 about (50,60) at x = 50 ± √(16.35² − 6.35²)
/// = 50 ± √227 = 50 ± 15.066519, which rs274 prints as 65.0665 / 34.9335.
#[test]
fn pocket_with_round_corner_and_bump() {
    let text = "G21 G17 G90 G94\nT1 M6\nG00 X20. Y0.\nG01 Z-1. F500\nG41 D1 X40. Y0.\nX100.\nY40.\nG03 X80. Y60. I-20. J0.\nG01 X60.\nG02 X40. Y60. I-10. J0.\nG01 X0.\nY0.\nX40.\nG40 X40. Y15.\nM30\n";
    let lc = [
        l(40.0, 6.35),
        l(93.65, 6.35),
        l(93.65, 40.0),
        a(80.0, 53.65, 80.0, 40.0, 1),
        l(65.0665, 53.65),
        a(34.9335, 53.65, 50.0, 60.0, -1),
        l(6.35, 53.65),
        l(6.35, 6.35),
        l(40.0, 6.35),
        l(40.0, 15.0),
    ];
    let s = 227f64.sqrt();
    // Hand-worked kerf points equal to rs274's to its 4 decimals.
    assert!((50.0 + s - 65.0665).abs() < 5e-5 && (50.0 - s - 34.9335).abs() < 5e-5);
    compare(
        text,
        (20.0, 0.0),
        &lc,
        &[
            (40.0, 6.35),
            (93.65, 6.35),
            (93.65, 40.0),
            (80.0, 53.65),
            (65.0665, 53.65),
            (34.9335, 53.65),
            (6.35, 53.65),
            (6.35, 6.35),
            (40.0, 15.0),
        ],
        &[(80.0, 40.0), (50.0, 60.0)],
        &[],
    );
}
