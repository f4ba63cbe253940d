//! The plane point and vector as a `(first, second)` pair in a plane's
//! axes, mm, and the arithmetic the geometry modules share.

/// A point or vector in a plane's (first, second) axes.
pub type P = (f64, f64);

/// `a - b`.
pub fn sub(a: P, b: P) -> P {
    (a.0 - b.0, a.1 - b.1)
}
/// `a + b`.
pub fn add(a: P, b: P) -> P {
    (a.0 + b.0, a.1 + b.1)
}
/// `a · k`.
pub fn mul(a: P, k: f64) -> P {
    (a.0 * k, a.1 * k)
}
/// Dot product.
pub fn dot(a: P, b: P) -> f64 {
    a.0 * b.0 + a.1 * b.1
}
/// z of the cross product: positive when `b` turns counter-clockwise
/// from `a`.
pub fn cross(a: P, b: P) -> f64 {
    a.0 * b.1 - a.1 * b.0
}
/// Length.
pub fn len(a: P) -> f64 {
    a.0.hypot(a.1)
}
/// The left normal of a direction (turned 90° counter-clockwise).
pub fn left(u: P) -> P {
    (-u.1, u.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arithmetic() {
        assert_eq!(sub((3.0, 4.0), (1.0, 1.0)), (2.0, 3.0));
        assert_eq!(add((3.0, 4.0), (1.0, 1.0)), (4.0, 5.0));
        assert_eq!(mul((3.0, 4.0), 2.0), (6.0, 8.0));
        assert_eq!(dot((3.0, 4.0), (-4.0, 3.0)), 0.0);
        assert_eq!(cross((1.0, 0.0), (0.0, 1.0)), 1.0);
        assert_eq!(len((3.0, 4.0)), 5.0);
        assert_eq!(left((1.0, 0.0)), (0.0, 1.0));
    }
}
