//! The HX's coordinate transform and coordinate-system codes: G15/G16
//! polar coordinate command (000 §8.3), G50/G51 scaling and mirror image
//! (§15.2, §15.3), G68/G69 coordinate rotation (§15.4), G52 local
//! coordinates (§7.3), `G10` (interp/offset_data.rs)
//! and the G22 area of stored stroke check 2 (§15.5.3).
//! The geometry lives in [`crate::xform`].

use super::*;
use crate::dialect::meaning::{Kind, KindSet, OneShot};
use crate::xform::{Rotation, Scale};

impl Interp {
    /// Runs the block's transform and coordinate-system codes (after the
    /// modal codes, before the other one-shot codes and motion). Returns
    /// true when the block's axis words were the data of one of them: the
    /// block then makes no move.
    pub(super) fn transform_codes(&mut self, one_shot: &[(u16, u32)], kinds: KindSet) -> R<bool> {
        if !self.cfg.dialect.caps.frame_codes {
            return Ok(false);
        }
        let frame = [
            Kind::PolarCommand,
            Kind::Scaling,
            Kind::Rotation,
            Kind::Stroke,
        ];
        let mut data = kinds.any(&frame) && self.frame_modal_codes()?;
        if let Some(r) = self.frames.xf.rot {
            if r.plane != self.modal.plane.means {
                let at = self
                    .block_g(|m| matches!(m, Means::Plane(_)))
                    .map_or(0, |g| g.1);
                return Err(self.alarm(
                    AlarmKind::TransformConflict,
                    at,
                    "plane change in coordinate rotation mode (cancel with G69 first)",
                ));
            }
        }
        for &(c, at) in one_shot {
            let Some(Means::OneShot(what)) = self.gcode(c).map(|g| g.means) else {
                continue;
            };
            let not_in_xf = matches!(what, OneShot::RefReturn(_) | OneShot::CoordinateSetting);
            if self.frames.xf.active() && not_in_xf {
                let what = if self.frames.xf.rot.is_some() {
                    "coordinate rotation (G69 first)"
                } else {
                    "scaling (G50 first)"
                };
                return Err(self.alarm(
                    AlarmKind::TransformConflict,
                    at,
                    format!("G{} is not allowed in {what}", fmt_code(c)),
                ));
            }
            match what {
                OneShot::LocalCoords => {
                    self.g52();
                    data = true;
                }
                OneShot::FrameData => {
                    self.g10(at)?;
                    data = true;
                }
                _ => {}
            }
        }
        Ok(data)
    }

    /// The block's G15/G16, G50/G51, G68/G69 and G22 (only called for a
    /// block that has one). True when the axis words were G51's, G68's
    /// or G22's data.
    fn frame_modal_codes(&mut self) -> R<bool> {
        let mut data = false;
        // Cutter compensation works on the transformed path, so G68/G69
        // may change the rotation in offset mode (000 §15.4.2's N1-N8).
        // Scaling is set before G41/G42 and cancelled after G40 (000
        // §15.4.2: G51, G68, G41 … G40, G69, G50).
        if self.common.comp.as_deref().is_some_and(|c| c.on())
            && self.modal.cutter_comp.means != CompSide::Off
        {
            if let Some((c, at)) = self.block_g(|m| matches!(m, Means::Scaling(_))) {
                return Err(self.alarm(
                    AlarmKind::TransformConflict,
                    at,
                    format!(
                        "G{} in cutter compensation mode: command scaling before G41/G42 and cancel it after G40 (000 §15.4.2)",
                        fmt_code(c)
                    ),
                ));
            }
        }
        // Cancels first, so `G69 G28 …` and `G50 G92 …` are legal.
        for i in 0..self.words.ng {
            match self.gcode(self.words.g[i].0).map(|g| g.means) {
                Some(Means::PolarCommand(false)) => self.frames.polar = false,
                Some(Means::PolarCommand(true)) if !self.frames.polar => {
                    self.frames.polar = true;
                    self.frames.polar_origin.set((0.0, 0.0));
                }
                Some(Means::Scaling(false)) => self.frames.xf.scale = None,
                Some(Means::Rotation(false)) => self.frames.xf.rot = None,
                _ => {}
            }
        }
        for i in 0..self.words.ng {
            let (c, at) = self.words.g[i];
            match self.gcode(c).map(|g| g.means) {
                Some(Means::Scaling(true)) => {
                    self.g51(at)?;
                    data = true;
                }
                Some(Means::Rotation(true)) => {
                    self.g68(at)?;
                    data = true;
                }
                Some(Means::Stroke(true)) => {
                    self.g22(at)?;
                    data = true;
                }
                _ => {}
            }
        }
        Ok(data)
    }

    /// A scale factor: P/I/J/K in 1/1000 (`P2000` = `P2000.` = ×2, 000
    /// §15.2).
    fn scale_factor(&self, w: WVal) -> R<f64> {
        // Always 1/1000, with or without a decimal point: 000 prints every
        // G51 factor with one and means ×2 / ×1.5 (§15.2 `I1000. J1000.`,
        // `I1500. J1500.`, §15.2.2 `I2000. J1000.`, §15.3 `I-1500.`).
        let f = w.v / 1000.0;
        if !(0.001..=999.999).contains(&f.abs()) {
            return Err(self.alarm(
                AlarmKind::OutOfRange,
                w.at,
                format!(
                    "scaling factor {} out of range (±0.001 … ±999.999)",
                    fmt_num(f)
                ),
            ));
        }
        Ok(f)
    }

    /// `G51 X_ Y_ Z_ P_` or `G51 X_ Y_ Z_ I_ J_ K_`: scaling (negative
    /// factors mirror) about the given centre, the current position for
    /// an omitted axis; without P, I, J, K the factors of PI 108-110.
    fn g51(&mut self, at: u32) -> R<()> {
        if self.frames.xf.rot.is_some() {
            return Err(self.alarm(
                AlarmKind::TransformConflict,
                at,
                "G51 in coordinate rotation mode: command G51 before G68 (000 §15.4.2)",
            ));
        }
        self.frames.xf.scale = None;
        let cur = self.prog_pos();
        let mut center = [0.0; 3];
        for (i, c) in center.iter_mut().enumerate() {
            let ax = Axis::ALL[i];
            *c = match self.words.get(ax_letter(ax)) {
                Some(w) => self.axis_value(ax, w),
                None => cur[i],
            };
        }
        let mut factor = [1.0; 3];
        if let Some(p) = self.words.get(b'P') {
            factor = [self.scale_factor(p)?; 3];
        } else {
            for (i, l) in [b'I', b'J', b'K'].into_iter().enumerate() {
                factor[i] = match self.words.get(l) {
                    Some(w) => self.scale_factor(w)?,
                    None => {
                        self.cfg
                            .profile
                            .param(["PI 108", "PI 109", "PI 110"][i], 1000.0)
                            / 1000.0
                    }
                };
            }
        }
        self.frames.xf.scale = Some(Scale { center, factor });
        Ok(())
    }

    /// `G68 X_ Y_ R_` (in the plane's axes): rotation about the given
    /// centre (absolute; the current position when omitted) by R degrees
    /// (decimal-point rule: `R60` = 0.060°, `R60.` = 60°; PI 117 when
    /// omitted). In G91 the angle is added to the rotation in force.
    fn g68(&mut self, at: u32) -> R<()> {
        let plane = self.modal.plane.means;
        let (a1, a2, _) = plane.axes();
        if let Some(r) = self.frames.xf.rot {
            if r.plane != plane {
                return Err(self.alarm(
                    AlarmKind::TransformConflict,
                    at,
                    "G68 in another plane while coordinate rotation is in force",
                ));
            }
        }
        let cur = self.prog_pos();
        let coord = |me: &Self, i: usize| -> f64 {
            let ax = Axis::ALL[i];
            match me.words.get(ax_letter(ax)) {
                Some(w) => me.axis_value(ax, w),
                None => cur[i],
            }
        };
        let mut c = cur;
        c[a1] = coord(self, a1);
        c[a2] = coord(self, a2);
        // With scaling in force the centre is scaled too (000 §15.4.2).
        if let Some(s) = self.frames.xf.scale {
            let only = crate::xform::Xform {
                scale: Some(s),
                rot: None,
            };
            c = only.forward(&c);
        }
        let r = match self.words.get(b'R') {
            Some(w) => self.angular(w),
            None => self.cfg.profile.param("PI 117", 0.0) / 1000.0,
        };
        if r.abs() > 360.0 {
            let rat = self.words.get(b'R').map(|w| w.at).unwrap_or(at);
            return Err(self.alarm(
                AlarmKind::OutOfRange,
                rat,
                format!("rotation angle {} out of range (±360°)", fmt_num(r)),
            ));
        }
        let deg = match (self.modal.absolute(), self.frames.xf.rot) {
            (false, Some(old)) => old.deg + r,
            _ => r,
        };
        self.frames.xf.rot = Some(Rotation {
            plane,
            center: (c[a1], c[a2]),
            deg,
        });
        Ok(())
    }

    /// `G52 X_ Y_ Z_`: the local coordinate origin in the work system
    /// (absolute values; in G91 added to the current local offset);
    /// `G52 X0 Y0 Z0` cancels. Only the named axes change.
    fn g52(&mut self) {
        for ax in Axis::ALL {
            let i = ax as usize;
            if !self.cfg.has_axis[i] {
                continue;
            }
            if let Some(w) = self.words.get(ax_letter(ax)) {
                let v = self.axis_value(ax, w);
                self.frames.local_mut()[i] = if self.modal.absolute() {
                    v
                } else {
                    self.frames.local()[i] + v
                };
            }
        }
    }
}
