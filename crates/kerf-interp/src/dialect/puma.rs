//! Daewoo PUMA 450 with a Fanuc 0-T control, G-code system A (001): the
//! G-code table ("standard G code" column) with its modal groups and the
//! power-on defaults 001 marks with `#`, and the machine's complete M-code
//! list ("NC LATHE M-CODE LIST" and the M-function descriptions).
//!
//! Where 001 is garbled or kerf departs from it, the decision is recorded
//! in docs/dialects.md.
use super::MAction::*;
use super::MWhen::*;
use super::Support::*;
use super::*;

const LATER_LATHE: Support =
    Later("PUMA G22 interference area and G31 skip (not modelled; docs/dialects.md)");

/// G codes of 001 (system A). G10, G31 and G65-G67 are not in 001's
/// G-code table but are Fanuc 0-T codes (001 itself uses G31 in the M86
/// example); they are kept so that programs reach the "not yet supported"
/// alarm instead of "unknown G code". G18, G53, G54-G59 and G80 are not in
/// 001 either (001 is silent on work coordinate systems); they are the
/// Fanuc 0-T/16T/18T standard codes real lathe programs start with
/// (`G18 G21 G40 G80 G99`, `G54`), docs/dialects.md §3.
/// A table row with its meaning ([`means`]).
const fn g(code10: u16, group: u8, default: bool, name: &'static str, support: Support) -> GCode {
    super::g(code10, group, default, name, support, means(code10, group))
}

/// What a PUMA modal code means (001); a code without one is a
/// compile-time error in [`GCODES`]. G90/G92/G94 are group-01 cycles
/// here, G98/G99 the feed mode; the system B G90/G91 are 900/901 shifted
/// (interp/system_b.rs).
const fn means(code10: u16, group: u8) -> Means {
    use super::meaning::*;
    if group == 0 {
        return Means::OneShot(match code10 {
            100 => OneShot::DataSetting,
            310 => OneShot::Skip,
            500 => OneShot::CoordinateSetting,
            700 => OneShot::Mrc(LatheCycle::Finish),
            710 => OneShot::Mrc(LatheCycle::RoughTurn),
            720 => OneShot::Mrc(LatheCycle::RoughFace),
            730 => OneShot::Mrc(LatheCycle::Pattern),
            740 => OneShot::Mrc(LatheCycle::PeckZ),
            750 => OneShot::Mrc(LatheCycle::GrooveX),
            760 => OneShot::Mrc(LatheCycle::Thread),
            c => match common_one_shot(c) {
                Some(o) => o,
                None => panic!("PUMA one-shot G code without a meaning"),
            },
        });
    }
    match code10 {
        320 => return Means::Motion(MotionMode::ThreadLathe),
        900 => return Means::Motion(MotionMode::TurnCycle),
        920 => return Means::Motion(MotionMode::ThreadCycle),
        940 => return Means::Motion(MotionMode::FaceCycle),
        _ => {}
    }
    if let Some(m) = common(code10) {
        return m;
    }
    match code10 {
        220 => Means::Stroke(true),
        230 => Means::Stroke(false),
        800 => Means::Cycle(None),
        9000 => Means::Distance(Distance::Absolute),
        9010 => Means::Distance(Distance::Incremental),
        980 => Means::FeedMode(FeedMode::PerMin),
        990 => Means::FeedMode(FeedMode::PerRev),
        _ => panic!("PUMA modal G code without a meaning"),
    }
}

#[rustfmt::skip]
pub static GCODES: &[GCode] = &[
    g(0, 1, true, "positioning (rapid feed)", Yes), // # in 001
    g(10, 1, false, "straight interpolation", Yes),
    g(20, 1, false, "circular interpolation (CW)", Yes),
    g(30, 1, false, "circular interpolation (CCW)", Yes),
    g(40, 0, false, "dwell", Yes),
    g(100, 0, false, "offset value setting", Yes), // Fanuc 0-T, not in 001's table
    g(200, 6, false, "data input (inch)", Yes),
    g(210, 6, true, "data input (mm)", Yes), // # in 001
    g(220, 4, true, "stored distance limit effective (spindle interference check on)", LATER_LATHE), // # in 001
    g(230, 4, false, "stored distance limit ineffective (spindle interference check off)", Yes),
    g(270, 0, false, "machine reference return check", Yes),
    g(280, 0, false, "automatic reference return", Yes),
    g(290, 0, false, "return from reference", Yes),
    g(300, 0, false, "2nd reference return", Yes),
    g(310, 0, false, "skip cutting", LATER_LATHE), // Fanuc 0-T; used in 001's M86 example
    g(320, 1, false, "thread process (thread cutting)", Yes), // 001 prints "#G32": see docs/dialects.md
    g(180, 16, true, "plane selection ZX", Yes), // not in 001; the lathe's plane, Fanuc 0-T/16T reset state
    g(400, 7, true, "cancel of compensation", Yes), // not #-marked in 001; Fanuc reset state
    g(410, 7, false, "tool nose radius compensation left", Yes),
    g(420, 7, false, "tool nose radius compensation right", Yes),
    g(500, 0, false, "coordinate system setting, max spindle speed setting", Yes),
    g(530, 0, false, "machine coordinate system selection", Yes), // not in 001; Fanuc 0-T standard
    g(540, 14, true, "work coordinate system 1 selection", Yes), // G54-G59: not in 001; Fanuc 0-T standard
    g(550, 14, false, "work coordinate system 2 selection", Yes),
    g(560, 14, false, "work coordinate system 3 selection", Yes),
    g(570, 14, false, "work coordinate system 4 selection", Yes),
    g(580, 14, false, "work coordinate system 5 selection", Yes),
    g(590, 14, false, "work coordinate system 6 selection", Yes),
    g(650, 0, false, "user macro simple call", Yes), // Fanuc 0-T, not in 001's table
    g(660, 12, false, "user macro modal call", Yes),
    g(670, 12, true, "user macro modal call cancel", Yes),
    g(700, 0, false, "compound repeat cycle (finishing cycle)", Yes),
    g(710, 0, false, "compound repeat cycle (stock removal in turning)", Yes),
    g(720, 0, false, "compound repeat cycle (stock removal in facing)", Yes),
    g(730, 0, false, "compound repeat cycle (pattern repeating cycle)", Yes),
    g(740, 0, false, "compound repeat cycle (peck drilling in Z direction)", Yes),
    g(750, 0, false, "compound repeat cycle (grooving in X direction)", Yes),
    g(760, 0, false, "compound repeat cycle (thread cutting cycle)", Yes),
    g(800, 10, true, "canned cycle for drilling cancel", Yes), // not in 001; Fanuc 0-T; the PUMA has no drilling cycles to cancel
    g(900, 1, false, "fixed cycle (process cycle in turning)", Yes),
    g(920, 1, false, "fixed cycle (thread process cycle)", Yes),
    g(940, 1, false, "fixed cycle (facing process cycle)", Yes),
    g(960, 2, false, "constant surface speed control", Yes),
    // G-code system B's G90/G91 (interp/system_b.rs translates them to these
    // internal numbers; in system A a program cannot write them).
    g(9000, 3, true, "absolute programming (G-code system B G90)", Yes),
    g(9010, 3, false, "incremental programming (G-code system B G91)", Yes),
    g(970, 2, true, "constant surface speed control cancel (rpm)", Yes), // # in 001
    g(980, 5, false, "feed per minute (mm/min)", Yes),
    g(990, 5, true, "feed per revolution (mm/rev)", Yes), // # in 001
];

/// The PUMA 450 M-code list of 001 (both pages of the list, plus M82/M83
/// which only the M-function descriptions name). `when`: codes that switch
/// something on, clamp, advance, select or prepare act before the block's
/// motion; codes that stop, switch off, unclamp, retract, count or end act
/// after it (the usual Fanuc PMC sequencing). Machine functions that kerf
/// does not model are `Aux` events with the manual's name.
#[rustfmt::skip]
pub static MCODES: &[MCode] = &[
    m(0, "program stop", After, Stop),
    m(1, "optional stop", After, OptionalStop),
    m(2, "program end", After, End),
    m(3, "main spindle forward", Before, SpindleCw),
    m(4, "main spindle reverse", Before, SpindleCcw),
    m(5, "main spindle stop", After, SpindleStop),
    m(7, "high pressure coolant on", Before, Aux), // option; not the mist coolant of a mill
    m(8, "coolant on", Before, CoolantFlood),
    m(9, "coolant off", After, CoolantOff), // stops high pressure and normal coolant
    m(10, "parts catcher advance", Before, Aux),
    m(11, "parts catcher retract", After, Aux),
    m(13, "turret air blow", Before, Aux),
    m(14, "main spindle air blow", Before, Aux),
    m(15, "air blow off", After, Aux),
    m(17, "machine lock on (MDI only)", Before, Aux),
    m(18, "machine lock off (MDI only)", After, Aux),
    m(19, "main spindle orientation", After, Aux).and(MAlso::Orient),
    m(24, "chip conveyor run", Before, Aux),
    m(25, "chip conveyor stop", After, Aux),
    m(30, "program end and rewind", After, End),
    m(31, "interlock by-pass (spindle and tailstock)", Before, Aux),
    m(32, "interlock by-pass (spindle and steady rest)", Before, Aux),
    m(33, "revolving tool spindle forward", Before, Aux),
    m(34, "revolving tool spindle reverse", Before, Aux),
    m(35, "revolving tool spindle stop", After, Aux),
    m(38, "steady rest 1 clamp", Before, Aux), // name lost in 001's list; from M39/M58/M59 and the text
    m(39, "steady rest 1 unclamp", After, Aux),
    m(40, "gear change neutral", Before, Aux),
    m(41, "gear change low", Before, Aux),
    m(42, "gear change middle", Before, Aux),
    m(43, "gear change high", Before, Aux),
    m(46, "programmable tailstock body unclamp and traction bar advance", Before, Aux),
    m(47, "programmable tailstock body clamp and traction bar retract", After, Aux),
    m(50, "bar feeder command 1", Before, Aux),
    m(51, "bar feeder command 2", Before, Aux),
    m(52, "splash guard door open", After, Aux),
    m(53, "splash guard door close", Before, Aux),
    m(54, "parts count", After, Aux),
    m(58, "steady rest 2 clamp", Before, Aux),
    m(59, "steady rest 2 unclamp", After, Aux),
    m(61, "switching low speed (aP60 spindle motor, Y connection)", Before, Aux),
    m(62, "switching high speed (aP60 spindle motor, delta connection)", Before, Aux),
    m(63, "main spindle CW and coolant on", Before, SpindleCw).and(MAlso::CoolantOn),
    m(64, "main spindle CCW and coolant on", Before, SpindleCcw).and(MAlso::CoolantOn), // list: "coolant off"; text: "on"
    m(65, "main spindle and coolant stop", After, SpindleStop).and(MAlso::CoolantOff),
    m(66, "dual chucking low clamp", Before, Aux),
    m(67, "dual chucking high clamp", Before, Aux),
    m(68, "main chuck clamp", Before, Aux),
    m(69, "main chuck unclamp", After, Aux),
    m(70, "dual tailstock low advance", Before, Aux),
    m(74, "error detect on", Before, Aux),
    m(75, "error detect off", Before, Aux), // power-on state
    m(76, "thread chamfering on", Before, Aux).and(MAlso::ThreadChamfer(true)),
    m(77, "thread chamfering off", Before, Aux).and(MAlso::ThreadChamfer(false)), // modal; power-on state assumed
    m(78, "tailstock quill advance", Before, Aux),
    m(79, "tailstock quill retract", After, Aux),
    m(80, "Q-setter swing arm down", Before, Aux),
    m(81, "Q-setter swing arm up", After, Aux),
    m(82, "mirror image on", Before, Aux), // M-function text only
    m(83, "mirror image off", Before, Aux), // M-function text only
    m(84, "turret CW rotation", Before, Aux), // non-modal, with the T code
    m(85, "turret CCW rotation", Before, Aux), // non-modal, with the T code
    m(86, "torque skip act", Before, Aux),
    m(87, "torque skip cancel", After, Aux),
    m(88, "C-axis low clamp", Before, Aux), // list: "spindle low clamp"
    m(89, "C-axis high clamp", Before, Aux), // list: "spindle high clamp"
    m(90, "C-axis unclamp", Before, Aux),   // list: "spindle unclamp"; before C motion
    m(91, "external M91 command", Before, Aux),
    m(92, "external M92 command", Before, Aux),
    m(93, "external M93 command", Before, Aux),
    m(94, "external M94 command", Before, Aux),
    m(98, "sub-program call", After, SubCall),
    m(99, "end of sub-program", After, SubReturn),
    m(103, "sub-spindle forward", Before, Aux),
    m(104, "sub-spindle reverse", Before, Aux),
    m(105, "sub-spindle stop", After, Aux),
    m(110, "parts catcher 2 advance (sub)", Before, Aux),
    m(111, "parts catcher 2 retract (sub)", After, Aux),
    m(114, "sub-spindle air blow", Before, Aux),
    m(119, "sub-spindle orientation", After, Aux),
    m(131, "interlock by-pass (sub-spindle)", Before, Aux),
    m(163, "sub-spindle CW and coolant on", Before, Aux),
    m(164, "sub-spindle CCW and coolant on", Before, Aux), // list: "coolant off"
    m(165, "sub-spindle and coolant stop", After, Aux),
    m(168, "sub-chuck clamp", Before, Aux),
    m(169, "sub-chuck unclamp", After, Aux),
    m(203, "forward synchronous command", Before, Aux),
    m(204, "reverse synchronous command", Before, Aux),
    m(205, "synchronous stop", After, Aux),
    m(206, "spindle rotation release", Before, Aux),
];

/// The PUMA dialect.
pub static DIALECT: Dialect = Dialect {
    id: DialectId::Puma,
    gcodes: GCODES,
    mcodes: MCODES,
    // 001 "Meaning of Address": O N G X Z U W I K R F E M S T P Q L A D C
    // (C the direct chamfer); no B, H, J, V, Y on the two-axis lathe.
    letters: b"ACDEFGIKLMNOPQRSTUWXZ",
    long_names: &[],
    diameter_default: true,
    uvw_incremental: true,
    hurco_syntax: false,
    order: super::FANUC_LATHE,
    alarm_column: alarm_codes::AlarmColumn::Fanuc,
    macro_calls: [650, 660],
    caps: Caps {
        bracket_nesting: 5,
        power_on_params: false,
        g53_checks: false,
        comma_corners: false,
        frame_codes: false,
        rotary_interp: false,
        max_loop_label: 3,
        sub_nesting: 4,
        m98_q_m99_l: false,
        dwell_revs_param: false,
        word_ranges: false,
        dwell_is_f: false,
        css_radius_word: false,
        linear_rapid: false,
        stops_stop_spindle: false,
        max_m_per_block: 3,
        offsets_wait_for_move: false,
        reset_keeps_tool_offset: false,
        part_zero_is_e1: false,
        gcode_system_b: true,
        short_r_half_circle: true,
        direct_drawing: true,
        hx_variables: false,
        comp: CompParams {
            type_b: ("comp_type_b", 0.0, 1.0),
            idle_blocks: 1.0,
            circular_joining: false,
        },
        restricted_words: true,
    },
};
