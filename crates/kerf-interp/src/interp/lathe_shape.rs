//! The finishing shape N(ns)..N(nf) of the PUMA cycles G70-G73 (001
//! "G71"-"G73"; fanuc-semantics §1.1), read with the program's own
//! [`kerf_lang::LineSource`]: the source is moved to block N(ns)
//! ([`Interp::seek_sequence`], forward first, then from the program
//! start), the blocks up to N(nf) are parsed and evaluated one at a time
//! into segments (at most [`MAX_SHAPE_BLOCKS`]), direct chamfers and
//! corner Rs in them expanded (001 p.10), and the source is left after
//! N(nf); interp/lathe_mrc.rs decides where execution goes on. The block
//! being executed is set aside while the shape is read, so the
//! parsed-block cache and the alarm positions stay right.

use super::*;
use crate::dialect::meaning::OneShot;
use crate::turning::{self, Seg, P};

/// Most blocks a finishing shape may have (memory bound; more is an
/// alarm).
pub(super) const MAX_SHAPE_BLOCKS: usize = 2000;

/// The finishing shape A → A′ → B.
pub(super) struct Shape {
    /// A′: the end of block ns.
    pub(super) start: P,
    /// Block ns moved X / Z.
    pub(super) ns_x: bool,
    pub(super) ns_z: bool,
    /// Block ns is G00.
    pub(super) ns_rapid: bool,
    /// The segments A′ → B.
    pub(super) segs: Vec<Seg>,
    /// Per segment: a G00 block, and the F in force in the shape (mm, per
    /// the feed mode), None = the modal F.
    pub(super) modes: Vec<(bool, Option<f64>)>,
    /// Per segment: the S in force in the shape (None = the modal S).
    pub(super) speeds: Vec<Option<f64>>,
    /// S in block ns.
    pub(super) ns_speed: Option<f64>,
    /// F in block ns.
    pub(super) ns_feed: Option<f64>,
    /// G40/G41/G42 written in block ns / taking effect with each
    /// segment (a code in a block without a move goes with the next
    /// segment).
    pub(super) ns_comp: Option<CompSide>,
    pub(super) comps: Vec<Option<CompSide>>,
    /// A G41/G42 anywhere in the shape.
    pub(super) comp_on: bool,
    /// Where block ns / each segment's block is (alarms of the
    /// compensation).
    pub(super) ns_src: SrcRef,
    pub(super) srcs: Vec<SrcRef>,
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
pub(super) enum ShapeErr {
    Here(Alarm),
    AtCycle(AlarmKind, u8, String),
}

impl Shape {
    /// A shape with no segment yet, starting at `start`.
    fn empty(start: P, ns_src: SrcRef) -> Shape {
        Shape {
            start,
            ns_x: false,
            ns_z: false,
            ns_rapid: false,
            segs: Vec::new(),
            modes: Vec::new(),
            speeds: Vec::new(),
            ns_feed: None,
            ns_speed: None,
            ns_comp: None,
            comps: Vec::new(),
            comp_on: false,
            ns_src,
            srcs: Vec::new(),
        }
    }
}

impl Interp {
    /// Reads the shape N(ns)..N(nf) (see the module documentation).
    pub(super) fn read_shape(&mut self, ns: u32, nf: u32) -> Result<Shape, ShapeErr> {
        if !self.seek_sequence(ns, true) {
            return Err(ShapeErr::AtCycle(
                AlarmKind::MrcSeqNotFound,
                b'P',
                format!("sequence number N{ns} (P) not found"),
            ));
        }
        let saved_raw = std::mem::take(&mut self.prog.raw);
        let saved_block = std::mem::take(&mut self.prog.block);
        let saved_words = self.words.clone();
        let r = self.read_shape_blocks(ns, nf);
        self.prog.raw = saved_raw;
        self.prog.block = saved_block;
        self.words = saved_words;
        r
    }

    fn read_shape_blocks(&mut self, ns: u32, nf: u32) -> Result<Shape, ShapeErr> {
        use MotionMode::{ArcCcw, ArcCw, Linear, Rapid};
        let a = self.zx_pos();
        let mut cur = a;
        let mut mode: Option<MotionMode> = None;
        let mut feed: Option<f64> = None;
        let mut speed: Option<f64> = None;
        let mut shape = Shape::empty(a, self.prog.cur);
        let mut comp_pending: Option<CompSide> = None;
        let mut count = 0usize;
        let mut corners: Vec<ShapeCorner> = Vec::new();
        let mut seg_blocks: Vec<(usize, u32)> = Vec::new();
        loop {
            let (nwords, skip) = self.shape_read_block(ns, nf)?;
            let is_last = self.prog.block.n == Some(nf);
            if skip {
                if is_last {
                    break;
                }
                continue;
            }
            if self.prog.block.stmt.is_some() {
                return Err(ShapeErr::Here(self.alarm(
                    AlarmKind::MrcIllegal,
                    self.prog.block.stmt_at,
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
            let blk_mode = self.shape_block_codes(&mut comp_pending, &mut shape.comp_on)?;
            if first {
                self.shape_first_mode(ns, blk_mode)?;
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
            let (t, hx, hz) = self.shape_end_point(cur)?;
            if m == Linear {
                let here = (is_last, first, shape.segs.len(), count);
                if let Some(c) = self.shape_corner_word(nf, here)? {
                    corners.push(c);
                }
            }
            let blk_at = [b'X', b'U', b'Z', b'W']
                .iter()
                .find_map(|&l| self.words.get(l))
                .map(|w| w.at)
                .or(self.words.gs().first().map(|g| g.1))
                .unwrap_or(0);
            let blk_src = self.alarm(AlarmKind::CompArc, blk_at, "").src;
            if first {
                shape.ns_comp = comp_pending.take();
                shape.ns_src = blk_src;
                shape.start = t;
                shape.ns_x = hx;
                shape.ns_z = hz;
                shape.ns_rapid = m == Rapid;
                shape.ns_feed = feed;
                shape.ns_speed = speed;
            } else if hx
                || hz
                || matches!(m, ArcCw | ArcCcw) && self.words.has(b'I') | self.words.has(b'K')
            {
                let arc = if matches!(m, ArcCw | ArcCcw) {
                    let ccw = m == ArcCcw;
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
                    shape.modes.push((m == Rapid, feed));
                    shape.speeds.push(speed);
                    shape.comps.push(comp_pending.take());
                    shape.srcs.push(blk_src);
                    seg_blocks.push((count, self.prog.raw.mark.line));
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

    /// Reads and parses the next block of the shape (an alarm at the
    /// cycle when the text ends before N(nf)); returns its word count
    /// after block delete and whether block delete skips it whole.
    fn shape_read_block(&mut self, ns: u32, nf: u32) -> Result<(usize, bool), ShapeErr> {
        let src = self.prog.src.as_mut().expect("loaded");
        match src.next_block(&mut self.prog.raw) {
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
        if self.prog.block.percent || self.prog.block.program.is_some() {
            return Err(ShapeErr::AtCycle(
                AlarmKind::MrcSeqNotFound,
                b'Q',
                format!("sequence number N{nf} (Q) not found after N{ns} in this program"),
            ));
        }
        let mut nwords = self.prog.block.words.len();
        let mut skip = false;
        for &(idx, mask) in &self.prog.block.deletes {
            if mask & self.settings.block_skip != 0 {
                if idx == 0 {
                    skip = true;
                }
                nwords = nwords.min(idx as usize);
                break;
            }
        }
        Ok((nwords, skip))
    }

    /// The first block of the finishing shape N(ns) must be G00 or G01.
    fn shape_first_mode(&self, ns: u32, mode: Option<MotionMode>) -> Result<(), ShapeErr> {
        match mode {
            Some(MotionMode::Rapid | MotionMode::Linear) => Ok(()),
            _ => Err(ShapeErr::Here(self.alarm(
                AlarmKind::MrcFirstBlock,
                mode.map(|_| self.words.gs()[0].1).unwrap_or(0),
                format!("the first block N{ns} of the finishing shape has no G00 or G01"),
            ))),
        }
    }

    /// The G and M codes a shape block may carry; its motion code. A
    /// G40-G42 is kept for the segment (`comp_pending`; `comp_on` when one
    /// switches compensation on).
    fn shape_block_codes(
        &self,
        comp_pending: &mut Option<CompSide>,
        comp_on: &mut bool,
    ) -> Result<Option<MotionMode>, ShapeErr> {
        let mut blk_mode = None;
        use MotionMode::{ArcCcw, ArcCw, Linear, Rapid};
        for &(g, gat) in self.words.gs() {
            match self.gcode(g).map(|c| c.means) {
                Some(Means::Motion(mode @ (Rapid | Linear | ArcCw | ArcCcw))) => {
                    blk_mode = Some(mode)
                }
                Some(
                    Means::OneShot(OneShot::Dwell)
                    | Means::Units(_)
                    | Means::Css(_)
                    | Means::FeedMode(_),
                ) => {}
                // Nose radius compensation: G70 runs the shape with
                // it, G71-G73 offset the shape (interp/lathe_mrc.rs).
                Some(Means::CutterComp(side)) => {
                    *comp_pending = Some(side);
                    *comp_on |= side != CompSide::Off;
                }
                _ => {
                    return Err(ShapeErr::Here(self.alarm(
                        AlarmKind::MrcIllegal,
                        gat,
                        format!(
                            "G{} is not allowed inside the finishing shape ns-nf",
                            fmt_code(g)
                        ),
                    )))
                }
            }
        }
        for &(m, mat) in self.words.ms() {
            let call = self.mcode(m).map(|c| c.action);
            if matches!(call, Some(MAction::SubCall | MAction::SubReturn)) {
                return Err(ShapeErr::Here(self.alarm(
                    AlarmKind::MrcIllegal,
                    mat,
                    format!("M{m} is not allowed inside the finishing shape ns-nf"),
                )));
            }
        }
        Ok(blk_mode)
    }

    /// A shape block's end point from `cur` (X a diameter in G08, U/W
    /// incremental), and whether it names X and Z.
    fn shape_end_point(&self, cur: P) -> Result<(P, bool, bool), ShapeErr> {
        // End point.
        let mut t = cur;
        let (mut hx, mut hz) = (false, false);
        let half = if self.modal.diameter.means { 0.5 } else { 1.0 };
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
        Ok((t, hx, hz))
    }

    /// The chamfer / corner R word of a shape G01 (direct drawing input,
    /// 001 p.10), as a corner to cut once the shape is read. `here`: (the
    /// block is N(nf), is N(ns), the segment it ends, its block count).
    fn shape_corner_word(
        &self,
        nf: u32,
        here: (bool, bool, usize, usize),
    ) -> Result<Option<ShapeCorner>, ShapeErr> {
        let (is_last, first, seg, count) = here;
        let Some(w) = [b'C', b'R', b'I', b'K']
            .iter()
            .find_map(|&l| self.words.get(l))
        else {
            return Ok(None);
        };
        if is_last {
            return Err(ShapeErr::Here(self.alarm(
                AlarmKind::MrcEndCorner,
                w.at,
                format!(
                    "the last block N{nf} of the finishing shape ends with a chamfer or corner R"
                ),
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
        Ok(Some(ShapeCorner {
            seg,
            letter,
            amount: self.linear(w),
            word: self.alarm(AlarmKind::CornerConflict, w.at, "").src,
            block: count,
        }))
    }

    /// A chamfer or corner R on shape segment `c.seg` (001 p.10, the same
    /// rules as interp/lathe_chamfer.rs): the segment is shortened and the
    /// corner inserted before the next segment, which starts at C′.
    fn shape_corner(&self, shape: &mut Shape, c: &ShapeCorner, blocks: &[(usize, u32)]) -> R<()> {
        let d = self.cfg.dialect.id;
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
        insert_corner(shape, i, c.letter == b'R', along_z, (len.signum(), s), amt);
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
        if let Err(e) = crate::arc::check_end(s.zx(), e.zx(), c.zx(), self.cfg.arc_tol) {
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
}

/// Shortens shape segment `i` by `amt` before its end and inserts the
/// chamfer (or, `round`, the corner arc) to the next segment's new start.
/// `along_z`: segment `i` moves in Z; `(d1, s)`: the signs of its move and
/// of the next one's.
fn insert_corner(
    shape: &mut Shape,
    i: usize,
    round: bool,
    along_z: bool,
    signs: (f64, f64),
    amt: f64,
) {
    let (d1, s) = signs;
    let seg = shape.segs[i];
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
    let arc = (round).then(|| {
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
    shape.comps.insert(i + 1, None);
    let src = shape.srcs[i];
    shape.srcs.insert(i + 1, src);
}
