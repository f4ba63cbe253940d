//! The [`Runner`]: runs a loaded program with the interpreter and the
//! planner, handing what happens to a set of [`Sink`]s.
//!
//! Each [`Runner::step`] takes one canonical command from the interpreter,
//! gives it to every sink ([`Sink::event`]), pushes it to the planner and
//! hands out what the planner has finished: the end times of motions and
//! dwells ([`Sink::timed`], through the pending queue below) and the
//! timeline pieces ([`Sink::pieces`]). [`Runner::finish`] stops the
//! planner, drains it, saves the retained state and finishes the sinks.
//! [`Runner::run`] runs a whole program with the interpreter on a thread
//! of its own and the planner and the sinks on the caller's
//! ([`threaded`]); what the sinks are handed, in what order, is the same
//! as stepping.
//!
//! What happens to each event after the interpreter (the sinks, the
//! planner, the pending queue, the warnings) is [`downstream`].

mod downstream;
mod threaded;

use std::fmt;
use std::io;
use std::path::PathBuf;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Arc;

use kerf_canon::Alarm;
use kerf_interp::{Interp, Step};
use kerf_motion::{Dynamics, Planner};

use crate::job::Lint;
use crate::sink::{Context, Files, Sink};
use crate::warnings::Warning;
use downstream::Downstream;
use threaded::End;

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

/// How far a run has got, for a progress display.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Tick {
    /// Blocks executed so far.
    pub blocks: u64,
    /// Bytes read of the main program and its size, when known
    /// ([`Runner::track_source`]).
    pub source: Option<(u64, u64)>,
}

fn sink_err(s: &dyn Sink) -> impl FnOnce(io::Error) -> RunError + '_ {
    move |e| RunError::Sink(s.name().to_string(), e)
}

/// Runs one loaded program: the interpreter, the planner, the pending
/// queue of records waiting for their end time, and the retained state.
pub struct Runner {
    it: Interp,
    down: Downstream,
    started: bool,
    alarm: Option<Alarm>,
    ended: bool,
    state: Option<PathBuf>,
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
            down: Downstream::new(planner, work),
            started: false,
            alarm: None,
            ended: false,
            state: None,
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
        self.down.plan = false;
    }

    /// The interpreter (positions, variables, file names).
    pub fn interp(&self) -> &Interp {
        &self.it
    }

    /// The planner (planned time so far, totals).
    pub fn planner(&self) -> &Planner {
        &self.down.planner
    }

    /// The warnings found so far.
    pub fn warnings(&self) -> &[Warning] {
        &self.down.warnings.list
    }

    /// Adds a warning found outside the runner (e.g. by [`crate::lint`]);
    /// sinks see it in [`Context::warnings`] from then on.
    pub fn warn(&mut self, w: Warning) {
        self.down.warnings.push(w);
    }

    /// The planned time so far, s: every motion ending before it has been
    /// handed to [`Sink::timed`] or is in the look-ahead window.
    pub fn planned_time(&self) -> f64 {
        self.down.planner.now()
    }

    fn context(&self) -> Context<'_> {
        Context {
            interp: &self.it,
            planner: &self.down.planner,
            warnings: &self.down.warnings.list,
        }
    }

    /// Runs the program to its end and finishes: the interpreter on a
    /// thread of its own, the planner and the sinks on this one. The
    /// sinks are handed the same calls in the same order as by
    /// [`Runner::step`] until [`Progress::Ended`] and then
    /// [`Runner::finish`]; the outcome and the errors are the same.
    pub fn run(self, sinks: &mut [&mut dyn Sink]) -> Result<Outcome, RunError> {
        self.run_with_progress(sinks, &mut |_| {})
    }

    /// [`Runner::run`], calling `tick` every few hundred events with how
    /// far the run has got.
    pub fn run_with_progress(
        mut self,
        sinks: &mut [&mut dyn Sink],
        tick: &mut dyn FnMut(Tick),
    ) -> Result<Outcome, RunError> {
        if !self.started {
            self.start(sinks)?;
        }
        if !self.ended {
            let source = self.source.clone();
            let mut on = |blocks| {
                let source = source
                    .as_ref()
                    .map(|(len, r)| (r.load(Ordering::Relaxed).min(*len), *len));
                tick(Tick { blocks, source })
            };
            let end = threaded::run(&mut self.it, &mut self.down, sinks, &mut on)?;
            self.ended = true;
            if let End::Alarm(a) = end {
                self.alarm = Some(a);
            }
        }
        self.finish(sinks)
    }

    fn start(&mut self, sinks: &mut [&mut dyn Sink]) -> Result<(), RunError> {
        self.started = true;
        self.down.pieces = self.down.plan && sinks.iter().any(|s| s.wants_pieces());
        if self.down.pieces {
            self.down.planner.keep_pieces();
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
                let files = Files::Interp(&self.it);
                self.down.event(e, files, self.it.profile(), sinks)?;
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

    /// Ends the run: plans what is still queued, hands it out, saves the
    /// retained state and finishes every sink.
    pub fn finish(mut self, sinks: &mut [&mut dyn Sink]) -> Result<Outcome, RunError> {
        if !self.started {
            self.start(sinks)?;
        }
        let down = &mut self.down;
        if down.plan {
            down.planner.finish();
            down.drain(Files::Interp(&self.it), self.it.profile(), sinks)?;
        }
        down.detector
            .end(&self.it, self.alarm.is_some(), &mut down.warnings);
        if let Some(lint) = self.lint.take() {
            for w in lint.join() {
                down.warnings.push(w);
            }
            // In source order within each file.
            down.warnings
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
            cycle_time: self.down.plan.then(|| self.down.planner.now()),
            stalled: self.down.planner.stalled,
            warnings: self.down.warnings.list,
            warnings_dropped: self.down.warnings.dropped,
        })
    }
}
