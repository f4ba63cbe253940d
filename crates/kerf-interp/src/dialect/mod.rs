//! Dialects: the per-control data tables (G codes with modal groups and
//! defaults, M codes with their execution category) and the few switches
//! in which the controls' languages differ. One interpreter reads them all.

pub mod alarm_codes;
pub mod hurco;
pub mod hx;
pub mod meaning;
pub mod puma;
pub mod system_b;

pub use meaning::Means;

/// Which control's language a profile speaks.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Deserialize, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum DialectId {
    /// TurboTek HX machining-center control (000).
    Hx,
    /// Fanuc 0-T on the Daewoo PUMA 450, G-code system A (001).
    Puma,
    /// Hurco MAX turning-center control (002).
    Hurco,
}

/// How far kerf implements a code.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Support {
    /// Executed.
    Yes,
    /// Recognised; executed once the named issue lands. Until then using it
    /// stops with alarm `KERF-0100` "not yet supported".
    Later(&'static str),
}

/// One G code of a dialect.
#[derive(Clone, Copy, Debug)]
pub struct GCode {
    /// The code times ten: G01 = 10, G10.3 = 103, G84.2 = 842.
    pub code10: u16,
    /// Modal group; 0 = one-shot (non-modal).
    pub group: u8,
    /// Power-on / reset default of its group.
    pub default: bool,
    /// The manual's name for it.
    pub name: &'static str,
    pub support: Support,
    /// What it means: the modal state it sets, or what a one-shot
    /// (group 0) code does.
    pub means: Means,
}

/// When an M code acts relative to the motion of its block.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MWhen {
    /// Before the block's motion (spindle start, coolant on, …).
    Before,
    /// Hurco job syncing (M100-M199): before everything else of the
    /// block (002 Table 1, first row).
    JobSync,
    /// After the block's motion (spindle stop, program stop, end, …).
    After,
}

/// What an M code does to the modelled machine state.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MAction {
    /// Only an auxiliary event with the manual's name.
    Aux,
    SpindleCw,
    SpindleCcw,
    SpindleStop,
    CoolantMist,
    CoolantFlood,
    CoolantOff,
    /// M00.
    Stop,
    /// M01.
    OptionalStop,
    /// M02 / M30.
    End,
    /// M06 tool change.
    ToolChange,
    /// M98 subprogram call.
    SubCall,
    /// M99 subprogram return.
    SubReturn,
    /// 002 M48 (true) / M49: use / ignore the feedrate override (an
    /// auxiliary event, then the mode).
    FeedOverride(bool),
}

/// One M code of a dialect.
#[derive(Clone, Copy, Debug)]
pub struct MCode {
    pub code: u16,
    pub name: &'static str,
    pub when: MWhen,
    pub action: MAction,
    /// What the code does besides its action.
    pub also: MAlso,
}

/// What an M code does besides its [`MAction`] (a PUMA compound code,
/// the orientation a cycle emits).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MAlso {
    Nothing,
    /// PUMA M63/M64: the coolant on with the spindle, before the motion.
    CoolantOn,
    /// PUMA M65: the coolant off with the spindle, after the motion.
    CoolantOff,
    /// PUMA M76 (true) / M77: thread chamfering in G92/G76.
    ThreadChamfer(bool),
    /// The spindle orientation code the HX cycles G76/G87 emit for their
    /// oriented stop.
    Orient,
}

/// The language of one control.
#[derive(Debug)]
pub struct Dialect {
    pub id: DialectId,
    pub gcodes: &'static [GCode],
    pub mcodes: &'static [MCode],
    /// Addresses (upper-case letters) the control accepts at all.
    pub letters: &'static [u8],
    /// Multi-letter parameter names (Hurco G78).
    pub long_names: &'static [&'static str],
    /// X is programmed as a diameter by default (lathes).
    pub diameter_default: bool,
    /// U/V/W are incremental X/Y/Z (Fanuc lathe G-code system A).
    pub uvw_incremental: bool,
    /// Hurco: loop commands in comments, `\` continuation.
    pub hurco_syntax: bool,
    /// The order in which a block's codes execute: [`FANUC_MILL`] on the
    /// HX, [`FANUC_LATHE`] on the PUMA, [`HURCO_TABLE_1`] on the Hurco.
    pub order: &'static [Phase],
    /// What the control's language has or lacks beyond its tables.
    pub caps: Caps,
    /// The alarm codes the control shows.
    pub alarm_column: alarm_codes::AlarmColumn,
    /// The codes of the macro call and the macro modal call (G65, G66):
    /// a block with one reads its letters as arguments. The Hurco, whose
    /// table has neither, lists them too, so that such a block alarms on
    /// the unknown code rather than on one of its arguments.
    pub macro_calls: [u16; 2],
}

/// The features in which the three controls' languages differ, one fact
/// each, so that the interpreter asks the dialect instead of naming it.
#[derive(Debug)]
pub struct Caps {
    /// Bracket nesting levels in a macro expression: 10 on the HX (000
    /// §14.2.4), Fanuc's 5 elsewhere.
    pub bracket_nesting: u8,
    /// The HX power-on parameters PI 144-147 (000 §3.2) set the motion,
    /// plane, distance and unit defaults.
    pub power_on_params: bool,
    /// 002: a G53 block's own checks (interp/hurco.rs).
    pub g53_checks: bool,
    /// The HX `,C` / `,R` chamfer and corner R words.
    pub comma_corners: bool,
    /// The HX frame codes G15/G16, G50/G51, G68/G69, G52.
    pub frame_codes: bool,
    /// The HX polar (G112/G113) and cylindrical (G107) interpolation.
    pub rotary_interp: bool,
    /// The highest WHILE … DO label: 1-9999 on the HX, Fanuc's 1-3.
    pub max_loop_label: u32,
    /// Subprogram nesting when the profile does not say (HX 8, Fanuc 4).
    pub sub_nesting: u8,
    /// HX M98 takes the repeat count as Q and M99 a return count L.
    pub m98_q_m99_l: bool,
    /// HX PI 120: in G95 a G04 counts spindle revolutions (000 §5.4).
    pub dwell_revs_param: bool,
    /// 002: the word ranges of the Hurco are checked per word.
    pub word_ranges: bool,
    /// 002: in a G04 block F is the dwell, not a feed.
    pub dwell_is_f: bool,
    /// 002: G96 takes the radius of the surface speed as R.
    pub css_radius_word: bool,
    /// 002: rapids move in a straight line (no dog-leg).
    pub linear_rapid: bool,
    /// 002: M00, M01, M02 and M30 stop the spindle.
    pub stops_stop_spindle: bool,
    /// M codes one block may carry: 3 (Fanuc), as many as the block holds
    /// (002).
    pub max_m_per_block: usize,
    /// 002 Table 16: the offsets of a T or E code take effect with the
    /// next move, and a move's words go to the position they name.
    pub offsets_wait_for_move: bool,
    /// 002: RESET keeps the T offset in force (with its number) and drops
    /// the drill data and an offset change waiting for its move.
    pub reset_keeps_tool_offset: bool,
    /// 002: the part zero is fixture offset E1.
    pub part_zero_is_e1: bool,
    /// The PUMA's G-code system B (profile `gcode_system_b`).
    pub gcode_system_b: bool,
    /// 001 p.15 note (4): an arc R shorter than half the move makes a
    /// half circle instead of an alarm.
    pub short_r_half_circle: bool,
    /// 001: A, D, L and E are read only by the codes that use them (PS009
    /// otherwise).
    pub restricted_words: bool,
    /// 001: direct drawing dimension input (the angle A, the direct
    /// chamfer and corner R of the next block).
    pub direct_drawing: bool,
    /// How cutter / nose radius compensation reads the profile.
    pub comp: CompParams,
    /// The HX numbering of system variables (000 §14: #2001-, #5001-)
    /// and its calls by G, M and T code (PI 85-105).
    pub hx_variables: bool,
}

/// The profile parameters of a control's compensation.
#[derive(Debug)]
pub struct CompParams {
    /// The parameter that selects start-up and cancel type B, its
    /// default, and the value that means type B: HX PI 128 = 1, PUMA
    /// `comp_type_b` = 1, Hurco `comp_exit_normal` = 0 (type B unless
    /// the exit is along the normal).
    pub type_b: (&'static str, f64, f64),
    /// The default of `comp_idle_blocks`, the blocks without a move in
    /// the plane the look-ahead waits: 2 (HX, Hurco), 1 (PUMA).
    pub idle_blocks: f64,
    /// 002: circular joining of outside corners (`comp_circular_joining`).
    pub circular_joining: bool,
}

/// One step of executing a block. A dialect lists its steps in the
/// control's order ([`Dialect::order`]) and executing a block is a walk
/// over that list (interp/phases.rs); the block's G and M codes are
/// checked before the first step.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Phase {
    /// Hurco: the G78/G38 block and mode checks of 002.
    HurcoChecks,
    /// Hurco: the job-synchronisation M codes M100-M199 (002 Table 1, first).
    JobSyncM,
    /// The modal G codes (every group but 0 and 1) and the motion mode.
    ModalG,
    /// HX: the canned cycle mode (group 10) entered, kept or left.
    HxCycleMode,
    /// Hurco: the drill cycle mode.
    HurcoCycleMode,
    /// Hurco: a G78 or G38 block runs as its cycle, which ends the block.
    HurcoMacro,
    /// G112/G113/G107 and the coordinate frame codes (G15/G16, G50/G51,
    /// G68/G69, G52, G10 L2).
    Frames,
    /// D, and G43/G44/G49 with H.
    ToolLength,
    /// Cutter / nose radius compensation codes (G39-G42, D).
    Comp,
    /// The one-shot codes that act before motion (G10 on the PUMA,
    /// G92/G50, Hurco G59); the others are noted for the motion.
    OneShots,
    /// Hurco: the G96 R radius.
    CssRadius,
    /// Hurco: M48/M49 (feed and speed overrides).
    OverrideM,
    /// Hurco: M07/M08 coolant.
    CoolantM,
    /// Hurco: the T and E codes (tool and fixture offsets).
    ToolAndFixture,
    /// F.
    Feed,
    /// T (Fanuc).
    Tool,
    /// S and the spindle M codes.
    Spindle,
    /// Fanuc: the before-motion M codes other than spindle start.
    MBefore,
    /// Hurco: the before-motion M codes not run in the phases above.
    HurcoMBefore,
    /// G04.
    Dwell,
    /// PUMA: the coolant part of M63-M65 and M76/M77 chamfering.
    PumaM,
    /// Fanuc: G09 exact stop, before the motion.
    ExactStopBefore,
    /// The block's motion.
    Motion,
    /// Hurco: the block moved (offsets waiting for a move, Table 16).
    Moved,
    /// Hurco: G09 exact stop, after the motion (Table 1).
    ExactStopAfter,
    /// The after-motion M codes other than M00/M01/M02/M30.
    MAfter,
    /// PUMA: the after-motion part of M76/M77.
    PumaMAfter,
    /// M00, M01, M02, M30.
    Stop,
    /// Compensation's end of block (look-ahead count).
    CompEnd,
    /// M98 / M99 (or the G66 modal call) last; nothing after the end.
    Transfer,
}

/// The Fanuc order on the HX (000; fanuc-semantics §2).
pub static FANUC_MILL: &[Phase] = &[
    Phase::ModalG,
    Phase::HxCycleMode,
    Phase::Frames,
    Phase::ToolLength,
    Phase::Comp,
    Phase::OneShots,
    Phase::Feed,
    Phase::Tool,
    Phase::Spindle,
    Phase::MBefore,
    Phase::Dwell,
    Phase::ExactStopBefore,
    Phase::Motion,
    Phase::MAfter,
    Phase::Stop,
    Phase::CompEnd,
    Phase::Transfer,
];

/// The Fanuc order on the PUMA (Fanuc 0-T), with its compound M codes.
pub static FANUC_LATHE: &[Phase] = &[
    Phase::ModalG,
    Phase::Frames,
    Phase::ToolLength,
    Phase::Comp,
    Phase::OneShots,
    Phase::Feed,
    Phase::Tool,
    Phase::Spindle,
    Phase::MBefore,
    Phase::Dwell,
    Phase::PumaM,
    Phase::ExactStopBefore,
    Phase::Motion,
    Phase::MAfter,
    Phase::PumaMAfter,
    Phase::Stop,
    Phase::CompEnd,
    Phase::Transfer,
];

/// 002 Table 1, row by row: job-sync M codes first, the modal and
/// one-shot codes, G96 R, M48/M49, M07/M08, T and E, S, the other
/// before-motion M codes, G04, F, the motion, G09 after it, the
/// after-motion M codes, M00/M01/M02/M30, then M98/M99.
pub static HURCO_TABLE_1: &[Phase] = &[
    Phase::HurcoChecks,
    Phase::JobSyncM,
    Phase::ModalG,
    Phase::HurcoCycleMode,
    Phase::HurcoMacro,
    Phase::Frames,
    Phase::ToolLength,
    Phase::Comp,
    Phase::OneShots,
    Phase::CssRadius,
    Phase::OverrideM,
    Phase::CoolantM,
    Phase::ToolAndFixture,
    Phase::Spindle,
    Phase::HurcoMBefore,
    Phase::Dwell,
    Phase::Feed,
    Phase::Motion,
    Phase::Moved,
    Phase::ExactStopAfter,
    Phase::MAfter,
    Phase::Stop,
    Phase::CompEnd,
    Phase::Transfer,
];

impl Dialect {
    /// The dialect for an id.
    pub fn get(id: DialectId) -> &'static Dialect {
        match id {
            DialectId::Hx => &hx::DIALECT,
            DialectId::Puma => &puma::DIALECT,
            DialectId::Hurco => &hurco::DIALECT,
        }
    }

    /// Looks up a G code by its value times ten.
    pub fn gcode(&self, code10: u16) -> Option<&'static GCode> {
        self.gcodes.iter().find(|g| g.code10 == code10)
    }

    /// Looks up an M code.
    pub fn mcode(&self, code: u16) -> Option<&'static MCode> {
        self.mcodes.iter().find(|m| m.code == code)
    }
}

/// Shorthand for the tables.
pub(crate) const fn g(
    code10: u16,
    group: u8,
    default: bool,
    name: &'static str,
    support: Support,
    means: Means,
) -> GCode {
    GCode {
        code10,
        group,
        default,
        name,
        support,
        means,
    }
}

/// Shorthand for the tables.
pub(crate) const fn m(code: u16, name: &'static str, when: MWhen, action: MAction) -> MCode {
    MCode {
        code,
        name,
        when,
        action,
        also: MAlso::Nothing,
    }
}

impl MCode {
    /// The same code doing `also` besides its action.
    pub(crate) const fn and(self, also: MAlso) -> MCode {
        MCode { also, ..self }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every table is well formed: codes unique, exactly one default per
    /// modal group that has one, one-shot codes never default.
    #[test]
    fn tables_are_consistent() {
        for id in [DialectId::Hx, DialectId::Puma, DialectId::Hurco] {
            let d = Dialect::get(id);
            for (i, a) in d.gcodes.iter().enumerate() {
                for b in &d.gcodes[i + 1..] {
                    assert_ne!(a.code10, b.code10, "{id:?} duplicate G{}", a.code10);
                }
                if a.group == 0 {
                    assert!(!a.default, "{id:?} one-shot G{} marked default", a.code10);
                }
            }
            let mut groups: Vec<u8> = d
                .gcodes
                .iter()
                .map(|g| g.group)
                .filter(|&g| g != 0)
                .collect();
            groups.sort();
            groups.dedup();
            for grp in groups {
                let n = d
                    .gcodes
                    .iter()
                    .filter(|g| g.group == grp && g.default)
                    .count();
                assert!(n <= 1, "{id:?} group {grp} has {n} defaults");
            }
            for (i, a) in d.mcodes.iter().enumerate() {
                for b in &d.mcodes[i + 1..] {
                    assert_ne!(a.code, b.code, "{id:?} duplicate M{}", a.code);
                }
            }
        }
    }

    /// 001's compound M codes and the orientation code of the HX cycles
    /// (M19) are in the tables.
    #[test]
    fn m_codes_besides_their_action() {
        let also = |id, code| Dialect::get(id).mcode(code).map(|m| m.also);
        assert_eq!(also(DialectId::Hx, 19), Some(MAlso::Orient));
        assert_eq!(also(DialectId::Puma, 63), Some(MAlso::CoolantOn));
        assert_eq!(also(DialectId::Puma, 64), Some(MAlso::CoolantOn));
        assert_eq!(also(DialectId::Puma, 65), Some(MAlso::CoolantOff));
        assert_eq!(also(DialectId::Puma, 76), Some(MAlso::ThreadChamfer(true)));
        assert_eq!(also(DialectId::Puma, 77), Some(MAlso::ThreadChamfer(false)));
        for id in [DialectId::Hx, DialectId::Puma, DialectId::Hurco] {
            let n = Dialect::get(id)
                .mcodes
                .iter()
                .filter(|m| m.also == MAlso::Orient)
                .count();
            assert!(n <= 1, "{id:?}: {n} orientation codes");
        }
    }

    /// The macro call codes are the table's G65 (`OneShot::MacroCall`)
    /// and G66 (`ModalCall(true)`) where the table has them.
    #[test]
    fn macro_call_codes() {
        use meaning::OneShot;
        for id in [DialectId::Hx, DialectId::Puma, DialectId::Hurco] {
            let d = Dialect::get(id);
            assert_eq!(d.macro_calls, [650, 660], "{id:?}");
            for g in d.gcodes {
                let call = matches!(
                    g.means,
                    Means::OneShot(OneShot::MacroCall) | Means::ModalCall(true)
                );
                assert_eq!(
                    call,
                    d.macro_calls.contains(&g.code10),
                    "{id:?} G{}",
                    g.code10
                );
            }
        }
    }

    /// Each control's order: every phase once, the motion once, the
    /// transfer (M98/M99) last; Fanuc G09 before the motion, 002 Table 1
    /// G09 after it, its job-sync M codes before the modal codes and F
    /// after G04.
    #[test]
    fn block_orders() {
        let pos = |o: &[Phase], p: Phase| o.iter().position(|&q| q == p);
        for d in [DialectId::Hx, DialectId::Puma, DialectId::Hurco] {
            let o = Dialect::get(d).order;
            for (i, p) in o.iter().enumerate() {
                assert!(!o[i + 1..].contains(p), "{d:?}: {p:?} twice");
            }
            assert!(pos(o, Phase::Motion).is_some(), "{d:?}");
            assert_eq!(o.last(), Some(&Phase::Transfer), "{d:?}");
        }
        let before = |o: &[Phase], a: Phase, b: Phase| pos(o, a).unwrap() < pos(o, b).unwrap();
        for o in [FANUC_MILL, FANUC_LATHE] {
            assert!(before(o, Phase::Feed, Phase::Dwell));
            assert!(before(o, Phase::ExactStopBefore, Phase::Motion));
            assert!(pos(o, Phase::ExactStopAfter).is_none());
        }
        let h = HURCO_TABLE_1;
        assert!(before(h, Phase::JobSyncM, Phase::ModalG));
        assert!(before(h, Phase::Dwell, Phase::Feed));
        assert!(before(h, Phase::Motion, Phase::ExactStopAfter));
        assert!(before(h, Phase::ExactStopAfter, Phase::MAfter));
        assert!(before(h, Phase::MAfter, Phase::Stop));
        assert!(pos(h, Phase::ExactStopBefore).is_none());
    }
}
