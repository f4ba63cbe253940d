//! `RotaryMode::mm_per_degree`: the developed length of C on the G107
//! cylinder (000 §4.7: θ degrees are θ·π·r/180 mm on the surface).

use kerf_canon::{Plane, RotaryMode};

#[test]
fn a_quarter_turn_of_a_30_mm_cylinder_is_a_quarter_of_its_circumference() {
    let m = RotaryMode::Cylinder {
        radius: 30.0,
        plane: Plane::ZX,
    };
    // Circumference 2·π·30 = 188.4956 mm; a quarter is 47.1239 mm.
    let quarter = 90.0 * m.mm_per_degree().unwrap();
    assert!((quarter - 47.123_889_8).abs() < 1e-6, "{quarter}");
}

#[test]
fn only_cylindrical_interpolation_develops_c() {
    assert_eq!(RotaryMode::Off.mm_per_degree(), None);
    assert_eq!(RotaryMode::Polar.mm_per_degree(), None);
}

#[test]
fn a_polar_move_is_measured_on_the_face() {
    // 000 §4.6's example: at X20, C0 to the virtual point (20, 10), which
    // is X = √500 = 22.36068, C = 26.565051°: 10 mm on the face, however
    // little X moves.
    let r1 = 500f64.sqrt();
    let p0 = [-380.0, 0.0, -200.0, 0.0, 0.0, 0.0];
    let p1 = [-400.0 + r1, 0.0, -200.0, 0.0, 0.0, 26.565_051_177];
    let len = RotaryMode::Polar
        .programmed_len(&p0, &p1, 20.0, r1)
        .unwrap();
    assert!((len - 10.0).abs() < 1e-8, "{len}");
    // Half a turn at radius 10 crosses the centre: 20 mm; with Z 5 mm
    // down as well, √(400 + 25).
    let p1 = [0.0, 0.0, -5.0, 0.0, 0.0, 180.0];
    let len = RotaryMode::Polar
        .programmed_len(&[0.0; 6], &p1, 10.0, 10.0)
        .unwrap();
    assert!((len - 425f64.sqrt()).abs() < 1e-12, "{len}");
}

#[test]
fn a_cylinder_move_counts_c_as_its_arc_and_off_is_the_machines_own() {
    // r = 10: Z20 C180 is √(20² + (10π)²) on the developed surface.
    let m = RotaryMode::Cylinder {
        radius: 10.0,
        plane: Plane::ZX,
    };
    let p1 = [0.0, 0.0, 20.0, 0.0, 0.0, 180.0];
    let len = m.programmed_len(&[0.0; 6], &p1, 0.0, 0.0).unwrap();
    let pi = std::f64::consts::PI;
    assert!((len - (400.0 + 100.0 * pi * pi).sqrt()).abs() < 1e-12);
    assert_eq!(
        RotaryMode::Off.programmed_len(&[0.0; 6], &p1, 0.0, 0.0),
        None
    );
}
