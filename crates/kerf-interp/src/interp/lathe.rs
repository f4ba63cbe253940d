//! PUMA (Fanuc 0-T, G-code system A) lathe motion: G32 threading and the
//! single cycles G90/G92/G94 (001 "G32", "G90", "G92", "G94";
//! fanuc-semantics §2), their modal data, and the M76/M77 thread
//! chamfering switch. The paths are made by the pure geometry of
//! [`crate::turning`]; every move goes through [`Interp::line_to`] (or
//! [`Interp::thread_to`]) in program coordinates.

use super::*;
use crate::dialect::{Dialect, MAlso};
use crate::turning::{self, Mv, P};

/// The lathe cycle state of one interpreter: the modal data of the single
/// cycles and of the multiple repetitive cycles (interp/lathe_mrc.rs), the
/// thread chamfer switch.
#[derive(Clone, Debug, Default)]
pub(super) struct PumaFeatures {
    /// G90/G92/G94 in force: its end point (program coordinates, X a
    /// radius) and taper R (radius), kept for blocks that repeat the
    /// cycle with only some words.
    pub(super) single: Option<(P, f64)>,
    /// M76 in force (thread chamfering on); M77 (power-on) turns it off.
    pub(super) chamfer_on: bool,
    /// The corner B of the last chamfer / corner-R block: the next
    /// block's incremental words count from it (interp/lathe_chamfer.rs).
    pub(super) ddi_base: Option<Pos>,
    /// Modal first-block values of G70-G76 (interp/lathe_mrc.rs).
    pub(super) mrc: super::lathe_mrc::MrcModal,
    /// G-code system B selected (`gcode_system_b = 1`, interp/system_b.rs).
    pub(super) system_b: bool,
}

impl PumaFeatures {
    /// No cycle in force, thread chamfering off; G-code system B when the
    /// control has it and the profile selects it (`gcode_system_b = 1`).
    pub(super) fn new(profile: &Profile, dialect: &Dialect) -> PumaFeatures {
        PumaFeatures {
            system_b: dialect.caps.gcode_system_b && profile.param("gcode_system_b", 0.0) != 0.0,
            ..Default::default()
        }
    }
}

impl Interp {
    /// What the PUMA's compound M codes do besides their action (the
    /// table's `MAlso`), before the block's motion: M76/M77 (001 "M76,
    /// M77") switch thread chamfering; M63/M64 (main spindle CW/CCW and
    /// coolant on) start the coolant too (the action is the spindle part).
    pub(super) fn lathe_m_codes(&mut self) {
        for i in 0..self.words.nm {
            match self.mcode(self.words.m[i].0).map(|c| c.also) {
                Some(MAlso::ThreadChamfer(on)) => self.puma.chamfer_on = on,
                Some(MAlso::CoolantOn) => self.lathe_coolant(true),
                _ => {}
            }
        }
    }

    /// After the block's motion: M65 (main spindle and coolant stop) stops
    /// the coolant too.
    pub(super) fn lathe_m_after(&mut self) {
        let off = |m: &(u32, u32)| self.mcode(m.0).is_some_and(|c| c.also == MAlso::CoolantOff);
        if self.words.ms().iter().any(off) {
            self.lathe_coolant(false);
        }
    }

    fn lathe_coolant(&mut self, on: bool) {
        if self.tool.flood != on || (!on && self.tool.mist) {
            self.tool.flood = on;
            if !on {
                self.tool.mist = false;
            }
            self.emit(Canon::Coolant {
                mist: self.tool.mist,
                flood: self.tool.flood,
            });
        }
    }

    /// G96 (constant surface speed): before each move, a spindle event
    /// when the rpm for the move's end point (the position is already
    /// there when the move is emitted) differs from the last one — the
    /// Fanuc rule for G00, and for cutting moves the speed the spindle
    /// reaches at their end (fanuc-semantics §8.9). Clamped by G50 S and
    /// the machine maximum.
    pub(super) fn css_follow(&mut self) {
        if self.tool.spindle == SpindleDir::Stop || self.cfg.profile.kind != MachineKind::Lathe {
            return;
        }
        let rpm = self.rpm();
        if (rpm - self.tool.last_rpm).abs() > 1e-6 {
            self.tool.last_rpm = rpm;
            let css = self.css_speed();
            self.emit(Canon::Spindle {
                dir: self.tool.spindle,
                rpm,
                css,
            });
        }
    }

    /// The current position as a ZX point (program coordinates).
    pub(super) fn zx_pos(&self) -> P {
        let c = self.prog_pos();
        turning::p(c[Axis::X as usize], c[Axis::Z as usize])
    }

    /// A ZX point as a full program-coordinate position (the other axes
    /// where they are).
    pub(super) fn zx_full(&self, q: P) -> Pos {
        let mut t = self.prog_pos();
        t[Axis::X as usize] = q.x;
        t[Axis::Z as usize] = q.z;
        t
    }

    /// Emits generated moves; `feed` overrides the modal feed of the cuts.
    pub(super) fn emit_moves(&mut self, mvs: &[Mv], feed: Option<Feed>, at: u32) -> R<()> {
        let speed = match feed {
            Some(f) => motion::Speed::Feed(f),
            None => motion::Speed::Modal,
        };
        let same = |a: &Pos, b: &Pos| a.iter().zip(b).all(|(u, v)| (u - v).abs() < 1e-9);
        for m in mvs {
            let t = self.zx_full(m.to());
            match *m {
                Mv::Rapid(_) => {
                    if !same(&t, &self.prog_pos()) {
                        self.line_to(t, motion::Speed::Rapid, at)?
                    }
                }
                Mv::Feed(_) => {
                    if !same(&t, &self.prog_pos()) {
                        self.line_to(t, speed, at)?
                    }
                }
                Mv::Thread(_) => self.thread_to(t, at)?,
                Mv::Arc { c, ccw, .. } => {
                    let f = match feed {
                        Some(f) => f,
                        None => self.feed(at)?,
                    };
                    let cur = self.prog_pos();
                    self.arc_to(cur, t, (c.z, c.x), ccw, f, at)?
                }
            }
        }
        Ok(())
    }

    /// A spindle-synchronised straight move to `tw` (program coordinates)
    /// at the modal lead F: G32, and the cuts of G92 and G76. The lead
    /// must be set, the spindle turning, and (kerf's rule, docs/dialects.md)
    /// a thread that changes X is not cut in G96.
    pub(super) fn thread_to(&mut self, tw: Pos, at: u32) -> R<()> {
        let Some(lead) = self.tool.feed.filter(|f| *f > 0.0) else {
            return Err(self.alarm(AlarmKind::NoFeed, at, "threading without a thread lead (F)"));
        };
        if self.tool.spindle == SpindleDir::Stop {
            return Err(self.alarm(
                AlarmKind::NoFeed,
                at,
                "threading with the spindle stopped: the cut would wait for the one-revolution signal forever",
            ));
        }
        let cur = self.prog_pos();
        let xi = Axis::X as usize;
        if self.modal.css.means && (tw[xi] - cur[xi]).abs() > 1e-9 {
            return Err(self.alarm(
                AlarmKind::LatheCycle,
                at,
                "threading move that changes X (taper or face thread, run-out chamfer) in G96 (constant surface speed): the spindle speed would change during the cut; program G97",
            ));
        }
        self.thread_move(tw, lead, at)
    }

    /// The block's move in G32, G90, G92 or G94 mode (PUMA).
    pub(super) fn lathe_motion(&mut self, mode: MotionMode, tw: Pos, any: bool, at: u32) -> R<()> {
        if !any {
            return Ok(());
        }
        if mode == MotionMode::ThreadLathe {
            return self.thread_to(tw, at);
        }
        let a = self.zx_pos();
        let code = self.modal.motion.code10;
        let fresh = self.words.gs().iter().any(|g| g.0 == code);
        let xi = Axis::X as usize;
        let zi = Axis::Z as usize;
        let has = |me: &Self, ax: Axis| me.words.has(ax_letter(ax)) || me.uvw(ax).is_some();
        // A block that repeats the cycle takes the words it lacks from the
        // cycle in force; a new cycle from the current position.
        let (mut e, mut r) = match (fresh, self.puma.single) {
            (false, Some(s)) => s,
            _ => (a, 0.0),
        };
        if has(self, Axis::X) {
            e.x = tw[xi];
        }
        if has(self, Axis::Z) {
            e.z = tw[zi];
        }
        if let Some(w) = self.words.get(b'R') {
            r = self.linear(w);
        }
        self.puma.single = Some((e, r));
        let at_r = self.words.get(b'R').map(|w| w.at).unwrap_or(at);
        // Cases 3 and 4 of the figures: |R| ≤ |U/2| (|W| for G94); beyond,
        // the cut would start behind the start point.
        let (len, rr) = if mode == MotionMode::FaceCycle {
            (e.z - a.z, r)
        } else {
            (e.x - a.x, r)
        };
        if len * rr < 0.0 && rr.abs() > len.abs() + 1e-9 {
            return Err(self.alarm(
                AlarmKind::LatheCycle,
                at_r,
                format!(
                    "G{}: taper R {} is larger than the cycle's {} distance {} (cases 3/4 need |R| ≤ |{}|)",
                    code / 10,
                    fmt_num(rr),
                    if mode == MotionMode::FaceCycle { "Z" } else { "X (radius)" },
                    fmt_num(len.abs()),
                    if mode == MotionMode::FaceCycle { "W" } else { "U/2" }
                ),
            ));
        }
        let mvs: Vec<Mv> = match mode {
            MotionMode::TurnCycle => turning::g90(a, e, r).to_vec(),
            MotionMode::FaceCycle => turning::g94(a, e, r).to_vec(),
            _ => {
                let c = if self.puma.chamfer_on {
                    self.cfg.profile.param("thread_chamfer_leads", 1.0)
                        * self.tool.feed.unwrap_or(0.0)
                } else {
                    0.0
                };
                turning::g92(a, e, r, c)
                    .map_err(|e| self.alarm(AlarmKind::LatheCycle, at, cycle_msg(&e)))?
            }
        };
        self.emit_moves(&mvs, None, at)
    }
}

/// The text of a geometry error.
pub(super) fn cycle_msg(e: &turning::CycleError) -> String {
    match e {
        turning::CycleError::Value(s) => s.clone(),
        turning::CycleError::NotMonotonic(i, ax) => {
            format!("the shape is not monotonic in {ax} (segment {})", i + 1)
        }
        turning::CycleError::TooManyMoves => format!(
            "the cycle would make more than {} moves",
            turning::MAX_MOVES
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// G-code system B is a PUMA option selected by a parameter; no
    /// cycle is in force at power-on.
    #[test]
    fn system_b_is_the_pumas_and_needs_its_parameter() {
        let features = |name: &str, b: Option<f64>| {
            let mut p = Profile::builtin(name).unwrap();
            if let Some(b) = b {
                p.params.insert("gcode_system_b".into(), b);
            }
            PumaFeatures::new(&p, Dialect::get(p.dialect))
        };
        assert!(features("puma-lathe", Some(1.0)).system_b);
        assert!(!features("puma-lathe", Some(0.0)).system_b);
        assert!(!features("puma-lathe", None).system_b);
        assert!(!features("hx-mc", Some(1.0)).system_b);
        let f = features("puma-lathe", None);
        assert!(f.single.is_none() && !f.chamfer_on && f.ddi_base.is_none());
    }
}
