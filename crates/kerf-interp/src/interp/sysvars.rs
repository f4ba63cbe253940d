//! System variables (`#1000` and up, and on the HX its numbers below the
//! plain ranges), read from and written to the interpreter state.
//! Numbering: the HX table of 000 §14.2.3 for the `hx` dialect, the Fanuc
//! standard (fanuc-semantics §7.8) for the others. This is reached only
//! for numbers outside the plain-variable ranges (`Vars::class`), so
//! ordinary macro arithmetic never pays for it.

use std::time::Instant;

use super::work_offsets::WorkId;
use super::Interp;
use crate::alarms::AlarmKind;
use crate::machine::MachineKind;
use crate::macros::{Lookup, MacroError, VarClass, Vars};

/// System-variable state that lives nowhere else in the interpreter.
#[derive(Clone, Debug)]
pub(crate) struct SysState {
    /// Interface inputs: HX UI000-UI331 as four 32-bit words (#7000-#7035);
    /// Fanuc #1000-#1015 / #1032 are the low 16 bits of word 0.
    pub inputs: [u32; 4],
    /// Interface outputs: HX UO000-UO331 (#7500-#7535); Fanuc
    /// #1100-#1115 / #1132 / #1133 use word 0.
    pub outputs: [u32; 4],
    /// Last D number and sequence number.
    pub d: f64,
    pub last_n: f64,
    /// #3001 (ms) and #3002 (hours) clocks: start and written offsets.
    pub clock: Instant,
    pub clock1_ms: f64,
    pub clock2_h: f64,
    /// #3003, #3004, #3901, #3902, HX #3083.
    pub c3003: f64,
    pub c3004: f64,
    pub parts_done: f64,
    pub parts_needed: f64,
    pub single_block: f64,
}

impl SysState {
    pub fn new(inputs: [u32; 4], single_block: bool) -> SysState {
        SysState {
            inputs,
            outputs: [0; 4],
            d: 0.0,
            last_n: 0.0,
            clock: Instant::now(),
            clock1_ms: 0.0,
            clock2_h: 0.0,
            c3003: 0.0,
            c3004: 0.0,
            parts_done: 0.0,
            parts_needed: 0.0,
            single_block: if single_block { 1.0 } else { 0.0 },
        }
    }
}

/// What the macro variables #3003 and #3004 ask of the runtime
/// (fanuc-semantics §7.8). The interpreter records them; a batch run has
/// no single-block stop, feed hold or override to suppress, and the
/// runtime or planner that has them reads them here between steps (the
/// state after the block that made the last event handed out, since a
/// block runs only when the previous one's events are all taken).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct MacroSwitches {
    /// #3003 bit 0: no single-block stop.
    pub single_block_suppressed: bool,
    /// #3003 bit 1: do not wait for the auxiliary-function completion
    /// signal (FIN).
    pub no_fin_wait: bool,
    /// #3004 bit 0: feed hold disabled.
    pub feed_hold_disabled: bool,
    /// #3004 bit 1: feedrate override disabled (100 %).
    pub override_disabled: bool,
    /// #3004 bit 2: exact-stop check disabled.
    pub exact_stop_disabled: bool,
}

fn fail<T>(kind: AlarmKind, message: String) -> Result<T, MacroError> {
    Err(MacroError { kind, message })
}

fn bit(words: &[u32; 4], w: usize, b: usize) -> f64 {
    ((words[w] >> b) & 1) as f64
}

/// Expression variables seen through the interpreter: plain numbers from
/// [`Vars`], the rest from [`Interp::sys_read`].
pub(crate) struct Env<'a>(pub &'a Interp);

impl Lookup for Env<'_> {
    #[inline]
    fn get(&self, n: f64) -> Result<Option<f64>, MacroError> {
        // Fast path: a whole number in the plain ranges.
        if let Some(k) = self.0.vars.plain_index(n) {
            return Ok(self.0.vars.raw(k));
        }
        let i = Vars::number(n)?;
        match self.0.vars.class(i) {
            VarClass::Plain => Ok(self.0.vars.raw(i)),
            VarClass::System => self.0.sys_read(i),
        }
    }
}

/// What a system variable number names.
/// A field of a lathe tool offset, as the Fanuc 0-T system variables
/// number them: #2001+n X wear, #2101+n Z wear, #2201+n R wear, #2301+n
/// tip, #2701+n X geometry, #2801+n Z geometry, #2901+n R geometry.
#[derive(Clone, Copy, Debug, PartialEq)]
enum LatheField {
    X,
    Z,
    R,
    WearX,
    WearZ,
    WearR,
    Tip,
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Sys {
    D(usize),
    H(usize),
    /// Common shift (G92/EXT), axis number 0-based.
    Shift(usize),
    /// Work offset G54+w, axis number.
    Wcs(usize, usize),
    SingleBlock,
    /// HX parameter window: #3000+n is PI n (000 pairs them throughout,
    /// e.g. §5.4 `#3120` = PI 120).
    Param(usize),
    /// HX #4018: 1 while the program runs in TPG (the control's tool-path
    /// graphic check), 0 in a real run.
    Tpg,
    S,
    DNum,
    HNum,
    Machine(usize),
    Work(usize),
    Programmed(usize),
    Skip(usize),
    Modal(usize),
    InBit(usize, usize),
    InWord(usize, u32),
    OutBit(usize, usize),
    OutWord(usize, u32),
    RefPoint(u32, usize),
    /// Lathe tool offset (Fanuc 0-T numbering): field, offset number.
    LatheOff(LatheField, usize),
    Clock1,
    Clock2,
    C3003,
    C3004,
    PartsDone,
    PartsNeeded,
    F,
    T,
    N,
}

impl Interp {
    /// The switches set by #3003 and #3004 (Fanuc numbering; always off
    /// on the HX, whose #3000+n are parameter windows). Reset clears them.
    pub fn macro_switches(&self) -> MacroSwitches {
        let (a, b) = (self.sys.c3003 as u32, self.sys.c3004 as u32);
        MacroSwitches {
            single_block_suppressed: a & 1 != 0,
            no_fin_wait: a & 2 != 0,
            feed_hold_disabled: b & 1 != 0,
            override_disabled: b & 2 != 0,
            exact_stop_disabled: b & 4 != 0,
        }
    }

    /// Whether a single-block runner stops after the block that made the
    /// last event: the single-block switch is on (`Settings::single_block`,
    /// or #3083 on the HX as the program set it) and #3003 bit 0 does not
    /// suppress the stop.
    pub fn single_block_stop(&self) -> bool {
        self.sys.single_block != 0.0 && !self.macro_switches().single_block_suppressed
    }

    fn sys_decode(&self, i: usize) -> Option<Sys> {
        use Sys::*;
        Some(if self.cfg.dialect.caps.hx_variables {
            match i {
                2112..=2239 => D(i - 2111),
                2240..=2367 => H(i - 2239),
                2368..=2370 => Shift(i - 2368),
                2377..=2430 => Wcs((i - 2377) / 9, (i - 2377) % 9),
                3083 => SingleBlock,
                // #3000 and #3006 keep Fanuc's alarm and message meaning
                // (calls.rs): 000 names no PI 0 or PI 6.
                3001..=3999 if i != 3006 => Param(i - 3000),
                4018 => Tpg,
                4083..=4086 => Work(i - 4083),
                // 000 §14.2.3's O9300 reads the Fanuc block end point and
                // machine position (fanuc-semantics §6.7).
                5001..=5004 => Programmed(i - 5001),
                5021..=5024 => Machine(i - 5021),
                4379..=4382 => Machine(i - 4379),
                4792 => S,
                4882 => DNum,
                4883 => HNum,
                6205..=6208 => Machine(i - 6205),
                6319..=6322 => Skip(i - 6319),
                6718..=6749 => Modal(i - 6717),
                7000..=7031 => InBit(0, i - 7000),
                7032..=7035 => InWord(i - 7032, u32::MAX),
                7500..=7531 => OutBit(0, i - 7500),
                7532..=7535 => OutWord(i - 7532, u32::MAX),
                8000..=8095 => RefPoint(2 + (i as u32 - 8000) / 32, (i - 8000) % 32),
                _ => return None,
            }
        } else {
            match i {
                1000..=1015 => InBit(0, i - 1000),
                1032 => InWord(0, 0xffff),
                1100..=1115 => OutBit(0, i - 1100),
                1132 => OutWord(0, 0xffff),
                1133 => OutWord(0, u32::MAX),
                2001..=2999 => {
                    let f = match (i - 2000) / 100 {
                        0 => LatheField::WearX,
                        1 => LatheField::WearZ,
                        2 => LatheField::WearR,
                        3 => LatheField::Tip,
                        7 => LatheField::X,
                        8 => LatheField::Z,
                        9 => LatheField::R,
                        _ => return None,
                    };
                    match i % 100 {
                        0 => return None,
                        n => LatheOff(f, n),
                    }
                }
                3001 => Clock1,
                3002 => Clock2,
                3003 => C3003,
                3004 => C3004,
                3901 => PartsDone,
                3902 => PartsNeeded,
                4001..=4031 => Modal(i - 4000),
                4107 => DNum,
                4109 => F,
                4111 => HNum,
                4114 => N,
                4119 => S,
                4120 => T,
                5001..=5006 => Programmed(i - 5001),
                5021..=5026 => Machine(i - 5021),
                5041..=5046 => Work(i - 5041),
                5061..=5066 => Skip(i - 5061),
                5201..=5206 => Shift(i - 5201),
                5221..=5340 if (i - 5221) % 20 < 6 => Wcs((i - 5221) / 20, (i - 5221) % 20),
                _ => return None,
            }
        })
    }

    /// mm (or degrees) → program units for axis slot `s`; lathe X in
    /// diameter when diameter programming is on.
    fn to_prog_units(&self, s: usize, v: f64) -> f64 {
        let mut v = v;
        if s < 3 {
            v /= self.unit();
        }
        if s == 0 && self.cfg.profile.kind == MachineKind::Lathe && self.modal.diameter.means {
            v *= 2.0;
        }
        v
    }

    fn prog_units_to_mm(&self, s: usize, v: f64) -> f64 {
        let mut v = v;
        if s < 3 {
            v *= self.unit();
        }
        if s == 0 && self.cfg.profile.kind == MachineKind::Lathe && self.modal.diameter.means {
            v /= 2.0;
        }
        v
    }

    fn axis_value_of(&self, k: usize, p: &kerf_canon::Pos) -> Option<f64> {
        self.cfg.axis_slot(k).map(|s| self.to_prog_units(s, p[s]))
    }

    /// Reads system variable `#i`.
    pub(crate) fn sys_read(&self, i: usize) -> Result<Option<f64>, MacroError> {
        use Sys::*;
        let Some(s) = self.sys_decode(i) else {
            return fail(
                AlarmKind::BadVariable,
                format!("#{i} is not a variable of this control"),
            );
        };
        let u = self.unit();
        Ok(Some(match s {
            D(n) => self.offsets.d_entry(n).map_or(0.0, |e| e.geom) / u,
            H(n) => self.offsets.h_entry(n).map_or(0.0, |e| e.geom) / u,
            Shift(k) => return Ok(self.axis_value_of(k, self.frames.shift()).or(Some(0.0))),
            Wcs(w, k) => {
                let o = self.frames.work().get(WorkId::G5x(w));
                return Ok(self.axis_value_of(k, &o).or(Some(0.0)));
            }
            SingleBlock => self.sys.single_block,
            Param(n) => self.cfg.profile.param(&format!("PI {n}"), 0.0),
            Tpg => (self.cfg.profile.param("tpg", 0.0) != 0.0) as u8 as f64,
            S => self.tool.s,
            DNum => self.sys.d,
            HNum => self.frames.h as f64,
            Machine(k) => return Ok(self.axis_value_of(k, &self.frames.mover.pos())),
            Work(k) => return Ok(self.axis_value_of(k, &self.work_position())),
            Programmed(k) => return Ok(self.axis_value_of(k, &self.frames.programmed_position())),
            Skip(k) => {
                let p = self
                    .frames
                    .skip_pos
                    .unwrap_or_else(|| self.frames.programmed_position());
                return Ok(self.axis_value_of(k, &p));
            }
            Modal(g) => {
                let c =
                    u8::try_from(g).map_or(0, |g| self.modal.code_of_group(self.cfg.dialect, g));
                let c = if self.system_b() {
                    crate::dialect::system_b::to_b(c)
                } else {
                    c
                };
                c as f64 / 10.0
            }
            InBit(w, b) => bit(&self.sys.inputs, w, b),
            InWord(w, mask) => (self.sys.inputs[w] & mask) as f64,
            OutBit(w, b) => bit(&self.sys.outputs, w, b),
            OutWord(w, mask) => (self.sys.outputs[w] & mask) as f64,
            RefPoint(n, k) => {
                let Some(s) = self.cfg.axis_slot(k) else {
                    return Ok(None);
                };
                let ax = kerf_canon::Axis::ALL[s];
                self.to_prog_units(s, self.reference_point(n, ax))
            }
            LatheOff(f, n) => {
                let o = self.offsets.lathe(n);
                match f {
                    LatheField::X => self.to_prog_units(0, o.x),
                    LatheField::WearX => self.to_prog_units(0, o.wear_x),
                    LatheField::Z => o.z / u,
                    LatheField::WearZ => o.wear_z / u,
                    LatheField::R => o.r / u,
                    LatheField::WearR => o.wear_r / u,
                    LatheField::Tip => o.tip as f64,
                }
            }
            Clock1 => self.sys.clock.elapsed().as_secs_f64() * 1000.0 + self.sys.clock1_ms,
            Clock2 => self.sys.clock.elapsed().as_secs_f64() / 3600.0 + self.sys.clock2_h,
            C3003 => self.sys.c3003,
            C3004 => self.sys.c3004,
            PartsDone => self.sys.parts_done,
            PartsNeeded => self.sys.parts_needed,
            F => match self.tool.feed {
                Some(f) => f / u,
                None => return Ok(None),
            },
            T => {
                if self.cfg.profile.kind == MachineKind::Lathe {
                    (self.tool.number * 100 + self.tool.offset) as f64
                } else {
                    self.tool.number as f64
                }
            }
            N => self.sys.last_n,
        }))
    }

    /// Writes system variable `#i` (vacant writes 0).
    pub(crate) fn sys_write(&mut self, i: usize, v: Option<f64>) -> Result<(), MacroError> {
        use Sys::*;
        let Some(s) = self.sys_decode(i) else {
            return fail(
                AlarmKind::BadVariable,
                format!("#{i} is not a variable of this control"),
            );
        };
        let x = v.unwrap_or(0.0);
        if !x.is_finite() {
            return fail(AlarmKind::MathError, "value is not a finite number".into());
        }
        let u = self.unit();
        let word = |x: f64, mask: u32| -> Result<u32, MacroError> {
            if x < 0.0 || x.fract() != 0.0 || x > mask as f64 {
                return fail(
                    AlarmKind::OutOfRange,
                    format!("#{i} = {x}: expected a whole number 0-{mask}"),
                );
            }
            Ok(x as u32)
        };
        let flag = |x: f64| -> Result<bool, MacroError> {
            match x {
                0.0 => Ok(false),
                1.0 => Ok(true),
                _ => fail(
                    AlarmKind::OutOfRange,
                    format!("#{i} = {x}: expected 0 or 1"),
                ),
            }
        };
        match s {
            D(n) => {
                if let Some(d) = self.offsets.d_mut(n) {
                    d.geom = x * u;
                }
            }
            H(n) => {
                if let Some(h) = self.offsets.h_mut(n) {
                    h.geom = x * u;
                }
            }
            Shift(k) | Wcs(_, k) => {
                let Some(slot) = self.cfg.axis_slot(k) else {
                    return fail(
                        AlarmKind::BadVariable,
                        format!("#{i}: this machine has no axis {}", k + 1),
                    );
                };
                let mm = self.prog_units_to_mm(slot, x);
                match s {
                    Shift(_) => self.frames.shift_mut()[slot] = mm,
                    Wcs(w, _) => {
                        if let Some(o) = self.frames.work_mut().g5x_mut(w) {
                            o[slot] = mm;
                        }
                    }
                    _ => unreachable!(),
                }
            }
            SingleBlock => self.sys.single_block = flag(x)? as u8 as f64,
            Param(n) => {
                self.cfg.profile.params.insert(format!("PI {n}"), x);
            }
            OutBit(w, b) => {
                if flag(x)? {
                    self.sys.outputs[w] |= 1 << b;
                } else {
                    self.sys.outputs[w] &= !(1 << b);
                }
            }
            OutWord(w, mask) => {
                let n = word(x, mask)?;
                self.sys.outputs[w] = (self.sys.outputs[w] & !mask) | n;
            }
            LatheOff(f, n) => {
                if f == LatheField::Tip && !(0.0..=9.0).contains(&x.round()) {
                    return fail(
                        AlarmKind::OutOfRange,
                        format!("#{i}: tool tip direction must be 0-9"),
                    );
                }
                let xr = self.prog_units_to_mm(0, x);
                let Some(o) = self.offsets.lathe_mut(n) else {
                    return fail(
                        AlarmKind::BadVariable,
                        format!("#{i}: offset {n} is not in this control's offset memory"),
                    );
                };
                match f {
                    LatheField::X => o.x = xr,
                    LatheField::WearX => o.wear_x = xr,
                    LatheField::Z => o.z = x * u,
                    LatheField::WearZ => o.wear_z = x * u,
                    LatheField::R => o.r = x * u,
                    LatheField::WearR => o.wear_r = x * u,
                    LatheField::Tip => o.tip = x.round() as u8,
                }
            }
            Clock1 => {
                self.sys.clock1_ms = x - self.sys.clock.elapsed().as_secs_f64() * 1000.0;
            }
            Clock2 => {
                self.sys.clock2_h = x - self.sys.clock.elapsed().as_secs_f64() / 3600.0;
            }
            C3003 => self.sys.c3003 = word(x, 3)? as f64,
            C3004 => self.sys.c3004 = word(x, 7)? as f64,
            PartsDone => self.sys.parts_done = x,
            PartsNeeded => self.sys.parts_needed = x,
            _ => {
                return fail(AlarmKind::BadVariable, format!("#{i} is read-only"));
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The interface inputs come from the settings, the outputs start
    /// off, and #3003-style counters at 0; the single block switch reads
    /// as 1.
    #[test]
    fn the_system_state_at_the_start_of_a_run() {
        let s = SysState::new([0b101, 0, 0, 1 << 31], true);
        assert_eq!(s.inputs, [0b101, 0, 0, 1 << 31]);
        assert_eq!(s.outputs, [0; 4]);
        assert_eq!((s.c3003, s.c3004, s.last_n, s.d), (0.0, 0.0, 0.0, 0.0));
        assert_eq!(s.single_block, 1.0);
        assert_eq!(SysState::new([0; 4], false).single_block, 0.0);
        // UI000 and UI002 on, UI001 off; UI331 is word 3's top bit.
        assert_eq!(
            (
                bit(&s.inputs, 0, 0),
                bit(&s.inputs, 0, 1),
                bit(&s.inputs, 0, 2)
            ),
            (1.0, 0.0, 1.0)
        );
        assert_eq!(bit(&s.inputs, 3, 31), 1.0);
    }
}
