//! Milling canned cycles G73, G74, G76, G80-G89, G84.2/G84.3 (HX, 000
//! chapter 12) and G60 single-direction positioning (000 §4.2).
//!
//! A hole is the six actions of 000 §12.1.1: (1) positioning in the plane
//! (rapid, G60 if given), (2) rapid to the R level, (3) the hole operation,
//! (4) the action at the bottom, (5) return to R, (6) rapid to the initial
//! level (G98). Every move goes through [`Interp::move_line`] in program
//! coordinates, so the coordinate transforms apply to cycles unchanged.
//! The decisions where 000 is unreadable are in docs/dialects.md.

use super::*;
use crate::dialect::meaning::HoleCycle;
use crate::dialect::MAlso;

/// Most moves one canned-cycle block may queue (K repeats × pecks); more
/// is an alarm rather than an unbounded queue.
const MAX_CYCLE_MOVES: f64 = 100_000.0;

/// Profile parameters the cycles read, fetched once at start.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct CycleParams {
    /// PI 129: G73 retract amount / G83 clearance d (mm).
    d: f64,
    /// PI 70 / PI 71: shift direction bits of G76/G87.
    shift_bits: (bool, bool),
    /// PI 61-66: G60 overrun per axis slot X Y Z A B C (mm; sign =
    /// approach direction).
    overrun: [f64; NAXES],
}

impl CycleParams {
    /// Reads PI 129, PI 70/71 and PI 61-66 from the profile.
    pub(super) fn from_profile(p: &Profile) -> CycleParams {
        let mut overrun = [0.0; NAXES];
        for (i, o) in overrun.iter_mut().enumerate() {
            *o = p.param(&format!("PI {}", 61 + i), 0.0);
        }
        CycleParams {
            d: p.param("PI 129", 0.1).abs(),
            shift_bits: (p.param("PI 70", 0.0) != 0.0, p.param("PI 71", 0.0) != 0.0),
            overrun,
        }
    }
}

/// The modal data of the canned cycles, kept while the cycle mode lasts
/// and cleared by G80 or a group-01 code. Levels are drilling-axis
/// positions in program coordinates.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct CycleData {
    /// Parameters (not cleared).
    pub(super) params: CycleParams,
    /// Drilling-axis position when the cycle mode was entered.
    initial: Option<f64>,
    /// R level.
    r: Option<f64>,
    /// Hole bottom.
    z: Option<f64>,
    /// Q in mm (peck depth of G73/G83, shift of G76/G87).
    q: Option<f64>,
    /// Dwell P in seconds.
    p: Option<f64>,
    /// G76/G87 shift given as I/J (first and second plane axis), mm.
    ij: Option<(f64, f64)>,
}

impl CycleData {
    /// Forgets the hole data (G80, group-01 code), keeping the parameters.
    pub(super) fn clear(&mut self) {
        *self = CycleData {
            params: self.params,
            ..CycleData::default()
        };
    }
}

/// The hole data of one cycle block, resolved.
#[derive(Clone, Copy)]
struct Hole {
    kind: HoleCycle,
    /// Drilling-axis index.
    n: usize,
    initial: f64,
    r: f64,
    z: f64,
    /// Return level (initial in G98, R in G99).
    ret: f64,
    q: f64,
    dwell: f64,
    /// Shift vector (full position offset, drilling axis 0).
    shift: Pos,
    at: u32,
}

impl Interp {
    /// Block-level bookkeeping of the cycle mode, after the block's modal
    /// codes are set: a group-01 code cancels it, G80 clears the data, a
    /// plane change inside the mode is an alarm (a plane code naming the
    /// plane already in force is not a change). True if the block runs in
    /// cycle mode.
    pub(super) fn cycle_mode(
        &mut self,
        was_cycle: bool,
        plane_changed: bool,
        motion: Option<(u16, u32)>,
        kinds: crate::dialect::meaning::KindSet,
    ) -> R<bool> {
        if let Some((m, m_at)) = motion {
            // The block's first code of the cycle group, unless it is G80.
            let first = if kinds.has(crate::dialect::meaning::Kind::Cycle) {
                self.block_g(|m| matches!(m, Means::Cycle(_)))
            } else {
                None
            };
            let cycle = |g: &(u16, u32)| {
                self.gcode(g.0)
                    .is_some_and(|c| c.means != Means::Cycle(None))
            };
            if let Some((c, _)) = first.filter(cycle) {
                return Err(self.alarm(
                    AlarmKind::CannedCycle,
                    m_at,
                    format!(
                        "G{} and the canned cycle G{} in one block",
                        fmt_code(m),
                        fmt_code(c)
                    ),
                ));
            }
            // A motion code cancels the cycle mode (a table search, so
            // only when one is in force: this runs for every G01 block).
            if self.modal.cycle.means.is_some() {
                self.modal.set_meaning(self.cfg.dialect, Means::Cycle(None));
            }
        }
        if self.modal.cycle.means.is_none() {
            if was_cycle {
                self.hx.cyc.clear();
            }
            return Ok(false);
        }
        if was_cycle && plane_changed {
            if let Some((c, at)) = self.block_g(|m| matches!(m, Means::Plane(_))) {
                return Err(self.alarm(
                    AlarmKind::CannedCycle,
                    at,
                    format!(
                        "G{} changes the plane in canned cycle mode (cancel with G80 first)",
                        fmt_code(c)
                    ),
                ));
            }
        }
        Ok(true)
    }

    /// The cycle data words Q (peck, shift), P (dwell) and, for G76/G87,
    /// the shift I/J along the plane axes `axes`.
    fn cycle_qpij(&mut self, kind: HoleCycle, axes: (usize, usize)) -> R<()> {
        let (a1, a2) = axes;
        if let Some(w) = self.words.get(b'Q') {
            let v = self.linear(w);
            if v <= 0.0 {
                return Err(self.alarm(
                    AlarmKind::OutOfRange,
                    w.at,
                    format!("canned cycle Q must be positive (Q{})", fmt_num(w.v)),
                ));
            }
            self.hx.cyc.q = Some(v);
        }
        if let Some(w) = self.words.get(b'P') {
            if w.point || w.v < 0.0 {
                return Err(self.alarm(
                    AlarmKind::OutOfRange,
                    w.at,
                    "canned cycle dwell P is in milliseconds, positive, without a decimal point",
                ));
            }
            self.hx.cyc.p = Some(w.v / 1000.0);
        }
        if kind.shifts() {
            let (l1, l2) = (b"IJK"[a1], b"IJK"[a2]);
            let (w1, w2) = (self.words.get(l1), self.words.get(l2));
            if w1.is_some() || w2.is_some() {
                let v = |me: &Self, w: Option<WVal>| w.map(|w| me.linear(w)).unwrap_or(0.0);
                self.hx.cyc.ij = Some((v(self, w1), v(self, w2)));
            }
        }
        Ok(())
    }

    /// Executes a block in canned cycle mode: stores the cycle data and,
    /// if the block names a position, R or the depth, drills K holes.
    pub(super) fn canned_cycle(&mut self, entered: bool, g60: bool) -> R<()> {
        let code = self.modal.cycle.code10;
        let Some(kind) = self.modal.cycle.means else {
            return Ok(());
        };
        let at = self
            .words
            .gs()
            .iter()
            .find(|g| g.0 == code)
            .map(|g| g.1)
            .unwrap_or(0);
        let (a1, a2, n) = self.modal.plane.means.axes();
        let drill_ax = Axis::ALL[n];
        if !self.cfg.has_axis[n] {
            return Err(self.alarm(
                AlarmKind::CannedCycle,
                at,
                format!(
                    "the drilling axis of this plane ({}) is not on the machine",
                    drill_ax.name().to_uppercase()
                ),
            ));
        }
        let cur = self.prog_pos();
        if entered || self.hx.cyc.initial.is_none() {
            self.hx.cyc.initial = Some(cur[n]);
        }
        // An M98/M99 block is a call or return: its P (and HX Q/R sequence
        // numbers) are not cycle data, and it drills nothing.
        let transfer = self.words.ms().iter().any(|&(m, _)| {
            matches!(
                self.mcode(m).map(|c| c.action),
                Some(MAction::SubCall | MAction::SubReturn)
            )
        });
        if transfer {
            return Ok(());
        }
        let initial = self.hx.cyc.initial.unwrap_or(cur[n]);
        let abs = self.modal.absolute();
        // Data words: R, the depth (the drilling axis's address), Q, P, I/J.
        if let Some(w) = self.words.get(b'R') {
            let v = self.linear(w);
            self.hx.cyc.r = Some(if abs { v } else { initial + v });
        }
        let dl = ax_letter(drill_ax);
        if let Some(w) = self.words.get(dl) {
            let v = self.axis_value(drill_ax, w);
            self.hx.cyc.z =
                Some(if abs {
                    v
                } else {
                    match self.hx.cyc.r {
                        Some(r) => r + v,
                        None => return Err(self.alarm(
                            AlarmKind::MissingArgument,
                            w.at,
                            "canned cycle in G91: the depth is measured from R, and no R is given",
                        )),
                    }
                });
        }
        self.cycle_qpij(kind, (a1, a2))?;
        let count = match self.words.get(b'K') {
            None => 1,
            Some(k) if k.v >= 0.0 && k.v <= 9999.0 && k.v.fract() == 0.0 => k.v as u32,
            Some(k) => {
                return Err(self.alarm(
                    AlarmKind::OutOfRange,
                    k.at,
                    format!("canned cycle repeat count K{} is not 0-9999", fmt_num(k.v)),
                ))
            }
        };
        // A block without a position, R or depth only stores the data.
        if count == 0 || !(self.has_axis_word() || self.words.has(b'R')) {
            return Ok(());
        }
        let hole = self.resolve_hole((kind, code), n, initial, at)?;
        let (t, _) = self.target()?;
        let mut step = [0.0; NAXES];
        if !abs {
            for i in 0..NAXES {
                step[i] = t[i] - cur[i];
            }
        }
        // G91 in polar mode (G16): each repeat turns by the angle again
        // (and keeps the radius), as a repeated block would; elsewhere the
        // Cartesian step is repeated.
        let polar_step = !abs && self.frames.polar;
        for k in 0..count {
            let tk = if polar_step && k > 0 {
                self.target()?.0
            } else {
                t
            };
            let mut p = self.prog_pos();
            for i in 0..NAXES {
                if i != n {
                    p[i] = if abs || polar_step {
                        tk[i]
                    } else {
                        cur[i] + step[i] * f64::from(k + 1)
                    };
                }
            }
            self.position(p, g60, Some(n), at)?;
            self.hole(&hole)?;
        }
        Ok(())
    }

    /// Checks the stored data for one cycle and resolves the levels.
    fn resolve_hole(&self, cycle: (HoleCycle, u16), n: usize, initial: f64, at: u32) -> R<Hole> {
        let (kind, code) = cycle;
        // Only alarms need the name: built on demand, not for every hole.
        let name = || format!("G{}", fmt_code(code));
        let Some(z) = self.hx.cyc.z else {
            return Err(self.alarm(
                AlarmKind::MissingArgument,
                at,
                format!(
                    "{}: no hole depth ({}) given",
                    name(),
                    ax_letter(Axis::ALL[n]) as char
                ),
            ));
        };
        let Some(r) = self.hx.cyc.r else {
            return Err(self.alarm(
                AlarmKind::MissingArgument,
                at,
                format!("{}: no R level given", name()),
            ));
        };
        let peck = kind.pecks();
        let q = match self.hx.cyc.q {
            Some(q) => q,
            None if peck => {
                return Err(self.alarm(
                    AlarmKind::MissingArgument,
                    at,
                    format!("{}: no peck depth Q given", name()),
                ))
            }
            None => 0.0,
        };
        let g99 = self.modal.cycle_return.means == CycleReturn::RPoint;
        if kind == HoleCycle::BackBore && g99 {
            return Err(self.alarm(
                AlarmKind::CannedCycle,
                at,
                "G87 back boring returns to the initial level only: G99 is not allowed",
            ));
        }
        // Bound the moves this block queues.
        let pecks = if peck {
            ((z - r).abs() / q).ceil()
        } else {
            1.0
        };
        let k = self.words.get(b'K').map(|k| k.v).unwrap_or(1.0).max(1.0);
        if k * (3.0 * pecks + 8.0) > MAX_CYCLE_MOVES {
            return Err(self.alarm(
                AlarmKind::OutOfRange,
                at,
                format!(
                    "{}: {} holes of {} pecks would make more than {} moves in one block",
                    name(),
                    k,
                    pecks,
                    MAX_CYCLE_MOVES
                ),
            ));
        }
        let mut shift = [0.0; NAXES];
        if kind.shifts() {
            let (a1, a2, _) = self.modal.plane.means.axes();
            match self.hx.cyc.ij {
                Some((i, j)) => {
                    shift[a1] = i;
                    shift[a2] = j;
                }
                None => {
                    // PI 70 / PI 71 as Fanuc's RD1 / RD2: 00 +first axis,
                    // 01 (PI 70 = 1) -first, 10 (PI 71 = 1) +second, 11 -second.
                    let (rd1, rd2) = self.hx.cyc.params.shift_bits;
                    let sign = if rd1 { -1.0 } else { 1.0 };
                    shift[if rd2 { a2 } else { a1 }] = sign * q;
                }
            }
        }
        Ok(Hole {
            kind,
            n,
            initial,
            r,
            z,
            ret: if g99 { r } else { initial },
            q,
            dwell: self.hx.cyc.p.unwrap_or(0.0),
            shift,
            at,
        })
    }

    /// A straight move to `p` (program coordinates) unless already there.
    fn go(&mut self, rapid: bool, p: Pos, at: u32) -> R<()> {
        let cur = self.prog_pos();
        if (0..NAXES).all(|i| (p[i] - cur[i]).abs() < 1e-9) {
            return Ok(());
        }
        self.move_line(rapid, p, at)
    }

    /// Moves the drilling axis alone to level `v`.
    fn level(&mut self, rapid: bool, n: usize, v: f64, at: u32) -> R<()> {
        let mut p = self.prog_pos();
        p[n] = v;
        self.go(rapid, p, at)
    }

    /// Moves by the shift vector `s` (sign +1 out, -1 back) at rapid.
    fn shift(&mut self, s: &Pos, sign: f64, at: u32) -> R<()> {
        let mut p = self.prog_pos();
        for i in 0..NAXES {
            p[i] += sign * s[i];
        }
        self.go(true, p, at)
    }

    /// Rapid positioning to `p`; with G60 through the overrun point of
    /// each moving axis (all but `skip`, the drilling axis in a cycle).
    fn position(&mut self, p: Pos, g60: bool, skip: Option<usize>, at: u32) -> R<()> {
        if g60 {
            let cur = self.prog_pos();
            let mut mid = p;
            let mut any = false;
            for i in 0..NAXES {
                let o = self.hx.cyc.params.overrun[i];
                if Some(i) != skip && (p[i] - cur[i]).abs() > 1e-9 && o != 0.0 {
                    // Sign = approach direction: stop short (or beyond) by
                    // the overrun, then approach in that direction.
                    mid[i] = p[i] - o;
                    any = true;
                }
            }
            if any {
                self.go(true, mid, at)?;
            }
        }
        self.go(true, p, at)
    }

    /// G60 as a positioning block (000 §4.2): a one-shot rapid through the
    /// overrun point of every moving axis.
    pub(super) fn g60(&mut self, at: u32) -> R<()> {
        use crate::dialect::meaning::MotionMode::{ArcCcw, ArcCw, Linear};
        let feed_move = |g: &&(u16, u32)| {
            self.gcode(g.0)
                .is_some_and(|c| matches!(c.means, Means::Motion(Linear | ArcCw | ArcCcw)))
        };
        if let Some(&(c, c_at)) = self.words.gs().iter().find(feed_move) {
            return Err(self.alarm(
                AlarmKind::CannedCycle,
                c_at,
                format!(
                    "G60 is a positioning command (with G00 or G81-G89); G{} is not allowed with it",
                    fmt_code(c)
                ),
            ));
        }
        let (t, any) = self.target()?;
        if any {
            self.position(t, true, None, at)?;
        }
        Ok(())
    }

    fn dwell_secs(&mut self, s: f64) {
        if s > 0.0 {
            self.emit(Canon::Dwell {
                seconds: s,
                revolutions: 0.0,
            });
        }
    }

    /// Switches the spindle as a cycle does (reversal, stop, restart).
    fn cycle_spindle(&mut self, dir: SpindleDir) {
        self.tool.spindle = dir;
        let rpm = if dir == SpindleDir::Stop {
            0.0
        } else {
            self.rpm()
        };
        self.tool.last_rpm = rpm;
        let css = self.css_speed().filter(|_| dir != SpindleDir::Stop);
        self.emit(Canon::Spindle { dir, rpm, css });
    }

    /// Oriented spindle stop: emitted as M19 "spindle orientation".
    fn orient(&mut self) {
        self.tool.spindle = SpindleDir::Stop;
        self.tool.last_rpm = 0.0;
        // The table's orientation code (M19 on the HX).
        let orient = self
            .cfg
            .dialect
            .mcodes
            .iter()
            .find(|m| m.also == MAlso::Orient);
        if let Some(mc) = orient {
            self.emit(Canon::Aux {
                m: u32::from(mc.code),
                name: mc.name,
            });
        }
    }

    /// The cutting mode of group 15 in force, re-emitted after tapping.
    fn restore_cut_mode(&mut self) {
        match self.modal.cutting_mode.means {
            Some(CuttingMode::Tapping) | None => {}
            Some(m) => self.mode_event(Means::CuttingMode(m)),
        }
    }

    /// Actions 2-6 of one hole, after the positioning in the plane.
    fn hole(&mut self, h: &Hole) -> R<()> {
        let (n, at) = (h.n, h.at);
        let dir0 = self.tool.spindle;
        let restart = if dir0 == SpindleDir::Stop {
            SpindleDir::Cw
        } else {
            dir0
        };
        use HoleCycle::*;
        if h.kind == BackBore {
            return self.back_boring(h, restart);
        }
        // Action 2: rapid to R.
        self.level(true, n, h.r, at)?;
        match h.kind {
            Drill | DrillDwell => {
                self.level(false, n, h.z, at)?;
                if h.kind == DrillDwell {
                    self.dwell_secs(h.dwell);
                }
                self.level(true, n, h.ret, at)?;
            }
            PeckChipBreak | Peck => {
                self.peck(h)?;
                self.level(true, n, h.ret, at)?;
            }
            Tap | TapLeft | RigidTap | RigidTapLeft => {
                let (inward, outward) = if h.kind.left_hand() {
                    (SpindleDir::Ccw, SpindleDir::Cw)
                } else {
                    (SpindleDir::Cw, SpindleDir::Ccw)
                };
                self.emit(Canon::Mode(ModeChange::TappingMode));
                self.level(false, n, h.z, at)?;
                self.dwell_secs(h.dwell);
                self.cycle_spindle(outward);
                self.level(false, n, h.r, at)?;
                self.dwell_secs(h.dwell);
                self.cycle_spindle(inward);
                self.restore_cut_mode();
                self.level(true, n, h.ret, at)?;
            }
            Bore | BoreDwell => {
                self.level(false, n, h.z, at)?;
                if h.kind == BoreDwell {
                    self.dwell_secs(h.dwell);
                }
                self.level(false, n, h.r, at)?;
                self.level(true, n, h.ret, at)?;
            }
            BoreStop => {
                self.level(false, n, h.z, at)?;
                self.cycle_spindle(SpindleDir::Stop);
                self.level(true, n, h.ret, at)?;
                self.cycle_spindle(restart);
            }
            ManualBore => {
                self.level(false, n, h.z, at)?;
                self.dwell_secs(h.dwell);
                self.cycle_spindle(SpindleDir::Stop);
                // The operator retracts by hand, then presses cycle start.
                self.emit(Canon::Stop { optional: false });
                self.level(true, n, h.ret, at)?;
                self.cycle_spindle(restart);
            }
            FineBore => {
                self.level(false, n, h.z, at)?;
                self.dwell_secs(h.dwell);
                self.orient();
                self.shift(&h.shift, 1.0, at)?;
                self.level(true, n, h.ret, at)?;
                self.shift(&h.shift, -1.0, at)?;
                self.cycle_spindle(restart);
            }
            BackBore => {}
        }
        Ok(())
    }

    /// G73 / G83 pecking from R to the bottom (actions 3-4).
    fn peck(&mut self, h: &Hole) -> R<()> {
        let (n, at) = (h.n, h.at);
        let down = if h.z < h.r { -1.0 } else { 1.0 };
        let total = (h.z - h.r).abs();
        // Scaling does not apply to Q and d (000 §15.2): in program
        // coordinates they shrink by the drilling axis's factor.
        let f = match self.frames.xf.scale {
            Some(s) if n < 3 => s.factor[n].abs(),
            _ => 1.0,
        };
        let (q, d) = (h.q / f, self.hx.cyc.params.d / f);
        let mut done = 0.0f64;
        while total - done > 1e-9 {
            let prev = done;
            done = (done + q).min(total);
            if prev > 0.0 {
                if h.kind == HoleCycle::Peck {
                    // G83: back to R, then rapid down to d above the last depth.
                    self.level(true, n, h.r, at)?;
                    let to = (prev - d).max(0.0);
                    self.level(true, n, h.r + down * to, at)?;
                } else {
                    // G73: rapid up by d.
                    let to = (prev - d).max(0.0);
                    self.level(true, n, h.r + down * to, at)?;
                }
            }
            self.level(false, n, h.r + down * done, at)?;
        }
        Ok(())
    }

    /// G87 back boring: oriented stop and shift at the initial level, rapid
    /// down to R (below the bore), shift back, spindle on, feed up to Z,
    /// dwell, oriented stop, shift, rapid up to the initial level, shift
    /// back, spindle on.
    fn back_boring(&mut self, h: &Hole, restart: SpindleDir) -> R<()> {
        let (n, at) = (h.n, h.at);
        self.orient();
        self.shift(&h.shift, 1.0, at)?;
        self.level(true, n, h.r, at)?;
        self.shift(&h.shift, -1.0, at)?;
        self.cycle_spindle(restart);
        self.level(false, n, h.z, at)?;
        self.dwell_secs(h.dwell);
        self.orient();
        self.shift(&h.shift, 1.0, at)?;
        self.level(true, n, h.initial, at)?;
        self.shift(&h.shift, -1.0, at)?;
        self.cycle_spindle(restart);
        Ok(())
    }
}
