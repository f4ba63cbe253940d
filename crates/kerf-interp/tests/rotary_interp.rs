//! HX G112/G113 polar coordinate interpolation (000 §4.6) and G107
//! cylindrical interpolation (000 §4.7): chord end points at block ends and
//! at chosen points of the virtual path, chord tolerance, and the modes'
//! alarms. Expected values are worked out by hand in the comments:
//! virtual (x, y) → X = hypot(x, y), C = atan2(y, x) in degrees.

use kerf_canon::{Canon, Event};

mod common;
use common::{alarm, ok, run_on};
use kerf_interp::Run;

/// (line, X, C) of every feed/rapid end, work coordinates.
fn xc(r: &Run) -> Vec<(u32, f64, f64, f64)> {
    r.events
        .iter()
        .filter(|e| matches!(e.cmd, Canon::Feed { .. } | Canon::Rapid { .. }))
        .map(|e: &Event| {
            let m = e.motion().unwrap();
            (e.src.line, m.to[0], m.to[5], m.to[2])
        })
        .collect()
}

fn on_line(r: &Run, line: u32) -> Vec<(f64, f64, f64)> {
    xc(r)
        .into_iter()
        .filter(|m| m.0 == line)
        .map(|m| (m.1, m.2, m.3))
        .collect()
}

fn near(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol
}

/// Virtual point of machine (X, C°) with the virtual +x at C = 0.
fn virt(x: f64, c: f64) -> (f64, f64) {
    let t = c.to_radians();
    (x * t.cos(), x * t.sin())
}

/// The brief's case: a G112 straight line X 20 → 10 at virtual C = 10.
#[test]
fn polar_straight_line_at_virtual_c_10() {
    let r = run_on(
        "hx-mc",
        "G54 G90 G00 X20. C0. Z0.\n\
         G112\n\
         G01 C10. F100.\n\
         X10.\n\
         G113\n\
         M30\n",
    );
    ok(&r);
    // Line 3 ends at (20, 10): X = sqrt(500) = 22.360680, C = atan(0.5) = 26.565051°.
    let l3 = on_line(&r, 3);
    let (x, c, _) = *l3.last().unwrap();
    assert!(
        near(x, 22.360680, 1e-6) && near(c, 26.565051, 1e-6),
        "{x} {c}"
    );
    // Line 4 ends at (10, 10): X = sqrt(200) = 14.142136, C = 45°.
    let l4 = on_line(&r, 4);
    let (x, c, _) = *l4.last().unwrap();
    assert!(near(x, 14.142136, 1e-6) && near(c, 45.0, 1e-6), "{x} {c}");
    // The chords are bisections, so the path's middle (15, 10) is a chord
    // end: X = hypot(15, 10) = 18.027756, C = atan2(10, 15) = 33.690068°.
    assert!(
        l4.iter()
            .any(|&(x, c, _)| near(x, 18.027756, 1e-6) && near(c, 33.690068, 1e-6)),
        "{l4:?}"
    );
    // Every chord end is on the line y = 10, x falling from 20 to 10, and
    // the machine's straight X/C move between two ends stays within the
    // 0.001 mm tolerance of the line at its middle.
    let mut prev = (22.360679774997898, 26.56505117707799);
    let mut last_x = 20.0;
    for &(x, c, _) in &l4 {
        let v = virt(x, c);
        assert!(near(v.1, 10.0, 1e-9), "chord end off the line: {v:?}");
        assert!(v.0 < last_x, "x must fall: {v:?}");
        last_x = v.0;
        let mid = virt(0.5 * (prev.0 + x), 0.5 * (prev.1 + c));
        assert!(near(mid.1, 10.0, 0.001 + 1e-9), "sag too large: {mid:?}");
        prev = (x, c);
    }
}

/// 000 §4.6's example (examples/hx/polar_interp_g112.nc): points inside
/// the two arcs.
#[test]
fn polar_example_arcs_of_000_4_6() {
    let r = run_on(
        "hx-mc",
        include_str!("../../../examples/hx/polar_interp_g112.nc"),
    );
    ok(&r);
    // Line 6, G03 X10. C20. R10. from (20, 10): centre (10, 10). Its
    // middle (10 + 10 cos 45°, 10 + 10 sin 45°) = (17.071068, 17.071068):
    // X = 17.071068·√2 = 24.142136, C = 45°.
    let l6 = on_line(&r, 6);
    assert!(
        l6.iter()
            .any(|&(x, c, _)| near(x, 24.142136, 1e-6) && near(c, 45.0, 1e-6)),
        "{l6:?}"
    );
    for &(x, c, _) in &l6 {
        let v = virt(x, c);
        assert!(near((v.0 - 10.0).hypot(v.1 - 10.0), 10.0, 1e-9), "{v:?}");
    }
    // Line 9, G03 X-10. C-20. I10. J0. from (-20, -10): centre (-10, -10),
    // middle (-10 - 7.071068, -10 - 7.071068): X = 24.142136, C = 225°.
    let l9 = on_line(&r, 9);
    assert!(
        l9.iter()
            .any(|&(x, c, _)| near(x, 24.142136, 1e-6) && near(c, 225.0, 1e-6)),
        "{l9:?}"
    );
    // Z stays at 50 throughout.
    assert!(xc(&r).iter().all(|m| near(m.3, 50.0, 1e-9)));
}

/// The C angle at G112 is the virtual plane's 0° (Fanuc); incremental
/// X/C words add to the virtual point.
#[test]
fn polar_start_angle_and_incremental_words() {
    let r = run_on(
        "hx-mc",
        "G54 G90 G00 X20. C30. Z0.\n\
         G112\n\
         G91 G01 C10. F100.\n\
         X-10.\n\
         G113\n",
    );
    ok(&r);
    // (20, 10): C = 30 + 26.565051 = 56.565051; then (10, 10): C = 30 + 45 = 75.
    let (x, c, _) = *on_line(&r, 3).last().unwrap();
    assert!(
        near(x, 22.360680, 1e-6) && near(c, 56.565051, 1e-6),
        "{x} {c}"
    );
    let (x, c, _) = *on_line(&r, 4).last().unwrap();
    assert!(near(x, 14.142136, 1e-6) && near(c, 75.0, 1e-6), "{x} {c}");
}

/// A line through the centre needs no rotation at all: X runs through 0
/// to -10 with C kept (one chord). Z words move linearly along.
#[test]
fn polar_line_through_the_centre_and_z() {
    let r = run_on(
        "hx-mc",
        "G54 G90 G00 X10. C0. Z0.\n\
         G112\n\
         G01 X-10. Z-5. F100.\n\
         G113\n",
    );
    ok(&r);
    assert_eq!(on_line(&r, 3), vec![(-10.0, 0.0, -5.0)]);
}

/// After G113, C is an ordinary rotary axis again (degrees, G00 allowed).
#[test]
fn polar_cancel_restores_ordinary_c() {
    let r = run_on(
        "hx-mc",
        "G54 G90 G00 X20. C0. Z0.\n\
         G112\n\
         G01 C20. F100.\n\
         G113\n\
         G00 C10.\n",
    );
    ok(&r);
    // (20, 20) → C = 45°; then C10. is 10 degrees.
    assert!(near(on_line(&r, 3).last().unwrap().1, 45.0, 1e-9));
    assert_eq!(on_line(&r, 5), vec![(28.284271247461902, 10.0, 0.0)]);
}

/// 000 §4.7: G02 Z90. C60. R30. from Z120 C30 on a cylinder of radius
/// 180/π (57.29578: 1° = 1 mm on the surface). Centre (Z120, C60),
/// start angle -90°, 90° clockwise: point at t = Z 120 + 30 cos(-90° - 90°t),
/// C 60 + 30 sin(-90° - 90°t). Chords for a 0.001 mm sagitta:
/// d = 2 acos(1 - 0.001/30) = 0.0163300 rad, (π/2)/d = 96.2 → 97.
#[test]
fn cylindrical_arc_points() {
    let r = run_on(
        "hx-mc",
        "G54 G00 G90 Z120. C30.\n\
         G18\n\
         G107 C57.29578\n\
         G02 Z90. C60. R30. F250.\n\
         G107 C0\n",
    );
    ok(&r);
    let l4 = on_line(&r, 4);
    assert_eq!(l4.len(), 97);
    for (i, &(_, c, z)) in l4.iter().enumerate() {
        let a = (-90.0 - 90.0 * (i + 1) as f64 / 97.0f64).to_radians();
        assert!(near(z, 120.0 + 30.0 * a.cos(), 1e-5), "#{i}: z {z}");
        assert!(near(c, 60.0 + 30.0 * a.sin(), 1e-5), "#{i}: c {c}");
    }
    let (_, c, z) = *l4.last().unwrap();
    assert_eq!((z, c), (90.0, 60.0));
}

/// Radius 10: 1° = π/18 = 0.174533 mm. G02 Z0 C114.592 R10. is a half
/// circle on the surface (chord 114.592·0.174533 = 20.0 mm): centre at
/// Z0, s = 10 mm (C = 57.29578°), going through Z = -10 (clockwise in
/// Z-C from the bottom). A G01 in C is one ordinary move in degrees.
#[test]
fn cylindrical_radius_scales_the_surface() {
    let r = run_on(
        "hx-mc",
        "G54 G00 G90 Z0 C0\n\
         G18 G107 C10.\n\
         G02 Z0 C114.592 R10. F100.\n\
         G01 C180.\n\
         G107 C0\n",
    );
    ok(&r);
    let k = std::f64::consts::PI * 10.0 / 180.0;
    let l3 = on_line(&r, 3);
    for &(_, c, z) in &l3 {
        assert!(near(z.hypot(c * k - 10.0), 10.0, 2e-4), "{z} {c}");
    }
    let zmin = l3.iter().map(|m| m.2).fold(f64::MAX, f64::min);
    assert!(near(zmin, -10.0, 0.001), "{zmin}");
    assert_eq!(on_line(&r, 4), vec![(400.0, 180.0, 0.0)]);
}

#[test]
fn polar_alarms() {
    let setup = "G54 G90 G00 X20. C0. Z0.\n";
    let cases: &[(&str, u32)] = &[
        ("G112\nG00 X10.\n", 3),       // G00 in G112
        ("G112\nX10.\n", 3),           // G00 still modal
        ("G112 X10.\n", 2),            // axis words with G112
        ("G112\nG28 X0\n", 3),         // reference return
        ("G112\nG92 X0\n", 3),         // coordinate setting
        ("G112\nG18\n", 3),            // plane change
        ("G16\nG112\n", 3),            // G112 in G16
        ("G18 G107 C10.\nG112\n", 3),  // G112 in G107
        ("G68 X0 Y0 R30.\nG112\n", 3), // G112 in rotation
    ];
    for (body, line) in cases {
        let r = run_on("hx-mc", &format!("{setup}{body}"));
        let (code, l, _) = alarm(&r);
        assert_eq!((code, l), ("F_82204", *line), "{body}");
    }
}

#[test]
fn cylindrical_alarms() {
    let setup = "G54 G90 G00 Z0 C0\nG18\n";
    let cases: &[(&str, u32)] = &[
        ("G107\n", 3),                                  // radius missing
        ("G107 C-5.\n", 3),                             // negative radius
        ("G107 C10. Z5.\n", 3),                         // other axis word
        ("G107 C10.\nG02 Z10. C20. I5. F100\n", 4),     // I/J/K arc
        ("G107 C10.\nG19 G02 Z10. C20. R5. F100\n", 4), // plane change in the mode
        ("G112\nG107 C10.\n", 4),                       // G107 in G112
        ("G107 C10.\nG54\n", 4),                        // work system change
    ];
    for (body, line) in cases {
        let r = run_on("hx-mc", &format!("{setup}{body}"));
        let (code, l, _) = alarm(&r);
        assert_eq!((code, l), ("F_82208", *line), "{body}");
    }
    // A G19 arc is refused too (plane selected before G107).
    let r = run_on(
        "hx-mc",
        "G54 G90 G00 Z0 C0\nG19\nG107 C10.\nG02 Y10. Z10. R10. F100\n",
    );
    assert_eq!(alarm(&r).0, "F_82208");
}
