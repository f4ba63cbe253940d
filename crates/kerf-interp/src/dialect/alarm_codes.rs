//! The code each control shows for each alarm, one column per control:
//! HX codes are the manual's `F_8xxxx` numbers where 000 names one; the
//! PUMA (Fanuc 0-T) codes are the Fanuc P/S alarm numbers; the Hurco
//! manual names no numbers, so Hurco alarms use kerf's own `HU-` codes.
//! docs/alarms.md lists them all; keep the two in step.

use crate::alarms::AlarmKind;

/// Which column of the table a dialect shows ([`super::Dialect::alarm_column`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AlarmColumn {
    /// The HX's `F_8xxxx` numbers.
    Hx,
    /// Fanuc P/S numbers (the PUMA's 0-T).
    Fanuc,
    /// kerf's `HU-` codes.
    Hurco,
}

/// The code of alarm `kind` in column `col`.
pub fn code(kind: AlarmKind, col: AlarmColumn) -> &'static str {
    use AlarmKind::*;
    let (hx, fanuc, hurco) = match kind {
        IllegalAddress => ("F_82001", "PS009", "HU-001"),
        MissingValue => ("F_82004", "PS005", "HU-002"),
        TooManyDigits => ("F_82002", "PS003", "HU-003"),
        UnterminatedComment => ("F_82001", "PS009", "HU-004"),
        BadExpression => ("F_82005", "PS114", "HU-005"),
        BadSequenceNumber => ("F_82018", "PS009", "HU-006"),
        BlockTooLong => ("F_82111", "PS009", "HU-007"),
        UnknownG => ("F_82030", "PS010", "HU-010"),
        UnknownM => ("F_82031", "PS010", "HU-011"),
        NoSuchAxis => ("F_82001", "PS009", "HU-012"),
        DuplicateAddress => ("F_82006", "PS009", "HU-013"),
        OutOfRange => ("F_82007", "PS003", "HU-014"),
        NoFeed => ("F_84020", "PS011", "HU-020"),
        ArcEndPoint => ("F_82112", "PS020", "HU-021"),
        ArcRadius => ("F_82100", "PS023", "HU-022"),
        ArcNoCenter => ("F_82102", "PS021", "HU-023"),
        Overtravel => ("F_84100", "OT510", "HU-030"),
        NotYetSupported => ("KERF-0100", "KERF-0100", "KERF-0100"),
        MissingArgument => ("F_82008", "PS004", "HU-015"),
        BadVariable => ("F_82200", "PS115", "HU-040"),
        MathError => ("F_82201", "PS112", "HU-041"),
        LoopLimit => ("KERF-0101", "KERF-0101", "KERF-0101"),
        SequenceNotFound => ("F_82021", "PS060", "HU-042"),
        BadLoop => ("F_82202", "PS128", "HU-043"),
        MCodeConflict => ("F_82032", "PS009", "HU-016"),
        ReferenceCheck => ("F_82209", "PS092", "HU-044"),
        Io => ("KERF-0001", "KERF-0001", "KERF-0001"),
        ProgramNotFound => ("F_82109", "PS078", "HU-045"),
        NoProgramNumber => ("F_82109", "PS076", "HU-046"),
        CallNesting => ("F_82023", "PS077", "HU-047"),
        SubprogramEnd => ("F_82024", "KERF-0102", "KERF-0102"),
        UserAlarm => ("3000+n", "3000+n", "3000+n"),
        TransformConflict => ("F_82210", "PS144", "HU-048"),
        NoContact => ("F_84022", "PS080", "HU-049"),
        CannedCycle => ("KERF-0103", "KERF-0103", "KERF-0103"),
        PolarInterp => ("F_82204", "PS145", "HU-050"),
        CylindricalInterp => ("F_82208", "PS175", "HU-051"),
        CornerNoMove => ("F_82103", "PS051", "HU-024"),
        CornerTooLarge => ("F_82104", "PS055", "HU-025"),
        CornerConflict => ("F_82105", "PS053", "HU-026"),
        CompArc => ("F_82120", "PS034", "HU-080"),
        CompPlane => ("F_82121", "PS037", "HU-081"),
        CompInterference => ("F_82122", "PS041", "HU-082"),
        CompNoSolution => ("F_82123", "PS033", "HU-083"),
        CompG39 => ("F_82124", "PS035", "HU-084"),
        ToolOffset => ("F_82106", "PS042", "HU-027"),
        MrcNoPq => ("KERF-0161", "PS061", "KERF-0161"),
        MrcValue => ("KERF-0162", "PS062", "KERF-0162"),
        MrcSeqNotFound => ("KERF-0163", "PS063", "KERF-0163"),
        MrcNotMonotonic => ("KERF-0164", "PS064", "KERF-0164"),
        MrcFirstBlock => ("KERF-0165", "PS065", "KERF-0165"),
        MrcIllegal => ("KERF-0166", "PS066", "KERF-0166"),
        MrcEndCorner => ("KERF-0167", "PS069", "KERF-0167"),
        LatheCycle => ("KERF-0168", "KERF-0168", "KERF-0168"),
        ChamferNextBlock => ("KERF-0169", "PS052", "KERF-0169"),
        ChamferTaper => ("KERF-0170", "PS054", "KERF-0170"),
        ThreadCycle => ("KERF-0104", "KERF-0104", "HU-060"),
        ProbeCycle => ("KERF-0105", "KERF-0105", "HU-061"),
        HurcoMode => ("KERF-0106", "KERF-0106", "HU-062"),
    };
    match col {
        AlarmColumn::Hx => hx,
        AlarmColumn::Fanuc => fanuc,
        AlarmColumn::Hurco => hurco,
    }
}
