//! The [`Runner`]: runs a loaded program with the interpreter and the
//! planner, handing what happens to a set of [`Sink`]s.
//!
//! Each [`Runner::step`] takes one canonical command from the interpreter,
//! gives it to every sink ([`Sink::event`]), pushes it to the planner and
//! hands out what the planner has finished: the end times of motions and
//! dwells ([`Sink::timed`], through the pending queue below) and the
//! timeline pieces ([`Sink::pieces`]). [`Runner::finish`] stops the
//! planner, drains it, saves the retained state and finishes the sinks.
//! [`Runner::run`] is the two together.
//!
//! The pending queue holds each motion and dwell until the planner reports
//! its end time; the planner reports them in order and holds at most its
//! look-ahead window, so the queue is bounded by that window too.

use std::collections::VecDeque;
use std::fmt;
use std::io;
use std::path::PathBuf;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Arc;

use kerf_canon::{Alarm, Canon, Event, Pos};
use kerf_interp::{Interp, Step};
use kerf_motion::{Dynamics, Piece, Planner};

use crate::job::Lint;
use crate::sink::{Context, Sink, Timed};
use crate::warnings::{Detector, Warning, Warnings};

/// A motion or dwell waiting for its end time.
struct Pending {
    event: Event,
    from: Pos,
    to: Pos,
    feed_mm_min: Option<f64>,
}

/// Where a run stands after a [`Runner::step`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Progress {
    /// The program goes on: call `step` again.
    Running,
    /// The program has ended (M02/M30, end of text) or stopped on an
    /// alarm: call [`Runner::finish`].
    Ended,
}

/// How a run ended.
#[derive(Clone, Debug)]
pub struct Outcome {
    /// The alarm that stopped the run, if any.
    pub alarm: Option<Alarm>,
    /// The name of the file the alarm points into (empty without alarm).
    pub alarm_file: String,
    /// Blocks executed.
    pub blocks: u64,
    /// The planned cycle time, s (`None` when only interpreting).
    pub cycle_time: Option<f64>,
    /// Cutting moves timed as 0 s because they had no feed (per-revolution
    /// feed or thread with the spindle stopped).
    pub stalled: u64,
    /// The warnings found, in order (at most `warnings::MAX_WARNINGS`).
    pub warnings: Vec<Warning>,
    /// Warnings found beyond those kept.
    pub warnings_dropped: u64,
}

/// A run that could not go on: a sink's output failed, or the retained
/// state could not be saved.
#[derive(Debug)]
pub enum RunError {
    /// A sink returned an error (its name, the error).
    Sink(String, io::Error),
    /// Saving the retained variables or offsets into `--state DIR` failed.
    State(PathBuf, io::Error),
}

impl fmt::Display for RunError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            RunError::Sink(name, e) => write!(f, "{name}: {e}"),
            RunError::State(dir, e) => write!(f, "--state {}: {e}", dir.display()),
        }
    }
}

impl std::error::Error for RunError {}

fn sink_err(s: &dyn Sink) -> impl FnOnce(io::Error) -> RunError + '_ {
    move |e| RunError::Sink(s.name().to_string(), e)
}

/// Runs one loaded program: the interpreter, the planner, the pending
/// queue of records waiting for their end time, and the retained state.
pub struct Runner {
    it: Interp,
    planner: Planner,
    plan: bool,
    pieces: bool,
    started: bool,
    alarm: Option<Alarm>,
    ended: bool,
    pending: VecDeque<Pending>,
    /// Work position after the last event.
    work: Pos,
    batch: Vec<Piece>,
    state: Option<PathBuf>,
    detector: Detector,
    warnings: Warnings,
    /// Size of the main program and the count of bytes read from it.
    source: Option<(u64, Arc<AtomicU64>)>,
    lint: Option<Lint>,
}

impl Runner {
    /// A runner for an interpreter whose main program is loaded
    /// ([`Interp::load_main`]) and whose offsets are set; `dynamics` must
    /// have passed `Dynamics::validate` (as [`crate::dynamics::dynamics_of`]
    /// returns them). The planner starts at rest where the machine is.
    pub fn new(it: Interp, dynamics: Dynamics) -> Runner {
        let mut planner = Planner::new(dynamics, it.machine_position(), it.work_position()[0]);
        planner.max_rpm = it.profile().spindle.max_rpm;
        let work = it.work_position();
        Runner {
            it,
            planner,
            plan: true,
            pieces: false,
            started: false,
            alarm: None,
            ended: false,
            pending: VecDeque::new(),
            work,
            batch: Vec::new(),
            state: None,
            detector: Detector::default(),
            warnings: Warnings::default(),
            source: None,
            lint: None,
        }
    }

    /// Adds the decimal-point check's warnings at the end of the run.
    pub fn lint_with(&mut self, lint: Lint) {
        self.lint = Some(lint);
    }

    /// Reports the main program's progress from `read`, the bytes read of
    /// `len` (see [`crate::source`]).
    pub fn track_source(&mut self, len: u64, read: Arc<AtomicU64>) {
        self.source = Some((len, read));
    }

    /// How far the main program has been read: (bytes read, size), when
    /// known.
    pub fn source_progress(&self) -> Option<(u64, u64)> {
        self.source
            .as_ref()
            .map(|(len, r)| (r.load(Ordering::Relaxed).min(*len), *len))
    }

    /// Saves the retained variables and offsets into `dir` at the end of
    /// the run (also after an alarm, as the control keeps them).
    pub fn save_state_to(&mut self, dir: PathBuf) {
        self.state = Some(dir);
    }

    /// Only interprets: events go to the sinks' [`Sink::event`], nothing is
    /// planned (no `timed`, no `pieces`, no cycle time). Call before the
    /// first step.
    pub fn interpret_only(&mut self) {
        self.plan = false;
    }

    /// The interpreter (positions, variables, file names).
    pub fn interp(&self) -> &Interp {
        &self.it
    }

    /// The planner (planned time so far, totals).
    pub fn planner(&self) -> &Planner {
        &self.planner
    }

    /// The warnings found so far.
    pub fn warnings(&self) -> &[Warning] {
        &self.warnings.list
    }

    /// Adds a warning found outside the runner (e.g. by [`crate::lint`]);
    /// sinks see it in [`Context::warnings`] from then on.
    pub fn warn(&mut self, w: Warning) {
        self.warnings.push(w);
    }

    /// The planned time so far, s: every motion ending before it has been
    /// handed to [`Sink::timed`] or is in the look-ahead window.
    pub fn planned_time(&self) -> f64 {
        self.planner.now()
    }

    fn context(&self) -> Context<'_> {
        Context {
            interp: &self.it,
            planner: &self.planner,
            warnings: &self.warnings.list,
        }
    }

    /// Runs the program to its end and finishes.
    pub fn run(mut self, sinks: &mut [&mut dyn Sink]) -> Result<Outcome, RunError> {
        while self.step(sinks)? == Progress::Running {}
        self.finish(sinks)
    }

    fn start(&mut self, sinks: &mut [&mut dyn Sink]) -> Result<(), RunError> {
        self.started = true;
        self.pieces = self.plan && sinks.iter().any(|s| s.wants_pieces());
        if self.pieces {
            self.planner.keep_pieces();
        }
        let cx = self.context();
        for s in sinks.iter_mut() {
            s.start(&cx).map_err(sink_err(*s))?;
        }
        Ok(())
    }

    /// Takes the next canonical command from the interpreter and hands out
    /// everything it lets the planner finish.
    pub fn step(&mut self, sinks: &mut [&mut dyn Sink]) -> Result<Progress, RunError> {
        if !self.started {
            self.start(sinks)?;
        }
        if self.ended {
            return Ok(Progress::Ended);
        }
        match self.it.step() {
            Step::Event(e) => {
                self.event(e, sinks)?;
                Ok(Progress::Running)
            }
            Step::End => {
                self.ended = true;
                Ok(Progress::Ended)
            }
            Step::Alarm(a) => {
                self.alarm = Some(a);
                self.ended = true;
                Ok(Progress::Ended)
            }
        }
    }

    #[inline]
    fn event(&mut self, e: Event, sinks: &mut [&mut dyn Sink]) -> Result<(), RunError> {
        let from = self.work;
        if let Some(m) = e.motion() {
            self.work = m.to;
        }
        let cx = self.context();
        for s in sinks.iter_mut() {
            s.event(&e, &from, &cx).map_err(sink_err(*s))?;
        }
        if !self.plan {
            self.detector.event(&e, false, &self.it, &mut self.warnings);
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
            .event(&e, stalled, &self.it, &mut self.warnings);
        if e.motion().is_some() || matches!(e.cmd, Canon::Dwell { .. }) {
            self.pending.push_back(Pending {
                event: e,
                from,
                to: self.work,
                feed_mm_min,
            });
        }
        self.drain(sinks)
    }

    /// Hands out the records whose end time is planned and the finished
    /// timeline pieces.
    fn drain(&mut self, sinks: &mut [&mut dyn Sink]) -> Result<(), RunError> {
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
            let cx = Context {
                interp: &self.it,
                planner: &self.planner,
                warnings: &self.warnings.list,
            };
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
        let cx = self.context();
        for s in sinks.iter_mut().filter(|s| s.wants_pieces()) {
            s.pieces(&self.batch, &cx).map_err(sink_err(*s))?;
        }
        Ok(())
    }

    /// Ends the run: plans what is still queued, hands it out, saves the
    /// retained state and finishes every sink.
    pub fn finish(mut self, sinks: &mut [&mut dyn Sink]) -> Result<Outcome, RunError> {
        if !self.started {
            self.start(sinks)?;
        }
        if self.plan {
            self.planner.finish();
            self.drain(sinks)?;
        }
        self.detector
            .end(&self.it, self.alarm.is_some(), &mut self.warnings);
        if let Some(lint) = self.lint.take() {
            for w in lint.join() {
                self.warnings.push(w);
            }
            // In source order within each file.
            self.warnings
                .list
                .sort_by(|a, b| (&a.file, a.line, a.col).cmp(&(&b.file, b.line, b.col)));
        }
        if let Some(dir) = &self.state {
            kerf_interp::state::save_retained(dir, &self.it)
                .and_then(|_| kerf_interp::state::save_offsets(dir, &self.it))
                .map_err(|e| RunError::State(dir.clone(), e))?;
        }
        let cx = self.context();
        for s in sinks.iter_mut() {
            s.finish(&cx, self.alarm.as_ref()).map_err(sink_err(*s))?;
        }
        let alarm_file = match &self.alarm {
            Some(a) => self.it.file_name(a.src.file).to_string(),
            None => String::new(),
        };
        Ok(Outcome {
            alarm_file,
            alarm: self.alarm,
            blocks: self.it.blocks(),
            cycle_time: self.plan.then(|| self.planner.now()),
            stalled: self.planner.stalled,
            warnings: self.warnings.list,
            warnings_dropped: self.warnings.dropped,
        })
    }
}
