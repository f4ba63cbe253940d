//! Executing a block: the block's codes are checked, then the control's
//! phases run in the order its dialect lists (`Dialect::order`: the Fanuc
//! order on the HX and the PUMA, 002 Table 1 on the Hurco). Each
//! [`Phase`] is one small step; what one phase finds that a later one
//! needs (the motion code, the one-shots, the cycle modes) travels in the
//! block's [`BlockRun`].

use super::*;
use crate::dialect::meaning::{HoleCycle, Kind, KindSet, LatheCycle, OneShot as Os};
use crate::dialect::Phase;

/// What a phase tells the walk.
enum Flow {
    /// Go on with the next phase.
    Next,
    /// The block is done: Ok(this) from `execute_block` (false = the
    /// program ended).
    Done(bool),
}

/// The one-shot (group 0) G codes of a block that change how it runs.
#[derive(Clone, Copy, Default)]
pub(super) struct OneShots {
    g53: bool,
    dwell: bool,
    g09: bool,
    g60: Option<u32>,
    setting: bool,
    refret: Option<(crate::dialect::meaning::RefReturn, u32)>,
    skip: Option<(u16, u32)>,
    g45: Option<(i8, u16, u32)>,
    mrc: Option<(LatheCycle, u16, u32)>,
}

/// The state of one block's execution, passed from phase to phase.
pub(super) struct BlockRun {
    /// The group 1 code of the block, with its byte.
    motion: Option<(u16, u32)>,
    /// The group 0 codes, in block order.
    one_shot: [(u16, u32); MAX_CODES],
    n_one: usize,
    /// M98 / M99.
    transfer: Option<(MAction, u32)>,
    /// The kinds of G code in the block.
    kinds: KindSet,
    /// Hurco: the block is a G78 / G38 macro cycle (code, byte, face M).
    hurco_macro: Option<(u16, u32, Option<WVal>)>,
    /// HX: a canned cycle mode was in force before the block.
    was_cycle: bool,
    plane_before: Plane,
    /// HX canned cycle / Hurco drill cycle mode after the modal codes.
    cycle: bool,
    hurco_cycle: bool,
    /// The axis words were data (G107 C, G51, G68, G10 L2 …).
    xdata: bool,
    /// A G39 block (no move of its own).
    g39: bool,
    os: OneShots,
}

impl BlockRun {
    fn one_shot(&self) -> &[(u16, u32)] {
        &self.one_shot[..self.n_one]
    }

    /// A dwell or a coordinate-setting block does not move: its axis words
    /// are the time or the new coordinates.
    fn no_motion(&self) -> bool {
        self.os.dwell || self.os.setting || self.xdata || self.g39
    }
}

/// The phases of [`crate::dialect::FANUC_MILL`] that can act on a quiet block (see
/// [`Interp::quiet_block`]), in its order. The others do nothing for
/// such a block: HxCycleMode (no cycle in force and no cycle code: it
/// returns false), ToolLength (no D, no H, no G43/G44/G49), Comp (no D,
/// no plane or compensation code, no one-shot, no compensation in
/// force: false), OneShots (none: the default), Tool (no T), MBefore,
/// MAfter and Stop (no M code), Dwell and ExactStopBefore (no G04, no
/// G09), CompEnd (no compensation in force). The walk over them costs
/// more than the plain move itself.
static QUIET_MILL: &[Phase] = &[
    Phase::ModalG,
    Phase::Frames,
    Phase::Feed,
    Phase::Spindle,
    Phase::Motion,
    Phase::Transfer,
];

impl Interp {
    /// A block the [`QUIET_MILL`] walk gives the same results for as the
    /// [`crate::dialect::FANUC_MILL`] one: on a control with that order, its only G code
    /// (if any) a motion code, no M code, no D, H or T word, no canned
    /// cycle and no cutter compensation in force.
    #[inline]
    fn quiet_block(&self, b: &BlockRun) -> bool {
        let mut motion_only = KindSet::default();
        motion_only.insert(Kind::Motion);
        self.quiet_walk
            && self.modal.cycle.means.is_none()
            && self.common.comp.is_none()
            && self.words.nm == 0
            && (b.kinds == motion_only || b.kinds == KindSet::default())
            && !self.words.has(b'D')
            && !self.words.has(b'H')
            && !self.words.has(b'T')
            && self.cfg.mill_order
    }

    /// The first G code of the block (code, byte) whose table meaning
    /// satisfies `is`.
    pub(super) fn block_g(&self, is: impl Fn(Means) -> bool) -> Option<(u16, u32)> {
        self.words
            .gs()
            .iter()
            .copied()
            .find(|g| self.gcode(g.0).is_some_and(|c| is(c.means)))
    }

    /// What a G code of the block means (None: not in the table).
    pub(super) fn means_of(&self, code10: u16) -> Option<Means> {
        self.gcode(code10).map(|g| g.means)
    }

    /// Executes the block in `self.words`: its codes checked, then the
    /// dialect's phases in order. Ok(false) when the program ended.
    pub(super) fn execute_block(&mut self) -> R<bool> {
        let Some(mut b) = self.classify_block()? else {
            return Ok(true);
        };
        let order = if self.quiet_block(&b) {
            QUIET_MILL
        } else {
            self.cfg.dialect.order
        };
        for &p in order {
            if let Flow::Done(r) = self.run_phase(p, &mut b)? {
                return Ok(r);
            }
        }
        Ok(true)
    }

    /// Checks the block's G and M codes and sorts them; None when the
    /// block was a G65 / G66 call (executed here).
    fn classify_block(&mut self) -> R<Option<BlockRun>> {
        // Classify G codes.
        let mut motion: Option<(u16, u32)> = None;
        let mut one_shot: [(u16, u32); MAX_CODES] = [(0, 0); MAX_CODES];
        let mut n_one = 0;
        let mut kinds = KindSet::default();
        for i in 0..self.words.ng {
            let (c, at) = self.words.g[i];
            let Some(g) = self.gcode(c) else {
                return Err(self.alarm(
                    AlarmKind::UnknownG,
                    at,
                    format!("G{} is not a G code of this control", fmt_code(c)),
                ));
            };
            if let Support::Later(which) = g.support {
                return Err(self.alarm(
                    AlarmKind::NotYetSupported,
                    at,
                    format!(
                        "G{} ({}) is not yet supported: {which}",
                        fmt_code(c),
                        g.name
                    ),
                ));
            }
            kinds.insert(g.means.kind());
            if matches!(
                g.means,
                Means::OneShot(Os::MacroCall) | Means::ModalCall(true)
            ) {
                self.g65(c, at)?;
                return Ok(None);
            }
            if let Means::Motion(_) = g.means {
                motion = Some((c, at));
            } else if let Means::OneShot(_) = g.means {
                one_shot[n_one] = (c, at);
                n_one += 1;
            }
        }
        let transfer = self.classify_m()?;
        // A held ,C/,R move, or one in this block, cannot be followed by a
        // block that moves otherwise or leaves the program.
        if self.common.corner.is_some()
            | self.words.comma_c.is_some()
            | self.words.comma_r.is_some()
        {
            self.corner_gate(&one_shot[..n_one], transfer.map(|t| t.0))?;
        }
        Ok(Some(BlockRun {
            motion,
            one_shot,
            n_one,
            transfer,
            kinds,
            hurco_macro: None,
            was_cycle: false,
            plane_before: self.modal.plane.means,
            cycle: false,
            hurco_cycle: false,
            xdata: false,
            g39: false,
            os: OneShots::default(),
        }))
    }

    /// One phase of the block (see [`Phase`]). Inlined into the walk:
    /// a call per phase of a function this size costs more than the
    /// phase itself on a plain block.
    #[inline(always)]
    fn run_phase(&mut self, p: Phase, b: &mut BlockRun) -> R<Flow> {
        match p {
            Phase::HurcoChecks => b.hurco_macro = self.hurco_block_checks(b.one_shot())?,
            Phase::JobSyncM => self.run_m(|m| m.1 == MWhen::JobSync)?,
            Phase::ModalG => self.apply_modal_codes(b),
            Phase::HxCycleMode => {
                let plane_changed = self.modal.plane.means != b.plane_before;
                b.cycle = self.cycle_mode(b.was_cycle, plane_changed, b.motion, b.kinds)?;
            }
            Phase::HurcoCycleMode => b.hurco_cycle = self.hurco_cycle_mode(b.motion)?,
            Phase::HurcoMacro => {
                if let Some((c, at, face_m)) = b.hurco_macro {
                    return self.hurco_macro_block(c, at, face_m).map(Flow::Done);
                }
            }
            Phase::Frames => {
                // G112/G113/G107 in the block, or a mode in force to check
                // the block against.
                let rotary = b.kinds.any(&[Kind::PolarInterp, Kind::Cylindrical])
                    || self.frames.rot != polar_interp::RotInterp::Off;
                let rdata = rotary && self.rotary_codes_and_event()?;
                b.xdata = self.transform_codes(b.one_shot(), b.kinds)? || rdata;
            }
            Phase::ToolLength => self.tool_length_codes(b.kinds)?,
            Phase::Comp => b.g39 = self.block_comp(b.one_shot(), b.cycle, b.kinds)?,
            Phase::OneShots => b.os = self.one_shots(b.one_shot())?,
            Phase::CssRadius => self.g96_r()?,
            Phase::OverrideM => self.run_m(|m| matches!(m.2, MAction::FeedOverride(_)))?,
            Phase::CoolantM => {
                self.run_m(|m| matches!(m.2, MAction::CoolantMist | MAction::CoolantFlood))?
            }
            Phase::ToolAndFixture => self.hurco_t_e()?,
            Phase::Feed => self.f_word(b.os.dwell)?,
            Phase::Tool => self.t_word()?,
            Phase::Spindle => self.spindle_words()?,
            Phase::MBefore => self.run_m(|m| {
                m.1 == MWhen::Before && !matches!(m.2, MAction::SpindleCw | MAction::SpindleCcw)
            })?,
            // Other before-motion machine functions, after the spindle.
            Phase::HurcoMBefore => self.run_m(|m| {
                m.1 == MWhen::Before
                    && !matches!(
                        m.2,
                        MAction::CoolantMist | MAction::CoolantFlood | MAction::FeedOverride(_)
                    )
            })?,
            Phase::Dwell => {
                if b.os.dwell {
                    self.dwell()?;
                }
            }
            Phase::PumaM => {
                if self.words.nm > 0 {
                    self.lathe_m_codes();
                }
            }
            Phase::ExactStopBefore | Phase::ExactStopAfter => {
                if b.os.g09 {
                    self.emit(Canon::Mode(ModeChange::ExactStopBlock));
                }
            }
            Phase::Motion => {
                let cycles = (b.cycle, b.was_cycle, b.hurco_cycle);
                self.block_motion(&b.os, b.no_motion(), cycles)?;
            }
            Phase::Moved => {
                if !b.no_motion() && self.has_axis_word() {
                    self.hurco_moved();
                }
            }
            Phase::MAfter => self.run_m(|m| {
                m.1 == MWhen::After
                    && !matches!(m.2, MAction::Stop | MAction::OptionalStop | MAction::End)
            })?,
            Phase::PumaMAfter => {
                if self.words.nm > 0 {
                    self.lathe_m_after();
                }
            }
            Phase::Stop => {
                self.run_m(|m| matches!(m.2, MAction::Stop | MAction::OptionalStop | MAction::End))?
            }
            Phase::CompEnd => {
                if self.common.comp.is_some() {
                    self.comp_block_end()?;
                }
            }
            Phase::Transfer => {
                if self.finished_by_end() {
                    return Ok(Flow::Done(false));
                }
                self.transfer(b)?;
            }
        }
        Ok(Flow::Next)
    }

    /// The modal G codes (every group but 0 and 1) and the motion mode.
    fn apply_modal_codes(&mut self, b: &mut BlockRun) {
        b.was_cycle = self.modal.cycle.means.is_some();
        b.plane_before = self.modal.plane.means;
        for i in 0..self.words.ng {
            let (c, _) = self.words.g[i];
            let Some(g) = self.gcode(c) else { continue };
            if !matches!(g.means, Means::OneShot(_) | Means::Motion(_)) {
                self.apply_modal(g);
                if g.means == Means::ModalCall(false) {
                    self.g67();
                }
            }
        }
        if let Some((c, _)) = b.motion {
            // The same code again (a G01 on every line) changes nothing.
            if c != self.modal.motion.code10 {
                if let Some(g) = self.gcode(c) {
                    self.modal.set(g);
                }
            }
        }
    }

    /// D, and G43/G44/G49 or H: the tool length offset.
    fn tool_length_codes(&mut self, kinds: KindSet) -> R<()> {
        if let Some(dw) = self.words.get(b'D') {
            self.sys.d = dw.v;
        }
        if self.words.has(b'H') || kinds.has(Kind::LengthComp) {
            self.tool_length()?;
        }
        Ok(())
    }

    /// Subprogram call / return last, after everything else of the block;
    /// without one, G66 in force calls the macro after a block with an
    /// axis move.
    fn transfer(&mut self, b: &BlockRun) -> R<()> {
        match b.transfer {
            Some((MAction::SubCall, at)) => self.m98(at)?,
            Some((_, at)) => self.m99(at)?,
            None => {
                let moved = b.os.refret.is_some() || !b.no_motion();
                if !self.prog.calls.modal.is_empty() && moved && self.has_axis_word() {
                    self.modal_call(self.motion_at())?;
                }
            }
        }
        Ok(())
    }

    /// Cutter / tool nose radius compensation codes, before the one-shots
    /// (a G92 or G28 ends a held move first). True for a G39 block.
    fn block_comp(&mut self, one_shot: &[(u16, u32)], cycle: bool, kinds: KindSet) -> R<bool> {
        let g39 = Some(Means::OneShot(Os::CompCorner));
        let comp_words = self.words.has(b'D')
            || kinds.any(&[Kind::Plane, Kind::CutterComp])
            || one_shot.iter().any(|g| self.means_of(g.0) == g39);
        if comp_words || (self.common.comp.is_some() && (!one_shot.is_empty() || cycle)) {
            // The one-shots that move otherwise than by G00-G03.
            let special = cycle
                || one_shot.iter().any(|g| {
                    matches!(
                        self.gcode(g.0).map(|c| c.means),
                        Some(Means::OneShot(
                            Os::RefReturn(_)
                                | Os::MachineCoords
                                | Os::Skip
                                | Os::ToolOffset(_)
                                | Os::Mrc(_)
                        ))
                    )
                });
            let setting = one_shot.iter().any(|g| self.is_coordinate_setting(g.0));
            self.comp_codes(one_shot, special, setting)
        } else {
            Ok(false)
        }
    }

    /// The block's M codes checked; the M98/M99 it carries (one at most).
    fn classify_m(&self) -> R<Option<(MAction, u32)>> {
        let mut transfer: Option<(MAction, u32)> = None;
        for i in 0..self.words.nm {
            let (m, at) = self.words.m[i];
            if self.mcode(m).is_none() {
                // Fanuc programs ask for rigid tapping with M29 before G84;
                // the HX has G84.2/G84.3 instead (000 §12.3.5-12.3.6).
                let rigid = Means::Cycle(Some(HoleCycle::RigidTap));
                let hint = if m == 29 && self.cfg.dialect.gcodes.iter().any(|g| g.means == rigid) {
                    ": rigid tapping on this control is G84.2 (G84.3 left-hand), without M29"
                } else {
                    ""
                };
                return Err(self.alarm(
                    AlarmKind::UnknownM,
                    at,
                    format!("M{m:02} is not an M code of this control{hint}"),
                ));
            }
            if let Some(mc) = self.mcode(m) {
                if matches!(mc.action, MAction::SubCall | MAction::SubReturn) {
                    if transfer.is_some() {
                        return Err(self.alarm(
                            AlarmKind::MCodeConflict,
                            at,
                            "M98 and M99 in one block",
                        ));
                    }
                    transfer = Some((mc.action, at));
                }
            }
        }
        Ok(transfer)
    }

    /// Runs the block's one-shot codes that act before motion (G10 on
    /// the PUMA, coordinate setting, G59 on the Hurco) and notes the rest.
    fn one_shots(&mut self, one_shot: &[(u16, u32)]) -> R<OneShots> {
        use crate::dialect::meaning::OneShot::*;
        let mut os = OneShots::default();
        for &(c, at) in one_shot {
            let Some(Means::OneShot(what)) = self.gcode(c).map(|g| g.means) else {
                continue;
            };
            match what {
                Dwell => os.dwell = true,
                RefReturn(kind) => os.refret = Some((kind, at)),
                ExactStop => os.g09 = true,
                SingleDirection => os.g60 = Some(at),
                MachineCoords => {
                    if self.cfg.dialect.caps.g53_checks {
                        self.g53_checks(at)?;
                    }
                    os.g53 = true
                }
                Skip => os.skip = Some((c, at)),
                ToolOffset(k) => os.g45 = Some((k, c, at)),
                DataSetting => {
                    os.setting = true;
                    self.g10(at)?
                }
                Mrc(kind) => os.mrc = Some((kind, c, at)),
                CoordinateSetting => {
                    os.setting = true;
                    self.coordinate_setting(at)?
                }
                CancelWorkShift => *self.frames.shift_mut() = [0.0; NAXES],
                MacroCall | FrameData | LocalCoords | CompCorner | Probe | ThreadCycle => {}
            }
        }
        Ok(os)
    }

    /// The block's motion: a reference return, a skip, a lathe cycle, or
    /// (when the block's axis words are a move) G53, a canned cycle, G60,
    /// G45-G48 or the modal motion. `cycles`: (HX cycle mode, entered
    /// before this block, Hurco cycle mode).
    fn block_motion(
        &mut self,
        os: &OneShots,
        no_motion: bool,
        cycles: (bool, bool, bool),
    ) -> R<()> {
        let (cycle, was_cycle, hurco_cycle) = cycles;
        if let Some((kind, at)) = os.refret {
            self.reference_return(kind, at)?;
        } else if let Some((c, at)) = os.skip {
            self.skip_block(c, at)?;
        } else if let Some((kind, c, at)) = os.mrc {
            self.mrc(kind, c, at)?;
        } else if !no_motion {
            if os.g53 {
                self.g53()?;
            } else if cycle {
                self.canned_cycle(!was_cycle, os.g60.is_some())?;
            } else if hurco_cycle {
                if self.words.has(b'X') || self.words.has(b'Z') || self.words.has(b'R') {
                    self.hurco_drill()?;
                }
            } else if let Some(at) = os.g60 {
                self.g60(at)?;
            } else if let Some((k, c, at)) = os.g45 {
                self.tool_offset_motion((k, c), at)?;
            } else {
                self.motion()?;
            }
        }
        Ok(())
    }
}
