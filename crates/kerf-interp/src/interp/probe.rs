//! Hurco G38 turret probe cycles (002): S0 datum, S1 set/adjust fixture
//! offset, S2 measure, S3 adjust tool offset, against a simulated part
//! surface declared with the run ([`Settings::probe`], `--set probe.x=`,
//! `--set probe.z=`, in program units, X as the program writes it in the
//! G07/G08 mode of the G38 block).
//!
//! Motion of every cycle, on the probing axis only: feed at V to the
//! approach point (expected contact ∓ A), feed at F towards expected ± T,
//! stopping at the contact, feed at V back to the start. A contact before
//! expected - T (also during the approach) or none by expected + T aborts:
//! the axis feeds back to its start at V and the run stops with NoContact
//! after those moves. The recorded data are `Canon::Message` lines in
//! 002's formats, stamped with the run's clock (`--set probe.time=`).

use super::hurco_thread::MacroParams;
use super::*;

/// Which datum slot: -X, +X, -Z, +Z.
fn datum_slot(ax: Axis, dir: f64) -> usize {
    let base = if ax == Axis::X { 0 } else { 2 };
    base + usize::from(dir > 0.0)
}

/// What G38 S1 and S3 need besides the contact.
#[derive(Clone, Copy)]
struct ProbeNumbers {
    /// S1: the fixture offset E.
    e_no: u32,
    /// S3: the tool offset H.
    h_no: usize,
    /// S1 Q1: the offset changes by the error.
    incremental: bool,
    /// S1: I/K, added to the measured position.
    adj: f64,
}

impl Interp {
    /// A value in program units from mm (X in the block's G07/G08 mode).
    fn probe_units(&self, ax: Axis, mm: f64) -> f64 {
        let mut v = mm / self.unit();
        if ax == Axis::X && self.modal.diameter.means {
            v *= 2.0;
        }
        v
    }

    /// The log stamp hh:mm:ss.
    fn stamp(&self) -> String {
        let t = self.settings.clock % 86_400;
        format!("{:02}:{:02}:{:02}", t / 3600, t / 60 % 60, t % 60)
    }

    /// A G38 block.
    pub(super) fn g38(&mut self, at: u32) -> R<()> {
        let p = self.macro_params()?;
        let (cycle, ax, ew) = self.probe_cycle_axis(&p, at)?;
        self.check_range_hurco(ax_letter(ax), ew)?;
        let i = ax as usize;
        let expected = self.axis_value(ax, ew);
        let (a, f, tol, v) = self.probe_feeds(&p, at)?;
        let probe_no = p
            .get(b'P')
            .map(|w| w.v)
            .unwrap_or_else(|| self.cfg.profile.param("probe_number", -1.0));
        let nums = self.probe_numbers(&p, cycle, ax, at)?;
        // Direction from the start towards the expected contact.
        let start = self.prog_pos();
        let dir = (expected - start[i]).signum();
        if (expected - start[i]).abs() < 1e-9 {
            return Err(self.alarm(
                AlarmKind::ProbeCycle,
                ew.at,
                "G38: the probing axis is already at the expected contact point",
            ));
        }
        let slot = datum_slot(ax, dir);
        let dname = format!(
            "{}{}",
            if dir < 0.0 { '-' } else { '+' },
            ax_letter(ax) as char
        );
        if cycle != 0
            && self.hurco.datum[slot].is_none()
            && self.cfg.profile.param("probe_require_datum", 1.0) != 0.0
        {
            return Err(self.alarm(
                AlarmKind::ProbeCycle,
                at,
                format!("G38 S{cycle}: the probe is not datumed in {dname} (run G38 S0 first)"),
            ));
        }
        // The simulated surface.
        let surface = self.settings.probe[i].map(|sv| {
            self.axis_value(
                ax,
                WVal {
                    v: sv,
                    point: true,
                    at: 0,
                },
            )
        });
        let levels = (expected - dir * a, expected, expected + dir * tol);
        let (contact, fault, stamp_pos) =
            self.probe_path(i, dir, levels, surface, (v, f, tol), at)?;
        let Some(c) = contact else {
            let msg = fault.unwrap_or_default();
            self.common.after_block =
                Some(self.alarm(AlarmKind::NoContact, at, format!("G38 S{cycle}: {msg}")));
            return Ok(());
        };
        let line = self.probe_record(
            cycle,
            ax,
            (c, expected, slot),
            &dname,
            &nums,
            stamp_pos,
            probe_no,
        );
        self.emit(Canon::Message(line));
        Ok(())
    }

    /// G38's S (the cycle 0-3) and its one probing axis with the expected
    /// contact's word.
    fn probe_cycle_axis(&self, p: &MacroParams, at: u32) -> R<(u8, Axis, WVal)> {
        let sw = p
            .get(b'S')
            .ok_or_else(|| self.alarm(AlarmKind::MissingArgument, at, "G38 needs S (cycle 0-3)"))?;
        if !(0.0..=3.0).contains(&sw.v) || sw.v.fract() != 0.0 {
            return Err(self.alarm(
                AlarmKind::ProbeCycle,
                sw.at,
                "G38 S is 0 (datum), 1 (fixture offset), 2 (measure) or 3 (tool offset)",
            ));
        }
        let cycle = sw.v as u8;
        let (ax, ew) = match (p.get(b'X'), p.get(b'Z')) {
            (Some(x), None) => (Axis::X, x),
            (None, Some(z)) => (Axis::Z, z),
            (Some(_), Some(z)) => {
                return Err(self.alarm(
                    AlarmKind::ProbeCycle,
                    z.at,
                    "G38 probes one axis: X or Z, not both",
                ))
            }
            (None, None) => {
                return Err(self.alarm(
                    AlarmKind::MissingArgument,
                    at,
                    "G38 needs X or Z (the expected contact point)",
                ))
            }
        };
        Ok((cycle, ax, ew))
    }

    /// A (approach), F (probing feed), T (tolerance), V (approach feed):
    /// the block's or the profile's, mm and mm/min.
    fn probe_feeds(&self, p: &MacroParams, at: u32) -> R<(f64, f64, f64, f64)> {
        let param = |l: u8, key: &str, what: &str| -> R<f64> {
            if let Some(w) = p.get(l) {
                if w.v <= 0.0 {
                    return Err(self.alarm(
                        AlarmKind::OutOfRange,
                        w.at,
                        format!("G38 {} ({what}) must be positive", l as char),
                    ));
                }
                return Ok(self.linear(w));
            }
            match self.cfg.profile.params.get(key) {
                Some(&v) if v > 0.0 => Ok(v),
                _ => Err(self.alarm(
                    AlarmKind::MissingArgument,
                    at,
                    format!(
                        "G38 needs {} ({what}) in the block or as `{key}` in the profile",
                        l as char
                    ),
                )),
            }
        };
        let a = param(b'A', "probe_approach", "approach distance")?;
        let f = param(b'F', "probe_feed", "probing feedrate")?;
        let tol = param(b'T', "probe_tolerance", "tolerance")?;
        let v = param(b'V', "probe_approach_feed", "approach feedrate")?;
        Ok((a, f, tol, v))
    }

    /// The numbers a cycle needs: S1 the fixture offset E (and I/K, Q1
    /// incremental), S3 the tool offset H.
    fn probe_numbers(&self, p: &MacroParams, cycle: u8, ax: Axis, at: u32) -> R<ProbeNumbers> {
        let e_no = if cycle == 1 {
            let w = p.get(b'E').ok_or_else(|| {
                self.alarm(
                    AlarmKind::MissingArgument,
                    at,
                    "G38 S1 needs E (fixture offset number)",
                )
            })?;
            if w.v < 1.0 || w.v > super::hurco::MAX_FIXTURE as f64 || w.v.fract() != 0.0 {
                return Err(self.alarm(
                    AlarmKind::OutOfRange,
                    w.at,
                    "G38 S1 E is a fixture offset number 1-9999",
                ));
            }
            w.v as u32
        } else {
            0
        };
        let h_no = if cycle == 3 {
            let w = p.get(b'H').ok_or_else(|| {
                self.alarm(
                    AlarmKind::MissingArgument,
                    at,
                    "G38 S3 needs H (tool offset number)",
                )
            })?;
            if w.v < 1.0 || w.v.fract() != 0.0 || w.v as usize > self.offsets.count() {
                return Err(self.alarm(
                    AlarmKind::OutOfRange,
                    w.at,
                    format!(
                        "G38 S3 H is a tool offset number 1-{}",
                        self.offsets.count()
                    ),
                ));
            }
            w.v as usize
        } else {
            0
        };
        let incremental = cycle == 1 && p.get(b'Q').is_some_and(|w| w.v == 1.0);
        let adj_l = if ax == Axis::X { b'I' } else { b'K' };
        let adj = if cycle == 1 {
            match p.get(adj_l) {
                Some(w) if incremental => {
                    return Err(self.alarm(
                        AlarmKind::ProbeCycle,
                        w.at,
                        format!(
                            "G38 S1: {} may only be used with absolute entry",
                            adj_l as char
                        ),
                    ))
                }
                Some(w) => self.axis_value(ax, w),
                None => 0.0,
            }
        } else {
            0.0
        };
        Ok(ProbeNumbers {
            e_no,
            h_no,
            incremental,
            adj,
        })
    }

    /// The probe's moves on axis `i` toward the contact (`dir`): at V to
    /// the approach point, at F toward the far end of the tolerance,
    /// stopping at the `surface`; back to the start at V. `levels`:
    /// (approach, expected, far). Returns the contact (None with a fault)
    /// and the position at the contact, for the record.
    #[allow(clippy::type_complexity)]
    fn probe_path(
        &mut self,
        i: usize,
        dir: f64,
        levels: (f64, f64, f64),
        surface: Option<f64>,
        feeds: (f64, f64, f64),
        at: u32,
    ) -> R<(Option<f64>, Option<String>, Pos)> {
        let (approach, expected, far) = levels;
        let (v, f, tol) = feeds;
        let ax = Axis::ALL[i];
        let start = self.prog_pos();
        let mut fault: Option<String> = None;
        let mut contact = None;
        // Approach at V (when the start is not already inside it).
        if (approach - start[i]) * dir > 0.0 {
            if let Some(c) =
                surface.filter(|&c| (c - start[i]) * dir > 0.0 && (approach - c) * dir >= 0.0)
            {
                self.probe_move(i, c, v, at)?;
                fault = Some(format!(
                    "premature probe contact at {}",
                    fmt_num(self.probe_units(ax, c))
                ));
            } else {
                self.probe_move(i, approach, v, at)?;
            }
        }
        if fault.is_none() {
            let from = self.prog_pos()[i];
            match surface.filter(|&c| (c - from) * dir > 0.0 && (far - c) * dir >= -1e-12) {
                Some(c) => {
                    self.probe_move(i, c, f, at)?;
                    if (c - expected).abs() > tol + 1e-9 {
                        fault = Some(format!(
                            "probe contact at {} outside the tolerance ±{} of {}",
                            fmt_num(self.probe_units(ax, c)),
                            fmt_num(tol / self.unit()),
                            fmt_num(self.probe_units(ax, expected))
                        ));
                    } else {
                        contact = Some(c);
                    }
                }
                None => {
                    self.probe_move(i, far, f, at)?;
                    fault = Some("no probe contact".to_string());
                }
            }
        }
        // Back to the start at V.
        let stamp_pos = self.prog_pos();
        self.probe_move(i, start[i], v, at)?;
        Ok((contact, fault, stamp_pos))
    }

    /// The data a cycle records (002's log formats) and the offsets it
    /// sets, for the contact `c` against `expected` in datum `slot`.
    #[allow(clippy::too_many_arguments)]
    fn probe_record(
        &mut self,
        cycle: u8,
        ax: Axis,
        contact: (f64, f64, usize),
        dname: &str,
        nums: &ProbeNumbers,
        stamp_pos: Pos,
        probe_no: f64,
    ) -> String {
        let (c, expected, slot) = contact;
        let i = ax as usize;
        let ProbeNumbers {
            e_no,
            h_no,
            incremental,
            adj,
        } = *nums;
        let pu = |s: &Self, mm: f64| s.probe_units(ax, mm);
        let letter = ax_letter(ax) as char;
        let stamp = self.stamp();
        match cycle {
            0 => {
                let off = expected - c;
                self.hurco.datum[slot] = Some(off);
                format!(
                    "{stamp} Probe Datum: Probe #{}; {dname} Offset {:.4} at X{:.4}, Z{:.4}",
                    fmt_num(probe_no),
                    pu(self, off),
                    self.probe_units(Axis::X, stamp_pos[0]),
                    stamp_pos[2] / self.unit()
                )
            }
            _ => {
                let measured = c + self.hurco.datum[slot].unwrap_or(0.0);
                match cycle {
                    1 => {
                        let mut fx = self.fixture_offset(e_no);
                        let old = fx[i];
                        let new = if incremental {
                            old + (measured - expected)
                        } else {
                            measured + adj
                        };
                        fx[i] = new;
                        self.set_fixture_offset(e_no, fx);
                        format!(
                            "{stamp} Probe Fixture {letter}: E{e_no} new: {:.4} old: {:.4}",
                            pu(self, new),
                            pu(self, old)
                        )
                    }
                    2 => {
                        let mut pp = self.prog_pos();
                        pp[i] = measured;
                        let mach = self.to_machine(&pp)[i];
                        format!(
                            "{stamp} Probe Measure {letter}: machine: {:.4} part: {:.4}",
                            pu(self, mach),
                            pu(self, measured)
                        )
                    }
                    _ => {
                        let delta = expected - measured;
                        let o = self.offsets.lathe(h_no);
                        let old = if ax == Axis::X {
                            o.total_x()
                        } else {
                            o.total_z()
                        };
                        let e = self.offsets.lathe_mut(h_no).expect("checked");
                        if ax == Axis::X {
                            e.wear_x += delta;
                        } else {
                            e.wear_z += delta;
                        }
                        format!(
                            "{stamp} Probe Offset {letter}: T{h_no} new: {:.4} old: {:.4}",
                            pu(self, old + delta),
                            pu(self, old)
                        )
                    }
                }
            }
        }
    }

    /// Feeds the probing axis alone to `v` (program coordinates, mm) at
    /// `feed` mm/min.
    fn probe_move(&mut self, i: usize, v: f64, feed: f64, at: u32) -> R<()> {
        let mut p = self.prog_pos();
        if (p[i] - v).abs() < 1e-12 {
            return Ok(());
        }
        p[i] = v;
        self.line_to(p, motion::Speed::Feed(Feed::PerMin(feed * 1.0)), at)
    }
}
