//! Transforms of programmed points, before the work-offset stack
//! (fanuc-semantics §6.1): scaling and mirror image (G51, 000 §15.2-15.3)
//! then coordinate rotation (G68, 000 §15.4), and the polar coordinate
//! input of G16 (000 §8.3).
//!
//! Everything here is pure geometry on [`Pos`] values in program units
//! (mm, degrees); the interpreter owns the state and the alarms.

use kerf_canon::{Plane, Pos};

/// Scaling / mirror image about a centre, one factor per linear axis
/// (X, Y, Z); a negative factor mirrors that axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Scale {
    /// Scaling centre (program coordinates, X Y Z).
    pub center: [f64; 3],
    /// Factor per axis.
    pub factor: [f64; 3],
}

/// Coordinate rotation in a plane about a centre.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rotation {
    /// The plane the rotation acts in.
    pub plane: Plane,
    /// Centre in the plane (after scaling: 000 §15.4.2 scales the centre).
    pub center: (f64, f64),
    /// Angle in degrees, counter-clockwise positive.
    pub deg: f64,
}

/// The active transforms.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Xform {
    /// G51 in force.
    pub scale: Option<Scale>,
    /// G68 in force.
    pub rot: Option<Rotation>,
}

impl Xform {
    /// True when a point is changed by the transforms.
    #[inline]
    pub fn active(&self) -> bool {
        self.scale.is_some() || self.rot.is_some()
    }

    /// Program coordinates → work coordinates: scaling first, then rotation
    /// (000 §15.4.2).
    pub fn forward(&self, p: &Pos) -> Pos {
        let mut q = *p;
        if let Some(s) = &self.scale {
            for i in 0..3 {
                q[i] = s.center[i] + (q[i] - s.center[i]) * s.factor[i];
            }
        }
        if let Some(r) = &self.rot {
            let (a1, a2, _) = r.plane.axes();
            let (u, v) = rotate((q[a1], q[a2]), r.center, r.deg);
            q[a1] = u;
            q[a2] = v;
        }
        q
    }

    /// Work coordinates → program coordinates (the inverse of
    /// [`Xform::forward`]; factors are never zero).
    pub fn inverse(&self, p: &Pos) -> Pos {
        let mut q = *p;
        if let Some(r) = &self.rot {
            let (a1, a2, _) = r.plane.axes();
            let (u, v) = rotate((q[a1], q[a2]), r.center, -r.deg);
            q[a1] = u;
            q[a2] = v;
        }
        if let Some(s) = &self.scale {
            for i in 0..3 {
                q[i] = s.center[i] + (q[i] - s.center[i]) / s.factor[i];
            }
        }
        q
    }

    /// True when the transforms mirror the plane (an odd number of its two
    /// axes has a negative factor): arcs and compensation sides reverse.
    pub fn mirrors(&self, plane: Plane) -> bool {
        match &self.scale {
            None => false,
            Some(s) => {
                let (a1, a2, _) = plane.axes();
                (s.factor[a1] < 0.0) != (s.factor[a2] < 0.0)
            }
        }
    }

    /// The factors of a plane's two axes (1 when not scaling).
    pub fn plane_factors(&self, plane: Plane) -> (f64, f64) {
        match &self.scale {
            None => (1.0, 1.0),
            Some(s) => {
                let (a1, a2, _) = plane.axes();
                (s.factor[a1], s.factor[a2])
            }
        }
    }
}

/// Rotates `p` about `c` by `deg` degrees (counter-clockwise positive).
pub fn rotate(p: (f64, f64), c: (f64, f64), deg: f64) -> (f64, f64) {
    if deg == 0.0 {
        return p;
    }
    let (s, co) = deg.to_radians().sin_cos();
    let (dx, dy) = (p.0 - c.0, p.1 - c.1);
    (c.0 + dx * co - dy * s, c.1 + dx * s + dy * co)
}

/// A polar point: `origin` + `r` at `deg` degrees from the plane's first
/// axis, counter-clockwise positive.
pub fn polar_point(origin: (f64, f64), r: f64, deg: f64) -> (f64, f64) {
    let (s, c) = deg.to_radians().sin_cos();
    (origin.0 + r * c, origin.1 + r * s)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: (f64, f64), b: (f64, f64)) {
        assert!(
            (a.0 - b.0).abs() < 1e-9 && (a.1 - b.1).abs() < 1e-9,
            "{a:?} != {b:?}"
        );
    }

    #[test]
    fn rotation_about_a_centre() {
        // (100, 0) about (70, 30) by 90°: offset (30, -30) → (30, 30).
        close(rotate((100.0, 0.0), (70.0, 30.0), 90.0), (100.0, 60.0));
        // 60°: offset (1, 0) → (cos 60, sin 60) = (0.5, 0.8660254037844386).
        close(
            rotate((1.0, 0.0), (0.0, 0.0), 60.0),
            (0.5, 0.866_025_403_784_438_6),
        );
    }

    #[test]
    fn scaling_then_rotation_and_back() {
        let x = Xform {
            scale: Some(Scale {
                center: [10.0, 0.0, 0.0],
                factor: [2.0, -1.5, 1.0],
            }),
            rot: Some(Rotation {
                plane: Plane::XY,
                center: (0.0, 0.0),
                deg: 90.0,
            }),
        };
        // (20, 4, 5): scaled about (10, 0): (30, -6, 5); rotated 90°: (6, 30, 5).
        let f = x.forward(&[20.0, 4.0, 5.0, 0.0, 0.0, 0.0]);
        close((f[0], f[1]), (6.0, 30.0));
        assert_eq!(f[2], 5.0);
        let b = x.inverse(&f);
        close((b[0], b[1]), (20.0, 4.0));
        assert!(x.mirrors(Plane::XY));
        assert!(!x.mirrors(Plane::ZX));
    }

    #[test]
    fn polar_points() {
        // Bolt circle of 000 §8.3: radius 20 about (60, 44), 120°:
        // (60 - 10, 44 + 17.320508075688775).
        close(
            polar_point((60.0, 44.0), 20.0, 120.0),
            (50.0, 61.320_508_075_688_77),
        );
    }
}
