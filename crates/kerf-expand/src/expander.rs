//! `Expander`: the canonical event stream written as G-code text, one
//! output block per event that the target can express, each ending in a
//! comment naming the file and line of the block that made it.
//!
//! The state kept is the output's own modal state (motion code, feed mode,
//! F, plane, spindle, coolant) and the position the output program has
//! told the control so far, so memory does not grow with the program.

use std::io::{self, Write};

use kerf_canon::{
    Alarm, ArcDir, Axis, Canon, Event, Feed, ModeChange, Motion, Plane, Pos, RotaryMode, NAXES,
};

use crate::num;
use crate::target::{Spelling, Target, ThreadWord};

/// A change of the original's frame (machine − work) larger than this (mm)
/// is set in the output; smaller ones are float noise.
const FRAME_TOL: f64 = 1e-7;

/// Output is handed to the writer in pieces of about this many bytes.
const FLUSH_AT: usize = 1 << 16;

/// Writes events as G-code blocks: [`Expander::start`] once, then
/// [`Expander::event`] for every event in order ([`Expander::alarm`] if
/// the run stopped on one), then [`Expander::finish`], which writes the
/// trailer and the last buffered blocks.
pub struct Expander<W: Write> {
    w: W,
    sp: Spelling,
    axes: Vec<Axis>,
    /// Output not yet handed to `w` (written in pieces of `FLUSH_AT`).
    buf: Vec<u8>,
    /// Where the block being built starts in `buf`.
    start: usize,
    /// The block being built has more than one line (`new_line`).
    multi: bool,
    /// Last value written per axis, scaled (X as a diameter when the
    /// output writes diameters); None until first written.
    written: [Option<i64>; NAXES],
    /// The start position (radius X, mm): what the output program holds
    /// on an axis it has not written yet.
    held: Pos,
    /// The machine position after the previous motion of the original.
    prev_mto: Pos,
    /// The output's frame: machine − work position per axis.
    shift: Pos,
    motion: Option<u8>,
    feed_mode: Option<usize>,
    feed: Option<i64>,
    /// The last feed value given to `feed_word` (its bits) and its scaled F.
    feed_memo: Option<(u64, i64)>,
    plane: Option<Plane>,
    /// The original's G112/G107 in force (rotary.rs).
    pub(crate) rotary: RotaryMode,
    pub(crate) spindle: crate::machine::SpindleState,
    pub(crate) coolant: (bool, bool),
    exact_stop_block: bool,
    blocks: u64,
    /// The file the cached comment head is for, and `(NAME:` for it.
    comment_file: String,
    comment_head: Vec<u8>,
    /// The last source line number's text (counted up in place).
    line_text: num::LineText,
}

/// How an event maps to an output block: the words go to `buf`, then the
/// source comment is added.
pub(crate) enum Written {
    Block,
    Nothing,
}

impl<W: Write> Expander<W> {
    /// An expander writing to `w` with the spellings `sp`, for a machine
    /// with `axes`, whose program starts at `start_work` (work
    /// coordinates) / `start_machine`.
    pub fn new(
        w: W,
        sp: Spelling,
        axes: Vec<Axis>,
        start_work: Pos,
        start_machine: Pos,
    ) -> Expander<W> {
        Expander {
            w,
            sp,
            axes,
            buf: Vec::with_capacity(FLUSH_AT + 4096),
            start: 0,
            multi: false,
            written: [None; NAXES],
            held: start_work,
            prev_mto: start_machine,
            shift: std::array::from_fn(|i| start_machine[i] - start_work[i]),
            motion: None,
            feed_mode: None,
            feed: None,
            feed_memo: None,
            plane: None,
            rotary: RotaryMode::Off,
            spindle: Default::default(),
            coolant: (false, false),
            exact_stop_block: false,
            blocks: 0,
            comment_file: String::new(),
            comment_head: b"(:".to_vec(),
            line_text: num::LineText::default(),
        }
    }

    /// The spellings in use.
    pub fn spelling(&self) -> &Spelling {
        &self.sp
    }

    /// Output blocks written so far (header and trailer not counted).
    pub fn blocks(&self) -> u64 {
        self.blocks
    }

    /// Writes the program start: a comment naming the source, then the
    /// header blocks of the target.
    pub fn start(&mut self, source: &str) -> io::Result<()> {
        let header = self.sp.header();
        let mut rest = header;
        if let Some((&first, tail)) = header.split_first() {
            if first == "%" {
                self.buf.extend_from_slice(b"%\n");
                rest = tail;
            }
        }
        for (i, line) in rest.iter().enumerate() {
            self.buf.extend_from_slice(line.as_bytes());
            if i == 0 {
                self.buf.extend_from_slice(b" (KERF EXPAND OF ");
                push_comment_text(&mut self.buf, base_name(source), 96);
                self.buf.extend_from_slice(b" TO ");
                let t = self.sp.target.to_string();
                self.buf.extend_from_slice(t.as_bytes());
                self.buf.push(b')');
            }
            self.buf.push(b'\n');
        }
        Ok(())
    }

    /// Writes one event with its source comment; `file` is the name of the
    /// file `e.src.file` refers to.
    pub fn event(&mut self, e: &Event, file: &str) -> io::Result<()> {
        self.start = self.buf.len();
        self.multi = false;
        let done = match &e.cmd {
            Canon::Rapid { m, .. } => return self.line_move(m, None, file, e.src.line),
            Canon::Feed { m, feed } => return self.line_move(m, Some(*feed), file, e.src.line),
            Canon::Arc {
                m,
                center,
                dir,
                plane,
                turns,
                feed,
                ..
            } => self.arc(m, center, *dir, *plane, *turns, *feed)?,
            Canon::Thread { m, lead } => self.thread(m, *lead),
            Canon::Dwell {
                seconds,
                revolutions,
            } => self.dwell(*seconds, *revolutions),
            Canon::Mode(ModeChange::Rotary(r)) => self.rotary_words(*r),
            _ => self.machine_event(&e.cmd),
        };
        match done {
            Written::Block => self.end_block(file, e.src.line),
            Written::Nothing => {
                self.buf.truncate(self.start);
                Ok(())
            }
        }
    }

    /// Writes a rapid (`feed` None) or a feed move as [`Expander::event`]
    /// writes the `Canon::Rapid` or `Canon::Feed` event, from its motion,
    /// feed and source line alone (a writer on another thread is handed
    /// these, not the whole event).
    #[inline]
    pub fn line_move(
        &mut self,
        m: &Motion,
        feed: Option<Feed>,
        file: &str,
        line: u32,
    ) -> io::Result<()> {
        self.start = self.buf.len();
        self.multi = false;
        self.linear(u8::from(feed.is_some()), m, feed);
        self.end_block(file, line)
    }

    /// Writes where the program stopped on an alarm, as a comment.
    pub fn alarm(&mut self, a: &Alarm, file: &str) -> io::Result<()> {
        self.buf.extend_from_slice(b"(ALARM ");
        let text = format!(
            "{} {}:{}: {}",
            a.code,
            base_name(file),
            a.src.line,
            a.message
        );
        push_comment_text(&mut self.buf, &text, 200);
        self.buf.extend_from_slice(b")\n");
        Ok(())
    }

    /// Writes the trailer, flushes and hands the writer back.
    pub fn finish(mut self) -> io::Result<W> {
        let t = self.sp.trailer();
        if !t.is_empty() {
            self.buf.extend_from_slice(t.as_bytes());
            self.buf.push(b'\n');
        }
        self.w.write_all(&self.buf)?;
        self.buf.clear();
        self.w.flush()?;
        Ok(self.w)
    }

    pub(crate) fn buf(&mut self) -> &mut Vec<u8> {
        &mut self.buf
    }

    pub(crate) fn sp(&self) -> &Spelling {
        &self.sp
    }

    /// Sets the modal F the output holds (a thread lead written as F, a
    /// Hurco dwell's F: None forces the next feed to write F again).
    pub(crate) fn set_feed(&mut self, f: Option<i64>) {
        self.feed = f;
    }

    pub(crate) fn set_exact_stop_block(&mut self) {
        self.exact_stop_block = true;
    }

    pub(crate) fn feed_mode(&self) -> Option<usize> {
        self.feed_mode
    }

    pub(crate) fn set_feed_mode(&mut self, m: usize) {
        self.feed_mode = Some(m);
    }

    /// Ends the block in `buf` (or each of its lines, when an event takes
    /// more than one block) with the source comment and writes it.
    fn end_block(&mut self, file: &str, line: u32) -> io::Result<()> {
        if file != self.comment_file {
            self.comment_file.clear();
            self.comment_file.push_str(file);
            self.comment_head.clear();
            self.comment_head.push(b'(');
            push_comment_text(&mut self.comment_head, base_name(file), 64);
            self.comment_head.push(b':');
        }
        if !std::mem::take(&mut self.multi) {
            self.sep();
            self.buf.extend_from_slice(&self.comment_head);
            self.line_text.put(&mut self.buf, line as u64);
            self.buf.extend_from_slice(b")\n");
            self.blocks += 1;
        } else {
            let mut tail = self.comment_head.clone();
            num::put_uint(&mut tail, line as u64, 1);
            tail.extend_from_slice(b")\n");
            let block = self.buf.split_off(self.start);
            for piece in block.split(|&c| c == b'\n') {
                self.buf.extend_from_slice(piece);
                if !piece.is_empty() {
                    self.buf.push(b' ');
                }
                self.buf.extend_from_slice(&tail);
                self.blocks += 1;
            }
        }
        if self.buf.len() >= FLUSH_AT {
            self.w.write_all(&self.buf)?;
            self.buf.clear();
        }
        Ok(())
    }

    fn word(&mut self, letter: u8, v: f64, dec: u32) {
        self.sep();
        self.buf.push(letter);
        num::put(&mut self.buf, v, dec);
    }

    /// Ends a line inside the block being built: the event takes more
    /// than one block, each gets the source comment.
    pub(crate) fn new_line(&mut self) {
        self.buf.push(b'\n');
        self.multi = true;
    }

    /// A space between words (none at the start of a block).
    fn sep(&mut self) {
        if self.buf.len() > self.start && self.buf.last() != Some(&b'\n') {
            self.buf.push(b' ');
        }
    }

    pub(crate) fn code(&mut self, code: &str) {
        self.sep();
        self.buf.extend_from_slice(code.as_bytes());
    }

    /// The G code of a motion (00 01 02 03 32 33), written when it changes.
    fn motion_code(&mut self, g: u8) {
        if self.motion != Some(g) {
            self.motion = Some(g);
            let text: &str = match (self.sp.target, g) {
                (Target::LinuxCnc, 0) => "G0",
                (Target::LinuxCnc, 1) => "G1",
                (Target::LinuxCnc, 2) => "G2",
                (Target::LinuxCnc, 3) => "G3",
                (_, 0) => "G00",
                (_, 1) => "G01",
                (_, 2) => "G02",
                (_, 3) => "G03",
                (_, 32) => "G32",
                _ => "G33",
            };
            self.code(text);
        }
    }

    /// The block prefix shared by every motion: a pending G09.
    fn motion_prefix(&mut self) {
        if std::mem::take(&mut self.exact_stop_block)
            && self.sp.target == Target::Fanuc
            && self.sp.control != crate::Control::Puma
        {
            self.code("G09");
        }
    }

    /// The feed mode code (per minute / per revolution / inverse time) when
    /// it changes; the F word comes later in the block.
    fn feed_mode_code(&mut self, mode: usize) {
        if self.feed_mode != Some(mode) {
            if let Some(c) = self.sp.feed_code(mode) {
                self.code(c);
            }
            self.feed_mode = Some(mode);
            // F is read anew in the new mode.
            self.feed = None;
        }
    }

    fn feed_word(&mut self, f: Feed) {
        let (mode, v) = feed_parts(f);
        // The scaled F of a value depends on nothing else: the last one is
        // kept (a program's feed seldom changes).
        let n = match self.feed_memo {
            Some((bits, n)) if bits == v.to_bits() => n,
            _ => {
                let dec = self.digits_for(v, self.sp.feed_decimals);
                let n = num::scaled(v, dec) * 10i64.pow(self.sp.feed_decimals - dec);
                self.feed_memo = Some((v.to_bits(), n));
                n
            }
        };
        // Inverse time needs F in every block.
        if self.feed != Some(n) || mode == 2 {
            self.feed = Some(n);
            self.sep();
            self.buf.push(b'F');
            num::put_scaled(&mut self.buf, n, self.sp.feed_decimals);
        }
    }

    /// Decimals for `v` so that the number keeps within the control's digits.
    pub(crate) fn digits_for(&self, v: f64, dec: u32) -> u32 {
        let mut int_digits = 1;
        let mut a = v.abs();
        while a >= 10.0 && int_digits < 16 {
            a /= 10.0;
            int_digits += 1;
        }
        dec.min(self.sp.max_digits.saturating_sub(int_digits))
    }

    fn scaled_axis(&self, i: usize, v: f64) -> i64 {
        if i == 0 && self.sp.diameter {
            num::scaled(2.0 * v, self.sp.decimals)
        } else {
            num::scaled(v, self.sp.decimals)
        }
    }

    fn value_of(&self, i: usize, n: i64) -> f64 {
        let v = num::unscaled(n, self.sp.decimals);
        if i == 0 && self.sp.diameter {
            v / 2.0
        } else {
            v
        }
    }

    /// The axis words of a move to `to`: every axis whose written value
    /// changes, and the axes in `always` (an arc's plane).
    fn axis_words(&mut self, to: &Pos, always: [usize; 2]) {
        // A move that goes nowhere in the output's numbers still names an
        // axis, so that it is a motion (the original's record) there too.
        let first = self.axes.first().map_or(0, |a| *a as usize);
        let always = if always[0] == usize::MAX {
            [first, usize::MAX]
        } else {
            always
        };
        let mut n = [0i64; NAXES];
        let mut any = false;
        for k in 0..self.axes.len() {
            let i = self.axes[k] as usize;
            n[i] = self.scaled_axis(i, to[i]);
            any |= self.written[i] != Some(n[i]);
        }
        let always = if any && always[1] == usize::MAX {
            [usize::MAX; 2]
        } else {
            always
        };
        for k in 0..self.axes.len() {
            let i = self.axes[k] as usize;
            if self.written[i] != Some(n[i]) || always.contains(&i) {
                self.written[i] = Some(n[i]);
                self.sep();
                self.buf.push(AXIS_LETTERS[i]);
                num::put_scaled(&mut self.buf, n[i], self.sp.decimals);
            }
        }
    }

    /// The position the output program holds on axis `i`: what it last
    /// wrote, or the start.
    fn held(&self, i: usize) -> f64 {
        match self.written[i] {
            Some(n) => self.value_of(i, n),
            None => self.held[i],
        }
    }

    /// The move to `to` (work) in the output's own numbers: each axis's
    /// written value less the value the output holds (zero on an axis the
    /// machine does not have).
    pub(crate) fn written_move(&self, to: &Pos) -> Pos {
        let mut d = [0.0; NAXES];
        for a in &self.axes {
            let i = *a as usize;
            d[i] = self.value_of(i, self.scaled_axis(i, to[i])) - self.held(i);
        }
        d
    }

    /// The machine position after the original's previous motion.
    pub(crate) fn prev_mto(&self) -> Pos {
        self.prev_mto
    }

    fn moved(&mut self, m: &Motion) {
        self.prev_mto = m.mto;
    }

    fn linear(&mut self, g: u8, m: &Motion, feed: Option<Feed>) -> Written {
        let feed = feed.map(|f| self.surface_feed(f, m));
        self.frame(m);
        self.motion_prefix();
        if let Some(f) = feed {
            self.feed_mode_code(feed_parts(f).0);
        }
        self.motion_code(g);
        self.axis_words(&m.to, [usize::MAX; 2]);
        if let Some(f) = feed {
            self.feed_word(f);
        }
        self.moved(m);
        Written::Block
    }

    pub(crate) fn plane_code(&mut self, plane: Plane) {
        if self.sp.planes && self.plane != Some(plane) {
            self.plane = Some(plane);
            let c = match (self.sp.target, plane) {
                (_, Plane::XY) => "G17",
                (_, Plane::ZX) => "G18",
                (_, Plane::YZ) => "G19",
            };
            self.code(c);
        }
    }

    /// Keeps the output's frame (work = machine − shift) the original's.
    /// Where the original's changed since the last motion (a work offset
    /// selected, G92/G52, a tool length or tool offset taken up), the
    /// output sets the same frame at the current position with G92 (PUMA
    /// G50), as a block of its own before the move; so every move starts
    /// and ends where the original's did, in machine coordinates too.
    fn frame(&mut self, m: &Motion) {
        let mut changed = false;
        for k in 0..self.axes.len() {
            let i = self.axes[k] as usize;
            if (m.mto[i] - m.to[i] - self.shift[i]).abs() > FRAME_TOL {
                changed = true;
            }
        }
        if !changed {
            return;
        }
        let g = match (self.sp.target, self.sp.control) {
            (Target::Fanuc, crate::Control::Puma) => "G50",
            _ => "G92",
        };
        self.code(g);
        for k in 0..self.axes.len() {
            let i = self.axes[k] as usize;
            let shift = m.mto[i] - m.to[i];
            if (shift - self.shift[i]).abs() <= FRAME_TOL {
                continue;
            }
            self.shift[i] = shift;
            let n = self.scaled_axis(i, self.prev_mto[i] - shift);
            self.written[i] = Some(n);
            self.sep();
            self.buf.push(AXIS_LETTERS[i]);
            num::put_scaled(&mut self.buf, n, self.sp.decimals);
        }
        self.new_line();
    }

    fn arc(
        &mut self,
        m: &Motion,
        center: &Pos,
        dir: ArcDir,
        plane: Plane,
        turns: u32,
        feed: Feed,
    ) -> io::Result<Written> {
        let (a1, a2, _) = plane.axes();
        if turns > 0 && self.sp.target == Target::Fanuc {
            return Err(io::Error::new(
                io::ErrorKind::InvalidData,
                "an arc of more than one turn has no single-block form on this control",
            ));
        }
        self.frame(m);
        let from: Pos = std::array::from_fn(|i| self.held(i));
        self.motion_prefix();
        self.feed_mode_code(feed_parts(feed).0);
        self.plane_code(plane);
        self.motion_code(if dir == ArcDir::Cw { 2 } else { 3 });
        self.axis_words(&m.to, [a1, a2]);
        // I J K from the start the output holds, to the centre.
        for (i, letter) in [(0usize, b'I'), (1, b'J'), (2, b'K')] {
            if i == a1 || i == a2 {
                self.word(letter, center[i] - from[i], self.sp.decimals);
            }
        }
        if turns > 0 {
            self.word(b'P', (turns + 1) as f64, 0);
        }
        self.feed_word(feed);
        self.moved(m);
        Ok(Written::Block)
    }

    fn thread(&mut self, m: &Motion, lead: f64) -> Written {
        self.frame(m);
        self.motion_prefix();
        // Hurco: the lead goes with the axis of the longer move (002 G33).
        let x_longer = (m.to[0] - self.held(0)).abs() > (m.to[2] - self.held(2)).abs() + 1e-9;
        let (g, letter) = match (self.sp.target, self.sp.thread) {
            (Target::LinuxCnc, _) => (33, b'K'),
            (_, ThreadWord::G32F) => (32, b'F'),
            (_, ThreadWord::G33F) => (33, b'F'),
            (_, ThreadWord::G33K) if x_longer => (33, b'I'),
            (_, ThreadWord::G33K) => (33, b'K'),
        };
        self.motion_code(g);
        self.axis_words(&m.to, [usize::MAX; 2]);
        let dec = self.digits_for(lead, self.sp.feed_decimals);
        self.word(letter, lead, dec);
        if letter == b'F' {
            // The lead is the modal F now: the next feed writes its own.
            self.feed = None;
        }
        self.moved(m);
        Written::Block
    }
}

/// (mode index, value) of a feed: 0 per minute, 1 per revolution, 2
/// inverse time.
pub(crate) fn feed_parts(f: Feed) -> (usize, f64) {
    match f {
        Feed::PerMin(v) => (0, v),
        Feed::PerRev(v) => (1, v),
        Feed::InverseTime(v) => (2, v),
    }
}

const AXIS_LETTERS: [u8; NAXES] = *b"XYZABC";

/// The last component of a path (the comment names the file, not where it
/// was on this computer).
pub fn base_name(path: &str) -> &str {
    path.rsplit(['/', '\\']).next().unwrap_or(path)
}

/// Appends comment text that every target reads back as one comment: no
/// parentheses (nesting is an error on Fanuc and LinuxCNC), no semicolons,
/// printable ASCII only, at most `max` bytes (the end kept).
pub(crate) fn push_comment_text(out: &mut Vec<u8>, text: &str, max: usize) {
    let b = text.as_bytes();
    let from = b.len().saturating_sub(max);
    for &c in &b[from..] {
        out.push(match c {
            b'(' => b'[',
            b')' => b']',
            b';' => b',',
            0x20..=0x7e => c,
            _ => b'?',
        });
    }
}
