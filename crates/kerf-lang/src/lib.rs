//! kerf-lang: the NC language of the three controls, as text.
//!
//! [`LineSource`] streams logical blocks from a seekable reader (so a
//! 10-million-block file is never held in memory), and [`parse_block`]
//! turns one block's text into a reusable [`Block`] of words, a macro
//! statement, comments, block-delete markers and Hurco loop commands.
//!
//! This crate knows nothing of execution, machines or units: a word's value
//! is the number as written (with a flag telling whether it had a decimal
//! point); what `X100` means is the interpreter's business.
//!
//! [`plain_words`] recognises a block made only of simple number words and
//! reads it in one pass, with the words [`parse_block`] would give.

pub mod ahead;
pub mod block;
pub mod parse;
pub mod plain;
pub mod source;

pub use ahead::ScanSpec;
pub use block::{Addr, BinOp, Block, Expr, ExprId, Func, LoopCmd, Num, Stmt, Val, Word};
pub use parse::{
    is_blank, loop_command, parse_block, parse_block_general, plain_digits, plain_number, LexError,
    LexErrorKind, LexOptions, PlainDigits,
};
pub use plain::{letter_bit, plain_words, PlainScan, PlainWord, SCAN_WORDS};
pub use source::{ends_with_backslash, LineSource, Mark, ProgramRead, RawBlock};

#[cfg(test)]
mod tests;
