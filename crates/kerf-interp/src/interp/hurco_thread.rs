//! Hurco G78 multi-pass threading cycle (002 Tables 5-13).
//!
//! The cycle is planned in two abstract axes: the thread axis `a` (Z for a
//! turn thread, X as a radius for a face thread, M1) and the depth axis `d`
//! (X radius / Z). Rules where 002 is silent are kerf's and are recorded in
//! docs/dialects.md ("G78 threading"):
//!
//! - Rough passes: rough depth `Rt = |J| - P*L`. Without V the cut depth
//!   of each pass falls linearly from at most D to exactly E:
//!   `n = ceil(2 Rt / (D + E))` passes, first `2 Rt / n - E`, last E; when
//!   that would make the first pass smaller than E, `ceil(Rt / D)` equal
//!   passes. With V1 (constant volume) the cumulative depth of pass k is
//!   `D * sqrt(k)`, the last one clipped to Rt. Then P finish passes of L
//!   and R spring passes at full depth (P + R spring passes when L is 0).
//! - One pass: rapid to the start point (clearance, W before the thread
//!   start), in-feed (rapid, or with A a threaded chase-in line at A° to
//!   the depth axis), thread to the pull-out point, pull-out (rapid, or
//!   with C a threaded line at C° reaching the clearance), rapid back to
//!   the start point. The pull-out line passes through the thread end at
//!   the major radius (H); Z (end at the clearance) and T (length from K
//!   at the major radius, towards -Z when positive) are converted to H.
//! - Taper B: every line of the pass is parallel to the thread at B° to
//!   the thread axis; positive B moves away from the centre line (turn) or
//!   from the part face (face) as the thread proceeds.
//! - Q > 0 starts: every depth is cut at each start, at 360/Q steps; a
//!   start angle other than 0 is emitted as a message before the pass's
//!   first threaded move ("thread start angle 120").

use super::thread_plan::{self, ParamError, ThreadPlan, Units};
use super::*;
use crate::dialect::hurco::{LongKind, LONG_LETTERS};

/// The G78/G38 parameters: the block's letters merged with the
/// multi-letter names.
pub(super) struct MacroParams {
    pub v: [Option<WVal>; 26],
    /// X was given as `minD` (a diameter).
    pub x_diameter: bool,
}

impl MacroParams {
    pub fn get(&self, l: u8) -> Option<WVal> {
        self.v[(l - b'A') as usize]
    }
}

impl Interp {
    /// The G78/G38 block's parameters (letters and multi-letter names; a
    /// letter given both ways is an alarm).
    pub(super) fn macro_params(&self) -> R<MacroParams> {
        let mut p = MacroParams {
            v: self.words.letters,
            x_diameter: false,
        };
        for i in 0..self.words.nlong {
            let (k, mut w) = self.words.long[i];
            let Some(&(l, kind)) = LONG_LETTERS.get(k as usize) else {
                continue;
            };
            let slot = &mut p.v[(l - b'A') as usize];
            if slot.is_some() {
                return Err(self.alarm(
                    AlarmKind::DuplicateAddress,
                    w.at,
                    format!("parameter {} given twice", l as char),
                ));
            }
            match kind {
                LongKind::Plain => {}
                LongKind::Negated => w.v = -w.v,
                LongKind::Diameter => p.x_diameter = true,
            }
            *slot = Some(w);
        }
        Ok(p)
    }

    /// A G78 block: plan the passes, then cut them.
    pub(super) fn g78(&mut self, at: u32, face_m: Option<WVal>) -> R<()> {
        let mut p = self.macro_params()?;
        if let Some(m) = face_m {
            if p.get(b'M').is_some() {
                return Err(self.alarm(
                    AlarmKind::DuplicateAddress,
                    m.at,
                    "parameter M given twice",
                ));
            }
            p.v[(b'M' - b'A') as usize] = Some(m);
        }
        if self.modal.css.means {
            return Err(self.alarm(
                AlarmKind::ThreadCycle,
                at,
                "G78 needs direct spindle speed (G97), not G96",
            ));
        }
        if self.tool.spindle == SpindleDir::Stop || self.rpm() <= 0.0 {
            return Err(self.alarm(
                AlarmKind::ThreadCycle,
                at,
                "G78 needs the spindle running (M03/M04 with S)",
            ));
        }
        let plan = self.thread_plan(&p, at)?;
        self.cut_thread(&plan, at)
    }

    /// Reads and checks the parameters of Tables 5-13
    /// ([`ThreadPlan::from_params`]).
    pub(super) fn thread_plan(&self, p: &MacroParams, at: u32) -> R<ThreadPlan> {
        let face = thread_plan::face_of(p).map_err(|e| self.param_alarm(e))?;
        for (l, w) in p.v.iter().enumerate() {
            if let Some(w) = w {
                let l = b'A' + l as u8;
                if matches!(l, b'X' | b'Z' | b'I' | b'K' | b'U' | b'W' | b'J' | b'H') {
                    self.check_range_hurco(l, *w)?;
                }
            }
        }
        let units = Units {
            metric: self.modal.metric(),
            calculator_decimal: self.cfg.profile.calculator_decimal,
            lead_range: self.hurco_lead_range(),
        };
        ThreadPlan::from_params(p, face, units, at).map_err(|e| self.param_alarm(e))
    }

    /// A parameter error as an alarm at its place in the block.
    fn param_alarm(&self, e: ParamError) -> Alarm {
        self.alarm(e.kind, e.at, e.msg)
    }

    /// A point of the plan (thread axis `a`, depth axis `d`) in program
    /// coordinates.
    fn thread_point(&self, plan: &ThreadPlan, a: f64, d: f64) -> Pos {
        let mut p = self.prog_pos();
        if plan.face {
            p[0] = a;
            p[2] = d;
        } else {
            p[2] = a;
            p[0] = d;
        }
        p
    }

    /// A threaded line from the current point to `to` with the plan's
    /// lead along the thread axis (expressed along the longer axis).
    fn thread_seg(&mut self, plan: &ThreadPlan, to: Pos, at: u32) -> R<()> {
        let cur = self.prog_pos();
        let (da, dd) = if plan.face {
            ((to[0] - cur[0]).abs(), (to[2] - cur[2]).abs())
        } else {
            ((to[2] - cur[2]).abs(), (to[0] - cur[0]).abs())
        };
        let lead = if dd > da && da > 1e-12 {
            plan.lead * dd / da
        } else {
            plan.lead
        };
        self.hurco_thread_to(to, lead, at)
    }

    /// Cuts the planned passes; the tool ends at the start point.
    fn cut_thread(&mut self, plan: &ThreadPlan, at: u32) -> R<()> {
        let s = plan.s;
        let a0 = plan.a_start - s * plan.clear_a;
        let start = self.thread_point(plan, a0, plan.d_at(-plan.clear_d, a0));
        self.line_to(start, motion::Speed::Rapid, at)?;
        for &c in &plan.depths {
            for &angle in &plan.starts {
                // In-feed.
                let a1 = a0 + s * (plan.clear_d + c) * plan.tan_a;
                let p1 = self.thread_point(plan, a1, plan.d_at(c, a1));
                let msg = (angle != 0.0).then(|| format!("thread start angle {}", fmt_num(angle)));
                if plan.tan_a > 0.0 {
                    if let Some(m) = &msg {
                        self.emit(Canon::Message(m.clone()));
                    }
                    self.thread_seg(plan, p1, at)?;
                } else {
                    self.line_to(p1, motion::Speed::Rapid, at)?;
                    if let Some(m) = &msg {
                        self.emit(Canon::Message(m.clone()));
                    }
                }
                // Thread to the pull-out point.
                let a2 = plan.a_end_major - s * c * plan.tan_c;
                let p2 = self.thread_point(plan, a2, plan.d_at(c, a2));
                self.thread_seg(plan, p2, at)?;
                // Pull-out.
                if plan.tan_c > 0.0 {
                    let a3 = plan.a_end_major + s * plan.clear_d * plan.tan_c;
                    let p3 = self.thread_point(plan, a3, plan.d_at(-plan.clear_d, a3));
                    self.thread_seg(plan, p3, at)?;
                } else {
                    let p3 = self.thread_point(plan, a2, plan.d_at(-plan.clear_d, a2));
                    self.line_to(p3, motion::Speed::Rapid, at)?;
                }
                self.line_to(start, motion::Speed::Rapid, at)?;
            }
        }
        Ok(())
    }
}
