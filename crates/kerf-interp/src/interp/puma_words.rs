//! The PUMA's (Fanuc 0-T) addresses that only some blocks use. 001's
//! address table ("Meaning of Address") gives A, D, E, L and the cycle
//! parameters a meaning in a few codes only; a block that carries one of
//! them where no code reads it stops with PS009 instead of ignoring the
//! word (the HX alarms an unused axis the same way). B, H, J, V and Y are
//! not addresses of the PUMA at all (`dialect/puma.rs`).
//!
//! - `A`: the tool angle of the one-block G76 (Fanuc 10/11 tape format).
//! - `D`: the depth / divisions / relief of the one-block G71-G76.
//! - `E`: the thread lead (001 "F, E: designation of feedrate and thread
//!   lead") in a threading block (G32, G92, G76); it is read as F.
//! - `L`: the repetitions of `M98` (and `G10 L2`).

use super::*;
use crate::dialect::meaning::{LatheCycle, OneShot};

impl Interp {
    /// Whether the profile reads the one-block G71-G76 of the Fanuc 10/11
    /// tape format (`tape_format_10_11 = 1`, on for the PUMA).
    pub(super) fn tape_format_10_11(&self) -> bool {
        self.cfg.profile.param("tape_format_10_11", 0.0) != 0.0
    }

    /// A, D, E, L on the PUMA: allowed only where a code of the block
    /// reads them; E in a thread block becomes its F.
    pub(super) fn puma_words(&mut self) -> R<()> {
        // G71-G76 (not G70: it reads none of these).
        let mrc = self
            .words
            .gs()
            .iter()
            .find_map(|g| match self.means_of(g.0) {
                Some(Means::OneShot(OneShot::Mrc(k))) if k != LatheCycle::Finish => Some(k),
                _ => None,
            });
        let one_block = self.tape_format_10_11();
        if let Some(w) = self.words.get(b'A') {
            if !(one_block && mrc == Some(LatheCycle::Thread)) {
                return Err(self.unused_word(b'A', w.at, "the tool angle of a one-block G76"));
            }
        }
        if let Some(w) = self.words.get(b'D') {
            if !(one_block && mrc.is_some()) {
                let why = if mrc.is_some() {
                    "a one-block G71-G76 (profile parameter tape_format_10_11 is off)"
                } else {
                    "a one-block G71-G76"
                };
                return Err(self.unused_word(b'D', w.at, why));
            }
        }
        if let Some(w) = self.words.get(b'L') {
            let m98 = self.words.ms().iter().any(|m| {
                self.mcode(m.0)
                    .is_some_and(|c| c.action == MAction::SubCall)
            });
            let g10 = Means::OneShot(OneShot::DataSetting);
            if !m98 && self.block_g(|m| m == g10).is_none() {
                return Err(self.unused_word(b'L', w.at, "M98 (repetitions) and G10 L2"));
            }
        }
        if let Some(w) = self.words.get(b'E') {
            let motion_g =
                self.block_g(|m| matches!(m, Means::Motion(_) | Means::OneShot(OneShot::Mrc(_))));
            let thread = match motion_g {
                Some(g) => matches!(
                    self.means_of(g.0),
                    Some(
                        Means::Motion(MotionMode::ThreadLathe | MotionMode::ThreadCycle)
                            | Means::OneShot(OneShot::Mrc(LatheCycle::Thread))
                    )
                ),
                None => matches!(
                    self.modal.motion.means,
                    MotionMode::ThreadLathe | MotionMode::ThreadCycle
                ),
            };
            if !thread {
                return Err(self.unused_word(b'E', w.at, "a threading block (G32, G92, G76)"));
            }
            if let Some(f) = self.words.get(b'F') {
                return Err(self.alarm(
                    AlarmKind::DuplicateAddress,
                    f.at,
                    "F and E (both the thread lead) in one block",
                ));
            }
            self.words.letters[(b'F' - b'A') as usize] = Some(w);
            self.words.letters[(b'E' - b'A') as usize] = None;
        }
        Ok(())
    }

    pub(super) fn unused_word(&self, l: u8, at: u32, used_by: &str) -> Alarm {
        self.alarm(
            AlarmKind::IllegalAddress,
            at,
            format!(
                "address {} is not used in this block (on this control only {used_by} reads it)",
                l as char
            ),
        )
    }
}
