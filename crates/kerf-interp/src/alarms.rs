//! Every alarm a program can cause. The code each control shows for it
//! is a dialect table (dialect/alarm_codes.rs): the HX's `F_8xxxx`
//! numbers, the Fanuc P/S numbers of the PUMA, kerf's `HU-` codes for
//! the Hurco. docs/alarms.md lists them all; keep the two in step.

use kerf_canon::{Alarm, SrcRef};

use crate::dialect::DialectId;

/// The kinds of alarm the interpreter raises.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AlarmKind {
    /// A character or address the control does not accept.
    IllegalAddress,
    /// An address with no value.
    MissingValue,
    /// Too many digits.
    TooManyDigits,
    /// Comment not closed.
    UnterminatedComment,
    /// Brackets unbalanced or too deep, malformed expression or statement.
    BadExpression,
    /// Sequence or program number malformed or repeated.
    BadSequenceNumber,
    /// Block longer than the control allows.
    BlockTooLong,
    /// G code not in the control's table.
    UnknownG,
    /// M code not in the control's table.
    UnknownM,
    /// An axis word for an axis the machine does not have.
    NoSuchAxis,
    /// The same address twice in a block.
    DuplicateAddress,
    /// A value outside the control's range.
    OutOfRange,
    /// G01/G02/G03 without any feedrate commanded.
    NoFeed,
    /// Arc end point not on the circle.
    ArcEndPoint,
    /// Arc radius too small for the chord, or zero.
    ArcRadius,
    /// Arc without centre or radius.
    ArcNoCenter,
    /// Move beyond the machine's travel.
    Overtravel,
    /// A recognised code whose implementation is in a later issue.
    NotYetSupported,
    /// A G code that needs a value it did not get (e.g. G04 without time).
    MissingArgument,
    /// Macro variable problems (bad number, write to read-only, …).
    BadVariable,
    /// Division by zero or a math domain error in an expression.
    MathError,
    /// Too many blocks executed without progress (loop guard).
    LoopLimit,
    /// Jump target not found.
    SequenceNotFound,
    /// WHILE/DO/END mismatch.
    BadLoop,
    /// M-code restrictions in one block (too many, or illegal combination).
    MCodeConflict,
    /// G27: not at the reference position.
    ReferenceCheck,
    /// I/O error while reading the program.
    Io,
    /// M98/G65: the called program is in neither the file nor a library.
    ProgramNotFound,
    /// M98/G65 without P.
    NoProgramNumber,
    /// Calls nested deeper than the control allows.
    CallNesting,
    /// A called program ends (end of text, `%`, next O) without M99.
    SubprogramEnd,
    /// `#3000 = n (MESSAGE)`: the program's own alarm; the code is 3000+n.
    UserAlarm,
    /// A code not allowed while coordinate rotation or scaling is in force
    /// (plane change, G27-G30, G92), or transforms in the wrong order.
    TransformConflict,
    /// Skip (G31) or measurement (G37) move without the skip signal, or a
    /// G37 contact outside the allowed range.
    NoContact,
    /// Canned cycle or G60 used in a way the control forbids (plane change
    /// in cycle mode, G87 with G99, a cycle and a group-01 code in one
    /// block, G60 with an interpolation code).
    CannedCycle,
    /// G112 polar coordinate interpolation: a code not allowed in the mode,
    /// G00, a machine without the X/C pair, G112 in a block with axis words
    /// or while G16/G51/G68/G107 is in force.
    PolarInterp,
    /// G107 cylindrical interpolation: radius missing or negative, a code
    /// not allowed in the mode, an arc with I/J/K or outside the plane of
    /// the rotary axis, G107 while G16/G51/G68/G112 is in force.
    CylindricalInterp,
    /// `,C`/`,R`: the block, or the block after it, is not a G01/G02/G03
    /// move in the selected plane (G00, another plane or axis, no move
    /// before the end of the program, a call or return in between).
    CornerNoMove,
    /// `,C`/`,R`: the chamfer or radius does not fit on the two paths, or
    /// the paths meet without a corner (tangent or reversing).
    CornerTooLarge,
    /// `,C` and `,R` in one block, or a change of coordinate system or
    /// tool between a `,C`/`,R` block and its next move.
    CornerConflict,
    /// G45-G48 tool position offset outside G00-G03, or with cutter
    /// radius compensation in force.
    ToolOffset,
    /// G70-G73 without P (ns) or Q (nf).
    MrcNoPq,
    /// A G70-G76 value out of range: depth Δd, peck Δk, height k ≤ 0, divisions d < 1, tool angle a not 80/60/55/30/29/0, run-out longer than the thread, start point level with the shape.
    MrcValue,
    /// The sequence number P (ns) or Q (nf) of a G70-G73 shape is not in the program.
    MrcSeqNotFound,
    /// G71/G72 type I: the finishing shape is not monotonic in X or Z.
    MrcNotMonotonic,
    /// The first block ns of a finishing shape has no G00 or G01.
    MrcFirstBlock,
    /// A code not allowed inside a finishing shape ns-nf (one-shot G codes, G32/G90-G94, G70-G76, M98/M99, macro statements).
    MrcIllegal,
    /// The last block nf of a finishing shape ends with a chamfer or corner R.
    MrcEndCorner,
    /// A lathe cycle or thread kerf refuses: G90/G92/G94 taper R beyond the cycle (cases 3/4 need |R| ≤ |U/2|, |W|), a taper or face thread in G96, a thread chamfer longer than the thread, a finishing shape longer than 2,000 blocks.
    LatheCycle,
    /// Lathe direct chamfer / corner R (I, K, R, C on a G01): no next block, or the next block is not a G01 moving along the other axis in the direction of the sign (PUMA 001 p.10).
    ChamferNextBlock,
    /// Lathe direct chamfer / corner R on a block that moves both X and Z, or followed by a block that does (001 p.10 note 3).
    ChamferTaper,
    /// Cutter / tool nose radius compensation started (G41/G42) or
    /// cancelled (G40) in a G02/G03 block.
    CompArc,
    /// A plane change (G17/G18/G19) in compensation mode.
    CompPlane,
    /// Compensation interference (gouge): a compensated move that runs
    /// against the programmed direction, or an offset larger than the
    /// radius of an inside arc.
    CompInterference,
    /// No intersection of the compensated paths at an inside corner.
    CompNoSolution,
    /// G39 outside offset mode, or in a start-up or cancel block.
    CompG39,
    /// Hurco G78 threading: X+J of the wrong sign (X crossing the centre
    /// line), not in G97, more than one of Z/H/T, a zero-length thread,
    /// inconsistent depths.
    ThreadCycle,
    /// Hurco G38 turret probe: bad S, a direction not datumed, missing E/H
    /// numbers, the probing axis not moving towards the contact point.
    ProbeCycle,
    /// Hurco G53 preconditions (CRC on, G91, not G00/G01) and drill-cycle
    /// rules (G00 with G80).
    HurcoMode,
}

impl AlarmKind {
    /// Every kind, for documentation checks.
    pub const ALL: &'static [AlarmKind] = &[
        AlarmKind::IllegalAddress,
        AlarmKind::MissingValue,
        AlarmKind::TooManyDigits,
        AlarmKind::UnterminatedComment,
        AlarmKind::BadExpression,
        AlarmKind::BadSequenceNumber,
        AlarmKind::BlockTooLong,
        AlarmKind::UnknownG,
        AlarmKind::UnknownM,
        AlarmKind::NoSuchAxis,
        AlarmKind::DuplicateAddress,
        AlarmKind::OutOfRange,
        AlarmKind::NoFeed,
        AlarmKind::ArcEndPoint,
        AlarmKind::ArcRadius,
        AlarmKind::ArcNoCenter,
        AlarmKind::Overtravel,
        AlarmKind::NotYetSupported,
        AlarmKind::MissingArgument,
        AlarmKind::BadVariable,
        AlarmKind::MathError,
        AlarmKind::LoopLimit,
        AlarmKind::SequenceNotFound,
        AlarmKind::BadLoop,
        AlarmKind::MCodeConflict,
        AlarmKind::ReferenceCheck,
        AlarmKind::Io,
        AlarmKind::ProgramNotFound,
        AlarmKind::NoProgramNumber,
        AlarmKind::CallNesting,
        AlarmKind::SubprogramEnd,
        AlarmKind::UserAlarm,
        AlarmKind::TransformConflict,
        AlarmKind::NoContact,
        AlarmKind::CannedCycle,
        AlarmKind::PolarInterp,
        AlarmKind::CylindricalInterp,
        AlarmKind::CornerNoMove,
        AlarmKind::CornerTooLarge,
        AlarmKind::CornerConflict,
        AlarmKind::CompArc,
        AlarmKind::CompPlane,
        AlarmKind::CompInterference,
        AlarmKind::CompNoSolution,
        AlarmKind::CompG39,
        AlarmKind::ToolOffset,
        AlarmKind::MrcNoPq,
        AlarmKind::MrcValue,
        AlarmKind::MrcSeqNotFound,
        AlarmKind::MrcNotMonotonic,
        AlarmKind::MrcFirstBlock,
        AlarmKind::MrcIllegal,
        AlarmKind::MrcEndCorner,
        AlarmKind::LatheCycle,
        AlarmKind::ChamferNextBlock,
        AlarmKind::ChamferTaper,
        AlarmKind::ThreadCycle,
        AlarmKind::ProbeCycle,
        AlarmKind::HurcoMode,
    ];

    /// The control's code for this alarm (the dialect's column of
    /// [`crate::dialect::alarm_codes`]).
    pub fn code(self, d: DialectId) -> &'static str {
        crate::dialect::alarm_codes::code(self, crate::dialect::Dialect::get(d).alarm_column)
    }

    /// Builds the alarm for a dialect.
    pub fn at(self, d: DialectId, src: SrcRef, msg: impl Into<String>) -> Alarm {
        Alarm::new(self.code(d), msg, src)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// docs/alarms.md lists every code of every control.
    #[test]
    fn alarms_doc_is_complete() {
        let doc = include_str!("../../../docs/alarms.md");
        for k in AlarmKind::ALL {
            for d in [DialectId::Hx, DialectId::Puma, DialectId::Hurco] {
                let code = k.code(d);
                assert!(
                    doc.contains(code),
                    "{k:?} code {code} missing from docs/alarms.md"
                );
            }
            assert!(
                doc.contains(&format!("| {k:?} |")),
                "{k:?} missing from docs/alarms.md"
            );
        }
    }
}
