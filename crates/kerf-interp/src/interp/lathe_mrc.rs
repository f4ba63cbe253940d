//! PUMA (Fanuc 0-T) multiple repetitive cycles G70-G76 (001 "G71"-"G76";
//! fanuc-semantics §1 and Appendix A): the two-block formats with their
//! modal first-block values, the finishing shape ns..nf read from the
//! program text, and the emission of the passes computed by
//! [`crate::turning`].
//!
//! The shape is read with the program's own [`kerf_lang::LineSource`]:
//! the source is moved to block N(ns) ([`Interp::seek_sequence`], forward
//! first, then from the program start), the blocks up to N(nf) are parsed
//! and evaluated one at a time into segments (at most
//! [`MAX_SHAPE_BLOCKS`]), and the source is left after N(nf) (G71-G73:
//! execution continues there) or put back after the cycle block (G70).
//! The block being executed is set aside while the shape is read, so the
//! parsed-block cache and the alarm positions stay right.

use super::*;
use crate::turning::{self, Mv, Seg, P};

/// Most blocks a finishing shape may have (memory bound; more is an
/// alarm).
pub(super) const MAX_SHAPE_BLOCKS: usize = 2000;

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

/// The finishing shape A → A′ → B.
struct Shape {
    /// A′: the end of block ns.
    start: P,
    /// Block ns moved X / Z.
    ns_x: bool,
    ns_z: bool,
    /// Block ns is G00.
    ns_rapid: bool,
    /// The segments A′ → B.
    segs: Vec<Seg>,
    /// Per segment: a G00 block, and the F in force in the shape (mm, per
    /// the feed mode), None = the modal F.
    modes: Vec<(bool, Option<f64>)>,
    /// Per segment: the S in force in the shape (None = the modal S).
    speeds: Vec<Option<f64>>,
    /// S in block ns.
    ns_speed: Option<f64>,
    /// F in block ns.
    ns_feed: Option<f64>,
}

/// A chamfer / corner-R word on a shape block, applied once the shape is
/// read.
struct ShapeCorner {
    /// Index of the block's segment.
    seg: usize,
    letter: u8,
    amount: f64,
    /// Where the word is.
    word: SrcRef,
    /// Block counter of the block.
    block: usize,
}

/// Why a shape could not be read: an alarm already positioned in a shape
/// block, or one to position on a word of the cycle block.
enum ShapeErr {
    Here(Alarm),
    AtCycle(AlarmKind, u8, String),
}

impl Interp {
    /// A G70-G76 block (`code` × 10), `at` the G word.
    pub(super) fn mrc(&mut self, code: u16, at: u32) -> R<()> {
        match code {
            700..=730 => self.mrc_shape_cycle(code, at),
            740 | 750 => self.mrc_peck(code, at),
            _ => self.mrc_thread(at),
        }
    }

    /// A parameter from the profile (`No.xxxx`) with a default.
    fn mrc_param(&self, n: u32, default: f64) -> f64 {
        self.profile.param(&format!("No.{n}"), default)
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

    /// G70, G71, G72, G73.
    fn mrc_shape_cycle(&mut self, code: u16, at: u32) -> R<()> {
        let has_pq = self.words.has(b'P') || self.words.has(b'Q');
        if !has_pq {
            if code == 700 {
                return Err(self.alarm(AlarmKind::MrcNoPq, at, "G70 without P (ns) and Q (nf)"));
            }
            // First block: modal data only.
            match code {
                710 | 720 => {
                    let l = if code == 710 { b'U' } else { b'W' };
                    if let Some(d) = self.positive(l, "depth of cut Δd")? {
                        self.lathe.mrc.depth = Some(d);
                    }
                    if let Some(w) = self.words.get(b'R') {
                        self.lathe.mrc.escape = Some(self.linear(w).abs());
                    }
                }
                _ => {
                    let (mut i, mut k) = self.lathe.mrc.relief.unwrap_or((None, None));
                    if let Some(w) = self.words.get(b'U') {
                        i = Some(self.linear(w));
                    }
                    if let Some(w) = self.words.get(b'W') {
                        k = Some(self.linear(w));
                    }
                    self.lathe.mrc.relief = Some((i, k));
                    if let Some(w) = self.words.get(b'R') {
                        if w.v < 1.0 || w.v.fract() != 0.0 || w.v > 9999.0 {
                            return Err(self.alarm(
                                AlarmKind::MrcValue,
                                w.at,
                                "G73 R (number of divisions d) must be a whole number 1-9999",
                            ));
                        }
                        self.lathe.mrc.divisions = Some(w.v as u32);
                    }
                }
            }
            return Ok(());
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
        let half = if self.st.diameter { 0.5 } else { 1.0 };
        let du = self
            .words
            .get(b'U')
            .map(|w| self.linear(w) * half)
            .unwrap_or(0.0);
        let dw = self.words.get(b'W').map(|w| self.linear(w)).unwrap_or(0.0);
        let p_at = self.words.get(b'P').map(|w| w.at).unwrap_or(at);
        let q_at = self.words.get(b'Q').map(|w| w.at).unwrap_or(at);
        let a = self.zx_pos();
        let resume = self.src.as_ref().expect("loaded").tell();
        let shape = match self.read_shape(ns, nf) {
            Ok(s) => s,
            Err(ShapeErr::Here(a)) => return Err(a),
            Err(ShapeErr::AtCycle(k, l, msg)) => {
                return Err(self.alarm(k, if l == b'P' { p_at } else { q_at }, msg))
            }
        };
        // G70 goes on after its own block; G71-G73 after N(nf) when the
        // shape follows the cycle, else after the cycle block too.
        let after_nf = self.src.as_ref().expect("loaded").tell();
        if code == 700 || after_nf.offset <= resume.offset {
            self.seek(resume)?;
        }
        if code == 700 {
            return self.g70(a, &shape, at);
        }
        // Type II (pockets) when block ns moves both axes.
        let type2 = shape.ns_x && shape.ns_z;
        let mut out = Vec::with_capacity(64 + shape.segs.len());
        let res = match code {
            710 | 720 => {
                let r = turning::Rough {
                    depth: self
                        .lathe
                        .mrc
                        .depth
                        .unwrap_or_else(|| self.mrc_param(5132, 1.0)),
                    escape: self
                        .lathe
                        .mrc
                        .escape
                        .unwrap_or_else(|| self.mrc_param(5133, 0.5)),
                    allow_x: du,
                    allow_z: dw,
                };
                match (code, type2) {
                    (710, false) => {
                        turning::g71(a, shape.start, &shape.segs, r, shape.ns_rapid, &mut out)
                    }
                    (710, true) => {
                        turning::g71_type2(a, shape.start, &shape.segs, r, shape.ns_rapid, &mut out)
                    }
                    _ => turning::g72(
                        a,
                        shape.start,
                        &shape.segs,
                        r,
                        shape.ns_rapid,
                        type2,
                        &mut out,
                    ),
                }
            }
            _ => {
                let (i, k) = self.lathe.mrc.relief.unwrap_or((None, None));
                let relief = turning::p(
                    i.unwrap_or_else(|| self.mrc_param(5135, 0.0)),
                    k.unwrap_or_else(|| self.mrc_param(5136, 0.0)),
                );
                let d = self
                    .lathe
                    .mrc
                    .divisions
                    .unwrap_or_else(|| self.mrc_param(5137, 1.0) as u32);
                turning::g73(
                    a,
                    shape.start,
                    &shape.segs,
                    relief,
                    turning::p(du, dw),
                    d,
                    shape.ns_rapid,
                    &mut out,
                )
            }
        };
        match res {
            Ok(()) => {}
            Err(turning::CycleError::NotMonotonic(i, ax)) => {
                return Err(self.alarm(
                    AlarmKind::MrcNotMonotonic,
                    p_at,
                    format!(
                        "G{} type {}: the shape N{ns}-N{nf} is not monotonic in {ax} (segment {} after N{ns})",
                        code / 10,
                        if type2 { "II" } else { "I" },
                        i + 1
                    ),
                ));
            }
            Err(e) => return Err(self.alarm(AlarmKind::MrcValue, at, super::lathe::cycle_msg(&e))),
        }
        self.emit_moves(&out, None, at)
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

    /// G70: the shape once, each block in its own mode at the F of the
    /// shape (or the modal F), then a rapid back to the start point.
    fn g70(&mut self, a: P, s: &Shape, at: u32) -> R<()> {
        let feed_of = |me: &Self, f: Option<f64>| -> Option<Feed> {
            f.map(|f| match me.st.feed_mode {
                FeedMode::PerMin => Feed::PerMin(f.min(me.profile.feed.max_cutting)),
                FeedMode::PerRev => Feed::PerRev(f),
                FeedMode::Inverse => Feed::InverseTime(f),
            })
        };
        let first = if s.ns_rapid {
            Mv::Rapid(s.start)
        } else {
            Mv::Feed(s.start)
        };
        let s0 = self.st.s;
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
        if (sv - self.st.s).abs() < 1e-12 {
            return;
        }
        self.st.s = sv;
        if self.st.spindle == SpindleDir::Stop {
            return;
        }
        let rpm = self.rpm();
        if (rpm - self.st.last_rpm).abs() > 1e-6 {
            self.st.last_rpm = rpm;
            let css = self.css_speed();
            self.emit(Canon::Spindle {
                dir: self.st.spindle,
                rpm,
                css,
            });
        }
    }

    /// Reads the shape N(ns)..N(nf) (see the module documentation).
    fn read_shape(&mut self, ns: u32, nf: u32) -> Result<Shape, ShapeErr> {
        if !self.seek_sequence(ns, true) {
            return Err(ShapeErr::AtCycle(
                AlarmKind::MrcSeqNotFound,
                b'P',
                format!("sequence number N{ns} (P) not found"),
            ));
        }
        let saved_raw = std::mem::take(&mut self.raw);
        let saved_block = std::mem::take(&mut self.block);
        let saved_words = self.words.clone();
        let r = self.read_shape_blocks(ns, nf);
        self.raw = saved_raw;
        self.block = saved_block;
        self.words = saved_words;
        r
    }

    fn read_shape_blocks(&mut self, ns: u32, nf: u32) -> Result<Shape, ShapeErr> {
        let a = self.zx_pos();
        let mut cur = a;
        let mut mode: Option<u16> = None;
        let mut feed: Option<f64> = None;
        let mut speed: Option<f64> = None;
        let mut shape = Shape {
            start: a,
            ns_x: false,
            ns_z: false,
            ns_rapid: false,
            segs: Vec::new(),
            modes: Vec::new(),
            speeds: Vec::new(),
            ns_feed: None,
            ns_speed: None,
        };
        let mut count = 0usize;
        let mut corners: Vec<ShapeCorner> = Vec::new();
        let mut seg_blocks: Vec<(usize, u32)> = Vec::new();
        loop {
            let src = self.src.as_mut().expect("loaded");
            match src.next_block(&mut self.raw) {
                Ok(true) => {}
                _ => {
                    return Err(ShapeErr::AtCycle(
                        AlarmKind::MrcSeqNotFound,
                        b'Q',
                        format!("sequence number N{nf} (Q) not found after N{ns}"),
                    ))
                }
            }
            self.parse_raw().map_err(ShapeErr::Here)?;
            if self.block.percent || self.block.program.is_some() {
                return Err(ShapeErr::AtCycle(
                    AlarmKind::MrcSeqNotFound,
                    b'Q',
                    format!("sequence number N{nf} (Q) not found after N{ns} in this program"),
                ));
            }
            let mut nwords = self.block.words.len();
            let mut skip = false;
            for &(idx, mask) in &self.block.deletes {
                if mask & self.settings.block_skip != 0 {
                    if idx == 0 {
                        skip = true;
                    }
                    nwords = nwords.min(idx as usize);
                    break;
                }
            }
            let is_last = self.block.n == Some(nf);
            if skip {
                if is_last {
                    break;
                }
                continue;
            }
            if self.block.stmt.is_some() {
                return Err(ShapeErr::Here(self.alarm(
                    AlarmKind::MrcIllegal,
                    self.block.stmt_at,
                    "macro statement inside the finishing shape ns-nf",
                )));
            }
            count += 1;
            if count > MAX_SHAPE_BLOCKS {
                return Err(ShapeErr::AtCycle(
                    AlarmKind::LatheCycle,
                    b'Q',
                    format!("finishing shape longer than {MAX_SHAPE_BLOCKS} blocks"),
                ));
            }
            self.collect(nwords).map_err(ShapeErr::Here)?;
            let first = mode.is_none();
            let mut blk_mode = None;
            for &(g, gat) in self.words.gs() {
                match g {
                    0 | 10 | 20 | 30 => blk_mode = Some(g),
                    40 | 200 | 210 | 400 | 960 | 970 | 980 | 990 => {}
                    410 | 420 => {
                        return Err(ShapeErr::Here(self.alarm(
                            AlarmKind::NotYetSupported,
                            gat,
                            "tool nose radius compensation in a finishing shape is not yet supported (issue 5)",
                        )))
                    }
                    _ => {
                        return Err(ShapeErr::Here(self.alarm(
                            AlarmKind::MrcIllegal,
                            gat,
                            format!("G{} is not allowed inside the finishing shape ns-nf", fmt_code(g)),
                        )))
                    }
                }
            }
            for &(m, mat) in self.words.ms() {
                if matches!(m, 98 | 99) {
                    return Err(ShapeErr::Here(self.alarm(
                        AlarmKind::MrcIllegal,
                        mat,
                        format!("M{m} is not allowed inside the finishing shape ns-nf"),
                    )));
                }
            }
            if first {
                match blk_mode {
                    Some(0 | 10) => {}
                    _ => {
                        return Err(ShapeErr::Here(self.alarm(
                            AlarmKind::MrcFirstBlock,
                            blk_mode.map(|_| self.words.gs()[0].1).unwrap_or(0),
                            format!(
                                "the first block N{ns} of the finishing shape has no G00 or G01"
                            ),
                        )))
                    }
                }
            }
            if let Some(m) = blk_mode {
                mode = Some(m);
            }
            let m = mode.expect("set by the first block");
            if let Some(f) = self.words.get(b'F') {
                feed = Some(f.v * self.unit());
            }
            if let Some(w) = self.words.get(b'S') {
                speed = Some(w.v);
            }
            // End point.
            let mut t = cur;
            let (mut hx, mut hz) = (false, false);
            let half = if self.st.diameter { 0.5 } else { 1.0 };
            if let Some(w) = self.words.get(b'X') {
                t.x = self.linear(w) * half;
                hx = true;
            } else if let Some(w) = self.words.get(b'U') {
                t.x = cur.x + self.linear(w) * half;
                hx = true;
            }
            if let Some(w) = self.words.get(b'Z') {
                t.z = self.linear(w);
                hz = true;
            } else if let Some(w) = self.words.get(b'W') {
                t.z = cur.z + self.linear(w);
                hz = true;
            }
            if self.words.has(b'X') && self.words.has(b'U')
                || self.words.has(b'Z') && self.words.has(b'W')
            {
                let w = self
                    .words
                    .get(b'U')
                    .or(self.words.get(b'W'))
                    .expect("present");
                return Err(ShapeErr::Here(self.alarm(
                    AlarmKind::DuplicateAddress,
                    w.at,
                    "an axis and its incremental address in one block",
                )));
            }
            // Chamfer / corner R words on a G01 (direct drawing input).
            let corner_word = if m == 10 {
                [b'C', b'R', b'I', b'K']
                    .iter()
                    .find_map(|&l| self.words.get(l))
            } else {
                None
            };
            if let Some(w) = corner_word {
                if is_last {
                    return Err(ShapeErr::Here(self.alarm(
                        AlarmKind::MrcEndCorner,
                        w.at,
                        format!("the last block N{nf} of the finishing shape ends with a chamfer or corner R"),
                    )));
                }
                if first {
                    return Err(ShapeErr::Here(self.alarm(
                        AlarmKind::NotYetSupported,
                        w.at,
                        "chamfer / corner R on the first block ns of a finishing shape is not yet supported",
                    )));
                }
                let n = [b'C', b'R', b'I', b'K']
                    .iter()
                    .filter(|&&l| self.words.has(l))
                    .count();
                if n > 1 {
                    return Err(ShapeErr::Here(self.alarm(
                        AlarmKind::CornerConflict,
                        w.at,
                        "two of I, K, R, C in one block (001 p.10 note 3)",
                    )));
                }
                let letter = [b'C', b'R', b'I', b'K']
                    .into_iter()
                    .find(|&l| self.words.has(l))
                    .expect("one");
                corners.push(ShapeCorner {
                    seg: shape.segs.len(),
                    letter,
                    amount: self.linear(w),
                    word: self.alarm(AlarmKind::CornerConflict, w.at, "").src,
                    block: count,
                });
            }
            if first {
                shape.start = t;
                shape.ns_x = hx;
                shape.ns_z = hz;
                shape.ns_rapid = m == 0;
                shape.ns_feed = feed;
                shape.ns_speed = speed;
            } else if hx
                || hz
                || matches!(m, 20 | 30) && self.words.has(b'I') | self.words.has(b'K')
            {
                let arc = if matches!(m, 20 | 30) {
                    let ccw = m == 30;
                    let c = self.shape_arc_center(cur, t, ccw).map_err(ShapeErr::Here)?;
                    Some((c, ccw))
                } else {
                    None
                };
                if arc.is_some() || t != cur {
                    shape.segs.push(Seg {
                        from: cur,
                        to: t,
                        arc,
                    });
                    shape.modes.push((m == 0, feed));
                    shape.speeds.push(speed);
                    seg_blocks.push((count, self.raw.mark.line));
                }
            }
            cur = t;
            if is_last {
                break;
            }
        }
        for c in corners.into_iter().rev() {
            self.shape_corner(&mut shape, &c, &seg_blocks)
                .map_err(ShapeErr::Here)?;
        }
        Ok(shape)
    }

    /// A chamfer or corner R on shape segment `c.seg` (001 p.10, the same
    /// rules as interp/lathe_chamfer.rs): the segment is shortened and the
    /// corner inserted before the next segment, which starts at C′.
    fn shape_corner(&self, shape: &mut Shape, c: &ShapeCorner, blocks: &[(usize, u32)]) -> R<()> {
        let d = self.dialect.id;
        let at_word = |k: AlarmKind, msg: String| k.at(d, c.word, msg);
        let i = c.seg;
        let next_line = blocks.get(i + 1).map(|b| b.1).unwrap_or(c.word.line);
        let at_next = |k: AlarmKind, msg: &str| {
            k.at(
                d,
                SrcRef {
                    line: next_line,
                    col: 1,
                    ..c.word
                },
                msg,
            )
        };
        let seg = shape.segs[i];
        let (dx, dz) = (seg.to.x - seg.from.x, seg.to.z - seg.from.z);
        if dx.abs() > 1e-9 && dz.abs() > 1e-9 {
            return Err(at_word(
                AlarmKind::ChamferTaper,
                "chamfer or corner R on a block that moves both X and Z".into(),
            ));
        }
        let along_z = dz.abs() > 1e-9;
        if (c.letter == b'I' && !along_z) || (c.letter == b'K' && along_z) {
            return Err(at_word(
                AlarmKind::CornerConflict,
                "I goes with a Z move, K with an X move (001 p.10 note 3)".into(),
            ));
        }
        let Some(next) = shape.segs.get(i + 1).copied() else {
            return Err(at_word(
                AlarmKind::ChamferNextBlock,
                "chamfer or corner R without a next move".into(),
            ));
        };
        if blocks[i + 1].0 != c.block + 1 || next.arc.is_some() || shape.modes[i + 1].0 {
            return Err(at_next(
                AlarmKind::ChamferNextBlock,
                "the block after a chamfer or corner R must be a G01 move",
            ));
        }
        let (nx, nz) = (next.to.x - next.from.x, next.to.z - next.from.z);
        let (na, nb) = if along_z { (nx, nz) } else { (nz, nx) };
        if nb.abs() > 1e-9 {
            return Err(at_next(
                if na.abs() > 1e-9 {
                    AlarmKind::ChamferTaper
                } else {
                    AlarmKind::ChamferNextBlock
                },
                "the block after a chamfer or corner R must move along the other axis only",
            ));
        }
        let amt = c.amount.abs();
        let s = if c.letter == b'C' {
            na.signum()
        } else {
            c.amount.signum()
        };
        if na.abs() < 1e-9 || na.signum() != s {
            return Err(at_next(
                AlarmKind::ChamferNextBlock,
                "the block after the chamfer or corner R goes the other way than its sign",
            ));
        }
        let len = if along_z { dz } else { dx };
        if amt > len.abs() + 1e-9 {
            return Err(at_word(
                AlarmKind::CornerTooLarge,
                format!(
                    "chamfer / corner R {} is longer than the block's move",
                    fmt_num(amt)
                ),
            ));
        }
        if amt > na.abs() + 1e-9 {
            return Err(at_next(
                AlarmKind::CornerTooLarge,
                "the move after a chamfer / corner R is shorter than it",
            ));
        }
        if amt == 0.0 {
            return Ok(());
        }
        let d1 = len.signum();
        let b = seg.to;
        let (pre, post) = if along_z {
            (
                turning::p(b.x, b.z - d1 * amt),
                turning::p(b.x + s * amt, b.z),
            )
        } else {
            (
                turning::p(b.x - d1 * amt, b.z),
                turning::p(b.x, b.z + s * amt),
            )
        };
        let arc = (c.letter == b'R').then(|| {
            let cen = if along_z {
                turning::p(pre.x + s * amt, pre.z)
            } else {
                turning::p(pre.x, pre.z + s * amt)
            };
            let (u1, v1) = if along_z { (d1, 0.0) } else { (0.0, d1) };
            let (u2, v2) = if along_z { (0.0, s) } else { (s, 0.0) };
            (cen, u1 * v2 - v1 * u2 > 0.0)
        });
        shape.segs[i].to = pre;
        shape.segs[i + 1].from = post;
        shape.segs.insert(
            i + 1,
            Seg {
                from: pre,
                to: post,
                arc,
            },
        );
        let mode = shape.modes[i];
        shape.modes.insert(i + 1, mode);
        let speed = shape.speeds[i];
        shape.speeds.insert(i + 1, speed);
        Ok(())
    }

    /// The centre of a shape block's arc from R or I/K (001: I, K radius
    /// values from the start point; R wins over I/K).
    fn shape_arc_center(&self, s: P, e: P, ccw: bool) -> R<P> {
        let at = self.words.gs().first().map(|g| g.1).unwrap_or(0);
        if let Some(r) = self.words.get(b'R') {
            let rv = self.linear(r);
            let c = crate::arc::center_from_radius(s.zx(), e.zx(), rv, ccw, f64::INFINITY)
                .map_err(|_| {
                    self.alarm(AlarmKind::ArcRadius, r.at, "arc radius zero in the shape")
                })?;
            return Ok(turning::p(c.1, c.0));
        }
        if !(self.words.has(b'I') || self.words.has(b'K')) {
            return Err(self.alarm(
                AlarmKind::ArcNoCenter,
                at,
                "arc without centre (I/K) or radius (R) in the shape",
            ));
        }
        let i = self.words.get(b'I').map(|w| self.linear(w)).unwrap_or(0.0);
        let k = self.words.get(b'K').map(|w| self.linear(w)).unwrap_or(0.0);
        let c = turning::p(s.x + i, s.z + k);
        if let Err(e) = crate::arc::check_end(s.zx(), e.zx(), c.zx(), self.arc_tol) {
            let msg = match e {
                ArcError::EndNotOnCircle { r_start, r_end } => format!(
                    "arc end point is not on the circle: start radius {r_start:.4}, end radius {r_end:.4}"
                ),
                _ => "arc centre coincides with the start point".into(),
            };
            return Err(self.alarm(AlarmKind::ArcEndPoint, at, msg));
        }
        Ok(c)
    }

    /// G74 / G75.
    fn mrc_peck(&mut self, code: u16, at: u32) -> R<()> {
        // The axis along which the columns (G74) / grooves (G75) step.
        let (cross, cross_inc) = if code == 740 {
            (b'X', b'U')
        } else {
            (b'Z', b'W')
        };
        let has_end = [b'X', b'U', b'Z', b'W'].iter().any(|&l| self.words.has(l));
        if !has_end {
            if let Some(w) = self.words.get(b'R') {
                self.lathe.mrc.peck_escape = Some(self.linear(w).abs());
            }
            return Ok(());
        }
        let a = self.zx_pos();
        let half = if self.st.diameter { 0.5 } else { 1.0 };
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
        // Q = shift Δk (Z).
        let pv = self
            .words
            .get(b'P')
            .map(|w| self.linear(w).abs())
            .unwrap_or(0.0);
        let qv = self
            .words
            .get(b'Q')
            .map(|w| self.linear(w).abs())
            .unwrap_or(0.0);
        let (shift, peck) = if code == 740 { (pv, qv) } else { (qv, pv) };
        let relief = self.words.get(b'R').map(|w| self.linear(w)).unwrap_or(0.0);
        let escape = self
            .lathe
            .mrc
            .peck_escape
            .unwrap_or_else(|| self.mrc_param(5139, 0.1));
        let k = turning::Peck {
            end: turning::p(xend.unwrap_or(a.x), zend.unwrap_or(a.z)),
            shift,
            peck,
            relief,
            escape,
            columns,
        };
        let mut out = Vec::new();
        let r = if code == 740 {
            turning::g74(a, k, &mut out)
        } else {
            turning::g75(a, k, &mut out)
        };
        if let Err(e) = r {
            let wat = self
                .words
                .get(if code == 740 { b'Q' } else { b'P' })
                .map(|w| w.at)
                .unwrap_or(at);
            return Err(self.alarm(AlarmKind::MrcValue, wat, super::lathe::cycle_msg(&e)));
        }
        self.emit_moves(&out, None, at)
    }

    /// G76.
    fn mrc_thread(&mut self, at: u32) -> R<()> {
        let has_end = [b'X', b'U', b'Z', b'W'].iter().any(|&l| self.words.has(l));
        if !has_end {
            if let Some(w) = self.words.get(b'P') {
                if w.v < 0.0 || w.v.fract() != 0.0 || w.v > 999_999.0 || w.point {
                    return Err(self.alarm(
                        AlarmKind::MrcValue,
                        w.at,
                        "G76 P must be six digits m r a without a decimal point",
                    ));
                }
                let v = w.v as u32;
                self.lathe.mrc.thread_p = Some((v / 10000, (v / 100) % 100, (v % 100) as f64));
            }
            if let Some(w) = self.words.get(b'Q') {
                self.lathe.mrc.min_depth = Some(self.linear(w).abs());
            }
            if let Some(w) = self.words.get(b'R') {
                self.lathe.mrc.allowance = Some(self.linear(w).abs());
            }
            return Ok(());
        }
        let a = self.zx_pos();
        let half = if self.st.diameter { 0.5 } else { 1.0 };
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
        let (m, r, ang) = self.lathe.mrc.thread_p.unwrap_or((
            self.mrc_param(5142, 1.0) as u32,
            self.mrc_param(5130, 10.0) as u32,
            self.mrc_param(5143, 60.0),
        ));
        let Some(k) = self.words.get(b'P') else {
            return Err(self.alarm(
                AlarmKind::MrcValue,
                at,
                "G76 without the thread height P(k)",
            ));
        };
        let Some(dd) = self.words.get(b'Q') else {
            return Err(self.alarm(AlarmKind::MrcValue, at, "G76 without the first depth Q(Δd)"));
        };
        let lead = self.st.feed.unwrap_or(0.0);
        if !self.words.has(b'F') && lead <= 0.0 {
            return Err(self.alarm(AlarmKind::NoFeed, at, "G76 without a thread lead (F)"));
        }
        let t = turning::Thread {
            finish_passes: m,
            chamfer: r,
            angle: ang,
            min_depth: self
                .lathe
                .mrc
                .min_depth
                .unwrap_or_else(|| self.mrc_param(5140, 0.1)),
            allowance: self
                .lathe
                .mrc
                .allowance
                .unwrap_or_else(|| self.mrc_param(5141, 0.0)),
            end,
            taper: self.words.get(b'R').map(|w| self.linear(w)).unwrap_or(0.0),
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
