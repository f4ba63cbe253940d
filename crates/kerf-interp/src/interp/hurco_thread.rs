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

use super::*;
use crate::dialect::hurco::{LongKind, LONG_LETTERS};

/// Most passes one G78 may cut (bad input guard).
const MAX_PASSES: usize = 10_000;

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

/// One planned G78 (mm, abstract axes).
#[derive(Clone, Debug)]
pub(super) struct ThreadPlan {
    /// Face thread (M1).
    pub face: bool,
    /// Cumulative cut depth of each pass (rough, finish, spring).
    pub depths: Vec<f64>,
    /// Start angles of the thread starts, degrees.
    pub starts: Vec<f64>,
    /// Lead along the thread axis, mm/rev.
    pub lead: f64,
    /// Thread start on the thread axis (K / I).
    pub a_start: f64,
    /// Direction of the thread along its axis (+1 / -1).
    pub s: f64,
    /// Thread end on the thread axis at the major depth (H / S).
    pub a_end_major: f64,
    /// Depth-axis coordinate of the major depth (X+J / Z+J).
    pub major: f64,
    /// Direction into the material along the depth axis (+1 / -1).
    pub m: f64,
    /// Depth-axis clearance from the major depth (U turn, W face).
    pub clear_d: f64,
    /// Thread-axis clearance before the start (W turn, U face).
    pub clear_a: f64,
    /// tan of the chase-in / chase-out angles and the taper.
    pub tan_a: f64,
    pub tan_c: f64,
    pub tan_b: f64,
    /// Sign of "away from the centre line / part face" on the depth axis.
    pub out: f64,
}

impl ThreadPlan {
    /// Depth-axis coordinate at cut depth `c` and thread-axis coordinate
    /// `a` (negative `c` = outside the major depth).
    pub fn d_at(&self, c: f64, a: f64) -> f64 {
        let along = self.s * (a - self.a_start);
        self.major + self.m * c + self.out * along * self.tan_b
    }
}

/// Rough pass depths (cumulative) for rough depth `rt`, start depth `d`,
/// final depth `e` (ignored with constant volume). More than
/// [`MAX_PASSES`] passes: the list stops at `MAX_PASSES + 1` entries (the
/// caller alarms), nothing larger is ever allocated.
pub(super) fn rough_depths(rt: f64, d: f64, e: f64, const_volume: bool) -> Vec<f64> {
    let mut out = Vec::new();
    if rt <= 1e-12 {
        return out;
    }
    let too_many = || vec![rt; MAX_PASSES + 1];
    if const_volume {
        let mut k = 1.0f64;
        loop {
            let c = d * k.sqrt();
            if c >= rt - 1e-9 || out.len() >= MAX_PASSES {
                out.push(rt);
                return out;
            }
            out.push(c);
            k += 1.0;
        }
    }
    let nf = ((2.0 * rt / (d + e)) - 1e-9).ceil().max(1.0);
    if nf.is_nan() || nf > MAX_PASSES as f64 {
        return too_many();
    }
    let n = nf as usize;
    let first = 2.0 * rt / n as f64 - e;
    let cuts: Vec<f64> = if n == 1 {
        vec![rt]
    } else if first < e - 1e-12 {
        let nf = ((rt / d) - 1e-9).ceil().max(1.0);
        if nf > MAX_PASSES as f64 {
            return too_many();
        }
        let n = nf as usize;
        vec![rt / n as f64; n]
    } else {
        let step = (first - e) / (n - 1) as f64;
        (0..n).map(|k| first - step * k as f64).collect()
    };
    let mut c = 0.0;
    for (i, cut) in cuts.iter().enumerate() {
        c += cut;
        out.push(if i + 1 == cuts.len() { rt } else { c });
    }
    out
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
        if self.st.css {
            return Err(self.alarm(
                AlarmKind::ThreadCycle,
                at,
                "G78 needs direct spindle speed (G97), not G96",
            ));
        }
        if self.st.spindle == SpindleDir::Stop || self.rpm() <= 0.0 {
            return Err(self.alarm(
                AlarmKind::ThreadCycle,
                at,
                "G78 needs the spindle running (M03/M04 with S)",
            ));
        }
        let plan = self.thread_plan(&p, at)?;
        self.cut_thread(&plan, at)
    }

    /// Reads and checks the parameters of Tables 5-13.
    pub(super) fn thread_plan(&self, p: &MacroParams, at: u32) -> R<ThreadPlan> {
        let need = |l: u8, what: &str| -> R<WVal> {
            p.get(l).ok_or_else(|| {
                self.alarm(
                    AlarmKind::MissingArgument,
                    at,
                    format!("G78 needs {} ({what})", l as char),
                )
            })
        };
        let face = match p.get(b'M') {
            None => false,
            Some(w) if w.v == 0.0 => false,
            Some(w) if w.v == 1.0 => true,
            Some(w) => {
                return Err(self.alarm(
                    AlarmKind::OutOfRange,
                    w.at,
                    "G78 M is 0 (turn thread) or 1 (face thread)",
                ))
            }
        };
        for (l, w) in p.v.iter().enumerate() {
            if let Some(w) = w {
                let l = b'A' + l as u8;
                if matches!(l, b'X' | b'Z' | b'I' | b'K' | b'U' | b'W' | b'J' | b'H') {
                    self.check_range_hurco(l, *w)?;
                }
            }
        }
        let len = |w: WVal| self.linear(w);
        // Depth axis: X (turn, a radius; minD a diameter) / Z (face).
        let (last_w, start_l, end_l, major_end_l) = if face {
            (need(b'Z', "Z of the final pass")?, b'I', b'X', b'S')
        } else {
            (
                need(b'X', "radius of the final pass: X, minR or minD")?,
                b'K',
                b'Z',
                b'H',
            )
        };
        let mut last = len(last_w);
        if !face && p.x_diameter {
            last /= 2.0;
        }
        let jw = need(b'J', "total depth")?;
        let j = len(jw);
        if j == 0.0 {
            return Err(self.alarm(AlarmKind::ThreadCycle, jw.at, "G78 J (total depth) is 0"));
        }
        let major = last + j;
        if !face && (major * last < 0.0 || major == 0.0 || (last == 0.0 && j < 0.0)) {
            return Err(self.alarm(
                AlarmKind::ThreadCycle,
                jw.at,
                "G78: X+J and X have different signs (the X axis would cross the centre line)",
            ));
        }
        let m = -j.signum();
        let out = if face {
            // Away from the part face: the side of the clearance.
            j.signum()
        } else if last != 0.0 {
            last.signum()
        } else {
            j.signum()
        };
        let start_w = need(start_l, "thread start")?;
        let a_start = len(start_w);
        // Clearances: depth (U turn / W face), thread axis (W / U).
        // Default 0.1 in or 2.54 mm: the same length.
        let def = 2.54;
        let (dl, al) = if face { (b'W', b'U') } else { (b'U', b'W') };
        let clear_d = p.get(dl).map(len).unwrap_or(def);
        let clear_a = p.get(al).map(len).unwrap_or(def);
        for (l, v) in [(dl, clear_d), (al, clear_a)] {
            if v < 0.0 {
                return Err(self.alarm(
                    AlarmKind::OutOfRange,
                    p.get(l).map(|w| w.at).unwrap_or(at),
                    format!("G78 {} (clearance) must not be negative", l as char),
                ));
            }
        }
        let angle = |l: u8, max: f64| -> R<f64> {
            match p.get(l) {
                None => Ok(0.0),
                Some(w) if w.v >= 0.0 && w.v < max => Ok(w.v.to_radians().tan()),
                Some(w) => Err(self.alarm(
                    AlarmKind::OutOfRange,
                    w.at,
                    format!("G78 {} angle out of range (0 to below {max}°)", l as char),
                )),
            }
        };
        let tan_a = angle(b'A', 90.0)?;
        let tan_c = angle(b'C', 90.0)?;
        let tan_b = match p.get(b'B') {
            None => 0.0,
            Some(w) if (-45.0..=45.0).contains(&w.v) => w.v.to_radians().tan(),
            Some(w) => {
                return Err(self.alarm(
                    AlarmKind::OutOfRange,
                    w.at,
                    "G78 B (taper angle) must be -45° to 45°",
                ))
            }
        };
        // Thread end: exactly one of Z/H/T (face: X/S/T).
        let ends: Vec<(u8, WVal)> = [end_l, major_end_l, b'T']
            .iter()
            .filter_map(|&l| p.get(l).map(|w| (l, w)))
            .collect();
        let (end_letter, end_w) = match ends.as_slice() {
            [] => {
                return Err(self.alarm(
                    AlarmKind::MissingArgument,
                    at,
                    format!(
                        "G78 needs the thread end: one of {}, {} or T",
                        end_l as char, major_end_l as char
                    ),
                ))
            }
            [one] => *one,
            [_, second, ..] => {
                return Err(self.alarm(
                    AlarmKind::ThreadCycle,
                    second.1.at,
                    format!(
                        "G78 takes exactly one of {}, {} and T (thread end)",
                        end_l as char, major_end_l as char
                    ),
                ))
            }
        };
        let ev = len(end_w);
        let (s, a_end_major) = if end_letter == b'T' {
            let s = if ev >= 0.0 { -1.0 } else { 1.0 };
            (s, a_start - ev)
        } else if end_letter == major_end_l {
            ((ev - a_start).signum(), ev)
        } else {
            let s = (ev - a_start).signum();
            (s, ev - s * clear_d * tan_c)
        };
        if s == 0.0 || (a_end_major - a_start) * s <= 1e-9 {
            return Err(self.alarm(
                AlarmKind::ThreadCycle,
                end_w.at,
                "G78: the thread has no length",
            ));
        }
        // Lead: F pitch, F- threads per inch.
        let fw = need(b'F', "pitch, or F- threads per inch")?;
        let lead = if fw.v < 0.0 {
            25.4 / -fw.v
        } else {
            fw.v * self.unit()
        };
        let (lo, hi) = self.hurco_lead_range();
        if lead < lo * (1.0 - 1e-9) || lead > hi * (1.0 + 1e-9) {
            return Err(self.alarm(
                AlarmKind::OutOfRange,
                fw.at,
                format!("G78 F: thread lead {} mm out of range", fmt_num(lead)),
            ));
        }
        // Depths.
        let dw = need(b'D', "start rough depth")?;
        let d = len(dw);
        if d <= 0.0 {
            return Err(self.alarm(AlarmKind::OutOfRange, dw.at, "G78 D must be positive"));
        }
        let vol = match p.get(b'V') {
            None => false,
            Some(w) if w.v == 0.0 => false,
            Some(w) if w.v == 1.0 => true,
            Some(w) => {
                return Err(self.alarm(AlarmKind::OutOfRange, w.at, "G78 V is 0 or 1"));
            }
        };
        let e = match p.get(b'E') {
            Some(w) if vol => {
                return Err(self.alarm(
                    AlarmKind::ThreadCycle,
                    w.at,
                    "G78: E (final rough depth) cannot be programmed with V1 (constant volume)",
                ))
            }
            Some(w) => {
                let e = len(w);
                if e <= 0.0 || e > d + 1e-12 {
                    return Err(self.alarm(
                        AlarmKind::ThreadCycle,
                        w.at,
                        "G78 E (final rough depth) must be positive and not above D",
                    ));
                }
                e
            }
            None => d,
        };
        let count = |l: u8| -> R<Option<u32>> {
            match p.get(l) {
                None => Ok(None),
                Some(w) if w.v >= 0.0 && w.v.fract() == 0.0 && w.v <= MAX_PASSES as f64 => {
                    Ok(Some(w.v as u32))
                }
                Some(w) => Err(self.alarm(
                    AlarmKind::OutOfRange,
                    w.at,
                    format!("G78 {} is a number of passes", l as char),
                )),
            }
        };
        let l_fin = match p.get(b'L') {
            None => 0.0,
            Some(w) if w.v >= 0.0 => len(w),
            Some(w) => {
                return Err(self.alarm(AlarmKind::OutOfRange, w.at, "G78 L must not be negative"))
            }
        };
        let p_fin = count(b'P')?;
        let springs = count(b'R')?.unwrap_or(0);
        let (n_fin, n_spring) = if l_fin > 0.0 {
            (p_fin.unwrap_or(1), springs)
        } else {
            (0, springs + p_fin.unwrap_or(0))
        };
        let total = j.abs();
        let rt = total - n_fin as f64 * l_fin;
        if rt < -1e-9 {
            return Err(self.alarm(
                AlarmKind::ThreadCycle,
                at,
                "G78: the finish passes (P x L) are deeper than J",
            ));
        }
        let mut depths = rough_depths(rt.max(0.0), d, e, vol);
        let mut c = depths.last().copied().unwrap_or(0.0);
        for k in 0..n_fin {
            c = if k + 1 == n_fin { total } else { c + l_fin };
            depths.push(c);
        }
        for _ in 0..n_spring {
            depths.push(total);
        }
        if depths.len() > MAX_PASSES {
            return Err(self.alarm(
                AlarmKind::OutOfRange,
                dw.at,
                format!("G78 would cut more than {MAX_PASSES} passes"),
            ));
        }
        // Starts: Q- (or Q0) start angle, Q+ number of starts.
        let starts = match p.get(b'Q') {
            None => vec![0.0],
            Some(w) if w.v <= 0.0 && w.v >= -360.0 => vec![-w.v],
            Some(w) if w.v > 0.0 && w.v.fract() == 0.0 && w.v <= 360.0 => {
                let n = w.v as usize;
                (0..n).map(|k| 360.0 * k as f64 / n as f64).collect()
            }
            Some(w) => {
                return Err(self.alarm(
                    AlarmKind::OutOfRange,
                    w.at,
                    "G78 Q: a start angle Q-0..-360 or a number of starts Q1..Q360",
                ))
            }
        };
        if depths.len() * starts.len() > MAX_PASSES {
            return Err(self.alarm(
                AlarmKind::OutOfRange,
                dw.at,
                format!("G78 would cut more than {MAX_PASSES} passes (depths x starts)"),
            ));
        }
        let plan = ThreadPlan {
            face,
            depths,
            starts,
            lead,
            a_start,
            s,
            a_end_major,
            major,
            m,
            clear_d,
            clear_a,
            tan_a,
            tan_c,
            tan_b,
            out,
        };
        // Chase-in and chase-out must not overlap on the deepest pass.
        let a_in = plan.a_start - s * clear_a + s * (clear_d + total) * tan_a;
        let a_out = plan.a_end_major - s * total * tan_c;
        if (a_out - a_in) * s < -1e-9 {
            return Err(self.alarm(
                AlarmKind::ThreadCycle,
                at,
                "G78: the lead-in and lead-out lines overlap (thread too short for A and C)",
            ));
        }
        if face {
            // The thread runs along X: its start (with the clearance) and
            // end must stay on one side of the centre line.
            let a0 = plan.a_start - s * clear_a;
            let a3 = plan.a_end_major + s * clear_d * tan_c;
            if a0 * a3 < 0.0 || a0 * plan.a_start < 0.0 {
                return Err(self.alarm(
                    AlarmKind::ThreadCycle,
                    end_w.at,
                    "G78: the face thread would take the X axis across the centre line",
                ));
            }
        } else {
            let clear = plan.d_at(-clear_d, plan.a_start - s * clear_a);
            let clear_end = plan.d_at(-clear_d, a_out + s * (clear_d + total) * tan_c);
            if clear * out < 0.0 || clear_end * out < 0.0 || plan.d_at(total, a_out) * out < 0.0 {
                return Err(self.alarm(
                    AlarmKind::ThreadCycle,
                    jw.at,
                    "G78: the X axis would cross the centre line",
                ));
            }
        }
        Ok(plan)
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

#[cfg(test)]
mod tests {
    use super::rough_depths;

    fn cuts(v: &[f64]) -> Vec<f64> {
        let mut prev = 0.0;
        v.iter()
            .map(|&c| {
                let d = ((c - prev) * 1e6).round() / 1e6;
                prev = c;
                d
            })
            .collect()
    }

    #[test]
    fn linear_from_d_to_e() {
        // 002 Figure 23: J.45 D.1 E.05: 2*.45/.15 = 6 passes,
        // .1 .09 .08 .07 .06 .05 (sum .45).
        assert_eq!(
            cuts(&rough_depths(0.45, 0.1, 0.05, false)),
            vec![0.1, 0.09, 0.08, 0.07, 0.06, 0.05]
        );
    }

    #[test]
    fn equal_passes_when_e_equals_d() {
        // Rt .25, D = E = .1: ceil(.25/.1) = 3 passes of .25/3.
        let v = rough_depths(0.25, 0.1, 0.1, false);
        assert_eq!(v.len(), 3);
        assert!((v[0] - 0.25 / 3.0).abs() < 1e-12);
        assert!((v[2] - 0.25).abs() < 1e-12);
    }

    #[test]
    fn constant_volume() {
        // D .1, Rt .25: .1, .1414, .1732, .2, .2236, then .25 (sqrt 6 * .1
        // = .2449 < .25, sqrt 7 * .1 = .2646 >= .25 -> clipped).
        let v = rough_depths(0.25, 0.1, 0.0, true);
        let want = [
            0.1,
            0.1 * 2f64.sqrt(),
            0.1 * 3f64.sqrt(),
            0.2,
            0.1 * 5f64.sqrt(),
            0.1 * 6f64.sqrt(),
            0.25,
        ];
        assert_eq!(v.len(), want.len());
        for (a, b) in v.iter().zip(want) {
            assert!((a - b).abs() < 1e-12);
        }
    }
}
