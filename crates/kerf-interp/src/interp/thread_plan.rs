//! The G78 thread plan (002 Tables 5-13): the cycle's parameters checked
//! and turned into the passes of [`ThreadPlan`], without the interpreter.
//! [`ThreadPlan::from_params`] takes the block's parameters and units and
//! returns the plan or a [`ParamError`] (alarm kind, byte of the block,
//! message) that the interpreter turns into its alarm. The rules where
//! 002 is silent are in interp/hurco_thread.rs and docs/dialects.md.

use crate::alarms::AlarmKind;
use crate::words::WVal;

use super::fmt_num;
use super::hurco_thread::MacroParams;

/// Most passes one G78 may cut (bad input guard).
const MAX_PASSES: usize = 10_000;

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

/// How the block's words become millimetres.
#[derive(Clone, Copy, Debug)]
pub(super) struct Units {
    /// G21 (else inch).
    pub metric: bool,
    /// The profile's calculator decimal input (X1 = 1 mm, not 0.001).
    pub calculator_decimal: bool,
    /// The thread leads the control accepts, mm/rev.
    pub lead_range: (f64, f64),
}

impl Units {
    fn unit(&self) -> f64 {
        if self.metric {
            1.0
        } else {
            25.4
        }
    }

    /// A linear word in mm (the least-input-increment rule, as
    /// `Interp::linear`).
    fn linear(&self, w: WVal) -> f64 {
        let mut v = w.v;
        if !w.point && !self.calculator_decimal {
            v *= if self.metric { 0.001 } else { 0.0001 };
        }
        v * self.unit()
    }
}

/// A bad G78 parameter: the alarm, where in the block, and why.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct ParamError {
    pub kind: AlarmKind,
    /// Byte of the block the alarm points at.
    pub at: u32,
    pub msg: String,
}

type PR<T> = Result<T, ParamError>;

fn err<T>(kind: AlarmKind, at: u32, msg: impl Into<String>) -> PR<T> {
    Err(ParamError {
        kind,
        at,
        msg: msg.into(),
    })
}

/// A parameter the cycle cannot do without.
fn need(p: &MacroParams, l: u8, what: &str, at: u32) -> PR<WVal> {
    match p.get(l) {
        Some(w) => Ok(w),
        None => err(
            AlarmKind::MissingArgument,
            at,
            format!("G78 needs {} ({what})", l as char),
        ),
    }
}

/// M: 0 a turn thread, 1 a face thread.
pub(super) fn face_of(p: &MacroParams) -> PR<bool> {
    match p.get(b'M') {
        None => Ok(false),
        Some(w) if w.v == 0.0 => Ok(false),
        Some(w) if w.v == 1.0 => Ok(true),
        Some(w) => err(
            AlarmKind::OutOfRange,
            w.at,
            "G78 M is 0 (turn thread) or 1 (face thread)",
        ),
    }
}

/// The depth axis: the final pass (X, a radius, or minD a diameter; Z on
/// a face thread), the total depth J and the major depth X+J.
struct DepthAxis {
    last: f64,
    jw: WVal,
    j: f64,
    major: f64,
}

fn depth_axis(p: &MacroParams, face: bool, u: Units, at: u32) -> PR<DepthAxis> {
    let last_w = if face {
        need(p, b'Z', "Z of the final pass", at)?
    } else {
        need(p, b'X', "radius of the final pass: X, minR or minD", at)?
    };
    let mut last = u.linear(last_w);
    if !face && p.x_diameter {
        last /= 2.0;
    }
    let jw = need(p, b'J', "total depth", at)?;
    let j = u.linear(jw);
    if j == 0.0 {
        return err(AlarmKind::ThreadCycle, jw.at, "G78 J (total depth) is 0");
    }
    let major = last + j;
    if !face && (major * last < 0.0 || major == 0.0 || (last == 0.0 && j < 0.0)) {
        return err(
            AlarmKind::ThreadCycle,
            jw.at,
            "G78: X+J and X have different signs (the X axis would cross the centre line)",
        );
    }
    Ok(DepthAxis { last, jw, j, major })
}

/// The clearances (depth axis, thread axis): U and W (face: W and U),
/// 0.1 in or 2.54 mm when not given.
fn clearances(p: &MacroParams, face: bool, u: Units, at: u32) -> PR<(f64, f64)> {
    let def = 2.54;
    let (dl, al) = if face { (b'W', b'U') } else { (b'U', b'W') };
    let clear_d = p.get(dl).map(|w| u.linear(w)).unwrap_or(def);
    let clear_a = p.get(al).map(|w| u.linear(w)).unwrap_or(def);
    for (l, v) in [(dl, clear_d), (al, clear_a)] {
        if v < 0.0 {
            return err(
                AlarmKind::OutOfRange,
                p.get(l).map(|w| w.at).unwrap_or(at),
                format!("G78 {} (clearance) must not be negative", l as char),
            );
        }
    }
    Ok((clear_d, clear_a))
}

/// tan of the chase-in A, chase-out C and taper B angles.
fn angles(p: &MacroParams) -> PR<(f64, f64, f64)> {
    let angle = |l: u8, max: f64| -> PR<f64> {
        match p.get(l) {
            None => Ok(0.0),
            Some(w) if w.v >= 0.0 && w.v < max => Ok(w.v.to_radians().tan()),
            Some(w) => err(
                AlarmKind::OutOfRange,
                w.at,
                format!("G78 {} angle out of range (0 to below {max}°)", l as char),
            ),
        }
    };
    let tan_a = angle(b'A', 90.0)?;
    let tan_c = angle(b'C', 90.0)?;
    let tan_b = match p.get(b'B') {
        None => 0.0,
        Some(w) if (-45.0..=45.0).contains(&w.v) => w.v.to_radians().tan(),
        Some(w) => {
            return err(
                AlarmKind::OutOfRange,
                w.at,
                "G78 B (taper angle) must be -45° to 45°",
            )
        }
    };
    Ok((tan_a, tan_c, tan_b))
}

/// The thread end from exactly one of Z/H/T (face: X/S/T), as (direction
/// along the thread axis, end at the major depth, the end's word).
fn thread_end(
    p: &MacroParams,
    face: bool,
    a_start: f64,
    clear_d_tan_c: f64,
    u: Units,
    at: u32,
) -> PR<(f64, f64, WVal)> {
    let (end_l, major_end_l) = if face { (b'X', b'S') } else { (b'Z', b'H') };
    let ends: Vec<(u8, WVal)> = [end_l, major_end_l, b'T']
        .iter()
        .filter_map(|&l| p.get(l).map(|w| (l, w)))
        .collect();
    let (end_letter, end_w) = match ends.as_slice() {
        [] => {
            return err(
                AlarmKind::MissingArgument,
                at,
                format!(
                    "G78 needs the thread end: one of {}, {} or T",
                    end_l as char, major_end_l as char
                ),
            )
        }
        [one] => *one,
        [_, second, ..] => {
            return err(
                AlarmKind::ThreadCycle,
                second.1.at,
                format!(
                    "G78 takes exactly one of {}, {} and T (thread end)",
                    end_l as char, major_end_l as char
                ),
            )
        }
    };
    let ev = u.linear(end_w);
    let (s, a_end_major) = if end_letter == b'T' {
        let s = if ev >= 0.0 { -1.0 } else { 1.0 };
        (s, a_start - ev)
    } else if end_letter == major_end_l {
        ((ev - a_start).signum(), ev)
    } else {
        let s = (ev - a_start).signum();
        (s, ev - s * clear_d_tan_c)
    };
    if s == 0.0 || (a_end_major - a_start) * s <= 1e-9 {
        return err(
            AlarmKind::ThreadCycle,
            end_w.at,
            "G78: the thread has no length",
        );
    }
    Ok((s, a_end_major, end_w))
}

/// The lead: F the pitch, F- threads per inch; within the control's range.
fn lead(p: &MacroParams, u: Units, at: u32) -> PR<f64> {
    let fw = need(p, b'F', "pitch, or F- threads per inch", at)?;
    let lead = if fw.v < 0.0 {
        25.4 / -fw.v
    } else {
        fw.v * u.unit()
    };
    let (lo, hi) = u.lead_range;
    if lead < lo * (1.0 - 1e-9) || lead > hi * (1.0 + 1e-9) {
        return err(
            AlarmKind::OutOfRange,
            fw.at,
            format!("G78 F: thread lead {} mm out of range", fmt_num(lead)),
        );
    }
    Ok(lead)
}

/// D (start rough depth), V (constant volume) and E (final rough depth).
fn rough_params(p: &MacroParams, u: Units, at: u32) -> PR<(WVal, f64, bool, f64)> {
    let dw = need(p, b'D', "start rough depth", at)?;
    let d = u.linear(dw);
    if d <= 0.0 {
        return err(AlarmKind::OutOfRange, dw.at, "G78 D must be positive");
    }
    let vol = match p.get(b'V') {
        None => false,
        Some(w) if w.v == 0.0 => false,
        Some(w) if w.v == 1.0 => true,
        Some(w) => return err(AlarmKind::OutOfRange, w.at, "G78 V is 0 or 1"),
    };
    let e = match p.get(b'E') {
        Some(w) if vol => {
            return err(
                AlarmKind::ThreadCycle,
                w.at,
                "G78: E (final rough depth) cannot be programmed with V1 (constant volume)",
            )
        }
        Some(w) => {
            let e = u.linear(w);
            if e <= 0.0 || e > d + 1e-12 {
                return err(
                    AlarmKind::ThreadCycle,
                    w.at,
                    "G78 E (final rough depth) must be positive and not above D",
                );
            }
            e
        }
        None => d,
    };
    Ok((dw, d, vol, e))
}

/// The cumulative depth of every pass for total depth `total`: rough,
/// then P finish passes of L, then R spring passes (P + R spring passes
/// when L is 0). Returns the depths and D's word.
fn depths(p: &MacroParams, total: f64, u: Units, at: u32) -> PR<(Vec<f64>, WVal)> {
    let (dw, d, vol, e) = rough_params(p, u, at)?;
    let count = |l: u8| -> PR<Option<u32>> {
        match p.get(l) {
            None => Ok(None),
            Some(w) if w.v >= 0.0 && w.v.fract() == 0.0 && w.v <= MAX_PASSES as f64 => {
                Ok(Some(w.v as u32))
            }
            Some(w) => err(
                AlarmKind::OutOfRange,
                w.at,
                format!("G78 {} is a number of passes", l as char),
            ),
        }
    };
    let l_fin = match p.get(b'L') {
        None => 0.0,
        Some(w) if w.v >= 0.0 => u.linear(w),
        Some(w) => return err(AlarmKind::OutOfRange, w.at, "G78 L must not be negative"),
    };
    let p_fin = count(b'P')?;
    let springs = count(b'R')?.unwrap_or(0);
    let (n_fin, n_spring) = if l_fin > 0.0 {
        (p_fin.unwrap_or(1), springs)
    } else {
        (0, springs + p_fin.unwrap_or(0))
    };
    let rt = total - n_fin as f64 * l_fin;
    if rt < -1e-9 {
        return err(
            AlarmKind::ThreadCycle,
            at,
            "G78: the finish passes (P x L) are deeper than J",
        );
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
        return err(
            AlarmKind::OutOfRange,
            dw.at,
            format!("G78 would cut more than {MAX_PASSES} passes"),
        );
    }
    Ok((depths, dw))
}

/// The start angles: Q- (or Q0) one start at that angle, Q+ that many
/// starts evenly spaced.
fn starts(p: &MacroParams) -> PR<Vec<f64>> {
    Ok(match p.get(b'Q') {
        None => vec![0.0],
        Some(w) if w.v <= 0.0 && w.v >= -360.0 => vec![-w.v],
        Some(w) if w.v > 0.0 && w.v.fract() == 0.0 && w.v <= 360.0 => {
            let n = w.v as usize;
            (0..n).map(|k| 360.0 * k as f64 / n as f64).collect()
        }
        Some(w) => {
            return err(
                AlarmKind::OutOfRange,
                w.at,
                "G78 Q: a start angle Q-0..-360 or a number of starts Q1..Q360",
            )
        }
    })
}

impl ThreadPlan {
    /// The plan of a G78 block from its parameters `p` (`face`: M1),
    /// checked in the order the control reads them; `at` is the G78
    /// word's byte, where alarms about missing words point.
    pub(super) fn from_params(p: &MacroParams, face: bool, u: Units, at: u32) -> PR<ThreadPlan> {
        let DepthAxis { last, jw, j, major } = depth_axis(p, face, u, at)?;
        let m = -j.signum();
        let out = if face {
            // Away from the part face: the side of the clearance.
            j.signum()
        } else if last != 0.0 {
            last.signum()
        } else {
            j.signum()
        };
        let start_l = if face { b'I' } else { b'K' };
        let a_start = u.linear(need(p, start_l, "thread start", at)?);
        let (clear_d, clear_a) = clearances(p, face, u, at)?;
        let (tan_a, tan_c, tan_b) = angles(p)?;
        let (s, a_end_major, end_w) = thread_end(p, face, a_start, clear_d * tan_c, u, at)?;
        let lead = lead(p, u, at)?;
        let total = j.abs();
        let (depths, dw) = depths(p, total, u, at)?;
        let starts = starts(p)?;
        if depths.len() * starts.len() > MAX_PASSES {
            return err(
                AlarmKind::OutOfRange,
                dw.at,
                format!("G78 would cut more than {MAX_PASSES} passes (depths x starts)"),
            );
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
        plan.check_clearance(total, (end_w, jw), at)?;
        Ok(plan)
    }

    /// The deepest pass's chase-in and chase-out must not overlap, and the
    /// X axis must not cross the centre line (`words`: the thread end's
    /// and J's words, where those alarms point).
    fn check_clearance(&self, total: f64, words: (WVal, WVal), at: u32) -> PR<()> {
        let (end_w, jw) = words;
        let s = self.s;
        let (clear_d, clear_a, tan_a, tan_c) = (self.clear_d, self.clear_a, self.tan_a, self.tan_c);
        let a_in = self.a_start - s * clear_a + s * (clear_d + total) * tan_a;
        let a_out = self.a_end_major - s * total * tan_c;
        if (a_out - a_in) * s < -1e-9 {
            return err(
                AlarmKind::ThreadCycle,
                at,
                "G78: the lead-in and lead-out lines overlap (thread too short for A and C)",
            );
        }
        if self.face {
            // The thread runs along X: its start (with the clearance) and
            // end must stay on one side of the centre line.
            let a0 = self.a_start - s * clear_a;
            let a3 = self.a_end_major + s * clear_d * tan_c;
            if a0 * a3 < 0.0 || a0 * self.a_start < 0.0 {
                return err(
                    AlarmKind::ThreadCycle,
                    end_w.at,
                    "G78: the face thread would take the X axis across the centre line",
                );
            }
        } else {
            let out = self.out;
            let clear = self.d_at(-clear_d, self.a_start - s * clear_a);
            let clear_end = self.d_at(-clear_d, a_out + s * (clear_d + total) * tan_c);
            if clear * out < 0.0 || clear_end * out < 0.0 || self.d_at(total, a_out) * out < 0.0 {
                return err(
                    AlarmKind::ThreadCycle,
                    jw.at,
                    "G78: the X axis would cross the centre line",
                );
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// MacroParams from (letter, value, decimal point) words, each at its
    /// own byte (its index × 10).
    fn params(words: &[(u8, f64)]) -> MacroParams {
        let mut v = [None; 26];
        for (i, &(l, x)) in words.iter().enumerate() {
            v[(l - b'A') as usize] = Some(WVal {
                v: x,
                point: true,
                at: 10 * i as u32,
            });
        }
        MacroParams {
            v,
            x_diameter: false,
        }
    }

    const INCH: Units = Units {
        metric: false,
        calculator_decimal: false,
        lead_range: (0.000001 * 25.4, 10.0 * 25.4),
    };

    /// 002 "Straight OD Thread": G78 X.9 J.2 Z1.2 K2 F.15 D.04 E.03 P2
    /// L.02 R3. Major radius 1.1 in, start K2, end Z1.2 at the clearance
    /// (C0: the same at the major radius), lead .15 in = 3.81 mm. Rough
    /// depth .2 - 2 × .02 = .16: 5 passes .034 … .030 (cumulative .034
    /// .067 .099 .130 .160), finish .18 .20, three spring passes at .20.
    #[test]
    fn the_manuals_straight_thread() {
        let p = params(&[
            (b'X', 0.9),
            (b'J', 0.2),
            (b'Z', 1.2),
            (b'K', 2.0),
            (b'F', 0.15),
            (b'D', 0.04),
            (b'E', 0.03),
            (b'P', 2.0),
            (b'L', 0.02),
            (b'R', 3.0),
        ]);
        let plan = ThreadPlan::from_params(&p, false, INCH, 0).unwrap();
        let inch: Vec<f64> = plan
            .depths
            .iter()
            .map(|d| (d / 25.4 * 1e6).round() / 1e6)
            .collect();
        assert_eq!(
            inch,
            vec![0.034, 0.067, 0.099, 0.130, 0.160, 0.18, 0.20, 0.20, 0.20, 0.20]
        );
        assert!((plan.lead - 3.81).abs() < 1e-12);
        assert!((plan.major - 1.1 * 25.4).abs() < 1e-9);
        assert!((plan.a_start - 2.0 * 25.4).abs() < 1e-9);
        assert!((plan.a_end_major - 1.2 * 25.4).abs() < 1e-9);
        assert_eq!((plan.s, plan.m, plan.out), (-1.0, -1.0, 1.0));
        assert_eq!(plan.starts, vec![0.0]);
    }

    #[test]
    fn errors_point_at_their_word() {
        let base = [
            (b'X', 0.9),
            (b'J', 0.2),
            (b'Z', 1.2),
            (b'K', 2.0),
            (b'F', 0.15),
            (b'D', 0.04),
        ];
        let plan = |w: &[(u8, f64)]| ThreadPlan::from_params(&params(w), false, INCH, 7);
        // J0 (the second word, byte 10).
        let mut w = base.to_vec();
        w[1].1 = 0.0;
        let e = plan(&w).unwrap_err();
        assert_eq!((e.kind, e.at), (AlarmKind::ThreadCycle, 10));
        // No F: missing, at the G78 word.
        let e = plan(&base[..4]).unwrap_err();
        assert_eq!((e.kind, e.at), (AlarmKind::MissingArgument, 7));
        // Z and T both: the second end word (T, byte 60).
        let mut w = base.to_vec();
        w.push((b'T', 0.8));
        let e = plan(&w).unwrap_err();
        assert_eq!((e.kind, e.at), (AlarmKind::ThreadCycle, 60));
        // The end at the start: no length.
        let mut w = base.to_vec();
        w[2].1 = 2.0;
        let e = plan(&w).unwrap_err();
        assert_eq!(e.msg, "G78: the thread has no length");
    }

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
