//! Number conversion (least input increment, units, diameter), range
//! checks, and the F, S, T, dwell and coordinate-setting codes of a block.

use super::*;

impl Interp {
    // ---- numbers -------------------------------------------------------------

    pub(super) fn unit(&self) -> f64 {
        if self.modal.metric() {
            1.0
        } else {
            25.4
        }
    }

    /// A linear dimension in mm (least-input-increment rule applied).
    pub(super) fn linear(&self, w: WVal) -> f64 {
        let mut v = w.v;
        if !w.point && !self.cfg.profile.calculator_decimal {
            v *= if self.modal.metric() { 0.001 } else { 0.0001 };
        }
        v * self.unit()
    }

    /// A rotary dimension in degrees.
    pub(super) fn angular(&self, w: WVal) -> f64 {
        if !w.point && !self.cfg.profile.calculator_decimal {
            w.v * 0.001
        } else {
            w.v
        }
    }

    /// Seconds from a dwell-time word (X/U: least increment 0.001 s).
    pub(super) fn seconds(&self, w: WVal) -> f64 {
        if !w.point && !self.cfg.profile.calculator_decimal {
            w.v * 0.001
        } else {
            w.v
        }
    }

    /// Range check of 002 Tables 2-3 for Hurco geometric words.
    #[inline]
    pub(super) fn check_range(&self, l: u8, w: WVal) -> R<()> {
        if !self.cfg.dialect.caps.word_ranges {
            return Ok(());
        }
        self.check_range_hurco(l, w)
    }

    pub(super) fn check_range_hurco(&self, l: u8, w: WVal) -> R<()> {
        // Table 2: the optional formats (profile `optional_format = 1`)
        // move the decimal point one place left.
        let scale = self.hurco_format_scale();
        let limit = match l {
            b'X' | b'Z' | b'I' | b'K' | b'R' | b'U' | b'W' | b'F' => {
                if self.modal.metric() {
                    21463.0 * scale
                } else {
                    845.0 * scale
                }
            }
            b'E' => 9999.0,
            b'T' | b'N' => 999_999_999.0,
            b'S' => 2e9,
            _ => return Ok(()),
        };
        if w.v.abs() > limit {
            return Err(self.alarm(
                AlarmKind::OutOfRange,
                w.at,
                format!(
                    "{} value {} out of range (±{})",
                    l as char,
                    fmt_num(w.v),
                    fmt_num(limit)
                ),
            ));
        }
        Ok(())
    }

    /// 1, or 0.1 with 002 Table 2's optional formats (profile
    /// `optional_format = 1`).
    pub(super) fn hurco_format_scale(&self) -> f64 {
        if self.cfg.profile.param("optional_format", 0.0) != 0.0 {
            0.1
        } else {
            1.0
        }
    }

    /// Table 2's thread lead range in mm/rev (G33 K/I, G78 F).
    pub(super) fn hurco_lead_range(&self) -> (f64, f64) {
        let optional = self.hurco_format_scale() < 1.0;
        match (self.modal.metric(), optional) {
            (true, false) => (0.00001, 254.0),
            (true, true) => (0.000001, 24.0),
            (false, false) => (0.000001 * 25.4, 10.0 * 25.4),
            (false, true) => (0.0000001 * 25.4, 1.0 * 25.4),
        }
    }

    // ---- F S T ---------------------------------------------------------------

    pub(super) fn f_word(&mut self, dwell: bool) -> R<()> {
        if dwell && self.cfg.dialect.caps.dwell_is_f {
            return Ok(());
        }
        if let Some(f) = self.words.get(b'F') {
            self.check_range(b'F', f)?;
            if f.v < 0.0 {
                return Err(self.alarm(AlarmKind::OutOfRange, f.at, "negative feedrate"));
            }
            self.set_feed(f.v);
        }
        Ok(())
    }

    /// The feed in force from an F word's value `v` (not negative): mm
    /// (or mm/rev) from program units, G93's inverse time as written.
    #[inline]
    pub(super) fn set_feed(&mut self, v: f64) {
        let v = if self.modal.feed_mode.means == FeedMode::Inverse {
            v
        } else {
            v * self.unit()
        };
        self.tool.feed = Some(v);
    }

    pub(super) fn t_word(&mut self) -> R<()> {
        let Some(t) = self.words.get(b'T') else {
            return Ok(());
        };
        self.check_range(b'T', t)?;
        if t.v < 0.0 || t.v.fract() != 0.0 || t.v > 999_999_999.0 {
            return Err(self.alarm(
                AlarmKind::OutOfRange,
                t.at,
                format!("T{} is not a tool code", fmt_num(t.v)),
            ));
        }
        let v = t.v as u32;
        match self.cfg.profile.kind {
            MachineKind::Mill => {
                if v > self.cfg.profile.tools.count {
                    return Err(self.alarm(
                        AlarmKind::OutOfRange,
                        t.at,
                        format!(
                            "T{v}: the tool changer has {} pockets",
                            self.cfg.profile.tools.count
                        ),
                    ));
                }
                self.tool.next = v;
                self.emit(Canon::Tool {
                    tool: v,
                    offset: self.tool.offset,
                    change: false,
                });
            }
            MachineKind::Lathe => {
                // Turret: T(tool)(offset), the last two digits the offset.
                let (tool, off) = (v / 100, v % 100);
                if tool > self.cfg.profile.tools.count {
                    return Err(self.alarm(
                        AlarmKind::OutOfRange,
                        t.at,
                        format!(
                            "T{v}: the turret has {} stations",
                            self.cfg.profile.tools.count
                        ),
                    ));
                }
                let change = tool != 0 && tool != self.tool.number;
                if tool != 0 {
                    self.tool.number = tool;
                }
                self.tool.next = self.tool.number;
                if !self.offsets.valid(off as usize) {
                    return Err(self.alarm(
                        AlarmKind::OutOfRange,
                        t.at,
                        format!(
                            "T{v}: no tool offset {off} (01-{:02})",
                            self.offsets.count()
                        ),
                    ));
                }
                self.tool.offset = off;
                self.apply_lathe_offset();
                self.emit(Canon::Tool {
                    tool: self.tool.number,
                    offset: off,
                    change,
                });
            }
        }
        Ok(())
    }

    /// The lathe tool offset selected by the T code (`tool.offset`, 0 =
    /// cancel) as the tool offset vector: X (radius) and Z, geometry +
    /// wear. The path shifts by it from the next move on (the T code
    /// itself moves nothing; in a block with a move, that move carries
    /// it), fanuc-semantics §5 / docs/dialects.md.
    pub(super) fn apply_lathe_offset(&mut self) {
        let o = self.offsets.lathe(self.tool.offset as usize);
        let tlo = self.frames.tlo_mut();
        *tlo = [0.0; NAXES];
        tlo[Axis::X as usize] = o.total_x();
        tlo[Axis::Z as usize] = o.total_z();
    }

    /// S word and spindle start codes, combined into one spindle event.
    pub(super) fn spindle_words(&mut self) -> R<()> {
        let mut dir = self.tool.spindle;
        for i in 0..self.words.nm {
            let (m, _) = self.words.m[i];
            match self.mcode(m).map(|c| c.action) {
                Some(MAction::SpindleCw) => dir = SpindleDir::Cw,
                Some(MAction::SpindleCcw) => dir = SpindleDir::Ccw,
                _ => {}
            }
        }
        if let Some(s) = self.words.get(b'S') {
            self.check_range(b'S', s)?;
            if s.v < 0.0 {
                return Err(self.alarm(AlarmKind::OutOfRange, s.at, "negative spindle speed"));
            }
            self.tool.s = s.v;
        }
        self.spindle_to(dir);
        Ok(())
    }

    /// The spindle turning `dir` at the speed the S in force gives: one
    /// spindle event when the direction or the rpm changed (a block
    /// without M or S calls it with the direction in force, for the rpm
    /// that G96 or a clamp may have changed).
    #[inline]
    pub(super) fn spindle_to(&mut self, dir: SpindleDir) {
        let changed_dir = dir != self.tool.spindle;
        self.tool.spindle = dir;
        if dir == SpindleDir::Stop {
            return;
        }
        let rpm = self.rpm();
        if changed_dir || (rpm - self.tool.last_rpm).abs() > 1e-9 {
            self.tool.last_rpm = rpm;
            let css = self.css_speed();
            self.emit(Canon::Spindle { dir, rpm, css });
        }
    }

    /// The surface speed in m/min when constant surface speed is on.
    pub(super) fn css_speed(&self) -> Option<f64> {
        self.modal
            .css
            .means
            .then_some(self.tool.s * if self.modal.metric() { 1.0 } else { 0.3048 })
    }

    /// Spindle rpm for the programmed S at the current position.
    pub(super) fn rpm(&self) -> f64 {
        let mut rpm = if self.modal.css.means {
            // Surface speed in m/min (ft/min in inch) at the current radius.
            let vc = self.tool.s * if self.modal.metric() { 1000.0 } else { 304.8 };
            let r = match self.hurco.css_r {
                Some(r) if self.cfg.dialect.caps.css_radius_word => r,
                _ => self.work_position()[0].abs(),
            }
            .max(1e-3);
            vc / (std::f64::consts::TAU * r)
        } else {
            self.tool.s
        };
        if let Some(c) = self.tool.s_clamp {
            rpm = rpm.min(c);
        }
        rpm.min(self.cfg.profile.spindle.max_rpm)
    }

    // ---- one-shots -------------------------------------------------------------

    pub(super) fn dwell(&mut self) -> R<()> {
        let w = &self.words;
        let (secs, revs) = if self.cfg.dialect.caps.dwell_is_f {
            // 002: "F is the only entry allowed in a G04 block".
            if let Some(x) = [b'X', b'Z', b'I', b'K', b'R', b'P', b'Q', b'A', b'H']
                .iter()
                .find_map(|&l| w.get(l))
            {
                return Err(self.alarm(
                    AlarmKind::IllegalAddress,
                    x.at,
                    "G04 takes only F (the dwell)",
                ));
            }
            match w.get(b'F') {
                // Table 3: 3.4 seconds or revolutions (0.0001-999.9999).
                Some(f) if f.v > 999.9999 => {
                    return Err(self.alarm(
                        AlarmKind::OutOfRange,
                        f.at,
                        format!("G04 F{} out of range (0.0001-999.9999)", fmt_num(f.v)),
                    ))
                }
                Some(f) if self.modal.feed_mode.means == FeedMode::PerRev => (0.0, f.v),
                Some(f) => (f.v, 0.0),
                None => {
                    return Err(self.alarm(
                        AlarmKind::MissingArgument,
                        self.words.g[0].1,
                        "G04 needs F (dwell time)",
                    ))
                }
            }
        } else if let Some(p) = w.get(b'P') {
            if p.point {
                return Err(self.alarm(
                    AlarmKind::OutOfRange,
                    p.at,
                    "G04 P is in milliseconds without a decimal point",
                ));
            }
            (p.v / 1000.0, 0.0)
        } else if let Some(x) = w.get(b'X').or(w.get(b'U')) {
            (self.seconds(x), 0.0)
        } else {
            (0.0, 0.0)
        };
        if secs < 0.0 || revs < 0.0 {
            return Err(self.alarm(AlarmKind::OutOfRange, 0, "negative dwell"));
        }
        // HX PI 120 = 1: in G95 the dwell counts spindle revolutions, in
        // the same units (000 §5.4, "(G95) PI 120 (#3120) 1").
        let (secs, revs) = if self.cfg.dialect.caps.dwell_revs_param
            && self.modal.feed_mode.means == FeedMode::PerRev
            && self.cfg.profile.param("PI 120", 0.0) == 1.0
        {
            (0.0, secs)
        } else {
            (secs, revs)
        };
        self.emit(Canon::Dwell {
            seconds: secs,
            revolutions: revs,
        });
        Ok(())
    }

    /// G92 (HX, Hurco) / G50 (PUMA): make the current position read as the
    /// given values; an S alone sets the spindle speed clamp.
    pub(super) fn coordinate_setting(&mut self, at: u32) -> R<()> {
        // 002 checks the S word's range (and refuses a negative clamp).
        if self.cfg.dialect.caps.word_ranges {
            self.g92_s()?;
        } else if let Some(s) = self.words.get(b'S') {
            self.tool.s_clamp = Some(s.v);
            self.words.take(b'S');
            self.emit(Canon::Mode(ModeChange::SpindleClamp(s.v)));
        }
        let cur = self.frames.programmed_position();
        let mut any = false;
        for ax in Axis::ALL {
            let l = ax_letter(ax);
            let mut target = None;
            if let Some(w) = self.words.get(l) {
                target = Some(self.axis_value(ax, w));
            } else if let Some(inc) = self.uvw(ax) {
                let w = self.words.get(inc).expect("present");
                target = Some(cur[ax as usize] + self.axis_value(ax, w));
            }
            if let Some(t) = target {
                any = true;
                // G92 clears the G52 local offset of the axis (Fanuc);
                // new shift so that pos - (wcs + shift + tlo) = t.
                let i = ax as usize;
                self.frames.local_mut()[i] = 0.0;
                self.frames.shift_mut()[i] = self.frames.mover.pos()[i]
                    - self.frames.work().origin()[i]
                    - self.frames.tlo()[i]
                    - t;
            }
        }
        let _ = (any, at);
        Ok(())
    }

    /// G53: a rapid to machine coordinates for this block. Machine
    /// coordinates are absolute only: in G91 (and with the lathe's U/W)
    /// the block is ignored, as Fanuc does (fanuc-semantics §6.2; 000
    /// §7.1.1 prints the format `G90 G53 X_Y_Z_`).
    pub(super) fn g53(&mut self) -> R<()> {
        let incremental =
            !self.modal.absolute() || Axis::ALL.iter().any(|&ax| self.uvw(ax).is_some());
        if incremental {
            return Ok(());
        }
        let mut to = self.frames.mover.pos();
        let mut any = false;
        for ax in Axis::ALL {
            if let Some(w) = self.words.get(ax_letter(ax)) {
                to[ax as usize] = self.axis_value(ax, w);
                any = true;
            }
        }
        if !any {
            return Ok(());
        }
        let g53 = Means::OneShot(crate::dialect::meaning::OneShot::MachineCoords);
        let at = self.block_g(|m| m == g53).map_or(0, |g| g.1);
        self.rapid_machine_always(to, at)
    }

    pub(super) fn linear_rapid(&self) -> bool {
        self.cfg.dialect.caps.linear_rapid
    }

    pub(super) fn work_of(&self, mpos: &Pos) -> Pos {
        let o = self.frames.origin_with_tlo();
        let mut p = *mpos;
        for i in 0..NAXES {
            p[i] -= o[i];
        }
        p
    }

    /// The value of an axis word in mm (X as a radius on lathes).
    pub(super) fn axis_value(&self, ax: Axis, w: WVal) -> f64 {
        let mut v = if ax.is_rotary() {
            self.angular(w)
        } else {
            self.linear(w)
        };
        if ax == Axis::X && self.cfg.profile.kind == MachineKind::Lathe && self.modal.diameter.means
        {
            v /= 2.0;
        }
        v
    }

    /// The incremental letter for an axis, if present (PUMA U/W).
    pub(super) fn uvw(&self, ax: Axis) -> Option<u8> {
        if !self.cfg.dialect.uvw_incremental {
            return None;
        }
        let l = match ax {
            Axis::X => b'U',
            Axis::Y => b'V',
            Axis::Z => b'W',
            Axis::C => b'H',
            _ => return None,
        };
        self.words.has(l).then_some(l)
    }
}
