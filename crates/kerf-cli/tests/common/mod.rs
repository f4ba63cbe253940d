//! Shared by the expansion tests.
pub mod programs;
