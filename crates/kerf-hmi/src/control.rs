//! The surface the server drives: one controller runtime behind a lock.
//! The real one is kerf-control's runtime (`runtime_control.rs`); unit
//! tests use a double.

use crate::command::Command;
use crate::state::{AlarmInfo, State};

/// Why a request was not carried out.
#[derive(Clone, Debug, PartialEq)]
pub enum Refusal {
    /// Not allowed in the present mode or state (HTTP 409).
    State(String),
    /// The content is wrong: an offset number out of range, an MDI block
    /// that does not parse (HTTP 400).
    Invalid(String),
}

impl From<Refusal> for crate::error::ApiError {
    fn from(r: Refusal) -> Self {
        match r {
            Refusal::State(m) => crate::error::ApiError::refused(m),
            Refusal::Invalid(m) => crate::error::ApiError::bad_request(m),
        }
    }
}

/// A controller the server can operate. It lives on one thread of its
/// own (the runtime's interpreter holds readers that are not `Send`); the
/// server sends it work (`Shared::with`).
pub trait Control: 'static {
    /// Loads a program as the main program (refused while one runs).
    fn load(&mut self, name: &str, text: &str) -> Result<(), Refusal>;
    /// Carries out an operator command, or refuses it leaving the state as
    /// it was.
    fn command(&mut self, cmd: &Command) -> Result<(), Refusal>;
    /// Advances machine time by `seconds`.
    fn advance(&mut self, seconds: f64);
    /// The state now.
    fn state(&self) -> State;
    /// The offset memory and work offsets, in the `--offsets` format as JSON.
    fn offsets(&self) -> serde_json::Value;
    /// Writes offsets given in that format (only the entries given).
    fn put_offsets(&mut self, offsets: &serde_json::Value) -> Result<(), Refusal>;
    /// Macro variables that hold a value: `{"#100": 1.5, …}`.
    fn variables(&self) -> serde_json::Value;
    /// Writes macro variables given as `{"#100": 1.5, "#101": null}`.
    fn put_variables(&mut self, vars: &serde_json::Value) -> Result<(), Refusal>;
    /// The control parameters: `{"PI 144": 0.0, …}`.
    fn parameters(&self) -> serde_json::Value;
    /// Writes parameters given as `{"NAME": value}`.
    fn put_parameters(&mut self, params: &serde_json::Value) -> Result<(), Refusal>;
    /// The alarm and message history, oldest first.
    fn alarms(&self) -> Vec<AlarmInfo>;
    /// Feeds the commands the axes finish to `feed` (the simulated part
    /// following the cut), or stops with None. A controller without a
    /// machine model ignores it.
    fn follow_part(&mut self, feed: Option<crate::live_part::PartFeed>) {
        let _ = feed;
    }
}
