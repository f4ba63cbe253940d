//! Machine time: the events the interpreter made, planned by kerf-motion's
//! planner into timeline pieces, and the position of the axes at any
//! instant of machine time (the interpolator's command on the planned
//! path, before the smoothing stages). Feed hold cuts the timeline at
//! the stop; resume plans the rest again from rest.

use std::collections::VecDeque;

use kerf_canon::{Canon, Event, ModeChange, Pos, NAXES};
use kerf_motion::{Dynamics, Modes, Piece, Planner};

use super::hold::{decelerate, speed_at, Stop};

/// How an event takes time.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Kind {
    /// Motion or dwell: the planner reports its end (`Done`).
    Timed,
    /// Spindle, tool, coolant, M function, stop, end: the planner stops
    /// the motion for it; its end is known when pushed.
    Flush,
    /// Mode changes and messages: no time of their own.
    Instant,
}

/// An event handed to the planner, with what resuming after a hold needs.
#[derive(Clone, Debug)]
pub(crate) struct Sched {
    pub ev: Event,
    pub kind: Kind,
    /// Machine time at its end (None until the planner has placed it).
    pub t_end: Option<f64>,
    /// The planner's modes before it was pushed.
    pub modes: Modes,
    /// A hold during it waits for its end (thread, tapping, M/S/T).
    pub no_hold: bool,
}

/// The timeline of one machine.
pub(crate) struct Clock {
    dynamics: Dynamics,
    planner: Planner,
    /// Machine time of the planner's t = 0.
    base: f64,
    pieces: VecDeque<Piece>,
    pub sched: VecDeque<Sched>,
    /// Position after everything pushed (machine coordinates).
    end_pos: Pos,
    /// Position when no piece covers the time asked.
    rest: Pos,
    /// G63 / tapping cycle in force in the event stream.
    tapping: bool,
    /// Index in `sched` from which the next timed event without its end
    /// time is searched (the planner reports ends in order).
    unresolved: usize,
    /// Machine time now, s.
    pub t: f64,
}

impl Clock {
    /// A machine at rest at `pos` at machine time `t`.
    pub fn new(dynamics: Dynamics, pos: Pos, work_x: f64, max_rpm: f64, t: f64) -> Clock {
        let mut planner = Planner::new(dynamics.clone(), pos, work_x);
        planner.max_rpm = max_rpm;
        planner.keep_pieces();
        Clock {
            dynamics,
            planner,
            base: t,
            pieces: VecDeque::new(),
            sched: VecDeque::new(),
            end_pos: pos,
            rest: pos,
            tapping: false,
            unresolved: 0,
            t,
        }
    }

    /// Sets the overrides (factors) and dry run for the events pushed
    /// from now on.
    pub fn set_overrides(&mut self, feed: f64, rapid: f64, dry_run: bool) {
        self.dynamics.feed_override = feed;
        self.dynamics.rapid_override = rapid;
        self.dynamics.dry_run = dry_run;
        self.planner.set_overrides(feed, rapid, dry_run);
    }

    /// Hands an event to the planner.
    pub fn push(&mut self, ev: Event) {
        self.push_flagged(ev, false);
    }

    /// Hands an event to the planner; `hold_disabled`: the program has
    /// switched feed hold off for it (#3004 bit 0).
    pub fn push_flagged(&mut self, ev: Event, hold_disabled: bool) {
        let kind = match &ev.cmd {
            Canon::Rapid { .. }
            | Canon::Feed { .. }
            | Canon::Arc { .. }
            | Canon::Thread { .. }
            | Canon::Dwell { .. } => Kind::Timed,
            Canon::Mode(_) | Canon::Message(_) => Kind::Instant,
            _ => Kind::Flush,
        };
        if let Canon::Mode(m) = &ev.cmd {
            match m {
                ModeChange::TappingMode => self.tapping = true,
                ModeChange::CuttingMode
                | ModeChange::ExactStopMode(_)
                | ModeChange::CornerOverride => self.tapping = false,
                _ => {}
            }
        }
        let no_hold = hold_disabled
            || match &ev.cmd {
                Canon::Thread { .. } => true,
                Canon::Feed { .. } | Canon::Arc { .. } => self.tapping,
                Canon::Dwell { .. } | Canon::Rapid { .. } => false,
                _ => kind == Kind::Flush,
            };
        let modes = self.planner.modes();
        if let Some(m) = ev.motion() {
            self.end_pos = m.mto;
        }
        self.planner.push(&ev);
        let t_end = match kind {
            Kind::Flush => Some(self.base + self.planner.now()),
            Kind::Instant => match self.sched.back() {
                None => Some(self.t.max(self.base + self.planner.now())),
                Some(s) => s.t_end,
            },
            Kind::Timed => None,
        };
        self.sched.push_back(Sched {
            ev,
            kind,
            t_end,
            modes,
            no_hold,
        });
        self.collect();
    }

    /// Plans everything pushed to a stop (the interpreter pauses).
    pub fn finish(&mut self) {
        self.planner.finish();
        self.collect();
    }

    /// Takes the planner's records and pieces.
    fn collect(&mut self) {
        while let Some(d) = self.planner.next_done() {
            let t = self.base + d.t_end;
            let from = self.unresolved.min(self.sched.len());
            if let Some(i) = self
                .sched
                .iter()
                .skip(from)
                .position(|s| s.kind == Kind::Timed && s.t_end.is_none())
                .map(|k| k + from)
            {
                self.unresolved = i + 1;
                self.sched[i].t_end = Some(t);
                let mut j = i + 1;
                while j < self.sched.len()
                    && self.sched[j].kind == Kind::Instant
                    && self.sched[j].t_end.is_none()
                {
                    self.sched[j].t_end = Some(t);
                    j += 1;
                }
            }
        }
        while let Some(mut p) = self.planner.next_piece() {
            p.t0 += self.base;
            self.pieces.push_back(p);
        }
    }

    /// Machine time up to which the motion is planned.
    pub fn planned_until(&self) -> f64 {
        self.base + self.planner.now()
    }

    /// Whether segments wait in the planner's look-ahead window.
    pub fn queued(&self) -> bool {
        self.planner.queued() > 0
    }

    /// Events not yet finished at time `t` (the first is the current one).
    pub fn drop_finished(&mut self, t: f64, mut done: impl FnMut(&Sched)) {
        while let Some(s) = self.sched.front() {
            match s.t_end {
                Some(te) if te <= t && self.sched.len() > 1 => {
                    done(s);
                    self.sched.pop_front();
                    self.unresolved = self.unresolved.saturating_sub(1);
                }
                Some(te) if te <= t && te <= self.planned_until() && !self.queued() => {
                    done(s);
                    self.sched.pop_front();
                    self.unresolved = self.unresolved.saturating_sub(1);
                }
                _ => break,
            }
        }
        while self.pieces.len() > 1 {
            let p = &self.pieces[0];
            if p.t0 + p.duration() < t {
                self.rest = p.pos_at(p.duration());
                self.pieces.pop_front();
            } else {
                break;
            }
        }
    }

    /// The machine position at time `t` (≥ the time of the last
    /// [`Clock::drop_finished`]).
    pub fn position(&self, t: f64) -> Pos {
        for p in &self.pieces {
            let end = p.t0 + p.duration();
            if t < p.t0 {
                return p.pos_at(0.0);
            }
            if t <= end {
                return p.pos_at(t - p.t0);
            }
        }
        match self.pieces.back() {
            Some(p) => p.pos_at(p.duration()),
            None => self.rest,
        }
    }

    /// Path speed at time `t`, mm/s.
    pub fn speed(&self, t: f64) -> f64 {
        for p in &self.pieces {
            if t >= p.t0 && t < p.t0 + p.duration() {
                let tau = t - p.t0;
                return match &p.kind {
                    kerf_motion::PieceKind::Move { trap, .. } => speed_at(trap, tau),
                    kerf_motion::PieceKind::Axes { traps, .. } => traps
                        .iter()
                        .map(|tr| speed_at(tr, tau).powi(2))
                        .sum::<f64>()
                        .sqrt(),
                    kerf_motion::PieceKind::Hold { .. } => 0.0,
                };
            }
        }
        0.0
    }

    /// The first event not finished at `t` (the one the block display shows).
    pub fn current(&self) -> Option<&Sched> {
        self.sched.front()
    }

    /// The end of the last consecutive event from the current one during
    /// which a hold waits (thread, tapping, M/S/T function), or `t`.
    pub fn hold_point(&self, t: f64) -> f64 {
        let mut at = t;
        for s in &self.sched {
            let Some(te) = s.t_end else { break };
            if te <= t {
                continue;
            }
            let in_dwell = matches!(s.ev.cmd, Canon::Dwell { .. });
            if s.no_hold || (!in_dwell && self.standing_aux(at, te)) {
                at = te;
            } else {
                break;
            }
        }
        at
    }

    /// Whether the axes stand still from `t` to `te` (settling, M/S/T).
    fn standing_aux(&self, t: f64, te: f64) -> bool {
        self.speed(t) == 0.0 && self.position(t) == self.position(te) && te > t
    }

    /// Stops the axes from time `t` on the planned path; the timeline
    /// after `t` is replaced by the deceleration. Returns the stop.
    pub fn hold(&mut self, t: f64) -> Stop {
        self.finish();
        let pieces: Vec<Piece> = self.pieces.iter().cloned().collect();
        let stop = decelerate(&pieces, t, self.position(t));
        while let Some(p) = self.pieces.back() {
            if p.t0 >= t {
                self.pieces.pop_back();
            } else {
                break;
            }
        }
        if let Some(p) = self.pieces.back_mut() {
            // The piece the hold came in is cut at `t`: from there on the
            // deceleration pieces say where the axes are.
            if t < p.t0 + p.duration() {
                let at = p.pos_at(t - p.t0);
                *p = Piece {
                    t0: t,
                    kind: kerf_motion::PieceKind::Hold { pos: at, dur: 0.0 },
                };
            }
        }
        self.rest = stop.at;
        self.pieces.extend(stop.pieces.iter().cloned());
        stop
    }

    /// After a hold stopped the axes at `at` at time `t_stop`: plans again
    /// from rest the events not finished, from machine time `now`.
    pub fn resume(&mut self, at: Pos, t_stop: f64, now: f64) {
        let left: Vec<Sched> = self
            .sched
            .drain(..)
            .filter(|s| s.t_end.is_none_or(|te| te > t_stop))
            .collect();
        self.unresolved = 0;
        let modes = left
            .first()
            .map(|s| s.modes)
            .unwrap_or_else(|| self.planner.modes());
        self.planner = Planner::resume(self.dynamics.clone(), at, &modes, true);
        self.base = now;
        self.t = now;
        self.pieces.clear();
        self.rest = at;
        self.end_pos = at;
        self.tapping = modes.tapping();
        for (k, s) in left.into_iter().enumerate() {
            let mut ev = s.ev;
            if k == 0 {
                if let Canon::Dwell { seconds, .. } = &mut ev.cmd {
                    if let Some(te) = s.t_end {
                        *seconds = (te - t_stop).clamp(0.0, *seconds);
                    }
                }
            }
            self.push(ev);
        }
    }

    /// Stops everything at once (RESET): nothing more is planned; the
    /// axes decelerate from `t` on the path.
    pub fn abort(&mut self, t: f64) -> Stop {
        let stop = self.hold(t);
        let keep_modes = self.planner.modes();
        self.sched.clear();
        self.unresolved = 0;
        self.planner = Planner::resume(self.dynamics.clone(), stop.at, &keep_modes, true);
        self.base = stop.t_stop;
        self.end_pos = stop.at;
        self.tapping = false;
        stop
    }

    /// Starts planning afresh at rest at `pos` (after a hand move, a
    /// reset or a stop), from machine time `now`, with the spindle turning
    /// as given (no ramp added).
    pub fn restart_at(
        &mut self,
        pos: Pos,
        work_x: f64,
        now: f64,
        spindle: (kerf_canon::SpindleDir, f64),
    ) {
        let max_rpm = self.planner.max_rpm;
        let t = self.t;
        let fresh = Planner::new(self.dynamics.clone(), pos, work_x);
        let mut modes = fresh.modes();
        modes = modes.with_spindle(spindle.0, spindle.1);
        self.planner = Planner::resume(self.dynamics.clone(), pos, &modes, true);
        self.planner.max_rpm = max_rpm;
        self.base = now;
        self.pieces.clear();
        self.sched.clear();
        self.unresolved = 0;
        self.end_pos = pos;
        self.rest = pos;
        self.tapping = false;
        self.t = t.max(now);
    }
}

/// Whether two positions differ in any slot.
pub(crate) fn moved(a: &Pos, b: &Pos) -> bool {
    (0..NAXES).any(|i| (a[i] - b[i]).abs() > 1e-9)
}
