//! The boundary between what a part program *means* and what the machine
//! *does*: canonical commands, axis positions, source references and alarms.
//!
//! Everything downstream of the interpreter (planner, simulator, toolpath
//! writers, plotters) consumes [`Event`]s and never re-reads G-code. This
//! crate holds types only; there is no logic here beyond small helpers
//! (`geom`, and `digits` for the text writers).
//!
//! Units are fixed: millimetres, degrees, seconds, mm/min. Lathe X is the
//! physical radius (distance from the spindle centre line) whatever the
//! program's diameter/radius mode was.

use std::fmt;

pub mod digits;
pub mod geom;

/// Number of axis slots carried in a [`Pos`]: X Y Z A B C.
pub const NAXES: usize = 6;

/// Axis index in a [`Pos`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Axis {
    /// Linear X (lathe: radius from the spindle centre line).
    X = 0,
    /// Linear Y.
    Y = 1,
    /// Linear Z.
    Z = 2,
    /// Rotary A.
    A = 3,
    /// Rotary B.
    B = 4,
    /// Rotary C.
    C = 5,
}

impl Axis {
    /// All axes in slot order.
    pub const ALL: [Axis; NAXES] = [Axis::X, Axis::Y, Axis::Z, Axis::A, Axis::B, Axis::C];

    /// The axis for an address letter (`b'X'` …), if it is one.
    pub fn from_letter(c: u8) -> Option<Axis> {
        Some(match c {
            b'X' => Axis::X,
            b'Y' => Axis::Y,
            b'Z' => Axis::Z,
            b'A' => Axis::A,
            b'B' => Axis::B,
            b'C' => Axis::C,
            _ => return None,
        })
    }

    /// Lower-case name used in the output formats (`"x"` …).
    pub fn name(self) -> &'static str {
        ["x", "y", "z", "a", "b", "c"][self as usize]
    }

    /// True for the rotary axes A, B, C.
    pub fn is_rotary(self) -> bool {
        matches!(self, Axis::A | Axis::B | Axis::C)
    }
}

/// A position of all axis slots, mm / degrees.
pub type Pos = [f64; NAXES];

/// Where in the source a block (or a word of it) came from.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct SrcRef {
    /// Index into the interpreter's file table (see `Interp::file_name`).
    pub file: u32,
    /// 1-based line.
    pub line: u32,
    /// 1-based column (byte column within the line).
    pub col: u32,
}

/// Direction of an arc seen from the positive end of the plane normal.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ArcDir {
    /// Clockwise (G02).
    Cw,
    /// Counter-clockwise (G03).
    Ccw,
}

impl ArcDir {
    /// `"cw"` or `"ccw"`.
    pub fn name(self) -> &'static str {
        match self {
            ArcDir::Cw => "cw",
            ArcDir::Ccw => "ccw",
        }
    }
}

/// Working plane; the first two axes are the arc plane, the third the normal.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Plane {
    /// G17: X-Y, normal Z.
    XY,
    /// G18: Z-X, normal Y.
    ZX,
    /// G19: Y-Z, normal X.
    YZ,
}

impl Plane {
    /// (first, second, normal) axis indices, right-handed.
    pub fn axes(self) -> (usize, usize, usize) {
        match self {
            Plane::XY => (0, 1, 2),
            Plane::ZX => (2, 0, 1),
            Plane::YZ => (1, 2, 0),
        }
    }
}

/// Spindle rotation.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SpindleDir {
    /// M03.
    Cw,
    /// M04.
    Ccw,
    /// M05 (or not yet started).
    Stop,
}

/// A linear or circular motion of the tool control point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Motion {
    /// End point of the tool tip in the active work coordinate system (what
    /// the ABSOLUTE position page shows): after cutter / nose radius
    /// compensation, while a tool length or lathe tool offset leaves it at
    /// the programmed point (000 §13.1.1).
    pub to: Pos,
    /// End point in machine coordinates (the spindle gauge line or turret
    /// reference: tool length and tool offsets included).
    pub mto: Pos,
}

/// A canonical command: one thing the machine is told to do.
#[derive(Clone, Debug, PartialEq)]
pub enum Canon {
    /// Positioning at rapid traverse. `linear` is false for the HX
    /// non-linear (dog-leg) positioning where each axis moves at its own rate.
    Rapid { m: Motion, linear: bool },
    /// Linear interpolation at `feed` mm/min (per-revolution feeds are
    /// converted by the planner using the spindle speed; `per_rev` is then
    /// the mm/rev value).
    Feed { m: Motion, feed: Feed },
    /// Circular (or helical) interpolation.
    Arc {
        m: Motion,
        /// Centre in work coordinates (the plane's two axes are meaningful;
        /// the normal coordinate is the start's).
        center: Pos,
        /// Centre in machine coordinates.
        mcenter: Pos,
        dir: ArcDir,
        plane: Plane,
        /// Extra full turns (0 for an ordinary arc).
        turns: u32,
        feed: Feed,
    },
    /// Spindle-synchronised threading move with a lead in mm/rev.
    Thread { m: Motion, lead: f64 },
    /// Dwell: `seconds`, or spindle `revolutions` when the control counts
    /// dwell in revolutions.
    Dwell { seconds: f64, revolutions: f64 },
    /// Spindle state change. `rpm` is the commanded speed; `css` is the
    /// surface speed in m/min when constant surface speed is active.
    Spindle {
        dir: SpindleDir,
        rpm: f64,
        css: Option<f64>,
    },
    /// Coolant on (`M07` mist / `M08` flood) or off (`M09`).
    Coolant { mist: bool, flood: bool },
    /// Tool selected (T word) and/or changed (M06, or a turret index).
    Tool {
        tool: u32,
        offset: u32,
        change: bool,
    },
    /// Program stop M00 or optional stop M01 (only emitted when the optional
    /// stop switch is on).
    Stop { optional: bool },
    /// An auxiliary function the interpreter does not model further: the M
    /// number and the manual's name for it.
    Aux { m: u32, name: &'static str },
    /// A modal setting the planner needs (exact stop, feed mode, …).
    Mode(ModeChange),
    /// An operator message (comment shown on the screen, `#3006`, …).
    Message(String),
    /// End of program (M02/M30/M99 at the top level/end of text).
    End { code: u32 },
}

/// A feed rate as programmed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Feed {
    /// mm/min.
    PerMin(f64),
    /// mm per spindle revolution.
    PerRev(f64),
    /// G93 inverse time: the move takes 1/`value` minutes.
    InverseTime(f64),
}

/// Modal changes reported for the planner.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ModeChange {
    /// G09: exact stop at the end of this block only.
    ExactStopBlock,
    /// G61 exact stop mode (true) / back to cutting mode.
    ExactStopMode(bool),
    /// G64 cutting mode.
    CuttingMode,
    /// G62 automatic corner override.
    CornerOverride,
    /// G63 tapping mode.
    TappingMode,
    /// G10.3 (true) / G11.3 (false) high-speed machining mode.
    HighSpeed(bool),
    /// HX G63.1 (true) / G63.2 (false) stitch function mode (000 §15.6;
    /// its stroke feeds and times are PM 7308-7357, for the planner).
    Stitch(bool),
    /// Maximum spindle speed under constant surface speed, rpm: PUMA G50 S,
    /// HX and Hurco G92 S (the planner's per-revolution feeds follow the
    /// clamped speed).
    SpindleClamp(f64),
    /// Hurco M48 (true) / M49 (false): the feed override applies / is
    /// ignored (the programmed feed is used).
    FeedOverride(bool),
    /// HX G112 / G113 and G107 (000 §4.6, §4.7): the rotary-axis
    /// interpolation the following motions are made in. Emitted at the
    /// block that changes it; the motions themselves stay in machine axes
    /// (X radius and C degrees), so a consumer that draws or times them on
    /// the programmed surface reads the mode from here.
    Rotary(RotaryMode),
}

/// The HX rotary-axis interpolation in force (see [`ModeChange::Rotary`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum RotaryMode {
    /// Neither: G113, G107 C0, or not yet commanded.
    Off,
    /// G112 polar coordinate interpolation: the contour is programmed in the
    /// Cartesian X-C plane on the part's face; the motions turn C.
    Polar,
    /// G107 cylindrical interpolation on a cylinder of `radius` mm: C in
    /// degrees stands for the length C·π·radius/180 on the developed
    /// surface. `plane` is the program's plane (G17: C with Y, G18: Z with C).
    Cylinder { radius: f64, plane: Plane },
}

impl RotaryMode {
    /// Millimetres on the developed surface per degree of C: π·r/180 in
    /// G107, None otherwise.
    pub fn mm_per_degree(self) -> Option<f64> {
        match self {
            RotaryMode::Cylinder { radius, .. } => Some(radius * std::f64::consts::PI / 180.0),
            _ => None,
        }
    }

    /// The length of a straight move from `p0` to `p1` (machine
    /// positions) on the programmed surface, which F is the speed along:
    /// in G107 with C as its arc length on the cylinder; in G112 in the
    /// Cartesian plane of the face, from the radii `r0` and `r1` (the work
    /// X at the two ends, X0 on the C axis) and the turn of C, with Y and
    /// Z. None when neither is in force (the machine's own length).
    #[inline]
    pub fn programmed_len(self, p0: &Pos, p1: &Pos, r0: f64, r1: f64) -> Option<f64> {
        if self == RotaryMode::Off {
            return None;
        }
        let d: [f64; NAXES] = std::array::from_fn(|i| p1[i] - p0[i]);
        let c = Axis::C as usize;
        match self {
            RotaryMode::Off => None,
            RotaryMode::Cylinder { .. } => {
                let k = self.mm_per_degree()?;
                let sq: f64 = (0..NAXES).filter(|&i| i != c).map(|i| d[i] * d[i]).sum();
                Some((sq + (d[c] * k).powi(2)).sqrt())
            }
            RotaryMode::Polar => {
                // The chord between (r0, θ0) and (r1, θ1): (r1 − r0)² +
                // 4·r0·r1·sin²(Δθ/2), exact for small turns too.
                let half = (d[c] / 2.0).to_radians().sin();
                let face = (r1 - r0).powi(2) + 4.0 * r0 * r1 * half * half;
                let (y, z) = (d[Axis::Y as usize], d[Axis::Z as usize]);
                Some((face.max(0.0) + y * y + z * z).sqrt())
            }
        }
    }
}

/// A canonical command with the source position of the block that made it.
#[derive(Clone, Debug, PartialEq)]
pub struct Event {
    pub src: SrcRef,
    /// Tool number in the spindle / active turret station.
    pub tool: u32,
    pub cmd: Canon,
    /// For a motion whose end point was moved by cutter or tool nose
    /// radius compensation: the programmed end point (work coordinates),
    /// where `cmd`'s `to` is the compensated control point. None when
    /// the two are the same.
    pub prog: Option<Box<Pos>>,
}

impl Event {
    /// The motion carried by this event, if it moves the axes.
    pub fn motion(&self) -> Option<&Motion> {
        match &self.cmd {
            Canon::Rapid { m, .. }
            | Canon::Feed { m, .. }
            | Canon::Arc { m, .. }
            | Canon::Thread { m, .. } => Some(m),
            _ => None,
        }
    }
}

/// An alarm: the control's number, a message, and where in the program.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Alarm {
    /// The control's alarm code, e.g. `F_82001` or `PS0010`.
    pub code: String,
    pub message: String,
    pub src: SrcRef,
}

impl Alarm {
    /// Builds an alarm.
    pub fn new(code: impl Into<String>, message: impl Into<String>, src: SrcRef) -> Alarm {
        Alarm {
            code: code.into(),
            message: message.into(),
            src,
        }
    }
}

impl fmt::Display for Alarm {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "alarm {}: {}", self.code, self.message)
    }
}

impl std::error::Error for Alarm {}
