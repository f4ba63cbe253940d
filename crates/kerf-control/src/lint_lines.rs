//! [`Lines`]: the blocks of a program for the decimal-point check
//! ([`crate::lint`]), read as kerf-lang's `LineSource` reads them (the
//! same text, line numbers and continuations) but without its copy: a
//! line that lies whole in the read buffer is handed out as a slice of
//! it. Only a line across the buffer's end, a line over the block limit
//! and a continued (Hurco `\`) block are copied, by the same steps as
//! `LineSource::read_physical` and `next_block`. The check reads forward
//! only, so there is no seeking.

use std::io::{self, ErrorKind};

use kerf_lang::{ends_with_backslash, ProgramRead};

/// Bytes read at a time (as `LineSource`'s buffer).
const CAP: usize = 64 * 1024;

/// Forward reader of logical blocks; see the module documentation.
pub(crate) struct Lines {
    r: Box<dyn ProgramRead>,
    buf: Box<[u8]>,
    /// The unread bytes are `buf[start..end]`.
    start: usize,
    end: usize,
    /// A read found the end of the text with nothing left in the buffer.
    eof: bool,
    /// Physical lines read.
    line: u32,
    max_len: usize,
    continuation: bool,
    /// The block: `buf[a..b]`, or `own` when `owned`.
    a: usize,
    b: usize,
    owned: bool,
    own: Vec<u8>,
    /// Line of the block's first physical line.
    first_line: u32,
    /// (byte index in the text, line) of each physical line after the
    /// first of a continued block.
    continuations: Vec<(u32, u32)>,
}

impl Lines {
    /// Reads `r`; `max_len` and `continuation` as `LineSource::new`.
    pub(crate) fn new(r: Box<dyn ProgramRead>, max_len: usize, continuation: bool) -> Lines {
        Lines {
            r,
            buf: vec![0; CAP].into_boxed_slice(),
            start: 0,
            end: 0,
            eof: false,
            line: 0,
            max_len,
            continuation,
            a: 0,
            b: 0,
            owned: false,
            own: Vec::new(),
            first_line: 0,
            continuations: Vec::new(),
        }
    }

    /// The unread bytes, reading more when there are none (`BufRead::fill_buf`).
    fn fill(&mut self) -> io::Result<()> {
        if self.start < self.end {
            return Ok(());
        }
        self.start = 0;
        self.end = 0;
        loop {
            match self.r.read(&mut self.buf) {
                Ok(n) => {
                    self.end = n;
                    return Ok(());
                }
                Err(e) if e.kind() == ErrorKind::Interrupted => continue,
                Err(e) => return Err(e),
            }
        }
    }

    /// One physical line appended to `out` (at most `room` bytes in all),
    /// as `LineSource::read_physical`: the bytes consumed.
    fn physical_into(&mut self, out: &mut Vec<u8>, room: usize) -> io::Result<u64> {
        let mut consumed = 0u64;
        loop {
            self.fill()?;
            let buf = &self.buf[self.start..self.end];
            if buf.is_empty() {
                self.eof = true;
                break;
            }
            let found = memchr::memchr(b'\n', buf);
            let chunk = &buf[..found.unwrap_or(buf.len())];
            let space = room.saturating_sub(out.len());
            out.extend_from_slice(&chunk[..chunk.len().min(space)]);
            let used = found.map_or(buf.len(), |i| i + 1);
            self.start += used;
            consumed += used as u64;
            if found.is_some() {
                break;
            }
        }
        if out.last() == Some(&b'\r') {
            out.pop();
        }
        Ok(consumed)
    }

    /// Reads the next block; false at the end of the text.
    pub(crate) fn next_block(&mut self) -> io::Result<bool> {
        self.continuations.clear();
        self.owned = false;
        self.a = 0;
        self.b = 0;
        if self.eof {
            return Ok(false);
        }
        self.first_line = self.line + 1;
        self.fill()?;
        let buf = &self.buf[self.start..self.end];
        match memchr::memchr(b'\n', buf) {
            Some(i) => {
                // The whole line is in the buffer.
                let (a, mut b) = (self.start, self.start + i.min(self.max_len));
                if b > a && self.buf[b - 1] == b'\r' {
                    b -= 1;
                }
                self.start += i + 1;
                self.line += 1;
                (self.a, self.b) = (a, b);
                if !(self.continuation && ends_with_backslash(&self.buf[a..b])) {
                    return Ok(true);
                }
                let mut own = std::mem::take(&mut self.own);
                own.clear();
                own.extend_from_slice(&self.buf[a..b]);
                self.own = own;
            }
            None => {
                let mut own = std::mem::take(&mut self.own);
                own.clear();
                let n = self.physical_into(&mut own, self.max_len);
                self.own = own;
                if n? == 0 && self.eof {
                    return Ok(false);
                }
                self.line += 1;
            }
        }
        self.owned = true;
        if self.continuation {
            self.join()?;
        }
        Ok(true)
    }

    /// `LineSource::next_block`'s continuation: while the block ends with
    /// a backslash, the next physical line is joined to it.
    fn join(&mut self) -> io::Result<()> {
        let mut own = std::mem::take(&mut self.own);
        let r = (|| {
            while !self.eof && ends_with_backslash(&own) {
                while matches!(own.last(), Some(b' ' | b'\t')) {
                    own.pop();
                }
                own.pop();
                let at = own.len() as u32;
                if self.physical_into(&mut own, self.max_len)? == 0 {
                    break;
                }
                self.line += 1;
                self.continuations.push((at, self.line));
            }
            Ok(())
        })();
        self.own = own;
        r
    }

    /// The block's text (line ends and continuations removed).
    pub(crate) fn text(&self) -> &[u8] {
        if self.owned {
            &self.own
        } else {
            &self.buf[self.a..self.b]
        }
    }

    /// (line, 1-based column) of byte `idx` of the text, as
    /// `RawBlock::line_col`.
    pub(crate) fn line_col(&self, idx: usize) -> (u32, u32) {
        let mut line = self.first_line;
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

#[cfg(test)]
mod tests {
    use super::*;
    use kerf_lang::{LineSource, RawBlock};

    /// A reader that hands out at most `n` bytes a call (lines across
    /// the buffer's end, short reads).
    struct Dribble(io::Cursor<Vec<u8>>, usize);

    impl io::Read for Dribble {
        fn read(&mut self, b: &mut [u8]) -> io::Result<usize> {
            let n = b.len().min(self.1);
            self.0.read(&mut b[..n])
        }
    }

    impl io::Seek for Dribble {
        fn seek(&mut self, p: io::SeekFrom) -> io::Result<u64> {
            self.0.seek(p)
        }
    }

    /// Every block, its first line and the place of each of its bytes,
    /// by `LineSource` and by `Lines`.
    fn both(text: &[u8], max: usize, cont: bool, chunk: usize) {
        let r = |t: &[u8]| Box::new(Dribble(io::Cursor::new(t.to_vec()), chunk));
        let mut src = LineSource::new(r(text), max, cont);
        let mut lines = Lines::new(r(text), max, cont);
        let mut raw = RawBlock::default();
        let mut n = 0;
        loop {
            let (x, y) = (
                src.next_block(&mut raw).unwrap(),
                lines.next_block().unwrap(),
            );
            assert_eq!(x, y, "block {n}");
            if !x {
                break;
            }
            assert_eq!(raw.text, lines.text(), "block {n}");
            for i in 0..raw.text.len() {
                assert_eq!(raw.line_col(i), lines.line_col(i), "block {n} byte {i}");
            }
            n += 1;
        }
        assert!(!lines.next_block().unwrap());
    }

    #[test]
    fn the_blocks_of_the_line_source() {
        let cases: [&[u8]; 12] = [
            b"",
            b"\n",
            b"G00 X1\r\nG01 Y2\nM30",
            b"G00 X1\r\nG01 Y2\nM30\n",
            b"\r\n\r\n\n",
            b"G1 X1 \\\nY2 \\  \nZ3\nM30\n",
            b"G1 X1 (a \\\nY2\n",
            b"G1 X1 \\",
            b"G1 X1 \\\n",
            b"G1 X1 \\\r\n\\\n\\\nG2\n",
            b"X123456789012345\r\nY1\rZ2\n",
            b"%\nO1\nN10 G0 X0\n\n;\n%",
        ];
        for t in cases {
            for cont in [false, true] {
                for chunk in [1, 2, 3, 7, CAP] {
                    both(t, 8, cont, chunk);
                    both(t, 256, cont, chunk);
                }
            }
        }
    }

    #[test]
    fn long_texts_across_the_buffer() {
        // Generated lines of many lengths, some over the limit and some
        // ending in a backslash, over several buffers.
        let mut x: u64 = 0x2545_F491_4F6C_DD1D;
        let mut t = Vec::new();
        while t.len() < 3 * CAP + 100 {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            let len = (x % 90) as usize;
            t.extend((0..len).map(|i| b"G1 X2.5 Y-3 (\\) "[(i + x as usize) % 16]));
            match x % 7 {
                0 => t.extend_from_slice(b"\\\n"),
                1 => t.extend_from_slice(b"\r\n"),
                _ => t.push(b'\n'),
            }
        }
        for cont in [false, true] {
            both(&t, 40, cont, CAP);
            both(&t, 256, cont, 5_000);
        }
        // One line longer than the buffer.
        let mut long = vec![b'X'; CAP + 10];
        long.extend_from_slice(b"\nY1\n");
        both(&long, 100, false, CAP);
        both(&long, CAP * 2, false, CAP);
    }
}
