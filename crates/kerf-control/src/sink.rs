//! The [`Sink`] trait: what the [`Runner`](crate::Runner) hands to every
//! output while a program runs.
//!
//! A sink sees the run through four calls: `start` and `finish` with a
//! [`Context`] to read the interpreter and the planner, the calls in
//! between with a [`Live`] (file names, profile, planner, warnings: what
//! the runner can give while the interpreter runs ahead on a thread of its
//! own, see [`Runner::run`](crate::Runner::run)):
//!
//! 1. [`Sink::start`] once, before the first block (the machine position
//!    at power-on, the planner's smoothing for a sampler);
//! 2. [`Sink::event`] for every canonical command, in execution order, as
//!    soon as the interpreter emits it, with the work position it starts
//!    from (a simulator, a G-code writer, the report);
//! 3. [`Sink::timed`] for every motion and dwell once the planner has
//!    fixed its end time (bounded by the look-ahead window), in the same
//!    order, with its start and end points (the toolpath);
//! 4. [`Sink::pieces`] for the planner's timeline pieces (the commanded
//!    position at any instant: [`Piece::pos_at`]), in time order, only to
//!    sinks whose [`Sink::wants_pieces`] says so (the sampler, a runtime
//!    showing positions);
//!
//! and [`Sink::finish`] once at the end (also after an alarm). Each call
//! returns `io::Result`: the first error stops the run and is returned by
//! the runner with the sink's [`Sink::name`].
//!
//! Without planning ([`Runner::interpret_only`](crate::Runner::interpret_only))
//! only `start`, `event` and `finish` are called.

use std::io;

use kerf_canon::{Alarm, Event, Pos};
use kerf_interp::{Interp, Profile};
use kerf_motion::{Piece, Planner};

use crate::warnings::Warning;

/// Read access to the run for a sink: the interpreter (file names, block
/// count, positions, profile) and the planner (time so far, totals).
#[derive(Clone, Copy)]
pub struct Context<'a> {
    /// The interpreter, after the event being handed out.
    pub interp: &'a Interp,
    /// The planner (its totals are final in [`Sink::finish`]; zero without
    /// planning).
    pub planner: &'a Planner,
    /// The warnings found so far (all of them in [`Sink::finish`]).
    pub warnings: &'a [Warning],
}

impl<'a> Context<'a> {
    /// The name of a source file by its id (`SrcRef::file`).
    pub fn file(&self, id: u32) -> &str {
        self.interp.file_name(id)
    }

    /// The same run as seen by [`Sink::event`], [`Sink::timed`] and
    /// [`Sink::pieces`] (to hand a sink its calls outside a runner).
    pub fn live(&self) -> Live<'a> {
        Live {
            files: Files::Interp(self.interp),
            profile: self.interp.profile(),
            planner: self.planner,
            warnings: self.warnings,
        }
    }
}

/// Where the names of the source files come from: the interpreter itself,
/// or the copies the interpreter's thread sent with the events.
#[derive(Clone, Copy)]
pub enum Files<'a> {
    /// The interpreter's own table.
    Interp(&'a Interp),
    /// Names by file id, as sent ("?" for an id not sent, as the
    /// interpreter names an unknown one).
    Names(&'a [String]),
}

impl<'a> Files<'a> {
    /// The name of file `id`.
    pub fn name(&self, id: u32) -> &'a str {
        match self {
            Files::Interp(it) => it.file_name(id),
            Files::Names(n) => n.get(id as usize).map(String::as_str).unwrap_or("?"),
        }
    }
}

/// Read access to the run for [`Sink::event`], [`Sink::timed`] and
/// [`Sink::pieces`]: the names of the source files the events point
/// into, the machine profile, the planner and the warnings so far. (The
/// interpreter itself may be running ahead on another thread.)
#[derive(Clone, Copy)]
pub struct Live<'a> {
    pub(crate) files: Files<'a>,
    /// The machine profile.
    pub profile: &'a Profile,
    /// The planner (zero without planning).
    pub planner: &'a Planner,
    /// The warnings found so far.
    pub warnings: &'a [Warning],
}

impl Live<'_> {
    /// The name of a source file by its id (`SrcRef::file`) of an event
    /// handed out so far.
    pub fn file(&self, id: u32) -> &str {
        self.files.name(id)
    }
}

/// A motion or dwell with its planned end time.
#[derive(Clone, Copy, Debug)]
pub struct Timed<'a> {
    /// The event (a `Rapid`, `Feed`, `Arc`, `Thread` or `Dwell` command).
    pub event: &'a Event,
    /// Work position where it starts (the tool tip, as `Motion::to`).
    pub from: Pos,
    /// Work position where it ends (`from` for a dwell).
    pub to: Pos,
    /// Seconds from program start when it ends (kerf-motion's `Done`).
    pub t_end: f64,
    /// Seconds it adds to the planner's time breakdown (cutting, rapid or
    /// dwell, with its settling when it stops); the records' times sum to
    /// those totals.
    pub time: f64,
    /// Effective feed of a `Feed` or `Arc`, mm/min (overrides, dry run
    /// and the cutting clamp applied); `None` otherwise.
    pub feed_mm_min: Option<f64>,
}

/// An output of a run. Every method but [`Sink::name`] has a default that
/// does nothing, so a sink implements only what it uses.
pub trait Sink {
    /// A short name for error messages ("toolpath", "report" …).
    fn name(&self) -> &str;

    /// Whether [`Sink::pieces`] should be called (the planner keeps its
    /// timeline only when some sink asks for it).
    fn wants_pieces(&self) -> bool {
        false
    }

    /// Once, before the first block.
    fn start(&mut self, _cx: &Context) -> io::Result<()> {
        Ok(())
    }

    /// Every canonical command in execution order; `from` is the work
    /// position before it.
    fn event(&mut self, _e: &Event, _from: &Pos, _cx: &Live) -> io::Result<()> {
        Ok(())
    }

    /// Every motion and dwell, in order, once its end time is planned.
    fn timed(&mut self, _t: &Timed, _cx: &Live) -> io::Result<()> {
        Ok(())
    }

    /// The timeline pieces the planner finished since the last call, in
    /// time order (only when [`Sink::wants_pieces`]).
    fn pieces(&mut self, _batch: &[Piece], _cx: &Live) -> io::Result<()> {
        Ok(())
    }

    /// Once at the end: after the last event and the last timed record,
    /// with the alarm that stopped the run, if any.
    fn finish(&mut self, _cx: &Context, _alarm: Option<&Alarm>) -> io::Result<()> {
        Ok(())
    }
}
