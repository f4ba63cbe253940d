//! kerf-sim: what the program does to the part. The stock is a height
//! field (machining center) or a half section of revolution (lathes);
//! every canonical motion removes the material its tool sweeps, and the
//! crash checks (rapid into stock, holder collision, cutting with the
//! spindle stopped, plunging with a tool that does not cut at its centre)
//! are reported with the block, time and position. The cut part is
//! written as a watertight binary STL and a PNG picture.
//!
//! Architecture invariant: this crate reads `kerf_canon` events only
//! (never the interpreter); it is streaming: its memory is the stock
//! model and one move. Models, accuracy and the tool file: docs/sim.md.
//!
//! ```
//! use kerf_sim::{Sim, Stock, ToolTable};
//! let sim = Sim::new(Stock::parse("bar:50,100").unwrap(), ToolTable::default(), None).unwrap();
//! assert_eq!(sim.report().removed_mm3, 0.0);
//! ```

pub mod ball;
pub mod ball_row;
pub mod bands;
pub mod deferred;
pub mod envelope;
pub mod events;
pub mod grid;
pub mod holder;
pub mod hull;
pub mod kernels;
pub mod lathe;
pub mod lathe_tool;
pub mod mesh;
pub mod path;
pub mod pipe;
pub mod render;
pub mod shape;
pub mod sim;
pub mod slab;
pub mod stl;
pub mod stock;
pub mod tool;
pub mod tool_file;
pub mod trapezoids;
pub mod zmap;

pub use events::{EventKind, SimEvent, SimReport};
pub use sim::{Model, Sim, MAX_EVENTS};
pub use stock::{Stock, StockError, StockProblem};
pub use tool::{LatheKind, LatheTool, MillKind, MillTool, OffsetData, Tool, ToolTable};
pub use tool_file::{parse_tools, ToolFileError, ToolProblem};
pub use zmap::ResolutionError;
