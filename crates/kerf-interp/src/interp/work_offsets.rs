//! The work offsets of all three controls in one table keyed by
//! [`WorkId`]: G54-G59 (HX, PUMA; 000 §7.2, `G10 L2`, #5221-/#2377-) and
//! the Hurco fixture offsets E1-E9999 (002 Table 16). Each entry is the
//! machine position of that system's zero (mm, lathe X as a radius).
//!
//! The active system's origin is what every move is offset by. On the
//! HX and the PUMA it is the selected G54-G59 entry, so editing that
//! entry (G10 L2, a system variable) moves the origin at once. On the
//! Hurco an E code takes a copy of its fixture into the first slot and
//! makes it active: editing the fixture afterwards (a probe cycle, an
//! offsets file) takes effect when the E code is next programmed.
//!
//! A G code selects a system only through the meaning its dialect table
//! gives it, `Means::Work(n)` (dialect/meaning.rs names G54-G59 one by
//! one): a modal row without a meaning (G54.1, say) does not compile,
//! rather than becoming the G54 a range would make of it.

use std::collections::BTreeMap;

use kerf_canon::{Pos, NAXES};

/// Highest fixture offset number (002 Table 3: E 0-9999).
pub(super) const MAX_FIXTURE: u32 = 9999;

/// One work coordinate system.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum WorkId {
    /// G54 + n (n = 0-5: G54-G59).
    G5x(usize),
    /// Hurco fixture offset E n (1-9999; E0 is no offset).
    Fixture(u32),
}

/// The work offset table and the active system.
#[derive(Clone, Debug)]
pub(super) struct WorkOffsets {
    /// G54-G59; on the Hurco the first is the active fixture's copy.
    g5x: [Pos; 6],
    /// Index of the active G54-G59 entry.
    active: usize,
    /// Hurco fixture offsets written so far (others read as zero).
    fixtures: BTreeMap<u32, Pos>,
}

impl WorkOffsets {
    /// G54-G59 at `g5x`, G54 active; fixture E1 = G54 (the Hurco's part
    /// zero).
    pub(super) fn new(g5x: [Pos; 6]) -> WorkOffsets {
        let mut fixtures = BTreeMap::new();
        fixtures.insert(1, g5x[0]);
        WorkOffsets {
            g5x,
            active: 0,
            fixtures,
        }
    }

    /// The active system's origin (machine coordinates of its zero).
    #[inline]
    pub(super) fn origin(&self) -> &Pos {
        &self.g5x[self.active]
    }

    /// An entry; a fixture never written (or E0) is zero, as is a G5x
    /// index past G59.
    pub(super) fn get(&self, id: WorkId) -> Pos {
        match id {
            WorkId::G5x(n) => self.g5x.get(n).copied().unwrap_or([0.0; NAXES]),
            WorkId::Fixture(0) => [0.0; NAXES],
            WorkId::Fixture(n) => self.fixtures.get(&n).copied().unwrap_or([0.0; NAXES]),
        }
    }

    /// Mutable access to a G54-G59 entry (None past G59).
    pub(super) fn g5x_mut(&mut self, n: usize) -> Option<&mut Pos> {
        self.g5x.get_mut(n)
    }

    /// Sets an entry; false when there is no such entry (past G59, E0,
    /// above E9999).
    pub(super) fn set(&mut self, id: WorkId, origin: Pos) -> bool {
        match id {
            WorkId::G5x(n) => match self.g5x.get_mut(n) {
                Some(w) => {
                    *w = origin;
                    true
                }
                None => false,
            },
            WorkId::Fixture(n) if n == 0 || n > MAX_FIXTURE => false,
            WorkId::Fixture(n) => {
                self.fixtures.insert(n, origin);
                true
            }
        }
    }

    /// Makes `id` the active system (a fixture: its copy, see the module
    /// documentation).
    pub(super) fn select(&mut self, id: WorkId) {
        match id {
            WorkId::G5x(n) if n < self.g5x.len() => self.active = n,
            WorkId::G5x(_) => {}
            WorkId::Fixture(_) => {
                self.g5x[0] = self.get(id);
                self.active = 0;
            }
        }
    }

    /// After RESET: the entries are kept, the active system is this
    /// table's (the power-on G54).
    pub(super) fn keep_entries_of(&mut self, old: &WorkOffsets) {
        self.g5x = old.g5x;
        self.fixtures = old.fixtures.clone();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn at(x: f64) -> Pos {
        let mut p = [0.0; NAXES];
        p[0] = x;
        p
    }

    #[test]
    fn g5x_follow_edits_and_fixtures_are_taken_when_selected() {
        let mut w = WorkOffsets::new([at(-400.0); 6]);
        assert_eq!(w.get(WorkId::Fixture(1)), at(-400.0));
        w.select(WorkId::G5x(2));
        w.set(WorkId::G5x(2), at(-100.0));
        assert_eq!(*w.origin(), at(-100.0));
        // E5, then E5 edited: the origin is the copy until E5 again.
        assert!(w.set(WorkId::Fixture(5), at(-50.0)));
        w.select(WorkId::Fixture(5));
        assert_eq!(*w.origin(), at(-50.0));
        w.set(WorkId::Fixture(5), at(-60.0));
        assert_eq!(*w.origin(), at(-50.0));
        w.select(WorkId::Fixture(5));
        assert_eq!(*w.origin(), at(-60.0));
        // A fixture never written is zero; E0 and E10000 are not entries.
        assert_eq!(w.get(WorkId::Fixture(7)), [0.0; NAXES]);
        assert!(!w.set(WorkId::Fixture(0), at(1.0)));
        assert!(!w.set(WorkId::Fixture(MAX_FIXTURE + 1), at(1.0)));
        assert!(!w.set(WorkId::G5x(6), at(1.0)));
    }

    #[test]
    fn reset_keeps_the_entries_not_the_selection() {
        let mut old = WorkOffsets::new([at(0.0); 6]);
        old.set(WorkId::G5x(3), at(7.0));
        old.set(WorkId::Fixture(9), at(8.0));
        old.select(WorkId::G5x(3));
        let mut fresh = WorkOffsets::new([at(0.0); 6]);
        fresh.keep_entries_of(&old);
        assert_eq!(*fresh.origin(), at(0.0));
        assert_eq!(fresh.get(WorkId::G5x(3)), at(7.0));
        assert_eq!(fresh.get(WorkId::Fixture(9)), at(8.0));
    }

    /// The codes that select a work system are G54-G59, G54 + n each,
    /// on the HX and the PUMA; none on the Hurco (its G59 is a one-shot
    /// cancel, its systems are E codes).
    #[test]
    fn g54_to_g59_are_the_only_work_codes() {
        use crate::dialect::{Dialect, DialectId, Means};
        for (id, n) in [
            (DialectId::Hx, 6),
            (DialectId::Puma, 6),
            (DialectId::Hurco, 0),
        ] {
            let work: Vec<(u16, u8)> = Dialect::get(id)
                .gcodes
                .iter()
                .filter_map(|g| match g.means {
                    Means::Work(k) => Some((g.code10, k)),
                    _ => None,
                })
                .collect();
            assert_eq!(work.len(), n, "{id:?}");
            for (c, k) in work {
                assert_eq!(c, 540 + 10 * k as u16, "{id:?}");
            }
        }
    }
}
