//! The server's [`Control`] on kerf-control's controller runtime: the
//! runtime's state and pages turned into the API's shapes (axis names
//! upper case in the machine's order, the alarm history with its
//! sequence numbers; the offsets document is the runtime's), and the API's
//! checked commands turned into the runtime's.

use kerf_control::runtime::{
    self as rt, decide, Command as RtCommand, Op, Runtime, VarWrite, Verdict,
};
use serde_json::{json, Map, Value};

use crate::command::{Command, RestartAt};
use crate::control::{Control, Refusal};
use crate::relative::Relative;
use crate::state::{self as st, AlarmInfo, Axes, State};

/// The runtime behind the server.
pub struct RuntimeControl {
    rt: Runtime,
    /// Axis names: (runtime key `x`, display name `X`), machine order.
    axes: Vec<(String, String)>,
    /// The RELATIVE counters (ORIGIN, PRESET).
    relative: Relative,
    /// The history read so far.
    history: Vec<AlarmInfo>,
    /// The simulated part following the cut (with `--stock`).
    part: Option<crate::live_part::PartFeed>,
}

impl RuntimeControl {
    /// Wraps a runtime (its mode, program and offsets as they are).
    pub fn new(rt: Runtime) -> RuntimeControl {
        let axes: Vec<(String, String)> = rt
            .axes()
            .iter()
            .map(|a| (a.name().to_string(), a.name().to_ascii_uppercase()))
            .collect();
        let machine = machine_of(&axes, &rt.state().position.machine);
        let mut c = RuntimeControl {
            rt,
            relative: Relative::new(&machine),
            axes,
            history: Vec::new(),
            part: None,
        };
        c.sync_history();
        c
    }

    /// The runtime (read-only).
    pub fn runtime(&self) -> &Runtime {
        &self.rt
    }

    fn sync_history(&mut self) {
        let after = self.history.last().map(|a| a.seq).unwrap_or(0);
        for r in self.rt.alarms(after) {
            self.history.push(AlarmInfo {
                seq: r.seq,
                code: r.code,
                message: r.message,
                file: r.file,
                line: r.line,
                col: r.col,
                block: String::new(),
                t: r.t,
                kind: match r.kind {
                    rt::RecordKind::Alarm => "alarm",
                    rt::RecordKind::Message => "message",
                    rt::RecordKind::Reset => "reset",
                }
                .into(),
            });
        }
        // Bounded as the runtime's own log is.
        if self.history.len() > 10_000 {
            let cut = self.history.len() - 10_000;
            self.history.drain(..cut);
        }
    }

    fn axes_of(&self, v: &rt::AxisValues) -> Axes {
        Axes(
            self.axes
                .iter()
                .map(|(k, n)| (n.clone(), v.get(k).copied().unwrap_or(0.0)))
                .collect(),
        )
    }

    /// A refusal of the runtime: 409 when the mode table refused `op` in
    /// this state, 400 when the table allowed it and the data was wrong.
    fn refusal(&self, op: Op, before: (rt::Mode, rt::Execution), r: rt::Refusal) -> Refusal {
        let data_op = matches!(
            op,
            Op::WriteOffset
                | Op::WriteVariable
                | Op::WriteParameter
                | Op::Jog
                | Op::Handle
                | Op::Restart
                | Op::Mdi
        );
        match decide(before.0, before.1, op) {
            Verdict::Allow(_) if data_op => Refusal::Invalid(r.to_string()),
            _ => Refusal::State(r.to_string()),
        }
    }

    fn run(&mut self, cmd: RtCommand) -> Result<(), Refusal> {
        let op = cmd.op();
        let before = (self.rt.mode(), self.rt.execution());
        let r = self.rt.command(cmd);
        self.sync_history();
        r.map_err(|e| self.refusal(op, before, e))
    }
}

fn mode_of(m: rt::Mode) -> st::Mode {
    match m {
        rt::Mode::Edit => st::Mode::EDIT,
        rt::Mode::Mem => st::Mode::MEM,
        rt::Mode::Mdi => st::Mode::MDI,
        rt::Mode::Jog => st::Mode::JOG,
        rt::Mode::Ref => st::Mode::REF,
    }
}

fn rt_mode(m: st::Mode) -> rt::Mode {
    match m {
        st::Mode::EDIT => rt::Mode::Edit,
        st::Mode::MEM => rt::Mode::Mem,
        st::Mode::MDI => rt::Mode::Mdi,
        st::Mode::JOG => rt::Mode::Jog,
        st::Mode::REF => rt::Mode::Ref,
    }
}

fn execution_of(x: rt::Execution) -> st::Execution {
    use rt::Execution as R;
    use st::Execution as S;
    match x {
        R::Ready => S::READY,
        R::Active => S::ACTIVE,
        R::FeedHold => S::FEED_HOLD,
        R::Stopped => S::STOPPED,
        R::OptionalStop => S::OPTIONAL_STOP,
        R::ProgramStopped => S::PROGRAM_STOPPED,
        R::ProgramCompleted => S::PROGRAM_COMPLETED,
        R::Interrupted => S::INTERRUPTED,
    }
}

/// The API command as the runtime's.
fn rt_command(c: &Command) -> RtCommand {
    match c {
        Command::CycleStart => RtCommand::CycleStart,
        Command::FeedHold => RtCommand::FeedHold,
        Command::Reset => RtCommand::Reset,
        Command::Mode(m) => RtCommand::Mode { mode: rt_mode(*m) },
        Command::Mdi(b) => RtCommand::Mdi { block: b.clone() },
        Command::Restart(RestartAt::Line(l)) => RtCommand::Restart {
            line: Some(*l),
            sequence: None,
        },
        Command::Restart(RestartAt::Sequence(n)) => RtCommand::Restart {
            line: None,
            sequence: Some(*n),
        },
        Command::Switch(s) => RtCommand::Switch {
            single_block: s.single_block,
            optional_stop: s.optional_stop,
            dry_run: s.dry_run,
            block_skip: s.block_skip.clone(),
        },
        Command::Override { feed, rapid } => RtCommand::Override {
            feed: *feed,
            rapid: *rapid,
        },
        Command::Jog { axis, distance } => RtCommand::Jog {
            axis: axis.to_ascii_lowercase(),
            distance: *distance,
        },
        Command::Handle {
            axis,
            pulses,
            increment,
        } => RtCommand::Handle {
            axis: axis.to_ascii_lowercase(),
            pulses: *pulses,
            increment: *increment,
        },
        Command::RefReturn(a) => RtCommand::RefReturn {
            axis: a.as_ref().map(|a| a.to_ascii_lowercase()),
        },
        Command::Origin { .. } => RtCommand::Reset, // not reached: handled before
    }
}

impl Control for RuntimeControl {
    fn load(&mut self, name: &str, text: &str) -> Result<(), Refusal> {
        let before = (self.rt.mode(), self.rt.execution());
        let r = self.rt.load_program(name, text);
        r.map_err(|e| self.refusal(Op::LoadProgram, before, e))
    }

    fn command(&mut self, cmd: &Command) -> Result<(), Refusal> {
        if let Command::Origin { axis, value } = cmd {
            let i = match axis {
                Some(a) => Some(self.axes.iter().position(|(_, n)| n == a).ok_or_else(|| {
                    Refusal::Invalid(format!("origin: this machine has no axis {a}"))
                })?),
                None => None,
            };
            let machine = machine_of(&self.axes, &self.rt.state().position.machine);
            self.relative.set(i, *value, &machine);
            return Ok(());
        }
        // A run of the program from its beginning cuts the stock afresh.
        let from_start = matches!(cmd, Command::CycleStart)
            && self.rt.mode() == rt::Mode::Mem
            && matches!(
                self.rt.execution(),
                rt::Execution::Ready | rt::Execution::ProgramCompleted
            );
        self.run(rt_command(cmd))?;
        if let (true, Some(p)) = (from_start, &self.part) {
            let it = self.rt.interp();
            p.start(
                kerf_control::sinks::sim::offset_data(it),
                it.work_position(),
            );
        }
        Ok(())
    }

    fn advance(&mut self, seconds: f64) {
        self.rt.step(seconds);
        self.sync_history();
    }

    fn state(&self) -> State {
        let s = self.rt.state();
        let work = self.axes_of(&s.position.work);
        let counters = self
            .relative
            .at(&machine_of(&self.axes, &s.position.machine));
        let relative = Axes(
            self.axes
                .iter()
                .zip(counters)
                .map(|((_, n), v)| (n.clone(), v))
                .collect(),
        );
        let it = self.rt.interp();
        let (_, s_prog) = it.spindle_state();
        let alarm = s.alarm.as_ref().map(|a| {
            let seq = self
                .history
                .iter()
                .rev()
                .find(|h| h.kind == "alarm" && h.code == a.code && h.line == a.line)
                .map(|h| (h.seq, h.t))
                .unwrap_or((0, s.t));
            AlarmInfo {
                seq: seq.0,
                code: a.code.clone(),
                message: a.message.clone(),
                file: a.file.clone(),
                line: a.line,
                col: a.col,
                block: String::new(),
                t: seq.1,
                kind: "alarm".into(),
            }
        });
        State {
            mode: mode_of(s.mode),
            execution: execution_of(s.execution),
            program: st::ProgramPos {
                name: (!s.program.name.is_empty()).then(|| s.program.name.clone()),
                file: (!s.program.name.is_empty()).then(|| s.program.name.clone()),
                line: s.program.line,
                block: s.program.block.clone(),
            },
            position: st::Positions {
                work,
                relative,
                machine: self.axes_of(&s.position.machine),
                distance_to_go: self.axes_of(&s.position.distance_to_go),
            },
            modal: s.modal.clone(),
            feed: st::FeedState {
                programmed: it.programmed_feed().unwrap_or(0.0),
                actual: s.feed,
            },
            spindle: st::SpindleState {
                rpm: s.spindle.rpm,
                programmed: s_prog,
                direction: s.spindle.direction.clone(),
            },
            tool: s.tool,
            switches: s.switches.clone(),
            overrides: s.overrides,
            alarm,
            t: s.t,
            alarm_seq: self.history.last().map(|a| a.seq).unwrap_or(0),
            seq: 0,
            path: Default::default(),
            restart: self
                .rt
                .pending_restart()
                .and_then(|p| serde_json::to_value(p).ok()),
        }
    }

    fn offsets(&self) -> Value {
        self.rt.offsets_document()
    }

    fn put_offsets(&mut self, v: &Value) -> Result<(), Refusal> {
        let before = (self.rt.mode(), self.rt.execution());
        let r = self.rt.put_offsets_document(v);
        r.map_err(|e| self.refusal(Op::WriteOffset, before, e))
    }

    fn variables(&self) -> Value {
        let it = self.rt.interp();
        let mut m = Map::new();
        for n in 1..10_000 {
            if let Some(v) = it.macro_var(n) {
                m.insert(format!("#{n}"), json!(v));
            }
        }
        Value::Object(m)
    }

    fn put_variables(&mut self, v: &Value) -> Result<(), Refusal> {
        let Some(o) = v.as_object() else {
            return Err(Refusal::Invalid(
                "variables: a JSON object {\"#100\": 1.5}".into(),
            ));
        };
        let mut writes = Vec::new();
        for (k, x) in o {
            let n: usize = k.trim_start_matches('#').parse().map_err(|_| {
                Refusal::Invalid(format!("variables: '{k}' is not a variable number"))
            })?;
            let value = match x {
                Value::Null => None,
                Value::Number(f) => f.as_f64(),
                _ => {
                    return Err(Refusal::Invalid(format!(
                        "variables: {k} must be a number or null"
                    )))
                }
            };
            writes.push(VarWrite { n, value });
        }
        for w in writes {
            let before = (self.rt.mode(), self.rt.execution());
            self.rt
                .write_variable(w)
                .map_err(|e| self.refusal(Op::WriteVariable, before, e))?;
        }
        Ok(())
    }

    fn parameters(&self) -> Value {
        let p = &self.rt.interp().profile().params;
        Value::Object(p.iter().map(|(k, v)| (k.clone(), json!(v))).collect())
    }

    fn put_parameters(&mut self, v: &Value) -> Result<(), Refusal> {
        let Some(o) = v.as_object() else {
            return Err(Refusal::Invalid(
                "parameters: a JSON object {\"NAME\": value}".into(),
            ));
        };
        let mut writes = Vec::new();
        for (k, x) in o {
            let Some(f) = x.as_f64() else {
                return Err(Refusal::Invalid(format!(
                    "parameters: {k} must be a number"
                )));
            };
            writes.push((k.clone(), f));
        }
        for (k, f) in writes {
            let before = (self.rt.mode(), self.rt.execution());
            self.rt
                .write_parameter(&k, f)
                .map_err(|e| self.refusal(Op::WriteParameter, before, e))?;
        }
        Ok(())
    }

    fn alarms(&self) -> Vec<AlarmInfo> {
        self.history.clone()
    }

    fn follow_part(&mut self, feed: Option<crate::live_part::PartFeed>) {
        let watcher = feed
            .clone()
            .map(|f| Box::new(move |e: &kerf_canon::Event| f.event(e)) as rt::OnPassed);
        self.rt.set_on_passed(watcher);
        self.part = feed;
    }
}

/// The machine position of each axis, in the server's axis order.
fn machine_of(axes: &[(String, String)], v: &rt::AxisValues) -> Vec<f64> {
    axes.iter()
        .map(|(k, _)| v.get(k).copied().unwrap_or(0.0))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::state::Mode;

    fn jog(c: &mut RuntimeControl, axis: &str, distance: f64) {
        c.command(&Command::Jog {
            axis: axis.into(),
            distance,
        })
        .unwrap();
        for _ in 0..2000 {
            c.advance(0.05);
        }
    }

    fn rel(c: &RuntimeControl, a: &str) -> f64 {
        c.state().position.relative.get(a).unwrap()
    }

    #[test]
    fn relative_counts_motion_per_axis_and_ignores_a_work_offset_change() {
        let mut c = RuntimeControl::new(Runtime::for_machine("hx-mc").unwrap());
        c.command(&Command::Mode(Mode::JOG)).unwrap();
        jog(&mut c, "X", -10.0);
        // ORIGIN of X only: X reads 0, Z still holds what it read.
        let z_before = rel(&c, "Z");
        c.command(&Command::Origin {
            axis: Some("X".into()),
            value: 0.0,
        })
        .unwrap();
        assert_eq!(rel(&c, "X"), 0.0);
        jog(&mut c, "X", -2.5);
        assert!((rel(&c, "X") + 2.5).abs() < 1e-6, "{}", rel(&c, "X"));
        assert_eq!(rel(&c, "Z"), z_before);
        // PRESET Y to 100, then move Y by -4: 96.
        c.command(&Command::Origin {
            axis: Some("Y".into()),
            value: 100.0,
        })
        .unwrap();
        jog(&mut c, "Y", -4.0);
        assert!((rel(&c, "Y") - 96.0).abs() < 1e-6, "{}", rel(&c, "Y"));
        // A new G54 moves the ABSOLUTE position, not the relative one.
        let (work_x, rel_x) = (c.state().position.work.get("X").unwrap(), rel(&c, "X"));
        c.put_offsets(&json!({"g54": {"x": 55.0}})).unwrap();
        let s = c.state();
        assert!((s.position.work.get("X").unwrap() - work_x).abs() > 1.0);
        assert_eq!(rel(&c, "X"), rel_x);
        // An axis the machine does not have is a 400.
        let r = c.command(&Command::Origin {
            axis: Some("A".into()),
            value: 0.0,
        });
        assert!(matches!(r, Err(Refusal::Invalid(_))), "{r:?}");
    }
}
