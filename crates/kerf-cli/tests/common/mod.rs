//! Shared by the expansion tests.
pub mod generate;
pub mod programs;
pub mod records;
