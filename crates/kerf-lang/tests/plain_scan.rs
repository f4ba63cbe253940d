//! The plain-block scanner (`plain_words`) reads exactly what the parser
//! reads: on generated blocks (words the scanner takes and words it must
//! refuse), whenever it says the block is plain, the parser gives a block
//! of the same words (letter, value to the bit, point, digit count, byte
//! position) and nothing else; and a block the parser reads as only such
//! words with no blank inside a number is one the scanner takes.

use kerf_lang::{letter_bit, parse_block, plain_words, Addr, Block, LexOptions, PlainWord, Val};
use proptest::prelude::*;

fn word() -> impl Strategy<Value = String> {
    let letter = prop::sample::select(b"GXYZFXYZGNIMxg".to_vec());
    let sign = prop::sample::select(vec!["", "", "", "-", "+", "--"]);
    let int = "[0-9]{0,14}";
    let point = prop::sample::select(vec!["", ".", ".", " ."]);
    let frac = "[0-9]{0,6}";
    let blanks = prop::sample::select(vec!["", " ", " ", "  ", "\t", " \r"]);
    let other = prop::sample::select(vec![
        "", "", "", "", "", "", "", "", "#1", "(C)", ";", "/", ",C1.",
    ]);
    (letter, sign, int, point, frac, blanks, other).prop_map(
        |(l, sign, int, point, frac, blanks, other)| {
            format!("{}{sign}{int}{point}{frac}{blanks}{other}", l as char)
        },
    )
}

fn block_text() -> impl Strategy<Value = String> {
    (prop::collection::vec(word(), 0..7), "[ ]{0,2}").prop_map(|(ws, lead)| lead + &ws.concat())
}

const GXYZF: u32 =
    letter_bit(b'G') | letter_bit(b'X') | letter_bit(b'Y') | letter_bit(b'Z') | letter_bit(b'F');

/// The parser's words as (letter, value bits, point, digits, at), or None
/// when the block is not only number words of GXYZF, each once.
fn parsed(text: &str, o: &LexOptions) -> Option<Vec<Seen>> {
    let mut b = Block::default();
    parse_block(text.as_bytes(), o, &mut b).ok()?;
    if b.n.is_some() || b.stmt.is_some() || !b.deletes.is_empty() || !b.comments.is_empty() {
        return None;
    }
    let mut out = Vec::new();
    for w in &b.words {
        let (Addr::L(l), Val::Num(n)) = (w.addr, w.val) else {
            return None;
        };
        out.push((l, n.value.to_bits(), n.point, n.digits, w.at));
    }
    Some(out)
}

type Seen = (u8, u64, bool, u8, u32);

fn seen(w: PlainWord) -> Seen {
    (
        w.letter,
        w.num.value.to_bits(),
        w.num.point,
        w.num.digits,
        w.at,
    )
}

/// The scanner's words, or None when it says the block is not plain.
fn scan(text: &str, max: u8) -> Option<Vec<Seen>> {
    let mut out = Vec::new();
    plain_words(text.as_bytes(), max, GXYZF, |w| {
        out.push(seen(w));
        true
    })
    .then_some(out)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(4000))]

    #[test]
    fn a_plain_block_is_what_the_parser_reads(text in block_text(), max in 4u8..=14) {
        let o = LexOptions { max_digits: max, ..LexOptions::default() };
        if let Some(mine) = scan(&text, max) {
            prop_assert_eq!(Some(mine), parsed(&text, &o), "{:?}", text);
        }
    }
}

#[test]
fn the_surface_blocks_are_plain() {
    let o = LexOptions::default();
    for text in [
        "G01 X6.7292 Y0.0000 Z43.0946 F1500.",
        "G00 Z45.2393",
        "G01 Z40.2393 F800.",
        "X-0.5000 Y-12.25",
        "G01X1.Y2.Z3.F4",
        "X-0",
    ] {
        let mine = scan(text, 12);
        assert!(mine.is_some(), "{text}");
        assert_eq!(mine, parsed(text, &o), "{text}");
    }
}
