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
