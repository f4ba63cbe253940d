//! The PUMA's G-code system B (001 G-code table, "special G code" column;
//! 001 note 2: "it is possible to select the special G code according to
//! setting of parameters"): profile parameter `gcode_system_b = 1`.
//!
//! System B writes the same functions with other numbers (fanuc-semantics
//! §10.1): G33 threading (A: G32), G77/G78/G79 the single cycles (A:
//! G90/G92/G94), G92 coordinate setting and spindle clamp (A: G50),
//! G94/G95 feed per minute / revolution (A: G98/G99), and G90/G91 absolute
//! / incremental (A has none: X/Z absolute, U/W incremental). kerf reads a
//! system-B block by translating its G codes into system A as they are
//! collected, so one implementation serves both; G90/G91 become the PUMA
//! table's group-3 entries 9000/9010 (`G900`/`G901` are not codes a
//! program can write). In G91 the block's X and Z are read as U and W, so
//! every code (cycles, shapes, G10, G53 …) sees incremental words as it
//! does in system A. #4001-#4031 give the system-B numbers back.

use super::*;
use crate::dialect::system_b::{to_a, ABS, INC};

impl Interp {
    /// Whether the PUMA reads G-code system B (`gcode_system_b = 1`).
    pub(super) fn system_b(&self) -> bool {
        self.puma.system_b
    }

    /// A G word's code as executed: system B translated, the internal
    /// G90/G91 codes refused in system A.
    pub(super) fn g_of_system(&self, c10: u16, at: u32) -> R<u16> {
        if !self.cfg.dialect.caps.gcode_system_b {
            return Ok(c10);
        }
        let bad = |me: &Self, why: &str| {
            Err(me.alarm(
                AlarmKind::UnknownG,
                at,
                format!("G{} is not a G code of this control{why}", fmt_code(c10)),
            ))
        };
        if !self.system_b() {
            if c10 == ABS || c10 == INC {
                return bad(self, "");
            }
            return Ok(c10);
        }
        match to_a(c10) {
            Some(c) => Ok(c),
            None => bad(
                self,
                " in G-code system B (G33 threads, G92 sets coordinates, G94/G95 feed)",
            ),
        }
    }

    /// System B in G91 (this block's G90/G91, else the mode in force): X
    /// and Z are incremental, read as U and W (both in one block: PS009).
    pub(super) fn system_b_words(&mut self) -> R<()> {
        let inc = match self
            .words
            .gs()
            .iter()
            .rev()
            .find(|g| g.0 == ABS || g.0 == INC)
        {
            Some(g) => g.0 == INC,
            None => !self.modal.absolute(),
        };
        if !inc || self.macro_args() {
            return Ok(());
        }
        for (a, i) in [(b'X', b'U'), (b'Z', b'W')] {
            let (ai, ii) = ((a - b'A') as usize, (i - b'A') as usize);
            if let Some(w) = self.words.letters[ai].take() {
                if let Some(u) = self.words.letters[ii] {
                    return Err(self.alarm(
                        AlarmKind::DuplicateAddress,
                        u.at,
                        format!("{} and {} in one G91 block", a as char, i as char),
                    ));
                }
                self.words.letters[ii] = Some(w);
            }
        }
        Ok(())
    }
}
