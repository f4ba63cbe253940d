//! Skip and measurement on the HX: G31 / G31.1-G31.4 (000 §4.9) and G37 /
//! G37.1-G37.4 automatic tool length measurement (000 §4.10), against a
//! simulated skip signal: the run declares where the probe touches
//! ([`Settings::skip`], `--set skip.z=-12.5`).

use super::motion::Speed;
use super::*;

impl Interp {
    /// The trip coordinates of skip signal `n` (0 = G31/G37, 1-4 =
    /// G31.n/G37.n), each axis falling back to signal 0's.
    fn trip(&self, n: usize) -> [Option<f64>; NAXES] {
        let mut t = self.settings.skip[n];
        for (i, v) in t.iter_mut().enumerate() {
            if v.is_none() {
                *v = self.settings.skip[0][i];
            }
        }
        t
    }

    /// Where along `from`→`to` (program coordinates) the signal comes:
    /// the first point at which a declared axis reaches its trip value.
    fn contact(&self, n: usize, from: &Pos, to: &Pos) -> Option<Pos> {
        let trip = self.trip(n);
        let mut best: Option<f64> = None;
        for i in 0..NAXES {
            let Some(v) = trip[i] else { continue };
            let d = to[i] - from[i];
            if d.abs() < 1e-12 {
                continue;
            }
            let t = (v - from[i]) / d;
            if t > 1e-12 && t <= 1.0 + 1e-12 && best.is_none_or(|b| t < b) {
                best = Some(t.min(1.0));
            }
        }
        best.map(|t| {
            let mut p = *from;
            for i in 0..NAXES {
                p[i] += (to[i] - from[i]) * t;
            }
            p
        })
    }

    /// A G31/G37 block.
    pub(super) fn skip_block(&mut self, c: u16, at: u32) -> R<()> {
        if c >= 370 {
            self.g37(c, at)
        } else {
            self.g31(c, at)
        }
    }

    /// G31 X_ Y_ Z_ F_: a feed move (as G01) that stops where the skip
    /// signal comes; the rest of the move is abandoned and the position
    /// is kept for #5061- / #6319-. No signal during the move alarms.
    fn g31(&mut self, c: u16, at: u32) -> R<()> {
        let (tw, any) = self.target()?;
        if !any {
            return Err(self.alarm(
                AlarmKind::MissingArgument,
                at,
                format!("G{} without an axis to move", fmt_code(c)),
            ));
        }
        let from = self.prog_pos();
        let n = (c - 310) as usize;
        match self.contact(n, &from, &tw) {
            Some(p) => {
                self.move_line(false, p, at)?;
                self.frames.skip_pos = Some(p);
                Ok(())
            }
            None => Err(self.alarm(
                AlarmKind::NoContact,
                at,
                format!(
                    "G{}: no skip signal during the move (declare the contact with --set skip.z=…)",
                    fmt_code(c)
                ),
            )),
        }
    }

    /// `G37 Z_`: automatic tool length measurement (000 §4.10). Rapid to
    /// r (PI 141, mm) before the measurement position, then at the
    /// measuring feed (PI 143, mm/min) toward it until the signal, at
    /// most e (PI 142, mm) beyond it; the contact must lie within ±e of
    /// the measurement position (else F_84022). The active H offset
    /// changes by (contact − measurement position); the tool stays at the
    /// contact point, which then reads as the measurement position.
    fn g37(&mut self, c: u16, at: u32) -> R<()> {
        for l in [b'X', b'Y'] {
            if let Some(w) = self.words.get(l) {
                return Err(self.alarm(
                    AlarmKind::OutOfRange,
                    w.at,
                    "G37 measures the tool length along Z on this machine",
                ));
            }
        }
        let Some(zw) = self.words.get(b'Z') else {
            return Err(self.alarm(
                AlarmKind::MissingArgument,
                at,
                format!("G{} without the measurement position Z", fmt_code(c)),
            ));
        };
        if self.frames.h == 0 {
            return Err(self.alarm(
                AlarmKind::MissingArgument,
                at,
                "G37 needs an active tool length offset number (G43 H_)",
            ));
        }
        let (tw, _) = self.target()?;
        let zi = Axis::Z as usize;
        let meas = tw[zi];
        let from = self.prog_pos();
        let r = self.cfg.profile.param("PI 141", 10.0);
        let e = self.cfg.profile.param("PI 142", 1.0);
        let feed = self.cfg.profile.param("PI 143", 100.0);
        let dir = if meas >= from[zi] { 1.0 } else { -1.0 };
        // Rapid to r before the measurement position (when further away).
        let mut p = from;
        if (meas - from[zi]).abs() > r {
            p[zi] = meas - dir * r;
            self.move_line(true, p, zw.at)?;
        }
        let mut end = p;
        end[zi] = meas + dir * e;
        let Some(hit) = self.contact((c - 370) as usize, &p, &end) else {
            return Err(self.alarm(
                AlarmKind::NoContact,
                at,
                format!(
                    "G{}: no measurement signal within ±{} of Z{} (F_84022; declare the contact with --set skip.z=…)",
                    fmt_code(c),
                    fmt_num(e),
                    fmt_num(meas)
                ),
            ));
        };
        if (hit[zi] - meas).abs() > e + 1e-9 {
            return Err(self.alarm(
                AlarmKind::NoContact,
                at,
                format!(
                    "G{}: contact at Z{} is outside ±{} of the measurement position Z{}",
                    fmt_code(c),
                    fmt_num(hit[zi]),
                    fmt_num(e),
                    fmt_num(meas)
                ),
            ));
        }
        self.line_to(hit, Speed::Feed(Feed::PerMin(feed)), at)?;
        self.frames.skip_pos = Some(hit);
        let h = self.frames.h as usize;
        let delta = hit[zi] - meas;
        if let Some(e) = self.offsets.h_mut(h) {
            e.geom += delta;
        }
        self.refresh_tool_length();
        Ok(())
    }
}
