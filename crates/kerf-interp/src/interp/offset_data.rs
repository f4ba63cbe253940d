//! `G10` programmable data input: work offsets and tool offset memory.
//!
//! - `G10 L2 P_ X_ Y_ Z_` (Fanuc standard): P1-P6 = G54-G59 origins, P0 =
//!   the work shift (000 §7.2.4). Absolute in G90, added in G91.
//! - `G10 L10/L11 P_ R_` (HX 000 §13.1.3 / Fanuc): H geometry / H wear;
//!   `G10 L12/L13 P_ R_`: D geometry / D wear. G90 replaces, G91 adds
//!   (000: `G10 G91 L10 P1 R-0.5` takes 0.5 from H1).
//! - Lathe (Fanuc 0-T, fanuc-semantics §5.3): `G10 P_ X_ Z_ R_ Q_` or
//!   `U_ W_ C_`: P1-Pn = wear offsets, P10001-P(10000+n) = geometry, P0 =
//!   work shift. X/Z/R replace, U/W/C add, Q = imaginary tip direction. X
//!   and U are diameters under diameter programming.
//!
//! Writing an offset that is in force does not move the tool; the new
//! value is used when the program selects the offset again (G43 H, T
//! code), as on the control.

use super::*;

impl Interp {
    /// G10 on the HX (called from `transform_codes`) and the lathes.
    pub(super) fn g10(&mut self, at: u32) -> R<()> {
        if self.cfg.profile.kind == MachineKind::Lathe {
            return self.g10_lathe(at);
        }
        let Some(l) = self.words.get(b'L') else {
            return Err(self.alarm(
                AlarmKind::MissingArgument,
                at,
                "G10 without L (L2 = work offset, L10/L11 = H, L12/L13 = D)",
            ));
        };
        match l.v {
            2.0 => self.g10_l2(at),
            10.0..=13.0 if l.v.fract() == 0.0 => self.g10_mill_offset(l.v as u32, at),
            _ => Err(self.alarm(
                AlarmKind::OutOfRange,
                l.at,
                format!(
                    "G10 L{}: L2 (work offset), L10/L11 (H geometry/wear), L12/L13 (D geometry/wear)",
                    fmt_num(l.v)
                ),
            )),
        }
    }

    /// The P word as an integer in `range`, or an alarm naming `what`.
    fn g10_p(&self, at: u32, range: std::ops::RangeInclusive<f64>, what: &str) -> R<usize> {
        match self.words.get(b'P') {
            Some(p) if p.v.fract() == 0.0 && range.contains(&p.v) => Ok(p.v as usize),
            Some(p) => Err(self.alarm(AlarmKind::OutOfRange, p.at, what.to_string())),
            None => Err(self.alarm(
                AlarmKind::MissingArgument,
                at,
                format!("G10 without P ({what})"),
            )),
        }
    }

    fn g10_l2(&mut self, at: u32) -> R<()> {
        let p = self.g10_p(
            at,
            0.0..=6.0,
            "G10 L2 P must be 0 (work shift) or 1-6 (G54-G59)",
        )?;
        for ax in Axis::ALL {
            let i = ax as usize;
            if !self.cfg.has_axis[i] {
                continue;
            }
            // Absolute words replace (G91 on the HX adds); the lathe's
            // U/W add.
            let (w, add) = match (self.words.get(ax_letter(ax)), self.uvw(ax)) {
                (Some(w), _) => (w, !self.modal.absolute()),
                (None, Some(l)) => (self.words.get(l).expect("present"), true),
                (None, None) => continue,
            };
            let v = self.axis_value(ax, w);
            let slot = if p == 0 {
                &mut self.frames.shift_mut()[i]
            } else {
                match self.frames.work_mut().g5x_mut(p - 1) {
                    Some(w) => &mut w[i],
                    None => continue,
                }
            };
            *slot = if add { *slot + v } else { v };
        }
        Ok(())
    }

    /// `G10 L10-L13 P_ R_`: H/D geometry or wear.
    fn g10_mill_offset(&mut self, l: u32, at: u32) -> R<()> {
        let count = self.offsets.count();
        let page = if l <= 11 { 'H' } else { 'D' };
        let p = self.g10_p(
            at,
            1.0..=count as f64,
            &format!("G10 L{l} P must be an offset number {page}1-{page}{count}"),
        )?;
        let Some(r) = self.words.get(b'R') else {
            return Err(self.alarm(
                AlarmKind::MissingArgument,
                at,
                format!("G10 L{l} without R (the offset value)"),
            ));
        };
        self.check_range(b'R', r)?;
        let v = self.linear(r);
        let absolute = self.modal.absolute();
        let e = if page == 'H' {
            self.offsets.h_mut(p)
        } else {
            self.offsets.d_mut(p)
        }
        .expect("offset number checked");
        let slot = if matches!(l, 10 | 12) {
            &mut e.geom
        } else {
            &mut e.wear
        };
        *slot = if absolute { v } else { *slot + v };
        Ok(())
    }

    /// `G10 P_ X_ Z_ R_ Q_` / `U_ W_ C_` on a lathe.
    fn g10_lathe(&mut self, at: u32) -> R<()> {
        // `G10 L2 P1-P6 X Z` (U W add): the work offsets G54-G59, Fanuc
        // 0-T/16T standard (001 is silent).
        if let Some(l) = self.words.get(b'L') {
            if l.v != 2.0 {
                return Err(self.alarm(
                    AlarmKind::OutOfRange,
                    l.at,
                    format!(
                        "G10 L{}: L2 (work offset) or no L (tool offset)",
                        fmt_num(l.v)
                    ),
                ));
            }
            return self.g10_l2(at);
        }
        let count = self.offsets.count();
        let p = self.g10_p(
            at,
            0.0..=(10_000 + count) as f64,
            &format!(
                "G10 P must be 0 (work shift), 1-{count} (wear) or 10001-{} (geometry)",
                10_000 + count
            ),
        )?;
        if p == 0 {
            return self.g10_l2(at);
        }
        let geometry = p > 10_000;
        let n = if geometry { p - 10_000 } else { p };
        if n == 0 || n > count {
            let pw = self.words.get(b'P').expect("checked");
            return Err(self.alarm(
                AlarmKind::OutOfRange,
                pw.at,
                format!("G10 P{p}: no tool offset {n} (1-{count})"),
            ));
        }
        for (a, b) in [(b'X', b'U'), (b'Z', b'W'), (b'R', b'C')] {
            if let (Some(_), Some(wb)) = (self.words.get(a), self.words.get(b)) {
                return Err(self.alarm(
                    AlarmKind::DuplicateAddress,
                    wb.at,
                    format!("G10: {} and {} in one block", a as char, b as char),
                ));
            }
        }
        let x = self.g10_len(b'X', Axis::X)?;
        let u = self.g10_len(b'U', Axis::X)?;
        let z = self.g10_len(b'Z', Axis::Z)?;
        let w = self.g10_len(b'W', Axis::Z)?;
        let r = self.g10_len(b'R', Axis::Z)?;
        let c = self.g10_len(b'C', Axis::Z)?;
        let q = match self.words.get(b'Q') {
            Some(q) if q.v.fract() == 0.0 && (0.0..=9.0).contains(&q.v) => Some(q.v as u8),
            Some(q) => {
                return Err(self.alarm(
                    AlarmKind::OutOfRange,
                    q.at,
                    "G10 Q is the imaginary tool tip direction 0-9",
                ))
            }
            None => None,
        };
        let e = self.offsets.lathe_mut(n).expect("offset number checked");
        let set = |slot: &mut f64, abs: Option<f64>, inc: Option<f64>| {
            if let Some(v) = abs {
                *slot = v;
            }
            if let Some(v) = inc {
                *slot += v;
            }
        };
        if geometry {
            set(&mut e.x, x, u);
            set(&mut e.z, z, w);
            set(&mut e.r, r, c);
        } else {
            set(&mut e.wear_x, x, u);
            set(&mut e.wear_z, z, w);
            set(&mut e.wear_r, r, c);
        }
        if let Some(q) = q {
            e.tip = q;
        }
        Ok(())
    }

    /// A G10 length word in mm (X and U as a radius under diameter
    /// programming; R and C as plain lengths).
    fn g10_len(&self, l: u8, ax: Axis) -> R<Option<f64>> {
        match self.words.get(l) {
            Some(w) => {
                self.check_range(l, w)?;
                Ok(Some(self.axis_value(ax, w)))
            }
            None => Ok(None),
        }
    }
}
