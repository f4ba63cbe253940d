//! kerf-control: runs a part program with the interpreter, the planner and
//! any set of output sinks, behind one API that the `kerf` CLI, the browser
//! screen and bindings share.
//!
//! - [`Job`] says what to load (program, machine, libraries, settings,
//!   offsets, retained state) and [`Job::load`] returns a [`Runner`];
//! - [`Runner`] steps the program through the planner and hands every
//!   event, timed record and timeline piece to the [`Sink`]s
//!   ([`Runner::run`] with the interpreter on a thread of its own);
//! - [`sinks`] holds the outputs the CLI writes: toolpath, report, plot,
//!   sample, log, one file each;
//! - [`settings`], [`offsets`] and [`dynamics`] read the `--set` list, an
//!   offsets file and a profile's `[motion]` table;
//! - [`runtime`]: the controller runtime (modes, execution states, machine
//!   time, feed hold, single block, reset, restart, MDI, offsets,
//!   alarm history, persistence); see docs/runtime.md.
//!
//! ```
//! use kerf_control::{sinks::Toolpath, Job, Sink};
//!
//! let runner = Job::text("part.nc", "G0 X10 Y5\nG1 X20 F600\nM30\n")
//!     .machine("hx-mc")
//!     .load()
//!     .unwrap();
//! let mut records = Vec::new();
//! let mut toolpath = Toolpath::new(&mut records);
//! let outcome = runner.run(&mut [&mut toolpath as &mut dyn Sink]).unwrap();
//! assert!(outcome.alarm.is_none());
//! # drop(toolpath);
//! assert_eq!(String::from_utf8(records).unwrap().lines().count(), 2);
//! ```
//!
//! Architecture invariant: nothing in this crate prints or exits; every
//! failure is a value returned to the caller.

// Axis arithmetic indexes several parallel position arrays by slot.
#![allow(clippy::needless_range_loop)]

mod block_dims;
mod block_points;
pub mod dynamics;
pub mod job;
pub mod lint;
mod lint_lines;
pub mod offsets;
pub mod runner;
pub mod runtime;
pub mod settings;
pub mod sink;
pub mod sinks;
pub mod source;
pub mod suggest;
pub mod warnings;

pub use job::{load_profile, Job, LoadError, Source};
pub use runner::{Outcome, Progress, RunError, Runner, Tick};
pub use sink::{Context, Live, Sink, Timed};
pub use warnings::Warning;
