//! kerf-control: runs a part program with the interpreter, the planner and
//! any set of output sinks, behind one API that the `kerf` CLI, the browser
//! screen and bindings share.
//!
//! - [`runtime`]: the controller runtime (modes, execution states, machine
//!   time, feed hold, single block, reset, restart, MDI, offsets,
//!   alarm history, persistence); see docs/runtime.md.
//!
//! Architecture invariant: nothing in this crate prints or exits; every
//! failure is a value returned to the caller.

// Axis arithmetic indexes several parallel position arrays by slot.
#![allow(clippy::needless_range_loop)]

pub mod runtime;
