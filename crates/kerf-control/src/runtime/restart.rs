//! Program restart (000 §2.3.4): after RESET, in MEM mode, the program is
//! run from its start without motion up to the block asked for, so every
//! modal group, work offset, G52/G92 shift, tool and offsets, spindle
//! (with G96 and its clamp), coolant, feed, canned-cycle data, macro
//! variables and the call stack are what a run from the start has there.
//! The re-entry path (retract, tool change, spindle and coolant, position,
//! plunge) is computed and reported ([`RestartPlan`]); cycle start runs it
//! and then the program from that block.

use kerf_canon::{Axis, Canon, Event, Pos, SpindleDir, SrcRef};
use kerf_interp::{BlockStep, MachineKind};
use serde::{Deserialize, Serialize};

use super::command::{Op, Refusal};
use super::mode::Execution;
use super::moves::{machine_move, MoveKind};
use super::restart_error::RestartError;
use super::snapshot::AxisValues;
use super::Runtime;

/// Where to restart.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum RestartAt {
    /// 1-based line of the main program.
    Line(u32),
    /// The block with this sequence number (N).
    Sequence(u32),
}

/// One leg of the re-entry path.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Leg {
    /// `"rapid"` or `"feed"`.
    pub kind: String,
    /// End point, machine coordinates.
    pub to: AxisValues,
}

/// A prepared restart: what cycle start will do before the program goes on.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct RestartPlan {
    /// The line restarted at.
    pub line: u32,
    /// Tool the block needs (changed first if another is in the spindle).
    pub tool: u32,
    /// Spindle rpm and direction (`cw`/`ccw`/`stop`) the block runs with.
    pub spindle_rpm: f64,
    pub spindle_direction: String,
    /// Coolant.
    pub mist: bool,
    pub flood: bool,
    /// G codes in force at the block.
    pub modal: Vec<String>,
    /// Programmed feed at the block.
    pub feed: Option<f64>,
    /// Retract, position, plunge (rapid), last approach (feed).
    pub path: Vec<Leg>,
    #[serde(skip)]
    pub(super) events: Vec<Event>,
}

/// What the silent run saw of the physical state.
#[derive(Default)]
struct Seen {
    spindle: Option<Event>,
    coolant: Option<(bool, bool)>,
    clamp: Option<Event>,
}

const MAX_SILENT_BLOCKS: u64 = 50_000_000;

impl Runtime {
    /// Prepares a restart at `line` or `sequence`.
    pub(super) fn prepare_restart(
        &mut self,
        line: Option<u32>,
        sequence: Option<u32>,
    ) -> Result<(), Refusal> {
        let op = Op::Restart;
        let at = match (line, sequence) {
            (Some(l), None) => RestartAt::Line(l),
            (None, Some(n)) => RestartAt::Sequence(n),
            _ => return Err(self.refuse(op, "give a line or a sequence number")),
        };
        let target = self
            .restart_line(at)
            .map_err(|r| self.refuse(op, r.to_string()))?;
        let home = self.clock.position(self.clock.t);
        // From the reset state at the program start.
        self.interp.reset();
        self.load_main_program();
        match self
            .silent_run(target)
            .and_then(|seen| self.reentry(target, home, seen))
        {
            Ok(plan) => {
                self.restart = Some(plan);
                self.exec = Execution::Ready;
                Ok(())
            }
            Err(r) => {
                // Back to the start of the program, where the axes are.
                self.interp.reset();
                self.load_main_program();
                self.interp.set_machine_position(home);
                Err(self.refuse(op, r.to_string()))
            }
        }
    }

    /// Forgets a prepared restart: the program is back at its start and
    /// the interpreter where the axes are.
    pub(super) fn drop_restart(&mut self) {
        if self.restart.take().is_some() {
            self.interp.reset();
            self.load_main_program();
            let pos = self.clock.position(self.clock.t);
            self.interp.set_machine_position(pos);
        }
    }

    fn load_main_program(&mut self) {
        if let Some(p) = &self.program {
            let (n, t) = (p.name.clone(), p.text.clone());
            self.interp.load_text(&n, &t);
            self.in_mdi = false;
        }
    }

    fn restart_line(&self, at: RestartAt) -> Result<u32, RestartError> {
        let p = self.program.as_ref().ok_or(RestartError::NoProgram)?;
        let l = match at {
            RestartAt::Line(l) => l,
            RestartAt::Sequence(n) => {
                p.line_of_sequence(n)
                    .ok_or_else(|| RestartError::NoSequence {
                        n,
                        name: p.name.clone(),
                    })?
            }
        };
        match p.line(l) {
            None => Err(RestartError::NoLine {
                name: p.name.clone(),
                lines: p.lines(),
                line: l,
            }),
            Some(t) if t.trim().is_empty() => Err(RestartError::EmptyLine(l)),
            Some(_) => Ok(l),
        }
    }

    /// Runs the program without motion until the next block read is
    /// `target` in the main program.
    fn silent_run(&mut self, target: u32) -> Result<Seen, RestartError> {
        let mut seen = Seen::default();
        let main = self.interp.next_block_at().map(|n| n.0).unwrap_or(0);
        let mut blocks = 0u64;
        loop {
            let Some((file, line, depth)) = self.interp.next_block_at() else {
                return Err(RestartError::NoProgram);
            };
            if file == main && line == target {
                if depth > 0 {
                    return Err(RestartError::InCall(target));
                }
                if self.interp.holds_motion() {
                    return Err(RestartError::InCompensation(target));
                }
                return Ok(seen);
            }
            blocks += 1;
            if blocks > MAX_SILENT_BLOCKS {
                return Err(RestartError::NotReached {
                    line: target,
                    blocks: MAX_SILENT_BLOCKS,
                });
            }
            let step = self.interp.step_block();
            while let Some(e) = self.interp.take_event() {
                match &e.cmd {
                    Canon::Spindle { .. } => seen.spindle = Some(e),
                    Canon::Coolant { mist, flood } => seen.coolant = Some((*mist, *flood)),
                    Canon::Mode(kerf_canon::ModeChange::SpindleClamp(_)) => seen.clamp = Some(e),
                    _ => {}
                }
            }
            match step {
                BlockStep::Block => {
                    if let Some((f, l, 0)) = self.interp.next_block_at() {
                        if depth == 0 && file == main && f == main && line < target && l > target {
                            return Err(RestartError::NotABlock(target));
                        }
                    }
                }
                BlockStep::End => return Err(RestartError::EndsBefore(target)),
                BlockStep::Alarm(a) => {
                    return Err(RestartError::AlarmBefore {
                        at: a.src.line,
                        line: target,
                        code: a.code,
                        message: a.message,
                    })
                }
            }
        }
    }

    /// The re-entry from the machine position `home` to the block start.
    fn reentry(&self, line: u32, home: Pos, seen: Seen) -> Result<RestartPlan, RestartError> {
        let it = &self.interp;
        let target = it.machine_position();
        let legs = self.reentry_legs(home, target);
        let tool = it.tool();
        let src = SrcRef {
            file: it.block_at().0.file,
            line,
            col: 1,
        };
        let ev = |cmd: Canon| Event {
            src,
            tool,
            cmd,
            prog: None,
        };
        let approach = self.profile.param("jog_feed", 2000.0);
        let shift = self.work_shift();
        let mut events = Vec::new();
        let mut path = Vec::new();
        let mut from = home;
        for (k, (kind, p)) in legs.iter().enumerate() {
            let how = if *kind == "rapid" {
                MoveKind::Rapid
            } else {
                MoveKind::Feed(approach)
            };
            let mut e = machine_move(&self.profile, from, *p, how, shift)?;
            e.src = src;
            e.tool = tool;
            events.push(e);
            from = *p;
            path.push(Leg {
                kind: kind.to_string(),
                to: self.axis_values(p),
            });
            if k == 0 {
                // At the retract height: tool, spindle, coolant.
                if tool != self.phys.tool && tool != 0 {
                    events.push(ev(Canon::Tool {
                        tool,
                        offset: 0,
                        change: true,
                    }));
                }
                events.extend(seen.clamp.iter().cloned());
                events.extend(seen.spindle.iter().cloned());
                if let Some((mist, flood)) = seen.coolant {
                    events.push(ev(Canon::Coolant { mist, flood }));
                }
            }
        }
        Ok(self.plan(line, tool, &seen, path, events))
    }

    /// Retract (mill Z, lathe X) to the top of its travel, position the
    /// other axes, plunge at rapid to the clearance, approach at feed.
    fn reentry_legs(&self, home: Pos, target: Pos) -> Vec<(&'static str, Pos)> {
        let lathe = self.profile.kind == MachineKind::Lathe;
        let ri = if lathe { Axis::X } else { Axis::Z } as usize;
        let top = self
            .profile
            .axis(if lathe { Axis::X } else { Axis::Z })
            .map(|a| a.max)
            .unwrap_or(home[ri]);
        let clearance = self.profile.param("restart_clearance_mm", 5.0).abs();
        let mut p1 = home;
        p1[ri] = top.max(home[ri]);
        let mut p2 = target;
        p2[ri] = p1[ri];
        let mut p3 = target;
        p3[ri] = (target[ri] + clearance).min(p1[ri]);
        let mut legs = vec![
            ("rapid", p1),
            ("rapid", p2),
            ("rapid", p3),
            ("feed", target),
        ];
        legs.dedup_by(|b, a| !super::clock::moved(&a.1, &b.1));
        if !super::clock::moved(&home, &legs[0].1) {
            legs.remove(0);
        }
        legs
    }

    fn plan(
        &self,
        line: u32,
        tool: u32,
        seen: &Seen,
        path: Vec<Leg>,
        events: Vec<Event>,
    ) -> RestartPlan {
        let (dir, rpm) = match seen.spindle.as_ref().map(|e| &e.cmd) {
            Some(Canon::Spindle { dir, rpm, .. }) => (*dir, *rpm),
            _ => (SpindleDir::Stop, 0.0),
        };
        RestartPlan {
            line,
            tool,
            spindle_rpm: if dir == SpindleDir::Stop { 0.0 } else { rpm },
            spindle_direction: match dir {
                SpindleDir::Cw => "cw",
                SpindleDir::Ccw => "ccw",
                SpindleDir::Stop => "stop",
            }
            .into(),
            mist: seen.coolant.is_some_and(|c| c.0),
            flood: seen.coolant.is_some_and(|c| c.1),
            modal: self.interp.modal_codes(),
            feed: self.interp.programmed_feed(),
            path,
            events,
        }
    }

    fn axis_values(&self, p: &Pos) -> AxisValues {
        self.axes()
            .into_iter()
            .map(|a| (a.name().to_string(), p[a as usize]))
            .collect()
    }

    /// Cycle start on a prepared restart: the re-entry, then the program.
    pub(super) fn start_restart(&mut self, plan: RestartPlan) {
        self.pause = None;
        let t = self.clock.t;
        let pos = self.clock.position(t);
        let wx = self.interp.work_position()[0];
        self.clock
            .restart_at(pos, wx, t, (self.phys.spindle, self.phys.rpm));
        let (f, r, d) = (
            self.overrides.feed / 100.0,
            self.overrides.rapid / 100.0,
            self.switches.dry_run,
        );
        self.clock.set_overrides(f, r, d);
        for e in plan.events {
            self.note_motion(&e);
            self.clock.push(e);
        }
        self.exec = Execution::Active;
    }
}
