//! Read-ahead: a [`LineSource`]'s reading and plain-block scan on a
//! thread of their own (opt-in, [`LineSource::read_ahead`]).
//!
//! The thread owns the real source. It reads blocks from where it was
//! told to start, scans each ([`PlainScan::of`]) and sends them in
//! batches (the text of all the batch's blocks in one buffer, a record
//! per block: its mark, the mark after it, its continuations, whether it
//! was over-long, its scan) over a bounded channel; the batches come
//! back over a second channel to be reused, so a run in steady state
//! allocates nothing. The reading side hands out the next record when
//! the source's position is where that record starts; any other position
//! (a seek: GOTO, a loop, M99, the block cache, a scan of the file)
//! starts the thread again there under a new generation number, and the
//! batches of older generations still in the channel are dropped. What a
//! caller reads is therefore what the source itself would give at each
//! position: the same text, marks, continuations, over-long flags, ends
//! and read errors (an error ends the thread's reading until the next
//! seek, and the next read after it starts again from the position).
//!
//! Batches start small after each start (a loop or a jump reads few
//! blocks before the next seek) and double up to [`BATCH`] records.

use std::io;
use std::sync::mpsc::{self, Receiver, Sender, SyncSender, TryRecvError};

use crate::plain::PlainScan;
use crate::source::{LineSource, Mark, RawBlock};

/// Records per batch at most.
pub const BATCH: usize = 512;

/// Records in the first batch after a start.
const FIRST: usize = 16;

/// Batches in flight between the two threads.
const IN_FLIGHT: usize = 4;

/// What the read-ahead thread's scan looks for: the arguments of
/// [`crate::plain_words`] the reader of the blocks will use.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ScanSpec {
    /// The parser's digit limit.
    pub max_digits: u8,
    /// The plain letters ([`crate::letter_bit`]s).
    pub allowed: u32,
}

/// One block read ahead.
#[derive(Clone, Copy, Debug)]
struct Rec {
    mark: Mark,
    /// The source's position after the block.
    next: Mark,
    /// The block's text in the batch's text buffer.
    text: (u32, u32),
    /// Its continuations in the batch's continuation list.
    conts: (u32, u32),
    overlong: bool,
    scan: PlainScan,
}

/// What follows a batch's records.
#[derive(Debug, Default)]
enum Tail {
    /// More batches of this generation.
    #[default]
    More,
    /// The end of the text.
    End,
    /// A read error (the thread waits for a new start).
    Err(io::Error),
}

/// Blocks read ahead, sent as one.
#[derive(Debug, Default)]
struct Batch {
    gen: u64,
    text: Vec<u8>,
    conts: Vec<(u32, u32)>,
    recs: Vec<Rec>,
    tail: Tail,
}

impl Batch {
    fn reset(&mut self, gen: u64) {
        self.gen = gen;
        self.text.clear();
        self.conts.clear();
        self.recs.clear();
        self.tail = Tail::More;
    }

    /// Reads up to `size` blocks from `src` into the batch: false when it
    /// ends at the end of the text or an error.
    fn fill(
        &mut self,
        src: &mut LineSource,
        spec: ScanSpec,
        raw: &mut RawBlock,
        size: usize,
    ) -> bool {
        while self.recs.len() < size {
            match src.next_block(raw) {
                Ok(true) => {}
                Ok(false) => {
                    self.tail = Tail::End;
                    return false;
                }
                Err(e) => {
                    self.tail = Tail::Err(e);
                    return false;
                }
            }
            let t0 = self.text.len() as u32;
            self.text.extend_from_slice(&raw.text);
            let c0 = self.conts.len() as u32;
            self.conts.extend_from_slice(&raw.continuations);
            let scan = if raw.overlong {
                PlainScan::Unknown
            } else {
                PlainScan::of(&raw.text, spec.max_digits, spec.allowed)
            };
            self.recs.push(Rec {
                mark: raw.mark,
                next: src.tell(),
                text: (t0, self.text.len() as u32),
                conts: (c0, self.conts.len() as u32),
                overlong: raw.overlong,
                scan,
            });
        }
        true
    }
}

/// The reading side of a source read ahead.
pub(crate) struct ReadAhead {
    /// Starts: (generation, where).
    ctl: Sender<(u64, Mark)>,
    /// The source, until it is given to the thread.
    give: Option<Sender<LineSource>>,
    rx: Receiver<Batch>,
    back: Sender<Batch>,
    gen: u64,
    /// The batch being handed out and the next record in it.
    cur: Batch,
    idx: usize,
    /// Where the next record starts (None after a read error).
    expect: Option<Mark>,
}

impl ReadAhead {
    /// Starts a thread that waits for its source ([`ReadAhead::give`]).
    pub(crate) fn spawn(spec: ScanSpec) -> io::Result<ReadAhead> {
        let (ctl, ctl_rx) = mpsc::channel();
        let (tx, rx) = mpsc::sync_channel(IN_FLIGHT);
        let (back, back_rx) = mpsc::channel();
        let (give, take) = mpsc::channel();
        std::thread::Builder::new()
            .name("read-ahead".into())
            .spawn(move || {
                if let Ok(src) = take.recv() {
                    work(src, spec, ctl_rx, tx, back_rx)
                }
            })?;
        Ok(ReadAhead {
            ctl,
            give: Some(give),
            rx,
            back,
            gen: 0,
            cur: Batch::default(),
            idx: 0,
            expect: None,
        })
    }

    /// Hands the thread its source: it reads from where `src` is.
    pub(crate) fn give(&mut self, src: LineSource) {
        self.expect = Some(src.tell());
        if let Some(g) = self.give.take() {
            let _ = g.send(src);
        }
    }

    /// The block at `pos` into `raw`: Some(the position after it), None
    /// at the end of the text.
    #[inline]
    pub(crate) fn next_block(&mut self, pos: Mark, raw: &mut RawBlock) -> io::Result<Option<Mark>> {
        if self.expect != Some(pos) {
            self.restart(pos);
        }
        loop {
            if let Some(r) = self.cur.recs.get(self.idx) {
                self.idx += 1;
                raw.text.clear();
                raw.text
                    .extend_from_slice(&self.cur.text[r.text.0 as usize..r.text.1 as usize]);
                raw.continuations.clear();
                if r.conts.1 > r.conts.0 {
                    raw.continuations
                        .extend_from_slice(&self.cur.conts[r.conts.0 as usize..r.conts.1 as usize]);
                }
                raw.mark = r.mark;
                raw.overlong = r.overlong;
                raw.scan = r.scan;
                self.expect = Some(r.next);
                return Ok(Some(r.next));
            }
            match std::mem::take(&mut self.cur.tail) {
                Tail::More => self.next_batch()?,
                Tail::End => {
                    self.cur.tail = Tail::End;
                    return Ok(None);
                }
                Tail::Err(e) => {
                    self.expect = None;
                    return Err(e);
                }
            }
        }
    }

    /// Waits for the next batch of the current generation.
    #[cold]
    fn next_batch(&mut self) -> io::Result<()> {
        loop {
            let Ok(b) = self.rx.recv() else {
                self.expect = None;
                return Err(io::Error::other("the read-ahead thread stopped"));
            };
            if b.gen == self.gen {
                let old = std::mem::replace(&mut self.cur, b);
                let _ = self.back.send(old);
                self.idx = 0;
                return Ok(());
            }
            let _ = self.back.send(b);
        }
    }

    /// Starts the thread again at `pos` under a new generation.
    #[cold]
    fn restart(&mut self, pos: Mark) {
        self.gen += 1;
        let _ = self.ctl.send((self.gen, pos));
        let old = std::mem::take(&mut self.cur);
        let _ = self.back.send(old);
        self.idx = 0;
        self.expect = Some(pos);
    }
}

/// The read-ahead thread: reads and scans batches until the reading side
/// is dropped.
fn work(
    mut src: LineSource,
    spec: ScanSpec,
    ctl: Receiver<(u64, Mark)>,
    out: SyncSender<Batch>,
    back: Receiver<Batch>,
) {
    let (mut gen, mut live, mut size) = (0u64, true, FIRST);
    let mut raw = RawBlock::default();
    loop {
        // While reading, look for a new start between batches; at the
        // end or after an error, wait for one.
        let start = if live {
            match ctl.try_recv() {
                Ok(s) => Some(s),
                Err(TryRecvError::Empty) => None,
                Err(TryRecvError::Disconnected) => return,
            }
        } else {
            match ctl.recv() {
                Ok(s) => Some(s),
                Err(_) => return,
            }
        };
        if let Some((g, at)) = start {
            gen = g;
            // A failed move is reported by the next read.
            let _ = src.seek(at);
            (live, size) = (true, FIRST);
            continue;
        }
        let mut b = back.try_recv().unwrap_or_default();
        b.reset(gen);
        live = b.fill(&mut src, spec, &mut raw, size);
        size = (size * 2).min(BATCH);
        if out.send(b).is_err() {
            return;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::letter_bit;
    use std::io::Cursor;

    const SPEC: ScanSpec = ScanSpec {
        max_digits: 12,
        allowed: letter_bit(b'G') | letter_bit(b'X') | letter_bit(b'Y'),
    };

    fn source(text: &str, ahead: bool) -> LineSource {
        let mut s = LineSource::new(Box::new(Cursor::new(text.as_bytes().to_vec())), 16, true);
        if ahead {
            s.read_ahead(SPEC).unwrap();
            assert!(s.reads_ahead());
        }
        s
    }

    /// Reads `n` blocks (or to the end) and notes each, then the end.
    fn read(s: &mut LineSource, n: usize, out: &mut Vec<String>) {
        let mut raw = RawBlock::default();
        for _ in 0..n {
            match s.next_block(&mut raw) {
                Ok(true) => out.push(format!(
                    "{:?} {:?} {:?} {} -> {:?}",
                    String::from_utf8_lossy(&raw.text),
                    raw.mark,
                    raw.continuations,
                    raw.overlong,
                    s.tell()
                )),
                Ok(false) => {
                    out.push(format!("end at {:?}", s.tell()));
                    return;
                }
                Err(e) => out.push(format!("error {e}")),
            }
        }
    }

    /// The same reads and seeks on a source read here and one read ahead.
    fn both(text: &str, plan: &[(usize, Option<usize>)]) {
        let run = |ahead| {
            let mut s = source(text, ahead);
            let mut out = Vec::new();
            let mut marks = vec![s.tell()];
            for &(n, seek) in plan {
                read(&mut s, n, &mut out);
                marks.push(s.tell());
                if let Some(k) = seek {
                    s.seek(marks[k % marks.len()]).unwrap();
                }
            }
            out
        };
        assert_eq!(run(false), run(true), "{text:?} {plan:?}");
    }

    #[test]
    fn reads_and_seeks_as_the_source_itself() {
        let long: String = (0..3000).map(|i| format!("G01 X{i} Y-{i}.5\n")).collect();
        // Forward, back to the start, to remembered marks (one of them
        // the end, after reading past it), over batch boundaries, and a
        // seek to where the source already is.
        let plan = [
            (5, Some(0)),
            (700, Some(1)),
            (3, Some(2)),
            (5000, Some(1)),
            (2, Some(3)),
            (10, None),
            (1, Some(5)),
            (4000, Some(0)),
            (3, None),
        ];
        both(&long, &plan);
        // Continuation lines, an over-long line, CR LF, no final newline.
        let odd = "G01 X1 \\\n Y2\r\nX123456789012345678901\n(NOTE)\nG00 X1 \\\nY3";
        both(odd, &plan);
        both("", &plan);
    }

    #[test]
    fn the_scan_comes_with_the_block() {
        let mut s = source("G01 X1.5 Y2\nG01 X1 (C)\nZ1\n", true);
        let mut raw = RawBlock::default();
        s.next_block(&mut raw).unwrap();
        assert!(matches!(raw.scan, PlainScan::Words { n: 3, .. }));
        s.next_block(&mut raw).unwrap();
        assert_eq!(raw.scan, PlainScan::No);
        // Z is not in the spec's letters.
        s.next_block(&mut raw).unwrap();
        assert_eq!(raw.scan, PlainScan::No);
        // Read here, nothing is scanned.
        let mut here = source("G01 X1.5\n", false);
        here.next_block(&mut raw).unwrap();
        assert_eq!(raw.scan, PlainScan::Unknown);
    }
}
