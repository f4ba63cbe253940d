//! The move seam: [`Mover`] owns the machine position, and the methods in
//! this file are the only code that turns a target into machine
//! coordinates, checks it against the travel limits and the stored stroke
//! limit (G22/G23, 000 §15.5.3; arcs and chords by their path, the HX's
//! non-linear rapid by the dog-leg it really follows), sets the position
//! and builds a motion [`Canon`] (Rapid, Feed, Arc, Thread).
//!
//! Every generated move comes here: G00-G03, canned cycles, chamfers and
//! corners, cutter and nose radius compensation, G112/G107 chords, G31/G37,
//! threading (HX G33, PUMA G32/G92/G76, Hurco G33/G78), the lathe single
//! and multiple repetitive cycles, the Hurco drill and probe cycles, G53
//! and the reference returns. A move is checked whole before its position
//! is taken; a block whose path is made of chords (G112, G107) has every
//! chord checked before the first is committed.
//!
//! Path stages (cutter compensation, the ,C/,R look-ahead, the G71-G73
//! capture, the PUMA chamfer look-ahead) hold a move and let the next block
//! start from its programmed end before the move is committed: they move
//! the position with [`Interp::place_at`] / [`Interp::place_machine`]
//! (no event) and commit the move's real pieces later, checked, through
//! this file. The tidy test (tests/tidy.rs) fails when a motion `Canon` is
//! built anywhere else.

use super::*;

/// The machine position (machine coordinates of the control point).
/// Private: only this file sets it.
#[derive(Clone, Copy, Debug)]
pub(super) struct Mover {
    pos: Pos,
}

impl Mover {
    /// At `pos` (power-on: the profile's start position).
    pub(super) fn new(pos: Pos) -> Mover {
        Mover { pos }
    }

    /// The machine position.
    #[inline]
    pub(super) fn pos(&self) -> Pos {
        self.pos
    }
}

/// How fast a straight move goes.
#[derive(Clone, Copy, Debug)]
pub(super) enum Speed {
    /// G00.
    Rapid,
    /// The modal feed (F, G94/G95/G93).
    Modal,
    /// A feed fixed earlier.
    Feed(Feed),
}

/// How a committed straight move's path is checked against the stroke
/// limit.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Line {
    /// A rapid: on the HX the axes run independently (dog-leg).
    Rapid,
    /// A feed or thread: the straight segment.
    Straight,
}

impl Interp {
    /// A point in program coordinates → machine coordinates (scaling,
    /// rotation, then the offset stack).
    pub(super) fn to_machine(&self, w: &Pos) -> Pos {
        if self.frames.xf.active() {
            self.offset_to_machine(&self.frames.xf.forward(w))
        } else {
            self.offset_to_machine(w)
        }
    }

    /// A point in (transformed) local coordinates → machine coordinates:
    /// the offset stack only.
    pub(super) fn offset_to_machine(&self, w: &Pos) -> Pos {
        let o = self.frames.prog_origin();
        let mut m = *w;
        for i in 0..NAXES {
            m[i] += o[i];
        }
        m
    }

    /// Stored stroke check 2 (G22): the whole path from `from` to `to`
    /// (machine coordinates) must stay out of the forbidden area.
    fn check_stroke(&self, from: &Pos, to: &Pos, line: Line, at: u32) -> R<()> {
        let Some(area) = self.stroke_check_area() else {
            return Ok(());
        };
        let bad = if line == Line::Rapid && !self.linear_rapid() {
            let rates = [Axis::X, Axis::Y, Axis::Z]
                .map(|a| self.cfg.profile.axis(a).map(|d| d.rapid).unwrap_or(0.0));
            crate::stroke::dogleg(from, to, rates)
                .windows(2)
                .any(|w| area.segment_enters(&w[0], &w[1]))
        } else {
            area.segment_enters(from, to)
        };
        if bad {
            return Err(self.stroke_alarm(&area, at));
        }
        Ok(())
    }

    /// The G22 area when the check is on (a control without G23 has no
    /// way to switch it off).
    pub(super) fn stroke_check_area(&self) -> Option<crate::stroke::Area> {
        let area = self.frames.stroke_area?;
        self.modal.stroke.means.then_some(area)
    }

    /// The alarm of a move that would enter (or leave) the area.
    pub(super) fn stroke_alarm(&self, area: &crate::stroke::Area, at: u32) -> Alarm {
        let side = if area.outside { "leaves" } else { "enters" };
        self.alarm(
            AlarmKind::Overtravel,
            at,
            format!(
                "stored stroke check (G22): the move {side} the forbidden area X {}…{} Y {}…{} Z {}…{} (machine)",
                fmt_num(area.lo[0]),
                fmt_num(area.hi[0]),
                fmt_num(area.lo[1]),
                fmt_num(area.hi[1]),
                fmt_num(area.lo[2]),
                fmt_num(area.hi[2])
            ),
        )
    }

    /// The travel limits of the machine axes at machine point `m`.
    fn check_travel(&self, m: &Pos, at: u32) -> R<()> {
        let Some((ax, v, (min, max))) = self.cfg.outside_travel(m) else {
            return Ok(());
        };
        let side = if v > max { '+' } else { '-' };
        Err(self.alarm(
            AlarmKind::Overtravel,
            at,
            format!(
                "overtravel {side}{}: machine {} = {:.3} outside [{}, {}]",
                ax.name().to_uppercase(),
                ax.name().to_uppercase(),
                v,
                min,
                max
            ),
        ))
    }

    /// Travel and stroke for the straight move from the position to `mto`.
    fn check_line(&self, mto: &Pos, line: Line, at: u32) -> R<()> {
        self.check_travel(mto, at)?;
        self.check_stroke(&self.frames.mover.pos, mto, line, at)
    }

    /// Takes the position `mto` and emits `cmd` (already checked).
    #[inline(always)]
    fn commit(&mut self, mto: Pos, cmd: Canon) {
        self.frames.mover.pos = mto;
        self.emit_here(cmd);
    }

    fn motion_to(&self, mto: Pos) -> Motion {
        Motion {
            to: self.work_of(&mto),
            mto,
        }
    }

    // ---- straight moves ------------------------------------------------------------

    /// A straight move to `tw` (program coordinates) at `speed`: a rapid,
    /// the modal feed, or a feed fixed earlier (the parts of a ,C/,R move
    /// keep the feed of their own block). `at` positions any alarm.
    pub(super) fn line_to(&mut self, tw: Pos, speed: Speed, at: u32) -> R<()> {
        let mto = self.to_machine(&tw);
        let line = match speed {
            Speed::Rapid => Line::Rapid,
            _ => Line::Straight,
        };
        self.check_line(&mto, line, at)?;
        let m = self.motion_to(mto);
        let cmd = match speed {
            Speed::Rapid => Canon::Rapid {
                m,
                linear: self.linear_rapid(),
            },
            Speed::Modal => Canon::Feed {
                m,
                feed: self.feed(at)?,
            },
            Speed::Feed(feed) => Canon::Feed { m, feed },
        };
        self.commit(mto, cmd);
        Ok(())
    }

    /// A rapid to machine point `mto` (G53, the reference returns);
    /// nothing is emitted when the tool is already there, the limits are
    /// checked either way.
    pub(super) fn rapid_machine(&mut self, mto: Pos, at: u32) -> R<()> {
        self.check_line(&mto, Line::Rapid, at)?;
        if mto != self.frames.mover.pos {
            let m = self.motion_to(mto);
            let linear = self.linear_rapid();
            self.commit(mto, Canon::Rapid { m, linear });
        }
        Ok(())
    }

    /// G53: a rapid to machine point `mto`, emitted even when the tool is
    /// there.
    pub(super) fn rapid_machine_always(&mut self, mto: Pos, at: u32) -> R<()> {
        self.check_line(&mto, Line::Rapid, at)?;
        let m = self.motion_to(mto);
        let linear = self.linear_rapid();
        self.commit(mto, Canon::Rapid { m, linear });
        Ok(())
    }

    /// An arc with R whose plane end point equals its start: only the other
    /// axes move (helical with zero sweep), as a feed.
    pub(super) fn linear_only(&mut self, tw: Pos) -> R<()> {
        let at = self.motion_at();
        let mto = self.to_machine(&tw);
        if mto == self.frames.mover.pos {
            return Ok(());
        }
        self.check_line(&mto, Line::Straight, at)?;
        let feed = self.feed(at)?;
        let m = self.motion_to(mto);
        self.commit(mto, Canon::Feed { m, feed });
        Ok(())
    }

    /// A spindle-synchronised straight move to `tw` (program coordinates)
    /// with lead `lead` (mm/rev): HX G33, PUMA G32/G92/G76, Hurco G33/G78.
    pub(super) fn thread_move(&mut self, tw: Pos, lead: f64, at: u32) -> R<()> {
        let mto = self.to_machine(&tw);
        self.check_line(&mto, Line::Straight, at)?;
        let m = self.motion_to(mto);
        self.commit(mto, Canon::Thread { m, lead });
        Ok(())
    }

    /// G112 / G107: the chain of feed chords through `points` (program
    /// coordinates). Every chord is checked, in order, before the first is
    /// committed, so a path that reaches the forbidden area or a travel
    /// limit alarms before the block moves.
    pub(super) fn chords(&mut self, points: &[Pos], feed: Feed, at: u32) -> R<()> {
        let mut from = self.frames.mover.pos;
        let mut mtos = Vec::with_capacity(points.len());
        for p in points {
            let mto = self.to_machine(p);
            self.check_travel(&mto, at)?;
            self.check_stroke(&from, &mto, Line::Straight, at)?;
            from = mto;
            mtos.push(mto);
        }
        for mto in mtos {
            let m = self.motion_to(mto);
            self.commit(mto, Canon::Feed { m, feed });
        }
        Ok(())
    }

    // ---- arcs ----------------------------------------------------------------------

    /// An arc from `start` to `tw` (program coordinates) about `center`
    /// (in the plane) at `feed`: travel-checked (the arc's extremes in the
    /// plane, the end point elsewhere), stroke-checked along its path and
    /// emitted. The axes outside the plane move linearly (helix).
    pub(super) fn arc_to(
        &mut self,
        start: Pos,
        tw: Pos,
        center: (f64, f64),
        ccw: bool,
        feed: Feed,
        at: u32,
    ) -> R<()> {
        let plane = self.modal.plane.means;
        let (a1, a2, _) = plane.axes();
        let (cur, tw, center, ccw) = self.transform_arc(start, tw, center, ccw, at)?;
        let s = (cur[a1], cur[a2]);
        let e = (tw[a1], tw[a2]);
        let (u0, v0, u1, v1) = arc::bbox(s, e, center, ccw);
        for (u, v) in [(u0, v0), (u1, v1)] {
            let mut p = tw;
            p[a1] = u;
            p[a2] = v;
            self.check_travel(&self.offset_to_machine(&p), at)?;
        }
        let mto = self.offset_to_machine(&tw);
        self.check_travel(&mto, at)?;
        let mut c = cur;
        c[a1] = center.0;
        c[a2] = center.1;
        let mcenter = self.offset_to_machine(&c);
        if let Some(area) = self.stroke_check_area() {
            let sw = arc::sweep(s, e, center, ccw);
            let pts = crate::stroke::arc_points(
                &self.frames.mover.pos,
                &mto,
                (mcenter[a1], mcenter[a2]),
                (a1, a2),
                if ccw { sw } else { -sw },
                1e-4,
            );
            if pts.windows(2).any(|w| area.segment_enters(&w[0], &w[1])) {
                return Err(self.stroke_alarm(&area, at));
            }
        }
        let center = self.work_of(&mcenter);
        let dir = if ccw { ArcDir::Ccw } else { ArcDir::Cw };
        let m = self.motion_to(mto);
        self.commit(
            mto,
            Canon::Arc {
                m,
                center,
                mcenter,
                dir,
                plane,
                turns: 0,
                feed,
            },
        );
        Ok(())
    }

    // ---- path stages ---------------------------------------------------------------

    /// A held move's programmed end `tw` (program coordinates) becomes the
    /// position the next block starts from; nothing is emitted (the stage
    /// commits the move's pieces later, checked).
    pub(super) fn place_at(&mut self, tw: &Pos) {
        self.frames.mover.pos = self.to_machine(tw);
    }

    /// Sets the position to machine point `m` without a move (a stage's
    /// start off the programmed point, or the position restored after a
    /// stage has committed or captured its pieces); returns the position
    /// before.
    pub(super) fn place_machine(&mut self, m: Pos) -> Pos {
        std::mem::replace(&mut self.frames.mover.pos, m)
    }

    /// The events held behind a compensated move, released at its corner:
    /// their moves keep their own off-plane coordinates and take the
    /// corner's plane point `corner` (machine coordinates); each is checked
    /// from where the one before ends, and the position is the last one's.
    pub(super) fn release_held(&mut self, events: &mut Vec<Event>, corner: &Pos) -> R<()> {
        let (a1, a2, _) = self.modal.plane.means.axes();
        let mut from = self.frames.mover.pos;
        for ev in events.iter_mut() {
            let line = match ev.cmd {
                Canon::Rapid { .. } => Line::Rapid,
                _ => Line::Straight,
            };
            if let Canon::Rapid { m, .. } | Canon::Feed { m, .. } = &mut ev.cmd {
                ev.prog = Some(Box::new(m.to));
                m.mto[a1] = corner[a1];
                m.mto[a2] = corner[a2];
                m.to = self.work_of(&m.mto);
                let mto = m.mto;
                self.check_travel(&mto, 0)?;
                self.check_stroke(&from, &mto, line, 0)?;
                from = mto;
            }
        }
        if let Some(last) = events.iter().rev().find_map(|e| e.motion()) {
            self.frames.mover.pos = last.mto;
        }
        self.queue.extend(events.drain(..));
        Ok(())
    }
}

/// The lathe and Hurco cycles through the seam. Neither lathe control
/// executes G22 (the PUMA's is not supported yet, the Hurco has none), so
/// these tests put an area on the interpreter directly: a "chuck jaw" in
/// machine coordinates that the cycle's path must cross. Machine X is the
/// radius; the PUMA's G54 is machine Z -529, the Hurco's Z -400.
#[cfg(test)]
mod tests {
    use super::*;
    use crate::stroke::Area;
    use crate::{run_interp, Profile};

    const INF: f64 = f64::INFINITY;

    /// Runs `text` on `machine` with the area X `x`, Z `z` (machine, Y
    /// unlimited) and returns the alarm's line, or None. Without the area
    /// the program must run to its end.
    fn stroke_line(machine: &str, x: (f64, f64), z: (f64, f64), text: &str) -> Option<u32> {
        let plain = crate::run_text(
            Profile::builtin(machine).unwrap(),
            Settings::default(),
            "t.nc",
            text,
        );
        assert!(plain.alarm.is_none(), "{text}: {:?}", plain.alarm);
        let mut it = Interp::new(Profile::builtin(machine).unwrap(), Settings::default());
        it.frames.stroke_area = Some(Area {
            lo: [x.0, -INF, z.0],
            hi: [x.1, INF, z.1],
            outside: false,
        });
        let r = run_interp(it, "t.nc", text);
        let a = r.alarm?;
        assert!(
            a.message.starts_with("stored stroke check"),
            "{text}: {a:?}"
        );
        Some(a.src.line)
    }

    /// The jaw on the PUMA: radius 15…25 (Ø30…50), work Z -30…-20.
    fn puma(text: &str) -> Option<u32> {
        stroke_line("puma-lathe", (15.0, 25.0), (-559.0, -549.0), text)
    }

    #[test]
    fn puma_moves_and_single_cycles() {
        // G01 along Ø40 (radius 20) from Z5 to Z-50: through Z -20…-30.
        assert_eq!(puma("G00 X40. Z5.\nG01 Z-50. F0.2\n"), Some(2));
        // Beside the jaw (Ø60): no alarm.
        assert_eq!(puma("G00 X60. Z5.\nG01 Z-50. F0.2\n"), None);
        // G90: rapid to Ø40, cut along Z to -50: through the jaw.
        assert_eq!(puma("G00 X100. Z5.\nG90 X40. Z-50. F0.2\n"), Some(2));
        // G94: rapid to Z-25, face from Ø100 to Ø0: through radius 25…15.
        assert_eq!(puma("G00 X100. Z5.\nG94 X0. Z-25. F0.2\n"), Some(2));
        // G92 and G32 threads along Ø40.
        let g92 = "G97 S500 M03\nG00 X60. Z5.\nG92 X40. Z-50. F2.\n";
        assert_eq!(puma(g92), Some(3));
        let g32 = "G97 S500 M03\nG00 X40. Z5.\nG32 Z-50. F2.\n";
        assert_eq!(puma(g32), Some(3));
        // Direct corner R: the first leg along Ø40 already crosses.
        let ddi = "G00 X40. Z5.\nG01 Z-50. R2. F0.2\nX100.\n";
        assert_eq!(puma(ddi), Some(2));
    }

    /// The shape Ø40 from Z0 to Z-50, then out to Ø100.
    const SHAPE: &str = "N10 G00 X40.\nN20 G01 Z-50. F0.2\nN30 X100.\n";

    #[test]
    fn puma_multiple_repetitive_cycles() {
        // G71 roughs down in 2 mm (radius) steps from Ø100: the passes
        // at radius 25 and below run along Z through the jaw.
        let g71 = format!(
            "G97 S500 M03\nG00 X100. Z5.\nG71 U2. R0.5\nG71 P10 Q30 U0.4 W0.1 F0.25\n{SHAPE}"
        );
        assert_eq!(puma(&g71), Some(4));
        // G70 follows the shape itself: N20 along Ø40.
        let g70 = format!("G97 S500 M03\nG00 X100. Z5.\nG70 P10 Q30\n{SHAPE}");
        assert_eq!(puma(&g70), Some(3));
        // G76 threads along Ø36…40.
        let g76 =
            "G97 S600 M03\nG00 X60. Z5.\nG76 P011060 Q100 R0.05\nG76 X36. Z-50. P2000 Q500 F2.\n";
        assert_eq!(puma(g76), Some(4));
    }

    #[test]
    fn puma_nose_radius_compensation() {
        // G42 with a 0.8 nose radius (tip 3): the compensated Ø40 line
        // runs through the jaw; it is committed at the next move, as the
        // held block's (line 4).
        let mut it = Interp::new(Profile::builtin("puma-lathe").unwrap(), Settings::default());
        let o = it.offsets_mut().lathe_mut(1).unwrap();
        o.r = 0.8;
        o.tip = 3;
        it.frames.stroke_area = Some(Area {
            lo: [15.0, -INF, -559.0],
            hi: [25.0, INF, -549.0],
            outside: false,
        });
        let text = "T0101\nG00 X100. Z5.\nG42 G01 X40. Z2. F0.2\nZ-50.\nG40 X100.\n";
        let a = run_interp(it, "t.nc", text).alarm.expect("an alarm");
        assert!(a.message.starts_with("stored stroke check"), "{a:?}");
        assert_eq!(a.src.line, 4);
    }

    #[test]
    fn hurco_cycles() {
        // The Hurco's G54 is machine Z -400: the jaw at work Z -30…-20.
        let jaw = |t: &str| stroke_line("hurco-lathe", (15.0, 25.0), (-430.0, -420.0), t);
        // G33 along Ø40.
        assert_eq!(
            jaw("G21 G90 M03 S120\nG0 X40. Z5.\nG33 Z-50. K2.\n"),
            Some(3)
        );
        // G78 threading at radius 18…20 from Z5 to Z-50.
        let g78 = "G21 G90 M03 S120\nG0 X60. Z10.\nG78 X18. J2. Z-50. K5. F2. D.5 E.3 P1 L.1 R0\n";
        assert_eq!(jaw(g78), Some(3));
        // G81 on the axis: the drill feeds from R1 to Z-50 at X0.
        let drill = |t: &str| stroke_line("hurco-lathe", (-5.0, 5.0), (-430.0, -420.0), t);
        assert_eq!(
            drill("G21 G90\nG0 X0. Z5.\nG81 X0. Z-50. R1. F0.2\n"),
            Some(3)
        );
        // G38 S0 X5 (inch, Ø) from Ø10 at Z5: the probe runs in X at work
        // Z 5 in = 127 mm (machine -273) from radius 127 mm towards 63.5
        // mm, through radius 70…120.
        let mut s = Settings::default();
        s.probe[0] = Some(5.0);
        let mut it = Interp::new(Profile::builtin("hurco-lathe").unwrap(), s);
        it.frames.stroke_area = Some(Area {
            lo: [70.0, -INF, -280.0],
            hi: [120.0, INF, -265.0],
            outside: false,
        });
        let text = "G20\nH00\nG00 G40 X10 Z5\nG38 S0 X5 A.5 T.125 V20 F10\n";
        let a = run_interp(it, "t.nc", text).alarm.expect("an alarm");
        assert!(a.message.starts_with("stored stroke check"), "{a:?}");
        assert_eq!(a.src.line, 4);
    }
}
