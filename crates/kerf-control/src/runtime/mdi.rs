//! MDI: blocks (and macro statements) typed in MDI mode, executed with the
//! machine's modal state (the interpreter that ran the last program or
//! MDI keeps its modals, offsets, variables and position).

use super::command::{Op, Refusal};
use super::mode::Execution;
use super::Runtime;

/// Most MDI text accepted at once, bytes.
pub const MAX_MDI: usize = 4096;

impl Runtime {
    /// Executes MDI text (the table allows it only in MDI mode, READY).
    /// Text that does not parse is refused with its line and column and
    /// nothing runs; an alarm while it executes stops it as a program's.
    pub(super) fn mdi(&mut self, text: &str) -> Result<(), Refusal> {
        let op = Op::Mdi;
        if text.trim().is_empty() {
            return Err(self.refuse(op, "nothing typed"));
        }
        if text.len() > MAX_MDI {
            return Err(self.refuse(op, format!("MDI takes at most {MAX_MDI} characters")));
        }
        if let Err(a) = self.interp.check_syntax(text) {
            return Err(self.refuse(
                op,
                format!("line {}, column {}: {}", a.src.line, a.src.col, a.message),
            ));
        }
        self.interp.load_text("MDI", text);
        self.in_mdi = true;
        self.pause = None;
        self.restart_clock();
        self.exec = Execution::Active;
        Ok(())
    }
}
