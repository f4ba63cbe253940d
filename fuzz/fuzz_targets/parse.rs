//! Fuzz target `parse`: arbitrary bytes through the streaming line source and
//! the block parser. Nothing here may panic, hang or allocate without bound.
//!
//! Byte 0 selects the line-source mode (bit 0: Hurco backslash continuation);
//! the rest is the program text. Every block is parsed with the default
//! options (HX / PUMA) and with the Hurco long parameter names and loop
//! comments switched on.
#![no_main]

use kerf_lang::{parse_block, Block, LexOptions, LineSource, RawBlock};
use libfuzzer_sys::fuzz_target;

/// The Hurco G78 multi-letter names (kept in step with
/// kerf_interp::dialect::hurco::LONG_NAMES, plus prefixes of each other to
/// exercise longest-match).
static LONG_NAMES: &[&str] = &["angIn", "XEnd", "ZEnd", "minD", "X", "ang"];

fuzz_target!(|data: &[u8]| {
    let (continuation, text) = match data.split_first() {
        Some((first, rest)) => (first & 1 == 1, rest),
        None => (false, data),
    };
    let mut src = LineSource::new(
        Box::new(std::io::Cursor::new(text.to_vec())),
        256,
        continuation,
    );
    let plain = LexOptions::default();
    let hurco = LexOptions {
        long_names: LONG_NAMES,
        loop_comments: true,
        ..LexOptions::default()
    };
    let mut raw = RawBlock::default();
    let mut block = Block::default();
    let mut blocks = 0usize;
    while let Ok(true) = src.next_block(&mut raw) {
        blocks += 1;
        // A logical block never exceeds the limit the source was given.
        assert!(
            raw.text.len() <= 256,
            "block of {} bytes > max_len 256",
            raw.text.len()
        );
        assert!(
            blocks <= text.len() + 1,
            "more blocks than bytes: the source does not advance"
        );
        for opts in [&plain, &hurco] {
            match parse_block(&raw.text, opts, &mut block) {
                Ok(()) => {}
                Err(e) => {
                    // The error position must be inside (or just past) the text,
                    // and map to a real line/column.
                    assert!(
                        e.at as usize <= raw.text.len(),
                        "error index {} past text {}",
                        e.at,
                        raw.text.len()
                    );
                    let (line, col) = raw.line_col(e.at as usize);
                    assert!(line >= 1 && col >= 1);
                    let _ = e.kind.message();
                }
            }
        }
        let _ = kerf_lang::loop_command(&raw.text);
    }
});
