//! The program being executed: the files read so far, the source being
//! read and where in it, the block in hand (its text and parsed form), the
//! parsed-block cache, the loops open in the current call level, and the
//! program store and call stack (`Calls`, interp/calls.rs). The loop
//! guard is interp/loop_guard.rs's.

use kerf_canon::SrcRef;
use kerf_lang::{Block, LineSource, Mark, ProgramRead, RawBlock};

use super::block_cache::BlockCache;
use super::calls::Calls;

/// Loops nested in one call level (000 §14.2.5, Fanuc: 3).
pub(super) const MAX_LOOP_DEPTH: usize = 3;

/// Loop scans remembered (an inner loop is entered again on every pass of
/// its outer loop).
const LOOP_ENDS_KEPT: usize = 16;

/// An active WHILE/DO loop: its label, the loop head and the position
/// after its END (found by scanning when the loop is first entered).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct LoopFrame {
    pub(super) label: u32,
    pub(super) start: Mark,
    pub(super) end: Mark,
}

/// A remembered loop scan: file, loop head offset, labels open around it.
pub(super) type LoopKey = (u32, u64, [u32; MAX_LOOP_DEPTH]);

/// Program text and the position in it.
#[derive(Default)]
pub(super) struct Program {
    /// File names by file id (the main program is the first loaded).
    pub(super) files: Vec<String>,
    /// The source being read (None before a program is loaded).
    pub(super) src: Option<LineSource>,
    /// The id of the file being read.
    pub(super) file_id: u32,
    /// Where the main program starts (after a leading `%`).
    pub(super) program_start: Mark,
    /// A leading `%` or a program block has been read: the next `%` ends
    /// the program.
    pub(super) tape_started: bool,
    /// The block being executed: its text and parsed form (boxed so that
    /// the parsed-block cache can swap them in and out).
    pub(super) raw: Box<RawBlock>,
    pub(super) block: Box<Block>,
    /// Parsed blocks of text executed again (loops, jumps back).
    pub(super) cache: BlockCache,
    /// The WHILE/DO loops open in this call level, outermost first.
    pub(super) loops: Vec<LoopFrame>,
    /// Recent loop scans: (file, loop head offset, open labels) → after END.
    loop_ends: Vec<(LoopKey, Mark)>,
    /// Hurco repeat loops open: (passes left, position after the head).
    pub(super) hurco_loops: Vec<(u32, Mark)>,
    /// The source reference of the block being executed.
    pub(super) cur: SrcRef,
    /// Program store and call stack (M98/M99, G65, G66; interp/calls.rs).
    pub(super) calls: Calls,
}

impl Program {
    /// Opens `reader` as the main program `name`, read in blocks of at
    /// most `max_block` characters (`hurco`: the Hurco's syntax).
    pub(super) fn load(
        &mut self,
        name: &str,
        reader: Box<dyn ProgramRead>,
        max_block: usize,
        hurco: bool,
    ) {
        self.files.push(name.to_string());
        self.file_id = (self.files.len() - 1) as u32;
        self.src = Some(LineSource::new(reader, max_block.max(1), hurco));
        self.program_start = Mark { offset: 0, line: 1 };
    }

    /// The name of file `id` ("?" for an id never given out).
    pub(super) fn file_name(&self, id: u32) -> &str {
        self.files
            .get(id as usize)
            .map(String::as_str)
            .unwrap_or("?")
    }

    /// Where the source is (the start of the next block).
    pub(super) fn tell(&self) -> Mark {
        self.src.as_ref().map(|s| s.tell()).unwrap_or_default()
    }

    /// The labels of the loops open in this call level, 0 for none.
    pub(super) fn open_labels(&self) -> [u32; MAX_LOOP_DEPTH] {
        let mut outer = [0u32; MAX_LOOP_DEPTH];
        for (o, l) in outer.iter_mut().zip(&self.loops) {
            *o = l.label;
        }
        outer
    }

    /// The end found by an earlier scan of the loop `key`.
    pub(super) fn loop_end(&self, key: &LoopKey) -> Option<Mark> {
        self.loop_ends
            .iter()
            .find(|e| e.0 == *key)
            .map(|&(_, end)| end)
    }

    /// Remembers the end of the loop `key` (the oldest of
    /// [`LOOP_ENDS_KEPT`] is forgotten).
    pub(super) fn remember_loop_end(&mut self, key: LoopKey, end: Mark) {
        if self.loop_ends.len() >= LOOP_ENDS_KEPT {
            self.loop_ends.remove(0);
        }
        self.loop_ends.push((key, end));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn program(text: &str) -> Program {
        let mut p = Program::default();
        let reader = Box::new(std::io::Cursor::new(text.as_bytes().to_vec()));
        p.load("main.nc", reader, 256, false);
        p
    }

    #[test]
    fn files_get_ids_in_load_order() {
        let mut p = program("G00 X1\n");
        assert_eq!((p.file_id, p.file_name(0)), (0, "main.nc"));
        assert_eq!(p.file_name(7), "?");
        let again = Box::new(std::io::Cursor::new(b"M30\n".to_vec()));
        p.load("mdi", again, 256, false);
        assert_eq!((p.file_id, p.file_name(1)), (1, "mdi"));
        assert_eq!(p.program_start, Mark { offset: 0, line: 1 });
    }

    #[test]
    fn the_cursor_moves_block_by_block() {
        let mut p = program("G00 X1\nG01 Y22\n");
        assert_eq!(p.tell(), Mark { offset: 0, line: 1 });
        let src = p.src.as_mut().unwrap();
        assert!(src.next_block(&mut p.raw).unwrap());
        assert_eq!(p.raw.text, b"G00 X1");
        // "G00 X1\n" is 7 bytes: the next block starts on line 2.
        assert_eq!(p.tell(), Mark { offset: 7, line: 2 });
        // Nothing loaded: the start.
        assert_eq!(Program::default().tell(), Mark::default());
    }

    #[test]
    fn open_labels_and_remembered_loop_ends() {
        let mut p = program("");
        let m = |offset| Mark { offset, line: 1 };
        p.loops.push(LoopFrame {
            label: 2,
            start: m(0),
            end: m(50),
        });
        p.loops.push(LoopFrame {
            label: 1,
            start: m(10),
            end: m(40),
        });
        assert_eq!(p.open_labels(), [2, 1, 0]);
        let key = (0, 10, p.open_labels());
        assert_eq!(p.loop_end(&key), None);
        p.remember_loop_end(key, m(40));
        assert_eq!(p.loop_end(&key), Some(m(40)));
        // The same head with other loops open around it is another scan.
        assert_eq!(p.loop_end(&(0, 10, [1, 0, 0])), None);
        // Only the last LOOP_ENDS_KEPT scans are kept.
        for head in 100..100 + LOOP_ENDS_KEPT as u64 {
            p.remember_loop_end((0, head, [0; 3]), m(head + 1));
        }
        assert_eq!(p.loop_end(&key), None);
        assert_eq!(p.loop_end(&(0, 100, [0; 3])), Some(m(101)));
    }
}
