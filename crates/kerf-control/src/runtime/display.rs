//! The state display: what the screen shows at the current machine time
//! (the block under way, the three position pages, the spindle and tool as
//! the axes reached them), as the contract's `State`.

use kerf_canon::{Axis, Pos, NAXES};

use super::clock::Sched;
use super::mode::Execution;
use super::snapshot::{Positions, ProgramAt, Spindle, State};
use super::Runtime;

impl Runtime {
    /// The state at the current machine time.
    pub fn state(&self) -> State {
        let t = self.clock.t;
        let mpos = self.clock.position(t);
        let cur = self.shown();
        let held_or_idle = self.exec != Execution::Active || self.held.is_some();
        let direction = match self.phys.spindle {
            kerf_canon::SpindleDir::Cw => "cw",
            kerf_canon::SpindleDir::Ccw => "ccw",
            kerf_canon::SpindleDir::Stop => "stop",
        };
        State {
            mode: self.mode,
            execution: self.exec,
            program: self.program_at(cur),
            position: self.positions(cur, mpos),
            modal: self.interp.modal_codes(),
            feed: if held_or_idle && self.held.is_none() {
                0.0
            } else {
                self.clock.speed(t) * 60.0
            },
            spindle: Spindle {
                rpm: self.phys.rpm,
                direction: direction.into(),
            },
            tool: self.phys.tool,
            switches: self.switches.clone(),
            overrides: self.overrides,
            alarm: self.alarm.clone(),
            t,
        }
    }

    /// The command the display shows: running, the one under way; in a
    /// feed hold, the one interrupted; stopped, the last one finished.
    fn shown(&self) -> Option<&Sched> {
        let t = self.clock.t;
        let t_eff = match &self.held {
            Some(h) => t.min(h.t_stop),
            None => t,
        };
        if self.exec == Execution::Active && self.held.is_none() {
            self.clock
                .current()
                .filter(|s| s.t_end.is_none_or(|te| te >= t))
        } else if self.held.is_some() {
            self.clock
                .sched
                .iter()
                .find(|s| s.t_end.is_none_or(|te| te > t_eff))
        } else {
            self.clock
                .sched
                .iter()
                .rev()
                .find(|s| s.t_end.is_some_and(|te| te <= t_eff + 1e-12))
        }
    }

    /// Work = machine − (the shown motion's machine − work point), or the
    /// interpreter's offsets when no motion is shown; distance to go to
    /// the shown motion's end.
    fn positions(&self, cur: Option<&Sched>, mpos: Pos) -> Positions {
        let (shift, end) = match cur.and_then(|s| s.ev.motion()) {
            Some(m) => {
                let mut d = [0.0; NAXES];
                for i in 0..NAXES {
                    d[i] = m.mto[i] - m.to[i];
                }
                (d, m.mto)
            }
            None => (self.work_shift(), mpos),
        };
        let mut p = Positions::default();
        for a in Axis::ALL.into_iter().filter(|&a| self.profile.has_axis(a)) {
            let i = a as usize;
            p.work.insert(a.name().into(), mpos[i] - shift[i]);
            p.machine.insert(a.name().into(), mpos[i]);
            let g = if cur.is_some() { end[i] - mpos[i] } else { 0.0 };
            p.distance_to_go.insert(a.name().into(), g);
        }
        p
    }

    /// The program, line and block text shown.
    fn program_at(&self, cur: Option<&Sched>) -> ProgramAt {
        let (line, name) = match cur {
            Some(s) => (
                s.ev.src.line,
                self.interp.file_name(s.ev.src.file).to_string(),
            ),
            None => (
                self.last_line,
                self.program
                    .as_ref()
                    .map(|p| p.name.clone())
                    .unwrap_or_default(),
            ),
        };
        if self.in_mdi {
            return ProgramAt {
                name: "MDI".into(),
                line,
                block: String::new(),
            };
        }
        let block = self
            .program
            .as_ref()
            .filter(|p| p.name == name)
            .and_then(|p| p.line(line))
            .unwrap_or("")
            .to_string();
        ProgramAt { name, line, block }
    }
}
