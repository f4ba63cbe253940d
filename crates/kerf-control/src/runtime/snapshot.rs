//! The state snapshot: what `GET /api/state` returns and the browser
//! screen shows (design.md "Runtime and browser screen"). It serialises
//! to exactly the contract's JSON:
//!
//! ```json
//! {"mode":"MEM","execution":"ACTIVE",
//!  "program":{"name":"O1000.nc","line":12,"block":"G01 X100. F600"},
//!  "position":{"work":{"x":30.0,"y":0.0,"z":0.0},
//!              "machine":{"x":-370.0,"y":-250.0,"z":-250.0},
//!              "distance_to_go":{"x":70.0,"y":0.0,"z":0.0}},
//!  "modal":["G01","G17","G90","G94","G21","G40","G49","G80","G98","G54"],
//!  "feed":600.0,"spindle":{"rpm":1000.0,"direction":"cw"},"tool":1,
//!  "switches":{"single_block":false,"optional_stop":false,"dry_run":false,"block_skip":[]},
//!  "overrides":{"feed":100.0,"rapid":100.0},
//!  "alarm":null,"t":3.0}
//! ```

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};

use super::mode::{Execution, Mode};
use super::switches::{Overrides, Switches};

/// Positions keyed by the machine's axis names (`x`, `y`, `z`, `c` …),
/// mm and degrees; lathe X is the radius.
pub type AxisValues = BTreeMap<String, f64>;

/// Where the program is.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct ProgramAt {
    /// The program's name (as loaded), empty when none.
    pub name: String,
    /// 1-based line of the block being executed (0 before the first).
    pub line: u32,
    /// That block's text.
    pub block: String,
}

/// The three position displays.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Positions {
    /// Tool tip in the active work coordinate system (ABSOLUTE page).
    pub work: AxisValues,
    /// Machine coordinates (MACHINE page).
    pub machine: AxisValues,
    /// What is left of the move being executed (DISTANCE TO GO page).
    pub distance_to_go: AxisValues,
}

/// The spindle as it turns.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Spindle {
    /// Speed, rpm (0 when stopped).
    pub rpm: f64,
    /// `"cw"` (M03), `"ccw"` (M04) or `"stop"`.
    pub direction: String,
}

/// The alarm in force.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct AlarmInfo {
    pub code: String,
    pub message: String,
    pub file: String,
    pub line: u32,
    pub col: u32,
}

/// The machine's state at one instant of machine time.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct State {
    pub mode: Mode,
    pub execution: Execution,
    pub program: ProgramAt,
    pub position: Positions,
    /// The G codes in force, one per modal group.
    pub modal: Vec<String>,
    /// Actual path feed, mm/min (0 standing still).
    pub feed: f64,
    pub spindle: Spindle,
    /// Tool in the spindle / active turret station (0 none).
    pub tool: u32,
    pub switches: Switches,
    pub overrides: Overrides,
    pub alarm: Option<AlarmInfo>,
    /// Machine time, s.
    pub t: f64,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn serialises_to_the_contract_fields() {
        let mut work = AxisValues::new();
        work.insert("x".into(), 1.5);
        let s = State {
            mode: Mode::Mem,
            execution: Execution::FeedHold,
            program: ProgramAt {
                name: "a.nc".into(),
                line: 3,
                block: "G01 X1.5".into(),
            },
            position: Positions {
                work: work.clone(),
                machine: work.clone(),
                distance_to_go: work,
            },
            modal: vec!["G01".into()],
            feed: 0.0,
            spindle: Spindle {
                rpm: 0.0,
                direction: "stop".into(),
            },
            tool: 0,
            switches: Switches::default(),
            overrides: Overrides::default(),
            alarm: None,
            t: 1.25,
        };
        let v: serde_json::Value = serde_json::to_value(&s).unwrap();
        let keys: Vec<&str> = v.as_object().unwrap().keys().map(|k| k.as_str()).collect();
        let mut want = vec![
            "mode",
            "execution",
            "program",
            "position",
            "modal",
            "feed",
            "spindle",
            "tool",
            "switches",
            "overrides",
            "alarm",
            "t",
        ];
        want.sort();
        let mut got = keys.clone();
        got.sort();
        assert_eq!(got, want);
        assert_eq!(v["execution"], "FEED_HOLD");
        assert_eq!(v["mode"], "MEM");
        assert_eq!(v["position"]["distance_to_go"]["x"], 1.5);
        assert_eq!(v["alarm"], serde_json::Value::Null);
        assert_eq!(v["switches"]["block_skip"], serde_json::json!([]));
        let back: State = serde_json::from_value(v).unwrap();
        assert_eq!(back, s);
    }
}
