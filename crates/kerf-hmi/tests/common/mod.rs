#![allow(dead_code)]
pub mod double;
pub mod http;
