//! `ModeChange::Rotary`: the G112 / G107 mode the interpreter reports in
//! the event stream, checked against the manual's own examples (000 §4.6
//! and §4.7, as in examples/hx/): one event where each block switches the
//! mode, with G107's cylinder radius and the plane the program selected,
//! and `Interp::rotary_mode` agreeing with the last event on every move.

use kerf_canon::{Canon, ModeChange, Plane, RotaryMode};
use kerf_interp::{Interp, Profile, Settings, Step};

/// The rotary mode events of `path` as (line, mode), and for each motion
/// whether `rotary_mode()` equals the last event's mode.
fn events(path: &str) -> (Vec<(u32, RotaryMode)>, Vec<bool>) {
    let text = std::fs::read(format!("{}/../../{path}", env!("CARGO_MANIFEST_DIR"))).unwrap();
    let mut it = Interp::new(Profile::builtin("hx-mc").unwrap(), Settings::default());
    it.load_main(path, Box::new(std::io::Cursor::new(text)));
    let (mut modes, mut agree) = (Vec::new(), Vec::new());
    loop {
        match it.step() {
            Step::Event(e) => match e.cmd {
                Canon::Mode(ModeChange::Rotary(m)) => modes.push((e.src.line, m)),
                _ if e.motion().is_some() => {
                    let last = modes.last().map_or(RotaryMode::Off, |m| m.1);
                    agree.push(it.rotary_mode() == last);
                }
                _ => {}
            },
            Step::End => break,
            Step::Alarm(a) => panic!("{path}: {a:?}"),
        }
    }
    (modes, agree)
}

#[test]
fn polar_interpolation_is_reported_at_g112_and_g113() {
    let (modes, agree) = events("examples/hx/polar_interp_g112.nc");
    // G112 on line 3, G113 on line 13.
    assert_eq!(modes, vec![(3, RotaryMode::Polar), (13, RotaryMode::Off)]);
    assert!(agree.len() > 10 && agree.iter().all(|&a| a), "{agree:?}");
}

#[test]
fn cylindrical_interpolation_carries_the_radius_and_the_zx_plane() {
    let (modes, agree) = events("examples/hx/cylindrical_g107.nc");
    // G107 C57.299 on line 4 after G18 on line 3; G107 C0 on line 16.
    let on = RotaryMode::Cylinder {
        radius: 57.299,
        plane: Plane::ZX,
    };
    assert_eq!(modes, vec![(4, on), (16, RotaryMode::Off)]);
    assert!(agree.len() > 8 && agree.iter().all(|&a| a), "{agree:?}");
}
