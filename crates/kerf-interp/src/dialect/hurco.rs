//! Hurco MAX turning-center control (002): its G codes, M codes with their
//! execution categories (Table 1), and the G78 multi-letter parameter names.
//!
//! Where 002 is silent or kerf departs from it, the decision is recorded in
//! docs/dialects.md.
use super::MAction::*;
use super::MWhen::*;
use super::Support::*;
use super::*;

/// G codes 002 documents (pages 14-55), with the "(default)" marks of their
/// headings: G00, G40, G90, G94, G97, G98. 002 prints no group numbers; the
/// groups follow Fanuc where the code exists there, G07/G08 get kerf's
/// group 24. G70 is not documented but opens every G78 sample program
/// ("G70 G90 M03 S120") where it can only be Hurco's legacy inch code.
/// Table 1 also names G58, G201 and G202, which 002 never defines; they are
/// not in the table (see docs/dialects.md), nor are G85-G89, which 002
/// mentions only as "G81-G89 drill cycles".
/// A table row with its meaning ([`means`]).
const fn g(code10: u16, group: u8, default: bool, name: &'static str, support: Support) -> GCode {
    super::g(code10, group, default, name, support, means(code10, group))
}

/// What a Hurco modal code means (002); a code without one is a
/// compile-time error in [`GCODES`].
const fn means(code10: u16, group: u8) -> Means {
    use super::meaning::*;
    if group == 0 {
        return Means::OneShot(match code10 {
            380 => OneShot::Probe,
            590 => OneShot::CancelWorkShift,
            780 => OneShot::ThreadCycle,
            920 => OneShot::CoordinateSetting,
            c => match common_one_shot(c) {
                Some(o) => o,
                None => panic!("Hurco one-shot G code without a meaning"),
            },
        });
    }
    if let Some(m) = common(code10) {
        return m;
    }
    match code10 {
        70 => Means::Diameter(false),
        80 => Means::Diameter(true),
        330 => Means::Motion(MotionMode::ThreadKI),
        700 => Means::Units(Units::Inch),
        800 => Means::Cycle(None),
        730 => Means::Cycle(Some(HoleCycle::PeckChipBreak)),
        740 => Means::Cycle(Some(HoleCycle::TapLeft)),
        810 => Means::Cycle(Some(HoleCycle::Drill)),
        820 => Means::Cycle(Some(HoleCycle::DrillDwell)),
        830 => Means::Cycle(Some(HoleCycle::Peck)),
        840 => Means::Cycle(Some(HoleCycle::Tap)),
        980 => Means::CycleReturn(CycleReturn::Initial),
        990 => Means::CycleReturn(CycleReturn::RPoint),
        _ => panic!("Hurco modal G code without a meaning"),
    }
}

#[rustfmt::skip]
pub static GCODES: &[GCode] = &[
    g(0, 1, true, "linear motion at rapid", Yes),
    g(10, 1, false, "linear motion at feed", Yes),
    g(20, 1, false, "clockwise circular motion at feed", Yes),
    g(30, 1, false, "counterclockwise circular motion at feed", Yes),
    g(40, 0, false, "dwell", Yes),
    g(70, 24, false, "radius programming", Yes),
    g(80, 24, true, "diameter programming", Yes), // default is a control setting; kerf: diameter
    g(90, 0, false, "exact stop", Yes),
    g(200, 6, false, "inch mode", Yes),
    g(210, 6, true, "millimeter mode", Yes), // default is a control setting; kerf: mm
    g(330, 1, false, "threading", Yes),
    g(380, 0, false, "turret probe", Yes),
    g(400, 7, true, "cutter radius compensation off", Yes),
    g(410, 7, false, "cutter radius compensation left", Yes),
    g(420, 7, false, "cutter radius compensation right", Yes),
    g(530, 0, false, "program machine coordinates", Yes),
    g(590, 0, false, "cancel work coordinate offsets", Yes),
    g(700, 6, false, "inch mode (legacy code of the G78 samples)", Yes),
    g(730, 10, false, "peck drill with chip break drill cycle", Yes),
    g(740, 10, false, "left hand tapping", Yes),
    g(780, 0, false, "threading cycle", Yes),
    g(800, 10, true, "cancel drill cycle", Yes),
    g(810, 10, false, "drill cycle", Yes),
    g(820, 10, false, "drill cycle with dwell", Yes),
    g(830, 10, false, "peck drill cycle", Yes),
    g(840, 10, false, "right hand tapping and float tapping", Yes),
    g(900, 3, true, "absolute programming", Yes),
    g(910, 3, false, "incremental programming", Yes),
    g(920, 0, false, "work coordinate offsets or spindle max speed", Yes),
    g(930, 5, false, "inverse time feed", Yes),
    g(940, 5, true, "feed per minute", Yes),
    g(950, 5, false, "feed per revolution", Yes),
    g(960, 2, false, "constant surface speed (CSS)", Yes),
    g(970, 2, true, "direct spindle speed", Yes),
    g(980, 19, true, "drill cycle initial level return", Yes),
    g(990, 19, false, "drill cycle R plane return", Yes),
];

/// Number of job-syncing M codes (M100-M199, 002 Tables 1 and 3).
const N_SYNC: usize = 100;

/// M codes of 002 before the job-syncing range, with the execution category
/// of Table 1 and the M-code descriptions.
const M_LOW: [MCode; 12] = [
    m(0, "program stop", After, Stop), // end of block system M code
    m(1, "optional stop", After, OptionalStop), // end of block system M code
    m(2, "end of program (no rewind)", After, End), // end of block system M code
    m(3, "spindle clockwise", Before, SpindleCw), // after T, S and E, before motion
    m(4, "spindle counterclockwise", Before, SpindleCcw),
    m(5, "spindle off", After, SpindleStop), // spindle stop, after motion
    m(7, "secondary coolant on", Before, CoolantMist), // beginning of block
    m(8, "primary coolant on", Before, CoolantFlood), // beginning of block
    m(9, "coolant off", After, CoolantOff),  // "usually ... at the end of the block"
    m(30, "end of program (rewind)", After, End), // end of block system M code
    m(48, "use feedrate override", Before, FeedOverride(true)), // feedrate override stage
    m(49, "ignore feedrate override", Before, FeedOverride(false)),
];

/// M codes of 002 after the job-syncing range.
const M_HIGH: [MCode; 1] = [
    // Not in Table 1; Table 15 groups it with M00/M01 (waits for the
    // look-ahead buffer to empty), so it is sequenced with the system codes.
    m(200, "block delete synchronization", After, Aux),
];

/// Builds the full M-code table: the low codes, M100-M199 (job syncing,
/// first stage of Table 1), the high codes.
const fn hurco_mcodes() -> [MCode; M_LOW.len() + N_SYNC + M_HIGH.len()] {
    let mut out = [M_LOW[0]; M_LOW.len() + N_SYNC + M_HIGH.len()];
    let mut i = 0;
    while i < M_LOW.len() {
        out[i] = M_LOW[i];
        i += 1;
    }
    let mut k = 0;
    while k < N_SYNC {
        out[M_LOW.len() + k] = m(100 + k as u16, "job syncing", JobSync, Aux);
        k += 1;
    }
    let mut j = 0;
    while j < M_HIGH.len() {
        out[M_LOW.len() + N_SYNC + j] = M_HIGH[j];
        j += 1;
    }
    out
}

/// M codes of 002 with their execution categories (Table 1), including
/// every job-syncing code M100-M199.
#[rustfmt::skip]
pub static MCODES: &[MCode] = &hurco_mcodes();

/// Hurco multi-letter parameter names (G78 and G38), matched
/// case-insensitively, the longest name winning. 002 prints `angIn`,
/// `ZEnd` (G78 introduction), `minR`, `minD` (Table 6) and, for G38,
/// `XExp`, `Xadj`, `ZExp`, `Zadj`, `FRAp` and `Tol`; the rest of the
/// multi-letter column of Tables 5-13 did not survive the extraction and
/// the other names are kerf's (docs/dialects.md). [`LONG_LETTERS`] gives
/// the single letter each stands for.
pub static LONG_NAMES: &[&str] = &[
    "angIn", "ZEnd", "minR", "minD", "XEnd", // 0-4
    "XExp", "ZExp", "Xadj", "Zadj", "FRAp", "Tol", // 5-10 (G38)
    "Face", "depth", "ZStart", "XStart", "pitch", "tpi", "length", // 11-17
    "ZMaj", "XMaj", "XClr", "ZClr", "angOut", "angSt", "nStart", // 18-24
    "taper", "dStart", "dEnd", "dFin", "nFin", "nSpring", "cVol", // 25-31
];

/// How a multi-letter parameter's value becomes its letter's value.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LongKind {
    /// The value as written.
    Plain,
    /// A diameter given for a radius letter (`minD`: X = minD/2).
    Diameter,
    /// The letter's negative form (`tpi`: F-, `angSt`: Q-).
    Negated,
}

/// The single letter (and conversion) of each [`LONG_NAMES`] entry.
pub static LONG_LETTERS: &[(u8, LongKind)] = &[
    (b'A', LongKind::Plain),
    (b'Z', LongKind::Plain),
    (b'X', LongKind::Plain),
    (b'X', LongKind::Diameter),
    (b'X', LongKind::Plain),
    (b'X', LongKind::Plain),
    (b'Z', LongKind::Plain),
    (b'I', LongKind::Plain),
    (b'K', LongKind::Plain),
    (b'V', LongKind::Plain),
    (b'T', LongKind::Plain),
    (b'M', LongKind::Plain),
    (b'J', LongKind::Plain),
    (b'K', LongKind::Plain),
    (b'I', LongKind::Plain),
    (b'F', LongKind::Plain),
    (b'F', LongKind::Negated),
    (b'T', LongKind::Plain),
    (b'H', LongKind::Plain),
    (b'S', LongKind::Plain),
    (b'U', LongKind::Plain),
    (b'W', LongKind::Plain),
    (b'C', LongKind::Plain),
    (b'Q', LongKind::Negated),
    (b'Q', LongKind::Plain),
    (b'B', LongKind::Plain),
    (b'D', LongKind::Plain),
    (b'E', LongKind::Plain),
    (b'L', LongKind::Plain),
    (b'P', LongKind::Plain),
    (b'R', LongKind::Plain),
    (b'V', LongKind::Plain),
];

/// The Hurco dialect. L, U and W are accepted for G78 (Tables 8 and 11);
/// outside a G78 block U and W are an alarm (a Fanuc-style incremental
/// X/Z must not be ignored silently).
pub static DIALECT: Dialect = Dialect {
    id: DialectId::Hurco,
    gcodes: GCODES,
    mcodes: MCODES,
    letters: b"ABCDEFGHIJKLMNPQRSTUVWXZ",
    long_names: LONG_NAMES,
    diameter_default: true,
    uvw_incremental: false,
    hurco_syntax: true,
    order: super::HURCO_TABLE_1,
    alarm_column: alarm_codes::AlarmColumn::Hurco,
    macro_calls: [650, 660],
    caps: Caps {
        bracket_nesting: 5,
        power_on_params: false,
        g53_checks: true,
        comma_corners: false,
        frame_codes: false,
        rotary_interp: false,
        max_loop_label: 3,
        sub_nesting: 4,
        m98_q_m99_l: false,
        dwell_revs_param: false,
        word_ranges: true,
        dwell_is_f: true,
        css_radius_word: true,
        linear_rapid: true,
        stops_stop_spindle: true,
        max_m_per_block: crate::words::MAX_CODES,
        offsets_wait_for_move: true,
        reset_keeps_tool_offset: true,
        part_zero_is_e1: true,
        gcode_system_b: false,
        short_r_half_circle: false,
        direct_drawing: false,
        hx_variables: false,
        comp: CompParams {
            type_b: ("comp_exit_normal", 1.0, 0.0),
            idle_blocks: 2.0,
            circular_joining: true,
        },
        restricted_words: false,
    },
};
