//! The machine state the API returns (`GET /api/state`) and pushes
//! (`WS /api/stream`): the contract of docs/hmi.md "State". Names follow
//! design.md and MTConnect `Execution`.

use serde::ser::SerializeMap;
use serde::{Deserialize, Serialize, Serializer};

/// Operating mode (the mode selector of the panel).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[allow(clippy::upper_case_acronyms)]
pub enum Mode {
    /// Program editing.
    EDIT,
    /// Memory (automatic) operation.
    #[default]
    MEM,
    /// Manual data input.
    MDI,
    /// Jog (and handle).
    JOG,
    /// Reference return.
    REF,
}

/// MTConnect `Execution`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[allow(non_camel_case_types, clippy::upper_case_acronyms)]
pub enum Execution {
    /// Idle, ready for cycle start.
    #[default]
    READY,
    /// Running.
    ACTIVE,
    /// Feed hold: the axes stopped on the path.
    FEED_HOLD,
    /// Stopped by an alarm or a reset during the run.
    STOPPED,
    /// M01 with optional stop on.
    OPTIONAL_STOP,
    /// M00.
    PROGRAM_STOPPED,
    /// M02 / M30 / end of text.
    PROGRAM_COMPLETED,
    /// Single-block stop.
    INTERRUPTED,
}

impl Execution {
    /// True while the axes may move (the server pushes at full rate).
    pub fn is_running(self) -> bool {
        matches!(self, Execution::ACTIVE)
    }
}

/// Axis values in the machine's axis order, serialised as a JSON object
/// `{"X": 1.0, "Z": -2.0}` in that order.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Axes(pub Vec<(String, f64)>);

impl Axes {
    /// The value of one axis by name (`"X"`), if the machine has it.
    pub fn get(&self, name: &str) -> Option<f64> {
        self.0.iter().find(|(n, _)| n == name).map(|(_, v)| *v)
    }
}

impl Serialize for Axes {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut m = s.serialize_map(Some(self.0.len()))?;
        for (k, v) in &self.0 {
            m.serialize_entry(k, &round6(*v))?;
        }
        m.end()
    }
}

impl<'de> Deserialize<'de> for Axes {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let m = serde_json::Map::<String, serde_json::Value>::deserialize(d)?;
        let mut v = Vec::new();
        for (k, x) in m {
            let x = x
                .as_f64()
                .ok_or_else(|| serde::de::Error::custom(format!("axis {k}: not a number")))?;
            v.push((k, x));
        }
        Ok(Axes(v))
    }
}

/// Rounds to 1 nm / 1 µdeg so the JSON stays short; the view needs no more.
fn round6(v: f64) -> f64 {
    if v.is_finite() {
        (v * 1e6).round() / 1e6
    } else {
        0.0
    }
}

/// Where the program is.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct ProgramPos {
    /// Name it was loaded under (null when none is loaded).
    pub name: Option<String>,
    /// File of the executing block (the main program or a library file).
    pub file: Option<String>,
    /// 1-based line of the executing block in `file` (0 before the first).
    pub line: u32,
    /// Text of the executing block.
    pub block: String,
}

/// The position pages.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Positions {
    /// ABSOLUTE: the tool tip in the active work coordinate system, mm.
    pub work: Axes,
    /// RELATIVE: the operator's relative counters, mm.
    pub relative: Axes,
    /// MACHINE: machine coordinates, mm.
    pub machine: Axes,
    /// DISTANCE TO GO of the executing motion, mm.
    pub distance_to_go: Axes,
}

/// Feed, mm/min.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct FeedState {
    /// Commanded (modal F, converted to mm/min).
    pub programmed: f64,
    /// Actual path speed now.
    pub actual: f64,
}

/// Spindle.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct SpindleState {
    /// Actual speed, rev/min.
    pub rpm: f64,
    /// Commanded speed, rev/min.
    pub programmed: f64,
    /// `cw`, `ccw` or `stop`.
    pub direction: String,
}

/// The operator panel switches and the overrides, as the runtime keeps
/// them (the same serde shape goes on the wire).
pub use kerf_control::runtime::{Overrides, Switches};

/// An alarm as shown on the ALARM page and in the history.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct AlarmInfo {
    /// Sequence number in the history (1 for the first of the session).
    pub seq: u64,
    /// The control's code, e.g. `F_82001`.
    pub code: String,
    /// Message.
    pub message: String,
    /// File, line and column of the block that raised it.
    pub file: String,
    /// 1-based line.
    pub line: u32,
    /// 1-based column.
    pub col: u32,
    /// Text of that block (empty when it is not known).
    pub block: String,
    /// Machine time it was raised, s.
    pub t: f64,
    /// `alarm` or `message` (#3006, M00 texts, probe records).
    pub kind: String,
}

/// The whole state, as `GET /api/state` returns it.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct State {
    /// Operating mode.
    pub mode: Mode,
    /// Execution state.
    pub execution: Execution,
    /// Program, line, block.
    pub program: ProgramPos,
    /// Positions.
    pub position: Positions,
    /// The G codes in force, one per modal group, e.g. `["G00", "G17", …]`.
    pub modal: Vec<String>,
    /// Feed.
    pub feed: FeedState,
    /// Spindle.
    pub spindle: SpindleState,
    /// Tool in the spindle / turret station.
    pub tool: u32,
    /// Panel switches.
    pub switches: Switches,
    /// Overrides.
    pub overrides: Overrides,
    /// The alarm in force, if any.
    pub alarm: Option<AlarmInfo>,
    /// Machine time since power-on, s.
    pub t: f64,
    /// Sequence number of the newest alarm-history entry (0: none).
    pub alarm_seq: u64,
    /// Publication number of this state: one more for every state the
    /// server publishes (a client drops a state numbered below one it
    /// has drawn: a stream message overtaken by a command's answer).
    pub seq: u64,
    /// The backplot of the loaded program: `{id, points, done, note}`.
    pub path: PathInfo,
    /// The program restart prepared by a `restart` command (line, tool,
    /// spindle, modal codes, feed, re-entry path), until cycle start runs it.
    pub restart: Option<serde_json::Value>,
}

/// Where the backplot of the loaded program stands.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct PathInfo {
    /// Changes whenever the path is rebuilt (a new program, a re-decimation).
    pub id: u32,
    /// Points made so far.
    pub points: u32,
    /// True once the whole program has been traced.
    pub done: bool,
    /// Why the trace ended before the program's end (an alarm, a limit).
    pub note: Option<String>,
    /// The simulated part is ready at `GET /api/part.stl`.
    pub part: bool,
    /// Changes whenever that part changes (the trace's whole-program part
    /// made, the part cut so far by the run under way written again).
    pub part_seq: u32,
}
