//! What the output is written for: the target (`--to fanuc` / `--to
//! linuxcnc`), the control the program came from, and the spellings that
//! follow from the two (header, feed-mode codes, the thread and dwell
//! words, the spindle clamp, comments).

use std::fmt;
use std::str::FromStr;

/// The kind of control the output is for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Target {
    /// An ISO program for the same kind of control the program was written
    /// for (its own G-code table: HX, PUMA 0-T system A, Hurco MAX).
    Fanuc,
    /// What LinuxCNC's rs274ngc interpreter runs to the same motions.
    LinuxCnc,
}

/// A `--to` value that names no target.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("unknown target '{0}' (fanuc, linuxcnc)")]
pub struct UnknownTarget(pub String);

impl FromStr for Target {
    type Err = UnknownTarget;
    fn from_str(s: &str) -> Result<Target, UnknownTarget> {
        match s {
            "fanuc" => Ok(Target::Fanuc),
            "linuxcnc" => Ok(Target::LinuxCnc),
            _ => Err(UnknownTarget(s.to_string())),
        }
    }
}

impl fmt::Display for Target {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Target::Fanuc => "fanuc",
            Target::LinuxCnc => "linuxcnc",
        })
    }
}

/// The control the program was written for (the machine profile's dialect).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Control {
    /// TurboTek HX machining center (000).
    Hx,
    /// Daewoo PUMA 450, Fanuc 0-T, G-code system A (001).
    Puma,
    /// Hurco MAX turning center (002).
    Hurco,
}

impl Control {
    /// True for the lathes (X written as a diameter on the Fanuc target).
    pub fn is_lathe(self) -> bool {
        !matches!(self, Control::Hx)
    }
}

/// How a threading move is written.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ThreadWord {
    /// PUMA `G32 X Z F(lead)`: F is the lead and shares the modal F.
    G32F,
    /// HX `G33 X Y Z F(lead)`: F is the lead and shares the modal F.
    G33F,
    /// Hurco `G33 X Z K(lead)`: the lead is its own modal word.
    G33K,
}

/// How a dwell is written.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DwellWord {
    /// `G04 X1.5`: seconds (with a decimal point) on the HX and the PUMA.
    X,
    /// Hurco `G04 F`: seconds in G94, spindle revolutions in G95.
    HurcoF,
    /// LinuxCNC `G4 P1.5`: seconds.
    P,
}

/// How the maximum spindle speed under constant surface speed is written.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ClampWord {
    /// PUMA `G50 S`.
    G50,
    /// HX and Hurco `G92 S`.
    G92,
    /// LinuxCNC: the `D` word of the next `G96` block.
    G96D,
}

/// The spellings of one (target, control) pair.
#[derive(Clone, Debug)]
pub struct Spelling {
    pub target: Target,
    pub control: Control,
    /// Decimals of positions and arc centres.
    pub decimals: u32,
    /// Decimals of F (feeds and thread leads) and S.
    pub feed_decimals: u32,
    /// At most this many digits in one number (the control's word format).
    pub max_digits: u32,
    /// Lathe X written as a diameter (its arc I stays a radius).
    pub diameter: bool,
    /// Plane codes G17/G18/G19 exist (the mill, and LinuxCNC).
    pub planes: bool,
    /// Feed per minute, per revolution, inverse time codes.
    pub feed_codes: [Option<&'static str>; 3],
    pub thread: ThreadWord,
    pub dwell: DwellWord,
    pub clamp: ClampWord,
}

impl Spelling {
    /// The spellings for `target` of a program written for `control`.
    pub fn new(target: Target, control: Control) -> Spelling {
        let lathe = control.is_lathe();
        match target {
            Target::Fanuc => Spelling {
                target,
                control,
                decimals: 3,
                feed_decimals: 4,
                max_digits: 8,
                diameter: lathe,
                planes: !lathe,
                feed_codes: match control {
                    Control::Hx => [Some("G94"), Some("G95"), None],
                    Control::Puma => [Some("G98"), Some("G99"), None],
                    Control::Hurco => [Some("G94"), Some("G95"), Some("G93")],
                },
                thread: match control {
                    Control::Hx => ThreadWord::G33F,
                    Control::Puma => ThreadWord::G32F,
                    Control::Hurco => ThreadWord::G33K,
                },
                dwell: match control {
                    Control::Hurco => DwellWord::HurcoF,
                    _ => DwellWord::X,
                },
                clamp: match control {
                    Control::Puma => ClampWord::G50,
                    _ => ClampWord::G92,
                },
            },
            Target::LinuxCnc => Spelling {
                target,
                control,
                decimals: 4,
                feed_decimals: 4,
                max_digits: 15,
                diameter: false,
                planes: true,
                feed_codes: [Some("G94"), Some("G95"), Some("G93")],
                thread: ThreadWord::G33K,
                dwell: DwellWord::P,
                clamp: ClampWord::G96D,
            },
        }
    }

    /// The blocks that open the program, before any event: the program
    /// start, then the modes the output relies on (mm, absolute, plane,
    /// no compensation, no cycle, and on the lathes diameter or radius X).
    pub fn header(&self) -> &'static [&'static str] {
        match (self.target, self.control) {
            (Target::Fanuc, Control::Hx) => &["%", "O0001", "G21", "G17 G40 G49 G80 G90"],
            (Target::Fanuc, Control::Puma) => &["%", "O0001", "G21", "G40 G97"],
            (Target::Fanuc, Control::Hurco) => &["%", "O0001", "G21", "G08 G40 G80 G90 G97"],
            (Target::LinuxCnc, Control::Hx) => &["G21", "G17 G40 G49 G80 G90 G91.1"],
            (Target::LinuxCnc, _) => &["G21", "G18 G8 G40 G49 G80 G90 G91.1 G97"],
        }
    }

    /// The text after the program end block (the Fanuc tape end).
    pub fn trailer(&self) -> &'static str {
        match self.target {
            Target::Fanuc => "%",
            Target::LinuxCnc => "",
        }
    }

    /// The code for a feed mode (0 per minute, 1 per revolution, 2 inverse
    /// time), or None when the control has none.
    pub fn feed_code(&self, mode: usize) -> Option<&'static str> {
        self.feed_codes[mode]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn targets_parse_by_name() {
        assert_eq!("fanuc".parse::<Target>(), Ok(Target::Fanuc));
        assert_eq!("linuxcnc".parse::<Target>(), Ok(Target::LinuxCnc));
        let e = "haas".parse::<Target>().unwrap_err();
        assert_eq!(e.to_string(), "unknown target 'haas' (fanuc, linuxcnc)");
        assert_eq!(Target::LinuxCnc.to_string(), "linuxcnc");
    }

    #[test]
    fn fanuc_lathes_write_diameters_and_no_planes() {
        for c in [Control::Puma, Control::Hurco] {
            let s = Spelling::new(Target::Fanuc, c);
            assert!(s.diameter && !s.planes);
        }
        let hx = Spelling::new(Target::Fanuc, Control::Hx);
        assert!(!hx.diameter && hx.planes);
        // The PUMA's G90 is a turning cycle (system A): never in its header.
        let puma = Spelling::new(Target::Fanuc, Control::Puma);
        assert!(!puma.header().iter().any(|b| b.contains("G90")));
        assert_eq!(puma.feed_code(1), Some("G99"));
    }

    #[test]
    fn linuxcnc_has_no_program_number_and_radius_lathe_x() {
        for c in [Control::Hx, Control::Puma, Control::Hurco] {
            let s = Spelling::new(Target::LinuxCnc, c);
            assert!(!s.header().iter().any(|b| b.starts_with('O') || *b == "%"));
            assert!(!s.diameter);
        }
        let lathe = Spelling::new(Target::LinuxCnc, Control::Puma);
        assert!(lathe.header().iter().any(|b| b.contains("G8")));
    }
}
