//! The interpreter's fixed configuration: what the machine profile and
//! its dialect say, read once when the interpreter is made and never
//! changed by a program (run state lives elsewhere: interp/frames.rs,
//! interp/tool_spindle.rs, interp/program.rs …).

use kerf_canon::{Axis, Pos, NAXES};
use kerf_lang::LexOptions;

use crate::dialect::{Dialect, GCode, MCode};
use crate::machine::Profile;

/// The profile, its dialect and the lookups built from them.
pub(super) struct Config {
    /// The machine profile as loaded.
    pub(super) profile: Profile,
    /// The dialect of the profile's control.
    pub(super) dialect: &'static Dialect,
    /// How the block parser reads this control's text.
    pub(super) lex: LexOptions,
    /// Arc end point tolerance (mm, profile `arc_tolerance_mm`).
    pub(super) arc_tol: f64,
    /// G codes by value × 10 (fast lookup; 0-199.9).
    g_index: Vec<Option<&'static GCode>>,
    /// M codes below 256 (fast lookup).
    m_index: Vec<Option<MCode>>,
    /// Letters the dialect accepts, by letter - 'A'.
    letter_ok: [bool; 26],
    /// Which axis slots the machine has.
    pub(super) has_axis: [bool; NAXES],
    /// Travel limits (machine coordinates) per axis slot.
    pub(super) travel: [Option<(f64, f64)>; NAXES],
    /// The limits as [`Config::outside_travel`] tests them, worked out
    /// once: (min - 1e-9, max + 1e-9), and (-inf, +inf) for an axis
    /// without limits (no coordinate is outside those).
    travel_hair: [(f64, f64); NAXES],
    /// The dialect executes a block in [`crate::dialect::FANUC_MILL`]
    /// order (the HX): quiet blocks may take the short walk
    /// (interp/phases.rs).
    pub(super) mill_order: bool,
    /// The control and machine let a plain block take the direct path
    /// (interp/plain.rs): the HX's order, a mill with X, Y and Z, G, X,
    /// Y, Z and F accepted, G00 and G01 rapid and linear motion, and none
    /// of the dialect features a plain block would have to pass through
    /// (word ranges, U/V/W, restricted words, direct drawing, G-code
    /// system B, offsets waiting for a move).
    pub(super) plain_ok: bool,
    /// G00 and G01 of the table (the plain path's motion codes).
    pub(super) plain_g: [Option<&'static GCode>; 2],
}

impl Config {
    /// Reads the configuration of `profile`.
    pub(super) fn new(profile: Profile) -> Config {
        let dialect = Dialect::get(profile.dialect);
        let lex = LexOptions {
            long_names: dialect.long_names,
            loop_comments: dialect.hurco_syntax,
            max_digits: profile.max_digits,
            // Bracket nesting: Fanuc 5 levels including function
            // brackets; the HX text of 000 §14.2.4 gives 10.
            max_nesting: dialect.caps.bracket_nesting,
        };
        let arc_tol = profile.param("arc_tolerance_mm", 0.02);
        let mut g_index = vec![None; 2000];
        for g in dialect.gcodes {
            if let Some(slot) = g_index.get_mut(g.code10 as usize) {
                *slot = Some(g);
            }
        }
        let m_index: Vec<_> = (0..256u16).map(|m| dialect.mcode(m).copied()).collect();
        let mut letter_ok = [false; 26];
        for &l in dialect.letters {
            if l.is_ascii_uppercase() {
                letter_ok[(l - b'A') as usize] = true;
            }
        }
        let mut has_axis = [false; NAXES];
        let mut travel = [None; NAXES];
        for ax in Axis::ALL {
            if let Some(a) = profile.axis(ax) {
                has_axis[ax as usize] = true;
                travel[ax as usize] = Some((a.min, a.max));
            }
        }
        let mill_order = dialect.order == crate::dialect::FANUC_MILL;
        let plain_g = [0u16, 10].map(|c| g_index[c as usize]);
        let plain_ok = plain_allowed(&profile, dialect, &letter_ok, &has_axis, plain_g);
        Config {
            mill_order,
            plain_ok,
            plain_g,
            profile,
            dialect,
            lex,
            arc_tol,
            g_index,
            m_index,
            letter_ok,
            has_axis,
            travel,
            travel_hair: travel.map(|t| match t {
                Some((min, max)) => (min - 1e-9, max + 1e-9),
                None => (f64::NEG_INFINITY, f64::INFINITY),
            }),
        }
    }

    /// The first axis of machine point `m` outside its travel limits:
    /// the axis, its coordinate and its limits (a hair of 1e-9 mm over a
    /// limit is on it).
    #[inline]
    pub(super) fn outside_travel(&self, m: &Pos) -> Option<(Axis, f64, (f64, f64))> {
        // Every move asks: one test per axis against the bounds worked
        // out once, and the search below only for a point outside.
        let out = (0..NAXES).any(|i| {
            let (lo, hi) = self.travel_hair[i];
            m[i] < lo || m[i] > hi
        });
        if !out {
            return None;
        }
        for ax in Axis::ALL {
            if let Some((min, max)) = self.travel[ax as usize] {
                let v = m[ax as usize];
                if v < min - 1e-9 || v > max + 1e-9 {
                    return Some((ax, v, (min, max)));
                }
            }
        }
        None
    }

    /// The position slot of the control's axis number `k` (0-based:
    /// X Y Z A on the mill, X Z on a two-axis lathe).
    pub(super) fn axis_slot(&self, k: usize) -> Option<usize> {
        (0..NAXES).filter(|&s| self.has_axis[s]).nth(k)
    }

    /// The dialect's G code of value × 10 `code10`, if it has one.
    #[inline]
    pub(super) fn gcode(&self, code10: u16) -> Option<&'static GCode> {
        match self.g_index.get(code10 as usize) {
            Some(g) => *g,
            None => self.dialect.gcode(code10),
        }
    }

    /// The dialect's M code `m`, if it has one.
    #[inline]
    pub(super) fn mcode(&self, m: u32) -> Option<MCode> {
        match self.m_index.get(m as usize) {
            Some(mc) => *mc,
            None => self.dialect.mcode(m.min(65535) as u16).copied(),
        }
    }

    /// Letters that name an axis but are arguments of a code on machines
    /// without that axis (a lathe's C as a chamfer, B in some cycles …).
    pub(super) fn letter_is_argument(&self, l: u8) -> bool {
        self.profile.kind == crate::machine::MachineKind::Lathe && matches!(l, b'C' | b'A' | b'B')
    }

    /// Whether the dialect accepts address letter `l` (an upper-case
    /// ASCII letter).
    #[inline]
    pub(super) fn letter_ok(&self, l: u8) -> bool {
        self.letter_ok[(l - b'A') as usize]
    }
}

/// Whether the plain path may run on this control and machine (see
/// [`Config::plain_ok`]).
fn plain_allowed(
    profile: &Profile,
    dialect: &Dialect,
    letter_ok: &[bool; 26],
    has_axis: &[bool; NAXES],
    plain_g: [Option<&'static GCode>; 2],
) -> bool {
    use crate::dialect::meaning::MotionMode;
    use crate::dialect::{Means, Support};
    let caps = &dialect.caps;
    let motion_ok = |g: Option<&GCode>, m: MotionMode| {
        g.is_some_and(|g| g.means == Means::Motion(m) && matches!(g.support, Support::Yes))
    };
    dialect.order == crate::dialect::FANUC_MILL
        && profile.kind == crate::machine::MachineKind::Mill
        && b"GXYZF".iter().all(|&l| letter_ok[(l - b'A') as usize])
        && has_axis[..3].iter().all(|&a| a)
        && motion_ok(plain_g[0], MotionMode::Rapid)
        && motion_ok(plain_g[1], MotionMode::Linear)
        && !dialect.uvw_incremental
        && !caps.word_ranges
        && !caps.restricted_words
        && !caps.direct_drawing
        && !caps.gcode_system_b
        && !caps.offsets_wait_for_move
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dialect::MAction;
    use kerf_canon::Axis;

    fn cfg(name: &str) -> Config {
        Config::new(Profile::builtin(name).expect("builtin profile"))
    }

    #[test]
    fn the_plain_path_runs_on_the_hx_mill_only() {
        let hx = cfg("hx-mc");
        assert!(hx.plain_ok);
        // Its G00 and G01: rapid and linear motion, value × 10 0 and 10.
        assert_eq!(hx.plain_g.map(|g| g.map(|g| g.code10)), [Some(0), Some(10)]);
        // The lathes have no Y axis, other phase orders and (the PUMA)
        // U/W and direct drawing.
        assert!(!cfg("puma-lathe").plain_ok);
        assert!(!cfg("hurco-lathe").plain_ok);
        // A mill without a Z axis: an axis word would be an alarm.
        let mut p = Profile::builtin("hx-mc").unwrap();
        p.axes.remove("z");
        assert!(!Config::new(p).plain_ok);
    }

    #[test]
    fn travel_limits_and_axes_come_out_per_slot() {
        for name in ["hx-mc", "puma-lathe"] {
            let c = cfg(name);
            let p = Profile::builtin(name).unwrap();
            for ax in Axis::ALL {
                let want = p.axis(ax).map(|a| (a.min, a.max));
                assert_eq!(c.travel[ax as usize], want, "{name} {ax:?}");
                assert_eq!(c.has_axis[ax as usize], want.is_some(), "{name} {ax:?}");
            }
        }
        // A lathe has X and Z, not Y; the machining center X, Y and Z.
        let lathe = cfg("puma-lathe");
        assert!(lathe.has_axis[Axis::X as usize] && lathe.has_axis[Axis::Z as usize]);
        assert!(!lathe.has_axis[Axis::Y as usize]);
        let mc = cfg("hx-mc");
        assert!([Axis::X, Axis::Y, Axis::Z]
            .iter()
            .all(|&a| mc.has_axis[a as usize]));
        let (lo, hi) = mc.travel[Axis::X as usize].unwrap();
        assert!(lo < hi);
    }

    #[test]
    fn a_point_outside_the_travel_names_its_first_axis() {
        let c = cfg("hx-mc");
        let (xlo, xhi) = c.travel[Axis::X as usize].unwrap();
        let (ylo, _) = c.travel[Axis::Y as usize].unwrap();
        let (zlo, zhi) = c.travel[Axis::Z as usize].unwrap();
        let inside = |x: f64| [x, ylo, (zlo + zhi) / 2.0, 0.0, 0.0, 0.0];
        assert_eq!(c.outside_travel(&inside(xlo)), None);
        assert_eq!(c.outside_travel(&inside(xhi + 1e-10)), None);
        assert_eq!(
            c.outside_travel(&inside(xhi + 0.001)),
            Some((Axis::X, xhi + 0.001, (xlo, xhi)))
        );
        // Both X and Y out: X is named.
        let mut both = inside(xlo - 1.0);
        both[Axis::Y as usize] = ylo - 1.0;
        assert_eq!(c.outside_travel(&both).map(|o| o.0), Some(Axis::X));
        both[Axis::X as usize] = xlo;
        assert_eq!(c.outside_travel(&both).map(|o| o.0), Some(Axis::Y));
    }

    #[test]
    fn an_axis_the_machine_lacks_and_a_nan_are_never_outside() {
        // The lathe has no Y: any Y, however far, is not an overtravel.
        let lathe = cfg("puma-lathe");
        let (xlo, _) = lathe.travel[Axis::X as usize].unwrap();
        let (zlo, _) = lathe.travel[Axis::Z as usize].unwrap();
        let mut p = [xlo, 0.0, zlo, 0.0, 0.0, 0.0];
        for y in [1e300, -1e300, f64::INFINITY, f64::NEG_INFINITY] {
            p[Axis::Y as usize] = y;
            assert_eq!(lathe.outside_travel(&p), None, "Y = {y}");
        }
        // A NaN compares false with both limits, as the search finds.
        p[Axis::X as usize] = f64::NAN;
        assert_eq!(lathe.outside_travel(&p), None);
        // Just past the hair of 1e-9 mm below Z's limit: Z is named.
        p[Axis::X as usize] = xlo;
        p[Axis::Z as usize] = zlo - 1e-6;
        assert_eq!(lathe.outside_travel(&p).map(|o| o.0), Some(Axis::Z));
    }

    #[test]
    fn axis_numbers_count_the_machines_axes_only() {
        // A lathe's second axis is Z (slot 2), past the Y slot it lacks.
        let lathe = cfg("puma-lathe");
        assert_eq!(lathe.axis_slot(0), Some(Axis::X as usize));
        assert_eq!(lathe.axis_slot(1), Some(Axis::Z as usize));
        let mc = cfg("hx-mc");
        assert_eq!(mc.axis_slot(1), Some(Axis::Y as usize));
        assert_eq!(mc.axis_slot(NAXES), None);
    }

    #[test]
    fn the_g_index_finds_the_dialects_codes_and_no_others() {
        for name in ["hx-mc", "puma-lathe", "hurco-lathe"] {
            let c = cfg(name);
            for g in c.dialect.gcodes {
                let found = c.gcode(g.code10).expect("a table code");
                assert_eq!(found.code10, g.code10, "{name}");
            }
            for code10 in (0..2100u16).chain([9999, 65535]) {
                let in_table = c.dialect.gcodes.iter().any(|g| g.code10 == code10);
                assert_eq!(c.gcode(code10).is_some(), in_table, "{name} G{code10}/10");
            }
        }
        // G84.2 is the HX rigid tap; the PUMA has no such code.
        assert!(cfg("hx-mc").gcode(842).is_some());
        assert!(cfg("puma-lathe").gcode(842).is_none());
    }

    #[test]
    fn the_m_index_gives_each_codes_action() {
        let c = cfg("hx-mc");
        assert_eq!(c.mcode(98).map(|m| m.action), Some(MAction::SubCall));
        assert_eq!(c.mcode(99).map(|m| m.action), Some(MAction::SubReturn));
        assert_eq!(c.mcode(30).map(|m| m.action), Some(MAction::End));
        assert_eq!(c.mcode(2).map(|m| m.action), Some(MAction::End));
        for m in (0..300u32).chain([65535, 70000]) {
            let in_table = c.dialect.mcodes.iter().any(|x| u32::from(x.code) == m);
            assert_eq!(c.mcode(m).is_some(), in_table, "M{m}");
        }
    }

    #[test]
    fn the_letters_a_dialect_accepts() {
        for name in ["hx-mc", "puma-lathe", "hurco-lathe"] {
            let c = cfg(name);
            for l in b'A'..=b'Z' {
                assert_eq!(c.letter_ok(l), c.dialect.letters.contains(&l), "{name} {l}");
            }
            // Every control has X, F, G and M.
            assert!([b'X', b'F', b'G', b'M'].iter().all(|&l| c.letter_ok(l)));
        }
    }

    #[test]
    fn a_lathes_a_b_c_are_arguments_a_mills_are_axes() {
        let lathe = cfg("puma-lathe");
        assert!([b'A', b'B', b'C']
            .iter()
            .all(|&l| lathe.letter_is_argument(l)));
        assert!(!lathe.letter_is_argument(b'X') && !lathe.letter_is_argument(b'Y'));
        let mc = cfg("hx-mc");
        assert!(![b'A', b'B', b'C'].iter().any(|&l| mc.letter_is_argument(l)));
    }

    #[test]
    fn the_lexer_options_follow_the_dialect() {
        let hurco = cfg("hurco-lathe");
        assert!(hurco.lex.loop_comments);
        assert!(!cfg("hx-mc").lex.loop_comments);
        let hx = cfg("hx-mc");
        assert_eq!(hx.lex.max_nesting, hx.dialect.caps.bracket_nesting);
        assert_eq!(hx.lex.max_digits, hx.profile.max_digits);
    }
}
