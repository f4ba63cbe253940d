//! Hurco MAX turning-center control (002): its G codes, M codes with their
//! execution categories (Table 1), and the G78 multi-letter parameter names.
use super::MAction::*;
use super::MWhen::*;
use super::Support::*;
use super::*;

const LATER_HURCO: Support = Later("Hurco cycles, probing, fixture offsets and loops (issue 7)");
const LATER_COMP: Support = Later("tool compensation (issue 5)");

/// G codes of 002.
pub static GCODES: &[GCode] = &[
    g(0, 1, true, "rapid positioning", Yes),
    g(10, 1, false, "linear interpolation", Yes),
    g(20, 1, false, "circular interpolation CW", Yes),
    g(30, 1, false, "circular interpolation CCW", Yes),
    g(40, 0, false, "dwell", Yes),
    g(70, 24, false, "radius programming", Yes),
    g(80, 24, true, "diameter programming", Yes),
    g(90, 0, false, "exact stop", Yes),
    g(200, 6, false, "inch mode", Yes),
    g(210, 6, true, "metric mode", Yes),
    g(330, 1, false, "threading", LATER_HURCO),
    g(380, 0, false, "turret probe cycle", LATER_HURCO),
    g(400, 7, true, "cutter radius compensation off", Yes),
    g(410, 7, false, "cutter radius compensation left", LATER_COMP),
    g(
        420,
        7,
        false,
        "cutter radius compensation right",
        LATER_COMP,
    ),
    g(530, 0, false, "machine coordinates", Yes),
    g(590, 0, false, "cancel G92 offsets", Yes),
    g(730, 10, false, "chip break drilling cycle", LATER_HURCO),
    g(740, 10, false, "left-hand tapping cycle", LATER_HURCO),
    g(780, 0, false, "multi-pass threading cycle", LATER_HURCO),
    g(800, 10, true, "drill cycle cancel", Yes),
    g(810, 10, false, "drilling cycle", LATER_HURCO),
    g(820, 10, false, "drilling with dwell cycle", LATER_HURCO),
    g(830, 10, false, "peck drilling cycle", LATER_HURCO),
    g(840, 10, false, "tapping cycle", LATER_HURCO),
    g(900, 3, true, "absolute mode", Yes),
    g(910, 3, false, "incremental mode", Yes),
    g(920, 0, false, "set part zero (G92 offsets)", Yes),
    g(930, 5, false, "inverse time feed", Yes),
    g(940, 5, false, "feed per minute", Yes),
    g(950, 5, true, "feed per revolution", Yes),
    g(960, 2, false, "constant surface speed", Yes),
    g(970, 2, true, "constant spindle speed (rpm)", Yes),
    g(980, 19, true, "drill cycle return to initial plane", Yes),
    g(990, 19, false, "drill cycle return to R plane", Yes),
];

/// M codes of 002 with their execution categories (Table 1).
pub static MCODES: &[MCode] = &[
    m(0, "program stop", After, Stop),
    m(1, "optional stop", After, OptionalStop),
    m(2, "end of program", After, End),
    m(3, "spindle CW", Before, SpindleCw),
    m(4, "spindle CCW", Before, SpindleCcw),
    m(5, "spindle stop", After, SpindleStop),
    m(7, "coolant mist on", Before, CoolantMist),
    m(8, "coolant flood on", Before, CoolantFlood),
    m(9, "coolant off", After, CoolantOff),
    m(30, "end of program, rewind", After, End),
    m(48, "feedrate override enabled", Before, Aux),
    m(49, "feedrate override disabled", Before, Aux),
];

/// Hurco G78 multi-letter parameter names (002 Tables 5-13).
pub static LONG_NAMES: &[&str] = &["angIn", "XEnd", "ZEnd", "minD"];

/// The Hurco dialect.
pub static DIALECT: Dialect = Dialect {
    id: DialectId::Hurco,
    gcodes: GCODES,
    mcodes: MCODES,
    letters: b"ABCDEFGHIJKMNPQRSTVXZ",
    long_names: LONG_NAMES,
    diameter_default: true,
    uvw_incremental: false,
    hurco_syntax: true,
    hurco_order: true,
};
