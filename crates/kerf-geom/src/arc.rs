//! Circular interpolation geometry in a plane: centre from R, end-point
//! checks, sweep angle and extreme points (for travel checks and bounding
//! boxes). Coordinates are (u, v) in the plane's (first, second) axes; CCW
//! is counter-clockwise seen from the positive end of the plane normal.

/// Why an arc cannot be made.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ArcError {
    /// |R| smaller than half the chord (beyond tolerance), or zero.
    RadiusTooSmall { r: f64, half_chord: f64 },
    /// Start and end radii differ by more than the tolerance.
    EndNotOnCircle { r_start: f64, r_end: f64 },
    /// Centre coincides with the start point.
    ZeroRadius,
}

/// The centre of an arc from start `s`, end `e`, signed radius `r`
/// (negative: the arc of more than 180°) and direction (`ccw`).
/// A radius up to `tol` shorter than half the chord is accepted as a
/// half circle.
pub fn center_from_radius(
    s: (f64, f64),
    e: (f64, f64),
    r: f64,
    ccw: bool,
    tol: f64,
) -> Result<(f64, f64), ArcError> {
    let (dx, dy) = (e.0 - s.0, e.1 - s.1);
    let chord = (dx * dx + dy * dy).sqrt();
    let half = chord / 2.0;
    let ra = r.abs();
    if ra == 0.0 || ra < half - tol {
        return Err(ArcError::RadiusTooSmall {
            r,
            half_chord: half,
        });
    }
    let h = if ra <= half {
        0.0
    } else {
        (ra * ra - half * half).sqrt()
    };
    let (mx, my) = ((s.0 + e.0) / 2.0, (s.1 + e.1) / 2.0);
    // Unit normal to the left of the chord direction.
    let (nx, ny) = (-dy / chord, dx / chord);
    // Minor arc CCW: centre on the left; CW: on the right. R < 0 flips.
    let mut side = if ccw { 1.0 } else { -1.0 };
    if r < 0.0 {
        side = -side;
    }
    Ok((mx + side * h * nx, my + side * h * ny))
}

/// Checks that `e` lies on the circle through `s` about `c` within `tol`;
/// returns the start radius.
pub fn check_end(s: (f64, f64), e: (f64, f64), c: (f64, f64), tol: f64) -> Result<f64, ArcError> {
    let r1 = (s.0 - c.0).hypot(s.1 - c.1);
    let r2 = (e.0 - c.0).hypot(e.1 - c.1);
    if r1 < 1e-9 {
        return Err(ArcError::ZeroRadius);
    }
    if (r1 - r2).abs() > tol {
        return Err(ArcError::EndNotOnCircle {
            r_start: r1,
            r_end: r2,
        });
    }
    Ok(r1)
}

pub use kerf_canon::geom::{bbox, sweep};

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::{PI, TAU};

    fn close(a: (f64, f64), b: (f64, f64)) -> bool {
        (a.0 - b.0).abs() < 1e-9 && (a.1 - b.1).abs() < 1e-9
    }

    #[test]
    fn radius_sign_picks_the_arc() {
        // Quarter circle of radius 10 from (10,0) to (0,10): centres (0,0) or (10,10).
        let s = (10.0, 0.0);
        let e = (0.0, 10.0);
        assert!(close(
            center_from_radius(s, e, 10.0, true, 0.0).unwrap(),
            (0.0, 0.0)
        ));
        assert!(close(
            center_from_radius(s, e, -10.0, true, 0.0).unwrap(),
            (10.0, 10.0)
        ));
        assert!(close(
            center_from_radius(s, e, 10.0, false, 0.0).unwrap(),
            (10.0, 10.0)
        ));
        assert!(close(
            center_from_radius(s, e, -10.0, false, 0.0).unwrap(),
            (0.0, 0.0)
        ));
    }

    #[test]
    fn half_circle_and_too_small_radius() {
        let c = center_from_radius((0.0, 0.0), (20.0, 0.0), 10.0, false, 0.0).unwrap();
        assert!(close(c, (10.0, 0.0)));
        assert!(matches!(
            center_from_radius((0.0, 0.0), (20.0, 0.0), 9.0, false, 0.01),
            Err(ArcError::RadiusTooSmall { .. })
        ));
        // Within tolerance: a half circle.
        let c = center_from_radius((0.0, 0.0), (20.0, 0.0), 9.995, false, 0.01).unwrap();
        assert!(close(c, (10.0, 0.0)));
    }

    #[test]
    fn sweep_angles() {
        let c = (0.0, 0.0);
        assert!((sweep((10.0, 0.0), (0.0, 10.0), c, true) - PI / 2.0).abs() < 1e-12);
        assert!((sweep((10.0, 0.0), (0.0, 10.0), c, false) - 3.0 * PI / 2.0).abs() < 1e-12);
        assert!((sweep((10.0, 0.0), (10.0, 0.0), c, false) - TAU).abs() < 1e-12);
    }

    #[test]
    fn end_point_check() {
        assert!(check_end((10.0, 0.0), (0.0, 10.0), (0.0, 0.0), 0.01).is_ok());
        assert!(matches!(
            check_end((10.0, 0.0), (0.0, 10.5), (0.0, 0.0), 0.01),
            Err(ArcError::EndNotOnCircle { .. })
        ));
        assert_eq!(
            check_end((0.0, 0.0), (0.0, 0.0), (0.0, 0.0), 0.01),
            Err(ArcError::ZeroRadius)
        );
    }

    #[test]
    fn bbox_includes_quadrant_points() {
        // CCW half circle from (10,0) to (-10,0) passes (0,10).
        let b = bbox((10.0, 0.0), (-10.0, 0.0), (0.0, 0.0), true);
        assert!((b.3 - 10.0).abs() < 1e-12 && b.1.abs() < 1e-12);
        // CW the other way passes (0,-10).
        let b = bbox((10.0, 0.0), (-10.0, 0.0), (0.0, 0.0), false);
        assert!((b.1 + 10.0).abs() < 1e-12 && b.3.abs() < 1e-12);
    }
}
