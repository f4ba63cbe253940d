//! What a modal G code means, independent of its number. Each dialect's
//! table gives every modal code its [`Means`] (hx.rs, puma.rs, hurco.rs),
//! so the interpreter's modal state (interp/modal.rs) is set and read by
//! meaning: "feed per revolution" is [`FeedMode::PerRev`] whether the
//! control calls it G95 (HX, Hurco) or G99 (PUMA).
use kerf_canon::Plane;

/// The meaning of one G code of a dialect's table.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Means {
    /// A one-shot code (group 0): acts in its own block only.
    OneShot(OneShot),
    /// Group 01: the motion mode.
    Motion(MotionMode),
    /// G96 (true) / G97: constant surface speed.
    Css(bool),
    /// G90 / G91 (PUMA system B G90 / G91).
    Distance(Distance),
    /// G93 / G94 / G95 (PUMA G98 / G99).
    FeedMode(FeedMode),
    /// G20 / G21 (Hurco also G70).
    Units(Units),
    /// G40 / G41 / G42: cutter or tool nose radius compensation.
    CutterComp(CompSide),
    /// G22 (true) / G23: stored stroke check.
    Stroke(bool),
    /// The canned (drill) cycle group: G80 (None) or the cycle a code
    /// selects.
    Cycle(Option<HoleCycle>),
    /// G51 (true) / G50: scaling and mirror image (HX).
    Scaling(bool),
    /// G66 (true) / G67: the macro modal call.
    ModalCall(bool),
    /// G43 / G44 / G49: tool length compensation (HX).
    LengthComp(LengthComp),
    /// G54-G59: the work coordinate system G54 + n.
    Work(u8),
    /// G61-G64 (HX).
    CuttingMode(CuttingMode),
    /// G17 / G18 / G19.
    Plane(Plane),
    /// G16 (true) / G15: polar coordinate command (HX).
    PolarCommand(bool),
    /// G68 (true) / G69: coordinate rotation (HX).
    Rotation(bool),
    /// G98 / G99 (HX, Hurco): the canned cycle return level.
    CycleReturn(CycleReturn),
    /// G112 (true) / G113: polar coordinate interpolation (HX).
    PolarInterp(bool),
    /// G10.3 (true) / G11.3: high speed machining (HX).
    HighSpeed(bool),
    /// G107: cylindrical interpolation (HX; turned off by G107 with a
    /// zero radius, which leaves no code of the group in force).
    Cylindrical(bool),
    /// G63.1 (true) / G63.2: stitch function (HX).
    Stitch(bool),
    /// Hurco G08 (true) / G07: diameter or radius programming of X.
    Diameter(bool),
}

/// What a one-shot (group 0) code does.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OneShot {
    /// G04.
    Dwell,
    /// G09.
    ExactStop,
    /// G27-G30: reference position return and its check.
    RefReturn(RefReturn),
    /// G53: a move in machine coordinates.
    MachineCoords,
    /// G65: the macro call (run as the block is classified).
    MacroCall,
    /// G92 (HX, Hurco), G50 (PUMA system A): coordinate setting.
    CoordinateSetting,
    /// HX G10: offset data, run with the frame codes
    /// (interp/transforms.rs).
    FrameData,
    /// HX G52: the local coordinate system, run with the frame codes.
    LocalCoords,
    /// PUMA G10: offset value setting, before the motion.
    DataSetting,
    /// G31-G31.4 and HX G37-G37.4: skip and tool length measurement.
    Skip,
    /// HX G39: the corner arc of cutter compensation.
    CompCorner,
    /// HX G45-G48: tool offset increase / decrease.
    /// The move amount changes by this many times the D offset: G45 +1,
    /// G46 -1, G47 +2, G48 -2 (000 §13.3).
    ToolOffset(i8),
    /// HX G60: single direction positioning.
    SingleDirection,
    /// PUMA G70-G76: the multiple repetitive cycles.
    Mrc(LatheCycle),
    /// Hurco G38: the turret probe.
    Probe,
    /// Hurco G59: cancel the work coordinate shift.
    CancelWorkShift,
    /// Hurco G78: the threading cycle.
    ThreadCycle,
}

/// A reference position code (G27-G30, on all three controls).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RefReturn {
    /// G27: move to the programmed point and check it is the reference.
    Check,
    /// G28: through the intermediate point to the reference position.
    Home,
    /// G29: from the reference through the stored intermediate point.
    Back,
    /// G30: to the 2nd (3rd, 4th by P) reference position.
    Other,
}

/// A multiple repetitive cycle of the lathe (001 G70-G76).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LatheCycle {
    /// G70: the finishing shape once.
    Finish,
    /// G71: stock removal in turning (cuts along Z).
    RoughTurn,
    /// G72: stock removal in facing (cuts along X).
    RoughFace,
    /// G73: pattern repeating.
    Pattern,
    /// G74: peck drilling along Z (columns stepped in X).
    PeckZ,
    /// G75: grooving along X (grooves stepped in Z).
    GrooveX,
    /// G76: multiple thread cutting.
    Thread,
}

/// The motion mode (group 01).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MotionMode {
    /// G00.
    Rapid,
    /// G01.
    Linear,
    /// G02.
    ArcCw,
    /// G03.
    ArcCcw,
    /// HX G33: thread cutting along a line, F the lead (000 §4.8).
    ThreadF,
    /// Hurco G33: thread cutting along a line, the lead in K (along Z)
    /// or I (along X), P the start angle (002).
    ThreadKI,
    /// PUMA G32: lathe thread cutting, F or E the lead (001).
    ThreadLathe,
    /// PUMA G90: the turning cycle.
    TurnCycle,
    /// PUMA G92: the thread cutting cycle.
    ThreadCycle,
    /// PUMA G94: the facing cycle.
    FaceCycle,
}

/// Absolute or incremental dimensions (group 03).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Distance {
    Absolute,
    Incremental,
}

/// Feed mode (group 05).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FeedMode {
    PerMin,
    PerRev,
    Inverse,
}

/// Input units (group 06).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Units {
    Metric,
    Inch,
}

/// Cutter / tool nose radius compensation side (group 07).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CompSide {
    /// G40.
    Off,
    /// G41.
    Left,
    /// G42.
    Right,
}

/// Tool length compensation (HX group 13).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LengthComp {
    /// G49.
    Off,
    /// G43.
    Plus,
    /// G44.
    Minus,
}

/// HX group 15.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CuttingMode {
    /// G61.
    ExactStop,
    /// G62.
    CornerOverride,
    /// G63.
    Tapping,
    /// G64.
    Cutting,
}

/// A canned (drill) cycle: what one hole does between the R level and
/// the return (000 chapter 12 on the HX, 002 G73-G84 on the Hurco).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum HoleCycle {
    /// G81: feed to the bottom, rapid out.
    Drill,
    /// G82: G81 with a dwell at the bottom.
    DrillDwell,
    /// G73: peck with a short retract that breaks the chip.
    PeckChipBreak,
    /// G83: peck, out to R after each peck.
    Peck,
    /// G84: tapping, spindle reversed at the bottom.
    Tap,
    /// G74: left-hand (counter) tapping.
    TapLeft,
    /// HX G84.2: rigid tapping.
    RigidTap,
    /// HX G84.3: rigid counter tapping.
    RigidTapLeft,
    /// HX G85: bore in and out at feed.
    Bore,
    /// HX G89: G85 with a dwell at the bottom.
    BoreDwell,
    /// HX G86: bore, spindle stopped at the bottom, rapid out.
    BoreStop,
    /// HX G88: bore, dwell, stop; the operator retracts by hand.
    ManualBore,
    /// HX G76: fine boring (oriented stop and shift at the bottom).
    FineBore,
    /// HX G87: back boring (from below the bore, upwards).
    BackBore,
}

impl HoleCycle {
    /// G73 and G83: the depth is cut in pecks of Q.
    pub const fn pecks(self) -> bool {
        matches!(self, HoleCycle::PeckChipBreak | HoleCycle::Peck)
    }

    /// G76 and G87: the tool is shifted off the wall by I/J or Q.
    pub const fn shifts(self) -> bool {
        matches!(self, HoleCycle::FineBore | HoleCycle::BackBore)
    }

    /// The tapping cycles.
    pub const fn taps(self) -> bool {
        matches!(
            self,
            HoleCycle::Tap | HoleCycle::TapLeft | HoleCycle::RigidTap | HoleCycle::RigidTapLeft
        )
    }

    /// A tapping cycle that cuts with the spindle CCW (left hand).
    pub const fn left_hand(self) -> bool {
        matches!(self, HoleCycle::TapLeft | HoleCycle::RigidTapLeft)
    }
}

/// Where a canned cycle returns after a hole (group 19 on the HX and the
/// Hurco).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CycleReturn {
    /// G98: the initial level.
    Initial,
    /// G99: the R point.
    RPoint,
}

/// The kind of modal state a meaning sets: one per field of the
/// interpreter's modal state, whatever the group's number in a dialect.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    OneShot,
    Motion,
    Css,
    Distance,
    FeedMode,
    Units,
    CutterComp,
    Stroke,
    Cycle,
    Scaling,
    ModalCall,
    LengthComp,
    Work,
    CuttingMode,
    Plane,
    PolarCommand,
    Rotation,
    CycleReturn,
    PolarInterp,
    HighSpeed,
    Cylindrical,
    Stitch,
    Diameter,
}

/// A set of [`Kind`]s: which kinds of code one block carries, found
/// once as its codes are checked, so that a phase with nothing to do
/// for the block skips it with one test instead of looking its codes up
/// again.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct KindSet(u32);

impl KindSet {
    /// Adds a kind.
    pub fn insert(&mut self, k: Kind) {
        self.0 |= 1 << k as u32;
    }

    /// Whether the set holds `k`.
    pub fn has(self, k: Kind) -> bool {
        self.0 & (1 << k as u32) != 0
    }

    /// Whether the set holds any of `ks`.
    pub fn any(self, ks: &[Kind]) -> bool {
        ks.iter().any(|&k| self.has(k))
    }
}

impl Means {
    /// The kind of state this meaning sets.
    pub const fn kind(self) -> Kind {
        match self {
            Means::OneShot(_) => Kind::OneShot,
            Means::Motion(_) => Kind::Motion,
            Means::Css(_) => Kind::Css,
            Means::Distance(_) => Kind::Distance,
            Means::FeedMode(_) => Kind::FeedMode,
            Means::Units(_) => Kind::Units,
            Means::CutterComp(_) => Kind::CutterComp,
            Means::Stroke(_) => Kind::Stroke,
            Means::Cycle(_) => Kind::Cycle,
            Means::Scaling(_) => Kind::Scaling,
            Means::ModalCall(_) => Kind::ModalCall,
            Means::LengthComp(_) => Kind::LengthComp,
            Means::Work(_) => Kind::Work,
            Means::CuttingMode(_) => Kind::CuttingMode,
            Means::Plane(_) => Kind::Plane,
            Means::PolarCommand(_) => Kind::PolarCommand,
            Means::Rotation(_) => Kind::Rotation,
            Means::CycleReturn(_) => Kind::CycleReturn,
            Means::PolarInterp(_) => Kind::PolarInterp,
            Means::HighSpeed(_) => Kind::HighSpeed,
            Means::Cylindrical(_) => Kind::Cylindrical,
            Means::Stitch(_) => Kind::Stitch,
            Means::Diameter(_) => Kind::Diameter,
        }
    }
}

/// The one-shot meanings the three controls share: G04, G09, G27-G30,
/// G53, G65.
pub(crate) const fn common_one_shot(code10: u16) -> Option<OneShot> {
    Some(match code10 {
        40 => OneShot::Dwell,
        90 => OneShot::ExactStop,
        270 => OneShot::RefReturn(RefReturn::Check),
        280 => OneShot::RefReturn(RefReturn::Home),
        290 => OneShot::RefReturn(RefReturn::Back),
        300 => OneShot::RefReturn(RefReturn::Other),
        530 => OneShot::MachineCoords,
        650 => OneShot::MacroCall,
        _ => return None,
    })
}

/// The meanings the three controls share under the same number: G00-G03,
/// G17-G19, G20/G21, G40-G42, G54-G59, G90/G91, G93-G97. None for a code
/// whose meaning depends on the control.
pub(crate) const fn common(code10: u16) -> Option<Means> {
    Some(match code10 {
        0 => Means::Motion(MotionMode::Rapid),
        10 => Means::Motion(MotionMode::Linear),
        20 => Means::Motion(MotionMode::ArcCw),
        30 => Means::Motion(MotionMode::ArcCcw),
        170 => Means::Plane(Plane::XY),
        180 => Means::Plane(Plane::ZX),
        190 => Means::Plane(Plane::YZ),
        200 => Means::Units(Units::Inch),
        210 => Means::Units(Units::Metric),
        400 => Means::CutterComp(CompSide::Off),
        410 => Means::CutterComp(CompSide::Left),
        420 => Means::CutterComp(CompSide::Right),
        540 => Means::Work(0),
        550 => Means::Work(1),
        560 => Means::Work(2),
        570 => Means::Work(3),
        580 => Means::Work(4),
        590 => Means::Work(5),
        660 => Means::ModalCall(true),
        670 => Means::ModalCall(false),
        900 => Means::Distance(Distance::Absolute),
        910 => Means::Distance(Distance::Incremental),
        930 => Means::FeedMode(FeedMode::Inverse),
        940 => Means::FeedMode(FeedMode::PerMin),
        950 => Means::FeedMode(FeedMode::PerRev),
        960 => Means::Css(true),
        970 => Means::Css(false),
        _ => return None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every kind has its own bit: a set holds what was put in, nothing
    /// else.
    #[test]
    fn kind_sets() {
        let all = [
            Kind::OneShot,
            Kind::Motion,
            Kind::Css,
            Kind::Distance,
            Kind::FeedMode,
            Kind::Units,
            Kind::CutterComp,
            Kind::Stroke,
            Kind::Cycle,
            Kind::Scaling,
            Kind::ModalCall,
            Kind::LengthComp,
            Kind::Work,
            Kind::CuttingMode,
            Kind::Plane,
            Kind::PolarCommand,
            Kind::Rotation,
            Kind::CycleReturn,
            Kind::PolarInterp,
            Kind::HighSpeed,
            Kind::Cylindrical,
            Kind::Stitch,
            Kind::Diameter,
        ];
        assert!(all.len() <= 32);
        for (i, &a) in all.iter().enumerate() {
            let mut s = KindSet::default();
            assert!(!s.has(a));
            s.insert(a);
            for (j, &b) in all.iter().enumerate() {
                assert_eq!(s.has(b), i == j, "{a:?} {b:?}");
            }
            assert!(s.any(&[Kind::Diameter, a]));
        }
        assert!(!KindSet::default().any(&all));
    }
}
