//! PUMA direct chamfer and corner R (001 p.10 "AUTO CHAMFERING C AND
//! CORNER R"; fanuc-semantics §2.5 (a)): a G01 along one axis with
//! `I±i` (Z move, chamfer toward X), `K±k` (X move, chamfer toward Z),
//! `R±r` (corner R) or `C c` ends at the sharp corner B; the tool cuts
//! the 45° chamfer or the tangent arc and stops at C′ on the next block's
//! path. The sign of I/K/R gives the direction of the next move; C has no
//! sign and takes it from the next block. The next block must be a G01
//! along the other axis, at least as long as the chamfer, and its
//! incremental words count from B (001 note 2).
//!
//! The next block is read ahead once (its text parsed and its words
//! evaluated, then the source put back), as the control does, so the
//! errors of 001 note 3 are found before the corner is cut.

use super::*;

/// What the block after a chamfer block does.
struct Next {
    /// G code of its motion (the modal one when it has none).
    mode: u16,
    /// Its X and Z words.
    x: Option<Coord>,
    z: Option<Coord>,
    /// Its line (alarms about it are positioned at its start).
    line: u32,
}

impl Interp {
    /// The block is a PUMA G01 with a chamfer or corner-R word.
    #[inline]
    pub(super) fn ddi_words(&self) -> bool {
        self.words.has(b'C') || self.words.has(b'I') || self.words.has(b'K') || self.words.has(b'R')
    }

    /// The base for the incremental words of the block after a chamfer
    /// block: the corner B rather than the tool's C′ (001 note 2).
    pub(super) fn ddi_target(&mut self) -> R<(Pos, bool)> {
        match self.puma.ddi_base.take() {
            None => self.target(),
            Some(b) => {
                let b = self.to_machine(&b);
                let real = self.place_machine(b);
                let r = self.target();
                self.place_machine(real);
                r
            }
        }
    }

    /// G01 with I/K/R/C (see the module documentation).
    pub(super) fn ddi_motion(&mut self, tw: Pos, at: u32) -> R<()> {
        let xi = Axis::X as usize;
        let zi = Axis::Z as usize;
        let cur = self.prog_pos();
        let words: Vec<(u8, WVal)> = [b'I', b'K', b'R', b'C']
            .iter()
            .filter_map(|&l| self.words.get(l).map(|w| (l, w)))
            .collect();
        if words.len() > 1 {
            return Err(self.alarm(
                AlarmKind::CornerConflict,
                words[1].1.at,
                "two of I, K, R, C in one block (001 p.10 note 3)",
            ));
        }
        let (l, w) = words[0];
        let dx = tw[xi] - cur[xi];
        let dz = tw[zi] - cur[zi];
        let moves_x = dx.abs() > 1e-9 || self.words.has(b'X') || self.words.has(b'U');
        let moves_z = dz.abs() > 1e-9 || self.words.has(b'Z') || self.words.has(b'W');
        if moves_x && moves_z {
            return Err(self.alarm(
                AlarmKind::ChamferTaper,
                w.at,
                format!("{} with a move in both X and Z: chamfer and corner R need a move along one axis", l as char),
            ));
        }
        // Along Z the next move is in X (I); along X it is in Z (K).
        let along_z = moves_z;
        if (l == b'I' && !along_z) || (l == b'K' && along_z) {
            return Err(self.alarm(
                AlarmKind::CornerConflict,
                w.at,
                format!(
                    "{} with a move along {}: I goes with Z, K with X (001 p.10 note 3)",
                    l as char,
                    if along_z { "Z" } else { "X" }
                ),
            ));
        }
        let amount = self.linear(w);
        if amount == 0.0 {
            return self.move_line(false, tw, at);
        }
        let len = if along_z { dz } else { dx };
        if len.abs() < 1e-9 {
            return Err(self.alarm(
                AlarmKind::CornerNoMove,
                w.at,
                "chamfer or corner R on a block that does not move",
            ));
        }
        let (s, c) = self.ddi_next_move(tw, along_z, (l, w), len)?;
        self.ddi_corner((cur, tw), along_z, (len, s, c), l == b'R', at)?;
        self.puma.ddi_base = Some(tw);
        Ok(())
    }

    /// The next block of a chamfer / corner R block, read ahead and
    /// checked (001 p.10): G01 along the other axis, toward the side the
    /// word's sign (C: the move's) gives, not shorter than the corner.
    /// Returns that side (±1) and the corner's size.
    fn ddi_next_move(
        &mut self,
        tw: Pos,
        along_z: bool,
        word: (u8, WVal),
        len: f64,
    ) -> R<(f64, f64)> {
        let (xi, zi) = (Axis::X as usize, Axis::Z as usize);
        let (l, w) = word;
        let amount = self.linear(w);
        let next = self.peek_next()?;
        let Some(next) = next else {
            return Err(self.alarm(
                AlarmKind::ChamferNextBlock,
                w.at,
                "chamfer or corner R without a next block",
            ));
        };
        let (na, nb) = if along_z {
            (next.x, next.z)
        } else {
            (next.z, next.x)
        };
        let bad_next = |me: &Self, kind: AlarmKind, msg: String| {
            let mut a = me.alarm(kind, w.at, msg);
            a.src.line = next.line;
            a.src.col = 1;
            a
        };
        if next.mode != 10 {
            return Err(bad_next(
                self,
                AlarmKind::ChamferNextBlock,
                format!(
                    "the block after a chamfer or corner R must be G01 (it is G{})",
                    fmt_code(next.mode)
                ),
            ));
        }
        if nb.is_some() {
            let (kind, msg) = if na.is_some() {
                (
                    AlarmKind::ChamferTaper,
                    "the block after a chamfer or corner R moves both X and Z",
                )
            } else {
                (
                    AlarmKind::ChamferNextBlock,
                    "the block after a chamfer or corner R must move along the other axis",
                )
            };
            return Err(bad_next(self, kind, msg.into()));
        }
        // End of the next move, measured from B.
        let b_other = if along_z { tw[xi] } else { tw[zi] };
        let Some(n_end) = na.map(|v| v.resolve(b_other)) else {
            return Err(bad_next(
                self,
                AlarmKind::ChamferNextBlock,
                "the block after a chamfer or corner R does not move along the other axis".into(),
            ));
        };
        let nlen = n_end - b_other;
        let s = if l == b'C' {
            nlen.signum()
        } else {
            amount.signum()
        };
        let c = amount.abs();
        if nlen.abs() < 1e-9 || nlen.signum() != s {
            return Err(bad_next(
                self,
                AlarmKind::ChamferNextBlock,
                format!(
                    "the block after {}{} must move toward {}{}",
                    l as char,
                    fmt_num(w.v),
                    if s > 0.0 { "+" } else { "-" },
                    if along_z { "X" } else { "Z" }
                ),
            ));
        }
        if c > len.abs() + 1e-9 || c > nlen.abs() + 1e-9 {
            let short_next = c > nlen.abs() + 1e-9;
            let msg = format!(
                "chamfer / corner R {} is longer than the {} move ({})",
                fmt_num(c),
                if short_next { "next" } else { "block's" },
                fmt_num(if short_next { nlen.abs() } else { len.abs() })
            );
            return Err(if short_next {
                bad_next(self, AlarmKind::CornerTooLarge, msg)
            } else {
                self.alarm(AlarmKind::CornerTooLarge, w.at, msg)
            });
        }
        Ok((s, c))
    }

    /// The shortened move to the pre-corner point and the chamfer (or, with
    /// `round`, the corner arc) to C′, for the block from `ends.0` to
    /// `ends.1`; `sizes`: (the block's move along its axis, the side of
    /// the next move, the corner's size).
    fn ddi_corner(
        &mut self,
        ends: (Pos, Pos),
        along_z: bool,
        sizes: (f64, f64, f64),
        round: bool,
        at: u32,
    ) -> R<()> {
        let (xi, zi) = (Axis::X as usize, Axis::Z as usize);
        let (cur, tw) = ends;
        let (len, s, c) = sizes;
        // Pre-corner point, C′, and the moves.
        let (a1, a2) = if along_z { (zi, xi) } else { (xi, zi) };
        let d1 = len.signum();
        let mut pre = tw;
        pre[a1] -= d1 * c;
        let mut post = tw;
        post[a2] += s * c;
        let feed = self.feed(at)?;
        let arc = round.then(|| {
            // Centre: c from both the block's line and the next one.
            let mut cen = pre;
            cen[a2] += s * c;
            // Turn from the block's direction to the next one in the ZX
            // plane (u = Z, v = X): left turn = CCW = G03.
            let (u1, v1) = if along_z { (d1, 0.0) } else { (0.0, d1) };
            let (u2, v2) = if along_z { (0.0, s) } else { (s, 0.0) };
            (cen, u1 * v2 - v1 * u2 > 0.0)
        });
        // With nose radius compensation the corner is part of the
        // programmed contour: the shortened move and the corner are
        // compensated like any other paths (interp/comp.rs), the next
        // block joins the corner.
        let zx = |q: &Pos| crate::turning::p(q[xi], q[zi]);
        let piece = |from: &Pos, to: &Pos, arc: Option<(Pos, bool)>| crate::turning::Seg {
            from: zx(from),
            to: zx(to),
            arc: arc.map(|(c, ccw)| (zx(&c), ccw)),
        };
        if self.common.comp.is_some() {
            let src = self.src_here(at);
            let sp = motion::Speed::Feed(feed);
            self.comp_shape_seg(&piece(&cur, &pre, None), false, sp, at, src)?;
        } else {
            self.line_to(pre, motion::Speed::Feed(feed), at)?;
        }
        if self.common.comp.is_some() {
            let src = self.src_here(at);
            let sp = motion::Speed::Feed(feed);
            self.comp_shape_seg(&piece(&pre, &post, arc), false, sp, at, src)?;
        } else if let Some((cen, ccw)) = arc {
            let start = self.prog_pos();
            self.arc_to(start, post, (cen[zi], cen[xi]), ccw, feed, at)?;
        } else {
            self.line_to(post, motion::Speed::Feed(feed), at)?;
        }
        Ok(())
    }

    /// Reads the next block with words (skipping empty ones) and puts the
    /// source back. None at the end of the program.
    fn peek_next(&mut self) -> R<Option<Next>> {
        let back = self.prog.src.as_ref().expect("loaded").tell();
        let saved_raw = std::mem::take(&mut self.prog.raw);
        let saved_block = std::mem::take(&mut self.prog.block);
        let saved_words = self.words.clone();
        let r = self.peek_blocks();
        self.prog.raw = saved_raw;
        self.prog.block = saved_block;
        self.words = saved_words;
        self.seek(back)?;
        r
    }

    fn peek_blocks(&mut self) -> R<Option<Next>> {
        for _ in 0..64 {
            let src = self.prog.src.as_mut().expect("loaded");
            match src.next_block(&mut self.prog.raw) {
                Ok(true) => {}
                _ => return Ok(None),
            }
            self.parse_raw()?;
            if self.prog.block.percent || self.prog.block.program.is_some() {
                return Ok(None);
            }
            let mut nwords = self.prog.block.words.len();
            let mut skip = false;
            for &(idx, mask) in &self.prog.block.deletes {
                if mask & self.settings.block_skip != 0 {
                    skip |= idx == 0;
                    nwords = nwords.min(idx as usize);
                    break;
                }
            }
            if skip {
                continue;
            }
            if self.prog.block.stmt.is_some() {
                return Err(self.alarm(
                    AlarmKind::ChamferNextBlock,
                    self.prog.block.stmt_at,
                    "a macro statement after a chamfer or corner R block (the next block must be a G01 move)",
                ));
            }
            if nwords == 0 {
                continue;
            }
            self.collect(nwords)?;
            // The block's last motion code other than G01 (G01 if none).
            let mut mode = 10;
            for &(g, _) in self.words.gs() {
                if let Some(Means::Motion(m)) = self.means_of(g) {
                    if m != MotionMode::Linear {
                        mode = g;
                    }
                }
            }
            let half = if self.modal.diameter.means { 0.5 } else { 1.0 };
            let ax = |me: &Self, abs: u8, inc: u8, k: f64| {
                if let Some(w) = me.words.get(abs) {
                    Some(Coord::Abs(me.linear(w) * k))
                } else {
                    me.words.get(inc).map(|w| Coord::Inc(me.linear(w) * k))
                }
            };
            return Ok(Some(Next {
                mode,
                x: ax(self, b'X', b'U', half),
                z: ax(self, b'Z', b'W', 1.0),
                line: self.prog.raw.mark.line,
            }));
        }
        Ok(None)
    }
}

/// An axis word of the next block.
#[derive(Clone, Copy, Debug)]
enum Coord {
    Abs(f64),
    Inc(f64),
}

impl Coord {
    fn resolve(self, base: f64) -> f64 {
        match self {
            Coord::Abs(v) => v,
            Coord::Inc(d) => base + d,
        }
    }
}
