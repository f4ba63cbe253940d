//! The interpreter: a resumable step machine. [`Interp::step`] reads and
//! executes blocks until it has the next canonical command, an alarm, or
//! the end of the program. A block's commands are queued in execution
//! order and handed out one per call ([`Interp::step_into`]: a batch at
//! a time, onto the caller's vector). A plain block takes the direct
//! path of interp/plain.rs.

use kerf_canon::*;
use kerf_lang::{parse_block, Addr, Block, LexErrorKind, Mark, ProgramRead, RawBlock, Stmt, Val};

use crate::alarms::AlarmKind;
use crate::arc::{self, ArcError};
use crate::dialect::meaning::{
    CompSide, CuttingMode, CycleReturn, FeedMode, LengthComp, MotionMode,
};
use crate::dialect::{GCode, MAction, MWhen, Means, Support};
use crate::machine::{MachineKind, Profile};
use crate::macros::{round_to, Vars};
use crate::offsets::OffsetTable;
use crate::words::{WVal, Words, MAX_CODES};

mod block_cache;
mod calls;
mod codes;
mod comp;
mod config;
mod corners;
mod cycles;
mod cylindrical;
mod features;
mod flow;
mod frames;
mod hurco;
mod hurco_cycles;
mod hurco_thread;
mod lathe;
mod lathe_chamfer;
mod lathe_mrc;
mod lathe_shape;
mod loop_guard;
mod modal;
mod motion;
mod mover;
mod offset_data;
mod phases;
mod plain;
mod polar_interp;
mod probe;
mod program;
mod puma_words;
mod queue;
mod reset;
mod rotary_mode;
mod runtime_hooks;
mod skip;
mod system_b;
mod sysvars;
mod thread_plan;
mod tool_offset;
mod tool_spindle;
mod transforms;
mod work_offsets;

use program::{LoopFrame, MAX_LOOP_DEPTH};
pub use runtime_hooks::{BlockStep, InterpSnapshot};
pub use sysvars::MacroSwitches;

/// Operator-panel switches and run options.
#[derive(Clone, Debug, Default)]
pub struct Settings {
    /// Block delete levels switched on (bit n = `/n`; a bare `/` is level 1).
    pub block_skip: u16,
    /// Optional stop (M01) switch.
    pub optional_stop: bool,
    /// The Hurco M01 switch state "On (turn off)": the first M01 that
    /// stops switches `optional_stop` off (`--set optional_stop=once`).
    pub optional_stop_once: bool,
    /// Single block switch (recorded; a batch run does not pause).
    pub single_block: bool,
    /// Dry run switch (recorded for the planner).
    pub dry_run: bool,
    /// Most blocks executed before the loop guard stops the run
    /// (0 = no limit).
    pub max_blocks: u64,
    /// Passes of a main program that ends in M99 without L (a bar-feed
    /// loop the control repeats until reset): 0 or 1 = one pass, then
    /// the program ends with a note (`--set main_passes=N`).
    pub main_passes: u32,
    /// Interface input signals as four 32-bit words: HX UI000-UI031 …
    /// UI300-UI331 (#7000-#7035); Fanuc #1000-#1015 are word 0's low bits.
    pub inputs: [u32; 4],
    /// Simulated skip signal: where the probe touches, per skip signal
    /// (index 0 = G31/G37, 1-4 = G31.1-G31.4 / G37.1-G37.4, falling back
    /// to index 0) and axis: the program coordinate at which contact
    /// happens during a skip or measurement move (`--set skip.z=-12.5`,
    /// `--set skip2.x=40`).
    pub skip: [[Option<f64>; NAXES]; 5],
    /// Simulated part surface for the Hurco G38 probe cycles, per axis,
    /// in program units as the G38 block writes its X/Z (X a diameter in
    /// G08): `--set probe.x=2.5 --set probe.z=7.5`. None = no contact.
    pub probe: [Option<f64>; NAXES],
    /// The control's clock at the start of the run, seconds after
    /// midnight, for the probe cycles' recorded data (`--set
    /// probe.time=10:15:00`).
    pub clock: u32,
}

/// What one call of [`Interp::step`] produced.
#[derive(Clone, Debug, PartialEq)]
pub enum Step {
    /// The next canonical command.
    Event(Event),
    /// The program has ended (M02/M30, end of tape, end of text).
    End,
    /// The program stopped on an alarm.
    Alarm(Alarm),
}

/// What one call of [`Interp::step_into`] stopped on.
#[derive(Clone, Debug, PartialEq)]
pub enum Filled {
    /// The batch has the events asked for (or more); the program goes on.
    Room,
    /// The program has ended; all its events are in the batch.
    End,
    /// The program stopped on an alarm; the events before it are in the
    /// batch.
    Alarm(Alarm),
}

/// The interpreter: the coordinator of the owning types below. Each
/// kind of state has its own type and file (docs/ARCHITECTURE.md,
/// "kerf-interp").
pub struct Interp {
    /// The profile and dialect, read once (interp/config.rs).
    cfg: config::Config,
    /// Operator-panel switches and run options.
    settings: Settings,
    /// Program text, the cursor in it, the loops open and the call stack
    /// (interp/program.rs).
    prog: program::Program,
    /// The loop guard's counters and budgets (interp/loop_guard.rs).
    guard: loop_guard::LoopGuard,
    /// The words of the block being executed (words.rs).
    words: Words,
    /// The block's commands not yet handed out by [`Interp::step`]
    /// (interp/queue.rs).
    queue: queue::Queue,
    /// The program has ended or stopped on an alarm.
    finished: bool,
    /// The modal G codes in force, by meaning (interp/modal.rs).
    modal: modal::Modal,
    /// The machine position and the coordinate frames (interp/frames.rs).
    frames: frames::Frames,
    /// Tool, spindle, feed and coolant (interp/tool_spindle.rs).
    tool: tool_spindle::ToolSpindle,
    /// Macro variables (macros.rs).
    vars: Vars,
    /// System-variable state (interface signals, D table, clocks …;
    /// interp/sysvars.rs).
    sys: Box<sysvars::SysState>,
    /// Tool offset memory (H/D, lathe X/Z/R/T; offsets.rs).
    pub(crate) offsets: OffsetTable,
    /// Features every control has: compensation, held corners
    /// (interp/features.rs).
    common: features::CommonFeatures,
    /// The HX's canned cycles and code calls (interp/features.rs).
    hx: features::HxFeatures,
    /// The PUMA's lathe cycles and G-code system B (interp/lathe.rs).
    puma: lathe::PumaFeatures,
    /// The Hurco's fixture offsets, offset activation, drill cycles,
    /// probe datums (interp/hurco.rs).
    hurco: Box<hurco::HurcoState>,
    /// Quiet blocks take the short phase walk (interp/phases.rs); off
    /// only to show that both walks give the same results.
    quiet_walk: bool,
    /// Plain blocks take the direct path (interp/plain.rs); off only to
    /// show that both paths give the same results.
    plain_path: bool,
    /// The main program is read and scanned on a thread of its own
    /// (kerf-lang's `LineSource::read_ahead`).
    read_ahead: bool,
}

type R<T> = Result<T, Alarm>;

impl Interp {
    /// A new interpreter for a machine, positioned at the machine's start
    /// position with the power-on modal state.
    pub fn new(profile: Profile, settings: Settings) -> Interp {
        let cfg = config::Config::new(profile);
        let (profile, dialect) = (&cfg.profile, cfg.dialect);
        let hx = dialect.caps.hx_variables;
        let offsets = OffsetTable::new(profile.tools.offsets as usize);
        let hurco = hurco::HurcoState::new();
        let modal = modal::Modal::at_power_on(profile, dialect);
        let frames = frames::Frames::power_on(profile);
        let guard = loop_guard::LoopGuard::new(profile, settings.max_blocks);
        let sys = Box::new(sysvars::SysState::new(
            settings.inputs,
            settings.single_block,
        ));
        let hx_features = features::HxFeatures::new(profile, dialect);
        let puma = lathe::PumaFeatures::new(profile, dialect);
        Interp {
            cfg,
            settings,
            prog: program::Program::default(),
            guard,
            words: Words::default(),
            queue: queue::Queue::new(),
            finished: false,
            modal,
            frames,
            tool: tool_spindle::ToolSpindle::default(),
            vars: Vars::with_numbering(hx),
            offsets,
            sys,
            common: features::CommonFeatures::default(),
            hx: hx_features,
            puma,
            hurco,
            quiet_walk: true,
            plain_path: true,
            read_ahead: false,
        }
    }

    /// Switches the short phase walk for quiet blocks (on by default) —
    /// for tests comparing it with the full walk; results are the same.
    #[doc(hidden)]
    pub fn set_quiet_walk(&mut self, on: bool) {
        self.quiet_walk = on;
    }

    /// Switches the direct path for plain blocks (on by default) — for
    /// tests comparing it with the general path; results are the same.
    #[doc(hidden)]
    pub fn set_plain_path(&mut self, on: bool) {
        self.plain_path = on;
    }

    /// Reads the main programs loaded from now on ahead of their
    /// execution, on a thread of their own (off by default): the reading
    /// of each line and the plain-block scan move off the interpreter's
    /// thread; every step, event, end and alarm is the same.
    pub fn set_read_ahead(&mut self, on: bool) {
        self.read_ahead = on;
    }

    /// Loads the main program from a reader; `name` is used in source
    /// references and messages.
    pub fn load_main(&mut self, name: &str, reader: Box<dyn ProgramRead>) {
        let max = self.cfg.profile.max_block_chars;
        let hurco = self.cfg.dialect.hurco_syntax;
        self.prog.load(name, reader, max, hurco);
        if self.read_ahead {
            let spec = self.plain_scan_spec();
            if let Some(src) = self.prog.src.as_mut() {
                // Not started (no thread to be had): read here.
                let _ = src.read_ahead(spec);
            }
        }
        self.calls_main_loaded();
    }

    /// Sets the work offset of G54+`idx` (machine coordinates of its zero),
    /// as loaded with `--offsets`.
    pub fn set_work_offset(&mut self, idx: usize, origin: Pos) {
        self.frames
            .work_mut()
            .set(work_offsets::WorkId::G5x(idx), origin);
        if idx == 0 && self.cfg.dialect.caps.part_zero_is_e1 {
            // The Hurco's part zero is fixture offset E1.
            self.frames
                .work_mut()
                .set(work_offsets::WorkId::Fixture(1), origin);
        }
    }

    /// The retained macro variables that hold a value (#200-#699 on the
    /// HX, #500-#999 on the Fanuc controls), to be kept across runs.
    pub fn retained_vars(&self) -> Vec<(usize, f64)> {
        self.vars.retained()
    }

    /// Sets retained macro variable `#i` as kept from an earlier run;
    /// false if `i` is not a retained variable of this control.
    pub fn set_retained_var(&mut self, i: usize, v: f64) -> bool {
        self.vars.set_retained(i, v)
    }

    /// Sets the geometry of tool length offset H`n` (mm); H0 is always 0.
    pub fn set_h(&mut self, n: usize, v: f64) {
        if let Some(h) = self.offsets.h_mut(n) {
            h.geom = v;
        }
    }

    /// Whether X is programmed as a diameter now (lathes).
    pub fn diameter_programming(&self) -> bool {
        self.cfg.profile.kind == MachineKind::Lathe && self.modal.diameter.means
    }

    /// The tool offset memory (H/D pages, lathe tool offsets).
    pub fn offsets(&self) -> &OffsetTable {
        &self.offsets
    }

    /// The tool offset memory for writing (an `--offsets` file, a runner).
    /// Offsets already in force are not re-applied until the program
    /// selects them again (as on the control).
    pub fn offsets_mut(&mut self) -> &mut OffsetTable {
        &mut self.offsets
    }

    /// The name of a file in source references.
    pub fn file_name(&self, id: u32) -> &str {
        self.prog.file_name(id)
    }

    /// The machine profile.
    pub fn profile(&self) -> &Profile {
        &self.cfg.profile
    }

    /// Blocks executed so far.
    pub fn blocks(&self) -> u64 {
        self.guard.blocks
    }

    /// The value of macro variable `#n` from the variable store (locals,
    /// commons and retained variables; None when vacant or when `n` is not
    /// such a variable, e.g. a system variable).
    pub fn macro_var(&self, n: usize) -> Option<f64> {
        match self.vars.class(n) {
            crate::macros::VarClass::Plain => self.vars.raw(n),
            crate::macros::VarClass::System => None,
        }
    }

    /// Blocks held in the parsed-block cache (text executed again is
    /// replayed from there instead of being read and parsed again; see
    /// docs/ARCHITECTURE.md). For diagnostics and tests.
    pub fn cached_blocks(&self) -> usize {
        self.prog.cache.len()
    }

    /// Current position in machine coordinates.
    pub fn machine_position(&self) -> Pos {
        self.frames.mover.pos()
    }

    /// Current position of the tool tip in the active work coordinate
    /// system (tool length / tool offsets not included, as `Motion::to`).
    pub fn work_position(&self) -> Pos {
        self.frames.work_position()
    }

    /// The settings in force.
    pub fn settings(&self) -> &Settings {
        &self.settings
    }

    /// Runs until the next canonical command, an alarm or the end.
    ///
    /// Not inlined: inlined into a caller's loop, the event it returns is
    /// copied once more (callgrind on drill_grid: +9.6 M instructions).
    #[inline(never)]
    pub fn step(&mut self) -> Step {
        loop {
            if let Some(e) = self.queue.pop_front() {
                return Step::Event(e);
            }
            if let Some(a) = self.common.after_block.take() {
                self.finished = true;
                return Step::Alarm(a);
            }
            if self.finished {
                return Step::End;
            }
            match self.next_block() {
                Ok(true) => {}
                Ok(false) => {
                    self.finished = true;
                }
                Err(a) => {
                    self.finished = true;
                    self.queue.clear();
                    self.common.drop_held();
                    return Step::Alarm(a);
                }
            }
        }
    }

    /// Runs blocks until at least `room` more events are at the end of
    /// `out`, or to the end of the program or an alarm: the events
    /// [`Interp::step`] would hand out one per call, in the same order,
    /// with the same end or alarm after them, pushed straight onto the
    /// caller's batch (a block's events are made in place there, not
    /// queued and copied out). Events left by earlier `step` calls come
    /// first.
    pub fn step_into(&mut self, out: &mut Vec<Event>, room: usize) -> Filled {
        let want = out.len() + room;
        self.queue.drain_into(out);
        self.queue.lend(out);
        let r = self.fill(want);
        self.queue.lend(out);
        r
    }

    /// [`Interp::step_into`] with the batch lent to the queue: blocks
    /// until the queue's storage holds `want` events.
    fn fill(&mut self, want: usize) -> Filled {
        loop {
            self.queue.set_base();
            if self.queue.total() >= want {
                return Filled::Room;
            }
            if let Some(a) = self.common.after_block.take() {
                self.finished = true;
                return Filled::Alarm(a);
            }
            if self.finished {
                return Filled::End;
            }
            match self.next_block() {
                Ok(true) => {}
                Ok(false) => self.finished = true,
                Err(a) => {
                    self.finished = true;
                    self.queue.clear();
                    self.common.drop_held();
                    return Filled::Alarm(a);
                }
            }
        }
    }

    fn alarm(&self, k: AlarmKind, at: u32, msg: impl Into<String>) -> Alarm {
        let (line, col) = self.prog.raw.line_col(at as usize);
        k.at(
            self.cfg.dialect.id,
            SrcRef {
                file: self.prog.cur.file,
                line,
                col,
            },
            msg,
        )
    }

    /// Queues `cmd` as an event of the block: straight onto the queue when
    /// no path stage holds events and G96 is off, else by
    /// [`Interp::emit_staged`].
    #[inline]
    fn emit(&mut self, cmd: Canon) {
        self.emit_here(cmd);
    }

    /// [`Interp::emit`] inlined where it is called (the move seam's
    /// commit, which every move takes: the command is then built where
    /// it is queued).
    #[inline(always)]
    fn emit_here(&mut self, cmd: Canon) {
        if !self.modal.css.means && self.common.corner.is_none() && self.common.comp.is_none() {
            // Built where it is pushed: one copy of the command fewer.
            self.queue.push_back(Event {
                src: self.prog.cur,
                tool: self.tool.number,
                cmd,
                prog: self.common.comp_prog.map(Box::new),
            });
            return;
        }
        self.emit_staged(cmd);
    }

    /// [`Interp::emit`] under G96 or with a path stage that may hold the
    /// event.
    #[inline(never)]
    fn emit_staged(&mut self, cmd: Canon) {
        // G96 on a lathe: the spindle follows X (interp/lathe.rs).
        if self.modal.css.means
            && matches!(
                cmd,
                Canon::Rapid { .. } | Canon::Feed { .. } | Canon::Arc { .. } | Canon::Thread { .. }
            )
        {
            self.css_follow();
        }
        let e = Event {
            src: self.prog.cur,
            tool: self.tool.number,
            cmd,
            prog: self.common.comp_prog.map(Box::new),
        };
        match self.common.corner.as_mut() {
            None if self.common.comp.is_none() => self.queue.push_back(e),
            // After a held compensated move: handed out at its corner.
            None => {
                if let Some(e) = self.comp_hold_event(e) {
                    self.queue.push_back(e)
                }
            }
            // After a held ,C/,R move: handed out once it is emitted.
            Some(p) => p.hold(e),
        }
    }

    /// A loop guard count gone over its budget as an alarm.
    fn loop_limit(&self, over: loop_guard::Over, at: u32) -> Alarm {
        self.alarm(AlarmKind::LoopLimit, at, over.message())
    }

    /// A `%` block: opens the tape (the program starts after it), opens a
    /// library file, or ends the program or the file.
    fn percent_block(&mut self) -> R<bool> {
        if !self.prog.calls.stack.is_empty() {
            // A library file's leading % opens it; any other ends it.
            if self.prog.raw.mark.offset == 0 {
                return Ok(true);
            }
            return Err(self.sub_end_alarm());
        }
        if self.prog.tape_started {
            self.emit_end(0)?;
            return Ok(false);
        }
        self.prog.tape_started = true;
        // The program proper starts after the leading %.
        self.prog.program_start = self.prog.src.as_ref().expect("loaded").tell();
        Ok(true)
    }

    /// Reads and executes one block. Ok(false) at the end of the program.
    fn next_block(&mut self) -> R<bool> {
        let src = match self.prog.src.as_mut() {
            Some(s) => s,
            None => return Ok(false),
        };
        // Text read before: take the parsed block from the cache if it is
        // there (the read and the parse below would give the same).
        self.prog
            .cache
            .give_back(&mut self.prog.raw, &mut self.prog.block);
        let at = src.tell();
        let cached = if self.guard.was_read(at.offset) {
            self.prog.cache.lend(
                self.prog.file_id,
                at,
                &mut self.prog.raw,
                &mut self.prog.block,
            )
        } else {
            None
        };
        if let Some(next) = cached {
            // Lazy: moves nothing until the next read.
            let _ = src.seek(next);
        } else {
            match src.next_block(&mut self.prog.raw) {
                Ok(true) => {}
                Ok(false) => {
                    if !self.prog.calls.stack.is_empty() {
                        return Err(self.sub_end_alarm());
                    }
                    self.emit_end(0)?;
                    return Ok(false);
                }
                Err(e) => {
                    return Err(AlarmKind::Io.at(
                        self.cfg.dialect.id,
                        SrcRef {
                            file: self.prog.file_id,
                            line: src.tell().line,
                            col: 1,
                        },
                        format!("read error: {e}"),
                    ))
                }
            }
        }
        self.prog.cur = SrcRef {
            file: self.prog.file_id,
            line: self.prog.raw.mark.line,
            col: 1,
        };
        // Loop guard: blocks executed again (after a jump back) are counted
        // against a budget, however long the repeated section is.
        let next = self.prog.tell();
        let repeated = self
            .guard
            .count_read(next.offset)
            .map_err(|over| self.loop_limit(over, 0))?;
        if cached.is_none() {
            // A block of simple words, read for the first time, while
            // nothing unusual is in force: executed directly.
            if !repeated && self.plain_state() {
                if let Some(r) = self.plain_block() {
                    return r;
                }
            }
            self.parse_raw()?;
            if repeated {
                self.prog
                    .cache
                    .insert(self.prog.file_id, &self.prog.raw, &self.prog.block, next);
            }
        }
        self.run_parsed()
    }

    /// Executes the parsed block in hand (`next_block` has read it).
    fn run_parsed(&mut self) -> R<bool> {
        if self.prog.block.percent {
            return self.percent_block();
        }
        // Text before the first % is tape leader: comment and blank lines
        // there do not start the program, so the % after them opens it
        // instead of ending it.
        let b = &self.prog.block;
        if !b.words.is_empty()
            || b.stmt.is_some()
            || b.program.is_some()
            || b.n.is_some()
            || b.loop_cmd.is_some()
        {
            self.prog.tape_started = true;
        }
        if self.prog.block.program.is_some() && self.program_header()? {
            self.emit_end(0)?;
            return Ok(false);
        }
        // Block delete: a marker whose level is switched on skips the rest.
        let mut nwords = self.prog.block.words.len();
        for &(idx, mask) in &self.prog.block.deletes {
            if mask & self.settings.block_skip != 0 {
                if idx == 0 {
                    return Ok(true);
                }
                nwords = nwords.min(idx as usize);
                break;
            }
        }
        if let Err(over) = self.guard.count_block() {
            return Err(self.loop_limit(over, 0));
        }
        if let Some(l) = self.prog.block.loop_cmd {
            self.hurco_loop(l)?;
        }
        if self.prog.calls.end_seq.is_some() && self.prog.block.n.is_some() {
            return self.block_with_end_seq(nwords);
        }
        if let Some(n) = self.prog.block.n {
            self.sys.last_n = n as f64;
        }
        if let Some(stmt) = self.prog.block.stmt {
            self.prog.calls.body_seen = true;
            return self.statement(stmt);
        }
        if nwords == 0 {
            return Ok(true);
        }
        self.prog.calls.body_seen = true;
        self.collect(nwords)?;
        self.execute()
    }

    /// A numbered block inside an `M98 ... R_` call: after the block with
    /// sequence number R the call returns as at M99 (000 §2.4.3).
    fn block_with_end_seq(&mut self, nwords: usize) -> R<bool> {
        let depth = self.prog.calls.stack.len();
        let end_here = self.prog.block.n == self.prog.calls.end_seq;
        let r = if let Some(stmt) = self.prog.block.stmt {
            self.statement(stmt)?
        } else if nwords == 0 {
            true
        } else {
            self.collect(nwords)?;
            self.execute()?
        };
        if r && end_here && self.prog.calls.stack.len() == depth && depth > 0 {
            self.sub_return(None, 0)?;
        }
        Ok(r)
    }

    /// Parses `self.prog.raw` into `self.prog.block`; a block too long or malformed
    /// is an alarm.
    fn parse_raw(&mut self) -> R<()> {
        if self.prog.raw.overlong {
            let max = self.cfg.profile.max_block_chars;
            return Err(self.alarm(
                AlarmKind::BlockTooLong,
                max as u32,
                format!("block longer than {max} characters"),
            ));
        }
        if let Err(e) = parse_block(&self.prog.raw.text, &self.cfg.lex, &mut self.prog.block) {
            let kind = match e.kind {
                LexErrorKind::UnexpectedChar(_) => AlarmKind::IllegalAddress,
                LexErrorKind::MissingValue => AlarmKind::MissingValue,
                LexErrorKind::UnterminatedComment => AlarmKind::UnterminatedComment,
                LexErrorKind::TooManyDigits => AlarmKind::TooManyDigits,
                LexErrorKind::BadNumber | LexErrorKind::DuplicateNumber => {
                    AlarmKind::BadSequenceNumber
                }
                _ => AlarmKind::BadExpression,
            };
            return Err(self.alarm(kind, e.at, e.kind.message()));
        }
        Ok(())
    }

    /// The end of the program (M02/M30: `code`; 0 the end of the text). A
    /// move still held for its ,C/,R is an alarm.
    fn emit_end(&mut self, code: u32) -> R<()> {
        if self.common.corner.is_some() {
            let what = if code == 0 {
                "the end of the program".to_string()
            } else {
                format!("M{code:02}")
            };
            return Err(self.corner_broken(&what));
        }
        if self.common.comp.is_some() {
            self.comp_finish()?;
        }
        self.emit(Canon::End { code });
        Ok(())
    }

    // ---- words -----------------------------------------------------------

    /// Evaluates the block's words into `self.words`, checking addresses.
    fn collect(&mut self, nwords: usize) -> R<()> {
        self.words.clear();
        for i in 0..nwords {
            let w = self.prog.block.words[i];
            let (v, point) = match w.val {
                Val::Num(n) => (Some(n.value), n.point),
                Val::Expr(e) => {
                    // An expression's value is rounded to the address's
                    // least input increment (000 §14.2.4: X#1 with
                    // #1 = 1.2345 moves 1.235).
                    let inc = match w.addr {
                        Addr::L(l) => self.addr_increment(l),
                        Addr::Comma(_) => self.addr_increment(b'R'),
                        _ => 0.0,
                    };
                    let v = self.eval_in(e, w.at, inc)?;
                    (
                        v.map(|v| if inc > 0.0 { round_to(v, inc) } else { v }),
                        true,
                    )
                }
            };
            // A word whose value is vacant is omitted.
            let Some(v) = v else { continue };
            let wv = WVal { v, point, at: w.at };
            match w.addr {
                Addr::L(b'G') => {
                    if self.words.ng >= MAX_CODES {
                        return Err(self.alarm(
                            AlarmKind::OutOfRange,
                            w.at,
                            "too many G codes in one block",
                        ));
                    }
                    let c10 = (v * 10.0).round();
                    if !(0.0..=65535.0).contains(&c10) || ((v * 10.0) - c10).abs() > 1e-6 {
                        return Err(self.alarm(
                            AlarmKind::UnknownG,
                            w.at,
                            format!("G{} is not a G code of this control", fmt_num(v)),
                        ));
                    }
                    let g = self.g_of_system(c10 as u16, w.at)?;
                    self.words.push_g(g, w.at);
                }
                Addr::L(b'M') => {
                    let max_m = self.cfg.dialect.caps.max_m_per_block;
                    if self.words.nm >= max_m {
                        return Err(self.alarm(
                            AlarmKind::MCodeConflict,
                            w.at,
                            format!("more than {max_m} M codes in one block"),
                        ));
                    }
                    if v < 0.0 || v.fract() != 0.0 || v > 65535.0 {
                        return Err(self.alarm(
                            AlarmKind::UnknownM,
                            w.at,
                            format!("M{} is not an M code of this control", fmt_num(v)),
                        ));
                    }
                    self.words.push_m(v as u32, w.at, max_m);
                }
                Addr::L(l) => self.collect_letter(l, wv)?,
                Addr::Comma(c) => self.collect_comma(c, wv)?,
                Addr::Long(k) => {
                    if self.words.nlong >= self.words.long.len() {
                        return Err(self.alarm(
                            AlarmKind::OutOfRange,
                            w.at,
                            "too many parameters in one block",
                        ));
                    }
                    self.words.long[self.words.nlong] = (k, wv);
                    self.words.nlong += 1;
                }
            }
        }
        if self.puma.system_b {
            self.system_b_words()?;
        }
        Ok(())
    }

    /// A letter address word of the block (not G or M).
    #[inline]
    fn collect_letter(&mut self, l: u8, wv: WVal) -> R<()> {
        if !self.cfg.letter_ok(l) && !self.macro_args() {
            return Err(self.alarm(
                AlarmKind::IllegalAddress,
                wv.at,
                format!("address {} is not used by this control", l as char),
            ));
        }
        if let Some(ax) = Axis::from_letter(l) {
            if !self.cfg.has_axis[ax as usize]
                && !self.cfg.letter_is_argument(l)
                && !self.macro_args()
            {
                return Err(self.alarm(
                    AlarmKind::NoSuchAxis,
                    wv.at,
                    format!("this machine has no {} axis", l as char),
                ));
            }
        }
        let li = (l - b'A') as usize;
        if self.words.letters[li].is_some() && !self.macro_args() {
            return Err(self.alarm(
                AlarmKind::DuplicateAddress,
                wv.at,
                format!("address {} twice in one block", l as char),
            ));
        }
        self.words.letters[li] = Some(wv);
        Ok(())
    }

    /// A `,C` / `,R` word (HX chamfer and corner R).
    fn collect_comma(&mut self, c: u8, wv: WVal) -> R<()> {
        if !self.cfg.dialect.caps.comma_corners || !matches!(c, b'C' | b'R') {
            return Err(self.alarm(
                AlarmKind::IllegalAddress,
                wv.at,
                format!("address ,{} is not used by this control", c as char),
            ));
        }
        let slot = if c == b'C' {
            &mut self.words.comma_c
        } else {
            &mut self.words.comma_r
        };
        if slot.is_some() {
            return Err(self.alarm(
                AlarmKind::DuplicateAddress,
                wv.at,
                format!("address ,{} twice in one block", c as char),
            ));
        }
        *slot = Some(wv);
        if self.words.comma_c.is_some() && self.words.comma_r.is_some() {
            return Err(self.alarm(
                AlarmKind::CornerConflict,
                wv.at,
                ",C (chamfer) and ,R (corner R) in one block",
            ));
        }
        Ok(())
    }

    /// The least input increment of a dimension address in program units
    /// (0 for other addresses and for macro call arguments).
    fn addr_increment(&self, l: u8) -> f64 {
        if self.macro_args() {
            return 0.0;
        }
        match l {
            b'X' | b'Y' | b'Z' | b'U' | b'V' | b'W' | b'I' | b'J' | b'K' | b'R' | b'Q' => {
                if self.modal.metric() {
                    0.001
                } else {
                    0.0001
                }
            }
            b'A' | b'B' | b'C' => 0.001,
            _ => 0.0,
        }
    }

    /// The block is a G65/G66 call: its letters are macro arguments.
    fn macro_args(&self) -> bool {
        let [call, modal_call] = self.cfg.dialect.macro_calls;
        self.words.has_g(call) || self.words.has_g(modal_call) || self.code_call_block()
    }

    // ---- execution ---------------------------------------------------------

    #[inline]
    fn execute(&mut self) -> R<bool> {
        if self.hx.code_calls.is_some() {
            if let Some(r) = self.code_call()? {
                return Ok(r);
            }
        }
        if self.cfg.dialect.caps.restricted_words && !self.macro_args() {
            self.puma_words()?;
        }
        self.execute_block()
    }

    /// The block names an axis of the machine (or its incremental address).
    fn has_axis_word(&self) -> bool {
        Axis::ALL.iter().any(|&ax| {
            self.cfg.has_axis[ax as usize] && self.words.has(ax_letter(ax))
                || self.uvw(ax).is_some()
        })
    }

    #[inline]
    /// G92 (HX, Hurco) / G50 (PUMA, G-code system A): coordinate setting.
    fn is_coordinate_setting(&self, code10: u16) -> bool {
        self.gcode(code10).is_some_and(|g| {
            g.means == Means::OneShot(crate::dialect::meaning::OneShot::CoordinateSetting)
        })
    }

    fn gcode(&self, code10: u16) -> Option<&'static crate::dialect::GCode> {
        self.cfg.gcode(code10)
    }

    fn finished_by_end(&self) -> bool {
        self.queue.ends()
    }

    fn mcode(&self, m: u32) -> Option<crate::dialect::MCode> {
        self.cfg.mcode(m)
    }

    /// Executes the block's M codes selected by `pick(code, when, action)`
    /// (skipping spindle start codes, which `spindle_words` handles).
    fn run_m(&mut self, pick: impl Fn((u32, MWhen, MAction)) -> bool) -> R<()> {
        for i in 0..self.words.nm {
            let (m, _) = self.words.m[i];
            let mc = self.mcode(m).expect("checked");
            if matches!(mc.action, MAction::SpindleCw | MAction::SpindleCcw) {
                continue;
            }
            if !pick((m, mc.when, mc.action)) {
                continue;
            }
            match mc.action {
                MAction::SpindleStop => {
                    if self.tool.spindle != SpindleDir::Stop {
                        self.tool.spindle = SpindleDir::Stop;
                        self.emit(Canon::Spindle {
                            dir: SpindleDir::Stop,
                            rpm: 0.0,
                            css: None,
                        });
                    }
                    self.tool.last_rpm = 0.0;
                }
                MAction::CoolantMist | MAction::CoolantFlood | MAction::CoolantOff => {
                    use tool_spindle::Coolant;
                    let (mist, flood) = self.tool.coolant(match mc.action {
                        MAction::CoolantMist => Some(Coolant::Mist),
                        MAction::CoolantFlood => Some(Coolant::Flood),
                        _ => None,
                    });
                    self.emit(Canon::Coolant { mist, flood });
                }
                MAction::ToolChange => {
                    self.tool.number = self.tool.next;
                    self.emit(Canon::Tool {
                        tool: self.tool.number,
                        offset: self.tool.offset,
                        change: true,
                    });
                }
                MAction::Stop => {
                    self.hurco_stop_spindle();
                    self.emit(Canon::Stop { optional: false })
                }
                MAction::OptionalStop => {
                    if self.settings.optional_stop {
                        self.hurco_stop_spindle();
                        self.emit(Canon::Stop { optional: true });
                        if self.settings.optional_stop_once {
                            // Hurco M01 "On (turn off)": acts once.
                            self.settings.optional_stop = false;
                        }
                    }
                }
                MAction::End => {
                    self.hurco_stop_spindle();
                    self.emit_end(m)?;
                    self.finished = true;
                }
                MAction::Aux => self.emit(Canon::Aux { m, name: mc.name }),
                MAction::FeedOverride(on) => {
                    self.emit(Canon::Aux { m, name: mc.name });
                    self.emit(Canon::Mode(ModeChange::FeedOverride(on)));
                }
                MAction::SpindleCw
                | MAction::SpindleCcw
                | MAction::SubCall
                | MAction::SubReturn => {}
            }
        }
        Ok(())
    }

    /// Puts a modal code in force: its group's state, the work system it
    /// selects, the mode event it makes (HX G61-G64, G10.3/G11.3,
    /// G63.1/G63.2).
    fn apply_modal(&mut self, g: &GCode) {
        self.modal.set(g);
        match g.means {
            Means::Work(n) => self
                .frames
                .work_mut()
                .select(work_offsets::WorkId::G5x(n as usize)),
            m => self.mode_event(m),
        }
    }

    /// The mode event of a modal code's meaning, if it makes one.
    fn mode_event(&mut self, m: Means) {
        use crate::dialect::meaning::CuttingMode;
        let m = match m {
            Means::CuttingMode(CuttingMode::ExactStop) => ModeChange::ExactStopMode(true),
            Means::CuttingMode(CuttingMode::CornerOverride) => ModeChange::CornerOverride,
            Means::CuttingMode(CuttingMode::Tapping) => ModeChange::TappingMode,
            Means::CuttingMode(CuttingMode::Cutting) => ModeChange::CuttingMode,
            Means::HighSpeed(on) => ModeChange::HighSpeed(on),
            Means::Stitch(on) => ModeChange::Stitch(on),
            _ => return,
        };
        self.emit(Canon::Mode(m));
    }
}

fn ax_letter(a: Axis) -> u8 {
    b"XYZABC"[a as usize]
}

/// Formats a number without trailing zeros.
pub(crate) fn fmt_num(v: f64) -> String {
    let s = format!("{v:.4}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    s.to_string()
}

fn fmt_code(c10: u16) -> String {
    if c10.is_multiple_of(10) {
        format!("{:02}", c10 / 10)
    } else {
        format!("{:02}.{}", c10 / 10, c10 % 10)
    }
}
