//! Hurco MAX (002) codes that are not cycles: T and E codes with their
//! immediate or deferred activation (Table 16), the fixture offset table
//! (E1-E9999), G33 with K/I and P, G53's preconditions, G96 R (Table 14)
//! and G92 S. The cycles are in `hurco_thread.rs` (G78),
//! `hurco_cycles.rs` (G73/G74/G80-G84) and `probe.rs` (G38).

use super::work_offsets::WorkId;
use super::*;
use crate::dialect::meaning::OneShot as Os;

pub(super) use super::work_offsets::MAX_FIXTURE;

/// Hurco-only state.
#[derive(Clone, Debug, Default)]
pub(crate) struct HurcoState {
    /// Active fixture offset number (E1 at power-on: the profile's part
    /// zero).
    pub fixture: u32,
    /// After a T or E code changed the offsets and before the next move:
    /// the program coordinates of each axis as they were before the
    /// change (Table 16).
    pub pending: Option<Pos>,
    /// G96 R (Table 14): the radius, mm, at which the surface speed is
    /// held; None or 0 = the X position.
    pub css_r: Option<f64>,
    /// G33 lead last programmed (mm/rev along the longer axis).
    pub g33_lead: Option<f64>,
    /// Drill cycle data (G73/G74/G81-G84).
    pub drill: super::hurco_cycles::Drill,
    /// G38 S0 datum offsets: -X, +X, -Z, +Z (mm; None = not datumed).
    pub datum: [Option<f64>; 4],
}

impl HurcoState {
    /// The Hurco state at power-on: E1 active (the profile's part zero,
    /// which the work offset table holds), no offset change waiting, no
    /// drill data, no datums.
    pub(super) fn new() -> Box<HurcoState> {
        Box::new(HurcoState {
            fixture: 1,
            ..Default::default()
        })
    }
}

impl Interp {
    /// Fixture offset `n` (machine coordinates of its part zero, mm).
    pub fn fixture_offset(&self, n: u32) -> Pos {
        self.frames.work().get(WorkId::Fixture(n))
    }

    /// Sets fixture offset `n` (1-9999; mm, X as a radius) as an offsets
    /// file or a probe cycle writes it. Takes effect when E`n` is next
    /// programmed. False when `n` is not a fixture number.
    pub fn set_fixture_offset(&mut self, n: u32, origin: Pos) -> bool {
        self.frames.work_mut().set(WorkId::Fixture(n), origin)
    }

    /// Remembers the program position before an offset change, once per
    /// change (the first change since the last move counts).
    fn hold_position(&mut self) {
        if self.hurco.pending.is_none() {
            self.hurco.pending = Some(self.prog_pos());
        }
    }

    /// T and E codes of a Hurco block (Table 1 stage "Tool and Fixture
    /// Commands").
    pub(super) fn hurco_t_e(&mut self) -> R<()> {
        if let Some(t) = self.words.get(b'T') {
            self.hurco_t(t)?;
        }
        if let Some(e) = self.words.get(b'E') {
            if e.v < 0.0 || e.v.fract() != 0.0 || e.v > MAX_FIXTURE as f64 {
                return Err(self.alarm(
                    AlarmKind::OutOfRange,
                    e.at,
                    format!("E{} is not a fixture offset (E0-E9999)", fmt_num(e.v)),
                ));
            }
            let n = e.v as u32;
            self.hold_position();
            self.hurco.fixture = n;
            self.frames.work_mut().select(WorkId::Fixture(n));
        }
        Ok(())
    }

    /// T mmmmmmmnn: tool number and offset number (the last two digits);
    /// the offset's X/Z apply from here, T00 (offset 00) cancels them.
    fn hurco_t(&mut self, t: WVal) -> R<()> {
        self.check_range(b'T', t)?;
        if t.v < 0.0 || t.v.fract() != 0.0 {
            return Err(self.alarm(
                AlarmKind::OutOfRange,
                t.at,
                format!("T{} is not a tool code", fmt_num(t.v)),
            ));
        }
        let v = t.v as u32;
        let (tool, off) = (v / 100, v % 100);
        if tool > self.cfg.profile.tools.count {
            return Err(self.alarm(
                AlarmKind::OutOfRange,
                t.at,
                format!(
                    "T{v}: the turret has {} stations",
                    self.cfg.profile.tools.count
                ),
            ));
        }
        if off as usize > self.offsets.count() {
            return Err(self.alarm(
                AlarmKind::OutOfRange,
                t.at,
                format!(
                    "T{v}: offset {off} is not in the tool offset table (00-{:02})",
                    self.offsets.count()
                ),
            ));
        }
        let change = tool != 0 && tool != self.tool.number;
        if tool != 0 {
            self.tool.number = tool;
        }
        self.tool.next = self.tool.number;
        self.hold_position();
        self.tool.offset = off;
        self.apply_lathe_offset();
        self.emit(Canon::Tool {
            tool: self.tool.number,
            offset: off,
            change,
        });
        Ok(())
    }

    /// Table 16, the base of a move's incremental words: after a T/E code
    /// and before the next move, the program position before the change.
    pub(super) fn hurco_base(&self, base: &mut Pos) {
        if let Some(p) = self.hurco.pending {
            for i in 0..NAXES {
                if self.cfg.has_axis[i] {
                    base[i] = p[i];
                }
            }
        }
    }

    /// Table 16, immediate activation: the axes a move does not program go
    /// to their program position before the change, relative to the new
    /// offsets (deferred: they stay where they are).
    pub(super) fn hurco_immediate(&self, t: &mut Pos, programmed: &[bool; NAXES]) {
        let Some(p) = self.hurco.pending else {
            return;
        };
        if !self.cfg.profile.tools.immediate_offsets {
            return;
        }
        for i in 0..NAXES {
            if self.cfg.has_axis[i] && !programmed[i] {
                t[i] = p[i];
            }
        }
    }

    /// A move has been made: the offset change is complete.
    pub(super) fn hurco_moved(&mut self) {
        self.hurco.pending = None;
    }

    /// 002: M00, M01 (when it stops), M02 and M30 turn the spindle off.
    pub(super) fn hurco_stop_spindle(&mut self) {
        if !self.cfg.dialect.caps.stops_stop_spindle || self.tool.spindle == SpindleDir::Stop {
            return;
        }
        self.tool.spindle = SpindleDir::Stop;
        self.tool.last_rpm = 0.0;
        self.emit(Canon::Spindle {
            dir: SpindleDir::Stop,
            rpm: 0.0,
            css: None,
        });
    }

    /// G53 preconditions (002): CRC off, G90, G00 or G01 mode.
    pub(super) fn g53_checks(&self, at: u32) -> R<()> {
        let why = if self.modal.cutter_comp.means != CompSide::Off {
            "cutter radius compensation must be off (G40)"
        } else if !self.modal.absolute() {
            "absolute mode (G90) must be active"
        } else if !matches!(
            self.modal.motion.means,
            MotionMode::Rapid | MotionMode::Linear
        ) {
            "G00 or G01 mode must be active"
        } else {
            return Ok(());
        };
        Err(self.alarm(AlarmKind::HurcoMode, at, format!("G53: {why}")))
    }

    /// G96 R in the block (Table 14): radius in G07, diameter in G08; 0
    /// returns to the X position; absent keeps the previous R.
    pub(super) fn g96_r(&mut self) -> R<()> {
        if self.block_g(|m| m == Means::Css(true)).is_none() {
            return Ok(());
        }
        if let Some(r) = self.words.take(b'R') {
            self.check_range(b'R', r)?;
            if r.v < 0.0 {
                return Err(self.alarm(AlarmKind::OutOfRange, r.at, "G96 R must not be negative"));
            }
            let v = self.axis_value(Axis::X, r);
            self.hurco.css_r = (v > 0.0).then_some(v);
        }
        Ok(())
    }

    /// G92 S (002): the spindle speed clamp for constant surface speed.
    pub(super) fn g92_s(&mut self) -> R<()> {
        if let Some(s) = self.words.take(b'S') {
            self.check_range(b'S', s)?;
            if s.v < 0.0 {
                return Err(self.alarm(AlarmKind::OutOfRange, s.at, "negative spindle clamp"));
            }
            self.tool.s_clamp = Some(s.v);
            self.emit(Canon::Mode(ModeChange::SpindleClamp(s.v)));
        }
        Ok(())
    }

    /// G33 on the Hurco: the lead is K (along Z) or I (along X), for the
    /// axis with the longer move; P is the start angle (-360..360, this
    /// block only).
    pub(super) fn hurco_g33(&mut self, tw: Pos, at: u32) -> R<()> {
        let cur = self.prog_pos();
        let dx = (tw[0] - cur[0]).abs();
        let dz = (tw[2] - cur[2]).abs();
        let (k, i) = (self.words.get(b'K'), self.words.get(b'I'));
        if let (Some(_), Some(iw)) = (k, i) {
            return Err(self.alarm(
                AlarmKind::DuplicateAddress,
                iw.at,
                "G33 takes the lead as K (Z) or I (X), not both",
            ));
        }
        if let Some(w) = k.or(i) {
            let (x_lead, longest_ok) = if k.is_some() {
                (false, dz + 1e-9 >= dx)
            } else {
                (true, dx + 1e-9 >= dz)
            };
            if !longest_ok {
                return Err(self.alarm(
                    AlarmKind::ThreadCycle,
                    w.at,
                    format!(
                        "G33: the lead must be given for the axis with the longest move ({})",
                        if x_lead { "K, along Z" } else { "I, along X" }
                    ),
                ));
            }
            let (lo, hi) = self.hurco_lead_range();
            let (lo, hi) = (lo / self.unit(), hi / self.unit());
            if w.v < lo * (1.0 - 1e-9) || w.v > hi * (1.0 + 1e-9) {
                return Err(self.alarm(
                    AlarmKind::OutOfRange,
                    w.at,
                    format!(
                        "thread lead {} out of range ({}-{})",
                        fmt_num(w.v),
                        fmt_num(lo),
                        fmt_num(hi)
                    ),
                ));
            }
            self.hurco.g33_lead = Some(w.v * self.unit());
        }
        let Some(lead) = self.hurco.g33_lead else {
            return Err(self.alarm(AlarmKind::MissingArgument, at, "G33 needs a lead (K or I)"));
        };
        if self.tool.spindle == SpindleDir::Stop {
            return Err(self.alarm(
                AlarmKind::ThreadCycle,
                at,
                "G33 with the spindle stopped: the threading move would wait forever",
            ));
        }
        if let Some(p) = self.words.get(b'P') {
            if !(-360.0..=360.0).contains(&p.v) {
                return Err(self.alarm(
                    AlarmKind::OutOfRange,
                    p.at,
                    format!("G33 start angle P{} out of range (-360..360)", fmt_num(p.v)),
                ));
            }
            if p.v != 0.0 {
                self.emit(Canon::Message(format!(
                    "thread start angle {}",
                    fmt_num(p.v)
                )));
            }
        }
        self.hurco_thread_to(tw, lead, at)
    }

    /// A spindle-synchronised straight move to `tw` (program coordinates).
    pub(super) fn hurco_thread_to(&mut self, tw: Pos, lead: f64, at: u32) -> R<()> {
        self.thread_move(tw, lead, at)
    }
}

impl Interp {
    /// Block checks before execution: a G78 or G38 block hands its letters
    /// to the cycle (G78's M is the face parameter); outside them the
    /// multi-letter names and U/W are not used ("Unused Data").
    pub(super) fn hurco_block_checks(
        &mut self,
        one_shot: &[(u16, u32)],
    ) -> R<Option<(u16, u32, Option<WVal>)>> {
        let mut found: Option<(u16, u32)> = None;
        for &(c, at) in one_shot {
            if matches!(
                self.means_of(c),
                Some(Means::OneShot(Os::Probe | Os::ThreadCycle))
            ) {
                if found.is_some() {
                    return Err(self.alarm(
                        AlarmKind::HurcoMode,
                        at,
                        "G38 and G78 cannot share a block",
                    ));
                }
                found = Some((c, at));
            }
        }
        let Some((c, at)) = found else {
            if self.words.nlong > 0 {
                let (k, w) = self.words.long[0];
                let name = crate::dialect::hurco::LONG_NAMES
                    .get(k as usize)
                    .copied()
                    .unwrap_or("?");
                return Err(self.alarm(
                    AlarmKind::IllegalAddress,
                    w.at,
                    format!("{name} is a G78/G38 parameter: not used in this block"),
                ));
            }
            // Letters only the G78/G38 macros use ("Unused Data").
            for &l in b"BCDJLUVW" {
                if let Some(w) = self.words.get(l) {
                    return Err(self.alarm(
                        AlarmKind::IllegalAddress,
                        w.at,
                        format!(
                            "address {} is only used by G78 threading or G38 probing",
                            l as char
                        ),
                    ));
                }
            }
            return Ok(None);
        };
        let mut face = None;
        let thread = self.means_of(c) == Some(Means::OneShot(Os::ThreadCycle));
        if thread && self.words.nm > 0 {
            if self.words.nm > 1 {
                return Err(self.alarm(
                    AlarmKind::DuplicateAddress,
                    self.words.m[1].1,
                    "parameter M given twice",
                ));
            }
            let (v, mat) = self.words.m[0];
            face = Some(WVal {
                v: v as f64,
                point: false,
                at: mat,
            });
            self.words.nm = 0;
        }
        Ok(Some((c, at, face)))
    }

    /// A G78 or G38 block after its modal G codes: the block's
    /// before-motion M codes, the cycle, the after-motion M codes.
    pub(super) fn hurco_macro_block(&mut self, c: u16, at: u32, face: Option<WVal>) -> R<bool> {
        self.run_m(|m| m.1 == MWhen::Before)?;
        if self.means_of(c) == Some(Means::OneShot(Os::ThreadCycle)) {
            self.g78(at, face)?;
            self.hurco_moved();
        } else {
            self.g38(at)?;
        }
        self.run_m(|m| {
            m.1 == MWhen::After
                && !matches!(m.2, MAction::Stop | MAction::OptionalStop | MAction::End)
        })?;
        self.run_m(|m| matches!(m.2, MAction::Stop | MAction::OptionalStop | MAction::End))?;
        Ok(!self.finished_by_end())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// 002: the part zero E1 is active at power-on; nothing waits for a
    /// move and no probe datum is set.
    #[test]
    fn power_on_has_e1_active_and_nothing_pending() {
        let h = HurcoState::new();
        assert_eq!(h.fixture, 1);
        assert!(h.pending.is_none() && h.css_r.is_none() && h.g33_lead.is_none());
        assert_eq!(h.datum, [None; 4]);
    }
}
