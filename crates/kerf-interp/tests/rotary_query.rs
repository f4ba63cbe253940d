//! `Interp::rotary_interpolation`: the G112 / G107 mode a sink reads on
//! every move, checked against the manual's own examples (000 §4.6 and
//! §4.7, as in examples/hx/): on for the moves between G112 and G113 and
//! after G107 with a radius, in the plane the program selected.

use kerf_canon::Plane;
use kerf_interp::{Interp, Profile, Settings, Step};

/// For each motion of `path`, whether its end was commanded with the mode.
fn modes_per_move(path: &str) -> Vec<Option<(bool, Plane)>> {
    let text = std::fs::read(format!("{}/../../{path}", env!("CARGO_MANIFEST_DIR"))).unwrap();
    let mut it = Interp::new(Profile::builtin("hx-mc").unwrap(), Settings::default());
    it.load_main(path, Box::new(std::io::Cursor::new(text)));
    let mut modes = Vec::new();
    loop {
        match it.step() {
            Step::Event(e) if e.motion().is_some() => modes.push(it.rotary_interpolation()),
            Step::Event(_) => {}
            Step::End => break,
            Step::Alarm(a) => panic!("{path}: {a:?}"),
        }
    }
    modes
}

#[test]
fn polar_interpolation_is_on_between_g112_and_g113() {
    let modes = modes_per_move("examples/hx/polar_interp_g112.nc");
    // The rapid to X60 C0 before G112, then G112's contour in XY.
    assert_eq!(modes.first(), Some(&None));
    assert!(modes.len() > 10, "{modes:?}");
    let inside = &modes[1..];
    assert!(
        inside.iter().all(|m| *m == Some((true, Plane::XY))),
        "{modes:?}"
    );
}

#[test]
fn cylindrical_interpolation_is_on_after_g107_in_the_zx_plane() {
    let modes = modes_per_move("examples/hx/cylindrical_g107.nc");
    // G00 Z100 C0 and the G01 G18 Z0 C0 before G107; G18 for the rest.
    assert_eq!(modes[0], None);
    assert!(modes.len() > 8, "{modes:?}");
    assert!(modes.contains(&Some((false, Plane::ZX))), "{modes:?}");
    assert!(
        modes
            .iter()
            .all(|m| matches!(m, None | Some((false, Plane::ZX)))),
        "{modes:?}"
    );
}
