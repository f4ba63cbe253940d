//! kerf-geom: the pure plane geometry that the interpreter (and the
//! simulator) build on.
//!
//! Architecture invariant: nothing here holds interpreter state, raises an
//! alarm, or knows which control is running. Every function takes numbers
//! in a plane's (first, second) axes, mm and degrees, and returns numbers
//! or a plain error value; the interpreter turns those into alarms.
//!
//! Module map:
//! - [`arc`]: circular interpolation: centre from R, end-point checks,
//!   sweep and extreme points;
//! - [`corner`]: chamfer and corner rounding (`,C` / `,R`);
//! - [`comp`]: cutter and nose radius compensation geometry (offset
//!   vectors, corner types, interference);
//! - [`xform`]: scaling, mirror image and coordinate rotation;
//! - [`rotary`]: polar (G112) and cylindrical (G107) interpolation;
//! - [`stroke`]: stored stroke check areas (G22/G23);
//! - [`turning`]: the passes of the lathe turning cycles;
//! - [`vec2`]: the plane point type and its arithmetic, shared by all.

// Axis arithmetic indexes several parallel position arrays by slot.
#![allow(clippy::needless_range_loop)]

pub mod arc;
pub mod comp;
pub mod corner;
pub mod rotary;
pub mod stroke;
pub mod turning;
pub mod vec2;
pub mod xform;
