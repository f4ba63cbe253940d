//! The toolpath as it is made: every motion the runtime hands to the
//! planner (program blocks, MDI, the restart re-entry, hand moves), in
//! order, numbered, for a screen drawing the backplot while the program
//! runs. Bounded: the newest 20,000 are kept (a reader sees the gap in the
//! numbers).

use std::collections::VecDeque;

use kerf_canon::{Canon, Event};
use serde::{Deserialize, Serialize};

use super::snapshot::AxisValues;
use super::Runtime;

/// Most motions kept.
pub const TRAIL_CAP: usize = 20_000;

/// One motion, in the toolpath format's terms (docs/formats.md).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct MotionRecord {
    /// Sequence number, from 1.
    pub seq: u64,
    pub file: String,
    pub line: u32,
    /// `rapid`, `feed`, `arc`, `thread`.
    pub kind: String,
    /// End point, work coordinates (tool tip).
    pub to: AxisValues,
    /// End point, machine coordinates.
    pub mto: AxisValues,
}

/// One kept motion, raw (converted when read).
struct Kept {
    seq: u64,
    file: u32,
    line: u32,
    kind: &'static str,
    to: kerf_canon::Pos,
    mto: kerf_canon::Pos,
}

/// The kept motions.
#[derive(Default)]
pub(super) struct Trail {
    kept: VecDeque<Kept>,
    next: u64,
}

impl Runtime {
    /// Records a motion handed to the planner for the first time.
    pub(super) fn note_motion(&mut self, e: &Event) {
        let Some(m) = e.motion() else { return };
        let kind = match e.cmd {
            Canon::Rapid { .. } => "rapid",
            Canon::Feed { .. } => "feed",
            Canon::Arc { .. } => "arc",
            _ => "thread",
        };
        let t = &mut self.trail;
        t.next += 1;
        if t.kept.len() == TRAIL_CAP {
            t.kept.pop_front();
        }
        t.kept.push_back(Kept {
            seq: t.next,
            file: e.src.file,
            line: e.src.line,
            kind,
            to: m.to,
            mto: m.mto,
        });
    }

    /// The motions with a sequence number greater than `after`, oldest
    /// first (0: all kept).
    pub fn motions_since(&self, after: u64) -> Vec<MotionRecord> {
        let values = |p: &kerf_canon::Pos| -> AxisValues {
            self.axes()
                .into_iter()
                .map(|a| (a.name().to_string(), p[a as usize]))
                .collect()
        };
        self.trail
            .kept
            .iter()
            .filter(|r| r.seq > after)
            .map(|r| MotionRecord {
                seq: r.seq,
                file: self.interp.file_name(r.file).to_string(),
                line: r.line,
                kind: r.kind.into(),
                to: values(&r.to),
                mto: values(&r.mto),
            })
            .collect()
    }
}
