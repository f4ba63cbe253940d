//! kerf-expand: a program as plain G-code for another control.
//!
//! The interpreter has already resolved every macro, call, cycle,
//! compensation, transform and offset into canonical events
//! ([`kerf_canon::Event`]); [`Expander`] writes those events back as
//! G-code text: G00/G01/G02/G03 (arcs stay arcs, centres as I J K from the
//! start), G04, the plane, G21, absolute positions, F with its feed mode, S
//! with M03/M04/M05, coolant, T and M06, program stops, each block ending
//! in a comment naming the file and line it came from. Positions are the
//! tool tip in the work coordinates of the toolpath (`Motion::to`).
//!
//! [`Target::Fanuc`] writes an ISO program for the same kind of control
//! (lathe X as a diameter); [`Target::LinuxCnc`] what LinuxCNC's rs274ngc
//! interpreter runs to the same motions. The output format of each is in
//! docs/expand.md.
//!
//! Architecture invariant: reads kerf-canon only (never kerf-interp, never
//! G-code), holds a fixed amount of state whatever the program's length,
//! and neither prints nor exits.

mod expander;
mod machine;
pub mod num;
mod rotary;
mod target;

pub use expander::{base_name, Expander};
pub use machine::SpindleState;
pub use target::{ClampWord, Control, DwellWord, Spelling, Target, ThreadWord, UnknownTarget};
