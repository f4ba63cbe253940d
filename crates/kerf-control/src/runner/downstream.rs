//! [`Downstream`]: what the runner does with each canonical command after
//! the interpreter: the sinks' `event`, the planner, the warning
//! detector, and the pending queue of motions and dwells handed to
//! `timed` once the planner has fixed their end times.
//!
//! It reads nothing of the interpreter but the file names and the
//! profile (given with each call), so it runs on the interpreter's thread
//! ([`Runner::step`](crate::Runner::step)) or on a thread of its own
//! ([`super::threaded`]) alike.
//!
//! The pending queue holds each motion and dwell until the planner reports
//! its end time; the planner reports them in order and holds at most its
//! look-ahead window, so the queue is bounded by that window too.

use std::collections::VecDeque;

use kerf_canon::{Canon, Event, Pos};
use kerf_interp::Profile;
use kerf_motion::{Piece, Planner};

use super::{sink_err, RunError};
use crate::sink::{Files, Live, Sink, Timed};
use crate::warnings::{Detector, Warnings};

/// A motion or dwell waiting for its end time.
struct Pending {
    event: Event,
    from: Pos,
    to: Pos,
    feed_mm_min: Option<f64>,
}

/// The planner side of a run.
pub(crate) struct Downstream {
    pub(crate) planner: Planner,
    /// Plan the events (off: only interpret).
    pub(crate) plan: bool,
    /// Some sink wants the timeline pieces.
    pub(crate) pieces: bool,
    pending: VecDeque<Pending>,
    /// Work position after the last event.
    work: Pos,
    batch: Vec<Piece>,
    pub(crate) detector: Detector,
    pub(crate) warnings: Warnings,
}

impl Downstream {
    /// Starts with the planner at rest at work position `work`.
    pub(crate) fn new(planner: Planner, work: Pos) -> Downstream {
        Downstream {
            planner,
            plan: true,
            pieces: false,
            pending: VecDeque::new(),
            work,
            batch: Vec::new(),
            detector: Detector::default(),
            warnings: Warnings::default(),
        }
    }

    /// What the sinks read while the run goes on.
    fn live<'a>(&'a self, files: Files<'a>, profile: &'a Profile) -> Live<'a> {
        Live {
            files,
            profile,
            planner: &self.planner,
            warnings: &self.warnings.list,
        }
    }

    /// Hands one event to the sinks and the planner, and out what it lets
    /// the planner finish.
    #[inline]
    pub(crate) fn event(
        &mut self,
        e: Event,
        files: Files,
        profile: &Profile,
        sinks: &mut [&mut dyn Sink],
    ) -> Result<(), RunError> {
        let from = self.work;
        if let Some(m) = e.motion() {
            self.work = m.to;
        }
        let cx = self.live(files, profile);
        for s in sinks.iter_mut() {
            s.event(&e, &from, &cx).map_err(sink_err(*s))?;
        }
        if !self.plan {
            self.detector
                .event(&e, &from, false, profile, files, &mut self.warnings);
            return Ok(());
        }
        let feed_mm_min = match &e.cmd {
            Canon::Feed { feed, m } => Some(
                self.planner
                    .feed_mm_min(*feed, kerf_motion::geom::line_len(&from, &m.to)),
            ),
            Canon::Arc { feed, .. } => Some(self.planner.feed_mm_min(*feed, 0.0)),
            _ => None,
        };
        let stalled = self.planner.stalled;
        self.planner.push(&e);
        let stalled = self.planner.stalled > stalled;
        self.detector
            .event(&e, &from, stalled, profile, files, &mut self.warnings);
        if e.motion().is_some() || matches!(e.cmd, Canon::Dwell { .. }) {
            self.pending.push_back(Pending {
                event: e,
                from,
                to: self.work,
                feed_mm_min,
            });
        }
        self.drain(files, profile, sinks)
    }

    /// Hands out the records whose end time is planned and the finished
    /// timeline pieces.
    pub(crate) fn drain(
        &mut self,
        files: Files,
        profile: &Profile,
        sinks: &mut [&mut dyn Sink],
    ) -> Result<(), RunError> {
        while let Some(d) = self.planner.next_done() {
            // Handed out where it lies in the queue (a pop would first
            // move the 350-byte record out).
            let Some(p) = self.pending.front() else {
                break;
            };
            let t = Timed {
                event: &p.event,
                from: p.from,
                to: p.to,
                t_end: d.t_end,
                time: d.time,
                feed_mm_min: p.feed_mm_min,
            };
            let cx = self.live(files, profile);
            for s in sinks.iter_mut() {
                s.timed(&t, &cx).map_err(sink_err(*s))?;
            }
            self.pending.pop_front();
        }
        if !self.pieces {
            return Ok(());
        }
        self.batch.clear();
        while let Some(p) = self.planner.next_piece() {
            self.batch.push(p);
        }
        let cx = self.live(files, profile);
        for s in sinks.iter_mut().filter(|s| s.wants_pieces()) {
            s.pieces(&self.batch, &cx).map_err(sink_err(*s))?;
        }
        Ok(())
    }
}
