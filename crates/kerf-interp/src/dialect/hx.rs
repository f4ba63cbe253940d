//! TurboTek HX machining-center control: the G-code table of 000 §3.1 with
//! its modal groups as printed there, the reset defaults of §3.2 (PI 144-150
//! at their factory values), and the general M codes of 000 §11.1.
//!
//! Where the extraction of 000 is unreadable or kerf departs from it, the
//! decision is recorded in docs/dialects.md.
use super::MAction::*;
use super::MWhen::*;
use super::Support::*;
use super::*;

/// G codes of 000 §3.1. Group numbers are the ones the table prints (they
/// are not Fanuc's: plane = 16, G43/G44/G49 = 13, G68/G69 = 18, …), with
/// two exceptions recorded in docs/dialects.md: G31-G31.4 (printed 23, a
/// group §3.2 counts as non-modal together with group 0) are one-shot here,
/// and G63.1/G63.2 (§15.6, absent from §3.1) get kerf's group 24.
/// A table row with its meaning ([`means`]).
const fn g(code10: u16, group: u8, default: bool, name: &'static str, support: Support) -> GCode {
    super::g(code10, group, default, name, support, means(code10, group))
}

/// What an HX modal code means (000 §3.1); a code without one is a
/// compile-time error in [`GCODES`].
const fn means(code10: u16, group: u8) -> Means {
    use super::meaning::*;
    if group == 0 {
        return Means::OneShot(match code10 {
            100 => OneShot::FrameData,
            520 => OneShot::LocalCoords,
            310..=314 | 370..=374 => OneShot::Skip,
            390 => OneShot::CompCorner,
            450 => OneShot::ToolOffset(1),
            460 => OneShot::ToolOffset(-1),
            470 => OneShot::ToolOffset(2),
            480 => OneShot::ToolOffset(-2),
            600 => OneShot::SingleDirection,
            920 => OneShot::CoordinateSetting,
            c => match common_one_shot(c) {
                Some(o) => o,
                None => panic!("HX one-shot G code without a meaning"),
            },
        });
    }
    if let Some(m) = common(code10) {
        return m;
    }
    match code10 {
        103 => Means::HighSpeed(true),
        113 => Means::HighSpeed(false),
        150 => Means::PolarCommand(false),
        160 => Means::PolarCommand(true),
        220 => Means::Stroke(true),
        230 => Means::Stroke(false),
        330 => Means::Motion(MotionMode::ThreadF),
        430 => Means::LengthComp(LengthComp::Plus),
        440 => Means::LengthComp(LengthComp::Minus),
        490 => Means::LengthComp(LengthComp::Off),
        500 => Means::Scaling(false),
        510 => Means::Scaling(true),
        610 => Means::CuttingMode(CuttingMode::ExactStop),
        620 => Means::CuttingMode(CuttingMode::CornerOverride),
        630 => Means::CuttingMode(CuttingMode::Tapping),
        640 => Means::CuttingMode(CuttingMode::Cutting),
        631 => Means::Stitch(true),
        632 => Means::Stitch(false),
        680 => Means::Rotation(true),
        690 => Means::Rotation(false),
        800 => Means::Cycle(None),
        730 => Means::Cycle(Some(HoleCycle::PeckChipBreak)),
        740 => Means::Cycle(Some(HoleCycle::TapLeft)),
        760 => Means::Cycle(Some(HoleCycle::FineBore)),
        810 => Means::Cycle(Some(HoleCycle::Drill)),
        820 => Means::Cycle(Some(HoleCycle::DrillDwell)),
        830 => Means::Cycle(Some(HoleCycle::Peck)),
        840 => Means::Cycle(Some(HoleCycle::Tap)),
        842 => Means::Cycle(Some(HoleCycle::RigidTap)),
        843 => Means::Cycle(Some(HoleCycle::RigidTapLeft)),
        850 => Means::Cycle(Some(HoleCycle::Bore)),
        860 => Means::Cycle(Some(HoleCycle::BoreStop)),
        870 => Means::Cycle(Some(HoleCycle::BackBore)),
        880 => Means::Cycle(Some(HoleCycle::ManualBore)),
        890 => Means::Cycle(Some(HoleCycle::BoreDwell)),
        980 => Means::CycleReturn(CycleReturn::Initial),
        990 => Means::CycleReturn(CycleReturn::RPoint),
        1070 => Means::Cylindrical(true),
        1120 => Means::PolarInterp(true),
        1130 => Means::PolarInterp(false),
        _ => panic!("HX modal G code without a meaning"),
    }
}

#[rustfmt::skip]
pub static GCODES: &[GCode] = &[
    g(0, 1, true, "rapid traverse positioning", Yes), // default: PI 144 = 0
    g(10, 1, false, "linear interpolation", Yes),     // default when PI 144 = 1
    g(20, 1, false, "circular/helical interpolation CW", Yes),
    g(30, 1, false, "circular/helical interpolation CCW", Yes),
    g(40, 0, false, "dwell", Yes),
    g(90, 0, false, "exact stop", Yes),
    g(100, 0, false, "setting data", Yes), // §13.1.3: G10 L10 (H) / L12 (D)
    g(103, 21, false, "high speed machining start", Yes),
    g(113, 21, true, "high speed machining end", Yes),
    g(150, 17, true, "polar coordinate command cancel", Yes),
    g(160, 17, false, "polar coordinate command", Yes),
    g(170, 16, true, "X-Y plane selection", Yes), // default: PI 145 = 0
    g(180, 16, false, "Z-X plane selection", Yes),
    g(190, 16, false, "Y-Z plane selection", Yes),
    g(200, 6, false, "inch", Yes),
    g(210, 6, true, "metric", Yes), // default: PI 147 = 1
    g(220, 9, true, "stored stroke check on", Yes), // default: PI 148 = 0 (§3.2 factory value)
    g(230, 9, false, "stored stroke check off", Yes),
    g(270, 0, false, "reference position return check", Yes),
    g(280, 0, false, "reference position return", Yes),
    g(290, 0, false, "return from reference position", Yes),
    g(300, 0, false, "return to 2nd, 3rd, 4th reference position", Yes),
    g(310, 0, false, "skip function", Yes), // §3.1 prints group 23 for G31-G31.4
    g(311, 0, false, "multi-step skip function 1", Yes),
    g(312, 0, false, "multi-step skip function 2", Yes),
    g(313, 0, false, "multi-step skip function 3", Yes),
    g(314, 0, false, "multi-step skip function 4", Yes),
    g(330, 1, false, "constant lead thread cutting", Yes),
    g(370, 0, false, "automatic tool length measurement", Yes),
    g(371, 0, false, "automatic tool length measurement 1", Yes),
    g(372, 0, false, "automatic tool length measurement 2", Yes),
    g(373, 0, false, "automatic tool length measurement 3", Yes),
    g(374, 0, false, "automatic tool length measurement 4", Yes),
    g(390, 0, false, "tool diameter compensation at corner arc", Yes),
    g(400, 7, true, "tool diameter compensation cancel", Yes),
    g(410, 7, false, "tool diameter compensation left", Yes),
    g(420, 7, false, "tool diameter compensation right", Yes),
    g(430, 13, false, "tool length compensation +", Yes),
    g(440, 13, false, "tool length compensation -", Yes),
    g(450, 0, false, "tool offset increase", Yes),
    g(460, 0, false, "tool offset decrease", Yes),
    g(470, 0, false, "tool offset double increase", Yes),
    g(480, 0, false, "tool offset double decrease", Yes),
    g(490, 13, true, "tool length compensation cancel", Yes),
    g(500, 11, true, "scaling cancel, mirror image cancel", Yes), // default: PI 149 = 0
    g(510, 11, false, "scaling, mirror image", Yes),
    g(520, 0, false, "local coordinate system setting", Yes),
    g(530, 0, false, "machine coordinate system selection", Yes),
    g(540, 14, true, "work coordinate 1 selection", Yes),
    g(550, 14, false, "work coordinate 2 selection", Yes),
    g(560, 14, false, "work coordinate 3 selection", Yes),
    g(570, 14, false, "work coordinate 4 selection", Yes),
    g(580, 14, false, "work coordinate 5 selection", Yes),
    g(590, 14, false, "work coordinate 6 selection", Yes),
    g(600, 0, false, "single direction positioning", Yes),
    g(610, 15, false, "exact stop mode", Yes),
    g(620, 15, false, "automatic corner override mode", Yes),
    g(630, 15, false, "tapping mode", Yes),
    g(640, 15, true, "cutting mode", Yes),
    g(631, 24, false, "stitch function mode on", Yes), // §15.6; group is kerf's
    g(632, 24, true, "stitch function mode off", Yes),
    g(650, 0, false, "macro call", Yes),
    g(660, 12, false, "macro modal call", Yes),
    g(670, 12, true, "macro modal call cancel", Yes),
    g(680, 18, false, "coordinate system rotation", Yes),
    g(690, 18, true, "coordinate system rotation cancel", Yes), // default: PI 150 = 0
    g(730, 10, false, "high speed peck drilling cycle", Yes),
    g(740, 10, false, "counter tapping cycle", Yes),
    g(760, 10, false, "fine boring cycle", Yes),
    g(800, 10, true, "canned cycle cancel", Yes),
    g(810, 10, false, "drilling cycle, spot drilling cycle", Yes),
    g(820, 10, false, "drilling dwell cycle, counter boring cycle", Yes),
    g(830, 10, false, "peck drilling cycle", Yes),
    g(840, 10, false, "tapping cycle", Yes),
    g(842, 10, false, "rigid tap cycle", Yes),
    g(843, 10, false, "rigid counter tap cycle", Yes),
    g(850, 10, false, "boring cycle", Yes),
    g(860, 10, false, "boring stop cycle", Yes),
    g(870, 10, false, "back boring cycle", Yes),
    g(880, 10, false, "manual boring cycle", Yes),
    g(890, 10, false, "boring dwell cycle", Yes),
    g(900, 3, true, "absolute command", Yes), // default: PI 146 = 0
    g(910, 3, false, "incremental command", Yes),
    g(920, 0, false, "work coordinate setting, maximum spindle speed", Yes),
    g(940, 5, true, "feed per minute", Yes),
    g(950, 5, false, "feed per revolution", Yes),
    g(960, 2, false, "constant surface speed control", Yes),
    g(970, 2, true, "constant surface speed control cancel", Yes),
    g(980, 19, true, "return to initial point at a canned cycle", Yes),
    g(990, 19, false, "return to R-point at a canned cycle", Yes),
    g(1070, 22, false, "cylindrical interpolation", Yes),
    g(1120, 20, false, "polar coordinate interpolation mode on", Yes),
    g(1130, 20, true, "polar coordinate interpolation mode off", Yes),
];

/// M codes of 000 §11.1 ("Table of General M Codes"): M00-M06, M08, M09,
/// M30, M98, M99. §11.1 leaves every other number (M00-M999) to the machine
/// tool builder; kerf adds the two standard Fanuc machining-centre builder
/// codes M07 and M19 (marked "assumed"). M29 is not an HX code: the HX taps
/// rigidly with G84.2/G84.3 (§12.3.5), not with M29 + G84.
#[rustfmt::skip]
pub static MCODES: &[MCode] = &[
    m(0, "program stop", After, Stop),
    m(1, "optional stop", After, OptionalStop),
    m(2, "end of program", After, End),
    m(3, "spindle CW", Before, SpindleCw),
    m(4, "spindle CCW", Before, SpindleCcw),
    m(5, "spindle stop", After, SpindleStop),
    m(6, "tool change (ATC)", Before, ToolChange),
    m(7, "coolant mist on", Before, CoolantMist), // assumed (builder code, not in §11.1)
    m(8, "coolant on", Before, CoolantFlood),
    m(9, "coolant off", After, CoolantOff),
    m(19, "spindle orientation", After, Aux).and(MAlso::Orient), // assumed (builder code, not in §11.1)
    m(30, "end of tape", After, End),
    m(98, "sub-program call", After, SubCall),
    m(99, "end of sub-program", After, SubReturn),
];

/// The HX dialect.
pub static DIALECT: Dialect = Dialect {
    id: DialectId::Hx,
    gcodes: GCODES,
    mcodes: MCODES,
    letters: b"ABCDEFGHIJKLMNOPQRSTUVWXYZ",
    long_names: &[],
    diameter_default: false,
    uvw_incremental: false,
    hurco_syntax: false,
    order: super::FANUC_MILL,
    alarm_column: alarm_codes::AlarmColumn::Hx,
    macro_calls: [650, 660],
    caps: Caps {
        bracket_nesting: 10,
        power_on_params: true,
        g53_checks: false,
        comma_corners: true,
        frame_codes: true,
        rotary_interp: true,
        max_loop_label: 9999,
        sub_nesting: 8,
        m98_q_m99_l: true,
        dwell_revs_param: true,
        word_ranges: false,
        dwell_is_f: false,
        css_radius_word: false,
        linear_rapid: false,
        stops_stop_spindle: false,
        max_m_per_block: 3,
        offsets_wait_for_move: false,
        reset_keeps_tool_offset: false,
        part_zero_is_e1: false,
        gcode_system_b: false,
        short_r_half_circle: false,
        direct_drawing: false,
        hx_variables: true,
        comp: CompParams {
            type_b: ("PI 128", 0.0, 1.0),
            idle_blocks: 2.0,
            circular_joining: false,
        },
        restricted_words: false,
    },
};
