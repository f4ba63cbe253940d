//! The streaming planner: a bounded look-ahead queue of segments, path
//! speed planning (backward/forward passes over trapezoids), junction
//! speeds, exact stop, and the timeline of everything else (dwell,
//! spindle, tool change, M-code handshakes). Motion law: docs/motion.md.

use std::cmp::Ordering;
use std::collections::VecDeque;

use kerf_canon::{
    Canon, Event, Feed, ModeChange, Motion, Plane, Pos, RotaryMode, SpindleDir, SrcRef, NAXES,
};

use crate::dynamics::Dynamics;
use crate::geom::{line_len, Geom};
use crate::trap::Trap;

mod lag_memo;
mod lower;
mod resume;
mod turn;
use lag_memo::LagMemo;
use lower::lower;
pub use resume::Modes;
use turn::turn_bound;

/// Time totals by category, seconds.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Breakdown {
    /// Rapid moves, with their settling (smoothing drain).
    pub rapid: f64,
    /// Cutting moves (feed, arc, thread), with their settling.
    pub cutting: f64,
    /// Dwells.
    pub dwell: f64,
    /// Tool changes and turret indexing.
    pub tool_change: f64,
    /// Spindle ramps and M/S/T handshakes.
    pub other: f64,
}

impl Breakdown {
    /// Sum of all categories.
    pub fn total(&self) -> f64 {
        self.rapid + self.cutting + self.dwell + self.tool_change + self.other
    }
}

/// A record's end time, reported in execution order for every motion
/// (rapid, feed, arc, thread) and dwell event pushed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Done {
    /// The sequence number of the event among the motion and dwell events
    /// pushed (0-based).
    pub id: u64,
    /// Seconds from program start at its end: when the axes arrive for a
    /// block that stops; for a block passed at speed, the end of its
    /// interpolation plus half the smoothing delay (`stages·T/2`), the
    /// moment the smoothed command passes its end point on a straight run.
    pub t_end: f64,
    /// Seconds this record adds to the [`Breakdown`]: to `cutting` for a
    /// feed, arc or thread (its interpolation, and its settling when it
    /// stops), to `rapid` for a rapid (with its settling), to `dwell` for a
    /// dwell. The records' times sum to those three totals.
    pub time: f64,
}

/// One piece of the (pre-smoothing) timeline, for the sampler.
#[derive(Clone, Debug, PartialEq)]
pub struct Piece {
    /// Start time, s.
    pub t0: f64,
    /// What happens.
    pub kind: PieceKind,
}

/// What a [`Piece`] does.
#[derive(Clone, Debug, PartialEq)]
pub enum PieceKind {
    /// Along a path with a trapezoidal speed.
    Move { geom: Geom, trap: Trap },
    /// Non-linear rapid: each axis its own trapezoid.
    Axes {
        p0: Pos,
        p1: Pos,
        traps: Box<[Trap; NAXES]>,
    },
    /// Standing still.
    Hold { pos: Pos, dur: f64 },
}

impl Piece {
    /// Duration, s.
    pub fn duration(&self) -> f64 {
        match &self.kind {
            PieceKind::Move { trap, .. } => trap.time(),
            PieceKind::Axes { traps, .. } => traps.iter().map(|t| t.time()).fold(0.0, f64::max),
            PieceKind::Hold { dur, .. } => *dur,
        }
    }

    /// Commanded position (before smoothing) at time `t` from the piece start.
    pub fn pos_at(&self, t: f64) -> Pos {
        match &self.kind {
            PieceKind::Move { geom, trap } => {
                if trap.len <= 0.0 {
                    return geom.end();
                }
                geom.at(trap.s_at(t) / trap.len)
            }
            PieceKind::Axes { p0, p1, traps } => {
                let mut p = *p0;
                for i in 0..NAXES {
                    let s = traps[i].s_at(t);
                    p[i] += if p1[i] >= p0[i] { s } else { -s };
                }
                p
            }
            PieceKind::Hold { pos, .. } => *pos,
        }
    }
}

#[derive(Clone, Copy, Debug)]
struct Seg {
    id: u64,
    /// Last segment of its event (the one that reports `Done`).
    last: bool,
    geom: Geom,
    len: f64,
    vmax: f64,
    acc: f64,
    /// Junction speed limit at the start.
    jmax: f64,
    /// Backward-planned bound of the entry speed.
    vb: f64,
    /// Stop (exact stop, smoothing drained) at the end.
    stop: bool,
    t_in: Pos,
    t_out: Pos,
}

/// Tool centre minus programmed end point of a compensated move.
fn comp_offset(m: &Motion, prog: Option<&Pos>) -> [f64; 3] {
    match prog {
        Some(p) => [m.to[0] - p[0], m.to[1] - p[1], m.to[2] - p[2]],
        None => [0.0; 3],
    }
}

/// Splits a segment at fraction `frac` of its length; the first part
/// ends inside the move (no stop, no record, no compensation corner).
fn split(s: &Seg, frac: f64) -> (Seg, Seg) {
    let (g0, g1) = (s.geom.sub(0.0, frac), s.geom.sub(frac, 1.0));
    let mut h = *s;
    let mut t = *s;
    h.geom = g0;
    h.len = s.len * frac;
    h.last = false;
    h.stop = false;
    t.geom = g1;
    t.len = s.len - h.len;
    if let Geom::Arc { .. } = s.geom {
        h.t_out = g0.tangent(1.0);
        t.t_in = g1.tangent(0.0);
    }
    // Inside one move the path is smooth: only the speed limits meet.
    t.jmax = h.vmax.min(t.vmax);
    (h, t)
}

/// The planner. Push events in execution order with [`Planner::push`];
/// take finished records with [`Planner::next_done`] and, when asked for,
/// timeline pieces with [`Planner::next_piece`]; call [`Planner::finish`]
/// at the end. Memory is bounded by the look-ahead window.
#[derive(Debug)]
pub struct Planner {
    d: Dynamics,
    t_smooth: f64,
    stages: usize,
    /// `stages · t_smooth²` (the corner and arc tolerance limits' divisor).
    k_tt: f64,
    /// First and second moments of the smoothing kernel's positive half
    /// (the corner rounding, see [`Planner::junction`]).
    m1: f64,
    m2: f64,
    q: VecDeque<Seg>,
    window: usize,
    head_v: f64,
    now: f64,
    pos: Pos,
    work_x: f64,
    rpm: f64,
    css: Option<f64>,
    /// Direction of the last spindle event (Stop before the first).
    spindle_dir: SpindleDir,
    exact_mode: bool,
    corner_mode: bool,
    /// Hurco M49: the feed override is ignored.
    ignore_override: bool,
    /// Source block of the last cutting motion pushed, while it is the
    /// last event: a G09 emitted after its block's motion (Hurco, 002
    /// Table 1) stops that motion.
    last_cut: Option<SrcRef>,
    g09: bool,
    tapping: bool,
    high_speed: bool,
    next_id: u64,
    done: VecDeque<Done>,
    pieces: Option<VecDeque<Piece>>,
    /// Totals so far (final after [`Planner::finish`]).
    pub time: Breakdown,
    /// Cutting path length so far, mm.
    pub feed_length: f64,
    /// G112 / G107 in force: F is then a speed on the programmed surface
    /// (the face's Cartesian plane, the developed cylinder).
    rotary: RotaryMode,
    /// Rapid path length so far, mm.
    pub rapid_length: f64,
    /// Spindle speed limit used with constant surface speed, rpm (the
    /// machine's `spindle.max_rpm`).
    pub max_rpm: f64,
    /// The program's clamp (G50 S / G92 S), rpm.
    s_clamp: f64,
    /// Following error of each axis's position loop behind the
    /// unsmoothed command (see [`lag_phase`]), mm.
    lag: Pos,
    /// Position loop gain, 1/s (infinite: no servo lag).
    gain: f64,
    /// [`lag_phase`] results of this gain, for phases that repeat.
    memo: LagMemo,
    /// Sum of the queued segments' `len / vmax` (each a lower bound of
    /// its time): no stop can come sooner.
    q_tmin: f64,
    /// Of the last segment pushed (the queue's last while it is queued):
    /// cutter compensation at its end, tool centre minus programmed point
    /// (X Y Z, zero without compensation), and its programmed feed after
    /// overrides and clamp, mm/s (what the G62 override scales).
    last_off: [f64; 3],
    last_feed: f64,
    /// Factor from the loop's error behind the unsmoothed command at the
    /// end of the interpolation to its error when the smoothed command
    /// arrives: `((1 − e^(−K·T))/(K·T))^k`.
    lag_c: f64,
    /// Cutting moves with no feed (per-revolution feed or thread with the
    /// spindle stopped): the control would wait for ever; they are timed
    /// as 0 s and counted here.
    pub stalled: u64,
    /// Cutting time of the event whose segments are being finalized (its
    /// `Done::time` once the last one is).
    ev_spent: f64,
}

/// The following error `e` of a first-order position loop of gain `k`
/// (`de/dt = v − k·e`) after `dt` seconds of a command whose speed is
/// `v0 + a·t`: `e·E + v0·(1 − E)/k + a·(k·dt − (1 − E))/k²`, `E = e^(−k·dt)`.
/// Returns (E, the increment for e = 0).
fn lag_phase(k: f64, v0: f64, a: f64, dt: f64) -> (f64, f64) {
    if dt <= 0.0 || k.is_nan() || !k.is_finite() {
        return (1.0, 0.0);
    }
    let x = k * dt;
    let one_minus_e = -(-x).exp_m1();
    // x − (1 − e^−x), by its series where the difference cancels.
    let g = if x < 1e-3 {
        x * x * (0.5 - x / 6.0 + x * x / 24.0)
    } else {
        x - one_minus_e
    };
    (1.0 - one_minus_e, v0 * one_minus_e / k + a * g / (k * k))
}

fn dot(a: &Pos, b: &Pos) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

impl Planner {
    /// A planner starting at rest at machine position `start`, work X
    /// `work_x` (for constant surface speed). `d` must have passed
    /// [`Dynamics::validate`].
    pub fn new(d: Dynamics, start: Pos, work_x: f64) -> Planner {
        let t_smooth = d.smoothing_time();
        let stages = d.stages();
        let window = d.lookahead.max(1);
        let gain = d.position_gain;
        let lag_c = if gain.is_finite() && gain > 0.0 && t_smooth > 0.0 {
            let x = gain * t_smooth;
            (-(-x).exp_m1() / x).powi(stages as i32)
        } else {
            1.0
        };
        let k = stages as f64;
        let t = t_smooth;
        let (m1, m2) = if stages == 1 {
            (t / 8.0, t * t / 48.0)
        } else {
            (t / 6.0, t * t / 24.0)
        };
        Planner {
            t_smooth,
            stages,
            k_tt: k * t * t,
            m1,
            m2,
            q: VecDeque::with_capacity(window + 1),
            window,
            head_v: 0.0,
            now: 0.0,
            pos: start,
            work_x,
            rpm: 0.0,
            css: None,
            spindle_dir: SpindleDir::Stop,
            exact_mode: false,
            corner_mode: false,
            ignore_override: false,
            last_cut: None,
            g09: false,
            tapping: false,
            high_speed: false,
            next_id: 0,
            done: VecDeque::new(),
            pieces: None,
            time: Breakdown::default(),
            feed_length: 0.0,
            rotary: RotaryMode::Off,
            rapid_length: 0.0,
            max_rpm: f64::INFINITY,
            s_clamp: f64::INFINITY,
            stalled: 0,
            ev_spent: 0.0,
            lag: [0.0; NAXES],
            gain,
            memo: LagMemo::new(gain),
            q_tmin: 0.0,
            last_off: [0.0; 3],
            last_feed: 0.0,
            lag_c,
            d,
        }
    }

    /// Keeps the timeline pieces for [`Planner::next_piece`] (the sampler).
    pub fn keep_pieces(&mut self) {
        self.pieces = Some(VecDeque::new());
    }

    /// Width of one smoothing stage, s.
    pub fn smoothing_time(&self) -> f64 {
        self.t_smooth
    }

    /// Number of smoothing stages (1 linear, 2 bell).
    pub fn stages(&self) -> usize {
        self.stages
    }

    /// The planned time so far (final after [`Planner::finish`]), s.
    pub fn now(&self) -> f64 {
        self.time.total()
    }

    /// The spindle speed last commanded, rpm.
    pub fn rpm(&self) -> f64 {
        self.rpm
    }

    /// Next finished record, in order.
    pub fn next_done(&mut self) -> Option<Done> {
        self.done.pop_front()
    }

    /// Next finished timeline piece (only with [`Planner::keep_pieces`]).
    pub fn next_piece(&mut self) -> Option<Piece> {
        self.pieces.as_mut().and_then(|p| p.pop_front())
    }

    /// Segments waiting in the look-ahead window.
    pub fn queued(&self) -> usize {
        self.q.len()
    }

    /// Effective feed in mm/min for a programmed feed before the motion
    /// limits (per-rev via the spindle speed, inverse time via the move
    /// length, overrides, dry run, the `feed.max_cutting` clamp).
    pub fn feed_mm_min(&self, f: Feed, len: f64) -> f64 {
        let v = if self.d.dry_run {
            self.d.dry_run_feed
        } else {
            match f {
                Feed::PerMin(v) => v,
                Feed::PerRev(v) => v * self.rpm,
                Feed::InverseTime(v) => len * v,
            }
        };
        (v * self.override_factor()).min(self.d.max_feed)
    }

    /// The feed override in force (100 % in G63 and after Hurco M49).
    fn override_factor(&self) -> f64 {
        if self.tapping || self.ignore_override {
            1.0
        } else {
            self.d.feed_override
        }
    }

    /// Stops the motion and plans everything still queued (end of program).
    pub fn finish(&mut self) {
        self.flush();
    }

    fn hold(&mut self, dur: f64) {
        if dur > 0.0 {
            if let Some(p) = self.pieces.as_mut() {
                p.push_back(Piece {
                    t0: self.now,
                    kind: PieceKind::Hold { pos: self.pos, dur },
                });
            }
            self.now += dur;
        }
    }

    fn drain_time(&self) -> f64 {
        self.stages as f64 * self.t_smooth
    }

    /// Runs the position loops through one trapezoid along the fixed
    /// direction `u` (per axis, per mm of path).
    fn track_lag(&mut self, u: &Pos, trap: &Trap) {
        for (v0, a, dt) in [
            (trap.v0, trap.a, trap.ta),
            (trap.vp, 0.0, trap.tc),
            (trap.vp, -trap.a, trap.td),
        ] {
            if dt > 0.0 {
                let (e, inc) = self.memo.get(v0, a, dt);
                for i in 0..NAXES {
                    self.lag[i] = self.lag[i] * e + u[i] * inc;
                }
            }
        }
    }

    /// One axis of [`Planner::track_lag`] along direction component `u`
    /// from zero lag: the same phases, the same memo calls, the same
    /// operations as that axis's part of it; returns its lag.
    fn track_lag_axis(&mut self, u: f64, trap: &Trap) -> f64 {
        let mut lag = 0.0;
        for (v0, a, dt) in [
            (trap.v0, trap.a, trap.ta),
            (trap.vp, 0.0, trap.tc),
            (trap.vp, -trap.a, trap.td),
        ] {
            if dt > 0.0 {
                let (e, inc) = self.memo.get(v0, a, dt);
                lag = lag * e + u * inc;
            }
        }
        lag
    }

    /// The same along a segment: lines at their direction; arcs in closed
    /// form while the speed is constant (the plane's two axes follow
    /// `R·e^(iθ(t))`: the increment is `iωR·(e^(iθ1) − E·e^(iθ0))/(K + iω)`,
    /// the other axes as on a line), and in steps of at most 0.02 rad of
    /// the sweep (at most 256 per phase), each at the tangent of its
    /// middle, while it changes.
    #[inline(never)]
    fn track_lag_seg(&mut self, g: &Geom, u_line: &Pos, trap: &Trap) {
        let Geom::Arc {
            p0,
            p1,
            plane,
            th0,
            sweep,
            r0,
            r1,
            ..
        } = *g
        else {
            return self.track_lag(u_line, trap);
        };
        let k = self.gain;
        let len = trap.len.max(1e-300);
        let (a1, a2, _) = plane.axes();
        let mut t0 = 0.0;
        for (v0, a, dt) in [
            (trap.v0, trap.a, trap.ta),
            (trap.vp, 0.0, trap.tc),
            (trap.vp, -trap.a, trap.td),
        ] {
            if dt > 0.0 {
                let s0 = trap.s_at(t0);
                let ds = trap.s_at(t0 + dt) - s0;
                if a == 0.0 {
                    let (e, inc) = lag_phase(k, v0, 0.0, dt);
                    for i in 0..NAXES {
                        if i != a1 && i != a2 {
                            self.lag[i] = self.lag[i] * e + (p1[i] - p0[i]) / len * inc;
                        }
                    }
                    let th_a = th0 + sweep * s0 / len;
                    let omega = v0 * sweep / len;
                    let r = r0 + (r1 - r0) * (s0 + 0.5 * ds) / len;
                    let (sa, ca) = th_a.sin_cos();
                    let (sb, cb) = (th_a + omega * dt).sin_cos();
                    let (nx, ny) = (cb - e * ca, sb - e * sa);
                    let (wx, wy) = (-omega * r * ny, omega * r * nx);
                    let d = k * k + omega * omega;
                    self.lag[a1] = self.lag[a1] * e + (wx * k + wy * omega) / d;
                    self.lag[a2] = self.lag[a2] * e + (wy * k - wx * omega) / d;
                } else {
                    let n = (sweep.abs() * ds / len / 0.02).ceil().clamp(1.0, 256.0);
                    let h = dt / n;
                    let (e, _) = lag_phase(k, 0.0, 0.0, h);
                    for j in 0..n as usize {
                        let tj = j as f64 * h;
                        let u = g.tangent(trap.s_at(t0 + tj + 0.5 * h) / len);
                        let (_, inc) = lag_phase(k, v0 + a * tj, a, h);
                        for i in 0..NAXES {
                            self.lag[i] = self.lag[i] * e + u[i] * inc;
                        }
                    }
                }
            }
            t0 += dt;
        }
    }

    /// In-position wait at a stop, s: when the smoothed command arrives,
    /// each loop's error is `lag_c·|lag_i|`; it then decays as
    /// `e^(−K·t)` until inside the axis's in-position width. The loops
    /// are taken as settled afterwards.
    fn settle(&mut self) -> f64 {
        if !self.gain.is_finite() {
            return 0.0;
        }
        let mut w: f64 = 0.0;
        for i in 0..NAXES {
            let width = self.d.in_position[i];
            let e = self.lag_c * self.lag[i].abs();
            if self.d.present[i] && width > 0.0 && e > width {
                w = w.max((e / width).ln() / self.gain);
            }
        }
        self.lag = [0.0; NAXES];
        if w.is_finite() {
            w
        } else {
            0.0
        }
    }

    fn done(&mut self, t_end: f64, time: f64) {
        let id = self.next_id;
        self.next_id += 1;
        self.done.push_back(Done { id, t_end, time });
    }

    /// Accounts for one event.
    pub fn push(&mut self, e: &Event) {
        if let Some(m) = e.motion() {
            // The start's work X in the move's own work system (a rapid,
            // G50/G92 X or a new work offset since the last cutting move
            // changes it): for constant surface speed.
            let x = self.pos[0] + (m.to[0] - m.mto[0]);
            if x.is_finite() {
                self.work_x = x;
            }
        }
        match &e.cmd {
            Canon::Rapid { m, linear } => {
                self.flush();
                self.rapid(m.mto, *linear);
            }
            Canon::Feed { m, feed } => {
                let g = Geom::Line {
                    p0: self.pos,
                    p1: m.mto,
                };
                let off = comp_offset(m, e.prog.as_deref());
                let len = g.len();
                let r = (self.work_x, m.to[0]);
                let surface = self.rotary.programmed_len(&self.pos, &m.mto, r.0, r.1);
                let surface = surface.unwrap_or(len);
                let ratio = if surface > 0.0 { len / surface } else { 1.0 };
                self.cut(g, *feed, m.to[0], false, off, ratio);
                self.feed_length += surface - len;
            }
            Canon::Arc {
                m,
                center,
                mcenter,
                plane,
                dir,
                turns,
                feed,
            } => {
                let g = Geom::arc(self.pos, m.mto, *mcenter, *plane, *dir, *turns);
                let off = comp_offset(m, e.prog.as_deref());
                let ratio = self.internal_arc_ratio(&m.to, center, *plane, e.prog.as_deref());
                self.cut(g, *feed, m.to[0], false, off, ratio);
            }
            Canon::Thread { m, lead } => {
                let g = Geom::Line {
                    p0: self.pos,
                    p1: m.mto,
                };
                // Spindle-synchronised: lead × rpm, no override, stop at the end.
                let v = lead * self.rpm;
                self.cut(g, Feed::PerMin(v), m.to[0], true, [0.0; 3], 1.0);
            }
            Canon::Dwell {
                seconds,
                revolutions,
            } => {
                self.flush();
                let mut t = seconds.max(0.0);
                if *revolutions > 0.0 && self.rpm > 0.0 {
                    t += revolutions / self.rpm * 60.0;
                }
                self.hold(t);
                self.time.dwell += t;
                self.done(self.now, t);
            }
            Canon::Spindle { dir, rpm, css }
                if css.is_some()
                    && *css == self.css
                    && *dir == self.spindle_dir
                    && *dir != SpindleDir::Stop =>
            {
                // G96 following X (the interpreter's speed for the next
                // move's end point): the spindle follows along the moves
                // (docs/motion.md), no stop, no ramp, no handshake.
                self.rpm = *rpm;
            }
            Canon::Spindle { dir, rpm, css } => {
                self.flush();
                self.spindle_dir = *dir;
                let new = if *dir == SpindleDir::Stop { 0.0 } else { *rpm };
                let t = (new - self.rpm).abs() / self.d.spindle_accel + self.d.aux_time_s;
                self.rpm = new;
                self.css = *css;
                self.hold(t);
                self.time.other += t;
            }
            Canon::Tool { change, .. } => {
                self.flush();
                if *change {
                    let t = self.d.tool_change_s;
                    self.hold(t);
                    self.time.tool_change += t;
                }
            }
            Canon::Coolant { .. } | Canon::Aux { .. } | Canon::Stop { .. } => {
                self.flush();
                let t = self.d.aux_time_s;
                self.hold(t);
                self.time.other += t;
            }
            Canon::End { .. } => self.flush(),
            Canon::Mode(ModeChange::ExactStopBlock)
                if self.last_cut == Some(e.src) && !self.q.is_empty() =>
            {
                // G09 after its block's motion: stop at its end.
                self.flush();
            }
            Canon::Mode(mc) => self.mode(*mc),
            Canon::Message(_) => {}
        }
        match &e.cmd {
            Canon::Feed { .. } | Canon::Arc { .. } | Canon::Thread { .. } => {
                self.last_cut = Some(e.src)
            }
            Canon::Mode(_) | Canon::Message(_) => {}
            _ => self.last_cut = None,
        }
    }

    fn mode(&mut self, mc: ModeChange) {
        match mc {
            ModeChange::ExactStopBlock => self.g09 = true,
            ModeChange::ExactStopMode(on) => {
                self.exact_mode = on;
                if on {
                    self.tapping = false;
                    self.corner_mode = false;
                }
            }
            ModeChange::CuttingMode => {
                self.exact_mode = false;
                self.tapping = false;
                self.corner_mode = false;
            }
            ModeChange::CornerOverride => {
                self.exact_mode = false;
                self.tapping = false;
                self.corner_mode = true;
            }
            ModeChange::TappingMode => {
                self.exact_mode = false;
                self.tapping = true;
                self.corner_mode = false;
            }
            ModeChange::HighSpeed(on) => {
                self.high_speed = on;
                self.window = if on {
                    self.d.lookahead_high_speed
                } else {
                    self.d.lookahead
                }
                .max(1);
                while self.q.len() > self.window {
                    self.finalize_head();
                }
            }
            ModeChange::Rotary(r) => self.rotary = r,
            ModeChange::Stitch(_) => {}
            ModeChange::FeedOverride(on) => self.ignore_override = !on,
            ModeChange::SpindleClamp(rpm) => {
                self.s_clamp = if rpm.is_nan() { f64::INFINITY } else { rpm };
            }
        }
    }

    fn rapid(&mut self, to: Pos, linear: bool) {
        let p0 = self.pos;
        self.rapid_length += line_len(&p0, &to);
        let ovr = self.d.rapid_override;
        let lag = self.gain.is_finite();
        let dur = if linear {
            let g = Geom::Line { p0, p1: to };
            let len = g.len();
            let u = g.tangent(0.0);
            let (mut v, mut a) = (f64::INFINITY, f64::INFINITY);
            for i in 0..NAXES {
                if u[i].abs() > 1e-12 {
                    v = v.min(self.d.rapid[i] / 60.0 * ovr / u[i].abs());
                    a = a.min(self.d.rapid_accel[i] / u[i].abs());
                }
            }
            let trap = if v.is_finite() && a.is_finite() {
                Trap::plan(len, 0.0, 0.0, v, a)
            } else {
                Trap::default()
            };
            let dur = trap.time();
            if lag && dur > 0.0 {
                // Servo lag behind the positioning (from a settled start).
                self.lag = [0.0; NAXES];
                self.track_lag(&u, &trap);
            }
            if let Some(p) = self.pieces.as_mut() {
                let kind = PieceKind::Move { geom: g, trap };
                p.push_back(Piece { t0: self.now, kind });
            }
            dur
        } else {
            let mut traps = [Trap::default(); NAXES];
            for i in 0..NAXES {
                let d = (to[i] - p0[i]).abs();
                if d > 0.0 && self.d.rapid[i] > 0.0 {
                    traps[i] = Trap::plan(
                        d,
                        0.0,
                        0.0,
                        self.d.rapid[i] / 60.0 * ovr,
                        self.d.rapid_accel[i],
                    );
                }
            }
            let dur = traps.iter().map(|t| t.time()).fold(0.0, f64::max);
            if lag && dur > 0.0 {
                self.lag_axes(&p0, &to, &traps, dur);
            }
            if let Some(p) = self.pieces.as_mut() {
                let kind = PieceKind::Axes {
                    p0,
                    p1: to,
                    traps: Box::new(traps),
                };
                p.push_back(Piece { t0: self.now, kind });
            }
            dur
        };
        self.now += dur;
        self.pos = to;
        let drain = if dur > 0.0 {
            self.drain_time() + self.settle()
        } else {
            0.0
        };
        self.hold(drain);
        self.time.rapid += dur + drain;
        self.done(self.now, dur + drain);
    }

    /// Servo lag behind a non-linear positioning of `dur` s: each axis
    /// from a settled start along its own trapezoid, then at rest until
    /// the slowest axis arrives. An axis that does not move ends with no
    /// lag (what the loop below gives it, without its `exp_m1`).
    fn lag_axes(&mut self, p0: &Pos, p1: &Pos, traps: &[Trap; NAXES], dur: f64) {
        for i in 0..NAXES {
            let ti = traps[i].time();
            if ti == 0.0 {
                self.lag[i] = 0.0;
                continue;
            }
            let sign = if p1[i] >= p0[i] { 1.0 } else { -1.0 };
            // `track_lag` of the unit vector along axis i from zero lag,
            // for axis i alone: the other axes' results were thrown away.
            let li = self.track_lag_axis(sign, &traps[i]);
            let (e, _) = self.memo.get(0.0, 0.0, dur - ti);
            self.lag[i] = li * e;
        }
    }

    /// Speed and acceleration limits of a path along `g`, mm/s and mm/s².
    fn limits(&self, g: &Geom, u: &Pos, feed: f64) -> (f64, f64) {
        let mut v = feed / 60.0;
        let mut a = f64::INFINITY;
        let d = &self.d;
        match g.radius() {
            None => {
                for i in 0..NAXES {
                    let ui = u[i].abs();
                    if ui > 1e-12 {
                        v = lower(v, d.rapid[i] / 60.0 / ui);
                        a = lower(a, 0.5 * d.accel[i] / ui);
                    }
                }
            }
            Some(r) => {
                let (p0, p1) = (g.start(), g.end());
                let (a1, a2) = match g {
                    Geom::Arc { plane, .. } => {
                        let (a1, a2, _) = plane.axes();
                        (a1, a2)
                    }
                    _ => (0, 1),
                };
                let (mut amin, mut jmin) = (f64::INFINITY, f64::INFINITY);
                for i in 0..NAXES {
                    if (i == a1 || i == a2 || (p1[i] - p0[i]).abs() > 0.0) && d.present[i] {
                        {
                            v = v.min(d.rapid[i] / 60.0);
                            amin = amin.min(d.accel[i]);
                            jmin = jmin.min(d.jerk[i]);
                        }
                    }
                }
                if amin.is_finite() {
                    a = 0.5 * amin;
                    let r = r.max(1e-9);
                    // Centripetal acceleration and jerk within half the
                    // axis limits; radial error of the smoothing within
                    // the path tolerance.
                    v = v.min((0.5 * amin * r).sqrt());
                    v = v.min((0.5 * jmin * r * r).cbrt());
                    if self.t_smooth > 0.0 {
                        v = v.min((24.0 * r * d.path_tolerance / self.k_tt).sqrt());
                    }
                }
            }
        }
        (v, a)
    }

    /// Junction speed limit between the end of `p` and the start of `n`;
    /// `None` when the corner needs an exact stop (the smoothing would
    /// leave the path tolerance even at zero speed).
    #[inline(always)]
    fn junction(&self, p: &Seg, n: &Seg) -> Option<f64> {
        let mut v = p.vmax.min(n.vmax);
        let (u1, u2) = (&p.t_out, &n.t_in);
        let n1 = dot(u1, u1).sqrt();
        let n2 = dot(u2, u2).sqrt();
        if n1 <= 0.0 || n2 <= 0.0 {
            return None;
        }
        let t = self.t_smooth;
        let lmin = p.len.min(n.len);
        for i in 0..NAXES {
            let du = (u2[i] - u1[i]).abs();
            if du > 1e-9 {
                let a = 0.5 * self.d.accel[i];
                v = lower(lower(v, a * t / du), (a * lmin / du).sqrt());
            }
        }
        let c = (dot(u1, u2) / (n1 * n2)).clamp(-1.0, 1.0);
        // Distance from the corner to the rounded path per unit of the
        // kernel's offset: |u2 − u1| = 2·sin(θ/2).
        let s = (2.0 * (1.0 - c)).max(0.0).sqrt();
        // Corner rounding of the smoothing kernel: the first and second
        // moments of its positive half, times the speed and the
        // acceleration on either side.
        let (m1, m2) = (self.m1, self.m2);
        if s > 1e-9 && m1 > 0.0 {
            let room = self.d.path_tolerance / s - m2 * p.acc.max(n.acc);
            if room <= 0.0 {
                return None;
            }
            v = lower(v, room / m1);
        }
        // The smoothing's radial error on the turn as an arc of radius
        // lmin/θ; the `acos` is skipped when even the largest angle the
        // chord allows would not lower v (the same v: each step below is
        // monotonic in θ).
        let th_max = turn_bound(s);
        if th_max > 1e-9 && t > 0.0 {
            let tol = self.d.path_tolerance;
            let floor = (24.0 * (lmin / th_max) * tol / self.k_tt).sqrt();
            // Unless v ≤ floor (a NaN takes the full path, as before).
            if !matches!(
                v.partial_cmp(&floor),
                Some(Ordering::Less | Ordering::Equal)
            ) {
                let th = c.acos();
                if th > 1e-9 {
                    let r = lmin / th;
                    v = lower(v, (24.0 * r * tol / self.k_tt).sqrt());
                }
            }
        }
        Some(v.max(0.0))
    }

    /// Internal circular cutting feed change (000 §5.3.6): on an arc
    /// whose tool centre radius `Rc` is smaller than the programmed
    /// radius `Rp` (the compensated tool inside the arc), the feed is
    /// scaled by `Rc/Rp`, not below the lower limit (PI 132).
    fn internal_arc_ratio(&self, to: &Pos, center: &Pos, plane: Plane, prog: Option<&Pos>) -> f64 {
        let (Some(min), Some(pp)) = (self.d.internal_arc_min, prog) else {
            return 1.0;
        };
        let (a1, a2, _) = plane.axes();
        let rc = (to[a1] - center[a1]).hypot(to[a2] - center[a2]);
        let rp = (pp[a1] - center[a1]).hypot(pp[a2] - center[a2]);
        if rp > 0.0 && rc < rp {
            (rc / rp).max(min)
        } else {
            1.0
        }
    }

    /// G62 (or PI 131 always): the junction from the last queued segment
    /// into `n` is an inside corner of the compensated path whose angle
    /// is from 2° up to PI 130. Inside: the tool centre's corner lies
    /// towards the turn from the programmed corner
    /// (`off · (u2 − u1) > 0`, `off` = tool centre − programmed point).
    fn inside_corner(&self, u2: &Pos) -> bool {
        if !(self.corner_mode || (self.d.corner.always && !self.tapping)) {
            return false;
        }
        let Some(p) = self.q.back() else {
            return false;
        };
        let off = &self.last_off;
        let on = off[0].hypot(off[1]).hypot(off[2]);
        if p.stop || on <= 0.0 {
            return false;
        }
        let u1 = &p.t_out;
        let (n1, n2) = (dot(u1, u1).sqrt(), dot(u2, u2).sqrt());
        if n1 <= 0.0 || n2 <= 0.0 {
            return false;
        }
        let c = (dot(u1, u2) / (n1 * n2)).clamp(-1.0, 1.0);
        let angle = 180.0 - c.acos().to_degrees();
        if !(2.0..=self.d.corner.angle_deg).contains(&angle) {
            return false;
        }
        let inward: f64 = (0..3).map(|i| off[i] * (u2[i] / n2 - u1[i] / n1)).sum();
        inward > 1e-9 * on
    }

    /// G62 before the corner: the last `before` mm of the last queued
    /// segment run at the overridden feed.
    fn override_before(&mut self) {
        let (f, ls) = (self.d.corner.factor, self.d.corner.before);
        if ls <= 0.0 {
            return;
        }
        let Some(mut p) = self.q.pop_back() else {
            return;
        };
        self.q_tmin -= p.len / p.vmax;
        let red = p.vmax.min(self.last_feed * f).max(1e-6);
        if ls >= p.len {
            p.vmax = red;
            p.jmax = p.jmax.min(red);
            p.vb = p.jmax.min((2.0 * p.acc * p.len).sqrt());
            self.q_tmin += p.len / red;
            self.q.push_back(p);
        } else {
            let (mut h, mut t) = split(&p, (p.len - ls) / p.len);
            t.vmax = red;
            t.jmax = t.jmax.min(red);
            t.vb = t.jmax.min((2.0 * t.acc * t.len).sqrt());
            // Recomputed by the backward pass below.
            h.vb = -1.0;
            self.q_tmin += h.len / h.vmax + t.len / t.vmax;
            self.q.push_back(h);
            self.q.push_back(t);
        }
        self.backward();
    }

    /// Pushes the move after a G62 inside corner: the end of the one
    /// before and its own start at the overridden feed.
    #[cold]
    #[inline(never)]
    fn push_overridden(&mut self, seg: &Seg, feed: f64) {
        let seg = *seg;
        self.override_before();
        let (f, le) = (self.d.corner.factor, self.d.corner.after);
        let red = seg.vmax.min(feed * f).max(1e-6);
        if le >= seg.len {
            self.push_seg(Seg { vmax: red, ..seg });
        } else if le > 0.0 {
            let (mut h, t) = split(&seg, le / seg.len);
            h.vmax = red;
            self.push_seg(h);
            self.push_seg(t);
        } else {
            self.push_seg(seg);
        }
    }

    fn cut(
        &mut self,
        g: Geom,
        feed: Feed,
        to_work_x: f64,
        thread: bool,
        off: [f64; 3],
        ratio: f64,
    ) {
        let len = g.len();
        let from_x = self.work_x;
        self.work_x = to_work_x;
        self.feed_length += len;
        let id = self.next_id;
        self.next_id += 1;
        let stop = thread || self.g09 || self.exact_mode || self.tapping;
        self.g09 = false;
        self.pos = g.end();
        if len <= 0.0 {
            self.flush();
            self.done.push_back(Done {
                id,
                t_end: self.now,
                time: 0.0,
            });
            return;
        }
        // Per-revolution feed with constant surface speed: the spindle
        // speed follows X along the move; split it so that each piece
        // runs at the speed of its middle.
        let pieces = match (feed, self.css, thread) {
            (Feed::PerRev(_), Some(_), false) if (to_work_x - from_x).abs() > 1e-9 => 16,
            _ => 1,
        };
        for k in 0..pieces {
            let (u0, u1) = (k as f64 / pieces as f64, (k + 1) as f64 / pieces as f64);
            let sub_owned;
            let sub: &Geom = if pieces == 1 {
                &g
            } else {
                sub_owned = g.sub(u0, u1);
                &sub_owned
            };
            let f = if thread {
                match feed {
                    Feed::PerMin(v) => v,
                    _ => 0.0,
                }
            } else if pieces > 1 {
                let xm = from_x + (to_work_x - from_x) * 0.5 * (u0 + u1);
                self.feed_css(feed, xm)
            } else {
                self.feed_mm_min(feed, len)
            };
            let f = if thread { f } else { f * ratio };
            let slen = if pieces == 1 { len } else { sub.len() };
            if f.is_nan() || f <= 0.0 {
                // Per-revolution feed or thread with the spindle stopped:
                // the control would wait for ever; counted and timed as 0.
                self.stalled += 1;
                self.pos = g.end();
                if k + 1 == pieces {
                    self.flush();
                    self.done.push_back(Done {
                        id,
                        t_end: self.now,
                        time: std::mem::take(&mut self.ev_spent),
                    });
                }
                continue;
            }
            let (t_in, t_out) = match *sub {
                Geom::Line { p0, p1 } => {
                    let mut u = [0.0; NAXES];
                    if slen > 0.0 {
                        let inv = 1.0 / slen;
                        for i in 0..NAXES {
                            u[i] = (p1[i] - p0[i]) * inv;
                        }
                    }
                    (u, u)
                }
                Geom::Arc { .. } => (sub.tangent(0.0), sub.tangent(1.0)),
            };
            let f = f.min(if thread {
                f64::INFINITY
            } else {
                self.d.max_feed
            });
            let (vmax, acc) = self.limits(sub, &t_in, f);
            let corner =
                k == 0 && (self.corner_mode || self.d.corner.always) && self.inside_corner(&t_in);
            let seg = Seg {
                id,
                last: k + 1 == pieces,
                geom: *sub,
                len: slen,
                vmax: vmax.max(1e-6),
                acc: if acc.is_finite() { acc } else { 1.0 },
                jmax: 0.0,
                vb: 0.0,
                stop: stop && k + 1 == pieces,
                t_in,
                t_out,
            };
            if corner {
                self.push_overridden(&seg, f / 60.0);
            } else {
                self.push_seg(seg);
            }
            self.last_off = if k + 1 == pieces { off } else { [0.0; 3] };
            self.last_feed = f / 60.0;
        }
    }

    /// Per-rev feed at work X `x` under constant surface speed, mm/min.
    fn feed_css(&self, feed: Feed, x: f64) -> f64 {
        let (Feed::PerRev(f), Some(vc)) = (feed, self.css) else {
            return self.feed_mm_min(feed, 0.0);
        };
        let r = x.abs().max(1e-3);
        let rpm = (vc * 1000.0 / (std::f64::consts::TAU * r))
            .min(self.max_rpm)
            .min(self.s_clamp);
        let ovr = self.override_factor();
        let v = if self.d.dry_run {
            self.d.dry_run_feed
        } else {
            f * rpm
        };
        (v * ovr).min(self.d.max_feed)
    }

    #[inline(always)]
    fn push_seg(&mut self, mut s: Seg) {
        s.jmax = match self.q.back() {
            Some(p) if !p.stop => match self.junction(p, &s) {
                Some(v) => v,
                None => {
                    self.flush();
                    0.0
                }
            },
            _ => 0.0,
        };
        s.jmax = lower(s.jmax, s.vmax);
        s.vb = lower(s.jmax, (2.0 * s.acc * s.len).sqrt());
        let stop = s.stop;
        self.q_tmin += s.len / s.vmax;
        self.q.push_back(s);
        self.backward();
        if stop {
            self.flush();
        }
        while self.q.len() > self.window {
            self.finalize_head();
        }
    }

    /// Backward pass from the last queued segment: lower entry bounds to
    /// what can still brake to the next one's, until one does not change.
    fn backward(&mut self) {
        let n = self.q.len();
        for i in (0..n.saturating_sub(1)).rev() {
            let next_vb = self.q[i + 1].vb;
            let si = &mut self.q[i];
            let nb = lower(si.jmax, (next_vb * next_vb + 2.0 * si.acc * si.len).sqrt());
            if nb == si.vb {
                break;
            }
            si.vb = nb;
        }
    }

    /// Stops at the end of what is queued and plans all of it.
    fn flush(&mut self) {
        if let Some(b) = self.q.back_mut() {
            b.stop = true;
        }
        while !self.q.is_empty() {
            self.finalize_head();
        }
    }

    /// Plans the segment at the head of the queue and takes it out (read
    /// where it lies: a pop would first copy the whole segment out).
    fn finalize_head(&mut self) {
        let Some(h) = self.q.front() else { return };
        let (len, vmax, acc, stop) = (h.len, h.vmax, h.acc, h.stop);
        let (last, id) = (h.last, h.id);
        let next_vb = self.q.get(1).map(|n| n.vb);
        self.q_tmin = if next_vb.is_none() {
            0.0
        } else {
            self.q_tmin - len / vmax
        };
        let v0 = self.head_v;
        let v1 = if stop {
            0.0
        } else {
            match next_vb {
                Some(vb) => lower(vb, (v0 * v0 + 2.0 * acc * len).sqrt()),
                None => 0.0,
            }
        };
        let trap = Trap::plan(len, v0, v1, vmax, acc);
        self.head_v = if stop { 0.0 } else { trap.v1 };
        if self.gain.is_finite() {
            if self.q_tmin * self.gain >= 40.0 {
                // No stop can come within 40/K s: this segment's (and all
                // earlier) lag will have decayed by e^-40 before any stop.
                self.lag = [0.0; NAXES];
            } else {
                let (geom, t_in) = (self.q[0].geom, self.q[0].t_in);
                self.track_lag_seg(&geom, &t_in, &trap);
            }
        }
        let t0 = self.now;
        let dt = trap.time();
        if let Some(p) = self.pieces.as_mut() {
            p.push_back(Piece {
                t0,
                kind: PieceKind::Move {
                    geom: self.q[0].geom,
                    trap,
                },
            });
        }
        self.now += dt;
        let mut spent = dt;
        let t_end = if stop {
            let pos = self.pos;
            self.pos = self.q[0].geom.end();
            let drain = self.drain_time() + self.settle();
            self.hold(drain);
            self.pos = pos;
            spent += drain;
            self.now
        } else {
            self.now + 0.5 * self.drain_time()
        };
        self.q.pop_front();
        self.time.cutting += spent;
        self.ev_spent += spent;
        if last {
            self.done.push_back(Done {
                id,
                t_end,
                time: std::mem::take(&mut self.ev_spent),
            });
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use kerf_canon::{Motion, SrcRef};

    fn ev(cmd: Canon) -> Event {
        Event {
            src: SrcRef::default(),
            tool: 0,
            cmd,
            prog: None,
        }
    }

    fn feed_to(x: f64, y: f64) -> Event {
        let p = [x, y, 0.0, 0.0, 0.0, 0.0];
        ev(Canon::Feed {
            m: Motion { to: p, mto: p },
            feed: Feed::PerMin(1200.0),
        })
    }

    fn dynm() -> Dynamics {
        let mut d = Dynamics::uniform(
            [true, true, true, false, false, false],
            24000.0,
            2000.0,
            1e5,
            10000.0,
        );
        d.lookahead = 8;
        d.lookahead_high_speed = 100;
        d
    }

    /// The junction limit as it was before the `acos` could be skipped:
    /// the curvature term always computed.
    fn junction_always_acos(pl: &Planner, p: &Seg, n: &Seg) -> Option<f64> {
        let mut v = p.vmax.min(n.vmax);
        let (u1, u2) = (&p.t_out, &n.t_in);
        let (n1, n2) = (dot(u1, u1).sqrt(), dot(u2, u2).sqrt());
        if n1 <= 0.0 || n2 <= 0.0 {
            return None;
        }
        let t = pl.t_smooth;
        let lmin = p.len.min(n.len);
        for i in 0..NAXES {
            let du = (u2[i] - u1[i]).abs();
            if du > 1e-9 {
                let a = 0.5 * pl.d.accel[i];
                v = v.min(a * t / du).min((a * lmin / du).sqrt());
            }
        }
        let c = (dot(u1, u2) / (n1 * n2)).clamp(-1.0, 1.0);
        let s = (2.0 * (1.0 - c)).max(0.0).sqrt();
        let (m1, m2) = if pl.stages == 1 {
            (t / 8.0, t * t / 48.0)
        } else {
            (t / 6.0, t * t / 24.0)
        };
        if s > 1e-9 && m1 > 0.0 {
            let room = pl.d.path_tolerance / s - m2 * p.acc.max(n.acc);
            if room <= 0.0 {
                return None;
            }
            v = v.min(room / m1);
        }
        let th = c.acos();
        if th > 1e-9 && t > 0.0 {
            let r = lmin / th;
            let k = pl.stages as f64;
            v = v.min((24.0 * r * pl.d.path_tolerance / (k * t * t)).sqrt());
        }
        Some(v.max(0.0))
    }

    #[test]
    fn skipping_the_acos_gives_the_same_junction_speed_bit_for_bit() {
        // Pseudo-random tangents, lengths, speeds and tolerances (an LCG,
        // so the cases are the same every run), turns from 0 to 180°
        // with many small ones, against the limit with the acos always
        // computed.
        let mut x: u64 = 0x2545_f491_4f6c_dd1d;
        let mut rnd = move || {
            x = x
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (x >> 11) as f64 / (1u64 << 53) as f64
        };
        let (mut skipped, mut bound) = (0, 0);
        for case in 0..200_000 {
            let mut d = dynm();
            d.path_tolerance = [0.001, 0.01, 0.1][case % 3];
            let pl = Planner::new(d, [0.0; NAXES], 0.0);
            let tilt = if case % 2 == 0 { 1e-3 } else { 1.0 };
            // A unit vector: `base` plus a random step of up to `amp`.
            let dir = |r: &mut dyn FnMut() -> f64, base: Pos, amp: f64| -> Pos {
                let mut u = base;
                for ui in u.iter_mut().take(3) {
                    *ui += (r() - 0.5) * amp;
                }
                let n = dot(&u, &u).sqrt();
                u.map(|c| c / n)
            };
            let u1 = dir(&mut rnd, [1.0, 0.0, 0.0, 0.0, 0.0, 0.0], 2.0);
            let u2 = dir(&mut rnd, u1, tilt * 4.0);
            let seg = |u: Pos, len: f64, vmax: f64| Seg {
                id: 0,
                last: true,
                geom: Geom::Line {
                    p0: [0.0; NAXES],
                    p1: u.map(|c| c * len),
                },
                len,
                vmax,
                acc: 1000.0,
                jmax: 0.0,
                vb: 0.0,
                stop: false,
                t_in: u,
                t_out: u,
            };
            let p = seg(u1, 0.01 + rnd() * 5.0, 1.0 + rnd() * 400.0);
            let n = seg(u2, 0.01 + rnd() * 5.0, 1.0 + rnd() * 400.0);
            let got = pl.junction(&p, &n).map(f64::to_bits);
            let want = junction_always_acos(&pl, &p, &n).map(f64::to_bits);
            assert_eq!(got, want, "case {case}");
            // How often the skip applies, and how often the curvature
            // term is what limits the speed.
            let c = dot(&u1, &u2).clamp(-1.0, 1.0);
            let s = (2.0 * (1.0 - c)).max(0.0).sqrt();
            let lmin = p.len.min(n.len);
            let k_tt = pl.k_tt;
            let floor = (24.0 * (lmin / turn_bound(s)) * pl.d.path_tolerance / k_tt).sqrt();
            if want.is_some_and(|w| f64::from_bits(w) <= floor) {
                skipped += 1;
            }
            let curv = (24.0 * (lmin / c.acos()) * pl.d.path_tolerance / k_tt).sqrt();
            if want.is_some_and(|w| f64::from_bits(w) == curv) {
                bound += 1;
            }
        }
        // Both paths are taken many times.
        assert!(skipped > 1000 && bound > 1000, "{skipped} {bound}");
    }

    #[test]
    fn one_axis_lag_equals_that_axis_of_the_full_lag_bit_for_bit() {
        // Trapezoids of rapids (with and without cruise, from lengths of
        // 0.001 to 500 mm), each axis and sign, against `track_lag` of
        // the unit vector from zero lag on a fresh planner (the same
        // memo state on both sides).
        let mut d = dynm();
        d.position_gain = 30.0;
        let mut cases = 0;
        for (n, len) in [0.001, 0.3, 2.0, 47.5, 500.0].into_iter().enumerate() {
            let trap = Trap::plan(len, 0.0, 0.0, 400.0 + n as f64, 2500.0);
            for i in 0..NAXES {
                for sign in [1.0, -1.0] {
                    let mut a = Planner::new(d.clone(), [0.0; NAXES], 0.0);
                    let mut b = Planner::new(d.clone(), [0.0; NAXES], 0.0);
                    let mut u = [0.0; NAXES];
                    u[i] = sign;
                    a.track_lag(&u, &trap);
                    let got = b.track_lag_axis(sign, &trap);
                    assert_eq!(got.to_bits(), a.lag[i].to_bits(), "{len} {i} {sign}");
                    assert!(got != 0.0 && got.signum() == sign);
                    cases += 1;
                }
            }
        }
        assert_eq!(cases, 60);
    }

    /// A gentle zig-zag (±0.5°) that never needs a stop.
    fn zigzag(pl: &mut Planner, n: usize) {
        for k in 1..=n {
            let y = if k.is_multiple_of(2) { 0.0 } else { 0.05 };
            pl.push(&feed_to(k as f64 * 5.0, y));
        }
    }

    /// G112 (000 §4.6): F is the speed in the face's Cartesian plane. At
    /// X20 C0, the virtual point (20, 10) is X √500, C 26.565°: 10 mm on
    /// the face, 1 s at F600 (plus the ramps), though X moves 2.36 mm.
    /// After G113 the same move back is timed by its linear axes.
    #[test]
    fn g112_feed_is_a_speed_on_the_face() {
        let d = Dynamics::uniform([true; NAXES], 24000.0, 2000.0, 1e5, 10000.0);
        let start = [20.0, 0.0, 0.0, 0.0, 0.0, 0.0];
        let mut pl = Planner::new(d.clone(), start, 20.0);
        let mv = |x: f64, c: f64| {
            let p = [x, 0.0, 0.0, 0.0, 0.0, c];
            ev(Canon::Feed {
                m: Motion { to: p, mto: p },
                feed: Feed::PerMin(600.0),
            })
        };
        let r1 = 500f64.sqrt();
        pl.push(&ev(Canon::Mode(ModeChange::Rotary(RotaryMode::Polar))));
        pl.push(&mv(r1, 26.565_051_177));
        pl.push(&ev(Canon::Mode(ModeChange::Rotary(RotaryMode::Off))));
        pl.push(&mv(20.0, 0.0));
        pl.finish();
        let back = r1 - 20.0;
        assert!(
            (pl.feed_length - 10.0 - back).abs() < 1e-6,
            "{}",
            pl.feed_length
        );
        let t0 = pl.next_done().unwrap().time;
        let t1 = pl.next_done().unwrap().time;
        // The same stop after a plain 10 mm line in X: the ramps and the
        // settling are the line's, so the two take the same time.
        let mut line = Planner::new(d, start, 20.0);
        line.push(&mv(30.0, 0.0));
        line.push(&ev(Canon::Mode(ModeChange::Rotary(RotaryMode::Off))));
        line.finish();
        let t_line = line.next_done().unwrap().time;
        assert!(
            t_line > 1.0 && (t0 - t_line).abs() < 0.02 * t_line,
            "{t0} vs {t_line}"
        );
        assert!(t1 > back / 10.0 && t1 < t_line, "{t1}");
    }

    /// G107 on a cylinder of radius 10: Z20 C180 is sqrt(20² + (10·π)²)
    /// = 37.242 mm on the developed surface, 3.724 s at F600 mm/min (plus
    /// the ramps). After G107 C0 the same move back is timed as the
    /// control times a linear-and-rotary move, by its linear axes: 20 mm,
    /// 2 s.
    #[test]
    fn g107_feed_is_a_speed_on_the_cylinder_surface() {
        let d = Dynamics::uniform([true; NAXES], 24000.0, 2000.0, 1e5, 10000.0);
        let mut pl = Planner::new(d, [0.0; NAXES], 0.0);
        let mv = |z: f64, c: f64| {
            let p = [0.0, 0.0, z, 0.0, 0.0, c];
            ev(Canon::Feed {
                m: Motion { to: p, mto: p },
                feed: Feed::PerMin(600.0),
            })
        };
        pl.push(&ev(Canon::Mode(ModeChange::Rotary(
            kerf_canon::RotaryMode::Cylinder {
                radius: 10.0,
                plane: Plane::ZX,
            },
        ))));
        pl.push(&mv(20.0, 180.0));
        pl.push(&ev(Canon::Mode(ModeChange::Rotary(
            kerf_canon::RotaryMode::Off,
        ))));
        pl.push(&mv(0.0, 0.0));
        pl.finish();
        let surface = (400.0 + (10.0 * std::f64::consts::PI).powi(2)).sqrt();
        let machine = 20.0;
        assert!(
            (pl.feed_length - surface - machine).abs() < 1e-9,
            "{} vs {surface} + {machine}",
            pl.feed_length
        );
        let t0 = pl.next_done().unwrap().time;
        // The ramps and the settling add a few per cent (C's 2000°/s²
        // limits the path acceleration along a move this steep in C).
        assert!(t0 > surface / 10.0 && t0 < surface / 10.0 * 1.05, "{t0}");
        let t1 = pl.next_done().unwrap().time;
        assert!(t1 > machine / 10.0 && t1 < machine / 10.0 * 1.1, "{t1}");
    }

    #[test]
    fn record_times_sum_to_the_breakdown() {
        let mut pl = Planner::new(dynm(), [0.0; NAXES], 0.0);
        let p = [0.0, 50.0, 0.0, 0.0, 0.0, 0.0];
        pl.push(&ev(Canon::Rapid {
            m: Motion { to: p, mto: p },
            linear: true,
        }));
        // 100 mm at 1200 mm/min from rest to rest: 5 s at 20 mm/s plus
        // v/a = 0.01 s for the two ramps, before settling.
        pl.push(&feed_to(100.0, 50.0));
        pl.push(&ev(Canon::Dwell {
            seconds: 1.5,
            revolutions: 0.0,
        }));
        zigzag(&mut pl, 30);
        pl.finish();
        let mut done = Vec::new();
        while let Some(d) = pl.next_done() {
            done.push(d);
        }
        assert_eq!(done.len(), 33);
        assert!((done[0].time - pl.time.rapid).abs() < 1e-12);
        assert!(done[1].time >= 5.01 - 1e-9, "{}", done[1].time);
        assert_eq!(done[2].time, 1.5);
        let cut: f64 = done[1].time + done[3..].iter().map(|d| d.time).sum::<f64>();
        assert!(
            (cut - pl.time.cutting).abs() < 1e-9,
            "{cut} vs {}",
            pl.time.cutting
        );
    }

    #[test]
    fn window_bounds_the_queue_and_g10_3_widens_it() {
        let mut pl = Planner::new(dynm(), [0.0; NAXES], 0.0);
        let mut most = 0;
        for k in 1..=200u32 {
            pl.push(&feed_to(
                k as f64 * 5.0,
                if k.is_multiple_of(2) { 0.0 } else { 0.05 },
            ));
            most = most.max(pl.queued());
        }
        assert_eq!(most, 8);
        pl.push(&ev(Canon::Mode(ModeChange::HighSpeed(true))));
        for k in 201..=400u32 {
            pl.push(&feed_to(
                k as f64 * 5.0,
                if k.is_multiple_of(2) { 0.0 } else { 0.05 },
            ));
            most = most.max(pl.queued());
        }
        assert_eq!(most, 100);
        pl.push(&ev(Canon::Mode(ModeChange::HighSpeed(false))));
        assert_eq!(pl.queued(), 8);
        pl.finish();
        assert_eq!(pl.queued(), 0);
        let mut n = 0;
        let mut last = 0.0;
        while let Some(d) = pl.next_done() {
            assert_eq!(d.id, n);
            assert!(d.t_end >= last);
            last = d.t_end;
            n += 1;
        }
        assert_eq!(n, 400);
        // The last record ends at rest: its t_end is the cycle time.
        assert!((last - pl.now()).abs() < 1e-9);
    }

    #[test]
    fn a_longer_window_is_never_slower() {
        let mut short = dynm();
        short.lookahead = 1;
        let mut a = Planner::new(short, [0.0; NAXES], 0.0);
        let mut b = Planner::new(dynm(), [0.0; NAXES], 0.0);
        zigzag(&mut a, 100);
        zigzag(&mut b, 100);
        a.finish();
        b.finish();
        assert!(b.now() <= a.now() + 1e-9, "{} vs {}", b.now(), a.now());
        // 500 mm at 20 mm/s is 25 s; both add only ramps and one stop.
        assert!(b.now() > 25.0 && b.now() < 25.2, "{}", b.now());
    }

    #[test]
    fn degenerate_input_takes_no_time_and_does_not_hang() {
        let mut pl = Planner::new(dynm(), [0.0; NAXES], 0.0);
        for _ in 0..1000 {
            pl.push(&feed_to(0.0, 0.0));
        }
        pl.push(&ev(Canon::Dwell {
            seconds: 0.0,
            revolutions: 5.0,
        }));
        pl.push(&ev(Canon::Thread {
            m: Motion {
                to: [0.0, 0.0, -5.0, 0.0, 0.0, 0.0],
                mto: [0.0, 0.0, -5.0, 0.0, 0.0, 0.0],
            },
            lead: 1.0,
        }));
        pl.finish();
        assert_eq!(pl.now(), 0.0);
        assert_eq!(pl.stalled, 1);
        let mut n = 0;
        while pl.next_done().is_some() {
            n += 1;
        }
        assert_eq!(n, 1002);
    }

    #[test]
    fn validation_names_the_parameter() {
        let mut d = dynm();
        d.jerk[1] = 0.0;
        let e = d.validate().unwrap_err();
        assert!(e.names("motion.axes.y.jerk"), "{e}");
        assert_eq!(
            e.to_string(),
            "profile parameter motion.axes.y.jerk must be a number > 0 (is 0)"
        );
        let mut d = dynm();
        d.path_tolerance = -1.0;
        assert!(d.validate().unwrap_err().names("motion.path_tolerance_mm"));
        let mut d = dynm();
        d.rapid[0] = f64::NAN;
        assert!(d.validate().unwrap_err().names("axes.x.rapid"));
        assert!(dynm().validate().is_ok());
        let mut d = dynm();
        d.corner.angle_deg = 1.0;
        assert!(d
            .validate()
            .unwrap_err()
            .names("motion.corner_override_angle_deg"));
        let mut d = dynm();
        d.corner.factor = 0.0;
        assert!(d
            .validate()
            .unwrap_err()
            .names("motion.corner_override_pct"));
        let mut d = dynm();
        d.internal_arc_min = Some(0.0);
        assert!(d
            .validate()
            .unwrap_err()
            .names("motion.internal_arc_min_pct"));
        let mut d = dynm();
        d.position_gain = f64::NAN;
        assert!(d.validate().unwrap_err().names("motion.position_gain"));
        d.position_gain = -1.0;
        assert!(d.validate().unwrap_err().names("motion.position_gain"));
        // An ideal servo is allowed.
        d.position_gain = f64::INFINITY;
        assert!(d.validate().is_ok());
    }

    #[test]
    fn overrides_and_dry_run_change_the_feed() {
        let mut d = dynm();
        d.feed_override = 0.5;
        let mut pl = Planner::new(d.clone(), [0.0; NAXES], 0.0);
        assert_eq!(pl.feed_mm_min(Feed::PerMin(1200.0), 1.0), 600.0);
        pl.push(&ev(Canon::Mode(ModeChange::TappingMode)));
        assert_eq!(pl.feed_mm_min(Feed::PerMin(1200.0), 1.0), 1200.0);
        d.dry_run = true;
        d.dry_run_feed = 3000.0;
        let pl = Planner::new(d, [0.0; NAXES], 0.0);
        assert_eq!(pl.feed_mm_min(Feed::PerMin(1200.0), 1.0), 1500.0);
    }

    fn at_line(mut e: Event, line: u32) -> Event {
        e.src.line = line;
        e
    }

    #[test]
    fn g09_before_or_after_its_motion_stops_that_motion() {
        // Two 20 mm moves along X at 20 mm/s (path acceleration 1000):
        // straight on, one trapezoid 40/20 + 20/1000 = 2.02 s plus one stop
        // 2T (T = 2·2000/1e5 = 0.04): 2.1 s. With G09 on the first block
        // (HX order: the mode before the motion; Hurco, 002 Table 1: after
        // it) two trapezoids: 2·(1.0 + 0.02 + 0.08) = 2.2 s.
        let g09 = || ev(Canon::Mode(ModeChange::ExactStopBlock));
        let run = |evs: Vec<Event>| {
            let mut pl = Planner::new(dynm(), [0.0; NAXES], 0.0);
            for e in &evs {
                pl.push(e);
            }
            pl.finish();
            pl.now()
        };
        let plain = run(vec![
            at_line(feed_to(20.0, 0.0), 1),
            at_line(feed_to(40.0, 0.0), 2),
        ]);
        assert!((plain - 2.1).abs() < 1e-9, "{plain}");
        let hx = run(vec![
            at_line(g09(), 1),
            at_line(feed_to(20.0, 0.0), 1),
            at_line(feed_to(40.0, 0.0), 2),
        ]);
        let hurco = run(vec![
            at_line(feed_to(20.0, 0.0), 1),
            at_line(g09(), 1),
            at_line(feed_to(40.0, 0.0), 2),
        ]);
        assert!((hx - 2.2).abs() < 1e-9, "{hx}");
        assert!((hurco - 2.2).abs() < 1e-9, "{hurco}");
    }

    #[test]
    fn hurco_m49_ignores_the_feed_override() {
        let mut d = dynm();
        d.feed_override = 0.5;
        let mut pl = Planner::new(d, [0.0; NAXES], 0.0);
        assert_eq!(pl.feed_mm_min(Feed::PerMin(1200.0), 1.0), 600.0);
        pl.push(&ev(Canon::Mode(ModeChange::FeedOverride(false))));
        assert_eq!(pl.feed_mm_min(Feed::PerMin(1200.0), 1.0), 1200.0);
        pl.push(&ev(Canon::Mode(ModeChange::FeedOverride(true))));
        assert_eq!(pl.feed_mm_min(Feed::PerMin(1200.0), 1.0), 600.0);
    }

    #[test]
    fn breakdown_adds_up() {
        let mut pl = Planner::new(dynm(), [0.0; NAXES], 0.0);
        let p = [10.0, 0.0, 0.0, 0.0, 0.0, 0.0];
        pl.push(&ev(Canon::Rapid {
            m: Motion { to: p, mto: p },
            linear: false,
        }));
        pl.push(&ev(Canon::Spindle {
            dir: SpindleDir::Cw,
            rpm: 1000.0,
            css: None,
        }));
        pl.push(&ev(Canon::Tool {
            tool: 1,
            offset: 1,
            change: true,
        }));
        pl.push(&ev(Canon::Dwell {
            seconds: 1.5,
            revolutions: 0.0,
        }));
        pl.push(&feed_to(20.0, 0.0));
        pl.finish();
        let b = pl.time;
        assert_eq!(b.tool_change, 2.0);
        assert_eq!(b.dwell, 1.5);
        // 1000 rpm at 2000 rpm/s.
        assert!((b.other - 0.5).abs() < 1e-12);
        assert!((b.total() - pl.now()).abs() < 1e-12);
        assert!(b.rapid > 0.0 && b.cutting > 0.0);
    }
}
