//! PUMA (Fanuc 0-T) multiple repetitive cycles G70-G76 (001 "G71"-"G76";
//! fanuc-semantics §1 and Appendix A): the two-block formats with their
//! modal first-block values, and the emission of the passes computed by
//! [`crate::turning`]. The finishing shape of G70-G73 is read by
//! interp/lathe_shape.rs.

use super::lathe_shape::{Shape, ShapeErr};
use super::*;
use crate::dialect::meaning::LatheCycle::{self, *};
use crate::turning::{self, Mv, P};

/// The modal first-block values (fanuc-semantics §1.1: they overwrite the
/// parameters, so a later cycle may omit its first block). `None` = the
/// profile parameter.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct MrcModal {
    /// G71/G72 Δd (radius, mm).
    depth: Option<f64>,
    /// G71/G72 e (mm).
    escape: Option<f64>,
    /// G73 Δi, Δk (mm, X a radius).
    relief: Option<(Option<f64>, Option<f64>)>,
    /// G73 d (divisions).
    divisions: Option<u32>,
    /// G74/G75 e (mm).
    peck_escape: Option<f64>,
    /// G76 m, r, a.
    thread_p: Option<(u32, u32, f64)>,
    /// G76 Δdmin (mm).
    min_depth: Option<f64>,
    /// G76 d (mm).
    allowance: Option<f64>,
}

impl Interp {
    /// A G70-G76 block (`kind`, its code `code` × 10 for the alarms),
    /// `at` the G word.
    pub(super) fn mrc(&mut self, kind: LatheCycle, code: u16, at: u32) -> R<()> {
        match kind {
            Finish | RoughTurn | RoughFace | Pattern => self.mrc_shape_cycle(kind, code, at),
            PeckZ | GrooveX => self.mrc_peck(kind, code, at),
            _ => self.mrc_thread(at),
        }
    }

    /// A parameter from the profile (`No.xxxx`) with a default.
    fn mrc_param(&self, n: u32, default: f64) -> f64 {
        self.cfg.profile.param(&format!("No.{n}"), default)
    }

    fn positive(&self, l: u8, what: &str) -> R<Option<f64>> {
        match self.words.get(l) {
            None => Ok(None),
            Some(w) => {
                let v = self.linear(w);
                if v <= 0.0 {
                    return Err(self.alarm(
                        AlarmKind::MrcValue,
                        w.at,
                        format!("{what} ({}) must be positive", l as char),
                    ));
                }
                Ok(Some(v))
            }
        }
    }

    /// The first block of G71/G72 (U or W: Δd, R: escape) or G73 (U, W:
    /// relief, R: divisions): modal data only.
    fn mrc_first_block(&mut self, kind: LatheCycle) -> R<()> {
        // G71 reads U R, G72 W R, G73 U W R; nothing else is read here.
        let unread: &[u8] = match kind {
            RoughTurn => b"WDIK",
            RoughFace => b"UDIK",
            _ => b"DIK",
        };
        if let Some(&l) = unread.iter().find(|&&l| self.words.has(l)) {
            let w = self.words.get(l).expect("present");
            return Err(self.unused_word(l, w.at, "the cycle block with P and Q"));
        }
        match kind {
            RoughTurn | RoughFace => {
                let l = if kind == RoughTurn { b'U' } else { b'W' };
                if let Some(d) = self.positive(l, "depth of cut Δd")? {
                    self.puma.mrc.depth = Some(d);
                }
                if let Some(w) = self.words.get(b'R') {
                    self.puma.mrc.escape = Some(self.linear(w).abs());
                }
            }
            _ => {
                let (mut i, mut k) = self.puma.mrc.relief.unwrap_or((None, None));
                if let Some(w) = self.words.get(b'U') {
                    i = Some(self.linear(w));
                }
                if let Some(w) = self.words.get(b'W') {
                    k = Some(self.linear(w));
                }
                self.puma.mrc.relief = Some((i, k));
                if let Some(w) = self.words.get(b'R') {
                    self.puma.mrc.divisions = Some(self.mrc_divisions(w, "G73 R")?);
                }
            }
        }
        Ok(())
    }

    /// G70, G71, G72, G73.
    fn mrc_shape_cycle(&mut self, kind: LatheCycle, code: u16, at: u32) -> R<()> {
        let has_pq = self.words.has(b'P') || self.words.has(b'Q');
        if !has_pq {
            if kind == Finish {
                return Err(self.alarm(AlarmKind::MrcNoPq, at, "G70 without P (ns) and Q (nf)"));
            }
            return self.mrc_first_block(kind);
        }
        let (ns, nf) = match (self.words.get(b'P'), self.words.get(b'Q')) {
            (Some(p), Some(q)) => (self.seq_word(p)?, self.seq_word(q)?),
            (p, _) => {
                let w = p.or(self.words.get(b'Q')).expect("one of them");
                return Err(self.alarm(
                    AlarmKind::MrcNoPq,
                    w.at,
                    format!("G{} needs both P (ns) and Q (nf)", code / 10),
                ));
            }
        };
        // Second-block values, before the shape blocks overwrite the words.
        let half = if self.modal.diameter.means { 0.5 } else { 1.0 };
        let du = self
            .words
            .get(b'U')
            .map(|w| self.linear(w) * half)
            .unwrap_or(0.0);
        let dw = self.words.get(b'W').map(|w| self.linear(w)).unwrap_or(0.0);
        self.mrc_one_block_shape(kind)?;
        let p_at = self.words.get(b'P').map(|w| w.at).unwrap_or(at);
        let q_at = self.words.get(b'Q').map(|w| w.at).unwrap_or(at);
        let a = self.zx_pos();
        let resume = self.prog.src.as_ref().expect("loaded").tell();
        let mut shape = match self.read_shape(ns, nf) {
            Ok(s) => s,
            Err(ShapeErr::Here(a)) => return Err(a),
            Err(ShapeErr::AtCycle(k, l, msg)) => {
                return Err(self.alarm(k, if l == b'P' { p_at } else { q_at }, msg))
            }
        };
        // G70 goes on after its own block; G71-G73 after N(nf) when the
        // shape follows the cycle, else after the cycle block too.
        let after_nf = self.prog.src.as_ref().expect("loaded").tell();
        if kind == Finish || after_nf.offset <= resume.offset {
            self.seek(resume)?;
        }
        if kind == Finish {
            return self.g70(a, &shape, at);
        }
        // Type II (pockets) when block ns moves both axes.
        let type2 = shape.ns_x && shape.ns_z;
        // Nose radius compensation in force before the cycle or written in
        // the shape: the levels and the semi-finish pass follow the
        // imaginary tip's path (fanuc-semantics §1.9).
        let tip_path = self.shape_tip_path(a, &shape, at)?;
        let comp = tip_path.is_some();
        let (start, segs) = match tip_path {
            Some(t) => t,
            None => (shape.start, std::mem::take(&mut shape.segs)),
        };
        let mut out = Vec::with_capacity(64 + segs.len());
        let res = match kind {
            RoughTurn | RoughFace => {
                let r = turning::Rough {
                    depth: self
                        .puma
                        .mrc
                        .depth
                        .unwrap_or_else(|| self.mrc_param(5132, 1.0)),
                    escape: self
                        .puma
                        .mrc
                        .escape
                        .unwrap_or_else(|| self.mrc_param(5133, 0.5)),
                    allow_x: du,
                    allow_z: dw,
                };
                match (kind, type2) {
                    (RoughTurn, false) => {
                        turning::g71(a, start, &segs, r, shape.ns_rapid, &mut out)
                    }
                    (RoughTurn, true) => {
                        turning::g71_type2(a, start, &segs, r, shape.ns_rapid, &mut out)
                    }
                    _ => turning::g72(a, start, &segs, r, shape.ns_rapid, type2, &mut out),
                }
            }
            _ => self.g73_passes(a, (start, &segs), (du, dw), shape.ns_rapid, &mut out),
        };
        match res {
            Ok(()) => {}
            Err(turning::CycleError::NotMonotonic(i, ax)) => {
                let line = shape.srcs.get(i).map_or(0, |s| s.line);
                let what = format!("G{} type {}", code / 10, if type2 { "II" } else { "I" });
                let msg = not_monotonic_msg(&what, (ns, nf), comp, ax, i, line);
                return Err(self.alarm(AlarmKind::MrcNotMonotonic, p_at, msg));
            }
            Err(e) => return Err(self.alarm(AlarmKind::MrcValue, at, super::lathe::cycle_msg(&e))),
        }
        self.emit_moves(&out, None, at)
    }

    /// G73's passes: the relief Δi/Δk and the divisions d (modal, else
    /// parameters 5135-5137), the allowances `allow` (Δu radius, Δw).
    fn g73_passes(
        &self,
        a: turning::P,
        shape: (turning::P, &[turning::Seg]),
        allow: (f64, f64),
        ns_rapid: bool,
        out: &mut Vec<turning::Mv>,
    ) -> Result<(), turning::CycleError> {
        let (start, segs) = shape;
        let (du, dw) = allow;
        let (i, k) = self.puma.mrc.relief.unwrap_or((None, None));
        let relief = turning::p(
            i.unwrap_or_else(|| self.mrc_param(5135, 0.0)),
            k.unwrap_or_else(|| self.mrc_param(5136, 0.0)),
        );
        let d = self
            .puma
            .mrc
            .divisions
            .unwrap_or_else(|| self.mrc_param(5137, 1.0) as u32);
        turning::g73(a, start, segs, relief, turning::p(du, dw), d, ns_rapid, out)
    }

    /// The one-block words of a G71/G72/G73 P Q block (Fanuc 10/11 tape
    /// format, fanuc-semantics §10.2): G71/G72 `D` = Δd (radius, the
    /// decimal-point rule), G73 `I`/`K` = Δi/Δk (radius) and `D` = the
    /// divisions. Like the first block of the 0-T form they are modal. `I`
    /// or `K` where the cycle does not read them is an alarm (`D` is
    /// checked with the block's addresses, interp/puma_words.rs).
    fn mrc_one_block_shape(&mut self, kind: LatheCycle) -> R<()> {
        let one_block = self.tape_format_10_11();
        if let Some(w) = self.words.get(b'R') {
            return Err(self.unused_word(
                b'R',
                w.at,
                "the first block of G71-G73 (without P and Q)",
            ));
        }
        for l in [b'I', b'K'] {
            if let Some(w) = self.words.get(l) {
                if !(one_block && kind == Pattern) {
                    return Err(self.unused_word(l, w.at, "a one-block G73 (relief Δi, Δk)"));
                }
            }
        }
        if kind == Pattern {
            let (mut i, mut k) = self.puma.mrc.relief.unwrap_or((None, None));
            if let Some(w) = self.words.get(b'I') {
                i = Some(self.linear(w));
            }
            if let Some(w) = self.words.get(b'K') {
                k = Some(self.linear(w));
            }
            if i.is_some() || k.is_some() {
                self.puma.mrc.relief = Some((i, k));
            }
            if let Some(w) = self.words.get(b'D') {
                self.puma.mrc.divisions = Some(self.mrc_divisions(w, "G73 D")?);
            }
        } else if kind != Finish {
            if let Some(d) = self.positive(b'D', "depth of cut Δd")? {
                self.puma.mrc.depth = Some(d);
            }
        }
        Ok(())
    }

    /// A G73 number of divisions (R of the 0-T form, D of the 10/11 form).
    fn mrc_divisions(&self, w: WVal, what: &str) -> R<u32> {
        if w.v < 1.0 || w.v.fract() != 0.0 || w.v > 9999.0 {
            return Err(self.alarm(
                AlarmKind::MrcValue,
                w.at,
                format!("{what} (number of divisions d) must be a whole number 1-9999"),
            ));
        }
        Ok(w.v as u32)
    }

    /// A P/Q sequence-number word.
    fn seq_word(&self, w: WVal) -> R<u32> {
        if w.v < 0.0 || w.v.fract() != 0.0 || w.v > 99_999.0 {
            return Err(self.alarm(
                AlarmKind::MrcNoPq,
                w.at,
                format!("{} is not a sequence number", fmt_num(w.v)),
            ));
        }
        Ok(w.v as u32)
    }

    /// G71-G73 with nose radius compensation in force before the cycle or
    /// written in the shape: the shape run through the compensation with
    /// its pieces captured instead of emitted — the imaginary tip's path
    /// A → A′ → B, as (A′, the segments after it). None without
    /// compensation. The compensation state, position and modal codes are
    /// left as before the cycle.
    fn shape_tip_path(&mut self, a: P, s: &Shape, at: u32) -> R<Option<(P, Vec<turning::Seg>)>> {
        let before = self.comp_side();
        if before == CompSide::Off && !s.comp_on {
            return Ok(None);
        }
        let saved = self.common.comp.take();
        let pos = self.frames.mover.pos();
        if before != CompSide::Off {
            self.comp_set_mode(before, None);
        }
        self.common.comp_capture = Some(Vec::with_capacity(2 * s.segs.len() + 4));
        let r = self.shape_run(a, s, at, false);
        let cap = self.common.comp_capture.take().unwrap_or_default();
        self.common.comp = saved;
        self.place_machine(pos);
        r?;
        let zx = |q: (f64, f64)| turning::p(q.1, q.0);
        let k = cap
            .iter()
            .rposition(|(_, src, own)| *own && *src == s.ns_src);
        let start = k.map(|k| zx(cap[k].0.end())).unwrap_or(a);
        let first = k.map(|k| k + 1).unwrap_or(0);
        let segs = cap[first..]
            .iter()
            .map(|(seg, _, _)| match *seg {
                crate::comp::Seg::Line { a, b } => turning::Seg {
                    from: zx(a),
                    to: zx(b),
                    arc: None,
                },
                crate::comp::Seg::Arc { a, b, c, ccw } => turning::Seg {
                    from: zx(a),
                    to: zx(b),
                    arc: Some((zx(c), ccw)),
                },
            })
            .collect();
        Ok(Some((start, segs)))
    }

    /// The feed of a shape block's F (mm, per the feed mode).
    fn shape_feed(&self, f: Option<f64>) -> Option<Feed> {
        f.map(|f| match self.modal.feed_mode.means {
            FeedMode::PerMin => Feed::PerMin(f.min(self.cfg.profile.feed.max_cutting)),
            FeedMode::PerRev => Feed::PerRev(f),
            FeedMode::Inverse => Feed::InverseTime(f),
        })
    }

    /// The shape's moves A → A′ → B with the nose radius compensation as
    /// written in the shape (G40/G41/G42 take effect with their block's
    /// move, the engine of interp/comp.rs joins the paths): emitted for
    /// G70 (`g70`: with the F and S of the shape; the G40/G41/G42 mode at
    /// the end of the shape stays in force), or captured into
    /// `comp_capture` for G71-G73 (where a G40 in the shape is ignored: the
    /// whole contour is offset). The last compensated move ends on its
    /// perpendicular vector.
    fn shape_run(&mut self, a: P, s: &Shape, at: u32, g70: bool) -> R<()> {
        let s0 = self.tool.s;
        let ns = turning::Seg {
            from: a,
            to: s.start,
            arc: None,
        };
        let first = (&ns, s.ns_rapid, s.ns_feed, s.ns_speed, s.ns_comp, s.ns_src);
        let rest = s
            .segs
            .iter()
            .zip(&s.modes)
            .zip(&s.speeds)
            .zip(&s.comps)
            .zip(&s.srcs)
            .map(|((((seg, &(rapid, f)), &sp), &c), &src)| (seg, rapid, f, sp, c, src));
        for (seg, rapid, f, sp, c, src) in std::iter::once(first).chain(rest) {
            match c {
                Some(c) if g70 => {
                    self.comp_set_mode(c, None);
                    self.modal
                        .set_meaning(self.cfg.dialect, Means::CutterComp(c));
                }
                // Roughing: the whole shape is offset, a G40 in it does not
                // cancel (docs/dialects.md).
                Some(c) if c != CompSide::Off => self.comp_set_mode(c, None),
                _ => {}
            }
            if g70 {
                self.g70_speed(sp.unwrap_or(s0));
            }
            let feed = self.shape_feed(f);
            if self.common.comp.is_some() {
                let speed = match (rapid, feed) {
                    (true, _) => motion::Speed::Rapid,
                    (false, Some(f)) => motion::Speed::Feed(f),
                    (false, None) if g70 => motion::Speed::Feed(self.feed(at)?),
                    _ => motion::Speed::Modal,
                };
                self.comp_shape_seg(seg, rapid, speed, at, src)?;
            } else if g70 {
                let m = if rapid { Mv::Rapid(seg.to) } else { seg.mv() };
                self.emit_moves(&[m], feed, at)?;
            } else {
                let zx = |q: P| (q.z, q.x);
                let cs = match seg.arc {
                    None => crate::comp::Seg::Line {
                        a: zx(seg.from),
                        b: zx(seg.to),
                    },
                    Some((c, ccw)) => crate::comp::Seg::Arc {
                        a: zx(seg.from),
                        b: zx(seg.to),
                        c: zx(c),
                        ccw,
                    },
                };
                if let Some(cap) = self.common.comp_capture.as_mut() {
                    cap.push((cs, src, true));
                }
                self.place_at(&self.zx_full(seg.to));
            }
        }
        self.comp_shape_end()
    }

    /// G70: the shape once, each block in its own mode at the F of the
    /// shape (or the modal F), then a rapid back to the start point.
    fn g70(&mut self, a: P, s: &Shape, at: u32) -> R<()> {
        if s.comp_on || self.comp_side() != CompSide::Off {
            let s0 = self.tool.s;
            self.shape_run(a, s, at, true)?;
            self.emit_moves(&[Mv::Rapid(a)], None, at)?;
            self.g70_speed(s0);
            return Ok(());
        }
        let feed_of = |me: &Self, f: Option<f64>| me.shape_feed(f);
        let first = if s.ns_rapid {
            Mv::Rapid(s.start)
        } else {
            Mv::Feed(s.start)
        };
        let s0 = self.tool.s;
        let f0 = feed_of(self, s.ns_feed);
        self.g70_speed(s.ns_speed.unwrap_or(s0));
        self.emit_moves(&[first], f0, at)?;
        for ((seg, &(rapid, f)), &sp) in s.segs.iter().zip(&s.modes).zip(&s.speeds) {
            let m = if rapid { Mv::Rapid(seg.to) } else { seg.mv() };
            let f = feed_of(self, f);
            self.g70_speed(sp.unwrap_or(s0));
            self.emit_moves(&[m], f, at)?;
        }
        self.emit_moves(&[Mv::Rapid(a)], None, at)?;
        // The S of the shape was for G70 only.
        self.g70_speed(s0);
        Ok(())
    }

    /// G70: the S in force for the next shape block; a spindle event when
    /// the rpm changes (the spindle running).
    fn g70_speed(&mut self, sv: f64) {
        if (sv - self.tool.s).abs() < 1e-12 {
            return;
        }
        self.tool.s = sv;
        if self.tool.spindle == SpindleDir::Stop {
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

    /// G74 / G75.
    fn mrc_peck(&mut self, kind: LatheCycle, code: u16, at: u32) -> R<()> {
        // The axis along which the columns (G74) / grooves (G75) step.
        let (cross, cross_inc) = if kind == PeckZ {
            (b'X', b'U')
        } else {
            (b'Z', b'W')
        };
        let has_end = [b'X', b'U', b'Z', b'W'].iter().any(|&l| self.words.has(l));
        if !has_end {
            // The first block `G74 R(e)` reads only R.
            if let Some(l) = [b'P', b'Q', b'I', b'K', b'D']
                .into_iter()
                .find(|&l| self.words.has(l))
            {
                let w = self.words.get(l).expect("present");
                return Err(self.unused_word(l, w.at, "the block with the end point X/Z"));
            }
            if let Some(w) = self.words.get(b'R') {
                self.puma.mrc.peck_escape = Some(self.linear(w).abs());
            }
            return Ok(());
        }
        let a = self.zx_pos();
        let half = if self.modal.diameter.means { 0.5 } else { 1.0 };
        let val = |me: &Self, abs: u8, inc: u8, cur: f64, is_x: bool| -> Option<f64> {
            let k = if is_x { half } else { 1.0 };
            if let Some(w) = me.words.get(abs) {
                Some(me.linear(w) * k)
            } else {
                me.words.get(inc).map(|w| cur + me.linear(w) * k)
            }
        };
        let (xend, zend) = (
            val(self, b'X', b'U', a.x, true),
            val(self, b'Z', b'W', a.z, false),
        );
        let columns = self.words.has(cross) || self.words.has(cross_inc);
        // G74: P = shift Δi (X), Q = peck Δk (Z); G75: P = peck Δi (X),
        // Q = shift Δk (Z). The one-block form (Fanuc 10/11) writes them
        // I, K and the relief Δd as D.
        let (li, lk, ld) = self.mrc_peck_letters(code)?;
        let amount = |me: &Self, l: u8| me.words.get(l).map(|w| me.linear(w).abs());
        let (pv, qv) = (amount(self, li), amount(self, lk));
        let (shift, peck) = if kind == PeckZ { (pv, qv) } else { (qv, pv) };
        let (shift, peck) = (shift.unwrap_or(0.0), peck.unwrap_or(0.0));
        let relief = self.words.get(ld).map(|w| self.linear(w)).unwrap_or(0.0);
        let escape = self
            .puma
            .mrc
            .peck_escape
            .unwrap_or_else(|| self.mrc_param(5139, 0.1));
        let end = turning::p(xend.unwrap_or(a.x), zend.unwrap_or(a.z));
        self.mrc_peck_amounts((kind, code), a, end, (li, lk), (pv, qv), at)?;
        let k = turning::Peck {
            end,
            shift,
            peck,
            relief,
            escape,
            columns,
        };
        let mut out = Vec::new();
        let r = if kind == PeckZ {
            turning::g74(a, k, &mut out)
        } else {
            turning::g75(a, k, &mut out)
        };
        if let Err(e) = r {
            let wat = self
                .words
                .get(if kind == PeckZ { lk } else { li })
                .map(|w| w.at)
                .unwrap_or(at);
            return Err(self.alarm(AlarmKind::MrcValue, wat, super::lathe::cycle_msg(&e)));
        }
        self.emit_moves(&out, None, at)
    }

    /// The one-block G76 (Fanuc 10/11 tape format, fanuc-semantics §10.2):
    /// `A` the tool angle (replaces a for this and later cycles, as the
    /// first block's P does), `P` the cutting method (only P1, single
    /// edge with a constant amount, which is what the 0-T form cuts), `Q`
    /// the thread start angle (canon has no spindle phase: an operator
    /// message). The letters of i, k, Δd are I, K, D.
    fn g76_one_block(&mut self, ang: &mut f64) -> R<(u8, u8, u8)> {
        let w = [b'I', b'K', b'D', b'A']
            .iter()
            .find_map(|&l| self.words.get(l))
            .expect("one of them");
        if !self.tape_format_10_11() {
            return Err(self.unused_word(b'I', w.at, "a one-block G76 (tape_format_10_11 on)"));
        }
        if let Some(r) = self.words.get(b'R') {
            return Err(self.alarm(
                AlarmKind::MrcValue,
                r.at,
                "G76: R(i) of the 0-T form with I K D A of the one-block form",
            ));
        }
        if let Some(a) = self.words.get(b'A') {
            let v = a.v;
            *ang = v;
            if let Some((m, r, _)) = self.puma.mrc.thread_p {
                self.puma.mrc.thread_p = Some((m, r, v));
            } else {
                self.puma.mrc.thread_p = Some((
                    self.mrc_param(5142, 1.0) as u32,
                    self.mrc_param(5130, 10.0) as u32,
                    v,
                ));
            }
        }
        if let Some(p) = self.words.get(b'P') {
            if p.v != 1.0 {
                return Err(self.alarm(
                    AlarmKind::MrcValue,
                    p.at,
                    format!(
                        "G76 P{}: only P1 (single-edge cutting, constant amount) is made",
                        fmt_num(p.v)
                    ),
                ));
            }
        }
        if let Some(q) = self.words.get(b'Q') {
            let deg = self.angular(q);
            if deg != 0.0 {
                self.emit(Canon::Message(format!(
                    "thread start angle {}",
                    fmt_num(deg)
                )));
            }
        }
        Ok((b'I', b'K', b'D'))
    }

    /// G74/G75: the peck (G74 Δk along Z, G75 Δi along X) and the shift
    /// between columns (G74 Δi, G75 Δk) must be given and positive when
    /// their axis moves; the alarm names the cycle's own letter.
    fn mrc_peck_amounts(
        &self,
        (kind, code): (LatheCycle, u16),
        a: P,
        end: P,
        (li, lk): (u8, u8),
        (vi, vk): (Option<f64>, Option<f64>),
        at: u32,
    ) -> R<()> {
        let (dx, dz) = ((end.x - a.x).abs() > 1e-9, (end.z - a.z).abs() > 1e-9);
        let g = code / 10;
        // (moves, letter, value, name)
        let checks = [
            (
                dx,
                li,
                vi,
                if kind == PeckZ {
                    "shift Δi"
                } else {
                    "peck depth Δi"
                },
            ),
            (
                dz,
                lk,
                vk,
                if kind == PeckZ {
                    "peck depth Δk"
                } else {
                    "shift Δk"
                },
            ),
        ];
        for (moves, l, v, name) in checks {
            if !moves {
                continue;
            }
            let axis = if l == li { "X" } else { "Z" };
            match v {
                Some(v) if v > 0.0 => {}
                Some(_) => {
                    let w = self.words.get(l).expect("present");
                    return Err(self.alarm(
                        AlarmKind::MrcValue,
                        w.at,
                        format!("G{g}: {name} ({}) must be positive", l as char),
                    ));
                }
                None => {
                    return Err(self.alarm(
                        AlarmKind::MrcValue,
                        at,
                        format!(
                            "G{g}: {name} ({}) missing: the end {axis} differs from the start",
                            l as char
                        ),
                    ))
                }
            }
        }
        Ok(())
    }

    /// The letters of a G74/G75 block's Δi, Δk, Δd: `P Q R` (0-T) or `I
    /// K D` (the one-block form of the Fanuc 10/11 tape format, profile
    /// `tape_format_10_11`); the two mixed, or I/K/D with the parameter
    /// off, are alarms.
    fn mrc_peck_letters(&self, code: u16) -> R<(u8, u8, u8)> {
        let new = [b'I', b'K', b'D'].into_iter().find(|&l| self.words.has(l));
        let Some(l) = new else {
            return Ok((b'P', b'Q', b'R'));
        };
        let w = self.words.get(l).expect("present");
        if !self.tape_format_10_11() {
            return Err(self.unused_word(l, w.at, "a one-block G74/G75 (tape_format_10_11 on)"));
        }
        if let Some(o) = [b'P', b'Q', b'R'].into_iter().find(|&o| self.words.has(o)) {
            return Err(self.alarm(
                AlarmKind::MrcValue,
                self.words.get(o).expect("present").at,
                format!(
                    "G{}: {} of the 0-T form with {} of the one-block form (I K D)",
                    code / 10,
                    o as char,
                    l as char
                ),
            ));
        }
        Ok((b'I', b'K', b'D'))
    }

    /// G76.
    fn mrc_thread(&mut self, at: u32) -> R<()> {
        let has_end = [b'X', b'U', b'Z', b'W'].iter().any(|&l| self.words.has(l));
        if !has_end {
            // The first block `G76 P(m r a) Q(Δdmin) R(d)` reads only those.
            if let Some(l) = [b'I', b'K', b'D', b'A']
                .into_iter()
                .find(|&l| self.words.has(l))
            {
                let w = self.words.get(l).expect("present");
                return Err(self.unused_word(l, w.at, "the block with the end point X/Z"));
            }
            if let Some(w) = self.words.get(b'P') {
                if w.v < 0.0 || w.v.fract() != 0.0 || w.v > 999_999.0 || w.point {
                    return Err(self.alarm(
                        AlarmKind::MrcValue,
                        w.at,
                        "G76 P must be six digits m r a without a decimal point",
                    ));
                }
                let v = w.v as u32;
                self.puma.mrc.thread_p = Some((v / 10000, (v / 100) % 100, (v % 100) as f64));
            }
            if let Some(w) = self.words.get(b'Q') {
                self.puma.mrc.min_depth = Some(self.linear(w).abs());
            }
            if let Some(w) = self.words.get(b'R') {
                self.puma.mrc.allowance = Some(self.linear(w).abs());
            }
            return Ok(());
        }
        let a = self.zx_pos();
        let half = if self.modal.diameter.means { 0.5 } else { 1.0 };
        let mut end = a;
        if let Some(w) = self.words.get(b'X') {
            end.x = self.linear(w) * half;
        } else if let Some(w) = self.words.get(b'U') {
            end.x = a.x + self.linear(w) * half;
        }
        if let Some(w) = self.words.get(b'Z') {
            end.z = self.linear(w);
        } else if let Some(w) = self.words.get(b'W') {
            end.z = a.z + self.linear(w);
        }
        let (m, r, mut ang) = self.puma.mrc.thread_p.unwrap_or((
            self.mrc_param(5142, 1.0) as u32,
            self.mrc_param(5130, 10.0) as u32,
            self.mrc_param(5143, 60.0),
        ));
        // 0-T: R(i) P(k) Q(Δd); one-block (Fanuc 10/11): I(i) K(k) D(Δd)
        // A(a) P(method) Q(start angle).
        let one_block = [b'I', b'K', b'D', b'A'].iter().any(|&l| self.words.has(l));
        let (li, lk, ld) = if one_block {
            self.g76_one_block(&mut ang)?
        } else {
            (b'R', b'P', b'Q')
        };
        let Some(k) = self.words.get(lk) else {
            return Err(self.alarm(
                AlarmKind::MrcValue,
                at,
                format!("G76 without the thread height {}(k)", lk as char),
            ));
        };
        let Some(dd) = self.words.get(ld) else {
            return Err(self.alarm(
                AlarmKind::MrcValue,
                at,
                format!("G76 without the first depth {}(Δd)", ld as char),
            ));
        };
        let lead = self.tool.feed.unwrap_or(0.0);
        if !self.words.has(b'F') && lead <= 0.0 {
            return Err(self.alarm(AlarmKind::NoFeed, at, "G76 without a thread lead (F)"));
        }
        let t = turning::Thread {
            finish_passes: m,
            chamfer: r,
            angle: ang,
            min_depth: self
                .puma
                .mrc
                .min_depth
                .unwrap_or_else(|| self.mrc_param(5140, 0.1)),
            allowance: self
                .puma
                .mrc
                .allowance
                .unwrap_or_else(|| self.mrc_param(5141, 0.0)),
            end,
            taper: self.words.get(li).map(|w| self.linear(w)).unwrap_or(0.0),
            height: self.linear(k),
            first_depth: self.linear(dd),
            lead,
        };
        let mut out = Vec::new();
        if let Err(e) = turning::g76(a, &t, &mut out) {
            return Err(self.alarm(AlarmKind::MrcValue, at, super::lathe::cycle_msg(&e)));
        }
        self.emit_moves(&out, None, at)
    }
}

/// PS064's message: the cycle (`G71 type I` …), the shape N(ns)-N(nf),
/// the axis, and the offending segment `i` (0-based) with its line — or,
/// on the nose-radius-compensated path, the piece.
fn not_monotonic_msg(
    what: &str,
    (ns, nf): (u32, u32),
    comp: bool,
    ax: char,
    i: usize,
    line: u32,
) -> String {
    if comp {
        format!(
            "{what}: the shape N{ns}-N{nf} offset by the nose radius (the imaginary tip's path) is not monotonic in {ax} (piece {} after N{ns})",
            i + 1
        )
    } else {
        format!(
            "{what}: the shape N{ns}-N{nf} is not monotonic in {ax} (segment {} after N{ns}, line {line})",
            i + 1
        )
    }
}
