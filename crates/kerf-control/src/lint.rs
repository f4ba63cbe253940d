//! The decimal-point check (`KERF-W001`): on these controls a dimension
//! written without a decimal point is in least input increments, so `X118`
//! is 0.118 mm (the least-input-increment rule of all three manuals, which
//! the interpreter applies unless the profile's calculator-type decimal
//! point is set). In a program that otherwise writes its dimensions
//! with a point, the few without one are almost always a slip.
//!
//! The check reads the program text a second time (beside the
//! interpreter, on its own thread started by [`crate::Job::load`]), its
//! blocks as kerf-lang's reader makes them but out of the read buffer
//! (`lint_lines.rs`), plain blocks with `block_dims.rs`
//! and the rest with kerf-lang's parser; it looks at literal X Y Z U V W I J words, K on
//! the lathes (on the HX K is a cycle's repeat count) and R on the HX
//! (an arc radius or a cycle's R level; on the lathes R counts or is
//! coded), leaves out zero (the same either way) and blocks with G04
//! (dwell), G10 (data setting), G65/G66 (macro arguments) or M98, follows
//! G20/G21 for the increment, and does nothing with the profile's
//! calculator-type decimal point.

use std::io;

use kerf_interp::{Dialect, DialectId, Profile};
use kerf_lang::{parse_block, Block, LexOptions, ProgramRead};

use crate::block_dims::{BlockDims, Letters};
use crate::block_points::PointScan;
use crate::lint_lines::Lines;

use crate::warnings::Warning;

/// Most warnings one file gets from this check; the rest are counted in
/// the last one.
const MAX_SHOWN: usize = 20;

/// What the check found in one file.
#[derive(Debug, Default)]
struct Tally {
    with_point: u64,
    without: u64,
    /// (line, column, word) of the first ones without a point.
    first: Vec<(u32, u32, (char, f64, bool))>,
}

/// The parser options the interpreter uses for this profile.
fn lex_options(profile: &Profile, d: &Dialect) -> LexOptions {
    LexOptions {
        long_names: d.long_names,
        loop_comments: d.hurco_syntax,
        max_digits: profile.max_digits,
        max_nesting: if d.id == DialectId::Hx { 10 } else { 5 },
    }
}

/// Checks the program read from `reader` (named `file` in the warnings).
pub fn decimal_points(
    profile: &Profile,
    file: &str,
    reader: Box<dyn ProgramRead>,
) -> io::Result<Vec<Warning>> {
    check_with(profile, file, reader, true)
}

/// [`decimal_points`], with `fast`: blocks whose dimensions all have a
/// point through [`PointScan`] first (the tests compare the two).
fn check_with(
    profile: &Profile,
    file: &str,
    reader: Box<dyn ProgramRead>,
    fast: bool,
) -> io::Result<Vec<Warning>> {
    if profile.calculator_decimal {
        return Ok(Vec::new());
    }
    let d = Dialect::get(profile.dialect);
    let opts = lex_options(profile, d);
    // HX: R is a radius or a cycle's R level; K is a canned cycle's
    // repeat count, left out. Lathes: R counts divisions (G73) or is coded
    // (G76), left out.
    let letters = Letters::new(if d.id == DialectId::Hx {
        b"XYZUVWIJR"
    } else {
        b"XYZUVWIJK"
    });
    let mut inch = false;
    let mut src = Lines::new(reader, profile.max_block_chars.max(1), d.hurco_syntax);
    let mut block = Block::default();
    let mut words = BlockDims::default();
    let mut t = Tally::default();
    let scan = PointScan::new(letters, opts.max_digits);
    while src.next_block()? {
        let text = src.text();
        if fast {
            if let Some(n) = scan.points(text) {
                t.with_point += n;
                continue;
            }
        }
        // Plain blocks without the parser; the rest through it.
        if !words.read_plain(text, letters, opts.max_digits) {
            if parse_block(text, &opts, &mut block).is_err() {
                continue;
            }
            words.read_parsed(&block, letters);
        }
        inch = words.inch.unwrap_or(inch);
        if words.skipped {
            continue;
        }
        for w in &words.dims {
            if w.point {
                t.with_point += 1;
                continue;
            }
            t.without += 1;
            if t.first.len() < MAX_SHOWN {
                let (line, col) = src.line_col(w.at as usize);
                t.first.push((line, col, (w.letter as char, w.value, inch)));
            }
        }
    }
    Ok(warnings(file, &t))
}

/// The warnings of a tally: only when the program writes most of its
/// dimensions with a point.
fn warnings(file: &str, t: &Tally) -> Vec<Warning> {
    if t.without == 0 || t.with_point < t.without {
        return Vec::new();
    }
    let n = t.first.len();
    t.first
        .iter()
        .enumerate()
        .map(|(i, (line, col, (l, v, inch)))| {
            // Shown to the increment, trailing zeros dropped.
            let (inc, digits, unit, g) = if *inch {
                (0.0001, 4, "in", "G20")
            } else {
                (0.001, 3, "mm", "G21")
            };
            let len = format!("{:.*}", digits, v * inc);
            let len = len.trim_end_matches('0').trim_end_matches('.');
            let mut message = format!(
                "{l}{v} has no decimal point, so it is {len} {unit} (in least input \
                 increments, {inc} {unit} in {g}), while this program writes its other \
                 dimensions with a point: {l}{v}. meant?"
            );
            if i + 1 == n && t.without > n as u64 {
                message.push_str(&format!(" ({} more like it)", t.without - n as u64));
            }
            Warning {
                code: "KERF-W001",
                message,
                file: file.to_string(),
                line: *line,
                col: *col,
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn check(machine: &str, text: &str) -> Vec<Warning> {
        let p = Profile::builtin(machine).unwrap();
        let r = Box::new(io::Cursor::new(text.as_bytes().to_vec()));
        decimal_points(&p, "t.nc", r).unwrap()
    }

    #[test]
    fn the_one_word_without_a_point_is_named_where_it_is() {
        let w = check(
            "hx-mc",
            "G90 G0 X10. Y5.\nG1 X118 Y20. F100.\nG2 X30. Y30. R10.\nM30\n",
        );
        assert_eq!(w.len(), 1, "{w:?}");
        assert_eq!((w[0].line, w[0].col), (2, 4));
        assert!(
            w[0].message.starts_with("X118 has no decimal point"),
            "{}",
            w[0].message
        );
    }

    #[test]
    fn a_program_written_without_points_is_left_alone() {
        // Old-style programs in increments throughout: X10000 = 10 mm.
        assert!(check(
            "hx-mc",
            "G90 G0 X10000 Y5000\nG1 X20000 F100\nX30000 Y1.\nM30\n"
        )
        .is_empty());
    }

    #[test]
    fn zero_dwell_data_setting_and_macro_arguments_are_not_counted() {
        let w = check(
            "hx-mc",
            "G0 X0 Y0 Z10.\nG4 X1000\nG10 L2 P1 X-100 Y-50 Z0\nG65 P9000 X12 Y3\nG1 X5. Y6. F100.\nM30\n",
        );
        assert!(w.is_empty(), "{w:?}");
    }

    #[test]
    fn inch_increments_are_a_ten_thousandth() {
        // 000 §8.4: in G20 the least input increment is 0.0001 inch.
        let w = check(
            "hx-mc",
            "G20 G90 G0 X1. Y2. Z.5\nG1 X1.5 F10.\nX25000\nM30\n",
        );
        assert_eq!(w.len(), 1, "{w:?}");
        assert!(w[0].message.contains("so it is 2.5 in"), "{}", w[0].message);
    }

    #[test]
    fn hx_cycle_repeats_and_subprogram_calls_are_not_dimensions() {
        let w = check(
            "hx-mc",
            "G0 X0. Y0.\nM98 P10 Q1 R2 L2\nG81 X10. Y10. Z-5. R2. F100.\nG91 Y-20. K2\nM30\n",
        );
        assert!(w.is_empty(), "{w:?}");
    }

    #[test]
    fn the_lathe_counts_u_and_w_but_not_r() {
        // PUMA G73 U W R: R is the number of divisions, an integer.
        let w = check(
            "puma-lathe",
            "G0 X50. Z2.\nG73 U5. W2. R3\nG1 U-2 W-1.\nM30\n",
        );
        assert_eq!(w.len(), 1, "{w:?}");
        assert_eq!((w[0].line, w[0].col), (3, 4));
    }

    #[test]
    fn generated_programs_get_the_same_warnings_with_and_without_the_fast_path() {
        // Programs of blocks mostly with points, some without, some the
        // check leaves out or that switch G20/G21, on the HX and a lathe:
        // the same warnings (text, line, column) either way.
        const WORDS: [&str; 16] = [
            "X12.5", "Y-3.", "Z0", "X118", "Z-43", "R2.", "K2", "U5.", "W-1", "F100.", "G4", "G20",
            "G21", "M98 P1", "(C)", "N5",
        ];
        let mut x: u64 = 0x2545_F491_4F6C_DD1D;
        for machine in ["hx-mc", "puma-lathe"] {
            let p = Profile::builtin(machine).unwrap();
            for round in 0..40 {
                let mut text = String::new();
                for _ in 0..200 {
                    x ^= x << 13;
                    x ^= x >> 7;
                    x ^= x << 17;
                    text.push_str(if x.is_multiple_of(3) { "G01" } else { "G00" });
                    for k in 0..(x >> 8) % 5 {
                        // Points far more often than not (the check warns
                        // only then), words without one now and then.
                        let w = (x >> (12 + 4 * k)) as usize % 64;
                        let w = if w < WORDS.len() {
                            WORDS[w]
                        } else {
                            WORDS[w % 3]
                        };
                        text.push(' ');
                        text.push_str(w);
                    }
                    text.push('\n');
                }
                let run = |fast| {
                    let r = Box::new(io::Cursor::new(text.as_bytes().to_vec()));
                    check_with(&p, "g.nc", r, fast).unwrap()
                };
                let (fast, general) = (run(true), run(false));
                assert_eq!(
                    format!("{fast:?}"),
                    format!("{general:?}"),
                    "{machine} {round}"
                );
                if round == 0 {
                    assert!(!general.is_empty(), "{machine}: nothing to compare");
                }
            }
        }
    }
}
