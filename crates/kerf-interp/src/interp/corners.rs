//! Chamfer `,C` and corner R `,R` (000 §4.3.1-4.3.2, Fanuc): the one-block
//! look-ahead that joins a G01/G02/G03 move to the next move in the plane.
//!
//! A move carrying `,C`/`,R` is not emitted when its block runs: it is held
//! as a [`Pending`] path from its start to the virtual corner (its
//! programmed end point), and the current position moves to the corner so
//! that the next block's incremental words and I/J/K read from there. When
//! the next move in the plane arrives, the held path is emitted trimmed,
//! then the chamfer or corner arc (at the held block's feed, attributed to
//! that block), then the events kept back in between, then the new move
//! from the trimmed point (an arc keeps its centre). The geometry is in
//! `crate::corner`.
//!
//! Blocks without a move (M codes, comments, macro statements) may stand in
//! between; their events come after the corner. G00, another plane, a move
//! off the plane, G04/G27-G30/G53/G92, a call or return, or the end of the
//! program after a held move are an alarm at its `,C`/`,R` word, as is a
//! change of coordinate system or tool in between.

use super::motion::Speed;
use super::*;
use crate::corner::{self, Corner, CornerError, Seg, EPS};

/// A move carrying `,C`/`,R`, held until the next move is known.
pub(crate) struct Pending {
    /// `,C` (true) or `,R`.
    chamfer: bool,
    /// Chamfer distance or corner radius, mm.
    size: f64,
    /// The path in the plane, from its start (already trimmed when the
    /// block before had a corner too) to the virtual corner.
    seg: Seg,
    /// Start and end points, program coordinates (the axes outside the
    /// plane do not move).
    start: Pos,
    end: Pos,
    plane: Plane,
    /// The feed of the block: the trimmed path and the corner use it.
    feed: Feed,
    /// The block (source of its events), its `,C`/`,R` word and its motion
    /// word (positions of alarms).
    src: SrcRef,
    word: SrcRef,
    motion: SrcRef,
    /// Origin of program coordinates and tool when the block ran.
    origin: Pos,
    tool: u32,
    /// Events made while the move is held, handed out after the corner.
    held: Vec<Event>,
}

impl Pending {
    /// Keeps back an event made while the move is held.
    pub(super) fn hold(&mut self, e: Event) {
        self.held.push(e);
    }

    fn letter(&self) -> char {
        if self.chamfer {
            'C'
        } else {
            'R'
        }
    }
}

impl Interp {
    /// The block's move when a move is held or the block carries `,C`/`,R`.
    pub(super) fn corner_motion(&mut self, mode: MotionMode, tw: Pos, any: bool, at: u32) -> R<()> {
        let word = self.corner_word()?;
        let circle = matches!(mode, MotionMode::ArcCw | MotionMode::ArcCcw)
            && [b'I', b'J', b'K'].iter().any(|&l| self.words.has(l));
        let moves = any || circle;
        let cutting = matches!(
            mode,
            MotionMode::Linear | MotionMode::ArcCw | MotionMode::ArcCcw
        );
        if self.common.corner.is_some() {
            if !cutting {
                let what = format!("G{}", fmt_code(self.modal.motion.code10));
                return Err(self.corner_broken(&what));
            }
            if !moves {
                // A block without a move keeps the look-ahead open.
                if let Some((_, w)) = word {
                    return Err(self.corner_no_move(w, "a block without a move"));
                }
                return Ok(());
            }
            self.corner_next(mode, tw, any, at, word)
        } else {
            let Some((chamfer, w)) = word else {
                // ,C0 / ,R0: no corner.
                return self.plain_motion(mode, tw, any, at);
            };
            if !cutting {
                let what = format!("a G{} block", fmt_code(self.modal.motion.code10));
                return Err(self.corner_no_move(w, &what));
            }
            if !moves {
                return Err(self.corner_no_move(w, "a block without a move"));
            }
            let Some(seg) = self.plane_path(mode, tw, any, at)? else {
                return Err(self.corner_no_move(w, "a block that does not move in the plane alone"));
            };
            let feed = self.feed(at)?;
            self.corner_hold(seg, tw, chamfer, w, feed, at)
        }
    }

    /// The next move after a held one: emits the held path trimmed, the
    /// corner, the events kept back, then this move from the trimmed point
    /// (or holds it in turn when it carries `,C`/`,R`).
    fn corner_next(
        &mut self,
        mode: MotionMode,
        tw: Pos,
        any: bool,
        at: u32,
        word: Option<(bool, WVal)>,
    ) -> R<()> {
        let Some(p) = self.common.corner.as_deref() else {
            return self.plain_motion(mode, tw, any, at);
        };
        if p.plane != self.modal.plane.means {
            return Err(self.corner_broken("a move in another plane"));
        }
        if p.origin != self.frames.prog_origin() {
            return Err(
                self.corner_conflict(p, "the coordinate system or tool length offset changed")
            );
        }
        if p.tool != self.tool.number {
            return Err(self.corner_conflict(p, "the tool changed"));
        }
        let Some(seg2) = self.plane_path(mode, tw, any, at)? else {
            return Err(self.corner_broken("a block that does not move in the plane alone"));
        };
        let Some(p) = self.common.corner.take() else {
            return self.plain_motion(mode, tw, any, at);
        };
        let found = if p.chamfer {
            corner::chamfer(&p.seg, &seg2, p.size)
        } else {
            corner::round(&p.seg, &seg2, p.size)
        };
        let c = match found {
            Ok(c) => c,
            Err(e) => {
                let (k, msg) = (p.letter(), fmt_num(p.size));
                let why = match e {
                    CornerError::TooLarge => {
                        format!(",{k}{msg} does not fit on the two paths at this corner")
                    }
                    CornerError::NoCorner => {
                        format!(",{k}{msg}: the paths meet without a corner (tangent or reversing)")
                    }
                };
                return Err(AlarmKind::CornerTooLarge.at(self.cfg.dialect.id, p.word, why));
            }
        };
        // The held block's part, attributed to it; its alarms (travel)
        // point at its motion.
        let here = std::mem::replace(&mut self.prog.cur, p.src);
        let r = self.corner_emit(&p, &c);
        self.prog.cur = here;
        r.map_err(|mut a| {
            a.src = p.motion;
            a
        })?;
        self.queue.extend(p.held);
        // This block's move, from the trimmed start.
        let seg2 = seg2.with_start(c.p2());
        if let Some((chamfer, w)) = word {
            let feed = self.feed(at)?;
            return self.corner_hold(seg2, tw, chamfer, w, feed, at);
        }
        let (s, e) = (seg2.start(), seg2.end());
        if (s.0 - e.0).hypot(s.1 - e.1) < EPS {
            return Ok(()); // used up by the corner
        }
        match seg2 {
            Seg::Line { .. } => self.move_line(false, tw, at),
            Seg::Arc { c, ccw, .. } => {
                let feed = self.feed(at)?;
                let start = self.plane_point(tw, s);
                self.arc_to(start, tw, c, ccw, feed, at)
            }
        }
    }

    /// Holds the block's move (`seg`, from the current position to `tw`).
    fn corner_hold(
        &mut self,
        seg: Seg,
        tw: Pos,
        chamfer: bool,
        w: WVal,
        feed: Feed,
        at: u32,
    ) -> R<()> {
        let size = self.linear(w);
        let start = self.prog_pos();
        let word = self.src_at(w.at);
        let motion = self.src_at(at);
        let pending = Pending {
            chamfer,
            size,
            seg,
            start,
            end: tw,
            plane: self.modal.plane.means,
            feed,
            src: self.prog.cur,
            word,
            motion,
            origin: self.frames.prog_origin(),
            tool: self.tool.number,
            held: Vec::new(),
        };
        // The next block reads from the virtual corner.
        self.place_at(&tw);
        self.common.corner = Some(Box::new(pending));
        Ok(())
    }

    /// Emits the held path up to the corner's first point, then the
    /// chamfer or corner arc.
    fn corner_emit(&mut self, p: &Pending, c: &Corner) -> R<()> {
        let p1 = self.plane_point(p.end, c.p1());
        let s = p.seg.start();
        let q = c.p1();
        if (s.0 - q.0).hypot(s.1 - q.1) >= EPS {
            match p.seg {
                Seg::Line { .. } => self.line_to(p1, Speed::Feed(p.feed), 0)?,
                Seg::Arc { c: centre, ccw, .. } => {
                    self.arc_to(p.start, p1, centre, ccw, p.feed, 0)?
                }
            }
        }
        let p2 = self.plane_point(p.end, c.p2());
        match *c {
            Corner::Chamfer { .. } => self.line_to(p2, Speed::Feed(p.feed), 0),
            Corner::Round { c: centre, ccw, .. } => self.arc_to(p1, p2, centre, ccw, p.feed, 0),
        }
    }

    /// The block's move from the current position to `tw` as a path in the
    /// plane; None when it does not move in the plane or moves another axis.
    fn plane_path(&mut self, mode: MotionMode, tw: Pos, any: bool, at: u32) -> R<Option<Seg>> {
        let (a1, a2, _) = self.modal.plane.means.axes();
        let cur = self.prog_pos();
        if (0..NAXES).any(|i| i != a1 && i != a2 && (tw[i] - cur[i]).abs() > 1e-9) {
            return Ok(None);
        }
        let (a, b) = ((cur[a1], cur[a2]), (tw[a1], tw[a2]));
        let chord = (a.0 - b.0).hypot(a.1 - b.1);
        if mode == MotionMode::Linear {
            return Ok((chord >= EPS).then_some(Seg::Line { a, b }));
        }
        let ijk = [b'I', b'J', b'K'].iter().any(|&l| self.words.has(l));
        if chord < EPS && !ijk {
            return Ok(None); // R with the end at the start: no arc
        }
        let ccw = mode == MotionMode::ArcCcw;
        Ok(self
            .arc_center(tw, any, ccw, at)?
            .map(|c| Seg::Arc { a, b, c, ccw }))
    }

    /// `p` with its plane coordinates replaced by `uv`.
    fn plane_point(&self, p: Pos, uv: (f64, f64)) -> Pos {
        let (a1, a2, _) = self.modal.plane.means.axes();
        let mut q = p;
        q[a1] = uv.0;
        q[a2] = uv.1;
        q
    }

    /// The block's `,C`/`,R` (chamfer?, word), None for none or a zero
    /// value; a negative value is an alarm.
    pub(super) fn corner_word(&self) -> R<Option<(bool, WVal)>> {
        let Some((chamfer, w)) = self.words.corner() else {
            return Ok(None);
        };
        if w.v < 0.0 {
            return Err(self.alarm(
                AlarmKind::OutOfRange,
                w.at,
                format!(",{} must not be negative", if chamfer { 'C' } else { 'R' }),
            ));
        }
        Ok((w.v > 0.0).then_some((chamfer, w)))
    }

    /// Refuses a block that cannot follow a held move, or carry `,C`/`,R`:
    /// one-shot G codes other than G09/G10 (G04, G27-G30, G53, G92 …),
    /// M98/M99.
    pub(super) fn corner_gate(&self, one_shot: &[(u16, u32)], transfer: Option<MAction>) -> R<()> {
        use crate::dialect::meaning::OneShot::{DataSetting, ExactStop, FrameData};
        let allowed = |c: u16| {
            matches!(
                self.means_of(c),
                Some(Means::OneShot(ExactStop | FrameData | DataSetting))
            )
        };
        let what = if let Some(&(c, _)) = one_shot.iter().find(|g| !allowed(g.0)) {
            format!("G{}", fmt_code(c))
        } else {
            match transfer {
                Some(MAction::SubCall) => "M98".to_string(),
                Some(_) => "M99".to_string(),
                None => return Ok(()),
            }
        };
        if self.common.corner.is_some() {
            return Err(self.corner_broken(&what));
        }
        match self.words.corner() {
            Some((_, w)) => Err(self.corner_no_move(w, &format!("a {what} block"))),
            None => Ok(()),
        }
    }

    /// An alarm when a move is held: `what` (a call, a return) cannot come
    /// before the next move.
    pub(super) fn corner_open(&self, what: &str) -> R<()> {
        if self.common.corner.is_some() {
            return Err(self.corner_broken(what));
        }
        Ok(())
    }

    /// The alarm for a held move not followed by a move in its plane: at
    /// its `,C`/`,R` word.
    pub(super) fn corner_broken(&self, what: &str) -> Alarm {
        let Some(p) = self.common.corner.as_deref() else {
            return self.alarm(AlarmKind::CornerNoMove, 0, what);
        };
        AlarmKind::CornerNoMove.at(
            self.cfg.dialect.id,
            p.word,
            format!(
                "{what} after a ,{} block: the next move must be G01/G02/G03 in the same plane",
                p.letter()
            ),
        )
    }

    fn corner_conflict(&self, p: &Pending, why: &str) -> Alarm {
        AlarmKind::CornerConflict.at(
            self.cfg.dialect.id,
            p.word,
            format!("{why} between a ,{} block and its next move", p.letter()),
        )
    }

    pub(super) fn corner_no_move(&self, w: WVal, what: &str) -> Alarm {
        self.alarm(
            AlarmKind::CornerNoMove,
            w.at,
            format!(",C/,R in {what}: it needs a G01/G02/G03 move in the plane"),
        )
    }

    /// The source position of a byte of the current block.
    fn src_at(&self, at: u32) -> SrcRef {
        let (line, col) = self.prog.raw.line_col(at as usize);
        SrcRef {
            file: self.prog.cur.file,
            line,
            col,
        }
    }
}
