//! The events that make no motion: dwell, spindle, coolant, tool, stops,
//! M functions, modes, messages and the program end, in each target's
//! words.

use std::io::Write;

use kerf_canon::{Canon, ModeChange, SpindleDir};

use crate::expander::{push_comment_text, Expander, Written};
use crate::num;
use crate::target::{ClampWord, DwellWord, Target};
use crate::Control;

/// The spindle as the output program has set it.
#[derive(Clone, Copy, Debug, Default)]
pub struct SpindleState {
    /// Direction written (None before the first spindle block).
    pub dir: Option<SpindleDir>,
    /// Surface speed written with G96 (m/min, scaled by 1000), or None in G97.
    pub css: Option<i64>,
    /// Speed written with G97 (rpm, scaled by 1000).
    pub rpm: Option<i64>,
    /// The speed the spindle runs at in the original (for LinuxCNC's
    /// dwell in revolutions).
    pub actual_rpm: f64,
    /// LinuxCNC: the maximum speed for the next G96 (its D word).
    pub clamp: Option<f64>,
}

impl<W: Write> Expander<W> {
    pub(crate) fn dwell(&mut self, seconds: f64, revolutions: f64) -> Written {
        let linux = self.sp().target == Target::LinuxCnc;
        match self.sp().dwell {
            DwellWord::HurcoF if !linux => {
                // 002: G04 F is seconds in G94, revolutions in G95.
                let (mode, v) = if revolutions > 0.0 {
                    (1, revolutions)
                } else {
                    (0, seconds)
                };
                if self.feed_mode() != Some(mode) {
                    let c = if mode == 1 { "G95 " } else { "G94 " };
                    self.buf().extend_from_slice(c.as_bytes());
                    self.set_feed_mode(mode);
                }
                self.buf().extend_from_slice(b"G04 F");
                num::put(self.buf(), v, 4);
                self.set_feed(None);
            }
            w => {
                let secs = if revolutions > 0.0 && self.spindle.actual_rpm > 0.0 {
                    seconds + revolutions * 60.0 / self.spindle.actual_rpm
                } else {
                    seconds
                };
                let text: &[u8] = if linux || w == DwellWord::P {
                    b"G4 P"
                } else {
                    b"G04 X"
                };
                self.buf().extend_from_slice(text);
                num::put(self.buf(), secs, 3);
            }
        }
        Written::Block
    }

    /// Every event that is neither a motion nor a dwell.
    pub(crate) fn machine_event(&mut self, cmd: &Canon) -> Written {
        let linux = self.sp().target == Target::LinuxCnc;
        match cmd {
            Canon::Spindle { dir, rpm, css } => self.spindle_words(*dir, *rpm, *css),
            Canon::Coolant { mist, flood } => self.coolant_words(*mist, *flood),
            Canon::Tool {
                tool,
                offset,
                change,
            } => self.tool_words(*tool, *offset, *change),
            Canon::Stop { optional } => {
                self.put_str(if *optional { "M01" } else { "M00" });
                Written::Block
            }
            Canon::Aux { m, name } => {
                if linux {
                    // LinuxCNC knows few M numbers, none with the Fanuc
                    // machine's meaning: kept as a note.
                    self.put_str("(M");
                    num::put_uint(self.buf(), *m as u64, 2);
                    self.put_str(" ");
                    push_comment_text(self.buf(), name, 80);
                    self.put_str(")");
                } else {
                    self.put_str("M");
                    num::put_uint(self.buf(), *m as u64, 2);
                }
                Written::Block
            }
            Canon::Mode(m) => self.mode_words(*m),
            Canon::Message(text) => {
                self.put_str(if linux { "(MSG, " } else { "(MSG " });
                push_comment_text(self.buf(), text, 120);
                self.put_str(")");
                Written::Block
            }
            Canon::End { code } => {
                let c = match (linux, *code) {
                    (true, 2) => "M2",
                    (true, _) => "M30",
                    (false, 2) => "M02",
                    (false, _) => "M30",
                };
                self.put_str(c);
                Written::Block
            }
            // Motions and dwells are written by the caller.
            _ => Written::Nothing,
        }
    }

    fn put_str(&mut self, s: &str) {
        self.buf().extend_from_slice(s.as_bytes());
    }

    fn spindle_words(&mut self, dir: SpindleDir, rpm: f64, css: Option<f64>) -> Written {
        let linux = self.sp().target == Target::LinuxCnc;
        self.spindle.actual_rpm = if dir == SpindleDir::Stop { 0.0 } else { rpm };
        let mut any = false;
        match css {
            Some(v) => {
                let n = num::scaled(v, 3);
                if self.spindle.css != Some(n) || (linux && self.spindle.clamp.is_some()) {
                    self.put_str("G96");
                    if let (true, Some(d)) = (linux, self.spindle.clamp.take()) {
                        self.put_str(" D");
                        num::put(self.buf(), d, 3);
                    }
                    self.put_str(" S");
                    num::put_scaled(self.buf(), n, 3);
                    self.spindle.css = Some(n);
                    self.spindle.rpm = None;
                    any = true;
                }
            }
            None => {
                let n = num::scaled(rpm, 3);
                let was_css = self.spindle.css.take().is_some();
                // The speed of a stopped spindle is written once it runs.
                if was_css || (self.spindle.rpm != Some(n) && rpm > 0.0) {
                    self.put_str(if was_css { "G97 S" } else { "S" });
                    num::put_scaled(self.buf(), n, 3);
                    self.spindle.rpm = Some(n);
                    any = true;
                }
            }
        }
        if self.spindle.dir != Some(dir) {
            self.spindle.dir = Some(dir);
            if any {
                self.put_str(" ");
            }
            self.put_str(match (linux, dir) {
                (false, SpindleDir::Cw) => "M03",
                (false, SpindleDir::Ccw) => "M04",
                (false, SpindleDir::Stop) => "M05",
                (true, SpindleDir::Cw) => "M3",
                (true, SpindleDir::Ccw) => "M4",
                (true, SpindleDir::Stop) => "M5",
            });
            any = true;
        }
        if any {
            Written::Block
        } else {
            Written::Nothing
        }
    }

    fn coolant_words(&mut self, mist: bool, flood: bool) -> Written {
        let (was_mist, was_flood) = self.coolant;
        if (mist, flood) == (was_mist, was_flood) {
            return Written::Nothing;
        }
        self.coolant = (mist, flood);
        // One M code per block (Fanuc; LinuxCNC's one modal group): M09 first when
        // something goes off, then what comes on, each its own block.
        let mut codes: Vec<&str> = Vec::with_capacity(3);
        if (was_mist && !mist) || (was_flood && !flood) {
            codes.push("M09");
            if mist {
                codes.push("M07");
            }
            if flood {
                codes.push("M08");
            }
        } else {
            if mist && !was_mist {
                codes.push("M07");
            }
            if flood && !was_flood {
                codes.push("M08");
            }
        }
        let linux = self.sp().target == Target::LinuxCnc;
        for (k, c) in codes.iter().enumerate() {
            if k > 0 {
                self.new_line();
            }
            // LinuxCNC spells them M7 M8 M9.
            self.put_str(if linux { &c[..1] } else { c });
            if linux {
                self.put_str(&c[2..]);
            }
        }
        Written::Block
    }

    fn tool_words(&mut self, tool: u32, offset: u32, change: bool) -> Written {
        let linux = self.sp().target == Target::LinuxCnc;
        let control = self.sp().control;
        self.put_str("T");
        if !linux && control.is_lathe() {
            // T tool(2) offset(2), PUMA T0101, Hurco T mm…nn; the offset
            // number is 00: the tool offset is in the output's frame
            // (G50/G92 before the next move), not taken up a second time.
            let _ = offset;
            num::put_uint(self.buf(), tool as u64, 2);
            self.put_str("00");
        } else {
            num::put_uint(self.buf(), tool as u64, 1);
        }
        if change && (linux || control == Control::Hx) {
            self.put_str(if linux { " M6" } else { " M06" });
        }
        if change && linux {
            // LinuxCNC's M6 stops the spindle (a Fanuc turret index or M06
            // leaves it to the program): start it again as it was.
            match self.spindle.dir {
                Some(SpindleDir::Cw) => {
                    self.new_line();
                    self.put_str("M3");
                }
                Some(SpindleDir::Ccw) => {
                    self.new_line();
                    self.put_str("M4");
                }
                _ => {}
            }
        }
        Written::Block
    }

    fn mode_words(&mut self, m: ModeChange) -> Written {
        let linux = self.sp().target == Target::LinuxCnc;
        let text: Option<&str> = match m {
            ModeChange::ExactStopBlock => {
                self.set_exact_stop_block();
                None
            }
            ModeChange::ExactStopMode(true) => Some("G61"),
            ModeChange::ExactStopMode(false) | ModeChange::CuttingMode => Some("G64"),
            ModeChange::CornerOverride if !linux => Some("G62"),
            ModeChange::TappingMode if !linux => Some("G63"),
            ModeChange::HighSpeed(on) if !linux => Some(if on { "G10.3" } else { "G11.3" }),
            ModeChange::Stitch(on) if !linux => Some(if on { "G63.1" } else { "G63.2" }),
            ModeChange::FeedOverride(on) => Some(if on { "M48" } else { "M49" }),
            ModeChange::SpindleClamp(rpm) => return self.clamp_words(rpm),
            // Planner modes LinuxCNC has no code for.
            _ => None,
        };
        match text {
            Some(t) => {
                self.put_str(t);
                Written::Block
            }
            None => Written::Nothing,
        }
    }

    fn clamp_words(&mut self, rpm: f64) -> Written {
        match self.sp().clamp {
            ClampWord::G96D => {
                self.spindle.clamp = Some(rpm);
                Written::Nothing
            }
            c => {
                self.put_str(if c == ClampWord::G50 {
                    "G50 S"
                } else {
                    "G92 S"
                });
                num::put(self.buf(), rpm, 3);
                Written::Block
            }
        }
    }
}
