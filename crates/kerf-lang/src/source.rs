//! Streaming line source: reads a program one logical block at a time from
//! any `Read + Seek`, never holding more than one block (plus the read
//! buffer) in memory. Supports seeking back to a remembered position, which
//! the interpreter uses for GOTO, WHILE loops and repeat commands.

use std::io::{self, BufRead, BufReader, Read, Seek, SeekFrom};

use crate::ahead::{ReadAhead, ScanSpec};
use crate::plain::PlainScan;

/// Anything a program can be read from (`Send`, so that an interpreter
/// can run on a thread of its own).
pub trait ProgramRead: Read + Seek + Send {}
impl<T: Read + Seek + Send> ProgramRead for T {}

/// A position in a source that can be returned to with [`LineSource::seek`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Mark {
    /// Byte offset of the start of a physical line.
    pub offset: u64,
    /// 1-based number of that line.
    pub line: u32,
}

/// One logical block of text as read from the source.
#[derive(Debug, Default)]
pub struct RawBlock {
    /// The text with line ends (and continuation backslashes) removed.
    pub text: Vec<u8>,
    /// Where the block starts.
    pub mark: Mark,
    /// For continued blocks: (byte index in `text`, line number) of each
    /// physical line after the first.
    pub continuations: Vec<(u32, u32)>,
    /// True when the block was longer than the reader's limit; `text` then
    /// holds only the first `max_len` bytes.
    pub overlong: bool,
    /// The plain-block scan of `text` made by a read-ahead thread
    /// ([`LineSource::read_ahead`]); [`PlainScan::Unknown`] otherwise.
    pub scan: PlainScan,
}

impl RawBlock {
    /// Makes `self` a copy of `other`, reusing `self`'s buffers.
    pub fn copy_from(&mut self, other: &RawBlock) {
        self.text.clone_from(&other.text);
        self.mark = other.mark;
        self.continuations.clone_from(&other.continuations);
        self.overlong = other.overlong;
        self.scan = other.scan;
    }

    /// Maps a byte index of `text` to (line, 1-based column).
    pub fn line_col(&self, idx: usize) -> (u32, u32) {
        let mut line = self.mark.line;
        let mut start = 0usize;
        for &(at, l) in &self.continuations {
            if (at as usize) <= idx {
                line = l;
                start = at as usize;
            }
        }
        (line, (idx - start) as u32 + 1)
    }
}

/// Reads logical blocks from a seekable byte stream.
pub struct LineSource {
    inner: BufReader<Box<dyn ProgramRead>>,
    offset: u64,
    line: u32,
    max_len: usize,
    continuation: bool,
    eof: bool,
    /// Where the underlying reader is (`offset` may differ after a
    /// [`LineSource::seek`] until the next read).
    phys: u64,
    /// The reading done on another thread ([`LineSource::read_ahead`]).
    ahead: Option<Box<ReadAhead>>,
}

impl LineSource {
    /// Wraps a reader. `max_len` bounds the bytes kept per block (longer
    /// blocks are flagged, not stored); `continuation` enables the Hurco
    /// trailing-backslash line continuation.
    pub fn new(r: Box<dyn ProgramRead>, max_len: usize, continuation: bool) -> LineSource {
        LineSource::with_buffer(r, 64 * 1024, max_len, continuation)
    }

    /// [`LineSource::new`] with a read buffer of `cap` bytes.
    fn with_buffer(
        r: Box<dyn ProgramRead>,
        cap: usize,
        max_len: usize,
        continuation: bool,
    ) -> LineSource {
        LineSource {
            inner: BufReader::with_capacity(cap, r),
            offset: 0,
            line: 0,
            max_len,
            continuation,
            eof: false,
            phys: 0,
            ahead: None,
        }
    }

    /// Moves the reading to a thread of its own, which reads ahead of
    /// the caller from the current position and scans every block for
    /// the plain-block path as `spec` says (the scan is in each block's
    /// [`RawBlock::scan`]). Every read gives what it gives without (the
    /// same blocks, marks, ends and errors, after any seek); see
    /// `ahead.rs`. Does nothing if the source already reads ahead; an
    /// error (the thread could not be started) leaves it reading on the
    /// caller's thread.
    pub fn read_ahead(&mut self, spec: ScanSpec) -> io::Result<()> {
        if self.ahead.is_some() {
            return Ok(());
        }
        let mut a = ReadAhead::spawn(spec)?;
        // The source moves to the thread; this one keeps its position.
        let none: Box<dyn ProgramRead> = Box::new(io::Cursor::new(Vec::new()));
        let mut src = LineSource::with_buffer(none, 0, self.max_len, self.continuation);
        std::mem::swap(self, &mut src);
        (self.offset, self.line) = (src.offset, src.line);
        a.give(src);
        self.ahead = Some(Box::new(a));
        Ok(())
    }

    /// Whether the source reads ahead on a thread of its own.
    pub fn reads_ahead(&self) -> bool {
        self.ahead.is_some()
    }

    /// The position of the next line to be read.
    pub fn tell(&self) -> Mark {
        Mark {
            offset: self.offset,
            line: self.line + 1,
        }
    }

    /// Returns to a position previously obtained from [`LineSource::tell`] or
    /// [`RawBlock::mark`].
    ///
    /// The move is lazy: it is recorded here and made on the underlying
    /// reader at the next read, so an interpreter replaying cached blocks
    /// can move through the text without touching the reader. A failure of
    /// the move is reported by that read.
    pub fn seek(&mut self, m: Mark) -> io::Result<()> {
        self.offset = m.offset;
        self.line = m.line.saturating_sub(1);
        self.eof = false;
        Ok(())
    }

    /// Moves the underlying reader to `offset` if a seek left it elsewhere.
    fn sync(&mut self) -> io::Result<()> {
        if self.phys != self.offset {
            // Relative seeks keep the read buffer when the target is inside
            // it, so tight loops do not re-read the file.
            if self.phys <= i64::MAX as u64 && self.offset <= i64::MAX as u64 {
                self.inner
                    .seek_relative(self.offset as i64 - self.phys as i64)?;
            } else {
                self.inner.seek(SeekFrom::Start(self.offset))?;
            }
            self.phys = self.offset;
        }
        Ok(())
    }

    /// Reads one physical line into `out`, appending at most `room` bytes.
    /// Returns (bytes consumed from the stream, hit end of stream, truncated).
    fn read_physical(&mut self, out: &mut Vec<u8>, room: usize) -> io::Result<(u64, bool)> {
        let mut consumed = 0u64;
        let mut truncated = false;
        loop {
            let buf = self.inner.fill_buf()?;
            if buf.is_empty() {
                self.eof = true;
                break;
            }
            let (chunk, found) = match memchr::memchr(b'\n', buf) {
                Some(i) => (&buf[..i], Some(i)),
                None => (buf, None),
            };
            let space = room.saturating_sub(out.len());
            if chunk.len() > space {
                truncated = true;
                out.extend_from_slice(&chunk[..space]);
            } else {
                out.extend_from_slice(chunk);
            }
            let used = match found {
                Some(i) => i + 1,
                None => buf.len(),
            };
            self.inner.consume(used);
            consumed += used as u64;
            if found.is_some() {
                break;
            }
        }
        if out.last() == Some(&b'\r') {
            out.pop();
        }
        Ok((consumed, truncated))
    }

    /// Reads the next logical block into `raw`. Returns false at end of text.
    pub fn next_block(&mut self, raw: &mut RawBlock) -> io::Result<bool> {
        if let Some(a) = self.ahead.as_mut() {
            let pos = Mark {
                offset: self.offset,
                line: self.line + 1,
            };
            return match a.next_block(pos, raw)? {
                Some(next) => {
                    self.offset = next.offset;
                    self.line = next.line - 1;
                    Ok(true)
                }
                None => Ok(false),
            };
        }
        raw.scan = PlainScan::Unknown;
        raw.text.clear();
        raw.continuations.clear();
        raw.overlong = false;
        if self.eof {
            return Ok(false);
        }
        raw.mark = self.tell();
        self.sync()?;
        let (n, trunc) = self.read_physical(&mut raw.text, self.max_len)?;
        if n == 0 && self.eof {
            return Ok(false);
        }
        self.offset += n;
        self.phys = self.offset;
        self.line += 1;
        raw.overlong |= trunc;
        if self.continuation {
            while !self.eof && ends_with_backslash(&raw.text) {
                // Drop the backslash (and blanks after it) and join the next line.
                while matches!(raw.text.last(), Some(b' ' | b'\t')) {
                    raw.text.pop();
                }
                raw.text.pop();
                let at = raw.text.len() as u32;
                let (n, trunc) = self.read_physical(&mut raw.text, self.max_len)?;
                if n == 0 {
                    break;
                }
                self.offset += n;
                self.phys = self.offset;
                self.line += 1;
                raw.overlong |= trunc;
                raw.continuations.push((at, self.line));
            }
        }
        Ok(true)
    }
}

/// Whether a line continues on the next: a backslash at its end (blanks
/// after it allowed), outside a comment (a backslash inside a comment
/// does not continue the line).
pub fn ends_with_backslash(t: &[u8]) -> bool {
    let trimmed = t.iter().rposition(|&c| c != b' ' && c != b'\t');
    match trimmed {
        Some(i) if t[i] == b'\\' => {
            let opens = t[..i].iter().filter(|&&c| c == b'(').count();
            let closes = t[..i].iter().filter(|&&c| c == b')').count();
            opens <= closes
        }
        _ => false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::io::Cursor;

    fn src(s: &str, cont: bool) -> LineSource {
        LineSource::new(Box::new(Cursor::new(s.as_bytes().to_vec())), 256, cont)
    }

    #[test]
    fn reads_lines_crlf_and_last_without_newline() {
        let mut s = src("G00 X1\r\nG01 Y2\nM30", false);
        let mut b = RawBlock::default();
        assert!(s.next_block(&mut b).unwrap());
        assert_eq!(b.text, b"G00 X1");
        assert_eq!(b.mark, Mark { offset: 0, line: 1 });
        assert!(s.next_block(&mut b).unwrap());
        assert_eq!(b.text, b"G01 Y2");
        assert_eq!(b.mark, Mark { offset: 8, line: 2 });
        assert!(s.next_block(&mut b).unwrap());
        assert_eq!(b.text, b"M30");
        assert!(!s.next_block(&mut b).unwrap());
    }

    #[test]
    fn seek_returns_to_a_line() {
        let mut s = src("A\nB\nC\n", false);
        let mut b = RawBlock::default();
        s.next_block(&mut b).unwrap();
        let m = s.tell();
        s.next_block(&mut b).unwrap();
        s.next_block(&mut b).unwrap();
        assert!(!s.next_block(&mut b).unwrap());
        s.seek(m).unwrap();
        s.next_block(&mut b).unwrap();
        assert_eq!(b.text, b"B");
        assert_eq!(b.mark.line, 2);
    }

    #[test]
    fn seek_is_lazy_and_reads_from_the_new_place() {
        // 20,000 lines "L<n>" (beyond the 64 kB read buffer): seek far
        // ahead, back to the start, twice in a row (only the last counts),
        // and past the end of the text.
        let text: String = (1..=20_000).map(|i| format!("L{i}\n")).collect();
        let mut s = src(&text, false);
        let mut b = RawBlock::default();
        s.next_block(&mut b).unwrap();
        let second = s.tell();
        // Line n starts after lines 1..n-1; "L1\n".."L9\n" are 3 bytes,
        // "L10\n".."L99\n" 4, "L100\n".."L999\n" 5, "L1000\n".."L9999\n"
        // 6: line 15000 starts at 9*3 + 90*4 + 900*5 + 9000*6 + 5000*7.
        let far = Mark {
            offset: 27 + 360 + 4500 + 54_000 + 5000 * 7,
            line: 15_000,
        };
        s.seek(far).unwrap();
        assert_eq!(s.tell(), far);
        s.next_block(&mut b).unwrap();
        assert_eq!((b.text.as_slice(), b.mark), (&b"L15000"[..], far));
        s.seek(Mark { offset: 0, line: 1 }).unwrap();
        s.seek(second).unwrap();
        s.next_block(&mut b).unwrap();
        assert_eq!((b.text.as_slice(), b.mark.line), (&b"L2"[..], 2));
        s.seek(Mark {
            offset: text.len() as u64 + 10,
            line: 30_000,
        })
        .unwrap();
        assert!(!s.next_block(&mut b).unwrap());
    }

    #[test]
    fn backslash_continues_a_hurco_block() {
        let mut s = src("G78 X1 \\\n Z2\nM30\n", true);
        let mut b = RawBlock::default();
        s.next_block(&mut b).unwrap();
        assert_eq!(b.text, b"G78 X1  Z2");
        assert_eq!(b.line_col(8), (2, 2));
        assert_eq!(b.line_col(2), (1, 3));
        s.next_block(&mut b).unwrap();
        assert_eq!(b.text, b"M30");
        assert_eq!(b.mark.line, 3);
    }

    #[test]
    fn overlong_line_is_truncated_and_flagged() {
        let long = "X".repeat(1000) + "\nM30\n";
        let mut s = LineSource::new(Box::new(Cursor::new(long.into_bytes())), 16, false);
        let mut b = RawBlock::default();
        s.next_block(&mut b).unwrap();
        assert!(b.overlong);
        assert_eq!(b.text.len(), 16);
        s.next_block(&mut b).unwrap();
        assert_eq!(b.text, b"M30");
        assert_eq!(b.mark.line, 2);
    }
}
