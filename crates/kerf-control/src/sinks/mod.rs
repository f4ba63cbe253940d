//! The outputs the `kerf` CLI writes, one [`Sink`](crate::Sink) per file:
//!
//! - [`Toolpath`]: one JSON line per motion and dwell, with its end time
//!   ([`ToolpathBehind`] formats and writes it on a thread of its own);
//! - [`Report`]: the JSON summary of the run;
//! - [`Plot`]: an SVG drawing of the path;
//! - [`Sample`]: the smoothed axis setpoints at a fixed period (CSV);
//! - [`Log`]: the operator messages, one per line;
//! - [`SimSink`]: the material-removal simulation (`--stock`), its STL
//!   and PNG, and the report's `sim` section.
//! - [`Expand`]: the program as plain G-code for a target control
//!   (docs/expand.md; [`ExpandBehind`] writes it on a thread of its own).
//!
//! Each takes any `io::Write`; formats are in docs/formats.md.

pub(crate) mod behind;
pub mod expand;
pub mod expand_behind;
pub mod log;
pub mod number;
pub mod plot;
pub mod report;
pub mod sample;
pub mod sim;
pub mod toolpath;
pub mod toolpath_behind;
mod toolpath_rec;

pub use expand::Expand;
pub use expand_behind::ExpandBehind;
pub use log::Log;
pub use plot::Plot;
pub use report::Report;
pub use sample::Sample;
pub use sim::{SimHandle, SimSink};
pub use toolpath::Toolpath;
pub use toolpath_behind::ToolpathBehind;

use kerf_canon::Axis;
use kerf_interp::Profile;

/// The machine's axes in output order (X Y Z A B C as present).
pub fn axes_of(p: &Profile) -> Vec<Axis> {
    Axis::ALL
        .iter()
        .copied()
        .filter(|a| p.has_axis(*a))
        .collect()
}
