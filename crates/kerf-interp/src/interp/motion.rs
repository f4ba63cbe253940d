//! Motion: the block's end point, travel limits, rapid/feed/arc moves,
//! G53, tool length offset and the reference-position returns G27-G30.

use super::*;
use crate::dialect::meaning::RefReturn;

pub(super) use super::mover::Speed;

impl Interp {
    // ---- motion ------------------------------------------------------------------

    /// The block's end point in work coordinates, and whether any axis moved.
    pub(super) fn target(&self) -> R<(Pos, bool)> {
        let mut cur = self.prog_pos();
        let mut t = cur;
        let mut any = false;
        let mut programmed = [false; NAXES];
        let table16 = self.cfg.dialect.caps.offsets_wait_for_move;
        if table16 {
            // Table 16: after a T/E code, before the next move.
            self.hurco_base(&mut cur);
        }
        for ax in Axis::ALL {
            let l = ax_letter(ax);
            let i = ax as usize;
            let abs_w = self.words.get(l).filter(|_| self.cfg.has_axis[ax as usize]);
            let inc_l = self.uvw(ax);
            if let (Some(w), Some(_)) = (abs_w, inc_l) {
                return Err(self.alarm(
                    AlarmKind::DuplicateAddress,
                    w.at,
                    format!("{} and its incremental address in one block", l as char),
                ));
            }
            if let Some(w) = abs_w {
                self.check_range(l, w)?;
                t[i] = self.axis_end(&cur, ax, w);
                any = true;
                programmed[i] = true;
            } else if let Some(il) = inc_l {
                let w = self.words.get(il).expect("present");
                self.check_range(il, w)?;
                t[i] = cur[i] + self.axis_value(ax, w);
                any = true;
            }
        }
        if any && table16 {
            self.hurco_immediate(&mut t, &programmed);
        }
        if self.frames.polar {
            self.polar_target(&cur, &mut t);
        }
        Ok((t, any))
    }

    /// Where axis word `w` puts axis `ax`: its value in G90, added to
    /// the current point `cur` (and this block's tool length change) in
    /// G91.
    #[inline]
    pub(super) fn axis_end(&self, cur: &Pos, ax: Axis, w: WVal) -> f64 {
        let i = ax as usize;
        let v = self.axis_value(ax, w);
        if self.modal.absolute() {
            v
        } else {
            cur[i] + v + self.tlo_change(i)
        }
    }

    /// The change of the tool length offset made by this block's
    /// G43/G44/G49/H in G91 on axis slot `i` (0 otherwise).
    fn tlo_change(&self, i: usize) -> f64 {
        self.common.tlo_change(self.guard.blocks, i)
    }

    /// G16: the plane's first-axis word is a radius, the second an angle
    /// (000 §8.3). A radius in G90 is measured from the program origin, in
    /// G91 from the current position; without a radius the previous origin
    /// and the current distance from it are kept. The angle is absolute in
    /// G90, added to the current angle in G91.
    fn polar_target(&self, cur: &Pos, t: &mut Pos) {
        let (a1, a2, _) = self.modal.plane.means.axes();
        let rw = self.words.get(b"XYZ"[a1]);
        let aw = self.words.get(b"XYZ"[a2]);
        if rw.is_none() && aw.is_none() {
            return;
        }
        let mut origin = self.frames.polar_origin.get();
        if rw.is_some() {
            origin = if self.modal.absolute() {
                (0.0, 0.0)
            } else {
                (cur[a1], cur[a2])
            };
        }
        let (dx, dy) = (cur[a1] - origin.0, cur[a2] - origin.1);
        let r_cur = dx.hypot(dy);
        let a_cur = if r_cur < 1e-12 {
            0.0
        } else {
            dy.atan2(dx).to_degrees()
        };
        let r = rw.map(|w| self.linear(w)).unwrap_or(r_cur);
        let a = match aw {
            Some(w) if self.modal.absolute() => self.angular(w),
            Some(w) => a_cur + self.angular(w),
            None => a_cur,
        };
        let (u, v) = crate::xform::polar_point(origin, r, a);
        t[a1] = u;
        t[a2] = v;
        self.frames.polar_origin.set(origin);
    }

    /// `G22 X_ Y_ Z_ I_ J_ K_`: the forbidden area, machine coordinates,
    /// (X, Y, Z) the upper and (I, J, K) the lower corner; an axis given by
    /// neither spans all. PM 3474 = 1 forbids the outside (000 §15.5.3).
    pub(super) fn g22(&mut self, at: u32) -> R<()> {
        let mut lo = [f64::NEG_INFINITY; 3];
        let mut hi = [f64::INFINITY; 3];
        let mut any = false;
        for (i, (u, l)) in [(b'X', b'I'), (b'Y', b'J'), (b'Z', b'K')]
            .into_iter()
            .enumerate()
        {
            let ax = Axis::ALL[i];
            if let Some(w) = self.words.get(u) {
                hi[i] = self.axis_value(ax, w);
                any = true;
            }
            if let Some(w) = self.words.get(l) {
                lo[i] = self.linear(w);
                any = true;
            }
            if lo[i] > hi[i] {
                let w = self
                    .words
                    .get(l)
                    .or(self.words.get(u))
                    .map(|w| w.at)
                    .unwrap_or(at);
                return Err(self.alarm(
                    AlarmKind::OutOfRange,
                    w,
                    format!(
                        "G22: the lower corner {} is above the upper corner {} (X ≥ I, Y ≥ J, Z ≥ K)",
                        (b'I' + i as u8) as char,
                        (b'X' + i as u8) as char
                    ),
                ));
            }
        }
        if !any {
            return Ok(());
        }
        let area = crate::stroke::Area {
            lo,
            hi,
            outside: self.cfg.profile.param("PM 3474", 0.0) == 1.0,
        };
        // The tool may not already be where the check forbids.
        if area.forbids(&self.frames.mover.pos()) {
            return Err(self.stroke_alarm(&area, at));
        }
        self.frames.stroke_area = Some(area);
        Ok(())
    }

    pub(super) fn motion_at(&self) -> u32 {
        self.words
            .gs()
            .iter()
            .find(|g| {
                matches!(
                    self.gcode(g.0).map(|c| c.means),
                    Some(Means::Motion(
                        MotionMode::Rapid
                            | MotionMode::Linear
                            | MotionMode::ArcCw
                            | MotionMode::ArcCcw
                            | MotionMode::ThreadF
                            | MotionMode::ThreadKI
                    ))
                )
            })
            .map(|g| g.1)
            .unwrap_or(0)
    }

    pub(super) fn feed(&self, at: u32) -> R<Feed> {
        match self.tool.feed {
            None => Err(self.alarm(
                AlarmKind::NoFeed,
                at,
                "cutting move without a feedrate (no F commanded)",
            )),
            Some(f) if f <= 0.0 => Err(self.alarm(AlarmKind::NoFeed, at, "feedrate is zero")),
            Some(f) => Ok(match self.modal.feed_mode.means {
                FeedMode::PerMin => Feed::PerMin(f.min(self.cfg.profile.feed.max_cutting)),
                FeedMode::PerRev => Feed::PerRev(f),
                FeedMode::Inverse => Feed::InverseTime(f),
            }),
        }
    }

    pub(super) fn motion(&mut self) -> R<()> {
        if self.frames.rot != polar_interp::RotInterp::Off {
            return self.rotary_interp_motion();
        }
        let mode = self.modal.motion.means;
        let ddi = self.cfg.dialect.caps.direct_drawing;
        let (tw, any) = if ddi {
            self.ddi_target()?
        } else {
            self.target()?
        };
        let at = self.motion_at();
        // PUMA direct chamfer / corner R (interp/lathe_chamfer.rs).
        if ddi && mode == MotionMode::Linear && any && self.ddi_words() {
            return self.ddi_motion(tw, at);
        }
        if self.common.comp.is_some() {
            return self.comp_motion(mode, tw, any, at);
        }
        // One test for the look-ahead of ,C/,R (a move held, or this block
        // carries one): interp/corners.rs.
        if self.common.corner.is_some()
            | self.words.comma_c.is_some()
            | self.words.comma_r.is_some()
        {
            return self.corner_motion(mode, tw, any, at);
        }
        self.plain_motion(mode, tw, any, at)
    }

    /// The block's move without chamfer or corner R.
    pub(super) fn plain_motion(&mut self, mode: MotionMode, tw: Pos, any: bool, at: u32) -> R<()> {
        use MotionMode::*;
        match mode {
            Rapid | Linear if any => self.move_line(mode == Rapid, tw, at)?,
            ThreadF if any => self.thread_line(tw, at)?,
            ThreadLathe | TurnCycle | ThreadCycle | FaceCycle => {
                self.lathe_motion(mode, tw, any, at)?
            }
            ThreadKI if any => self.hurco_g33(tw, at)?,
            ArcCw | ArcCcw => self.arc(tw, any, mode == ArcCcw, at)?,
            Rapid | Linear | ThreadF | ThreadKI => {}
        }
        Ok(())
    }

    /// Current position in the program's coordinates: the point the next
    /// incremental word adds to (before polar, scaling and rotation).
    pub(super) fn prog_pos(&self) -> Pos {
        let p = self.frames.programmed_position();
        if self.frames.xf.active() {
            self.frames.xf.inverse(&p)
        } else {
            p
        }
    }

    /// A straight move (rapid or feed) to `tw`, a point in the program's
    /// coordinates: transformed to machine coordinates, checked against
    /// the travel limits and emitted. `at` positions any alarm.
    pub(super) fn move_line(&mut self, rapid: bool, tw: Pos, at: u32) -> R<()> {
        self.line_to(tw, if rapid { Speed::Rapid } else { Speed::Modal }, at)
    }

    pub(super) fn arc(&mut self, tw: Pos, any: bool, ccw: bool, at: u32) -> R<()> {
        let Some(center) = self.arc_center(tw, any, ccw, at)? else {
            return Ok(());
        };
        let feed = self.feed(at)?;
        let cur = self.prog_pos();
        self.arc_to(cur, tw, center, ccw, feed, at)
    }

    /// The centre (in the plane) of the block's arc from the current
    /// position to `tw`, from R or I/J/K, with the end-point checks. None
    /// when the block makes no arc (no end point and no centre, or R with
    /// the end at the start, which moves only the other axes).
    pub(super) fn arc_center(
        &mut self,
        tw: Pos,
        any: bool,
        ccw: bool,
        at: u32,
    ) -> R<Option<(f64, f64)>> {
        let plane = self.modal.plane.means;
        let (a1, a2, normal) = plane.axes();
        // The centre word of the axis normal to the plane (J in G18, K in
        // G17, I in G19) is not part of the arc: an alarm, never ignored.
        let off_plane = b"IJK"[normal];
        if let Some(w) = self.words.get(off_plane) {
            let (g, pair) = match plane {
                Plane::XY => ("G17", "I and J"),
                Plane::ZX => ("G18", "K and I"),
                Plane::YZ => ("G19", "J and K"),
            };
            return Err(self.alarm(
                AlarmKind::IllegalAddress,
                w.at,
                format!(
                    "{} is not a centre word of the {g} plane (its centre is {pair})",
                    off_plane as char
                ),
            ));
        }
        let cur = self.prog_pos();
        let s = (cur[a1], cur[a2]);
        let e = (tw[a1], tw[a2]);
        let has_ijk = [b'I', b'J', b'K'].iter().any(|&l| self.words.has(l));
        let center = if let Some(r) = self.words.get(b'R') {
            self.check_range(b'R', r)?;
            let rv = self.linear(r);
            if !any || (s.0 - e.0).hypot(s.1 - e.1) < 1e-9 {
                // R with the end at the start: no movement (Fanuc).
                if any {
                    self.linear_only(tw)?;
                }
                return Ok(None);
            }
            // 001 p.15 note (4): on the PUMA an R shorter than half the
            // move is overridden and a half circle made; the others alarm.
            let tol = if self.cfg.dialect.caps.short_r_half_circle {
                f64::INFINITY
            } else {
                self.cfg.arc_tol
            };
            match arc::center_from_radius(s, e, rv, ccw, tol) {
                Ok(c) => c,
                Err(_) => {
                    let half = (s.0 - e.0).hypot(s.1 - e.1) / 2.0;
                    return Err(self.alarm(
                        AlarmKind::ArcRadius,
                        r.at,
                        format!(
                            "arc radius {:.4} is smaller than half the chord {:.4}",
                            rv.abs(),
                            half
                        ),
                    ));
                }
            }
        } else if has_ijk {
            let off = |l: u8| -> R<f64> {
                match self.words.get(l) {
                    Some(w) => {
                        self.check_range(l, w)?;
                        Ok(self.linear(w))
                    }
                    None => Ok(0.0),
                }
            };
            // I, J, K belong to X, Y, Z; lathe I is a radius value.
            let o = [off(b'I')?, off(b'J')?, off(b'K')?];
            (s.0 + o[a1.min(2)], s.1 + o[a2.min(2)])
        } else {
            if !any {
                return Ok(None);
            }
            return Err(self.alarm(
                AlarmKind::ArcNoCenter,
                at,
                "arc without centre (I/J/K) or radius (R)",
            ));
        };
        let bad_at = [b'I', b'J', b'K', b'R']
            .iter()
            .find_map(|&l| self.words.get(l))
            .map(|w| w.at)
            .unwrap_or(at);
        match arc::check_end(s, e, center, self.cfg.arc_tol) {
            Ok(_) => {}
            Err(ArcError::ZeroRadius) => return Err(self.alarm(AlarmKind::ArcNoCenter, bad_at, "arc centre coincides with the start point")),
            Err(ArcError::EndNotOnCircle { r_start, r_end }) => {
                return Err(self.alarm(
                    AlarmKind::ArcEndPoint,
                    bad_at,
                    format!("arc end point is not on the circle: start radius {r_start:.4}, end radius {r_end:.4}"),
                ))
            }
            Err(ArcError::RadiusTooSmall { .. }) => unreachable!(),
        }
        Ok(Some(center))
    }

    /// Scaling and rotation of an arc given in program coordinates: the
    /// end points and the centre are transformed, a mirror reverses the
    /// direction (000 §15.3). With unequal plane factors the arc keeps its
    /// transformed end points and takes its radius times the larger
    /// factor, on the same side (fanuc-semantics §8.3).
    pub(super) fn transform_arc(
        &self,
        start: Pos,
        tw: Pos,
        center: (f64, f64),
        ccw: bool,
        at: u32,
    ) -> R<(Pos, Pos, (f64, f64), bool)> {
        if !self.frames.xf.active() {
            return Ok((start, tw, center, ccw));
        }
        let xf = self.frames.xf;
        let plane = self.modal.plane.means;
        let (a1, a2, _) = plane.axes();
        let mut c = start;
        c[a1] = center.0;
        c[a2] = center.1;
        let (st, et, ct) = (xf.forward(&start), xf.forward(&tw), xf.forward(&c));
        let ccw_t = ccw != xf.mirrors(plane);
        let (f1, f2) = xf.plane_factors(plane);
        let center_t = if (f1.abs() - f2.abs()).abs() > 1e-12 {
            let (s, e) = ((start[a1], start[a2]), (tw[a1], tw[a2]));
            let r = (s.0 - center.0).hypot(s.1 - center.1);
            let major = arc::sweep(s, e, center, ccw) > std::f64::consts::PI + 1e-12;
            let rs = r * f1.abs().max(f2.abs()) * if major { -1.0 } else { 1.0 };
            arc::center_from_radius(
                (st[a1], st[a2]),
                (et[a1], et[a2]),
                rs,
                ccw_t,
                self.cfg.arc_tol,
            )
            .map_err(|_| {
                self.alarm(
                    AlarmKind::ArcRadius,
                    at,
                    "scaled arc radius is smaller than half the chord",
                )
            })?
        } else {
            (ct[a1], ct[a2])
        };
        Ok((st, et, center_t, ccw_t))
    }

    /// G33 on the HX (000 §4.8): a straight move synchronised with the
    /// spindle, F = lead (mm/rev, modal with the other feeds).
    fn thread_line(&mut self, tw: Pos, at: u32) -> R<()> {
        let Some(lead) = self.tool.feed.filter(|f| *f > 0.0) else {
            return Err(self.alarm(AlarmKind::NoFeed, at, "G33 without a thread lead (F)"));
        };
        if self.tool.spindle == SpindleDir::Stop {
            return Err(self.alarm(
                AlarmKind::NoFeed,
                at,
                "G33 with the spindle stopped: the threading move would wait forever",
            ));
        }
        self.thread_move(tw, lead, at)
    }

    // ---- tool length, reference returns ----------------------------------------

    /// G43/G44/G49 with H: the tool length offset on the axis normal to
    /// the plane (mills).
    pub(super) fn tool_length(&mut self) -> R<()> {
        if self.cfg.profile.kind != MachineKind::Mill {
            return Ok(());
        }
        if let Some(h) = self.words.get(b'H') {
            if h.v < 0.0 || h.v.fract() != 0.0 || !self.offsets.valid(h.v as usize) {
                return Err(self.alarm(
                    AlarmKind::OutOfRange,
                    h.at,
                    format!(
                        "H{} is not an offset number (H00-H{})",
                        fmt_num(h.v),
                        self.offsets.count()
                    ),
                ));
            }
            self.frames.h = h.v as u32;
        }
        let old = *self.frames.tlo();
        self.refresh_tool_length();
        // In G91 the block's incremental move counts from the tip as the
        // old offset had it, so the machine moves by the move plus the
        // offset change (fanuc-semantics §5.1).
        if !self.modal.absolute() && old != *self.frames.tlo() {
            let mut d = [0.0; NAXES];
            for i in 0..NAXES {
                d[i] = self.frames.tlo()[i] - old[i];
            }
            self.common.set_tlo_change(self.guard.blocks, d);
        }
        Ok(())
    }

    /// The tool length offset vector from the G43/G44 mode and H in force.
    pub(super) fn refresh_tool_length(&mut self) {
        let sign = match self.modal.length_comp.means {
            LengthComp::Plus => 1.0,
            LengthComp::Minus => -1.0,
            LengthComp::Off => 0.0,
        };
        // 000 §13.1.1: the axis normal to the plane in force when the
        // offset is taken (G17 Z, G18 Y, G19 X).
        let normal = self.modal.plane.means.axes().2;
        let h = self.offsets.h(self.frames.h as usize);
        let tlo = self.frames.tlo_mut();
        *tlo = [0.0; NAXES];
        tlo[normal] = sign * h;
    }

    /// The machine position of reference point `n` (1-4) for an axis.
    pub(super) fn reference_point(&self, n: u32, ax: Axis) -> f64 {
        let key = match n {
            2 => "second",
            3 => "third",
            4 => "fourth",
            _ => {
                return self
                    .cfg
                    .profile
                    .axis(ax)
                    .map(|a| a.reference)
                    .unwrap_or(0.0)
            }
        };
        self.cfg
            .profile
            .reference
            .get(key)
            .and_then(|m| m.get(ax.name()))
            .copied()
            .unwrap_or_else(|| {
                self.cfg
                    .profile
                    .axis(ax)
                    .map(|a| a.reference)
                    .unwrap_or(0.0)
            })
    }

    /// G27 check, G28 / G30 return via an intermediate point, G29 return
    /// from the reference point through the stored intermediate point.
    pub(super) fn reference_return(&mut self, kind: RefReturn, at: u32) -> R<()> {
        let (tw, _) = self.target()?;
        let mut named = [false; NAXES];
        for ax in Axis::ALL {
            named[ax as usize] = self.cfg.has_axis[ax as usize]
                && (self.words.has(ax_letter(ax)) || self.uvw(ax).is_some());
        }
        let rapid_to = |me: &mut Self, mto: Pos| me.rapid_machine(mto, at);
        match kind {
            RefReturn::Check => {
                let mto = self.to_machine(&tw);
                rapid_to(self, mto)?;
                for ax in Axis::ALL {
                    let i = ax as usize;
                    if named[i]
                        && (self.frames.mover.pos()[i] - self.reference_point(1, ax)).abs() > 1e-6
                    {
                        // The check follows the move: the positioning is
                        // made, then the control alarms.
                        self.common.after_block = Some(self.alarm(
                            AlarmKind::ReferenceCheck,
                            at,
                            format!(
                                "G27: {} is not at the reference position",
                                ax.name().to_uppercase()
                            ),
                        ));
                        break;
                    }
                }
            }
            RefReturn::Home | RefReturn::Other => {
                let n = if kind == RefReturn::Home {
                    1
                } else {
                    match self.words.get(b'P') {
                        None => 2,
                        Some(p) if matches!(p.v as i64, 2..=4) && p.v.fract() == 0.0 => p.v as u32,
                        Some(p) => {
                            return Err(self.alarm(
                                AlarmKind::OutOfRange,
                                p.at,
                                "G30 P must be 2, 3 or 4",
                            ))
                        }
                    }
                };
                // Intermediate point, then the reference point, named axes only.
                let mid = self.to_machine(&tw);
                rapid_to(self, mid)?;
                for ax in Axis::ALL {
                    let i = ax as usize;
                    if named[i] {
                        self.frames.g28_mid[i] = Some(tw[i]);
                    }
                }
                let mut r = self.frames.mover.pos();
                for ax in Axis::ALL {
                    if named[ax as usize] {
                        r[ax as usize] = self.reference_point(n, ax);
                    }
                }
                rapid_to(self, r)?;
            }
            RefReturn::Back => {
                // Through the stored intermediate point to the commanded point.
                let mut mid = self.frames.programmed_position();
                for ax in Axis::ALL {
                    let i = ax as usize;
                    if named[i] {
                        match self.frames.g28_mid[i] {
                            Some(v) => mid[i] = v,
                            None => {
                                return Err(self.alarm(
                                    AlarmKind::MissingArgument,
                                    at,
                                    "G29 without a preceding G28/G30 intermediate point",
                                ))
                            }
                        }
                    }
                }
                let mm = self.to_machine(&mid);
                rapid_to(self, mm)?;
                // The end point: absolute as given; incremental from the intermediate point.
                let mut end = self.frames.programmed_position();
                for ax in Axis::ALL {
                    let i = ax as usize;
                    if let Some(w) = self.words.get(ax_letter(ax)).filter(|_| named[i]) {
                        let v = self.axis_value(ax, w);
                        end[i] = if self.modal.absolute() { v } else { mid[i] + v };
                    } else if let Some(l) = self.uvw(ax) {
                        let w = self.words.get(l).expect("present");
                        end[i] = mid[i] + self.axis_value(ax, w);
                    }
                }
                let me = self.to_machine(&end);
                rapid_to(self, me)?;
            }
        }
        Ok(())
    }
}
