//! kerf-motion: turns canonical commands into timed motion.
//!
//! The [`Planner`] consumes the event stream and plans the path speed of
//! every move with a bounded look-ahead window (trapezoidal speed along
//! the path within the per-axis limits projected on it, junction speeds
//! from the path tolerance and the per-axis acceleration, exact stop, arcs
//! with centripetal limits); the commanded positions then pass through
//! the smoothing stages after interpolation (one moving average for
//! linear, two for bell-shaped acc/dec), which bound the jerk. The
//! [`Sampler`] evaluates that command at a fixed period. The motion law is
//! documented in docs/motion.md. This crate reads only kerf-canon, never
//! the interpreter; it is configured with a plain [`Dynamics`] struct.

// Axis arithmetic indexes several parallel position arrays by slot.
#![allow(clippy::needless_range_loop)]

pub mod dynamics;
mod dynamics_error;
pub mod geom;
pub mod planner;
pub mod sampler;
pub mod trap;

pub use dynamics::{AccelType, CornerOverride, Dynamics, DynamicsLimitError};
pub use planner::{Breakdown, Done, Modes, Piece, PieceKind, Planner};
pub use sampler::Sampler;
pub use trap::Trap;
