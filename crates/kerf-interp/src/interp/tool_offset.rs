//! G45-G48 tool position offset (HX, 000 §13.3): a one-shot change of the
//! block's move amount along each programmed axis by the D value.
//!
//! | code | move amount |
//! |------|-------------|
//! | G45  | lengthened by D |
//! | G46  | shortened by D |
//! | G47  | lengthened by 2 D |
//! | G48  | shortened by 2 D |
//!
//! "Lengthened" is along the move's own direction; a zero move (`G46 X0`
//! in G91) counts as positive, so it moves +D for G45/G47 and -D for
//! G46/G48 (000's notes on N9 and N11). A negative D reverses the effect.
//! On G02/G03 (quarter and three-quarter arcs whose ends lie on the axes
//! through the centre) the end point and the centre offsets I/J/K, or R,
//! change the same way, so the radius grows or shrinks by D. The offset
//! applies to the move amount, also in G90 (Fanuc; 000 programs it in G91).

use super::*;

impl Interp {
    /// The block's move under G45-G48: `times` D (the code's meaning) and
    /// its `code` ×10 for the alarms, `at` the code's column.
    pub(super) fn tool_offset_motion(&mut self, (times, code): (i8, u16), at: u32) -> R<()> {
        let mode = self.modal.motion.means;
        if !matches!(
            mode,
            MotionMode::Rapid | MotionMode::Linear | MotionMode::ArcCw | MotionMode::ArcCcw
        ) {
            return Err(self.alarm(
                AlarmKind::ToolOffset,
                at,
                format!("G{} needs G00, G01, G02 or G03 (000 §13.3)", fmt_code(code)),
            ));
        }
        if self.modal.cutter_comp.means != CompSide::Off {
            return Err(self.alarm(
                AlarmKind::ToolOffset,
                at,
                format!(
                    "G{} with cutter radius compensation (G41/G42) in force",
                    fmt_code(code)
                ),
            ));
        }
        let d = self.d_value(at)?;
        let amount = f64::from(times) * d;
        // A signed move `v` lengthened by `amount` along its own direction.
        let adj = |v: f64| if v < 0.0 { v - amount } else { v + amount };
        let (tw, any) = self.target()?;
        if !any {
            return Ok(());
        }
        let cur = self.prog_pos();
        let mut t = cur;
        for ax in Axis::ALL {
            let i = ax as usize;
            if self.cfg.has_axis[i] && (self.words.has(ax_letter(ax)) || self.uvw(ax).is_some()) {
                t[i] = if i < 3 {
                    cur[i] + adj(tw[i] - cur[i])
                } else {
                    tw[i]
                };
            }
        }
        let at = self.motion_at();
        match mode {
            MotionMode::Rapid | MotionMode::Linear => {
                self.move_line(mode == MotionMode::Rapid, t, at)
            }
            _ => {
                let ccw = mode == MotionMode::ArcCcw;
                let (a1, a2, _) = self.modal.plane.means.axes();
                let center =
                    if let Some(r) = self.words.get(b'R') {
                        self.check_range(b'R', r)?;
                        let rv = self.linear(r);
                        let rv = rv.signum() * adj(rv.abs());
                        let (s, e) = ((cur[a1], cur[a2]), (t[a1], t[a2]));
                        match arc::center_from_radius(s, e, rv, ccw, self.cfg.arc_tol) {
                            Ok(c) => c,
                            Err(_) => return Err(self.alarm(
                                AlarmKind::ArcRadius,
                                r.at,
                                "arc radius after the tool offset is smaller than half the chord",
                            )),
                        }
                    } else {
                        let off = |l: u8| -> R<f64> {
                            match self.words.get(l) {
                                Some(w) => {
                                    self.check_range(l, w)?;
                                    Ok(adj(self.linear(w)))
                                }
                                None => Ok(0.0),
                            }
                        };
                        let o = [off(b'I')?, off(b'J')?, off(b'K')?];
                        if o == [0.0; 3]
                            && !self.words.has(b'I')
                            && !self.words.has(b'J')
                            && !self.words.has(b'K')
                        {
                            return Err(self.alarm(
                                AlarmKind::ArcNoCenter,
                                at,
                                "arc without centre (I/J/K) or radius (R)",
                            ));
                        }
                        (cur[a1] + o[a1.min(2)], cur[a2] + o[a2.min(2)])
                    };
                let s = (cur[a1], cur[a2]);
                let e = (t[a1], t[a2]);
                if let Err(ArcError::EndNotOnCircle { r_start, r_end }) =
                    arc::check_end(s, e, center, self.cfg.arc_tol)
                {
                    return Err(self.alarm(
                        AlarmKind::ArcEndPoint,
                        at,
                        format!(
                            "G{}: the offset arc's end is not on its circle (start radius {r_start:.4}, end radius {r_end:.4}): only quarter and three-quarter arcs on the axes can be offset",
                            fmt_code(code)
                        ),
                    ));
                }
                let feed = self.feed(at)?;
                self.arc_to(cur, t, center, ccw, feed, at)
            }
        }
    }

    /// The cutter radius offset of the D number in force (mm); D out of
    /// range is an alarm at the D word (or `at`).
    pub(super) fn d_value(&self, at: u32) -> R<f64> {
        let n = self.sys.d;
        let at = self.words.get(b'D').map_or(at, |w| w.at);
        if n < 0.0 || n.fract() != 0.0 || !self.offsets.valid(n as usize) {
            return Err(self.alarm(
                AlarmKind::OutOfRange,
                at,
                format!(
                    "D{} is not an offset number (D00-D{})",
                    fmt_num(n),
                    self.offsets.count()
                ),
            ));
        }
        Ok(self.offsets.d(n as usize))
    }
}
