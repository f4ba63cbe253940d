//! The plain-block path: a block made only of G00/G01, X, Y, Z and F
//! words with plain numbers (kerf-lang's `plain_words`), read while
//! nothing is in force that such a block would have to pass through, is
//! executed here directly instead of being parsed into a `Block`,
//! collected into the words table and walked through the phases.
//!
//! What runs is what the quiet walk (interp/phases.rs) runs for such a
//! block, by the same functions, in the same order: the motion code put
//! in force (ModalG), F (Feed, `set_feed`), the spindle's rpm followed
//! (Spindle, `spindle_to`), the block's end point (`axis_end`, as
//! `target` works it out) and the move (`plain_motion`, Motion); Frames
//! and Transfer have nothing to do for it under [`Interp::plain_state`].
//! The next block's reading is the same as after a general block, and
//! the parsed block the runtime asks about (N, statement, M) is an empty
//! one, as it is for such a block.
//!
//! The conditions are conservative: anything unusual takes the general
//! path. The control and machine (`Config::plain_ok`): the HX's phase
//! order on a mill with X, Y and Z, and no dialect feature that acts on
//! every block. The state ([`Interp::plain_state`]): no canned cycle, no
//! cutter compensation, no `,C`/`,R` held, no call by code or modal call
//! (G66), no G112/G107, no G16 polar input, no scaling or rotation, no
//! G96. The block: read from the text for the first time (not replayed
//! from the cache or read again after a jump), not over-long; at most
//! one G word, G00 or G01, and the motion in force after it rapid or
//! linear; F not negative. `tests/plain_path.rs` runs generated programs
//! with the path on and off (`Interp::set_plain_path`) and compares
//! every step.

use kerf_lang::{letter_bit, PlainWord, ScanSpec};

use super::*;

/// The letters of a plain block.
const PLAIN_LETTERS: u32 =
    letter_bit(b'G') | letter_bit(b'X') | letter_bit(b'Y') | letter_bit(b'Z') | letter_bit(b'F');

/// A plain block's words, decoded.
struct Plain {
    /// The motion code and its byte.
    g: Option<(&'static GCode, u32)>,
    /// X, Y, Z.
    axes: [Option<WVal>; 3],
    f: Option<WVal>,
}

impl Interp {
    /// What a read-ahead thread scans each block for: the plain path's
    /// letters and the parser's digit limit, as [`Interp::plain_block`]
    /// reads them.
    pub(super) fn plain_scan_spec(&self) -> ScanSpec {
        ScanSpec {
            max_digits: self.cfg.lex.max_digits,
            allowed: PLAIN_LETTERS,
        }
    }

    /// Whether a block read now may take the plain path: the path is on,
    /// the control allows it, and nothing is in force that a plain block
    /// would pass through (see the module documentation).
    #[inline]
    pub(super) fn plain_state(&self) -> bool {
        self.plain_path
            && self.cfg.plain_ok
            && self.modal.cycle.means.is_none()
            && self.common.comp.is_none()
            && self.common.corner.is_none()
            && self.hx.code_calls.is_none()
            && self.prog.calls.modal.is_empty()
            && self.frames.rot == polar_interp::RotInterp::Off
            && !self.frames.polar
            && !self.frames.xf.active()
            && !self.modal.css.means
    }

    /// Executes the block in `prog.raw` by the plain path if it is a
    /// plain block (Some: the block's result, as `next_block` returns
    /// it); None, with nothing changed, when the general path must read
    /// it. Call only under [`Interp::plain_state`].
    #[inline]
    pub(super) fn plain_block(&mut self) -> Option<R<bool>> {
        let raw = &self.prog.raw;
        if raw.overlong {
            return None;
        }
        let mut p = Plain {
            g: None,
            axes: [None; 3],
            f: None,
        };
        let g = self.cfg.plain_g;
        let each = |w: PlainWord| {
            let wv = WVal {
                v: w.num.value,
                point: w.num.point,
                at: w.at,
            };
            let slot = match w.letter {
                b'G' => {
                    let code = match wv.v {
                        0.0 => g[0],
                        1.0 => g[1],
                        _ => None,
                    };
                    p.g = code.map(|c| (c, w.at));
                    return p.g.is_some();
                }
                b'X' => &mut p.axes[0],
                b'Y' => &mut p.axes[1],
                b'Z' => &mut p.axes[2],
                // A negative F is the general path's alarm.
                b'F' if wv.v >= 0.0 => &mut p.f,
                _ => return false,
            };
            *slot = Some(wv);
            true
        };
        // Scanned ahead by the read-ahead thread, or here.
        if !raw
            .scan
            .words(&raw.text, self.cfg.lex.max_digits, PLAIN_LETTERS, each)
        {
            return None;
        }
        // The motion in force after the block: rapid or linear only.
        let mode = match p.g {
            Some((g, _)) => match g.means {
                Means::Motion(m) => m,
                _ => return None,
            },
            None => self.modal.motion.means,
        };
        if !matches!(mode, MotionMode::Rapid | MotionMode::Linear) {
            return None;
        }
        Some(self.run_plain(&p))
    }

    /// The plain block `p` executed (see the module documentation for
    /// what the general path does with it).
    fn run_plain(&mut self, p: &Plain) -> R<bool> {
        // next_block's bookkeeping for a block of words only.
        self.prog.block.clear();
        self.prog.tape_started = true;
        if let Err(over) = self.guard.count_block() {
            return Err(self.loop_limit(over, 0));
        }
        self.prog.calls.body_seen = true;
        // ModalG: the same code again changes nothing.
        if let Some((g, _)) = p.g {
            if g.code10 != self.modal.motion.code10 {
                self.modal.set(g);
            }
        }
        if let Some(f) = p.f {
            self.set_feed(f.v);
        }
        self.spindle_to(self.tool.spindle);
        let cur = self.prog_pos();
        let mut tw = cur;
        let mut any = false;
        for (ax, w) in [Axis::X, Axis::Y, Axis::Z].into_iter().zip(p.axes) {
            if let Some(w) = w {
                tw[ax as usize] = self.axis_end(&cur, ax, w);
                any = true;
            }
        }
        let at = p.g.map_or(0, |g| g.1);
        self.plain_motion(self.modal.motion.means, tw, any, at)?;
        Ok(true)
    }
}
