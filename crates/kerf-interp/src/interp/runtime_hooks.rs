//! What a controller runtime (kerf-control) needs from the interpreter
//! beyond `step()`: execute one block at a time (single block, program
//! restart), switch the operator-panel switches between blocks, run MDI
//! text with the machine's modal state, and read the modal state for the
//! screen and for comparing two runs.

use super::*;

/// What one call of [`Interp::step_block`] did.
#[derive(Clone, Debug, PartialEq)]
pub enum BlockStep {
    /// One block was read and executed; its commands (if any) wait in
    /// [`Interp::take_event`].
    Block,
    /// The program has ended (M02/M30, end of text); take the remaining
    /// commands (the `End`) with [`Interp::take_event`].
    End,
    /// The block stopped on an alarm (commands of earlier blocks may still
    /// wait in [`Interp::take_event`]).
    Alarm(Alarm),
}

/// The interpreter's modal state in a comparable form (program restart
/// rebuilds it; a test compares it with a run from the start).
#[derive(Clone, Debug, PartialEq)]
pub struct InterpSnapshot {
    /// Every modal state field (groups, positions, work offsets, G92/G52
    /// shifts, tool and offsets, spindle, coolant, feed), as text.
    pub state: String,
    /// Canned-cycle modal data, as text.
    pub cycle: String,
    /// PUMA lathe single-cycle data, as text.
    pub lathe: String,
    /// Macro variables that hold a value (locals of the current level,
    /// commons, retained).
    pub vars: Vec<(usize, f64)>,
    /// Call stack depth (subprograms and macros).
    pub call_depth: usize,
}

impl Interp {
    /// Executes the next block when no command is pending (the runtime
    /// takes every pending command with [`Interp::take_event`] first).
    /// Unlike [`Interp::step`], it returns after each block, also one that
    /// made no command (a modal code alone, a macro statement).
    pub fn step_block(&mut self) -> BlockStep {
        if let Some(a) = self.common.after_block.take() {
            self.finished = true;
            return BlockStep::Alarm(a);
        }
        if self.finished {
            return BlockStep::End;
        }
        match self.next_block() {
            Ok(true) => BlockStep::Block,
            Ok(false) => {
                self.finished = true;
                BlockStep::End
            }
            Err(a) => {
                self.finished = true;
                self.queue.clear();
                self.common.corner = None;
                self.common.comp = None;
                BlockStep::Alarm(a)
            }
        }
    }

    /// The next pending command of the blocks executed so far.
    pub fn take_event(&mut self) -> Option<Event> {
        self.queue.pop_front()
    }

    /// Whether the last block read was a macro statement (assignment, IF,
    /// GOTO, WHILE, DO, END): single block stops after it only as the
    /// control's parameter says.
    pub fn last_block_is_statement(&self) -> bool {
        self.prog.block.stmt.is_some()
    }

    /// Whether the last block read carried M code `m` (e.g. the Hurco M01
    /// with the optional stop off, which still empties the look-ahead,
    /// 002 Table 15).
    pub fn last_block_has_m(&self, m: u32) -> bool {
        self.prog
            .block
            .words
            .iter()
            .any(|w| w.addr == Addr::L(b'M') && matches!(w.val, Val::Num(n) if n.value == m as f64))
    }

    /// Whether a move is held for the next block (cutter / nose radius
    /// compensation, `,C`/`,R`): the block's motion is not out yet.
    pub fn holds_motion(&self) -> bool {
        self.common.corner.is_some() || self.common.comp.is_some()
    }

    /// Where the last block read is: its file id and line, and its depth
    /// in the call stack (0 = the main program).
    pub fn block_at(&self) -> (SrcRef, usize) {
        (self.prog.cur, self.prog.calls.stack.len())
    }

    /// The sequence number (N) of the last block read, if it had one.
    pub fn block_n(&self) -> Option<u32> {
        self.prog.block.n
    }

    /// Sets the operator-panel switches; they act from the next block read
    /// (as on the control, whose look-ahead has read the block before).
    pub fn set_switches(&mut self, block_skip: u16, optional_stop: bool, single_block: bool) {
        self.settings.block_skip = block_skip;
        self.settings.optional_stop = optional_stop;
        self.settings.single_block = single_block;
        self.sys.single_block = if single_block { 1.0 } else { 0.0 };
    }

    /// Sets the dry-run switch as recorded in the settings.
    pub fn set_dry_run(&mut self, on: bool) {
        self.settings.dry_run = on;
    }

    /// Loads program text (the main program again, or MDI text) to
    /// execute with the machine's modal state as it is (positions, modals,
    /// offsets, variables kept), from its first block; `name` names it in
    /// source references.
    pub fn load_text(&mut self, name: &str, text: &str) {
        self.queue.clear();
        self.common.after_block = None;
        self.finished = false;
        self.prog.tape_started = false;
        self.guard.restart();
        self.guard.high_water = 0;
        self.load_main(
            name,
            Box::new(std::io::Cursor::new(text.as_bytes().to_vec())),
        );
    }

    /// Where the next block will be read: file id, line, and the call
    /// depth (0 = the main program). None before a program is loaded.
    pub fn next_block_at(&self) -> Option<(u32, u32, usize)> {
        let src = self.prog.src.as_ref()?;
        Some((
            self.prog.file_id,
            src.tell().line,
            self.prog.calls.stack.len(),
        ))
    }

    /// Sets the machine position after the axes were moved by hand (jog,
    /// handle, reference return): the next block starts from there.
    pub fn set_machine_position(&mut self, pos: Pos) {
        self.place_machine(pos);
    }

    /// The work offset of G54+`idx` (machine coordinates of its zero).
    pub fn work_offset(&self, idx: usize) -> Option<Pos> {
        (idx < 6).then(|| self.frames.work().get(work_offsets::WorkId::G5x(idx)))
    }

    /// Writes common (#100-#199) or retained macro variable `#n` from the
    /// operator's variable page (`None` = vacant); false for any other
    /// number (locals belong to a running program, system variables to
    /// the control) or a value that is not finite.
    pub fn set_common_var(&mut self, n: usize, v: Option<f64>) -> bool {
        let common = (100..=199).contains(&n) || self.vars.retained_range().contains(&n);
        if !common || v.is_some_and(|x| !x.is_finite()) {
            return false;
        }
        self.vars.set_raw(n, v);
        true
    }

    /// Writes a profile parameter (`"PI 144"`, `clear_commons_on_reset` …);
    /// parameters read at reset (the PI 144-150 reset states) act from
    /// the next RESET.
    pub fn set_param(&mut self, name: &str, v: f64) {
        self.cfg.profile.params.insert(name.to_string(), v);
    }

    /// Checks that every line of `text` parses as a block of this
    /// control, without executing anything: the first error as an alarm
    /// (line and column in `text`).
    pub fn check_syntax(&self, text: &str) -> Result<(), Alarm> {
        let mut block = Block::default();
        for (i, line) in text.lines().enumerate() {
            if let Err(e) = parse_block(line.as_bytes(), &self.cfg.lex, &mut block) {
                return Err(Alarm::new(
                    "SYNTAX",
                    e.kind.message(),
                    SrcRef {
                        file: 0,
                        line: i as u32 + 1,
                        col: e.at + 1,
                    },
                ));
            }
        }
        Ok(())
    }

    /// The G codes in force, one per modal group in group order, as the
    /// control's modal page prints them (`G01`, `G17`, `G54`, `G84.2`).
    pub fn modal_codes(&self) -> Vec<String> {
        let mut groups: Vec<u8> = self
            .cfg
            .dialect
            .gcodes
            .iter()
            .map(|g| g.group)
            .filter(|&g| g != 0)
            .collect();
        groups.sort_unstable();
        groups.dedup();
        groups
            .into_iter()
            .filter_map(|g| {
                let c = self.modal.code_of_group(self.cfg.dialect, g);
                self.cfg
                    .dialect
                    .gcodes
                    .iter()
                    .any(|d| d.group == g && d.code10 == c)
                    .then(|| g_name(c))
            })
            .collect()
    }

    /// The programmed feed (mm/min, or mm/rev in G95/G99), if an F was given.
    pub fn programmed_feed(&self) -> Option<f64> {
        self.tool.feed
    }

    /// The spindle as commanded: direction and S (rpm, or the surface
    /// speed in G96).
    pub fn spindle_state(&self) -> (SpindleDir, f64) {
        (self.tool.spindle, self.tool.s)
    }

    /// The tool in the spindle / active turret station.
    pub fn tool(&self) -> u32 {
        self.tool.number
    }

    /// The whole modal state in comparable form.
    pub fn snapshot(&self) -> InterpSnapshot {
        let mut vars = Vec::new();
        for n in 1..1000 {
            if let Some(v) = self.macro_var(n) {
                vars.push((n, v));
            }
        }
        InterpSnapshot {
            state: format!("{:?}", (&self.modal, &self.frames, &self.tool)),
            cycle: format!("{:?}", self.hx.cyc),
            lathe: format!("{:?}", (self.puma.single, self.puma.chamfer_on)),
            vars,
            call_depth: self.prog.calls.stack.len(),
        }
    }
}

/// `G01`, `G17`, `G84.2` from a code times ten.
fn g_name(c10: u16) -> String {
    if c10.is_multiple_of(10) {
        format!("G{:02}", c10 / 10)
    } else {
        format!("G{:02}.{}", c10 / 10, c10 % 10)
    }
}
