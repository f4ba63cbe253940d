//! The rotary-axis interpolation mode as the event stream carries it
//! (`ModeChange::Rotary`): G112 polar and G107 cylindrical interpolation
//! with the cylinder radius and the program's plane, emitted at the block
//! that switches the mode so that a consumer (the plot) can place the
//! motions on the surface the program describes.

use super::polar_interp::RotInterp;
use super::*;
use kerf_canon::RotaryMode;

impl Interp {
    /// The rotary-axis interpolation in force: `Polar` between G112 and
    /// G113, `Cylinder` after `G107 C<r>` with r and the plane selected,
    /// `Off` otherwise.
    pub fn rotary_mode(&self) -> RotaryMode {
        match self.frames.rot {
            RotInterp::Off => RotaryMode::Off,
            RotInterp::Polar { .. } => RotaryMode::Polar,
            RotInterp::Cylinder { r } => RotaryMode::Cylinder {
                radius: r,
                plane: self.modal.plane.means,
            },
        }
    }

    /// Runs the block's G112 / G113 / G107 (see `rotary_interp_codes`) and
    /// emits `ModeChange::Rotary` when they changed the mode.
    pub(super) fn rotary_codes_and_event(&mut self) -> R<bool> {
        let was = self.frames.rot;
        let data = self.rotary_interp_codes()?;
        if self.frames.rot != was {
            self.emit(Canon::Mode(ModeChange::Rotary(self.rotary_mode())));
        }
        Ok(data)
    }
}
