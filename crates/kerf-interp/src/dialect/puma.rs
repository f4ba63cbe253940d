//! Daewoo PUMA 450 with a Fanuc 0-T control, G-code system A (001): the
//! G-code table with modal groups and `#` power-on defaults, and the
//! machine's M-code list.
use super::MAction::*;
use super::MWhen::*;
use super::Support::*;
use super::*;

const LATER_MACRO: Support = Later("custom macro B and subprograms (issue 3)");
const LATER_LATHE: Support = Later("PUMA lathe cycles, threading and reference returns (issue 6)");
const LATER_COMP: Support = Later("tool compensation (issue 5)");

/// G codes of 001 (system A).
pub static GCODES: &[GCode] = &[
    g(0, 1, true, "positioning (rapid traverse)", Yes),
    g(10, 1, false, "linear interpolation (cutting feed)", Yes),
    g(20, 1, false, "circular interpolation CW", Yes),
    g(30, 1, false, "circular interpolation CCW", Yes),
    g(40, 0, false, "dwell", Yes),
    g(100, 0, false, "offset value setting", LATER_COMP),
    g(200, 6, false, "inch input", Yes),
    g(210, 6, true, "metric input", Yes),
    g(220, 4, false, "stored stroke check on", LATER_LATHE),
    g(230, 4, true, "stored stroke check off", Yes),
    g(270, 0, false, "reference point return check", LATER_LATHE),
    g(280, 0, false, "return to reference point", LATER_LATHE),
    g(290, 0, false, "return from reference point", LATER_LATHE),
    g(300, 0, false, "return to 2nd reference point", LATER_LATHE),
    g(310, 0, false, "skip cutting", LATER_LATHE),
    g(320, 1, false, "thread cutting", LATER_LATHE),
    g(400, 7, true, "tool nose radius compensation cancel", Yes),
    g(
        410,
        7,
        false,
        "tool nose radius compensation left",
        LATER_COMP,
    ),
    g(
        420,
        7,
        false,
        "tool nose radius compensation right",
        LATER_COMP,
    ),
    g(
        500,
        0,
        false,
        "work coordinate system change, max spindle speed setting",
        Yes,
    ),
    g(650, 0, false, "user macro simple call", LATER_MACRO),
    g(660, 12, false, "user macro modal call", LATER_MACRO),
    g(670, 12, true, "user macro modal call cancel", Yes),
    g(700, 0, false, "finishing cycle", LATER_LATHE),
    g(710, 0, false, "stock removal in turning", LATER_LATHE),
    g(720, 0, false, "stock removal in facing", LATER_LATHE),
    g(730, 0, false, "pattern repeating", LATER_LATHE),
    g(740, 0, false, "peck drilling in Z axis", LATER_LATHE),
    g(750, 0, false, "grooving in X axis", LATER_LATHE),
    g(760, 0, false, "multiple thread cutting cycle", LATER_LATHE),
    g(900, 1, false, "cutting cycle A (OD/ID)", LATER_LATHE),
    g(920, 1, false, "thread cutting cycle", LATER_LATHE),
    g(940, 1, false, "cutting cycle B (end face)", LATER_LATHE),
    g(960, 2, false, "constant surface speed control", Yes),
    g(970, 2, true, "constant surface speed control cancel", Yes),
    g(980, 5, false, "feed per minute", Yes),
    g(990, 5, true, "feed per revolution", Yes),
];

/// The PUMA 450 M-code list (001).
pub static MCODES: &[MCode] = &[
    m(0, "program stop", After, Stop),
    m(1, "optional stop", After, OptionalStop),
    m(2, "end of program", After, End),
    m(3, "spindle CW", Before, SpindleCw),
    m(4, "spindle CCW", Before, SpindleCcw),
    m(5, "spindle stop", After, SpindleStop),
    m(8, "coolant on", Before, CoolantFlood),
    m(9, "coolant off", After, CoolantOff),
    m(30, "end of program and rewind", After, End),
    m(98, "subprogram call", After, SubCall),
    m(99, "end of subprogram", After, SubReturn),
];

/// The PUMA dialect.
pub static DIALECT: Dialect = Dialect {
    id: DialectId::Puma,
    gcodes: GCODES,
    mcodes: MCODES,
    letters: b"ABCDEFGHIJKLMNOPQRSTUWXZ",
    long_names: &[],
    diameter_default: true,
    uvw_incremental: true,
    hurco_syntax: false,
    hurco_order: false,
};
