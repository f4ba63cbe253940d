//! G107 cylindrical interpolation (000 §4.7): `G107 C<r>` starts it for a
//! cylinder of radius r (mm), `G107 C0` ends it.
//!
//! As on Fanuc (G07.1), the rotary axis is still programmed in degrees;
//! the control works on the developed surface, where θ degrees are the
//! length θ·π·r/180. F is the speed on that surface and an arc's R is in
//! mm on it. The development is linear, so G00/G01 moves are ordinary
//! moves; an arc (R only) in the plane of the rotary axis and one linear
//! axis — G17 C-Y or G18 Z-C, C taking X's place — is followed as
//! `Canon::Feed` chords within the profile's `interp_tolerance_mm`.

use super::polar_interp::{lerp, RotInterp};
use super::*;
use crate::rotary;

const C: usize = Axis::C as usize;

impl Interp {
    /// `G107 C<r>`: r > 0 starts cylindrical interpolation, C0 ends it.
    /// The block holds no other axis word; G107 is refused in G112 and in
    /// G16, G51 or G68.
    pub(super) fn g107(&mut self, at: u32) -> R<()> {
        let alarm =
            |me: &Self, at: u32, msg: &str| Err(me.alarm(AlarmKind::CylindricalInterp, at, msg));
        if let Some(w) = [b'X', b'Y', b'Z', b'A', b'B']
            .iter()
            .find_map(|&l| self.words.get(l))
        {
            return alarm(
                self,
                w.at,
                "G107 takes only the cylinder radius C in its block",
            );
        }
        let Some(w) = self.words.get(b'C').filter(|_| self.cfg.has_axis[C]) else {
            return alarm(
                self,
                at,
                "G107 needs the cylinder radius C (C0 cancels); the machine needs a C axis",
            );
        };
        let r = self.linear(w);
        if matches!(self.frames.rot, RotInterp::Polar { .. }) {
            return alarm(
                self,
                at,
                "G107 in polar coordinate interpolation (G113 first)",
            );
        }
        if r < 0.0 {
            return alarm(self, w.at, "negative cylinder radius");
        }
        if r == 0.0 {
            self.frames.rot = RotInterp::Off;
            self.modal.cylindrical = modal::Active::none(false);
            return Ok(());
        }
        if let Some(what) = self.transform_after_block() {
            return Err(self.alarm(AlarmKind::CylindricalInterp, at, format!("G107 in {what}")));
        }
        self.frames.rot = RotInterp::Cylinder { r };
        Ok(())
    }

    /// A block's motion in G107: straight moves as usual (C in degrees),
    /// arcs on the developed surface.
    pub(super) fn cylinder_motion(&mut self, r: f64) -> R<()> {
        let mode = self.modal.motion.means;
        let (tw, any) = self.target()?;
        let at = self.motion_at();
        match mode {
            MotionMode::Rapid | MotionMode::Linear if any => {
                return self.move_line(mode == MotionMode::Rapid, tw, at)
            }
            MotionMode::ArcCw | MotionMode::ArcCcw => {}
            _ => return Ok(()),
        }
        let (a1, a2) = match self.modal.plane.means {
            Plane::XY => (C, Axis::Y as usize),
            Plane::ZX => (Axis::Z as usize, C),
            Plane::YZ => {
                return Err(self.alarm(
                    AlarmKind::CylindricalInterp,
                    at,
                    "an arc in cylindrical interpolation must be in G17 (C-Y) or G18 (Z-C)",
                ))
            }
        };
        // mm on the surface per degree of C.
        let k = std::f64::consts::PI * r / 180.0;
        let scale = |i: usize| if i == C { k } else { 1.0 };
        let cur = self.prog_pos();
        let dev = |p: &Pos| (p[a1] * scale(a1), p[a2] * scale(a2));
        let Some(path) = self.plane_arc(
            dev(&cur),
            dev(&tw),
            any,
            mode == MotionMode::ArcCcw,
            at,
            None,
        )?
        else {
            return Ok(());
        };
        let feed = self.feed(at)?;
        let n = match path {
            rotary::Path::Arc { r, sweep, .. } => rotary::arc_chords(r, sweep, self.chord_tol()),
            rotary::Path::Line { .. } => 1,
        };
        let mut points = Vec::with_capacity(n);
        for i in 1..=n {
            let t = if i == n { 1.0 } else { i as f64 / n as f64 };
            let mut p = lerp(&cur, &tw, t);
            if t < 1.0 {
                let q = path.at(t);
                p[a1] = q.0 / scale(a1);
                p[a2] = q.1 / scale(a2);
            }
            points.push(p);
        }
        self.chords(&points, feed, at)
    }
}
