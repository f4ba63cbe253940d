//! The program store and the call stack: programs by O number in the main
//! file and in `--lib` folders, `M98`/`M99` subprograms (000 §2.4,
//! fanuc-semantics §7.7) and `G65` simple macro calls (000 §14.1.1).
//!
//! Every open file is its own [`LineSource`]; the one being executed is
//! `Interp::src`, the others are parked here by file id. Programs inside one
//! file share that file's source (the call seeks to the program and the
//! return seeks back), so nothing is read into memory beyond one block.
//! None of this is on the per-block path of a program that makes no calls.

use std::collections::HashMap;
use std::fs::File;
use std::path::PathBuf;

use kerf_canon::{Canon, SrcRef};
use kerf_lang::{parse_block, Addr, Block, LineSource, Mark, RawBlock, Val};

use super::{fmt_num, Interp, R};
use crate::alarms::AlarmKind;
use crate::dialect::Means;

/// Most N-numbered blocks a program may have for its sequence index.
const SEQ_INDEX_MAX: usize = 65_536;

/// Where each sequence number stands in one program (in file order).
type SeqIndex = HashMap<u32, Vec<Mark>>;

/// One active call.
pub(super) struct Frame {
    /// A G65 macro call (own local variables) rather than an M98 call.
    macro_call: bool,
    /// The caller: file, position after the call block, program start,
    /// program header, WHILE loops, end sequence of its own call.
    file: u32,
    ret: Mark,
    start: Mark,
    header: Option<u64>,
    loops: Vec<super::program::LoopFrame>,
    end_seq: Option<u32>,
    /// The caller's #1-#99 (macro calls).
    locals: Option<Box<[Option<f64>; 99]>>,
    /// Where each repetition of the called program starts.
    callee_start: Mark,
    /// Repetitions left after the current one.
    left: u32,
    /// The G66 entry whose macro this call is.
    modal_idx: Option<usize>,
    /// Called by a G, M or T code (000 §14.1.3-14.1.6): inside it those
    /// codes are ordinary codes.
    by_code: bool,
}

/// Macro and subprogram calls by code (HX PI 85-106), built from the
/// profile's parameters; absent when none is set.
pub(super) struct CodeCalls {
    /// G code × 10 → program 9010-9019.
    g: Vec<(u16, u32)>,
    /// M code → program 9020-9029.
    m: Vec<(u32, u32)>,
    /// T codes call 9000 (PI 105).
    t: bool,
}

impl CodeCalls {
    /// The table from PI 85-94 (G codes 1-255), PI 95-104 (M codes 1-97
    /// other than M02, M30) and PI 105 (T); None when all are 0.
    pub(super) fn from_profile(
        p: &crate::machine::Profile,
        dialect: &crate::dialect::Dialect,
    ) -> Option<Box<CodeCalls>> {
        // The program end codes cannot be made calls.
        let ends = |m: f64| {
            dialect
                .mcode(m as u16)
                .is_some_and(|c| c.action == crate::dialect::MAction::End)
        };
        let mut cc = CodeCalls {
            g: Vec::new(),
            m: Vec::new(),
            t: p.param("PI 105", 0.0) != 0.0,
        };
        for k in 0..10u32 {
            let g = p.param(&format!("PI {}", 85 + k), 0.0);
            if (1.0..=255.0).contains(&g) && g.fract() == 0.0 {
                cc.g.push(((g * 10.0) as u16, 9010 + k));
            }
            let m = p.param(&format!("PI {}", 95 + k), 0.0);
            if (1.0..=97.0).contains(&m) && m.fract() == 0.0 && !ends(m) {
                cc.m.push((m as u32, 9020 + k));
            }
        }
        (cc.t || !cc.g.is_empty() || !cc.m.is_empty()).then(|| Box::new(cc))
    }

    /// The M codes that call programs: (M code, program number).
    #[cfg(test)]
    pub(super) fn m_calls(&self) -> &[(u32, u32)] {
        &self.m
    }
}

/// One G66 modal call in force.
pub(super) struct ModalCall {
    prog: u32,
    count: u32,
    args: Box<[Option<f64>; 33]>,
}

/// Programs, files and the call stack.
#[derive(Default)]
pub(super) struct Calls {
    lib_dirs: Vec<PathBuf>,
    /// Sources of the files not being executed, by file id.
    parked: Vec<Option<LineSource>>,
    /// Loop-guard high-water mark of each parked file.
    high_water: Vec<u64>,
    /// Files whose O numbers have been indexed.
    indexed: Vec<bool>,
    /// (file, program) → (header block, first block after the header).
    index: HashMap<(u32, u32), (Mark, Mark)>,
    /// The first program header of each indexed file.
    first_header: HashMap<u32, (Mark, Mark)>,
    /// Library programs already opened: program → file id.
    lib_files: HashMap<u32, u32>,
    /// Path of each library file (to reopen one that was closed).
    paths: Vec<Option<PathBuf>>,
    /// Files with more O headers than the index keeps.
    overflow: Vec<bool>,
    /// Sequence-number index per (file, program start offset): every N of
    /// the program with its block positions, built by one scan on the first
    /// search; `None` when the program has more N blocks than it keeps.
    seq_index: HashMap<(u32, u64), Option<SeqIndex>>,
    pub(super) stack: Vec<Frame>,
    /// Byte offset of the current program's O header, once known.
    pub(super) header: Option<u64>,
    /// A block with words or a statement has run in the main program.
    pub(super) body_seen: bool,
    /// `R` of the innermost M98: return after the block with this N.
    pub(super) end_seq: Option<u32>,
    /// Main-program `M99 ... L`: (offset of the M99 block, jumps left).
    main_repeat: Option<(u64, u32)>,
    /// Passes of the main program ended by an M99 without L so far.
    main_passes: u32,
    /// G66 modal calls in force, oldest first.
    pub(super) modal: Vec<ModalCall>,
}

/// Library files kept open while not executing.
const MAX_OPEN_LIBS: usize = 16;

/// O headers indexed per file; a file with more is searched per call.
const MAX_INDEX: usize = 4096;

/// Letters of argument specification I (000 §14.1.1) → local variable.
fn arg_var(l: u8) -> Option<usize> {
    Some(match l {
        b'A' => 1,
        b'B' => 2,
        b'C' => 3,
        b'D' => 7,
        b'E' => 8,
        b'F' => 9,
        b'H' => 11,
        b'M' => 13,
        b'Q' => 17,
        b'R' => 18,
        b'S' => 19,
        b'T' => 20,
        b'U' => 21,
        b'V' => 22,
        b'W' => 23,
        b'X' => 24,
        b'Y' => 25,
        b'Z' => 26,
        _ => return None,
    })
}

impl Calls {
    /// Registers a new file (its source is parked).
    fn add_file(&mut self, src: Option<LineSource>, path: Option<PathBuf>) {
        self.parked.push(src);
        self.high_water.push(0);
        self.indexed.push(false);
        self.paths.push(path);
        self.overflow.push(false);
    }
}

impl Interp {
    /// Adds a folder searched for programs called by number
    /// (`O1234.nc`, `1234.nc`, `O1234`, …), after the main file.
    pub fn add_lib_dir(&mut self, dir: PathBuf) {
        self.prog.calls.lib_dirs.push(dir);
    }

    /// Registers the main file in the call tables (from `load_main`).
    pub(super) fn calls_main_loaded(&mut self) {
        while self.prog.calls.parked.len() < self.prog.files.len() {
            self.prog.calls.add_file(None, None);
        }
    }

    /// Makes file `id` the one being executed.
    fn switch_to(&mut self, id: u32) {
        if id == self.prog.file_id {
            return;
        }
        let cur = self.prog.file_id as usize;
        // Library files stay open while in use and up to a few more; the
        // others are closed and reopened when called again.
        let open = self
            .prog
            .calls
            .parked
            .iter()
            .filter(|s| s.is_some())
            .count();
        let in_use = self.prog.calls.stack.iter().any(|f| f.file as usize == cur);
        if self.prog.calls.paths[cur].is_some() && !in_use && open >= MAX_OPEN_LIBS {
            self.prog.calls.parked[cur] = None;
            self.prog.src = None;
        } else {
            self.prog.calls.parked[cur] = self.prog.src.take();
        }
        self.prog.calls.high_water[cur] = self.guard.high_water;
        self.prog.src = self.prog.calls.parked[id as usize].take();
        self.guard.high_water = self.prog.calls.high_water[id as usize];
        self.prog.file_id = id;
    }

    /// The source of file `id`, current or parked.
    fn source_of(&mut self, id: u32) -> Option<&mut LineSource> {
        if id == self.prog.file_id {
            self.prog.src.as_mut()
        } else {
            self.prog.calls.parked.get_mut(id as usize)?.as_mut()
        }
    }

    /// Records the O headers of a file (one pass, at its first use).
    fn index_file(&mut self, id: u32) -> R<()> {
        if self
            .prog
            .calls
            .indexed
            .get(id as usize)
            .copied()
            .unwrap_or(true)
        {
            return Ok(());
        }
        self.prog.calls.indexed[id as usize] = true;
        let lex = self.cfg.lex;
        let mut found: Vec<(u32, Mark, Mark)> = Vec::new();
        let mut overflow = false;
        let Some(src) = self.source_of(id) else {
            return Ok(());
        };
        let back = src.tell();
        let mut raw = RawBlock::default();
        let mut blk = Block::default();
        let mut res = src.seek(Mark { offset: 0, line: 1 });
        if res.is_ok() {
            loop {
                match src.next_block(&mut raw) {
                    Ok(true) => {}
                    Ok(false) => break,
                    Err(e) => {
                        res = Err(e);
                        break;
                    }
                }
                if !raw.text.iter().any(|&c| matches!(c, b'O' | b'o' | b':')) {
                    continue;
                }
                if parse_block(&raw.text, &lex, &mut blk).is_ok() {
                    if let Some(p) = blk.program {
                        if found.len() >= MAX_INDEX {
                            overflow = true;
                            break;
                        }
                        found.push((p, raw.mark, src.tell()));
                    }
                }
            }
        }
        let res2 = src.seek(back);
        if let Err(e) = res.and(res2) {
            return Err(self.alarm(AlarmKind::Io, 0, format!("reading programs: {e}")));
        }
        self.prog.calls.overflow[id as usize] = overflow;
        if let Some(&(_, h, b)) = found.first() {
            self.prog.calls.first_header.insert(id, (h, b));
        }
        for (p, h, b) in found {
            self.prog.calls.index.entry((id, p)).or_insert((h, b));
        }
        Ok(())
    }

    /// Program `p` in file `id`: from the index, or by a search when the
    /// file has more programs than the index holds.
    fn lookup(&mut self, id: u32, p: u32) -> R<Option<(Mark, Mark)>> {
        self.index_file(id)?;
        if let Some(&hb) = self.prog.calls.index.get(&(id, p)) {
            return Ok(Some(hb));
        }
        if !self.prog.calls.overflow[id as usize] {
            return Ok(None);
        }
        let lex = self.cfg.lex;
        let Some(src) = self.source_of(id) else {
            return Ok(None);
        };
        let back = src.tell();
        let mut raw = RawBlock::default();
        let mut blk = Block::default();
        let mut hit = None;
        if src.seek(Mark { offset: 0, line: 1 }).is_ok() {
            while let Ok(true) = src.next_block(&mut raw) {
                if raw.text.iter().any(|&c| matches!(c, b'O' | b'o' | b':'))
                    && parse_block(&raw.text, &lex, &mut blk).is_ok()
                    && blk.program == Some(p)
                {
                    hit = Some((raw.mark, src.tell()));
                    break;
                }
            }
        }
        let _ = src.seek(back);
        Ok(hit)
    }

    /// Finds program `p`: in the current file, the main file, then the
    /// library folders. Returns (file, header offset, first block).
    fn find_program(&mut self, p: u32, at: u32) -> R<(u32, Option<u64>, Mark)> {
        for id in [self.prog.file_id, 0] {
            if let Some((h, b)) = self.lookup(id, p)? {
                return Ok((id, Some(h.offset), b));
            }
        }
        let id = match self.prog.calls.lib_files.get(&p) {
            Some(&id) => {
                if id != self.prog.file_id && self.prog.calls.parked[id as usize].is_none() {
                    let path = self.prog.calls.paths[id as usize]
                        .clone()
                        .expect("library file");
                    let f = File::open(&path).map_err(|e| {
                        self.alarm(AlarmKind::Io, at, format!("{}: {e}", path.display()))
                    })?;
                    let max = self.cfg.profile.max_block_chars.max(1);
                    self.prog.calls.parked[id as usize] = Some(LineSource::new(
                        Box::new(f),
                        max,
                        self.cfg.dialect.hurco_syntax,
                    ));
                    self.prog.calls.high_water[id as usize] = 0;
                }
                id
            }
            None => {
                let Some(path) = self.lib_path(p) else {
                    return Err(self.alarm(
                        AlarmKind::ProgramNotFound,
                        at,
                        format!("program O{p:04} not found (main file or --lib folders)"),
                    ));
                };
                let f = File::open(&path).map_err(|e| {
                    self.alarm(AlarmKind::Io, at, format!("{}: {e}", path.display()))
                })?;
                let max = self.cfg.profile.max_block_chars.max(1);
                let src = LineSource::new(Box::new(f), max, self.cfg.dialect.hurco_syntax);
                self.prog.files.push(path.display().to_string());
                self.prog.calls.add_file(Some(src), Some(path.clone()));
                let id = (self.prog.files.len() - 1) as u32;
                self.prog.calls.lib_files.insert(p, id);
                id
            }
        };
        if let Some((h, b)) = self.lookup(id, p)? {
            return Ok((id, Some(h.offset), b));
        }
        // A library file without that O number: the file is the program.
        match self.prog.calls.first_header.get(&id) {
            Some(&(h, b)) => Ok((id, Some(h.offset), b)),
            None => Ok((id, None, Mark { offset: 0, line: 1 })),
        }
    }

    /// The library file of program `p`, if any folder has one.
    fn lib_path(&self, p: u32) -> Option<PathBuf> {
        let mut names = Vec::new();
        for stem in [
            format!("O{p:04}"),
            format!("O{p}"),
            format!("{p:04}"),
            format!("{p}"),
        ] {
            for ext in [".nc", ".NC", ""] {
                let n = format!("{stem}{ext}");
                if !names.contains(&n) {
                    names.push(n);
                }
            }
        }
        for d in &self.prog.calls.lib_dirs {
            for n in &names {
                let path = d.join(n);
                if path.is_file() {
                    return Some(path);
                }
            }
        }
        None
    }

    /// An O header read while executing. Ok(true): it ends the current
    /// program (another program starts there).
    pub(super) fn program_header(&mut self) -> R<bool> {
        let here = self.prog.raw.mark.offset;
        if self.prog.calls.header == Some(here) {
            return Ok(false);
        }
        if self.prog.calls.stack.is_empty()
            && self.prog.calls.header.is_none()
            && !self.prog.calls.body_seen
        {
            self.prog.calls.header = Some(here);
            return Ok(false);
        }
        if self.prog.calls.stack.is_empty() {
            return Ok(true);
        }
        Err(self.sub_end_alarm())
    }

    /// The alarm for a called program that ends without M99.
    pub(super) fn sub_end_alarm(&self) -> kerf_canon::Alarm {
        self.alarm(
            AlarmKind::SubprogramEnd,
            0,
            "the called program ends without M99",
        )
    }

    /// True when a block read by a search starts another program.
    fn other_program(&self, blk: &Block, mark: Mark) -> bool {
        blk.program.is_some() && self.prog.calls.header != Some(mark.offset)
    }

    /// Searches the current program for sequence number `target`: forward
    /// from the current position to the program's end, then (with `wrap`)
    /// from the program start. Leaves the source at the block; false if
    /// there is none.
    /// The sequence index of the current program, built on first use.
    fn sequence_index(&mut self) -> Option<&SeqIndex> {
        let key = (self.prog.file_id, self.prog.program_start.offset);
        if !self.prog.calls.seq_index.contains_key(&key) {
            let built = self.build_sequence_index();
            self.prog.calls.seq_index.insert(key, built);
        }
        self.prog.calls.seq_index.get(&key).and_then(|o| o.as_ref())
    }

    /// Scans the current program once, recording where each N stands.
    fn build_sequence_index(&mut self) -> Option<SeqIndex> {
        let start = self.prog.program_start;
        let mut src = self.prog.src.take()?;
        let here = src.tell();
        let mut raw = RawBlock::default();
        let mut blk = Block::default();
        let mut map: SeqIndex = HashMap::new();
        let mut count = 0usize;
        let mut ok = src.seek(start).is_ok();
        while ok {
            let mark = src.tell();
            match src.next_block(&mut raw) {
                Ok(true) => {}
                _ => break,
            }
            if parse_block(&raw.text, &self.cfg.lex, &mut blk).is_err() {
                continue;
            }
            if self.other_program(&blk, mark) {
                break;
            }
            if let Some(n) = blk.n {
                count += 1;
                if count > SEQ_INDEX_MAX {
                    ok = false;
                    break;
                }
                map.entry(n).or_default().push(mark);
            }
        }
        let _ = src.seek(here);
        self.prog.src = Some(src);
        ok.then_some(map)
    }

    /// Positions the source at block N`target` of the current program:
    /// the first one at or after the current position, else (with `wrap`)
    /// the first one from the start of the program. Uses the program's
    /// sequence index; programs too large for it are scanned, and the
    /// scanned blocks count against the loop guard.
    pub(super) fn seek_sequence(&mut self, target: u32, wrap: bool) -> bool {
        let here = match self.prog.src.as_ref() {
            Some(s) => s.tell(),
            None => return false,
        };
        if let Some(index) = self.sequence_index() {
            let hit = index.get(&target).and_then(|marks| {
                marks
                    .iter()
                    .find(|m| m.offset >= here.offset)
                    .or_else(|| marks.first().filter(|m| wrap && m.offset < here.offset))
                    .copied()
            });
            return match hit {
                Some(m) => self.prog.src.as_mut().is_some_and(|s| s.seek(m).is_ok()),
                None => false,
            };
        }
        self.scan_for_sequence(target, wrap)
    }

    fn scan_for_sequence(&mut self, target: u32, wrap: bool) -> bool {
        let start = self.prog.program_start;
        let Some(mut src) = self.prog.src.take() else {
            return false;
        };
        let here = src.tell();
        let mut raw = RawBlock::default();
        let mut blk = Block::default();
        let mut hit = None;
        'passes: for pass in 0..(1 + wrap as u32) {
            if pass == 1 && src.seek(start).is_err() {
                break;
            }
            loop {
                let mark = src.tell();
                if pass == 1 && mark.offset >= here.offset {
                    break;
                }
                match src.next_block(&mut raw) {
                    Ok(true) => {}
                    _ => break,
                }
                self.guard.count_scanned();
                if parse_block(&raw.text, &self.cfg.lex, &mut blk).is_err() {
                    continue;
                }
                if self.other_program(&blk, mark) {
                    break;
                }
                if blk.n == Some(target) {
                    hit = Some(mark);
                    break 'passes;
                }
            }
        }
        let ok = match hit {
            Some(m) => src.seek(m).is_ok(),
            None => {
                let _ = src.seek(here);
                false
            }
        };
        self.prog.src = Some(src);
        ok
    }

    /// An integer word of a call (P, Q, R, L).
    fn int_word(&self, l: u8, max: f64) -> R<Option<(u32, u32)>> {
        let Some(w) = self.words.get(l) else {
            return Ok(None);
        };
        if w.v < 0.0 || w.v.fract() != 0.0 || w.v > max {
            return Err(self.alarm(
                AlarmKind::OutOfRange,
                w.at,
                format!("{}{} is out of range", l as char, fmt_num(w.v)),
            ));
        }
        Ok(Some((w.v as u32, w.at)))
    }

    fn nesting_check(&self, macro_call: bool, at: u32) -> R<()> {
        let macros = self
            .prog
            .calls
            .stack
            .iter()
            .filter(|f| f.macro_call)
            .count() as u32;
        let subs = self.prog.calls.stack.len() as u32 - macros;
        let p = |n: &str, def: f64| self.cfg.profile.param(n, def) as u32;
        let max_macro = p("max_macro_nesting", 4.0);
        let max_sub = p("max_sub_nesting", self.cfg.dialect.caps.sub_nesting as f64);
        let max_all = p("max_call_nesting", 8.0);
        let msg = if macro_call && macros + 1 > max_macro {
            format!("macro calls nested more than {max_macro} levels")
        } else if !macro_call && subs + 1 > max_sub {
            format!("subprogram calls nested more than {max_sub} levels")
        } else if macros + subs + 1 > max_all {
            format!("calls nested more than {max_all} levels in all")
        } else {
            return Ok(());
        };
        Err(self.alarm(AlarmKind::CallNesting, at, msg))
    }

    /// M98 P_ [Q_ R_] L_ (HX, 000 §2.4.3) / M98 P_ L_ and the 8-digit
    /// count+program P (Fanuc).
    pub(super) fn m98(&mut self, at: u32) -> R<()> {
        let hx = self.cfg.dialect.caps.m98_q_m99_l;
        let p = self.int_word(b'P', 99_999_999.0)?;
        let q = if hx {
            self.int_word(b'Q', 99_999.0)?
        } else {
            None
        };
        let r = if hx {
            self.int_word(b'R', 99_999.0)?
        } else {
            None
        };
        let l = self.int_word(b'L', 9999.0)?;
        let (prog, mut count) = match p {
            Some((v, _)) if !hx && l.is_none() && v > 9999 => (Some(v % 10_000), v / 10_000),
            Some((v, _)) => (Some(v), 1),
            None => (None, 1),
        };
        if let Some((n, _)) = l {
            count = n;
        }
        if count == 0 {
            return Ok(());
        }
        let target = match prog {
            Some(v) => Some(v),
            None if q.is_some() => None, // the current program (HX)
            None => {
                return Err(self.alarm(
                    AlarmKind::NoProgramNumber,
                    at,
                    "M98 without P (program number)",
                ))
            }
        };
        self.call(target, q, r.map(|r| r.0), count, false, at, None)
    }

    /// Enters program `prog` (None: the current one).
    #[allow(clippy::too_many_arguments)]
    fn call(
        &mut self,
        prog: Option<u32>,
        q: Option<(u32, u32)>,
        end_seq: Option<u32>,
        count: u32,
        macro_call: bool,
        at: u32,
        args: Option<[Option<f64>; 33]>,
    ) -> R<()> {
        self.corner_open("a subprogram or macro call")?;
        let (file, header, body) = match prog {
            Some(p) => self.find_program(p, at)?,
            None => (
                self.prog.file_id,
                self.prog.calls.header,
                self.prog.program_start,
            ),
        };
        self.nesting_check(macro_call, at)?;
        let ret = self.prog.src.as_ref().expect("loaded").tell();
        let frame = Frame {
            macro_call,
            file: self.prog.file_id,
            ret,
            start: self.prog.program_start,
            header: self.prog.calls.header,
            loops: std::mem::take(&mut self.prog.loops),
            end_seq: self.prog.calls.end_seq,
            locals: None,
            callee_start: body,
            left: count - 1,
            modal_idx: None,
            by_code: false,
        };
        self.prog.calls.stack.push(frame);
        self.switch_to(file);
        self.prog.program_start = body;
        self.prog.calls.header = header;
        self.prog.calls.end_seq = end_seq;
        self.seek(body)?;
        if let Some((n, qat)) = q {
            if !self.seek_sequence(n, false) {
                let err_src = self.calls_caller_src(qat);
                self.unwind_failed_call();
                return Err(AlarmKind::SequenceNotFound.at(
                    self.cfg.dialect.id,
                    err_src,
                    format!("M98 Q{n}: sequence number N{n} not found in the called program"),
                ));
            }
            let m = self.prog.src.as_ref().expect("loaded").tell();
            if let Some(f) = self.prog.calls.stack.last_mut() {
                f.callee_start = m;
            }
        }
        if let Some(a) = args {
            let saved = self.vars.take_locals();
            self.vars.put_args(&a);
            if let Some(f) = self.prog.calls.stack.last_mut() {
                f.locals = Some(Box::new(saved));
            }
        }
        Ok(())
    }

    fn calls_caller_src(&self, at: u32) -> SrcRef {
        let f = self.prog.calls.stack.last().expect("frame");
        let (line, col) = self.prog.raw.line_col(at as usize);
        SrcRef {
            file: f.file,
            line,
            col,
        }
    }

    /// Undoes a call whose start could not be found.
    fn unwind_failed_call(&mut self) {
        if let Some(f) = self.prog.calls.stack.pop() {
            self.switch_to(f.file);
            self.prog.program_start = f.start;
            self.prog.calls.header = f.header;
            self.prog.loops = f.loops;
            self.prog.calls.end_seq = f.end_seq;
            let _ = self.seek(f.ret);
        }
    }

    /// M99 [P_] [L_]: return to the caller (after the call block, or to its
    /// sequence P), repeat the called program, or in the main program jump
    /// back to its start (or N P), L times when L is given.
    pub(super) fn m99(&mut self, at: u32) -> R<()> {
        let p = self.int_word(b'P', 99_999.0)?;
        let l = if self.cfg.dialect.caps.m98_q_m99_l {
            self.int_word(b'L', 9999.0)?
        } else {
            None
        };
        if self.prog.calls.stack.is_empty() {
            return self.main_m99(p, l, at);
        }
        self.sub_return(p, at)
    }

    /// Ends one repetition of the called program (M99, or the block with
    /// sequence number R).
    pub(super) fn sub_return(&mut self, p: Option<(u32, u32)>, at: u32) -> R<()> {
        self.corner_open("the return from a subprogram")?;
        let f = self.prog.calls.stack.last_mut().expect("in a call");
        if f.left > 0 {
            f.left -= 1;
            let m = f.callee_start;
            self.count_jump(at)?;
            self.prog.loops.clear();
            return self.seek(m);
        }
        let f = self.prog.calls.stack.pop().expect("in a call");
        if let Some(l) = f.locals {
            self.vars.put_locals(&l);
        }
        self.switch_to(f.file);
        self.prog.program_start = f.start;
        self.prog.calls.header = f.header;
        self.prog.loops = f.loops;
        self.prog.calls.end_seq = f.end_seq;
        self.seek(f.ret)?;
        if let Some((n, pat)) = p {
            // A return to an earlier block can loop: it counts as a jump.
            self.count_jump(pat)?;
            if !self.seek_sequence(n, true) {
                let (line, col) = self.prog.raw.line_col(pat as usize);
                return Err(AlarmKind::SequenceNotFound.at(
                    self.cfg.dialect.id,
                    SrcRef {
                        file: self.prog.cur.file,
                        line,
                        col,
                    },
                    format!("M99 P{n}: sequence number N{n} not found in the calling program"),
                ));
            }
            let to = self.prog.src.as_ref().expect("loaded").tell().offset;
            self.leave_loops(to);
        }
        Ok(())
    }

    /// M99 in the main program (000 §2.4.4).
    fn main_m99(&mut self, p: Option<(u32, u32)>, l: Option<(u32, u32)>, at: u32) -> R<()> {
        self.corner_open("M99")?;
        let here = self.prog.raw.mark.offset;
        if let Some((n, _)) = l {
            let left = match self.prog.calls.main_repeat {
                Some((off, left)) if off == here => left,
                _ => n.saturating_sub(1),
            };
            if left == 0 {
                self.prog.calls.main_repeat = None;
                return Ok(());
            }
            self.prog.calls.main_repeat = Some((here, left - 1));
        } else if self.main_m99_last_pass()? {
            return Ok(());
        }
        self.count_jump(at)?;
        self.prog.loops.clear();
        match p {
            Some((n, pat)) => {
                if !self.seek_sequence(n, true) {
                    return Err(self.alarm(
                        AlarmKind::SequenceNotFound,
                        pat,
                        format!("M99 P{n}: sequence number N{n} not found"),
                    ));
                }
                Ok(())
            }
            None => {
                let s = self.prog.program_start;
                self.seek(s)
            }
        }
    }

    /// A main program ending in M99 without L (a bar-feed loop) repeats
    /// until the operator resets the control. kerf runs
    /// `Settings::main_passes` passes (0 = 1) and then ends the program
    /// (status 0) with an operator message saying so. True when this M99
    /// ended it.
    fn main_m99_last_pass(&mut self) -> R<bool> {
        self.prog.calls.main_passes += 1;
        let n = self.settings.main_passes.max(1);
        if self.prog.calls.main_passes < n {
            return Ok(false);
        }
        let s = if n == 1 { "" } else { "es" };
        self.emit(Canon::Message(format!(
            "M99 in the main program: ended after {n} pass{s} (the control repeats it until reset; --set main_passes=N runs N)"
        )));
        self.emit_end(99)?;
        self.finished = true;
        Ok(true)
    }

    /// G65 P_ L_ (000 §14.1.1) and G66 P_ L_ (§14.1.2) with arguments:
    /// one block, everything but P and L an argument. G65 calls at once;
    /// G66 only records the call for the move blocks that follow.
    pub(super) fn g65(&mut self, code10: u16, at: u32) -> R<()> {
        let modal = self.means_of(code10) == Some(Means::ModalCall(true));
        let name = if modal { "G66" } else { "G65" };
        if let Some((_, w)) = self.words.corner() {
            return Err(self.alarm(
                AlarmKind::CornerNoMove,
                w.at,
                format!(",C/,R in a {name} block: it belongs to a G01/G02/G03 move"),
            ));
        }
        if self.words.ng > 1 {
            let (c, gat) = self.words.g[if self.words.g[0].0 == code10 { 1 } else { 0 }];
            return Err(self.alarm(
                AlarmKind::IllegalAddress,
                gat,
                format!(
                    "G{} in a {name} block (G is not an argument)",
                    fmt_num(c as f64 / 10.0)
                ),
            ));
        }
        let Some((p, _)) = self.int_word(b'P', 99_999_999.0)? else {
            return Err(self.alarm(
                AlarmKind::NoProgramNumber,
                at,
                format!("{name} without P (program number)"),
            ));
        };
        let count = self.int_word(b'L', 9999.0)?.map(|l| l.0).unwrap_or(1);
        let args = self.g65_args(false)?;
        if modal {
            let max = self.cfg.profile.param("max_macro_nesting", 4.0) as usize;
            if self.prog.calls.modal.len() >= max {
                return Err(self.alarm(
                    AlarmKind::CallNesting,
                    at,
                    format!("G66 modal calls nested more than {max} deep"),
                ));
            }
            self.prog.calls.modal.push(ModalCall {
                prog: p,
                count,
                args: Box::new(args),
            });
            self.modal
                .set_meaning(self.cfg.dialect, Means::ModalCall(true));
            return Ok(());
        }
        if count == 0 {
            return Ok(());
        }
        self.call(Some(p), None, None, count, true, at, Some(args))
    }

    /// True when the block names a G or M code that calls a macro (its
    /// letters are then arguments).
    pub(super) fn code_call_block(&self) -> bool {
        match &self.hx.code_calls {
            Some(cc) if !self.prog.calls.stack.iter().any(|f| f.by_code) => {
                self.words
                    .gs()
                    .iter()
                    .any(|&(c, _)| cc.g.iter().any(|g| g.0 == c))
                    || self
                        .words
                        .ms()
                        .iter()
                        .any(|&(m, _)| cc.m.iter().any(|x| x.0 == m))
            }
            _ => false,
        }
    }

    /// Macro call by G or M code, subprogram call by T code (000
    /// §14.1.3-14.1.6). Some(result) when the block was such a call.
    /// Not made inside a program that a code called.
    #[inline(never)]
    pub(super) fn code_call(&mut self) -> R<Option<bool>> {
        let Some(cc) = self.hx.code_calls.as_ref() else {
            return Ok(None);
        };
        if self.prog.calls.stack.iter().any(|f| f.by_code) {
            return Ok(None);
        }
        let mut hit: Option<(u32, u32, bool)> = None;
        for &(c, at) in self.words.gs() {
            if let Some(&(_, prog)) = cc.g.iter().find(|g| g.0 == c) {
                hit = Some((prog, at, false));
            }
        }
        for &(m, at) in self.words.ms() {
            if let Some(&(_, prog)) = cc.m.iter().find(|x| x.0 == m) {
                hit = hit.or(Some((prog, at, true)));
            }
        }
        let t_call = cc.t;
        if let Some((prog, at, by_m)) = hit {
            let others = self.words.ng - usize::from(!by_m) + self.words.nm - usize::from(by_m);
            if others > 0 {
                return Err(self.alarm(
                    AlarmKind::IllegalAddress,
                    at,
                    format!("a block that calls macro O{prog} by code has other G or M codes"),
                ));
            }
            let count = self.int_word(b'L', 9999.0)?.map(|l| l.0).unwrap_or(1);
            let args = self.g65_args(by_m)?;
            if count == 0 {
                return Ok(Some(true));
            }
            self.call(Some(prog), None, None, count, true, at, Some(args))?;
            if let Some(f) = self.prog.calls.stack.last_mut() {
                f.by_code = true;
            }
            return Ok(Some(true));
        }
        if t_call {
            if let Some(t) = self.words.take(b'T') {
                // The T value goes to #149 (Fanuc; 000 names no variable),
                // the rest of the block runs, then M98 P9000.
                self.vars
                    .set(149.0, Some(t.v))
                    .map_err(|m| self.alarm(m.kind, t.at, m.message))?;
                let r = self.execute_block()?;
                self.call(Some(9000), None, None, 1, false, t.at, None)?;
                if let Some(f) = self.prog.calls.stack.last_mut() {
                    f.by_code = true;
                }
                return Ok(Some(r));
            }
        }
        Ok(None)
    }

    /// Reset: leaves every call (back to the main program's file, start and
    /// header, its own locals put back), drops the G66 calls, the M98 end
    /// sequence and the main-program M99 L count.
    pub(super) fn reset_calls(&mut self) {
        if let Some(bottom) = self.prog.calls.stack.first() {
            let (file, start, header) = (bottom.file, bottom.start, bottom.header);
            // The main level's locals are in the first macro call's frame.
            let main_locals = self.prog.calls.stack.iter().find_map(|f| f.locals.clone());
            self.switch_to(file);
            self.prog.program_start = start;
            self.prog.calls.header = header;
            if let Some(l) = main_locals {
                self.vars.put_locals(&l);
            }
        }
        self.prog.calls.stack.clear();
        self.prog.calls.end_seq = None;
        self.prog.calls.main_repeat = None;
        self.prog.calls.main_passes = 0;
        self.prog.calls.modal.clear();
    }

    /// G67: cancels the most recent G66.
    pub(super) fn g67(&mut self) {
        self.prog.calls.modal.pop();
        let on = !self.prog.calls.modal.is_empty();
        self.modal
            .set_meaning(self.cfg.dialect, Means::ModalCall(on));
    }

    /// After a block with an axis move while G66 is in force: call the
    /// modal macro (000 §14.1.8). A move inside the macro of G66 entry i
    /// calls entry i-1 (the next outer one); a move outside every modal
    /// macro calls the newest entry; moves in the oldest entry's macro call
    /// nothing.
    pub(super) fn modal_call(&mut self, at: u32) -> R<()> {
        let n = self.prog.calls.modal.len();
        let inside = self.prog.calls.stack.iter().rev().find_map(|f| f.modal_idx);
        let idx = match inside {
            None => n - 1,
            Some(0) => return Ok(()),
            Some(i) => (i - 1).min(n - 1),
        };
        let (prog, count) = (
            self.prog.calls.modal[idx].prog,
            self.prog.calls.modal[idx].count,
        );
        if count == 0 {
            return Ok(());
        }
        let args = *self.prog.calls.modal[idx].args;
        self.call(Some(prog), None, None, count, true, at, Some(args))?;
        if let Some(f) = self.prog.calls.stack.last_mut() {
            f.modal_idx = Some(idx);
        }
        Ok(())
    }

    /// Binds the arguments: specification I by letter, I/J/K as the sets
    /// of specification II; a later word wins where they meet.
    fn g65_args(&mut self, skip_m: bool) -> R<[Option<f64>; 33]> {
        let mut a = [None; 33];
        let mut set: i32 = -1;
        let mut last_k = 3usize;
        let scale = if self.modal.metric() { 0.001 } else { 0.0001 };
        for i in 0..self.prog.block.words.len() {
            let w = self.prog.block.words[i];
            let Addr::L(l) = w.addr else { continue };
            if matches!(l, b'G' | b'P' | b'L' | b'N' | b'O') || (skip_m && l == b'M') {
                continue;
            }
            let v = match w.val {
                Val::Num(n) => {
                    let dimension = matches!(
                        l,
                        b'A' | b'B'
                            | b'C'
                            | b'I'
                            | b'J'
                            | b'K'
                            | b'Q'
                            | b'R'
                            | b'U'
                            | b'V'
                            | b'W'
                            | b'X'
                            | b'Y'
                            | b'Z'
                    );
                    if dimension && !n.point && !self.cfg.profile.calculator_decimal {
                        let s = if matches!(l, b'A' | b'B' | b'C') {
                            0.001
                        } else {
                            scale
                        };
                        Some(n.value * s)
                    } else {
                        Some(n.value)
                    }
                }
                Val::Expr(e) => self.eval(e, w.at)?,
            };
            let var = if let Some(k) = b"IJK".iter().position(|&c| c == l) {
                if set < 0 || k <= last_k {
                    set += 1;
                }
                last_k = k;
                if set >= 10 {
                    return Err(self.alarm(
                        AlarmKind::OutOfRange,
                        w.at,
                        "more than 10 sets of I, J, K arguments",
                    ));
                }
                4 + 3 * set as usize + k
            } else {
                match arg_var(l) {
                    Some(n) => n,
                    None => {
                        return Err(self.alarm(
                            AlarmKind::IllegalAddress,
                            w.at,
                            format!("{} is not a macro argument", l as char),
                        ))
                    }
                }
            };
            // A vacant argument leaves the variable vacant.
            if v.is_some() {
                a[var - 1] = v;
            }
        }
        Ok(a)
    }

    /// `#3000 = n (MESSAGE)`: user alarm 3000+n; `#3006 = n (MESSAGE)`:
    /// message and stop. Ok(false) for any other variable.
    pub(super) fn system_write(&mut self, i: f64, v: Option<f64>, at: u32) -> R<bool> {
        if i != 3000.0 && i != 3006.0 {
            return Ok(false);
        }
        let n = v.unwrap_or(0.0);
        let text = self
            .prog
            .block
            .comments
            .first()
            .map(|&(s, e)| {
                String::from_utf8_lossy(&self.prog.raw.text[s as usize..e as usize])
                    .trim()
                    .to_string()
            })
            .unwrap_or_default();
        if i == 3000.0 {
            if !(0.0..=999.0).contains(&n) || n.fract() != 0.0 {
                return Err(self.alarm(
                    AlarmKind::OutOfRange,
                    at,
                    format!("#3000 = {}: alarm number must be 0-999", fmt_num(n)),
                ));
            }
            let (line, col) = self.prog.raw.line_col(at as usize);
            let msg = if text.is_empty() {
                format!("user alarm {}", 3000 + n as u32)
            } else {
                text
            };
            return Err(kerf_canon::Alarm::new(
                format!("{}", 3000 + n as u32),
                msg,
                SrcRef {
                    file: self.prog.file_id,
                    line,
                    col,
                },
            ));
        }
        let msg = if text.is_empty() { fmt_num(n) } else { text };
        self.emit(Canon::Message(msg));
        self.emit(Canon::Stop { optional: false });
        Ok(true)
    }
}
