//! The parser's fast path for plain words gives the same block (words,
//! values to the bit, byte positions, errors) as its general reader, on
//! generated blocks built from the pieces the fast path decides on: signs,
//! digits, points, blanks inside and after numbers, digit counts around
//! the limit, and words it must leave to the general reader.

use kerf_lang::{parse_block, parse_block_general, Block, LexOptions};
use proptest::prelude::*;

/// One word's text: an address letter (either case) and a value.
fn word() -> impl Strategy<Value = String> {
    let letter = prop::sample::select(b"GXYZFIJKRMSTHDPQABCNOUVWLgxyzf".to_vec());
    let sign = prop::sample::select(vec!["", "", "", "-", "+", "- ", "--"]);
    let int = "[0-9]{0,14}";
    let point = prop::sample::select(vec!["", ".", ".", " .", ". "]);
    let frac = "[0-9]{0,10}";
    let blanks = prop::sample::select(vec!["", "", " ", "  ", "\t", " \r"]);
    let inner = prop::sample::select(vec!["", "", "", "", " ", "\t"]);
    let other = prop::sample::select(vec![
        "", "", "", "", "", "", "#1", "[1+2]", "#[#1]", "(C)", ";", "/", ",C1.", "=",
    ]);
    (letter, sign, int, inner, point, frac, blanks, other).prop_map(
        |(l, sign, int, inner, point, frac, blanks, other)| {
            let (head, tail) = int.split_at(int.len() / 2);
            format!(
                "{}{sign}{head}{inner}{tail}{point}{frac}{blanks}{other}",
                l as char
            )
        },
    )
}

fn block_text() -> impl Strategy<Value = String> {
    (prop::collection::vec(word(), 0..8), "[ ]{0,2}").prop_map(|(ws, lead)| lead + &ws.concat())
}

fn both(text: &str, o: &LexOptions) -> (String, String) {
    let (mut fast, mut general) = (Block::default(), Block::default());
    let r_fast = parse_block(text.as_bytes(), o, &mut fast);
    let r_general = parse_block_general(text.as_bytes(), o, &mut general);
    (
        format!("{r_fast:?} {fast:?}"),
        format!("{r_general:?} {general:?}"),
    )
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(4000))]

    #[test]
    fn fast_and_general_paths_read_the_same_block(text in block_text(), max in 4u8..=14) {
        let o = LexOptions { max_digits: max, ..LexOptions::default() };
        let (fast, general) = both(&text, &o);
        prop_assert_eq!(fast, general, "{:?}", text);
    }
}

#[test]
fn the_surface_blocks_read_the_same_both_ways() {
    let o = LexOptions::default();
    for text in [
        "G01 X6.7292 Y0.0000 Z43.0946 F1500.",
        "G00 X-0.5000 Y-12.25",
        "X0.42928932 Y-.5 Z-0",
        "G01X1.Y2.Z3.F4",
        "X123456789012 Y1234567890123",
        "X1 2.5 Y-3 .25",
    ] {
        let (fast, general) = both(text, &o);
        assert_eq!(fast, general, "{text}");
    }
    // The fast path's values are the parser's: -0 keeps its sign.
    let mut b = Block::default();
    parse_block(b"X-0", &o, &mut b).unwrap();
    assert!(format!("{:?}", b.words[0].val).contains("-0.0"));
}

#[test]
fn a_blank_is_a_space_tab_cr_or_form_feed_only() {
    for c in 0..=255u8 {
        let want = matches!(c, b' ' | b'\t' | b'\r' | 0x0c);
        assert_eq!(kerf_lang::is_blank(c), want, "byte {c:#04x}");
    }
}
