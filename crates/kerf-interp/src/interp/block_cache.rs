//! Parsed-block cache for text that is executed again (WHILE loops, GOTO
//! back, M99 to the program start, subprograms called more than once).
//!
//! A block is cached when it is read a second time (its end lies at or
//! before the furthest point read so far), keyed by file id and byte
//! offset, with its text, its parsed form and the position after it. Later
//! passes swap the cached block in instead of reading and parsing the
//! text again (and swap it back before the next block). A straight-line
//! program never reads a block twice and so never fills the cache;
//! streaming is unchanged.
//!
//! Memory is bounded: at most [`MAX_ENTRIES`] blocks and about
//! [`MAX_BYTES`] bytes. When either would be exceeded the cache is emptied
//! and refills with the blocks repeated from then on (a program whose
//! repeated sections outgrow the cache runs as without it, plus the cost of
//! copying the blocks in).

use std::collections::HashMap;
use std::hash::{BuildHasherDefault, Hasher};

use kerf_lang::{Block, Mark, RawBlock};

/// Most blocks held.
pub(crate) const MAX_ENTRIES: usize = 4096;
/// Most bytes held (text, parsed vectors and the entries themselves).
pub(crate) const MAX_BYTES: usize = 1 << 20;

/// One cached block.
struct Entry {
    raw: Box<RawBlock>,
    block: Box<Block>,
    /// The source position after the block.
    next: Mark,
}

/// A multiply-rotate hasher for the (file, offset) keys (std's SipHash
/// costs more than the rest of a cache hit).
#[derive(Default)]
struct KeyHasher(u64);

impl Hasher for KeyHasher {
    fn finish(&self) -> u64 {
        self.0
    }
    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.write_u64(b as u64);
        }
    }
    fn write_u32(&mut self, n: u32) {
        self.write_u64(n as u64);
    }
    fn write_u64(&mut self, n: u64) {
        self.0 = (self.0.rotate_left(5) ^ n).wrapping_mul(0x51_7c_c1_b7_27_22_0a_95);
    }
}

/// The cache (see the module documentation).
#[derive(Default)]
pub(crate) struct BlockCache {
    map: HashMap<(u32, u64), u32, BuildHasherDefault<KeyHasher>>,
    entries: Vec<Entry>,
    bytes: usize,
    /// The entry whose block is lent out.
    lent: Option<u32>,
}

impl BlockCache {
    /// Lends the block cached at `at` in `file`: swaps its text and parsed
    /// form into `raw` and `block` (two pointers, no copy) and returns the position after
    /// it; None when it is not cached. The caller must hand the block back
    /// with [`BlockCache::give_back`] before it reads or parses into `raw`
    /// or `block` again, and before any other call on the cache.
    #[inline]
    pub fn lend(
        &mut self,
        file: u32,
        at: Mark,
        raw: &mut Box<RawBlock>,
        block: &mut Box<Block>,
    ) -> Option<Mark> {
        debug_assert!(self.lent.is_none());
        let &i = self.map.get(&(file, at.offset))?;
        let e = &mut self.entries[i as usize];
        if e.raw.mark != at {
            return None;
        }
        std::mem::swap(raw, &mut e.raw);
        std::mem::swap(block, &mut e.block);
        self.lent = Some(i);
        Some(e.next)
    }

    /// Takes back the block lent by [`BlockCache::lend`] (if any), leaving
    /// `raw` and `block` with buffers to reuse.
    #[inline]
    pub fn give_back(&mut self, raw: &mut Box<RawBlock>, block: &mut Box<Block>) {
        if let Some(i) = self.lent.take() {
            let e = &mut self.entries[i as usize];
            std::mem::swap(raw, &mut e.raw);
            std::mem::swap(block, &mut e.block);
        }
    }

    /// Caches a block read at `raw.mark` in `file`, followed by `next`.
    pub fn insert(&mut self, file: u32, raw: &RawBlock, block: &Block, next: Mark) {
        debug_assert!(self.lent.is_none());
        let key = (file, raw.mark.offset);
        if self.map.contains_key(&key) {
            return;
        }
        let mut e = Entry {
            raw: Box::default(),
            block: Box::default(),
            next,
        };
        e.raw.copy_from(raw);
        e.block.copy_from(block);
        let size = std::mem::size_of::<Entry>()
            + 32
            + e.raw.text.capacity()
            + e.raw.continuations.capacity() * 8
            + e.block.heap_bytes();
        if self.entries.len() >= MAX_ENTRIES || self.bytes + size > MAX_BYTES {
            self.clear();
            if size > MAX_BYTES {
                return;
            }
        }
        self.map.insert(key, self.entries.len() as u32);
        self.entries.push(e);
        self.bytes += size;
    }

    /// Empties the cache and frees its memory.
    pub fn clear(&mut self) {
        debug_assert!(self.lent.is_none());
        self.map = HashMap::default();
        self.entries = Vec::new();
        self.bytes = 0;
    }

    /// Blocks held.
    pub fn len(&self) -> usize {
        self.entries.len()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn block_at(text: &str, offset: u64) -> (RawBlock, Block) {
        let raw = RawBlock {
            text: text.as_bytes().to_vec(),
            mark: Mark { offset, line: 1 },
            ..RawBlock::default()
        };
        let mut block = Block::default();
        kerf_lang::parse_block(&raw.text, &kerf_lang::LexOptions::default(), &mut block).unwrap();
        (raw, block)
    }

    #[test]
    fn a_cached_block_is_lent_and_given_back() {
        let mut c = BlockCache::default();
        let (raw, block) = block_at("G01 X10", 40);
        let next = Mark {
            offset: 48,
            line: 2,
        };
        c.insert(0, &raw, &block, next);
        assert_eq!(c.len(), 1);
        let (mut r, mut b) = (Box::<RawBlock>::default(), Box::<Block>::default());
        // Not cached: another file, another offset.
        assert_eq!(c.lend(1, raw.mark, &mut r, &mut b), None);
        assert_eq!(c.lend(0, Mark { offset: 0, line: 1 }, &mut r, &mut b), None);
        assert_eq!(c.lend(0, raw.mark, &mut r, &mut b), Some(next));
        assert_eq!(r.text, b"G01 X10");
        assert_eq!(b.words.len(), block.words.len());
        c.give_back(&mut r, &mut b);
        // The entry has its block again.
        assert_eq!(c.lend(0, raw.mark, &mut r, &mut b), Some(next));
        c.give_back(&mut r, &mut b);
        c.clear();
        assert_eq!(c.len(), 0);
    }

    #[test]
    fn the_cache_is_bounded() {
        let mut c = BlockCache::default();
        let next = Mark::default();
        for i in 0..MAX_ENTRIES as u64 + 5 {
            let (raw, block) = block_at("X1", i * 3);
            c.insert(0, &raw, &block, next);
            assert!(c.len() <= MAX_ENTRIES);
        }
        // Full at MAX_ENTRIES: emptied and filled again.
        assert_eq!(c.len(), 5);
    }
}
