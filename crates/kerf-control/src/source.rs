//! Opening the main program: what is refused before anything runs (a
//! folder, a binary file, UTF-16 text), the UTF-8 byte-order mark skipped,
//! and a count of the bytes read for a progress display.

use std::fs::File;
use std::io::{self, Cursor, Read, Seek, SeekFrom};
use std::path::Path;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Arc;

use kerf_lang::ProgramRead;

/// How much of the start of a file is examined.
const HEAD: usize = 8192;

/// The UTF-8 byte-order mark.
const BOM: &[u8] = b"\xEF\xBB\xBF";

/// Why the bytes at the start of a file are not program text, if they
/// are not: UTF-16 (by its byte-order mark or its NUL bytes between ASCII
/// characters), or binary data (NUL bytes, or many control characters).
pub fn refuse(head: &[u8]) -> Option<&'static str> {
    if head.starts_with(b"\xFF\xFE") || head.starts_with(b"\xFE\xFF") {
        return Some("UTF-16 text: kerf reads ASCII or UTF-8; save the program as UTF-8");
    }
    let nuls = head.iter().filter(|&&b| b == 0).count();
    if nuls > 0 {
        // ASCII in UTF-16 has every other byte NUL.
        let even = head.iter().step_by(2).filter(|&&b| b == 0).count();
        let odd = nuls - even;
        if head.len() >= 4 && (even.max(odd) * 2 + 2 >= head.len()) && even.min(odd) == 0 {
            return Some("UTF-16 text: kerf reads ASCII or UTF-8; save the program as UTF-8");
        }
        return Some("not an NC program (binary data)");
    }
    let control = head
        .iter()
        .filter(|&&b| b < 0x20 && !matches!(b, b'\t' | b'\n' | b'\r' | 0x0B | 0x0C | 0x1A))
        .count();
    if control * 10 > head.len() {
        return Some("not an NC program (binary data)");
    }
    None
}

/// A program reader that hides a leading UTF-8 byte-order mark (positions
/// are those of the text after it) and counts how far it has read.
pub struct Counted<R> {
    inner: R,
    /// Bytes before the text (3 with a byte-order mark, else 0).
    skip: u64,
    pos: Arc<AtomicU64>,
}

impl<R: Read + Seek> Counted<R> {
    /// Wraps `inner`, positioned at its start; `skip` bytes are hidden.
    fn new(mut inner: R, skip: u64, pos: Arc<AtomicU64>) -> io::Result<Counted<R>> {
        inner.seek(SeekFrom::Start(skip))?;
        Ok(Counted { inner, skip, pos })
    }

    fn seen(&self, inner_pos: u64) -> u64 {
        let p = inner_pos.saturating_sub(self.skip);
        self.pos.store(p, Ordering::Relaxed);
        p
    }
}

impl<R: Read + Seek> Read for Counted<R> {
    fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
        let n = self.inner.read(buf)?;
        self.pos.fetch_add(n as u64, Ordering::Relaxed);
        Ok(n)
    }
}

impl<R: Read + Seek> Seek for Counted<R> {
    fn seek(&mut self, to: SeekFrom) -> io::Result<u64> {
        let to = match to {
            SeekFrom::Start(n) => SeekFrom::Start(n + self.skip),
            other => other,
        };
        let p = self.inner.seek(to)?;
        if p < self.skip {
            // Never into the byte-order mark.
            let p = self.inner.seek(SeekFrom::Start(self.skip))?;
            return Ok(self.seen(p));
        }
        Ok(self.seen(p))
    }
}

/// An opened main program: its reader, its size and the shared count of
/// bytes read so far.
pub struct Opened {
    /// The reader for the interpreter.
    pub reader: Box<dyn ProgramRead>,
    /// Size of the text, bytes (without a byte-order mark).
    pub len: u64,
    /// Bytes read so far (its position in the text).
    pub read: Arc<AtomicU64>,
}

/// A main program that could not be opened or is not program text; the
/// message names it (`FILE: is a folder, not a program`).
#[derive(Debug, thiserror::Error)]
#[error("{name}: {problem}")]
pub struct SourceError {
    /// The file as given (or the text's name).
    pub name: String,
    /// What is wrong.
    pub problem: SourceProblem,
}

/// Why a main program is not read.
#[derive(Debug, thiserror::Error)]
pub enum SourceProblem {
    /// The path is a folder.
    #[error("is a folder, not a program")]
    Folder,
    /// Opening or reading failed.
    #[error("{0}")]
    Io(#[from] io::Error),
    /// Binary data or UTF-16 text (the reason as printed).
    #[error("{0}")]
    NotText(&'static str),
}

impl From<SourceError> for crate::job::LoadError {
    fn from(e: SourceError) -> crate::job::LoadError {
        crate::job::LoadError(e.to_string())
    }
}

/// Opens a program file, refusing what is not program text.
pub fn open_file(path: &Path) -> Result<Opened, SourceError> {
    let named = |problem| SourceError {
        name: path.display().to_string(),
        problem,
    };
    if path.is_dir() {
        return Err(named(SourceProblem::Folder));
    }
    open_reader(path).map_err(named)
}

fn open_reader(path: &Path) -> Result<Opened, SourceProblem> {
    let mut f = File::open(path)?;
    let len = f.metadata()?.len();
    let mut head = Vec::with_capacity(HEAD);
    (&mut f).take(HEAD as u64).read_to_end(&mut head)?;
    let skip = check_head(&head)?;
    let read = Arc::new(AtomicU64::new(0));
    let r = Counted::new(f, skip, read.clone())?;
    Ok(Opened {
        reader: Box::new(r),
        len: len - skip,
        read,
    })
}

/// Opens program text held in memory, as [`open_file`] does a file.
pub fn open_text(name: &str, text: &[u8]) -> Result<Opened, SourceError> {
    let named = |problem| SourceError {
        name: name.to_string(),
        problem,
    };
    let skip = check_head(&text[..text.len().min(HEAD)]).map_err(named)?;
    let read = Arc::new(AtomicU64::new(0));
    let r = Counted::new(Cursor::new(text.to_vec()), skip, read.clone())
        .map_err(|e| named(SourceProblem::Io(e)))?;
    Ok(Opened {
        reader: Box::new(r),
        len: text.len() as u64 - skip,
        read,
    })
}

/// The bytes to skip (a byte-order mark), or why the text is refused.
fn check_head(head: &[u8]) -> Result<u64, SourceProblem> {
    if let Some(why) = refuse(head) {
        return Err(SourceProblem::NotText(why));
    }
    Ok(if head.starts_with(BOM) { 3 } else { 0 })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn text_passes_and_binary_or_utf16_is_named() {
        assert_eq!(refuse("G0 X1.\n(Ø 10 mm)\nM30\n".as_bytes()), None);
        assert_eq!(
            refuse(b"\x7fELF\x02\x01\x01\0\0\0"),
            Some("not an NC program (binary data)")
        );
        let utf16le: Vec<u8> = "G0 X1.\n".bytes().flat_map(|b| [b, 0]).collect();
        assert!(refuse(&utf16le).unwrap().starts_with("UTF-16"));
        assert!(refuse(b"\xFF\xFEG\0").unwrap().starts_with("UTF-16"));
        let ctl: Vec<u8> = (0..100u8).map(|i| i % 8 + 1).collect();
        assert_eq!(refuse(&ctl), Some("not an NC program (binary data)"));
    }

    #[test]
    fn refusals_name_the_program() {
        let e = open_file(Path::new("/")).err().expect("a folder");
        assert!(matches!(e.problem, SourceProblem::Folder));
        assert_eq!(e.to_string(), "/: is a folder, not a program");
        let e = open_text("x.nc", b"G0\0\0\0").err().expect("binary");
        assert_eq!(e.to_string(), "x.nc: not an NC program (binary data)");
        let e = open_file(Path::new("/no/such/file.nc"))
            .err()
            .expect("missing");
        assert!(
            matches!(&e.problem, SourceProblem::Io(io) if io.kind() == io::ErrorKind::NotFound)
        );
    }

    #[test]
    fn a_byte_order_mark_is_hidden_from_reads_and_seeks() {
        let o = open_text("t.nc", b"\xEF\xBB\xBFG0 X1.\nM30\n").unwrap();
        assert_eq!(o.len, 11);
        let mut r = o.reader;
        let mut s = String::new();
        r.read_to_string(&mut s).unwrap();
        assert_eq!(s, "G0 X1.\nM30\n");
        assert_eq!(o.read.load(Ordering::Relaxed), 11);
        assert_eq!(r.seek(SeekFrom::Start(7)).unwrap(), 7);
        let mut rest = String::new();
        r.read_to_string(&mut rest).unwrap();
        assert_eq!(rest, "M30\n");
        assert_eq!(r.seek(SeekFrom::Current(-4)).unwrap(), 7);
    }
}
