//! A test double of the controller: a program "runs" by moving X from 0
//! to 100 mm at 6000 mm/min (1 s), one line per 10 mm. Only for the API
//! tests: it checks the server, not the control.

use kerf_hmi::command::Command;
use kerf_hmi::state::{AlarmInfo, Axes, Execution, Mode, State};
use kerf_hmi::{Control, Refusal};

#[derive(Default)]
pub struct Double {
    pub state: State,
    pub loaded: Option<String>,
    pub offsets: serde_json::Value,
    pub history: Vec<AlarmInfo>,
}

impl Double {
    pub fn new() -> Double {
        let mut d = Double {
            offsets: serde_json::json!({"h": {}}),
            ..Default::default()
        };
        d.set_x(0.0);
        d
    }
    fn set_x(&mut self, x: f64) {
        let axes = |v: f64| Axes(vec![("X".into(), v), ("Y".into(), 0.0), ("Z".into(), 0.0)]);
        self.state.position.work = axes(x);
        self.state.position.machine = axes(x);
        self.state.position.relative = axes(x);
        self.state.position.distance_to_go = axes(100.0 - x);
        self.state.program.line = (x / 10.0) as u32 + 1;
    }
}

impl Control for Double {
    fn load(&mut self, name: &str, text: &str) -> Result<(), Refusal> {
        if self.state.execution == Execution::ACTIVE {
            return Err(Refusal::State("running".into()));
        }
        self.loaded = Some(text.to_string());
        self.state.program.name = Some(name.into());
        Ok(())
    }
    fn command(&mut self, cmd: &Command) -> Result<(), Refusal> {
        match cmd {
            Command::CycleStart => {
                if self.loaded.is_none() {
                    return Err(Refusal::State("no program".into()));
                }
                self.state.execution = Execution::ACTIVE;
            }
            Command::FeedHold => self.state.execution = Execution::FEED_HOLD,
            Command::Reset => {
                self.state.execution = Execution::READY;
                self.state.alarm = None;
            }
            Command::Mode(m) => self.state.mode = *m,
            Command::Mdi(b) => {
                if self.state.mode != Mode::MDI {
                    return Err(Refusal::State("MDI needs MDI mode".into()));
                }
                if b.contains('?') {
                    let a = AlarmInfo {
                        seq: self.history.len() as u64 + 1,
                        code: "T_1".into(),
                        message: "bad".into(),
                        line: 1,
                        col: 1,
                        block: b.clone(),
                        kind: "alarm".into(),
                        ..Default::default()
                    };
                    self.history.push(a.clone());
                    self.state.alarm_seq = a.seq;
                    self.state.alarm = Some(a);
                }
            }
            Command::Restart(_)
            | Command::Jog { .. }
            | Command::Handle { .. }
            | Command::RefReturn(_)
            | Command::Origin { .. } => {}
            Command::Switch(c) => {
                if let Some(v) = c.single_block {
                    self.state.switches.single_block = v;
                }
                if let Some(v) = &c.block_skip {
                    self.state.switches.block_skip = v.clone();
                }
            }
            Command::Override { feed, rapid } => {
                if let Some(f) = feed {
                    self.state.overrides.feed = *f;
                }
                if let Some(r) = rapid {
                    self.state.overrides.rapid = *r;
                }
            }
        }
        Ok(())
    }
    fn advance(&mut self, dt: f64) {
        self.state.t += dt;
        if self.state.execution == Execution::ACTIVE {
            let x = (self.state.position.work.get("X").unwrap() + 100.0 * dt).min(100.0);
            self.set_x(x);
            if x >= 100.0 {
                self.state.execution = Execution::PROGRAM_COMPLETED;
            }
        }
    }
    fn state(&self) -> State {
        self.state.clone()
    }
    fn offsets(&self) -> serde_json::Value {
        self.offsets.clone()
    }
    fn put_offsets(&mut self, v: &serde_json::Value) -> Result<(), Refusal> {
        let h = v.get("h").and_then(|h| h.as_object());
        let Some(h) = h else {
            return Err(Refusal::Invalid("only [h] here".into()));
        };
        for (k, x) in h {
            let Some(x) = x.as_f64() else {
                return Err(Refusal::Invalid(format!("h {k}: not a number")));
            };
            self.offsets["h"][k] = x.into();
        }
        Ok(())
    }
    fn variables(&self) -> serde_json::Value {
        serde_json::json!({})
    }
    fn put_variables(&mut self, _: &serde_json::Value) -> Result<(), Refusal> {
        Err(Refusal::Invalid("no variables here".into()))
    }
    fn parameters(&self) -> serde_json::Value {
        serde_json::json!({})
    }
    fn put_parameters(&mut self, _: &serde_json::Value) -> Result<(), Refusal> {
        Err(Refusal::Invalid("no parameters here".into()))
    }
    fn alarms(&self) -> Vec<AlarmInfo> {
        self.history.clone()
    }
}
