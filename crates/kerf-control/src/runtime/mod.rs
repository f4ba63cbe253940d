//! The controller runtime: a machine operated from a panel. Modes (EDIT,
//! MEM, MDI, JOG, REF), execution states (MTConnect names), cycle start,
//! feed hold, single block, optional stop, block skip, dry run,
//! overrides, RESET, program restart, MDI, jog/handle/reference return,
//! offsets, parameters and variables, the alarm history and the `--state`
//! persistence. The program runs through the interpreter (kerf-interp)
//! and the planner (kerf-motion) in machine time: [`Runtime::advance`]
//! moves the clock by wall seconds × the rate, [`Runtime::step`] by
//! machine seconds (tests).
//!
//! ```
//! use kerf_control::runtime::{Command, Execution, Mode, Runtime};
//! use kerf_interp::Profile;
//! use kerf_motion::Dynamics;
//!
//! let profile = Profile::builtin("hx-mc").unwrap();
//! let mut present = [false; 6];
//! present[..3].fill(true);
//! let dynamics = Dynamics::uniform(present, 20_000.0, 2000.0, 1e9, 10_000.0);
//! let mut rt = Runtime::new(profile, dynamics).unwrap();
//! rt.command(Command::Mode { mode: Mode::Mem }).unwrap();
//! rt.load_program("demo.nc", "G91 G01 X-100. F600\nM30\n").unwrap();
//! rt.command(Command::CycleStart).unwrap();
//! rt.step(3.0);
//! assert_eq!(rt.state().execution, Execution::Active);
//! rt.command(Command::FeedHold).unwrap();
//! rt.step(1.0);
//! let s = rt.state();
//! assert_eq!(s.execution, Execution::FeedHold);
//! // 10 mm/s, path acceleration 1000 mm/s²: at 3 s it was at 29.95 mm and
//! // stops 0.05 mm further on.
//! let x0 = rt.profile().start_position()[0];
//! assert!((s.position.machine["x"] - (x0 - 30.0)).abs() < 1e-6, "{:?}", s.position);
//! rt.command(Command::CycleStart).unwrap();
//! rt.step(20.0);
//! assert_eq!(rt.state().execution, Execution::ProgramCompleted);
//! ```

mod alarms;
mod clock;
mod command;
mod display;
mod hold;
mod manual;
mod mdi;
mod mode;
mod moves;
mod offset_error;
mod offsets_doc;
mod ops;
mod pages;
mod passed;
mod persist;
mod program;
mod restart;
mod restart_error;
mod run;
mod snapshot;
mod switches;
mod table;
mod trail;

use std::path::PathBuf;

use kerf_canon::{Pos, SpindleDir, NAXES};
use kerf_interp::{Interp, Profile, Settings};
use kerf_motion::Dynamics;

pub use alarms::{AlarmLog, Record, RecordKind};
pub use command::{Command, Op, Refusal};
pub use mode::{Execution, Mode};
pub use pages::{OffsetWrite, VarWrite};
pub use passed::OnPassed;
pub use persist::PersistError;
pub use program::MAX_PROGRAM_BYTES;
pub use restart::{RestartAt, RestartPlan};
pub use snapshot::{AlarmInfo, AxisValues, Positions, ProgramAt, Spindle, State};
pub use switches::{Overrides, PanelError, Switches};
pub use table::{decide, markdown as mode_table_markdown, reachable, Verdict};
pub use trail::{MotionRecord, TRAIL_CAP};

use clock::Clock;
use program::Program;

/// Why the interpreter stopped feeding the planner; it takes effect when
/// the axes reach the end of what was planned.
#[derive(Clone, Debug, PartialEq)]
enum Pause {
    /// The look-ahead waits for the axes, then goes on (Hurco M200, M01
    /// with the optional stop off: 002 Table 15).
    Sync,
    SingleBlock,
    Stop {
        optional: bool,
        src: kerf_canon::SrcRef,
    },
    End,
    Alarm(kerf_canon::Alarm),
}

/// The machine's physical state as the axes reach each command.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Physical {
    spindle: SpindleDir,
    rpm: f64,
    tool: u32,
    mist: bool,
    flood: bool,
}

/// A stop by feed hold, waiting for cycle start.
#[derive(Clone, Debug)]
struct Held {
    at: Pos,
    t_stop: f64,
}

/// A controller: one machine, one interpreter, one clock.
pub struct Runtime {
    profile: Profile,
    interp: Interp,
    clock: Clock,
    program: Option<Program>,
    /// The interpreter executes MDI text (not the loaded program).
    in_mdi: bool,
    mode: Mode,
    exec: Execution,
    pause: Option<Pause>,
    /// A feed hold asked for, taking effect at this time (thread, tap).
    hold_at: Option<f64>,
    held: Option<Held>,
    switches: Switches,
    overrides: Overrides,
    alarm: Option<AlarmInfo>,
    log: AlarmLog,
    phys: Physical,
    rate: f64,
    state_dir: Option<PathBuf>,
    restart: Option<RestartPlan>,
    /// Axes referenced by REF.
    referenced: [bool; NAXES],
    /// Line of the last command the axes finished (the block display when
    /// nothing is under way; 0 at the program start).
    last_line: u32,
    /// Single block: the block (file, line) whose commands went to the
    /// planner since the last stop, and a command of the next block held
    /// back until cycle start.
    sb_block: Option<(u32, u32)>,
    stash: Option<kerf_canon::Event>,
    /// The toolpath as it is made.
    trail: trail::Trail,
    /// A jog, handle or reference move under way.
    manual: Option<manual::ManualMove>,
    /// Commands the interpreter keeps read ahead of the axes (the
    /// planner's look-ahead window): the control's block buffer.
    buffer: usize,
    /// Blocks the interpreter may execute in one call of the clock
    /// (bounds the work of one `advance` on a program of statements).
    block_budget: usize,
    /// The watcher of the commands the axes finish (`passed.rs`).
    on_passed: Option<passed::OnPassed>,
}

/// A runtime that could not be built or set up.
#[derive(Debug, thiserror::Error)]
pub enum RuntimeError {
    /// The machine profile could not be loaded (its name or file).
    #[error(transparent)]
    Profile(#[from] crate::job::LoadError),
    /// The profile's `[motion]` table.
    #[error("machine {name}: {source}")]
    Motion {
        /// The machine as named.
        name: String,
        /// The parameter at fault.
        source: crate::dynamics::DynamicsError,
    },
    /// Dynamics out of range (kerf-motion's check, naming the parameter).
    #[error("{0}")]
    Dynamics(kerf_motion::DynamicsLimitError),
    /// A time rate outside (0, 10000].
    #[error("rate {0}: must be in (0, 10000]")]
    Rate(f64),
}

impl From<RuntimeError> for String {
    fn from(e: RuntimeError) -> String {
        e.to_string()
    }
}

impl Runtime {
    /// A machine at power-on: EDIT mode, READY, at the profile's start
    /// position, with `dynamics` for the planner (see kerf-motion).
    pub fn new(profile: Profile, dynamics: Dynamics) -> Result<Runtime, RuntimeError> {
        dynamics.validate().map_err(RuntimeError::Dynamics)?;
        let buffer = dynamics.lookahead.max(1);
        let interp = Interp::new(profile.clone(), Settings::default());
        let pos = interp.machine_position();
        let wx = interp.work_position()[0];
        let clock = Clock::new(dynamics, pos, wx, profile.spindle.max_rpm, 0.0);
        Ok(Runtime {
            profile,
            interp,
            clock,
            program: None,
            in_mdi: false,
            mode: Mode::Edit,
            exec: Execution::Ready,
            pause: None,
            hold_at: None,
            held: None,
            switches: Switches::default(),
            overrides: Overrides::default(),
            alarm: None,
            log: AlarmLog::default(),
            phys: Physical {
                spindle: SpindleDir::Stop,
                rpm: 0.0,
                tool: 0,
                mist: false,
                flood: false,
            },
            rate: 1.0,
            state_dir: None,
            restart: None,
            referenced: [false; NAXES],
            manual: None,
            trail: Default::default(),
            sb_block: None,
            stash: None,
            last_line: 0,
            buffer,
            block_budget: 20_000,
            on_passed: None,
        })
    }

    /// A machine by built-in name or profile file, with the planner's
    /// dynamics from its `[motion]` table (the same loading as `kerf run`:
    /// `load_profile`, `dynamics::dynamics_of`).
    pub fn for_machine(name: &str) -> Result<Runtime, RuntimeError> {
        let profile = crate::load_profile(name)?;
        let d = crate::dynamics::dynamics_of(&profile, 100.0, 100.0, false).map_err(|source| {
            RuntimeError::Motion {
                name: name.to_string(),
                source,
            }
        })?;
        Runtime::new(profile, d)
    }

    /// Reads an `--offsets` file (docs/formats.md: work offsets, H/D
    /// pages, lathe tools) into the offset pages, all of it or nothing;
    /// saved to `--state`.
    pub fn load_offsets_file(&mut self, path: &std::path::Path) -> Result<(), Refusal> {
        let op = Op::WriteOffset;
        self.check(op)?;
        let p = path.display();
        let text =
            std::fs::read_to_string(path).map_err(|e| self.refuse(op, format!("{p}: {e}")))?;
        let doc: toml::Value =
            toml::from_str(&text).map_err(|e| self.refuse(op, format!("{p}: {e}")))?;
        let json = serde_json::to_value(doc).map_err(|e| self.refuse(op, format!("{p}: {e}")))?;
        self.put_offsets_document(&json)
    }

    /// The machine profile.
    pub fn profile(&self) -> &Profile {
        &self.profile
    }

    /// The interpreter (read-only: offsets, variables, modal state).
    pub fn interp(&self) -> &Interp {
        &self.interp
    }

    /// The operating mode.
    pub fn mode(&self) -> Mode {
        self.mode
    }

    /// The execution state.
    pub fn execution(&self) -> Execution {
        self.exec
    }

    /// Machine time, s.
    pub fn time(&self) -> f64 {
        self.clock.t
    }

    /// Sets the rate of machine time to wall time for [`Runtime::advance`]
    /// (1 = real time; larger runs faster). Must be in (0, 10000].
    pub fn set_rate(&mut self, rate: f64) -> Result<(), RuntimeError> {
        if !(rate.is_finite() && rate > 0.0 && rate <= 10_000.0) {
            return Err(RuntimeError::Rate(rate));
        }
        self.rate = rate;
        Ok(())
    }

    /// The rate of machine time to wall time.
    pub fn rate(&self) -> f64 {
        self.rate
    }

    /// Advances the machine by `wall_seconds` of wall time at the rate.
    pub fn advance(&mut self, wall_seconds: f64) {
        self.step(wall_seconds * self.rate);
    }

    /// Advances the machine by `dt` seconds of machine time.
    pub fn step(&mut self, dt: f64) {
        if dt.is_finite() && dt > 0.0 {
            self.run_to(self.clock.t + dt);
        }
    }

    /// Advances machine time until the execution state is not ACTIVE (or
    /// `max_dt` machine seconds have passed, or `max_dt / 0.05 + 1000`
    /// steps were taken: a macro loop without motion takes no machine
    /// time); returns the machine time taken.
    pub fn run_until_stopped(&mut self, max_dt: f64) -> f64 {
        let t0 = self.clock.t;
        let mut steps = (max_dt / 0.05).min(1e9) as u64 + 1000;
        while self.exec == Execution::Active && self.clock.t - t0 < max_dt && steps > 0 {
            steps -= 1;
            self.step(0.05f64.min(max_dt - (self.clock.t - t0)).max(1e-6));
        }
        self.clock.t - t0
    }

    /// The alarm and message history after sequence number `after`
    /// (0: all kept), oldest first.
    pub fn alarms(&self, after: u64) -> Vec<Record> {
        self.log.since(after)
    }

    /// The program restart prepared by [`Command::Restart`], with its
    /// re-entry path, until cycle start runs it.
    ///
    /// ```
    /// use kerf_control::runtime::{Command, Execution, Mode, Runtime};
    ///
    /// let mut rt = Runtime::for_machine("hx-mc").unwrap();
    /// rt.command(Command::Mode { mode: Mode::Mem }).unwrap();
    /// rt.load_program("p.nc", "G90 G54 G00 X-50. Y-50. Z20.\nM03 S800\nG01 Z-2. F200\nX-80.\nM30\n").unwrap();
    /// rt.command(Command::Restart { line: Some(4), sequence: None }).unwrap();
    /// let plan = rt.pending_restart().unwrap();
    /// assert_eq!((plan.spindle_direction.as_str(), plan.spindle_rpm), ("cw", 800.0));
    /// assert_eq!(plan.feed, Some(200.0));
    /// assert_eq!(plan.path.last().unwrap().kind, "feed");
    /// rt.command(Command::CycleStart).unwrap();
    /// rt.run_until_stopped(120.0);
    /// assert_eq!(rt.execution(), Execution::ProgramCompleted);
    /// assert_eq!(rt.state().position.work["x"], -80.0);
    /// ```
    pub fn pending_restart(&self) -> Option<&RestartPlan> {
        self.restart.as_ref()
    }

    /// Keeps offsets, work offsets and retained variables in `dir` (loaded
    /// now, each write saved atomically).
    pub fn set_state_dir(&mut self, dir: PathBuf) -> Result<(), PersistError> {
        persist::load(&dir, &mut self.interp)?;
        self.state_dir = Some(dir);
        Ok(())
    }

    /// Adds a library folder (subprograms and macros by O number).
    pub fn add_lib_dir(&mut self, dir: PathBuf) {
        self.interp.add_lib_dir(dir);
    }

    fn refuse(&self, op: Op, reason: impl Into<String>) -> Refusal {
        Refusal {
            command: op.name(),
            mode: self.mode,
            execution: self.exec,
            reason: reason.into(),
        }
    }

    /// Checks `op` against the mode table.
    fn check(&self, op: Op) -> Result<Option<Execution>, Refusal> {
        match decide(self.mode, self.exec, op) {
            Verdict::Allow(next) => Ok(next),
            Verdict::Refuse(r) => Err(self.refuse(op, r)),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn setup_errors_say_what_is_wrong() {
        let e = Runtime::for_machine("no-such-machine")
            .err()
            .expect("refused");
        assert!(matches!(e, RuntimeError::Profile(_)), "{e:?}");
        let mut rt = Runtime::for_machine("hx-mc").expect("built in");
        let e = rt.set_rate(0.0).unwrap_err();
        assert!(matches!(e, RuntimeError::Rate(r) if r == 0.0));
        assert_eq!(e.to_string(), "rate 0: must be in (0, 10000]");
        assert!(rt.set_rate(10_000.0).is_ok());
        let mut p = Profile::builtin("hx-mc").unwrap();
        p.motion.as_mut().unwrap().remove("lookahead");
        let name = "hx-mc".to_string();
        let e = crate::dynamics::dynamics_of(&p, 100.0, 100.0, false)
            .map_err(|source| RuntimeError::Motion { name, source })
            .unwrap_err();
        assert_eq!(
            e.to_string(),
            "machine hx-mc: profile parameter motion.lookahead is missing"
        );
    }
}
