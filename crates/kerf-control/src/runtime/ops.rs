//! Carrying out operator commands: each is checked against the mode table
//! and its data validated before anything changes.

use super::alarms::RecordKind;
use super::command::{Command, Op, Refusal};
use super::mode::{Execution, Mode};
use super::program::Program;
use super::switches::{Overrides, PanelError, Switches};
use super::Runtime;

impl Runtime {
    /// Carries out an operator command, or refuses it with the reason
    /// (nothing of a refused command is done).
    ///
    /// ```
    /// use kerf_control::runtime::{Command, Execution, Mode, Runtime};
    ///
    /// let mut rt = Runtime::for_machine("hx-mc").unwrap();
    /// // Power-on: EDIT mode; cycle start runs programs in MEM or MDI.
    /// let r = rt.command(Command::CycleStart).unwrap_err();
    /// assert_eq!(r.reason, "cycle start runs programs in MEM or MDI mode");
    /// // The contract's JSON bodies deserialise to commands.
    /// let c: Command = serde_json::from_str(r#"{"cmd":"mode","mode":"MDI"}"#).unwrap();
    /// rt.command(c).unwrap();
    /// rt.command(Command::Mdi { block: "G91 G00 X-10.".into() }).unwrap();
    /// rt.run_until_stopped(10.0);
    /// assert_eq!(rt.execution(), Execution::Ready);
    /// assert_eq!(rt.state().position.machine["x"], -10.0);
    /// ```
    pub fn command(&mut self, cmd: Command) -> Result<(), Refusal> {
        let op = cmd.op();
        let next = self.check(op)?;
        match cmd {
            Command::CycleStart => self.cycle_start()?,
            Command::FeedHold => self.feed_hold(),
            Command::Reset => self.reset(),
            Command::Mode { mode } => {
                if mode != self.mode {
                    // The re-entry was computed from where the axes were.
                    self.drop_restart();
                }
                self.mode = mode;
                if let Some(x) = next {
                    self.exec = x;
                }
            }
            Command::Mdi { block } => self.mdi(&block)?,
            Command::Restart { line, sequence } => self.prepare_restart(line, sequence)?,
            Command::Switch {
                single_block,
                optional_stop,
                dry_run,
                block_skip,
            } => {
                let mut s = self.switches.clone();
                if let Some(v) = single_block {
                    s.single_block = v;
                }
                if let Some(v) = optional_stop {
                    s.optional_stop = v;
                }
                if let Some(v) = dry_run {
                    s.dry_run = v;
                }
                if let Some(v) = block_skip {
                    s.block_skip = v;
                }
                self.set_switches(s)
                    .map_err(|r| self.refuse(op, r.to_string()))?;
            }
            Command::Override { feed, rapid } => {
                let o = Overrides {
                    feed: feed.unwrap_or(self.overrides.feed),
                    rapid: rapid.unwrap_or(self.overrides.rapid),
                };
                self.set_overrides(o)
                    .map_err(|r| self.refuse(op, r.to_string()))?;
            }
            Command::Jog { axis, distance } => self.jog(op, &axis, distance, false)?,
            Command::Handle {
                axis,
                pulses,
                increment,
            } => {
                if ![0.001, 0.01, 0.1]
                    .iter()
                    .any(|&i| (i - increment).abs() < 1e-12)
                {
                    return Err(self.refuse(
                        op,
                        format!("handle increment {increment}: 0.001, 0.01 or 0.1 mm per pulse"),
                    ));
                }
                if pulses.unsigned_abs() > 100_000 {
                    return Err(self.refuse(op, "at most 100000 pulses at a time"));
                }
                self.jog(op, &axis, pulses as f64 * increment, true)?
            }
            Command::RefReturn { axis } => self.ref_return(op, axis.as_deref())?,
        }
        Ok(())
    }

    /// Sets the panel switches (they act from the next block read).
    pub fn set_switches(&mut self, s: Switches) -> Result<(), PanelError> {
        s.validate()?;
        self.interp
            .set_switches(s.skip_mask(), s.optional_stop, s.single_block);
        self.interp.set_dry_run(s.dry_run);
        self.switches = s;
        self.apply_overrides();
        Ok(())
    }

    /// Sets the override dials (they act from the next block read).
    pub fn set_overrides(&mut self, o: Overrides) -> Result<(), PanelError> {
        o.validate()?;
        self.overrides = o;
        self.apply_overrides();
        Ok(())
    }

    fn apply_overrides(&mut self) {
        self.clock.set_overrides(
            self.overrides.feed / 100.0,
            self.overrides.rapid / 100.0,
            self.switches.dry_run,
        );
    }

    /// Loads a program (EDIT or MEM mode, not while one runs): it becomes
    /// the program MEM runs, from its start.
    pub fn load_program(&mut self, name: &str, text: &str) -> Result<(), Refusal> {
        let next = self.check(Op::LoadProgram)?;
        if text.len() > super::MAX_PROGRAM_BYTES {
            let mib = super::MAX_PROGRAM_BYTES >> 20;
            return Err(self.refuse(
                Op::LoadProgram,
                format!("programs up to {mib} MiB are kept in memory"),
            ));
        }
        self.program = Some(Program::new(name, text));
        self.restart = None;
        self.last_line = 0;
        self.load_main();
        if let Some(x) = next {
            self.exec = x;
        }
        Ok(())
    }

    /// Makes the loaded program the one the interpreter executes, from its
    /// start, keeping the modal state.
    fn load_main(&mut self) {
        if let Some(p) = &self.program {
            let text = p.text.clone();
            let name = p.name.clone();
            self.interp.load_text(&name, &text);
            self.in_mdi = false;
        }
    }

    fn cycle_start(&mut self) -> Result<(), Refusal> {
        let op = Op::CycleStart;
        match self.exec {
            Execution::FeedHold => {
                if let Some(h) = self.held.take() {
                    let now = self.clock.t.max(h.t_stop);
                    self.clock.resume(h.at, h.t_stop, now);
                }
                self.hold_at = None;
                self.exec = Execution::Active;
            }
            x if x.is_stop_between_blocks() => {
                self.pause = None;
                self.sb_block = None;
                self.exec = Execution::Active;
            }
            Execution::Ready | Execution::ProgramCompleted if self.mode == Mode::Mem => {
                if self.program.is_none() {
                    return Err(self.refuse(op, "no program loaded"));
                }
                if let Some(plan) = self.restart.take() {
                    self.start_restart(plan);
                    return Ok(());
                }
                if self.exec == Execution::ProgramCompleted || self.in_mdi || self.pause.is_some() {
                    self.load_main();
                }
                self.pause = None;
                self.restart_clock();
                self.exec = Execution::Active;
            }
            _ => return Err(self.refuse(op, "nothing to start")),
        }
        Ok(())
    }

    /// The clock starts again at rest where the axes are, the spindle
    /// turning as it does.
    pub(super) fn restart_clock(&mut self) {
        let t = self.clock.t;
        let pos = self.clock.position(t);
        self.interp.set_machine_position(pos);
        let wx = self.interp.work_position()[0];
        self.clock
            .restart_at(pos, wx, t, (self.phys.spindle, self.phys.rpm));
        self.apply_overrides();
    }

    fn feed_hold(&mut self) {
        if matches!(self.mode, Mode::Jog | Mode::Ref) {
            let t = self.clock.t;
            let stop = self.clock.abort(t);
            self.manual_done();
            self.interp.set_machine_position(stop.at);
            return;
        }
        let t = self.clock.t;
        let at = self.clock.hold_point(t);
        self.exec = Execution::FeedHold;
        if at > t {
            // The thread or tap goes on: its pieces all planned now (the
            // interpreter reads no further until cycle start).
            self.clock.finish();
            self.hold_at = Some(at);
        } else {
            self.hold_now(t);
        }
    }

    /// RESET (PI 144-150, 000 §14.4 (5)): the axes stop (decelerating on
    /// the path), the spindle and coolant stop, the program is left and
    /// rewound, the modal codes return to their reset state, the alarm is
    /// cleared.
    fn reset(&mut self) {
        let t = self.clock.t;
        let stop = self.clock.abort(t);
        self.interp.reset();
        self.interp.set_machine_position(stop.at);
        self.pause = None;
        self.hold_at = None;
        self.held = None;
        self.restart = None;
        self.stash = None;
        self.sb_block = None;
        self.manual_clear();
        self.phys.spindle = kerf_canon::SpindleDir::Stop;
        self.phys.rpm = 0.0;
        self.phys.mist = false;
        self.phys.flood = false;
        self.alarm = None;
        self.last_line = 0;
        let r = self.record(RecordKind::Reset, "", "RESET", None);
        self.log.push(r);
        if self.in_mdi {
            self.load_main();
        }
        self.exec = Execution::Ready;
        self.save_state();
    }
}
