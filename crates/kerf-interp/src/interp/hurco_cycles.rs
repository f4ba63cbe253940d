//! Hurco MAX drill cycles (002 G73, G74, G80-G84, G98/G99) along Z.
//!
//! - The init plane is the Z of the first cycle after G80 (or after the
//!   start); later cycles keep it even when the tool was moved elsewhere
//!   (002 G98, examples N010-N050).
//! - The R plane: the block's R, else the modal R; when no R was ever
//!   programmed, the init plane of the first cycle, which then stays the R
//!   plane. G80 clears Z, Q, P and A and the init plane, not the R plane:
//!   002's second N010-N050 example rapids to the first cycle's Z10 after
//!   `G80 Z20` (docs/dialects.md).
//! - Depth Z: the block's or the modal one; none since G80 = the R plane.
//! - Each cycle: rapid X, rapid to R, the cycle's own moves, return to the
//!   init plane (G98) or R (G99).

use super::motion::Speed;
use super::*;
use crate::dialect::meaning::HoleCycle;

/// Modal drill cycle data (program coordinates, mm).
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Drill {
    /// Init plane (Z of the first cycle after G80).
    pub init: Option<f64>,
    /// R plane.
    pub r: Option<f64>,
    /// Depth.
    pub z: Option<f64>,
    /// Peck depth (G73/G83) or tapping in-feed (G84/G74).
    pub q: Option<f64>,
    /// Dwell (seconds in G93/G94, revolutions in G95).
    pub p: Option<f64>,
    /// G73 back-off distance.
    pub a: Option<f64>,
}

impl Interp {
    /// G80 in the block: cancels the cycle, selects G00 (not allowed with
    /// G00 in the block) and clears the modal data but the R plane.
    /// Returns whether a cycle is modal for this block's motion.
    pub(super) fn hurco_cycle_mode(&mut self, motion: Option<(u16, u32)>) -> R<bool> {
        if self.block_g(|m| m == Means::Cycle(None)).is_some() {
            if let Some((0, at)) = motion {
                return Err(self.alarm(
                    AlarmKind::HurcoMode,
                    at,
                    "G00 cannot be programmed in a G80 block",
                ));
            }
            if motion.is_none() {
                self.modal
                    .set_meaning(self.cfg.dialect, Means::Motion(MotionMode::Rapid));
            }
            let r = self.hurco.drill.r;
            self.hurco.drill = Drill {
                r,
                ..Drill::default()
            };
            return Ok(false);
        }
        Ok(self.modal.cycle.means.is_some() && motion.is_none())
    }

    /// A length word in mm (no diameter rule).
    fn len_word(&self, w: WVal) -> f64 {
        self.linear(w)
    }

    /// One drill cycle (the block's X/Z/R/Q/P/A and the modal data).
    pub(super) fn hurco_drill(&mut self) -> R<()> {
        let code = self.modal.cycle.code10;
        let Some(kind) = self.modal.cycle.means else {
            return Ok(());
        };
        let at = self
            .block_g(|m| matches!(m, Means::Cycle(Some(_))))
            .map_or(0, |g| g.1);
        self.drill_qpa()?;
        let cur = self.prog_pos();
        let init = *self.hurco.drill.init.get_or_insert(cur[2]);
        if let Some(w) = self.words.get(b'R') {
            self.check_range(b'R', w)?;
            let v = self.len_word(w);
            self.hurco.drill.r = Some(if self.modal.absolute() { v } else { init + v });
        }
        let r = *self.hurco.drill.r.get_or_insert(init);
        if let Some(w) = self.words.get(b'Z') {
            self.check_range(b'Z', w)?;
            let v = self.len_word(w);
            self.hurco.drill.z = Some(if self.modal.absolute() { v } else { r + v });
        }
        let z = self.hurco.drill.z.unwrap_or(r);
        let mut x = cur[0];
        if let Some(w) = self.words.get(b'X') {
            self.check_range(b'X', w)?;
            let v = self.axis_value(Axis::X, w);
            x = if self.modal.absolute() { v } else { cur[0] + v };
        }
        let d = self.hurco.drill;
        let ret = if self.modal.cycle_return.means == CycleReturn::RPoint {
            r
        } else {
            init
        };
        // 1. Position X, 2. rapid to the R plane.
        self.drill_go(Speed::Rapid, Some(x), None, at)?;
        self.drill_go(Speed::Rapid, None, Some(r), at)?;
        let dir = if z < r { -1.0 } else { 1.0 };
        let clear = self.cfg.profile.param("peck_clearance_mm", 0.254);
        match kind {
            HoleCycle::Drill | HoleCycle::DrillDwell => {
                self.drill_go(Speed::Modal, None, Some(z), at)?;
                if kind == HoleCycle::DrillDwell {
                    self.drill_dwell(d.p.unwrap_or(0.0));
                }
                self.drill_go(Speed::Rapid, None, Some(ret), at)?;
            }
            HoleCycle::PeckChipBreak | HoleCycle::Peck => {
                let q = match d.q {
                    Some(q) if q > 0.0 => q,
                    _ => {
                        return Err(self.alarm(
                            AlarmKind::MissingArgument,
                            at,
                            format!("G{} needs a peck depth Q > 0", code / 10),
                        ))
                    }
                };
                let n = ((z - r).abs() / q).ceil().max(1.0);
                if n > 10_000.0 {
                    return Err(self.alarm(AlarmKind::OutOfRange, at, "more than 10,000 pecks"));
                }
                let mut last = r;
                for k in 1..=n as u64 {
                    let depth = if k as f64 >= n {
                        z
                    } else {
                        r + dir * q * k as f64
                    };
                    if k > 1 {
                        // Rapid to just short of the last depth.
                        self.drill_go(Speed::Rapid, None, Some(last - dir * clear), at)?;
                    }
                    self.drill_go(Speed::Modal, None, Some(depth), at)?;
                    last = depth;
                    if k as f64 >= n {
                        break;
                    }
                    if kind == HoleCycle::Peck {
                        self.drill_go(Speed::Rapid, None, Some(r), at)?;
                    } else {
                        let a = d.a.unwrap_or(clear);
                        self.drill_go(Speed::Rapid, None, Some(depth - dir * a), at)?;
                    }
                }
                self.drill_go(Speed::Rapid, None, Some(ret), at)?;
            }
            HoleCycle::Tap | HoleCycle::TapLeft => self.drill_tap(kind, (r, z, ret), at)?,
            // Not Hurco cycles.
            _ => {}
        }
        Ok(())
    }

    /// The block's Q, P and A: modal drill data.
    fn drill_qpa(&mut self) -> R<()> {
        for l in [b'Q', b'P', b'A'] {
            if let Some(w) = self.words.get(l) {
                self.check_range(l, w)?;
                if w.v < 0.0 {
                    return Err(self.alarm(
                        AlarmKind::OutOfRange,
                        w.at,
                        format!("{} must not be negative in a drill cycle", l as char),
                    ));
                }
                let v = if l == b'P' { w.v } else { self.len_word(w) };
                match l {
                    b'Q' => self.hurco.drill.q = Some(v),
                    b'P' => self.hurco.drill.p = Some(v),
                    _ => self.hurco.drill.a = Some(v),
                }
            }
        }
        Ok(())
    }

    /// G84 / G74 tapping from R to Z (Q in-feeds), back to `ret`.
    fn drill_tap(&mut self, kind: HoleCycle, levels: (f64, f64, f64), at: u32) -> R<()> {
        let (r, z, ret) = levels;
        let d = self.hurco.drill;
        let dir = if z < r { -1.0 } else { 1.0 };
        let (fwd, rev) = if kind.left_hand() {
            (SpindleDir::Ccw, SpindleDir::Cw)
        } else {
            (SpindleDir::Cw, SpindleDir::Ccw)
        };
        let q = d.q.unwrap_or(0.0);
        let n = if q > 0.0 {
            ((z - r).abs() / q).ceil().max(1.0)
        } else {
            1.0
        };
        if n > 10_000.0 {
            return Err(self.alarm(AlarmKind::OutOfRange, at, "more than 10,000 in-feeds"));
        }
        if self.tool.spindle != fwd {
            self.drill_spindle(fwd);
        }
        for k in 1..=n as u64 {
            let depth = if k as f64 >= n {
                z
            } else {
                r + dir * q * k as f64
            };
            self.drill_go(Speed::Modal, None, Some(depth), at)?;
            self.drill_spindle(rev);
            self.drill_dwell(d.p.unwrap_or(0.0));
            self.drill_go(Speed::Modal, None, Some(r), at)?;
            self.drill_spindle(fwd);
        }
        self.drill_go(Speed::Rapid, None, Some(ret), at)?;
        Ok(())
    }

    /// A move of X and/or Z (program coordinates) unless already there.
    fn drill_go(&mut self, speed: Speed, x: Option<f64>, z: Option<f64>, at: u32) -> R<()> {
        let cur = self.prog_pos();
        let mut p = cur;
        if let Some(x) = x {
            p[0] = x;
        }
        if let Some(z) = z {
            p[2] = z;
        }
        if (p[0] - cur[0]).abs() < 1e-9 && (p[2] - cur[2]).abs() < 1e-9 {
            return Ok(());
        }
        self.line_to(p, speed, at)
    }

    fn drill_dwell(&mut self, p: f64) {
        if p <= 0.0 {
            return;
        }
        let (seconds, revolutions) = if self.modal.feed_mode.means == FeedMode::PerRev {
            (0.0, p)
        } else {
            (p, 0.0)
        };
        self.emit(Canon::Dwell {
            seconds,
            revolutions,
        });
    }

    fn drill_spindle(&mut self, dir: SpindleDir) {
        self.tool.spindle = dir;
        let rpm = self.rpm();
        self.tool.last_rpm = rpm;
        let css = self.css_speed();
        self.emit(Canon::Spindle { dir, rpm, css });
    }
}
