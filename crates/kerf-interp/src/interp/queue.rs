//! Its own type: [`Queue`], the events made and not yet handed out.
//!
//! [`Interp::step`](super::Interp::step) hands them out one per call
//! from the front. [`Interp::step_into`](super::Interp::step_into)
//! instead lends the queue the caller's vector ([`Queue::lend`]): the
//! blocks push their events straight onto the end of the caller's batch,
//! with no copy in between, and the events already there (`base` and
//! before) are the caller's: clearing the queue (an alarm drops the
//! failing block's events) and asking for its last event see only those
//! after `base`.

use std::collections::VecDeque;

use kerf_canon::{Canon, Event};

/// The events made and not yet handed out (see the module doc).
pub(super) struct Queue {
    q: VecDeque<Event>,
    /// Events before this index are the caller's (a lent vector), not
    /// the queue's.
    base: usize,
}

impl Queue {
    /// An empty queue.
    pub(super) fn new() -> Queue {
        Queue {
            q: VecDeque::with_capacity(16),
            base: 0,
        }
    }

    /// Adds an event at the end.
    #[inline]
    pub(super) fn push_back(&mut self, e: Event) {
        self.q.push_back(e);
    }

    /// Adds events at the end, in order.
    pub(super) fn extend(&mut self, es: impl IntoIterator<Item = Event>) {
        self.q.extend(es);
    }

    /// The first event not handed out (never one of the caller's).
    #[inline]
    pub(super) fn pop_front(&mut self) -> Option<Event> {
        debug_assert_eq!(self.base, 0, "not while lent");
        self.q.pop_front()
    }

    /// Drops the queue's events (not the caller's).
    pub(super) fn clear(&mut self) {
        self.q.truncate(self.base);
    }

    /// How many events the queue holds (not counting the caller's).
    pub(super) fn len(&self) -> usize {
        self.q.len() - self.base
    }

    /// How many events the storage holds, the caller's included.
    #[inline]
    pub(super) fn total(&self) -> usize {
        self.q.len()
    }

    /// Whether the last event of the queue (not the caller's) is the end.
    pub(super) fn ends(&self) -> bool {
        self.len() > 0
            && self
                .q
                .back()
                .is_some_and(|e| matches!(e.cmd, Canon::End { .. }))
    }

    /// Moves the queue's events to the end of `out`.
    pub(super) fn drain_into(&mut self, out: &mut Vec<Event>) {
        debug_assert_eq!(self.base, 0, "not while lent");
        out.extend(self.q.drain(..));
    }

    /// Swaps the queue's storage with `out`: after one call the queue
    /// pushes onto `out`'s events (which it does not count as its own:
    /// `base` is set with [`Queue::set_base`]), after the second `out`
    /// has them all and the queue its own storage back. The queue must be
    /// empty before the first call.
    pub(super) fn lend(&mut self, out: &mut Vec<Event>) {
        let mine = std::mem::take(&mut self.q);
        let theirs = std::mem::replace(out, Vec::from(mine));
        // From a vector the deque starts at its front: no copy.
        self.q = VecDeque::from(theirs);
        self.base = 0;
    }

    /// Events up to the queue's present length are the caller's.
    #[inline]
    pub(super) fn set_base(&mut self) {
        self.base = self.q.len();
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use kerf_canon::SrcRef;

    fn ev(line: u32, cmd: Canon) -> Event {
        Event {
            src: SrcRef {
                file: 0,
                line,
                col: 1,
            },
            tool: 0,
            cmd,
            prog: None,
        }
    }

    fn lines(es: &[Event]) -> Vec<u32> {
        es.iter().map(|e| e.src.line).collect()
    }

    #[test]
    fn events_come_out_in_order_and_clear_drops_them() {
        let mut q = Queue::new();
        q.push_back(ev(1, Canon::Stop { optional: false }));
        q.extend([ev(2, Canon::End { code: 30 })]);
        assert!(q.ends());
        assert_eq!(q.len(), 2);
        assert_eq!(q.pop_front().map(|e| e.src.line), Some(1));
        q.clear();
        assert_eq!((q.len(), q.ends(), q.pop_front()), (0, false, None));
    }

    #[test]
    fn a_lent_vector_keeps_the_callers_events() {
        let mut q = Queue::new();
        let mut out = vec![ev(1, Canon::End { code: 0 })];
        let cap = out.capacity();
        q.lend(&mut out);
        q.set_base();
        // The caller's End is not the queue's: not its last, not cleared.
        assert!(!q.ends());
        assert_eq!(q.len(), 0);
        q.push_back(ev(2, Canon::Stop { optional: false }));
        q.clear();
        q.push_back(ev(3, Canon::Stop { optional: true }));
        q.set_base();
        q.push_back(ev(4, Canon::End { code: 2 }));
        assert!(q.ends() && q.len() == 1);
        q.lend(&mut out);
        assert_eq!(lines(&out), [1, 3, 4]);
        assert!(out.capacity() >= cap);
        // The queue has its own (empty) storage back.
        assert_eq!(q.len(), 0);
        let mut out2 = Vec::new();
        q.drain_into(&mut out2);
        assert!(out2.is_empty());
    }
}
