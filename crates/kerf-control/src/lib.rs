//! kerf-control: runs a part program with the interpreter, the planner and
//! any set of output sinks, behind one API that the `kerf` CLI, the browser
//! screen and bindings share.
//!
//! Architecture invariant: nothing in this crate prints or exits; every
//! failure is a value returned to the caller.
