//! G112/G113 polar coordinate interpolation (000 §4.6), and the mode
//! handling it shares with G107 cylindrical interpolation (000 §4.7,
//! `cylindrical.rs`): the codes that switch the modes, the codes a mode
//! forbids, and the virtual-plane arc. Geometry: [`crate::rotary`].
//!
//! In G112 the program is Cartesian in the plane of the linear axis X and
//! a virtual axis addressed as C (mm, centred on the rotary axis, 0 at
//! G112). Each G01/G02/G03 is followed as a chain of `Canon::Feed` chords
//! in the machine axes X (signed radius) and C (degrees), within the
//! profile's `interp_tolerance_mm` of the programmed path.

use super::*;
use crate::rotary::{self, Path};

/// The rotary-axis interpolation in force.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(super) enum RotInterp {
    /// Neither (G113, G107 C0).
    #[default]
    Off,
    /// G112. `c0` is the program C angle when G112 was commanded: the
    /// direction of the virtual plane's +X.
    Polar { c0: f64 },
    /// G107 C`r`: the cylinder radius in mm.
    Cylinder { r: f64 },
}

const X: usize = Axis::X as usize;
const C: usize = Axis::C as usize;

/// Default chord tolerance in the virtual plane, mm.
const CHORD_TOL: f64 = 0.001;

/// G codes that neither mode accepts: coordinate systems and offsets
/// (G10, G52, G53, G54-G59, G92), reference returns (G27-G30), plane
/// and unit changes, G16 polar command, G51 scaling, G68 rotation.
fn forbidden_in_mode(m: Means) -> bool {
    use crate::dialect::meaning::OneShot::*;
    matches!(
        m,
        Means::OneShot(FrameData | LocalCoords | MachineCoords | CoordinateSetting | RefReturn(_))
            | Means::PolarCommand(true)
            | Means::Plane(_)
            | Means::Units(_)
            | Means::Scaling(true)
            | Means::Work(_)
            | Means::Rotation(true)
    )
}

impl Interp {
    /// Runs the block's G112, G113 and G107 and checks the block against
    /// the mode in force (codes in the block that starts a mode act before
    /// it). Returns true when the block's axis words were G107's radius
    /// (the block then makes no move).
    pub(super) fn rotary_interp_codes(&mut self) -> R<bool> {
        if !self.cfg.dialect.caps.rotary_interp {
            return Ok(false);
        }
        let was = self.frames.rot;
        let mut data = false;
        for i in 0..self.words.ng {
            let (c, at) = self.words.g[i];
            match self.means_of(c) {
                Some(Means::PolarInterp(on)) => self.g112_g113(on, at)?,
                Some(Means::Cylindrical(true)) => {
                    self.g107(at)?;
                    data = true;
                }
                _ => {}
            }
        }
        if self.frames.rot == RotInterp::Off || was == RotInterp::Off {
            return Ok(data);
        }
        let (kind, name, cancel) = self.mode_names();
        for i in 0..self.words.ng {
            let (c, at) = self.words.g[i];
            if self.means_of(c).is_some_and(forbidden_in_mode) {
                return Err(self.alarm(
                    kind,
                    at,
                    format!("G{} is not allowed in {name} ({cancel} first)", fmt_code(c)),
                ));
            }
        }
        Ok(data)
    }

    /// The alarm kind, name and cancel code of the mode in force.
    pub(super) fn mode_names(&self) -> (AlarmKind, &'static str, &'static str) {
        match self.frames.rot {
            RotInterp::Cylinder { .. } => (
                AlarmKind::CylindricalInterp,
                "cylindrical interpolation",
                "G107 C0",
            ),
            _ => (
                AlarmKind::PolarInterp,
                "polar coordinate interpolation",
                "G113",
            ),
        }
    }

    /// G16, scaling or rotation will be in force after this block.
    pub(super) fn transform_after_block(&self) -> Option<&'static str> {
        let g = |c| self.words.has_g(c);
        if (self.frames.polar && !g(150)) || g(160) {
            Some("polar coordinate command (G15 first)")
        } else if (self.frames.xf.scale.is_some() && !g(500)) || g(510) {
            Some("scaling (G50 first)")
        } else if (self.frames.xf.rot.is_some() && !g(690)) || g(680) {
            Some("coordinate rotation (G69 first)")
        } else {
            None
        }
    }

    /// G112 (`on`) / G113: in a block without axis words. G112 needs the
    /// X and C axes and no G16, G51, G68 or G107 in force; the C angle at
    /// G112 is the virtual plane's angle 0 (Fanuc). G112 in G112 and G113
    /// outside it change nothing.
    fn g112_g113(&mut self, on: bool, at: u32) -> R<()> {
        let alarm = |me: &Self, msg: &str| Err(me.alarm(AlarmKind::PolarInterp, at, msg));
        if self.has_axis_word() {
            return alarm(
                self,
                "G112/G113 must be commanded in a block without axis words",
            );
        }
        if !on {
            if matches!(self.frames.rot, RotInterp::Polar { .. }) {
                self.frames.rot = RotInterp::Off;
            }
            return Ok(());
        }
        match self.frames.rot {
            RotInterp::Polar { .. } => return Ok(()),
            RotInterp::Cylinder { .. } => {
                return alarm(self, "G112 in cylindrical interpolation (G107 C0 first)")
            }
            RotInterp::Off => {}
        }
        if !self.cfg.has_axis[X] || !self.cfg.has_axis[C] {
            return alarm(
                self,
                "polar coordinate interpolation needs the linear axis X and the rotary axis C",
            );
        }
        if let Some(what) = self.transform_after_block() {
            return Err(self.alarm(AlarmKind::PolarInterp, at, format!("G112 in {what}")));
        }
        self.frames.rot = RotInterp::Polar {
            c0: self.prog_pos()[C],
        };
        Ok(())
    }

    /// The chord tolerance of polar and cylindrical interpolation (mm in
    /// the virtual plane): the profile's `interp_tolerance_mm`.
    pub(super) fn chord_tol(&self) -> f64 {
        self.cfg
            .profile
            .param("interp_tolerance_mm", CHORD_TOL)
            .max(1e-6)
    }

    /// A block's motion in G112 or G107.
    pub(super) fn rotary_interp_motion(&mut self) -> R<()> {
        match self.frames.rot {
            RotInterp::Polar { c0 } => self.polar_motion(c0),
            RotInterp::Cylinder { r } => self.cylinder_motion(r),
            RotInterp::Off => Ok(()),
        }
    }

    /// G01/G02/G03 in G112: X and C words are the virtual point (mm,
    /// absolute or incremental); the other axes move linearly along.
    /// G00 alarms (Fanuc).
    fn polar_motion(&mut self, c0: f64) -> R<()> {
        let mode = self.modal.motion.means;
        let (tw, any) = self.target()?;
        let at = self.motion_at();
        if mode == MotionMode::Rapid {
            if any {
                return Err(self.alarm(
                    AlarmKind::PolarInterp,
                    at,
                    "G00 is not allowed in polar coordinate interpolation (G113 first)",
                ));
            }
            return Ok(());
        }
        let cur = self.prog_pos();
        let th0 = cur[C] - c0;
        let v0 = rotary::polar_virtual((cur[X], th0));
        let coord = |me: &Self, l: u8, from: f64| -> R<f64> {
            Ok(match me.words.get(l) {
                Some(w) => {
                    me.check_range(l, w)?;
                    let v = me.linear(w);
                    if me.modal.absolute() {
                        v
                    } else {
                        from + v
                    }
                }
                None => from,
            })
        };
        let v1 = (coord(self, b'X', v0.0)?, coord(self, b'C', v0.1)?);
        let path = match mode {
            MotionMode::Linear if any => Path::Line { s: v0, e: v1 },
            MotionMode::ArcCw | MotionMode::ArcCcw => {
                let ijk = Some((b'I', b'J'));
                match self.plane_arc(v0, v1, any, mode == MotionMode::ArcCcw, at, ijk)? {
                    Some(p) => p,
                    None => return Ok(()),
                }
            }
            _ => return Ok(()),
        };
        let feed = self.feed(at)?;
        let chords = rotary::polar_chords(&path, (cur[X], th0), self.chord_tol());
        let points: Vec<Pos> = chords
            .into_iter()
            .map(|(t, (x, th))| {
                let mut p = lerp(&cur, &tw, t);
                p[X] = x;
                p[C] = c0 + th;
                p
            })
            .collect();
        self.chords(&points, feed, at)
    }

    /// An arc in a virtual plane from `s` to `e`: the centre from R, or
    /// from the offsets `ijk` (letters for the plane's first and second
    /// axis; None: R only, G107). None when nothing moves.
    pub(super) fn plane_arc(
        &self,
        s: (f64, f64),
        e: (f64, f64),
        any: bool,
        ccw: bool,
        at: u32,
        ijk: Option<(u8, u8)>,
    ) -> R<Option<Path>> {
        let (kind, name, _) = self.mode_names();
        let ijk_word = [b'I', b'J', b'K'].iter().find_map(|&l| self.words.get(l));
        let center = if let Some(r) = self.words.get(b'R') {
            if !any {
                return Ok(None);
            }
            let rv = self.linear(r);
            if (s.0 - e.0).hypot(s.1 - e.1) < 1e-9 {
                // R with the end at the start: only the other axes move.
                return Ok(Some(Path::Line { s, e: s }));
            }
            arc::center_from_radius(s, e, rv, ccw, self.cfg.arc_tol).map_err(|_| {
                self.alarm(
                    AlarmKind::ArcRadius,
                    r.at,
                    format!(
                        "arc radius {:.4} is smaller than half the chord {:.4}",
                        rv.abs(),
                        (s.0 - e.0).hypot(s.1 - e.1) / 2.0
                    ),
                )
            })?
        } else if let Some(w) = ijk_word {
            let Some((l1, l2)) = ijk else {
                return Err(self.alarm(kind, w.at, format!("an arc in {name} takes R, not I/J/K")));
            };
            let off = |l: u8| self.words.get(l).map(|w| self.linear(w)).unwrap_or(0.0);
            (s.0 + off(l1), s.1 + off(l2))
        } else {
            if !any {
                return Ok(None);
            }
            return Err(self.alarm(
                AlarmKind::ArcNoCenter,
                at,
                "arc without centre (I/J) or radius (R)",
            ));
        };
        let bad_at = ijk_word
            .or_else(|| self.words.get(b'R'))
            .map(|w| w.at)
            .unwrap_or(at);
        let r = match arc::check_end(s, e, center, self.cfg.arc_tol) {
            Ok(r) => r,
            Err(ArcError::EndNotOnCircle { r_start, r_end }) => {
                return Err(self.alarm(
                    AlarmKind::ArcEndPoint,
                    bad_at,
                    format!("arc end point is not on the circle: start radius {r_start:.4}, end radius {r_end:.4}"),
                ))
            }
            Err(_) => {
                return Err(self.alarm(
                    AlarmKind::ArcNoCenter,
                    bad_at,
                    "arc centre coincides with the start point",
                ))
            }
        };
        let sw = arc::sweep(s, e, center, ccw);
        Ok(Some(Path::Arc {
            c: center,
            r,
            a0: (s.1 - center.1).atan2(s.0 - center.0),
            sweep: if ccw { sw } else { -sw },
            e,
        }))
    }
}

/// The point at `t` of the straight move from `a` to `b` (exactly `b` at 1).
pub(super) fn lerp(a: &Pos, b: &Pos, t: f64) -> Pos {
    if t >= 1.0 {
        return *b;
    }
    let mut p = *a;
    for i in 0..NAXES {
        p[i] += t * (b[i] - a[i]);
    }
    p
}
