//! Cutter radius compensation C (HX, Hurco: G40/G41/G42 with D, G39) and
//! tool nose radius compensation (lathes: G40/G41/G42 with the nose
//! radius and tip of the T code's offset): the glue that holds blocks.
//!
//! A move in offset mode is not emitted when its block runs: it is held
//! ([`Held`]: its programmed path in the plane, the compensated start
//! already decided, its speed, source and the events made after it) until
//! the next move in the plane is known, because the vector at its end
//! depends on that move (000 §13.2.2, fanuc-semantics §4). The next move
//! emits it up to the corner (`crate::comp::corner`, `startup`, `cancel`),
//! then the events kept back (blocks without motion in the plane are
//! executed at the corner; an off-plane move takes the corner's plane
//! point), then the corner's extra pieces, and is held in turn. More
//! blocks without a move in the plane than the profile allows
//! (`comp_idle_blocks`: HX 2, PUMA 1, Hurco 2) break the look-ahead: the
//! held move ends on the vector perpendicular to its end and the next move
//! starts slanted from there. The interpreter's position stays the
//! programmed (uncompensated) point, so incremental words and I/J/K read
//! from it; only the emitted events carry the compensated point.

use super::motion::Speed;
use super::*;
use crate::comp::{self, CompError, CornerOpt, Join, Piece, Seg, P};
use crate::dialect::meaning::OneShot;

/// A move held until the next one is known.
pub(crate) struct Held {
    /// The programmed path in the plane.
    seg: Seg,
    /// Programmed start and end (all axes).
    start: Pos,
    end: Pos,
    /// Compensated start in the plane (nose centre path on lathes).
    cstart: P,
    /// Rapid or the block's feed.
    speed: Speed,
    /// The signed offset of the block (+ left).
    r: f64,
    /// Lathe: imaginary tip shift added to the emitted points.
    tip: P,
    /// The start-up block (from the uncompensated point).
    startup: bool,
    /// The block (source of its events) and its motion word.
    src: SrcRef,
    motion: SrcRef,
    /// Events made while the move is held.
    events: Vec<Event>,
    /// The block carries `,C`/`,R`: the corner is cut in the programmed
    /// contour when the next move is known.
    corner: Option<Box<HeldCorner>>,
}

/// A `,C`/`,R` on a held compensated move (000 §4.3): the corner goes into
/// the programmed contour, then is compensated like any other path.
pub(super) struct HeldCorner {
    chamfer: bool,
    size: f64,
    /// The block's path in program coordinates (the corner is cut there,
    /// then transformed with the block).
    seg: Seg,
    /// The transforms of the block: the next move must have the same.
    xf: crate::xform::Xform,
    /// The `,C`/`,R` word.
    word: SrcRef,
}

/// A move in the plane handed to [`Interp::comp_path`].
pub(super) struct CompPath {
    /// Motion mode: G00-G03.
    pub(super) mode: MotionMode,
    /// The path in the plane, transformed, and in program coordinates.
    pub(super) seg: Seg,
    pub(super) seg_p: Seg,
    /// Start and end (all axes): program, and transformed.
    pub(super) cur: Pos,
    pub(super) cur_t: Pos,
    pub(super) tw: Pos,
    pub(super) tw_t: Pos,
    /// The move leaves the plane too.
    pub(super) off_plane: bool,
    pub(super) corner: Option<Box<HeldCorner>>,
    pub(super) speed: Speed,
    /// The motion word in the current block (emission alarms).
    pub(super) at: u32,
    /// Where geometry alarms of this path point.
    pub(super) motion: SrcRef,
}

/// Compensation state; `CommonFeatures::comp` is None when compensation is
/// cancelled and nothing is left over (so plain programs pay one test).
pub(crate) struct CompState {
    /// G41/G42 in force.
    on: bool,
    /// Signed offset for the blocks from now on (+ left of travel).
    r: f64,
    /// +1 for G41, −1 for G42.
    side: f64,
    /// Lathe: imaginary tip shift for the blocks from now on.
    tip: P,
    /// Plane of the offset mode.
    plane: Plane,
    /// The next move in the plane is a start-up.
    startup: bool,
    /// Emitted point − programmed point when nothing is held (after a
    /// broken look-ahead, G92, or the end of a cancel).
    vec: P,
    held: Option<Held>,
    /// Blocks without a move in the plane since the held move.
    idle: u32,
    /// The current block moved in the plane.
    moved: bool,
    /// G39 before the next move: the direction of its end vector.
    g39: Option<Option<P>>,
    /// G40 with I/J/K in this block: the direction.
    ij: Option<P>,
    /// Start-up / cancel type B.
    type_b: bool,
    /// Blocks without a move in the plane the look-ahead crosses.
    limit: u32,
    /// Hurco "circular joining": outer corners get an arc.
    circular: bool,
    /// A spare event buffer (reused between held moves).
    spare: Vec<Event>,
}

impl CompState {
    /// G41/G42 in force.
    pub(crate) fn on(&self) -> bool {
        self.on
    }
}

fn padd(a: P, b: P) -> P {
    (a.0 + b.0, a.1 + b.1)
}
fn psub(a: P, b: P) -> P {
    (a.0 - b.0, a.1 - b.1)
}

impl Interp {
    fn comp_new(&self) -> CompState {
        let cp = &self.cfg.dialect.caps.comp;
        let (key, default, b) = cp.type_b;
        let type_b = self.cfg.profile.param(key, default) == b;
        let limit = self.cfg.profile.param("comp_idle_blocks", cp.idle_blocks);
        let circular =
            cp.circular_joining && self.cfg.profile.param("comp_circular_joining", 0.0) == 1.0;
        CompState {
            on: false,
            r: 0.0,
            side: 1.0,
            tip: (0.0, 0.0),
            plane: self.modal.plane.means,
            startup: false,
            vec: (0.0, 0.0),
            held: None,
            idle: 0,
            moved: false,
            g39: None,
            ij: None,
            type_b,
            limit: limit.clamp(0.0, 16.0) as u32,
            circular,
            spare: Vec::new(),
        }
    }

    /// Keeps back an event made while a compensated move is held; gives
    /// the event back when nothing is held.
    pub(super) fn comp_hold_event(&mut self, e: Event) -> Option<Event> {
        match self.common.comp.as_mut().and_then(|c| c.held.as_mut()) {
            Some(h) => {
                h.events.push(e);
                None
            }
            None => Some(e),
        }
    }

    /// The offset value and tip shift in force: D on mills, the T code's
    /// nose radius and tip on lathes.
    fn comp_value(&self) -> (f64, P) {
        match self.cfg.profile.kind {
            MachineKind::Mill => (self.offsets.d(self.sys.d.max(0.0) as usize), (0.0, 0.0)),
            MachineKind::Lathe => {
                let o = self.offsets.lathe(self.tool.offset as usize);
                let r = o.total_r();
                let t = comp::tip_vector(o.tip);
                (r, (t.0 * r, t.1 * r))
            }
        }
    }

    /// The block's D (mills: an offset number), and G41/G42 with a
    /// reference return or G53, which cannot start the offset (000
    /// §13.2.1: "[G00/G01] X_ Y_ G41"; G40 with them is a cancel: allowed).
    fn comp_check_words(&self, one_shot: &[(u16, u32)]) -> R<()> {
        if self.cfg.profile.kind == MachineKind::Mill {
            if let Some(dw) = self.words.get(b'D') {
                if dw.v < 0.0 || dw.v.fract() != 0.0 || !self.offsets.valid(dw.v as usize) {
                    return Err(self.alarm(
                        AlarmKind::OutOfRange,
                        dw.at,
                        format!(
                            "D{} is not an offset number (D00-D{})",
                            fmt_num(dw.v),
                            self.offsets.count()
                        ),
                    ));
                }
            }
        }
        let no_startup = |g: &&(u16, u32)| {
            matches!(
                self.gcode(g.0).map(|c| c.means),
                Some(Means::OneShot(
                    OneShot::RefReturn(_) | OneShot::MachineCoords
                ))
            )
        };
        if let Some(&(g, _)) = one_shot.iter().find(no_startup) {
            let on = |m| matches!(m, Means::CutterComp(CompSide::Left | CompSide::Right));
            if let Some((c, at)) = self.block_g(on) {
                return Err(self.alarm(
                    AlarmKind::CompArc,
                    at,
                    format!(
                        "G{} in a G{} block: cutter compensation starts in a G00/G01 move",
                        fmt_code(c),
                        fmt_code(g)
                    ),
                ));
            }
        }
        Ok(())
    }

    /// The block's compensation codes (G39/G40/G41/G42, D), run before its
    /// one-shot codes. `special`: the block moves otherwise than by
    /// G00-G03 (G28-G30, G53, cycles, G45-G48, G31); `setting`: G92/G50.
    /// True when the block is a G39 (no move of its own).
    pub(super) fn comp_codes(
        &mut self,
        one_shot: &[(u16, u32)],
        special: bool,
        setting: bool,
    ) -> R<bool> {
        self.comp_check_words(one_shot)?;
        let mode = self.modal.cutter_comp.means;
        let g39 = one_shot
            .iter()
            .find(|g| self.gcode(g.0).map(|c| c.means) == Some(Means::OneShot(OneShot::CompCorner)))
            .map(|g| g.1);
        if self.common.comp.is_none() {
            if mode == CompSide::Off {
                if let Some(at) = g39 {
                    return Err(self.alarm(
                        AlarmKind::CompG39,
                        at,
                        "G39 outside cutter compensation (G41/G42) mode",
                    ));
                }
                return Ok(false);
            }
            self.common.comp = Some(Box::new(self.comp_new()));
        }
        let plane = self.modal.plane.means;
        let (on, cplane) = {
            let c = self.common.comp.as_deref().expect("set");
            (c.on, c.plane)
        };
        if on && plane != cplane {
            let at = self
                .block_g(|m| matches!(m, Means::Plane(_)))
                .map_or(0, |g| g.1);
            return Err(self.alarm(
                AlarmKind::CompPlane,
                at,
                "plane change (G17/G18/G19) in cutter compensation mode: cancel with G40 first",
            ));
        }
        // Moves other than G00-G03 break the look-ahead: the held move
        // ends on its perpendicular vector. G92 keeps the vector; G28-G30,
        // G53 and the cycles cancel it until the next move (000 §13.2.2
        // figures).
        if special || setting {
            self.comp_break()?;
            let c = self.common.comp.as_deref_mut().expect("set");
            if !setting {
                c.vec = (0.0, 0.0);
                c.startup = c.on;
            }
        }
        let (a1, a2, _) = plane.axes();
        let ijk = |me: &Self| -> Option<P> {
            let l = [b'I', b'J', b'K'];
            let v = |i: usize| me.words.get(l[i.min(2)]).map(|w| me.linear(w));
            let (u, w) = (v(a1), v(a2));
            (u.is_some() || w.is_some()).then(|| (u.unwrap_or(0.0), w.unwrap_or(0.0)))
        };
        let dir = if mode == CompSide::Off {
            ijk(self).map(|d| self.xf_dir(d))
        } else {
            None
        };
        self.comp_set_mode(mode, dir);
        if let Some(at) = g39 {
            let c = self.common.comp.as_deref().expect("set");
            if !c.on || c.held.is_none() || c.held.as_ref().is_some_and(|h| h.startup) {
                return Err(self.alarm(
                    AlarmKind::CompG39,
                    at,
                    "G39 in a start-up or cancel block: it needs a compensated move before it",
                ));
            }
            let dir = match ijk(self) {
                Some(d) => Some(d),
                None => {
                    let (tw, any) = self.target()?;
                    let cur = self.prog_pos();
                    any.then(|| (tw[a1] - cur[a1], tw[a2] - cur[a2]))
                        .filter(|d| d.0.hypot(d.1) > 1e-9)
                }
            }
            .map(|d| self.xf_dir(d));
            self.common.comp.as_deref_mut().expect("set").g39 = Some(dir);
            return Ok(true);
        }
        Ok(false)
    }

    /// G40 (`dir`: its I/J/K direction), G41 or G42 in force from now on
    /// (the state exists, or is made for G41/G42).
    pub(super) fn comp_set_mode(&mut self, mode: CompSide, dir: Option<P>) {
        if self.common.comp.is_none() {
            if mode == CompSide::Off {
                return;
            }
            self.common.comp = Some(Box::new(self.comp_new()));
        }
        let plane = self.modal.plane.means;
        let (value, tip) = self.comp_value();
        let c = self.common.comp.as_deref_mut().expect("set");
        match mode {
            CompSide::Left | CompSide::Right => {
                let side = if mode == CompSide::Left { 1.0 } else { -1.0 };
                c.side = side;
                c.r = side * value;
                c.tip = if value < 0.0 { (0.0, 0.0) } else { tip };
                if !c.on {
                    c.on = true;
                    c.plane = plane;
                    c.startup = c.held.is_none();
                }
            }
            CompSide::Off => {
                if c.on {
                    c.on = false;
                    c.ij = dir;
                }
            }
        }
    }

    /// The compensation side in force (Off when none is).
    pub(super) fn comp_side(&self) -> CompSide {
        match self.common.comp.as_deref() {
            Some(c) if c.on => {
                if c.side > 0.0 {
                    CompSide::Left
                } else {
                    CompSide::Right
                }
            }
            _ => CompSide::Off,
        }
    }

    /// After a G70-G73 shape run through the compensation: the held move
    /// ends on its perpendicular vector and the next move is a start-up
    /// (the cycle's return to its start point is not compensated).
    pub(super) fn comp_shape_end(&mut self) -> R<()> {
        self.comp_break()?;
        if let Some(c) = self.common.comp.as_deref_mut() {
            c.vec = (0.0, 0.0);
            c.startup = c.on;
        }
        Ok(())
    }

    /// A segment of a G70-G73 finishing shape (ZX points, X a radius) in
    /// compensation, from the current programmed point; alarms of its
    /// geometry point at `motion` (the shape block).
    pub(super) fn comp_shape_seg(
        &mut self,
        seg: &crate::turning::Seg,
        rapid: bool,
        speed: Speed,
        at: u32,
        motion: SrcRef,
    ) -> R<()> {
        let cur = self.zx_full(seg.from);
        let tw = self.zx_full(seg.to);
        let (a1, a2, _) = self.modal.plane.means.axes();
        let (cur_t, tw_t) = (self.xf_point(&cur), self.xf_point(&tw));
        let (sp, ep) = ((cur[a1], cur[a2]), (tw[a1], tw[a2]));
        let (s, e) = ((cur_t[a1], cur_t[a2]), (tw_t[a1], tw_t[a2]));
        let (mode, seg_t, seg_p) = match seg.arc {
            None => (
                if rapid {
                    MotionMode::Rapid
                } else {
                    MotionMode::Linear
                },
                Seg::Line { a: s, b: e },
                Seg::Line { a: sp, b: ep },
            ),
            Some((c, ccw)) => {
                let pc = (c.z, c.x);
                let (_, _, ct, ccw_t) = self.transform_arc(cur, tw, pc, ccw, at)?;
                (
                    if ccw {
                        MotionMode::ArcCcw
                    } else {
                        MotionMode::ArcCw
                    },
                    Seg::Arc {
                        a: s,
                        b: e,
                        c: ct,
                        ccw: ccw_t,
                    },
                    Seg::Arc {
                        a: sp,
                        b: ep,
                        c: pc,
                        ccw,
                    },
                )
            }
        };
        if seg.arc.is_none() && comp::dist(s, e) < comp::EPS {
            return Ok(());
        }
        self.comp_path(CompPath {
            mode,
            seg: seg_t,
            seg_p,
            cur,
            cur_t,
            tw,
            tw_t,
            off_plane: false,
            corner: None,
            speed,
            at,
            motion,
        })
    }

    /// The block's move in compensation (offset mode, or a held move or
    /// vector left over).
    pub(super) fn comp_motion(&mut self, mode: MotionMode, tw: Pos, any: bool, at: u32) -> R<()> {
        if self.common.corner.is_some() {
            // A ,C/,R move held before the compensation started.
            return Err(self.corner_broken("a cutter compensation start-up (G41/G42)"));
        }
        let plane = self.modal.plane.means;
        let (a1, a2, _) = plane.axes();
        let cur = self.prog_pos();
        let arc = matches!(mode, MotionMode::ArcCw | MotionMode::ArcCcw);
        if !matches!(
            mode,
            MotionMode::Rapid | MotionMode::Linear | MotionMode::ArcCw | MotionMode::ArcCcw
        ) {
            // G33 and the like: uncompensated, the look-ahead broken.
            self.comp_break()?;
            let c = self.common.comp.as_deref_mut().expect("comp");
            c.vec = (0.0, 0.0);
            c.startup = c.on;
            return self.plain_motion(mode, tw, any, at);
        }
        // The compensation works on the path after scaling, mirror and
        // rotation (000 §15.4.2): the block's points are mapped with the
        // block's own transform here, so a held move keeps it whatever the
        // next block changes.
        let (cur_t, tw_t) = (self.xf_point(&cur), self.xf_point(&tw));
        let (s, e) = ((cur_t[a1], cur_t[a2]), (tw_t[a1], tw_t[a2]));
        let (sp, ep) = ((cur[a1], cur[a2]), (tw[a1], tw[a2]));
        let seg = if arc {
            let ijk = [b'I', b'J', b'K'].iter().any(|&l| self.words.has(l));
            if comp::dist(s, e) < comp::EPS && !ijk {
                None
            } else {
                match self.arc_center(tw, any, mode == MotionMode::ArcCcw, at)? {
                    None => None,
                    Some(pc) => {
                        let (_, _, c, ccw) =
                            self.transform_arc(cur, tw, pc, mode == MotionMode::ArcCcw, at)?;
                        let prog = Seg::Arc {
                            a: sp,
                            b: ep,
                            c: pc,
                            ccw: mode == MotionMode::ArcCcw,
                        };
                        Some((Seg::Arc { a: s, b: e, c, ccw }, prog))
                    }
                }
            }
        } else {
            (comp::dist(s, e) >= comp::EPS)
                .then_some((Seg::Line { a: s, b: e }, Seg::Line { a: sp, b: ep }))
        };
        let word = self.corner_word()?;
        let Some((seg, seg_p)) = seg else {
            if !any {
                return Ok(());
            }
            if let Some((_, w)) = word {
                return Err(self.corner_no_move(w, "a block that does not move in the plane"));
            }
            return self.comp_offplane(mode, tw, any, at);
        };
        // ,C/,R on this block: a cutting move in the plane alone.
        let off_plane = (0..NAXES).any(|i| i != a1 && i != a2 && (tw[i] - cur[i]).abs() > 1e-9);
        let on_now = self.common.comp.as_deref().is_some_and(|c| c.on);
        let corner = match word {
            None => None,
            Some((_, w)) if mode == MotionMode::Rapid => {
                return Err(self.corner_no_move(w, "a G00 block"))
            }
            Some((_, w)) if !on_now => return Err(self.corner_no_move(w, "a G40 block")),
            Some((_, w)) if off_plane => {
                return Err(self.corner_no_move(w, "a block that does not move in the plane alone"))
            }
            Some((chamfer, w)) => Some(Box::new(HeldCorner {
                chamfer,
                size: self.linear(w),
                seg: seg_p,
                xf: self.frames.xf,
                word: self.src_here(w.at),
            })),
        };
        let speed = if mode == MotionMode::Rapid {
            Speed::Rapid
        } else {
            Speed::Feed(self.feed(at)?)
        };
        let motion = self.src_here(at);
        self.comp_path(CompPath {
            mode,
            seg,
            seg_p,
            cur,
            cur_t,
            tw,
            tw_t,
            off_plane,
            corner,
            speed,
            at,
            motion,
        })
    }

    /// The offset value is read for every move: a D word, a lathe T code
    /// or G10 changing the value in offset mode takes effect at the end of
    /// the next compensated move (000 §13.2.2: that block runs slanted
    /// from the old vector to the new one). Marks the block as moved.
    fn comp_refresh(&mut self) {
        let (value, vtip) = self.comp_value();
        let c = self.common.comp.as_deref_mut().expect("comp");
        if c.on {
            c.r = c.side * value;
            c.tip = if value < 0.0 { (0.0, 0.0) } else { vtip };
        }
        c.moved = true;
        c.idle = 0;
    }

    /// G40: the held move `h` emitted up to its cancel vector, toward the
    /// cancel move `seg` (or the G40 block's I/J/K direction `ij`); returns
    /// where the uncompensated move starts.
    fn comp_cancel_held(&mut self, mut h: Held, ij: Option<P>, seg: &Seg, type_b: bool) -> R<P> {
        let k = h.seg.end();
        let j = if h.startup {
            Join::at(self.comp_geom(comp::perp_end(&h.seg, h.r), h.motion)?)
        } else {
            let e = match ij {
                Some(d) => Seg::Line {
                    a: k,
                    b: padd(k, d),
                },
                None => *seg,
            };
            let j = comp::cancel(&h.seg, &e, h.r, type_b, ij.is_some());
            self.comp_geom(j, h.motion)?
        };
        let htip = h.tip;
        self.comp_flush(&mut h, &j)?;
        Ok(padd(j.start2(), htip))
    }

    /// A move in the plane in compensation: `p.seg` (transformed) is
    /// joined to the held move (or starts up, or cancels) and held in
    /// turn. Used by [`Self::comp_motion`] for a block's move and by the
    /// G70-G73 finishing shape (interp/lathe_mrc.rs) for its segments.
    pub(super) fn comp_path(&mut self, p: CompPath) -> R<()> {
        let CompPath {
            mode,
            mut seg,
            seg_p,
            cur,
            cur_t,
            tw,
            tw_t,
            off_plane,
            corner,
            speed,
            at,
            motion,
        } = p;
        let plane = self.modal.plane.means;
        let (a1, a2, _) = plane.axes();
        let arc = matches!(mode, MotionMode::ArcCw | MotionMode::ArcCcw);
        let (s, e) = ((cur_t[a1], cur_t[a2]), (tw_t[a1], tw_t[a2]));
        self.comp_refresh();
        let c = self.common.comp.as_deref_mut().expect("comp");
        let (on, r, tip, vec, startup, type_b) = (c.on, c.r, c.tip, c.vec, c.startup, c.type_b);
        // A mirror image on one axis of the plane reverses the path's
        // turning sense: the offset goes to the other side of travel
        // (000 §15.3); its value is not scaled.
        let r = if self.frames.xf.mirrors(plane) { -r } else { r };
        let mut held = c.held.take();
        let g39 = c.g39.take().or(c.circular.then_some(None));
        let ij = c.ij.take();
        let mut cur_t = cur_t;
        // A held ,C/,R: the corner cut in the programmed contour; the held
        // move ends at its first point, the corner becomes a held path of
        // that block and this move starts at its second point.
        let mut g39 = g39;
        if let Some(hc) = held.as_mut().and_then(|h| h.corner.take()) {
            let mut h = held.take().expect("held");
            let cut = (mode, on, off_plane, e);
            let (mut mid, p2) = self.comp_cut_corner(&mut h, &hc, cut, &seg_p, cur)?;
            mid.cstart = self.comp_join(&mut h, &mid.seg, mid.r, g39.take(), type_b)?;
            held = Some(mid);
            seg = seg.with_start(p2);
            cur_t = self.plane_pt(cur_t, p2);
        }
        let held = held;
        if !on {
            if arc {
                return Err(AlarmKind::CompArc.at(
                    self.cfg.dialect.id,
                    motion,
                    "cutter compensation cancelled (G40) in a G02/G03 block: cancel in G00/G01",
                ));
            }
            let base = match held {
                Some(h) => self.comp_cancel_held(h, ij, &seg, type_b)?,
                None => padd(s, vec),
            };
            if let Some(cap) = self.common.comp_capture.as_mut() {
                if comp::dist(base, e) >= comp::EPS {
                    cap.push((Seg::Line { a: base, b: e }, motion, true));
                }
                self.place_at(&tw);
                self.common.comp = None;
                return Ok(());
            }
            let start = self.offset_to_machine(&self.plane_pt(cur_t, base));
            let prog = self.place_machine(start);
            let r = self.line_to(tw, speed, at);
            if r.is_err() {
                self.place_machine(prog);
            }
            r?;
            self.common.comp = None;
            return Ok(());
        }
        // The offset at this block's start must exist (an inside arc
        // larger than the offset).
        self.comp_geom(comp::perp_start(&seg, r), motion)?;
        let cstart = if let Some(mut h) = held {
            self.comp_join(&mut h, &seg, r, g39, type_b)?
        } else {
            if startup && arc {
                return Err(AlarmKind::CompArc.at(
                    self.cfg.dialect.id,
                    motion,
                    "cutter compensation start-up (G41/G42) in a G02/G03 block: start in G00/G01",
                ));
            }
            // Start-up from the uncompensated point, or slanted from the
            // vector left by a broken look-ahead.
            psub(padd(s, vec), tip)
        };
        let src = self.prog.cur;
        let c = self.common.comp.as_deref_mut().expect("comp");
        c.startup = false;
        c.vec = (0.0, 0.0);
        let events = std::mem::take(&mut c.spare);
        c.held = Some(Held {
            seg,
            start: cur_t,
            end: tw_t,
            cstart,
            speed,
            r,
            tip,
            startup,
            src,
            motion,
            events,
            corner,
        });
        self.place_at(&tw);
        Ok(())
    }

    /// The corner between the held move `h` and the next path `next`
    /// (offset `r`), or the start-up when `h` is one; `h` is emitted up to
    /// it. Returns where `next` starts.
    fn comp_join(
        &mut self,
        h: &mut Held,
        next: &Seg,
        r: f64,
        g39: Option<Option<P>>,
        type_b: bool,
    ) -> R<P> {
        let j = if h.startup {
            comp::startup(&h.seg, next, h.r, type_b)
        } else {
            comp::corner(
                &h.seg,
                h.r,
                next,
                r,
                CornerOpt {
                    g39,
                    perpendicular: false,
                },
            )
        };
        let j = self.comp_geom(j, h.motion)?;
        self.comp_flush(h, &j)?;
        Ok(j.start2())
    }

    /// `,C`/`,R` of the held move `h` with the next move (`seg_p` in
    /// program coordinates from `cur`; `cut`: its motion mode, offset mode
    /// on, moving off the plane, transformed end): the chamfer or corner
    /// arc cut in the programmed contour (000 §4.3) and transformed with
    /// the block. `h` is trimmed to the corner's first point; returns the
    /// corner as a held path of `h`'s block (with `h`'s events, which come
    /// after the corner) and the corner's second point, where the next
    /// move starts.
    fn comp_cut_corner(
        &mut self,
        h: &mut Held,
        hc: &HeldCorner,
        cut: (MotionMode, bool, bool, P),
        seg_p: &Seg,
        cur: Pos,
    ) -> R<(Held, P)> {
        let (mode, on, off_plane, end2) = cut;
        let k = if hc.chamfer { 'C' } else { 'R' };
        let id = self.cfg.dialect.id;
        let broken = |what: &str| {
            AlarmKind::CornerNoMove.at(
                id,
                hc.word,
                format!("{what} after a ,{k} block: the next move must be G01/G02/G03 in the same plane"),
            )
        };
        if !on {
            return Err(broken("G40"));
        }
        if mode == MotionMode::Rapid {
            return Err(broken("G00"));
        }
        if off_plane {
            return Err(broken("a move off the plane"));
        }
        if hc.xf != self.frames.xf {
            return Err(AlarmKind::CornerConflict.at(
                id,
                hc.word,
                format!("the coordinate transform changed between a ,{k} block and its next move"),
            ));
        }
        let size = fmt_num(hc.size);
        let found = if hc.chamfer {
            crate::corner::chamfer(&hc.seg, seg_p, hc.size)
        } else {
            crate::corner::round(&hc.seg, seg_p, hc.size)
        };
        let c = found.map_err(|e| {
            let why = match e {
                crate::corner::CornerError::TooLarge => {
                    format!(",{k}{size} does not fit on the two paths at this corner")
                }
                crate::corner::CornerError::NoCorner => {
                    format!(",{k}{size}: the paths meet without a corner (tangent or reversing)")
                }
            };
            AlarmKind::CornerTooLarge.at(id, hc.word, why)
        })?;
        let (a1, a2, _) = self.modal.plane.means.axes();
        let fwd = |me: &Self, q: P| {
            let p = me.xf_point(&me.plane_pt(cur, q));
            (p[a1], p[a2])
        };
        let (p1, p2) = (fwd(self, c.p1()), fwd(self, c.p2()));
        // In offset mode both paths must keep a part: a path used up by
        // the corner has no direction to offset.
        if comp::dist(h.seg.start(), p1) < comp::EPS || comp::dist(p2, end2) < comp::EPS {
            return Err(AlarmKind::CornerTooLarge.at(
                id,
                hc.word,
                format!(",{k}{size} uses up a whole path: in cutter compensation mode the corner must leave part of both paths"),
            ));
        }
        let seg = match c {
            crate::corner::Corner::Chamfer { .. } => Seg::Line { a: p1, b: p2 },
            crate::corner::Corner::Round { c: pc, ccw, .. } => {
                let (q1, q2) = (self.plane_pt(cur, c.p1()), self.plane_pt(cur, c.p2()));
                let (_, _, ct, ccw) = self.transform_arc(q1, q2, pc, ccw, 0)?;
                Seg::Arc {
                    a: p1,
                    b: p2,
                    c: ct,
                    ccw,
                }
            }
        };
        h.seg = h.seg.with_end(p1);
        let end = h.end;
        h.end = self.plane_pt(end, p1);
        let mid = Held {
            seg,
            start: h.end,
            end: self.plane_pt(end, p2),
            cstart: (0.0, 0.0),
            speed: h.speed,
            r: h.r,
            tip: h.tip,
            startup: false,
            src: h.src,
            motion: h.motion,
            events: std::mem::take(&mut h.events),
            corner: None,
        };
        Ok((mid, p2))
    }

    /// A move without motion in the plane (Z alone in G17): with a move
    /// held it is kept back and takes the corner's plane point; otherwise
    /// it moves at the vector in force.
    fn comp_offplane(&mut self, mode: MotionMode, tw: Pos, any: bool, at: u32) -> R<()> {
        let c = self.common.comp.as_deref().expect("comp");
        if let Some(hc) = c.held.as_ref().and_then(|h| h.corner.as_ref()) {
            let k = if hc.chamfer { 'C' } else { 'R' };
            return Err(AlarmKind::CornerNoMove.at(
                self.cfg.dialect.id,
                hc.word,
                format!("a move off the plane after a ,{k} block: the next move must be G01/G02/G03 in the same plane"),
            ));
        }
        if c.held.is_some() || (c.vec.0 == 0.0 && c.vec.1 == 0.0) {
            return self.plain_motion(mode, tw, any, at);
        }
        let vec = c.vec;
        let cur_t = self.xf_point(&self.prog_pos());
        let tw_t = self.xf_point(&tw);
        let (a1, a2, _) = self.modal.plane.means.axes();
        let p = padd((cur_t[a1], cur_t[a2]), vec);
        let start = self.offset_to_machine(&self.plane_pt(cur_t, p));
        let prog = self.place_machine(start);
        self.common.comp_prog = Some(self.work_of(&self.to_machine(&tw)));
        // The vector is in the transformed plane: the target back in
        // program coordinates for the move.
        let target = self.plane_pt(tw_t, p);
        let target = if self.frames.xf.active() {
            self.frames.xf.inverse(&target)
        } else {
            target
        };
        let r = self.plain_motion(mode, target, any, at);
        self.common.comp_prog = None;
        if r.is_ok() {
            self.place_at(&tw);
        } else {
            self.place_machine(prog);
        }
        r
    }

    /// Ends a held move on the vector perpendicular to its end (the
    /// look-ahead broken); the vector stays in force.
    pub(super) fn comp_break(&mut self) -> R<()> {
        let Some(c) = self.common.comp.as_deref_mut() else {
            return Ok(());
        };
        let Some(mut h) = c.held.take() else {
            return Ok(());
        };
        if let Some(hc) = &h.corner {
            let k = if hc.chamfer { 'C' } else { 'R' };
            return Err(AlarmKind::CornerNoMove.at(
                self.cfg.dialect.id,
                hc.word,
                format!("no G01/G02/G03 move in the plane follows the ,{k} block (a move of another kind, too many blocks without a move, or the end)"),
            ));
        }
        let end1 = self.comp_geom(comp::perp_end(&h.seg, h.r), h.motion)?;
        let (a1, a2, _) = self.modal.plane.means.axes();
        let vec = psub(padd(end1, h.tip), (h.end[a1], h.end[a2]));
        self.comp_flush(&mut h, &Join::at(end1))?;
        self.common.comp.as_deref_mut().expect("comp").vec = vec;
        Ok(())
    }

    /// End of a block: blocks without a move in the plane count towards
    /// the look-ahead limit; a state with nothing left is dropped.
    pub(super) fn comp_block_end(&mut self) -> R<()> {
        let Some(c) = self.common.comp.as_deref_mut() else {
            return Ok(());
        };
        if c.moved {
            c.moved = false;
        } else if c.held.is_some() {
            c.idle += 1;
            if c.idle > c.limit {
                c.idle = 0;
                self.comp_break()?;
            }
        }
        let c = self.common.comp.as_deref().expect("comp");
        if !c.on && c.held.is_none() && c.vec == (0.0, 0.0) {
            self.common.comp = None;
        }
        Ok(())
    }

    /// The end of the program (M02/M30, end of text) cancels compensation
    /// (000 §13.2.1: RESET, M02, M30 → G40): a held move ends on its
    /// perpendicular vector.
    pub(super) fn comp_finish(&mut self) -> R<()> {
        self.comp_break()?;
        self.common.comp = None;
        Ok(())
    }

    /// A geometry result as an alarm at `src`.
    fn comp_geom<T>(&self, r: Result<T, CompError>, src: SrcRef) -> R<T> {
        r.map_err(|e| {
            let (kind, msg) = match e {
                CompError::ArcTooSmall => (
                    AlarmKind::CompInterference,
                    "interference: the offset is larger than the radius of an inside arc",
                ),
                CompError::NoIntersection => (
                    AlarmKind::CompNoSolution,
                    "no intersection of the compensated paths at the corner",
                ),
            };
            kind.at(self.cfg.dialect.id, src, msg)
        })
    }

    /// Emits a held move up to `j.end1`, the events kept back (motions at
    /// the corner's plane point), then the corner's pieces. Alarms point
    /// at the held block's motion word.
    fn comp_flush(&mut self, h: &mut Held, j: &Join) -> R<()> {
        let prog = self.frames.mover.pos();
        // The held points are already transformed (scaling, mirror,
        // rotation of their own block): emitted through the offset stack
        // only.
        let xf = std::mem::take(&mut self.frames.xf);
        let base = self.prog_pos();
        let here = std::mem::replace(&mut self.prog.cur, h.src);
        let mut events = std::mem::take(&mut h.events);
        let r = self.comp_emit(h, j, base, &mut events);
        self.frames.xf = xf;
        self.common.comp_prog = None;
        self.prog.cur = here;
        self.place_machine(prog);
        events.clear();
        if let Some(c) = self.common.comp.as_deref_mut() {
            if c.spare.capacity() < events.capacity() {
                c.spare = events;
            }
        }
        r.map_err(|mut a| {
            a.src = h.motion;
            a
        })
    }

    fn comp_emit(&mut self, h: &Held, j: &Join, base: Pos, events: &mut Vec<Event>) -> R<()> {
        // Interference: the compensated move must not run against the
        // programmed one (fanuc-semantics §4.7).
        let bad = match h.seg {
            Seg::Line { a, b } => !h.startup && comp::line_reverses((a, b), (h.cstart, j.end1)),
            Seg::Arc { .. } => comp::arc_reverses(&h.seg, (h.cstart, j.end1)),
        };
        if bad {
            return Err(AlarmKind::CompInterference.at(
                self.cfg.dialect.id,
                h.motion,
                "interference: the compensated move would run against the programmed direction (gouge)",
            ));
        }
        if let Some(cap) = self.common.comp_capture.as_mut() {
            // The G71-G73 tip path: the pieces are kept, nothing emitted.
            let (a, b) = (padd(h.cstart, h.tip), padd(j.end1, h.tip));
            match h.seg {
                Seg::Line { .. } => {
                    if comp::dist(a, b) >= comp::EPS {
                        cap.push((Seg::Line { a, b }, h.motion, true));
                    }
                }
                Seg::Arc { c, ccw, .. } => cap.push((
                    Seg::Arc {
                        a,
                        b,
                        c: padd(c, h.tip),
                        ccw,
                    },
                    h.motion,
                    true,
                )),
            }
            let mut prev = j.end1;
            for p in j.pieces() {
                let (a, b) = (padd(prev, h.tip), padd(p.end(), h.tip));
                match *p {
                    Piece::Line(_) => cap.push((Seg::Line { a, b }, h.motion, false)),
                    Piece::Arc(_, c, ccw) => cap.push((
                        Seg::Arc {
                            a,
                            b,
                            c: padd(c, h.tip),
                            ccw,
                        },
                        h.motion,
                        false,
                    )),
                }
                prev = p.end();
            }
            events.clear();
            return Ok(());
        }
        let s = self.plane_pt(h.start, padd(h.cstart, h.tip));
        let e = self.plane_pt(h.end, padd(j.end1, h.tip));
        self.place_at(&s);
        self.common.comp_prog = Some(self.work_of(&self.to_machine(&h.end)));
        let feed = |me: &Self| match h.speed {
            Speed::Feed(f) => Ok(f),
            _ => me.feed(0),
        };
        match h.seg {
            Seg::Line { .. } => {
                if s != e {
                    self.line_to(e, h.speed, 0)?;
                }
            }
            Seg::Arc { c, ccw, .. } => {
                let f = feed(self)?;
                self.arc_to(s, e, padd(c, h.tip), ccw, f, 0)?;
            }
        }
        // The events of the blocks between, at the corner.
        if !events.is_empty() {
            let corner = self.to_machine(&e);
            self.release_held(events, &corner)?;
        }
        let mut prev = j.end1;
        let corner = self.plane_pt(base, h.seg.end());
        self.common.comp_prog = Some(self.work_of(&self.to_machine(&corner)));
        for p in j.pieces() {
            match *p {
                Piece::Line(q) => {
                    let t = self.plane_pt(base, padd(q, h.tip));
                    self.line_to(t, h.speed, 0)?;
                }
                Piece::Arc(q, c, ccw) => {
                    let f = feed(self)?;
                    let s = self.plane_pt(base, padd(prev, h.tip));
                    let t = self.plane_pt(base, padd(q, h.tip));
                    self.arc_to(s, t, padd(c, h.tip), ccw, f, 0)?;
                }
            }
            prev = p.end();
        }
        Ok(())
    }

    /// A program point mapped by the transforms in force (scaling,
    /// mirror, rotation): the coordinates the compensation works in.
    fn xf_point(&self, p: &Pos) -> Pos {
        if self.frames.xf.active() {
            self.frames.xf.forward(p)
        } else {
            *p
        }
    }

    /// A direction in the plane (program coordinates) mapped by the
    /// transforms in force.
    fn xf_dir(&self, d: P) -> P {
        if !self.frames.xf.active() {
            return d;
        }
        let o = [0.0; NAXES];
        let q = self.plane_pt(o, d);
        let (a1, a2, _) = self.modal.plane.means.axes();
        let (fo, fq) = (self.frames.xf.forward(&o), self.frames.xf.forward(&q));
        (fq[a1] - fo[a1], fq[a2] - fo[a2])
    }

    /// `p` with its plane coordinates replaced by `uv`.
    fn plane_pt(&self, p: Pos, uv: P) -> Pos {
        let (a1, a2, _) = self.modal.plane.means.axes();
        let mut q = p;
        q[a1] = uv.0;
        q[a2] = uv.1;
        q
    }

    /// The source position of a byte of the current block.
    pub(super) fn src_here(&self, at: u32) -> SrcRef {
        let (line, col) = self.prog.raw.line_col(at as usize);
        SrcRef {
            file: self.prog.cur.file,
            line,
            col,
        }
    }
}
