//! The loop guard: counts what a run does that could go on for ever
//! (blocks executed, blocks executed again after a jump back, backward
//! jumps) against the budgets of the profile and the settings, so that a
//! program that loops without end stops with an alarm instead of hanging.

use crate::machine::Profile;

/// The loop guard's counters and budgets.
#[derive(Clone, Debug)]
pub(super) struct LoopGuard {
    /// Blocks executed so far (every block, first time or again).
    pub(super) blocks: u64,
    /// Backward jumps (GOTO, M99 P, M99 in a main program …).
    jumps: u64,
    /// Blocks executed again after jumping back.
    repeated: u64,
    /// Furthest byte offset read so far in the current file.
    pub(super) high_water: u64,
    /// Most blocks before the guard stops the run (0 = no limit).
    max_blocks: u64,
    /// Most blocks executed again before the guard stops the run.
    repeat_budget: u64,
    /// Most backward jumps before the guard stops the run.
    max_jumps: u64,
}

/// Which budget a count went over, with its limit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Over {
    /// More blocks than `max_blocks`.
    Blocks(u64),
    /// More blocks executed again than the repeat budget.
    Repeats(u64),
    /// More backward jumps than `max_jumps`.
    Jumps(u64),
}

impl Over {
    /// The alarm text.
    pub(super) fn message(self) -> String {
        match self {
            Over::Blocks(n) => format!("more than {n} blocks executed (loop guard)"),
            Over::Repeats(n) => {
                format!("more than {n} blocks executed again by loops (loop guard)")
            }
            Over::Jumps(n) => format!("more than {n} backward jumps (loop guard)"),
        }
    }
}

impl LoopGuard {
    /// A guard with the budgets of `profile` (`max_repeat_blocks`,
    /// `max_jumps`) and at most `max_blocks` blocks (0 = no limit).
    pub(super) fn new(profile: &Profile, max_blocks: u64) -> LoopGuard {
        LoopGuard::with_budgets(
            max_blocks,
            profile.param("max_repeat_blocks", 100_000_000.0) as u64,
            profile.param("max_jumps", 10_000_000.0) as u64,
        )
    }

    fn with_budgets(max_blocks: u64, repeat_budget: u64, max_jumps: u64) -> LoopGuard {
        LoopGuard {
            blocks: 0,
            jumps: 0,
            repeated: 0,
            high_water: 0,
            max_blocks,
            repeat_budget,
            max_jumps,
        }
    }

    /// Counts one block executed.
    #[inline]
    pub(super) fn count_block(&mut self) -> Result<(), Over> {
        self.blocks += 1;
        if self.max_blocks != 0 && self.blocks > self.max_blocks {
            return Err(Over::Blocks(self.max_blocks));
        }
        Ok(())
    }

    /// Counts a block ending at byte `here`: Ok(true) when it was read
    /// before (executed again after a jump back).
    #[inline]
    pub(super) fn count_read(&mut self, here: u64) -> Result<bool, Over> {
        let repeated = here <= self.high_water;
        if repeated {
            self.count_again()?;
        } else {
            self.high_water = here;
        }
        Ok(repeated)
    }

    /// Counts a block read again by a search (a GOTO scanning for its
    /// sequence number) against the repeat budget without a limit check
    /// of its own: the next block read checks it.
    pub(super) fn count_scanned(&mut self) {
        self.repeated += 1;
    }

    fn count_again(&mut self) -> Result<(), Over> {
        self.repeated += 1;
        if self.repeated > self.repeat_budget {
            return Err(Over::Repeats(self.repeat_budget));
        }
        Ok(())
    }

    /// Counts one backward jump.
    pub(super) fn count_jump(&mut self) -> Result<(), Over> {
        self.jumps += 1;
        if self.jumps > self.max_jumps {
            return Err(Over::Jumps(self.max_jumps));
        }
        Ok(())
    }

    /// Whether byte `offset` of the current file has been read before.
    #[inline]
    pub(super) fn was_read(&self, offset: u64) -> bool {
        offset < self.high_water
    }

    /// The jump and repeat counts start again (RESET, new program text);
    /// the blocks executed are still counted.
    pub(super) fn restart(&mut self) {
        self.jumps = 0;
        self.repeated = 0;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_block_budget_stops_after_its_limit() {
        let mut g = LoopGuard::with_budgets(3, 10, 10);
        for _ in 0..3 {
            assert_eq!(g.count_block(), Ok(()));
        }
        assert_eq!(g.count_block(), Err(Over::Blocks(3)));
        assert_eq!(g.blocks, 4);
        // 0 is no limit.
        let mut g = LoopGuard::with_budgets(0, 10, 10);
        for _ in 0..10_000 {
            assert_eq!(g.count_block(), Ok(()));
        }
    }

    #[test]
    fn only_text_read_again_counts_against_the_repeat_budget() {
        let mut g = LoopGuard::with_budgets(0, 2, 10);
        // First reading: blocks ending at 10, 20, 30.
        for end in [10, 20, 30] {
            assert_eq!(g.count_read(end), Ok(false));
        }
        assert_eq!(g.high_water, 30);
        assert!(g.was_read(29) && !g.was_read(30));
        // A jump back to the start: the blocks ending at 10 and 20 are
        // repeats; the third goes over the budget of 2.
        assert_eq!(g.count_read(10), Ok(true));
        assert_eq!(g.count_read(20), Ok(true));
        assert_eq!(g.count_read(30), Err(Over::Repeats(2)));
        // Reading past the furthest point is new text again.
        let mut g = LoopGuard::with_budgets(0, 2, 10);
        assert_eq!(g.count_read(30), Ok(false));
        assert_eq!(g.count_read(40), Ok(false));
    }

    #[test]
    fn scanned_blocks_and_jumps_are_counted_and_restart_clears_them() {
        let mut g = LoopGuard::with_budgets(0, 1, 2);
        assert_eq!(g.count_read(5), Ok(false));
        g.count_scanned();
        // The scan used the budget of 1: the next repeat goes over it.
        assert_eq!(g.count_read(5), Err(Over::Repeats(1)));
        assert_eq!(g.count_jump(), Ok(()));
        assert_eq!(g.count_jump(), Ok(()));
        assert_eq!(g.count_jump(), Err(Over::Jumps(2)));
        g.restart();
        assert_eq!(g.count_jump(), Ok(()));
        assert_eq!(g.count_read(5), Ok(true));
    }

    #[test]
    fn budgets_come_from_the_profile() {
        let mut p = Profile::builtin("hx-mc").unwrap();
        p.params.insert("max_jumps".into(), 1.0);
        let mut g = LoopGuard::new(&p, 0);
        assert_eq!(g.count_jump(), Ok(()));
        assert_eq!(g.count_jump(), Err(Over::Jumps(1)));
        assert_eq!(
            Over::Jumps(1).message(),
            "more than 1 backward jumps (loop guard)"
        );
        // The defaults: 10 000 000 jumps, 100 000 000 repeats.
        let g = LoopGuard::new(&Profile::builtin("hx-mc").unwrap(), 0);
        assert_eq!((g.max_jumps, g.repeat_budget), (10_000_000, 100_000_000));
    }
}
