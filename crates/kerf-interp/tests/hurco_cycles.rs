//! Hurco drill cycles (002 G73, G74, G80-G84, G98/G99), positions by hand
//! from 002's examples. Metric unless the block says G20; X is a diameter
//! (power-on G08), so X2 is a radius of 1.
mod common;
use common::*;
use kerf_canon::{Canon, SpindleDir};
use kerf_interp::Run;

/// (line, kind, z) of every move.
fn zs(r: &Run) -> Vec<(u32, &'static str, f64)> {
    moves(r)
        .into_iter()
        .zip(r.events.iter().filter(|e| e.motion().is_some()))
        .map(|(m, e)| (e.src.line, m.0, m.3))
        .collect()
}

#[test]
fn g98_init_plane_is_the_first_cycle_after_g80() {
    // 002 G98, first example (Z only, mm):
    // N010 G0 Z10
    // N020 G81 Z5 F60   (feed to Z5, rapid to Z10)
    // N030 G0 Z20
    // N040 G81 Z15      (rapid to Z10, feed up to Z15, rapid to Z10)
    // N050 G80
    let r = run_on(
        "hurco-lathe",
        "N010 G0 Z10\nN020 G81 Z5 F60\nN030 G0 Z20\nN040 G81 Z15\nN050 G80\nM30\n",
    );
    ok(&r);
    assert_eq!(
        zs(&r),
        vec![
            (1, "rapid", 10.0),
            (2, "feed", 5.0),
            (2, "rapid", 10.0),
            (3, "rapid", 20.0),
            (4, "rapid", 10.0),
            (4, "feed", 15.0),
            (4, "rapid", 10.0),
        ]
    );
}

#[test]
fn g80_changes_the_init_plane() {
    // 002 G98, second example:
    // N030 G80 Z20
    // N040 G81 Z15      (rapid to Z10, feed up to Z15, rapid to Z20)
    let r = run_on(
        "hurco-lathe",
        "N010 G0 Z10\nN020 G81 Z5 F60\nN030 G80 Z20\nN040 G81 Z15\nN050 G80\nM30\n",
    );
    ok(&r);
    assert_eq!(
        zs(&r),
        vec![
            (1, "rapid", 10.0),
            (2, "feed", 5.0),
            (2, "rapid", 10.0),
            (3, "rapid", 20.0),
            (4, "rapid", 10.0),
            (4, "feed", 15.0),
            (4, "rapid", 20.0),
        ]
    );
}

#[test]
fn g81_g82_with_g99() {
    // 002 G81/G82 examples without the mill's Y: G20, from X4 Z1:
    // G81 X2 Z-1.2 R.1 F10 G99: rapid X (radius 1 in), rapid Z.1, feed
    // Z-1.2, rapid back to R (G99).
    let r = run_on(
        "hurco-lathe",
        "G20 G90\nG0 X4 Z1\nG81 X2 Z-1.2 R.1 F10 G99\nG80\nG82 X2 Z-1.2 R.1 F10 P2.2 G99\nM30\n",
    );
    ok(&r);
    let m: Vec<_> = moves(&r)
        .iter()
        .map(|m| (m.0, round(m.1 / 25.4), round(m.3 / 25.4)))
        .collect();
    assert_eq!(
        m,
        vec![
            ("rapid", 2.0, 1.0),
            ("rapid", 1.0, 1.0),
            ("rapid", 1.0, 0.1),
            ("feed", 1.0, -1.2),
            ("rapid", 1.0, 0.1),
            // G82: already at X1 Z.1 (R): feed, dwell 2.2 s, rapid to R.
            ("feed", 1.0, -1.2),
            ("rapid", 1.0, 0.1),
        ]
    );
    let dwells: Vec<f64> = r
        .events
        .iter()
        .filter_map(|e| match e.cmd {
            Canon::Dwell { seconds, .. } => Some(seconds),
            _ => None,
        })
        .collect();
    assert_eq!(dwells, vec![2.2]);
}

#[test]
fn g83_and_g73_pecks() {
    // G83 X2 Z-1.2 R.1 Q.5 G99 (inch): pecks to -.4, -.9, -1.2; after each
    // a rapid to R, then a rapid to .01 in (peck_clearance_mm 0.254) short
    // of the last depth.
    let r = run_on(
        "hurco-lathe",
        "G20 G90\nG0 X2 Z1 F10\nG83 X2 Z-1.2 R.1 Q.5 G99\nM30\n",
    );
    ok(&r);
    let z: Vec<_> = moves(&r)
        .iter()
        .skip(1)
        .map(|m| (m.0, round(m.3 / 25.4)))
        .collect();
    assert_eq!(
        z,
        vec![
            ("rapid", 0.1),
            ("feed", -0.4),
            ("rapid", 0.1),
            ("rapid", -0.39),
            ("feed", -0.9),
            ("rapid", 0.1),
            ("rapid", -0.89),
            ("feed", -1.2),
            ("rapid", 0.1),
        ]
    );
    // G73 (002: feed Q, rapid back A, rapid to just short of the last
    // depth, feed Q): A.05: back to -.35 then -.39; -.85 then -.89.
    let r = run_on(
        "hurco-lathe",
        "G20 G90\nG0 X2 Z1 F10\nG73 X2 Z-1.2 R.1 Q.5 A.05 G99\nM30\n",
    );
    ok(&r);
    let z: Vec<_> = moves(&r)
        .iter()
        .skip(1)
        .map(|m| (m.0, round(m.3 / 25.4)))
        .collect();
    assert_eq!(
        z,
        vec![
            ("rapid", 0.1),
            ("feed", -0.4),
            ("rapid", -0.35),
            ("rapid", -0.39),
            ("feed", -0.9),
            ("rapid", -0.85),
            ("rapid", -0.89),
            ("feed", -1.2),
            ("rapid", 0.1),
        ]
    );
}

#[test]
fn g84_and_g74_reverse_the_spindle() {
    // G84: feed to depth, spindle reverses, feed back to R, spindle
    // reverses again; G98 then returns to the init plane (Z1).
    let r = run_on(
        "hurco-lathe",
        "G20 G90 G95 M03 S200\nG0 X0 Z1\nG84 Z-.5 R.2 F.05\nM30\n",
    );
    ok(&r);
    let seq: Vec<String> = r
        .events
        .iter()
        .filter_map(|e| match &e.cmd {
            Canon::Spindle { dir, .. } => Some(format!("{dir:?}")),
            Canon::Feed { m, .. } => Some(format!("feed {}", round(m.to[2] / 25.4))),
            Canon::Rapid { m, .. } => Some(format!("rapid {}", round(m.to[2] / 25.4))),
            _ => None,
        })
        .collect();
    assert_eq!(
        seq,
        vec![
            "Cw",
            "rapid 1",
            "rapid 0.2",
            "feed -0.5",
            "Ccw",
            "feed 0.2",
            "Cw",
            "rapid 1",
            // M30 turns the spindle off (002).
            "Stop"
        ]
    );
    // G74 left hand: the spindle runs CCW into the hole, CW out.
    let r = run_on(
        "hurco-lathe",
        "G20 G90 G95 M04 S200\nG0 X0 Z1\nG74 Z-.5 R.2 F.05\nM30\n",
    );
    ok(&r);
    let dirs: Vec<SpindleDir> = r
        .events
        .iter()
        .filter_map(|e| match e.cmd {
            Canon::Spindle { dir, .. } => Some(dir),
            _ => None,
        })
        .collect();
    assert_eq!(
        dirs,
        vec![
            SpindleDir::Ccw,
            SpindleDir::Cw,
            SpindleDir::Ccw,
            SpindleDir::Stop
        ]
    );
}

#[test]
fn drill_cycle_alarms() {
    // The mill examples' Y: not an address of the lathe control (HU-001).
    let r = run_on("hurco-lathe", "G90\nG73 X2 Y2 Z-1.2 R.1 Q.5 G99\n");
    assert_eq!(alarm(&r), ("HU-001", 2, 8));
    // G00 in a G80 block.
    let r = run_on("hurco-lathe", "G80 G00 Z20\n");
    assert_eq!(alarm(&r), ("HU-062", 1, 5));
    // G83 without Q.
    let r = run_on("hurco-lathe", "G0 Z10\nG83 Z-5 F50\n");
    assert_eq!(alarm(&r), ("HU-015", 2, 1));
}
