//! Running in machine time: the interpreter feeds the planner block by
//! block ahead of the axes (the planner's look-ahead), until a pause
//! (single block, M00/M01, the end, an alarm) that takes effect when the
//! axes reach it; the machine's spindle, tool and coolant change as the
//! axes reach each command.

use kerf_canon::Canon;
use kerf_interp::BlockStep;

use super::alarms::{Record, RecordKind};
use super::clock::Sched;
use super::mode::Execution;
use super::snapshot::AlarmInfo;
use super::{Pause, Runtime};

/// How far ahead of the axes the interpreter is kept, s of machine time
/// (and at least the planner's look-ahead window of commands).
const AHEAD: f64 = 0.5;

impl Runtime {
    /// Whether the interpreter may read more blocks now.
    fn feeding(&self) -> bool {
        self.exec == Execution::Active
            && self.pause.is_none()
            && self.held.is_none()
            && self.manual.is_none()
    }

    /// Reads one block into the planner (or pauses). Returns false when
    /// nothing more can be read.
    fn feed_block(&mut self) -> bool {
        if !self.drain_events() {
            return false;
        }
        match self.interp.step_block() {
            BlockStep::Block => {
                let before = self.clock.sched.len();
                if !self.drain_events() {
                    return false;
                }
                let emitted = self.clock.sched.len() > before;
                if self.hurco()
                    && self.pause.is_none()
                    && self.interp.last_block_has_m(1)
                    && !self.switches.optional_stop
                {
                    self.pause = Some(Pause::Sync);
                }
                let statement = self.interp.last_block_is_statement();
                let sb_macro = self.profile.param("single_block_macro", 0.0) != 0.0;
                if self.switches.single_block
                    && self.interp.single_block_stop()
                    && (!statement || sb_macro)
                    && (emitted || !self.interp.holds_motion())
                {
                    self.pause = Some(Pause::SingleBlock);
                }
                true
            }
            BlockStep::End => {
                self.drain_events();
                if self.pause.is_none() {
                    self.pause = Some(Pause::End);
                }
                false
            }
            BlockStep::Alarm(a) => {
                self.drain_events();
                self.pause = Some(Pause::Alarm(a));
                false
            }
        }
    }

    /// Hands the interpreter's pending commands to the planner; false when
    /// one of them paused the program (M00/M01, the end).
    fn drain_events(&mut self) -> bool {
        while self.pause.is_none() {
            let Some(e) = self.stash.take().or_else(|| self.interp.take_event()) else {
                return true;
            };
            // Single block: a command of another block than the one being
            // stepped waits for the next cycle start (compensation hands
            // out two blocks' moves after one read).
            let block = (e.src.file, e.src.line);
            if self.switches.single_block && self.interp.single_block_stop() {
                match self.sb_block {
                    Some(b) if b != block => {
                        self.stash = Some(e);
                        self.pause = Some(Pause::SingleBlock);
                        return false;
                    }
                    _ => self.sb_block = Some(block),
                }
            }
            match &e.cmd {
                Canon::Stop { optional } => {
                    self.pause = Some(Pause::Stop {
                        optional: *optional,
                        src: e.src,
                    })
                }
                Canon::End { .. } => self.pause = Some(Pause::End),
                Canon::Aux { m: 200, .. } if self.hurco() => self.pause = Some(Pause::Sync),
                Canon::Message(text) => {
                    let r = self.record(RecordKind::Message, "", text, Some(e.src));
                    self.log.push(r);
                }
                _ => {}
            }
            self.note_motion(&e);
            let ms = self.interp.macro_switches();
            if ms.override_disabled {
                // #3004 bit 1: the feed override does not act (100 %).
                let (r, d) = (self.overrides.rapid / 100.0, self.switches.dry_run);
                self.clock.set_overrides(1.0, r, d);
                self.clock.push_flagged(e, ms.feed_hold_disabled);
                self.clock.set_overrides(self.overrides.feed / 100.0, r, d);
            } else {
                self.clock.push_flagged(e, ms.feed_hold_disabled);
            }
        }
        false
    }

    /// A history record at the current machine time.
    pub(super) fn record(
        &self,
        kind: RecordKind,
        code: &str,
        message: &str,
        src: Option<kerf_canon::SrcRef>,
    ) -> Record {
        let (file, line, col) = match src {
            Some(s) => (self.interp.file_name(s.file).to_string(), s.line, s.col),
            None => (String::new(), 0, 0),
        };
        Record {
            seq: 0,
            t: self.clock.t,
            kind,
            code: code.to_string(),
            message: message.to_string(),
            file,
            line,
            col,
        }
    }

    /// Runs the machine to machine time `target`.
    pub(super) fn run_to(&mut self, target: f64) {
        let mut budget = self.block_budget;
        loop {
            // Keep the plan ahead of the axes.
            while self.feeding()
                && budget > 0
                && (self.clock.planned_until() < target + AHEAD
                    || self.clock.sched.len() < self.buffer)
            {
                budget -= 1;
                if !self.feed_block() {
                    break;
                }
            }
            if (self.pause.is_some() || self.manual_active()) && self.clock.queued() {
                self.clock.finish();
            }
            // A deferred feed hold.
            if let Some(th) = self.hold_at {
                if th <= target {
                    self.clock.t = self.clock.t.max(th);
                    self.apply_passed(th);
                    self.hold_now(th);
                    continue;
                }
            }
            if self.exec == Execution::Active
                && self.held.is_none()
                && (self.pause.is_some() || self.manual_active())
                && !self.clock.queued()
            {
                let end = self.clock.planned_until();
                if end <= target {
                    self.clock.t = self.clock.t.max(end);
                    self.apply_passed(end);
                    self.pause_reached();
                    continue;
                }
            }
            if self.feeding() && budget == 0 {
                // Work bounded: the axes wait at what is planned.
                let end = self.clock.planned_until().max(self.clock.t);
                self.clock.t = target.min(end);
            } else {
                self.clock.t = target;
            }
            self.apply_passed(self.clock.t);
            return;
        }
    }

    /// The commands the axes have passed by time `t`: the spindle, tool
    /// and coolant change.
    fn apply_passed(&mut self, t: f64) {
        // In a feed hold the commands after the stop wait (their planned
        // times are those before the hold).
        let t = match &self.held {
            Some(h) => t.min(h.t_stop),
            None => t,
        };
        let phys = &mut self.phys;
        let last = &mut self.last_line;
        let watcher = &mut self.on_passed;
        self.clock.drop_finished(t, |s: &Sched| {
            *last = s.ev.src.line;
            if let Some(f) = watcher.as_mut() {
                f(&s.ev);
            }
            match &s.ev.cmd {
                Canon::Spindle { dir, rpm, .. } => {
                    phys.spindle = *dir;
                    phys.rpm = if *dir == kerf_canon::SpindleDir::Stop {
                        0.0
                    } else {
                        *rpm
                    };
                }
                Canon::Tool {
                    tool, change: true, ..
                } => phys.tool = *tool,
                Canon::Coolant { mist, flood } => {
                    phys.mist = *mist;
                    phys.flood = *flood;
                }
                _ => {}
            }
        });
        // The tool in a turret is the station the events name.
        if let Some(s) = self.clock.current() {
            if s.t_end.is_some_and(|te| te > t) && s.ev.motion().is_some() {
                self.phys.tool = s.ev.tool;
            }
        }
    }

    /// The axes reached the pause: the execution state changes.
    fn pause_reached(&mut self) {
        if self.manual_active() {
            self.manual_done();
            return;
        }
        let Some(p) = self.pause.clone() else { return };
        match p {
            Pause::Sync => self.pause = None,
            Pause::SingleBlock => {
                self.pause = None;
                self.sb_block = None;
                self.exec = Execution::Interrupted;
            }
            Pause::Stop { optional, src } => {
                self.pause = None;
                self.stop_message(src);
                self.exec = if optional {
                    Execution::OptionalStop
                } else {
                    Execution::ProgramStopped
                };
            }
            Pause::End => {
                self.exec = if self.in_mdi {
                    Execution::Ready
                } else {
                    Execution::ProgramCompleted
                };
                self.phys.spindle = kerf_canon::SpindleDir::Stop;
                self.phys.rpm = 0.0;
                self.save_state();
            }
            Pause::Alarm(a) => {
                let file = self.interp.file_name(a.src.file).to_string();
                let r = self.record(RecordKind::Alarm, &a.code, &a.message, Some(a.src));
                self.log.push(r);
                self.alarm = Some(AlarmInfo {
                    code: a.code.clone(),
                    message: a.message.clone(),
                    file,
                    line: a.src.line,
                    col: a.src.col,
                });
                self.exec = Execution::Stopped;
                self.phys.spindle = kerf_canon::SpindleDir::Stop;
                self.phys.rpm = 0.0;
                self.save_state();
            }
        }
    }

    /// The comment of the block that stopped (M00 / M01 `(CHECK PART)`)
    /// goes to the history as a message, for the operator.
    fn stop_message(&mut self, src: kerf_canon::SrcRef) {
        let text = self
            .program
            .as_ref()
            .filter(|_| !self.in_mdi)
            .and_then(|p| p.line(src.line))
            .map(comments)
            .unwrap_or_default();
        if !text.is_empty() {
            let r = self.record(RecordKind::Message, "", &text, Some(src));
            self.log.push(r);
        }
    }

    fn hurco(&self) -> bool {
        self.profile.dialect == kerf_interp::DialectId::Hurco
    }

    /// Feed hold at machine time `t`.
    pub(super) fn hold_now(&mut self, t: f64) {
        self.hold_at = None;
        let stop = self.clock.hold(t);
        self.held = Some(super::Held {
            at: stop.at,
            t_stop: stop.t_stop,
        });
    }
}

/// The text of a block's comments `(…)`, joined by spaces.
fn comments(line: &str) -> String {
    let mut out = Vec::new();
    let mut rest = line;
    while let Some(a) = rest.find('(') {
        let after = &rest[a + 1..];
        let Some(b) = after.find(')') else { break };
        let c = after[..b].trim();
        if !c.is_empty() {
            out.push(c.to_string());
        }
        rest = &after[b + 1..];
    }
    out.join(" ")
}
