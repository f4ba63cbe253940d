//! The two-thread run behind [`Runner::run`](crate::Runner::run): the
//! interpreter on a thread of its own, the planner and the sinks
//! ([`Downstream`]) on the caller's.
//!
//! The interpreter's thread has its events made in a [`Batch`] of
//! [`BATCH`] (`Interp::step_into`); full batches go over a bounded channel and come back empty
//! to be filled again, so nothing is allocated per event and at most
//! [`IN_FLIGHT`] + 1 batches exist. With the events a batch carries what
//! the sinks read of the interpreter while the program runs: the name of
//! each file the first time an event points into it, and the blocks
//! executed (for a progress display). The last batch carries how the
//! program ended (its end or its alarm).
//!
//! The caller's thread hands the events out in order exactly as
//! [`Runner::step`](crate::Runner::step) does, so the records, the
//! warnings and the alarm are the same. When a sink fails, the caller's
//! thread stops taking batches, the interpreter's thread stops at its
//! next send, and the error is returned; the interpreter may have run a
//! few batches past the failing event, which nothing reads (the run ends
//! there, without `finish`).

use std::mem;
use std::sync::mpsc::{self, Receiver, SyncSender, TryRecvError};
use std::thread;

use kerf_canon::{Alarm, Event};
use kerf_interp::{Filled, Interp, Profile};

use super::downstream::Downstream;
use super::RunError;
use crate::sink::{Files, Sink};
use crate::sinks::behind::Named;

/// Events in one batch.
pub(crate) const BATCH: usize = 1024;
/// Batches sent and not yet taken back, at most. With four threads on two
/// cores a thread often waits for a core for a few milliseconds; eight
/// batches (about 2 MB of events) let the interpreter run that far ahead
/// and the planner work through them when it gets its core back, where
/// two of 512 left it waiting after half a millisecond (docs/benchmarks.md,
/// "Deeper queues between the threads").
pub(crate) const IN_FLIGHT: usize = 8;

/// How the program ended.
pub(crate) enum End {
    /// M02/M30, the end of the text.
    Done,
    /// Stopped by an alarm.
    Alarm(Alarm),
}

/// Events in execution order and what the sinks read with them.
struct Batch {
    events: Vec<Event>,
    /// Names of the files first pointed into by these events.
    names: Vec<(u32, String)>,
    /// Blocks executed after the last of these events.
    blocks: u64,
    /// Set on the last batch.
    end: Option<End>,
}

impl Batch {
    fn new() -> Batch {
        Batch {
            events: Vec::with_capacity(BATCH),
            names: Vec::new(),
            blocks: 0,
            end: None,
        }
    }
}

/// Runs the program from where `it` stands to its end: the interpreter
/// on a second thread, `down` and `sinks` on this one; `tick` is called
/// with the blocks executed after each batch. Returns how the program
/// ended, or the first sink error.
pub(crate) fn run(
    it: &mut Interp,
    down: &mut Downstream,
    sinks: &mut [&mut dyn Sink],
    tick: &mut dyn FnMut(u64),
) -> Result<End, RunError> {
    let profile = it.profile().clone();
    let (full_tx, full_rx) = mpsc::sync_channel::<Batch>(IN_FLIGHT);
    let (empty_tx, empty_rx) = mpsc::sync_channel::<Batch>(IN_FLIGHT + 1);
    thread::scope(|s| {
        let producer = s.spawn(move || produce(it, full_tx, empty_rx));
        let r = consume(down, &profile, full_rx, empty_tx, sinks, tick);
        // The channels are dropped: a producer still running stops at its
        // next send.
        if let Err(p) = producer.join() {
            std::panic::resume_unwind(p);
        }
        r
    })
}

/// The interpreter's thread: steps `it` to its end, sending full batches.
fn produce(it: &mut Interp, full: SyncSender<Batch>, empty: Receiver<Batch>) {
    let mut named = Named::default();
    let mut made = 1;
    let mut b = Batch::new();
    loop {
        // The interpreter pushes the events straight onto the batch.
        let before = b.events.len();
        let end = match it.step_into(&mut b.events, BATCH.saturating_sub(before)) {
            Filled::Room => None,
            Filled::End => Some(End::Done),
            Filled::Alarm(a) => Some(End::Alarm(a)),
        };
        for e in &b.events[before..] {
            let id = e.src.file;
            if named.first(id) {
                b.names.push((id, it.file_name(id).to_string()));
            }
        }
        let last = end.is_some();
        if !last && b.events.len() < BATCH {
            continue;
        }
        b.blocks = it.blocks();
        b.end = end;
        let next = match empty.try_recv() {
            Ok(n) => n,
            Err(TryRecvError::Empty) if made <= IN_FLIGHT => {
                made += 1;
                Batch::new()
            }
            Err(TryRecvError::Empty) => match empty.recv() {
                Ok(n) => n,
                Err(_) => return,
            },
            Err(TryRecvError::Disconnected) => return,
        };
        if full.send(mem::replace(&mut b, next)).is_err() || last {
            return;
        }
    }
}

/// The caller's thread: hands every event of every batch to `down`.
fn consume(
    down: &mut Downstream,
    profile: &Profile,
    full: Receiver<Batch>,
    empty: SyncSender<Batch>,
    sinks: &mut [&mut dyn Sink],
    tick: &mut dyn FnMut(u64),
) -> Result<End, RunError> {
    let mut names: Vec<String> = Vec::new();
    for mut b in full.iter() {
        for (id, name) in b.names.drain(..) {
            let i = id as usize;
            if names.len() <= i {
                names.resize(i + 1, "?".to_string());
            }
            names[i] = name;
        }
        for e in b.events.drain(..) {
            down.event(e, Files::Names(&names), profile, sinks)?;
        }
        tick(b.blocks);
        if let Some(end) = b.end.take() {
            return Ok(end);
        }
        // The producer may have stopped taking them back.
        let _ = empty.send(b);
    }
    // The interpreter's thread always ends on a batch with an end.
    Ok(End::Done)
}
