//! Unit tests for every lexical form the three manuals use.

use crate::*;

fn parse(s: &str) -> Block {
    parse_with(s, &LexOptions::default())
}

fn parse_with(s: &str, o: &LexOptions) -> Block {
    let mut b = Block::default();
    parse_block(s.as_bytes(), o, &mut b).unwrap_or_else(|e| panic!("{s}: {e:?}"));
    b
}

fn fail(s: &str) -> LexError {
    let mut b = Block::default();
    parse_block(s.as_bytes(), &LexOptions::default(), &mut b).expect_err(s)
}

fn num(b: &Block, i: usize) -> (u8, f64, bool) {
    match (b.words[i].addr, b.words[i].val) {
        (Addr::L(l), Val::Num(n)) => (l, n.value, n.point),
        other => panic!("word {i} is {other:?}"),
    }
}

#[test]
fn percent_and_program_numbers() {
    assert!(parse("%").percent);
    assert_eq!(parse("O1234").program, Some(1234));
    assert_eq!(parse("O 0010").program, Some(10));
    assert_eq!(parse(":1234").program, Some(1234));
    assert_eq!(parse("O0001 (MAIN)").comments.len(), 1);
}

#[test]
fn sequence_numbers_up_to_nine_digits() {
    assert_eq!(parse("N123400000 G00").n, Some(123_400_000));
    assert_eq!(fail("N1234567890").kind, LexErrorKind::TooManyDigits);
    assert_eq!(fail("N1.5").kind, LexErrorKind::BadNumber);
    assert_eq!(fail("N1 N2").kind, LexErrorKind::DuplicateNumber);
}

#[test]
fn numbers_with_and_without_point() {
    let b = parse("X100. Y.5 Z-0.25 A100 B+3");
    assert_eq!(num(&b, 0), (b'X', 100.0, true));
    assert_eq!(num(&b, 1), (b'Y', 0.5, true));
    assert_eq!(num(&b, 2), (b'Z', -0.25, true));
    assert_eq!(num(&b, 3), (b'A', 100.0, false));
    assert_eq!(num(&b, 4), (b'B', 3.0, false));
}

#[test]
fn decimal_values_are_the_nearest_double() {
    let b = parse("X0.1 Y1.2345 Z-123.456");
    assert_eq!(num(&b, 0).1, 0.1);
    assert_eq!(num(&b, 1).1, 1.2345);
    assert_eq!(num(&b, 2).1, -123.456);
}

#[test]
fn spaces_inside_words() {
    let b = parse("G0 1 X 10. Y - 2 .5");
    assert_eq!(num(&b, 0), (b'G', 1.0, false));
    assert_eq!(num(&b, 1), (b'X', 10.0, true));
    assert_eq!(num(&b, 2), (b'Y', -2.5, true));
}

#[test]
fn lower_case_addresses_are_upper_case() {
    let b = parse("g1 x2.");
    assert_eq!(num(&b, 0).0, b'G');
    assert_eq!(num(&b, 1).0, b'X');
}

#[test]
fn every_address_letter_is_a_word() {
    let letters = "ABCDEFGHIJKLMPQRSTUVWXYZ";
    let text: String = letters.chars().map(|c| format!("{c}1 ")).collect();
    let b = parse(&text);
    assert_eq!(b.words.len(), letters.len());
}

#[test]
fn comments_anywhere_and_semicolon() {
    let b = parse("G00 (RAPID) X1. (MORE) ;");
    assert_eq!(b.words.len(), 2);
    assert_eq!(b.comments.len(), 2);
    let b = parse("(ONLY A COMMENT)");
    assert!(b.words.is_empty());
    let e = fail("G00 (OPEN");
    assert_eq!(
        e,
        LexError {
            kind: LexErrorKind::UnterminatedComment,
            at: 4
        }
    );
}

#[test]
fn block_delete_levels() {
    let b = parse("/N10 G00 X1");
    assert_eq!(b.deletes, vec![(0, 1 << 1)]);
    let b = parse("/8/9N7 X3.0");
    assert_eq!(b.deletes, vec![(0, (1 << 8) | (1 << 9))]);
    assert_eq!(b.n, Some(7));
    let b = parse("/0 X1");
    assert_eq!(b.deletes, vec![(0, 1)]);
    let b = parse("G00 X1 /2 Y2");
    assert_eq!(b.deletes, vec![(2, 1 << 2)]);
    // 000 §2.3.3: "/0 ~ /10", a level 10.
    let b = parse("/10 N5 X1");
    assert_eq!(b.deletes, vec![(0, 1 << 10)]);
    assert_eq!(b.n, Some(5));
    let b = parse("/1N10 X1");
    assert_eq!(b.deletes, vec![(0, 1 << 1)]);
    assert_eq!(b.n, Some(10));
}

#[test]
fn macro_forms_in_words() {
    let b = parse("X#24 Z-#110 G#140 X[#1+#2] Y#[#100]");
    assert_eq!(b.words.len(), 5);
    for w in &b.words {
        assert!(matches!(w.val, Val::Expr(_)), "{w:?}");
    }
    // Z-#110 is Neg(Var(110))
    let Val::Expr(e) = b.words[1].val else {
        unreachable!()
    };
    let Expr::Neg(v) = b.exprs[e as usize] else {
        panic!()
    };
    let Expr::Var(i) = b.exprs[v as usize] else {
        panic!()
    };
    assert_eq!(b.exprs[i as usize], Expr::Num(110.0));
    // Y#[#100] is Var(Var(100))
    let Val::Expr(e) = b.words[4].val else {
        unreachable!()
    };
    let Expr::Var(i) = b.exprs[e as usize] else {
        panic!()
    };
    assert!(matches!(b.exprs[i as usize], Expr::Var(_)));
}

#[test]
fn assignment_and_precedence() {
    let b = parse("#1=#2+#3*2");
    let Some(Stmt::Assign { var, value }) = b.stmt else {
        panic!()
    };
    assert_eq!(b.exprs[var as usize], Expr::Num(1.0));
    let Expr::Bin(BinOp::Add, _, r) = b.exprs[value as usize] else {
        panic!("{:?}", b.exprs)
    };
    assert!(matches!(b.exprs[r as usize], Expr::Bin(BinOp::Mul, _, _)));
    let b = parse("N5 #[#1+1] = SIN[30.] + ATAN[1]/[2] OR 3 AND 1");
    assert_eq!(b.n, Some(5));
    let Some(Stmt::Assign { value, .. }) = b.stmt else {
        panic!()
    };
    // OR is additive level, AND multiplicative: (SIN + ATAN) OR (3 AND 1)
    let Expr::Bin(BinOp::Or, l, r) = b.exprs[value as usize] else {
        panic!("{:?}", b.exprs)
    };
    assert!(matches!(b.exprs[l as usize], Expr::Bin(BinOp::Add, _, _)));
    assert!(matches!(b.exprs[r as usize], Expr::Bin(BinOp::And, _, _)));
}

#[test]
fn control_statements() {
    assert!(matches!(
        parse("IF [#1 EQ 0] GOTO 10").stmt,
        Some(Stmt::IfGoto { .. })
    ));
    assert!(matches!(
        parse("IF[#1GT#2]THEN#3=1").stmt,
        Some(Stmt::IfThen { .. })
    ));
    assert!(matches!(
        parse("WHILE [#1 LT 10] DO1").stmt,
        Some(Stmt::While { label: 1, .. })
    ));
    assert!(matches!(
        parse("WHILE [#1 LT 10] DO 210").stmt,
        Some(Stmt::While { label: 210, .. })
    ));
    assert_eq!(parse("END1").stmt, Some(Stmt::End { label: 1 }));
    assert_eq!(parse("END 210").stmt, Some(Stmt::End { label: 210 }));
    assert!(matches!(parse("GOTO 99").stmt, Some(Stmt::Goto(_))));
    assert!(matches!(parse("GOTO#5").stmt, Some(Stmt::Goto(_))));
    assert_eq!(fail("IF #1 GOTO 5").kind, LexErrorKind::BadStatement);
    assert_eq!(fail("WHILE [1] X1").kind, LexErrorKind::BadStatement);
    assert_eq!(fail("GOTO 5 X1").kind, LexErrorKind::TrailingText);
}

#[test]
fn hx_comma_chamfer_and_corner() {
    let b = parse("G01 X10. ,C2. Y5. ,R1.5");
    assert_eq!(b.words[2].addr, Addr::Comma(b'C'));
    assert_eq!(b.words[4].addr, Addr::Comma(b'R'));
}

#[test]
fn hurco_long_names() {
    const NAMES: &[&str] = &["angIn", "ZEnd", "minD", "XEnd"];
    let o = LexOptions {
        long_names: NAMES,
        loop_comments: true,
        ..LexOptions::default()
    };
    let b = parse_with("G78 angIn30 ZEnd3.1 minD.01 X1.", &o);
    assert_eq!(b.words[1].addr, Addr::Long(0));
    assert_eq!(b.words[2].addr, Addr::Long(1));
    assert_eq!(b.words[3].addr, Addr::Long(2));
    assert_eq!(b.words[4].addr, Addr::L(b'X'));
    let Val::Num(n) = b.words[2].val else {
        panic!()
    };
    assert_eq!(n.value, 3.1);
}

#[test]
fn hurco_loop_commands() {
    let o = LexOptions {
        loop_comments: true,
        ..LexOptions::default()
    };
    assert_eq!(
        parse_with("(LOOP 3)", &o).loop_cmd,
        Some(LoopCmd::Start { count: 3 })
    );
    assert_eq!(
        parse_with("(repeat 12 times)", &o).loop_cmd,
        Some(LoopCmd::Start { count: 12 })
    );
    assert_eq!(parse_with("(END LOOP)", &o).loop_cmd, Some(LoopCmd::End));
    assert_eq!(parse_with("(A COMMENT)", &o).loop_cmd, None);
    assert_eq!(parse("(LOOP 3)").loop_cmd, None);
}

#[test]
fn errors_carry_the_column() {
    assert_eq!(
        fail("G00 X"),
        LexError {
            kind: LexErrorKind::MissingValue,
            at: 4
        }
    );
    assert_eq!(
        fail("G00 @"),
        LexError {
            kind: LexErrorKind::UnexpectedChar(b'@'),
            at: 4
        }
    );
    assert_eq!(
        fail("X[#1+2"),
        LexError {
            kind: LexErrorKind::UnbalancedBracket,
            at: 1
        }
    );
    assert_eq!(fail("X1234567890123").kind, LexErrorKind::TooManyDigits);
    assert_eq!(fail("X[[[[[[1]]]]]]").kind, LexErrorKind::NestingTooDeep);
    assert_eq!(fail("XY1").kind, LexErrorKind::MissingValue);
    assert_eq!(fail("X#").kind, LexErrorKind::BadExpression);
    assert_eq!(fail("#1 5").kind, LexErrorKind::BadStatement);
}

#[test]
fn deep_unary_chains_are_bounded() {
    let s = format!("#1={}1", "-".repeat(200));
    assert_eq!(fail(&s).kind, LexErrorKind::NestingTooDeep);
}

/// A leading zero is not a digit of the number (issue 15: `X0.42928932`
/// was refused where `X.42928932` was read): with the PUMA's 8 digits both
/// are 8 digits, `X1.42928932` is 9.
#[test]
fn leading_zeros_do_not_count_as_digits() {
    let o = LexOptions {
        max_digits: 8,
        ..LexOptions::default()
    };
    let b = parse_with("X0.42928932", &o);
    assert_eq!(num(&b, 0), (b'X', 0.42928932, true));
    let b = parse_with("X.42928932", &o);
    assert_eq!(num(&b, 0), (b'X', 0.42928932, true));
    let b = parse_with("Z-00012345678", &o);
    assert_eq!(num(&b, 0), (b'Z', -12345678.0, false));
    let mut b = Block::default();
    let e = parse_block(b"X1.42928932", &o, &mut b).unwrap_err();
    assert_eq!(e.kind, LexErrorKind::TooManyDigits);
    // Zeros after the point are digits of the number.
    let e = parse_block(b"X0.004292893", &o, &mut b).unwrap_err();
    assert_eq!(e.kind, LexErrorKind::TooManyDigits);
    assert_eq!(num(&parse_with("X0", &o), 0), (b'X', 0.0, false));
}

/// A comment inside `[ ]` is skipped like a space; the brackets balance.
#[test]
fn comment_inside_brackets() {
    let b = parse("#1 = [1 + (ONE) 2]");
    assert!(matches!(b.stmt, Some(Stmt::Assign { .. })));
    let b = parse("G01 X[#1 (HALF) / 2] F100.");
    assert_eq!(b.words.len(), 3);
    assert!(matches!(
        parse("IF [#1 (COUNT) GT 2] GOTO 5").stmt,
        Some(Stmt::IfGoto { .. })
    ));
    assert!(parse("X[(A)(B) 1]").words.len() == 1);
    // Unclosed: still an error, not a comment to the end of the block.
    assert!(parse_block(b"X[1 (OOPS]", &LexOptions::default(), &mut Block::default()).is_err());
}

/// Numbers read digit run by digit run agree with Rust's own decimal
/// reading of the same text without its blanks (exact up to 15 digits:
/// the mantissa and the power of ten are exact and the one division is
/// correctly rounded), over leading zeros, zeros after the point, blanks
/// between digits and every split of the digits around the point; the
/// digit count and the limit follow the rule above (leading zeros of the
/// integer part do not count).
#[test]
fn numbers_agree_with_a_decimal_reader() {
    let o = LexOptions {
        max_digits: 8,
        ..LexOptions::default()
    };
    let mut b = Block::default();
    let mut checked = 0;
    for digits in [
        "0",
        "7",
        "00",
        "05",
        "120",
        "0007",
        "1234567",
        "00012345678",
        "123456789",
    ] {
        for point in 0..=digits.len() + 1 {
            for blank in [None, Some(1)] {
                let mut text = String::new();
                for (i, c) in digits.chars().enumerate() {
                    if point == i {
                        text.push('.');
                    }
                    if blank == Some(i) {
                        text.push(' ');
                    }
                    text.push(c);
                }
                if point == digits.len() {
                    text.push('.');
                }
                let plain: String = text.chars().filter(|c| *c != ' ').collect();
                let int = plain.split('.').next().unwrap();
                let frac = plain.split('.').nth(1).unwrap_or("");
                let counted = int.trim_start_matches('0').len() + frac.len();
                let r = parse_block(format!("X{text}").as_bytes(), &o, &mut b);
                if counted > 8 {
                    assert_eq!(r.unwrap_err().kind, LexErrorKind::TooManyDigits, "{text}");
                } else {
                    r.unwrap_or_else(|e| panic!("{text}: {e:?}"));
                    let Val::Num(n) = b.words[0].val else {
                        panic!("{text}")
                    };
                    let want: f64 = plain.parse().unwrap();
                    assert_eq!(n.value, want, "{text}");
                    assert_eq!(n.point, plain.contains('.'), "{text}");
                    assert_eq!(n.digits as usize, digits.len(), "{text}");
                }
                checked += 1;
            }
        }
    }
    assert!(checked > 100);
}
