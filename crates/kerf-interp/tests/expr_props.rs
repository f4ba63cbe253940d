//! Property tests of macro expressions: random expression trees are
//! rendered as macro text (brackets only where Fanuc precedence needs them,
//! plus some redundant ones), run through the real parser and interpreter
//! as `#100 = <expr>` on hx-mc, and compared with an independent evaluator
//! written here on f64 with `Option` for vacant:
//!
//! - precedence (fanuc-semantics §7.4): functions > `* / AND` > `+ - OR
//!   XOR` > comparisons; left to right within a level;
//! - trigonometry in degrees; ROUND half away from zero to an integer
//!   (outside an address); FIX toward zero; FUP away from zero;
//! - vacant (§7.2): a vacant operand counts as 0 in arithmetic, functions
//!   and GT/GE/LT/LE; EQ/NE tell vacant from 0; a lone vacant (`#100 = #6`)
//!   stays vacant, and so does its negation;
//! - AND/OR/XOR bitwise on whole numbers (the generator only gives them
//!   whole, non-negative operands);
//! - division by zero and SQRT of a negative number are the control's math
//!   alarm (F_82201 on the HX) at the statement's line, never a panic.

use kerf_interp::{Interp, Profile, Settings, Step};
use proptest::prelude::*;

#[derive(Clone, Copy, Debug, PartialEq)]
enum Op {
    Add,
    Sub,
    Mul,
    Div,
    And,
    Or,
    Xor,
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Cmp {
    Eq,
    Ne,
    Gt,
    Lt,
    Ge,
    Le,
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Fun {
    Sin,
    Cos,
    Abs,
    Sqrt,
    Round,
    Fix,
    Fup,
}

#[derive(Clone, Debug)]
enum E {
    /// A literal: thousandths, written with a decimal point when not whole.
    Num(i64),
    /// `#n`.
    Var(u32),
    /// `#[#7]` (#7 holds 3).
    Indirect,
    Neg(Box<E>),
    Bin(Op, Box<E>, Box<E>),
    /// A bitwise operator on two whole, non-negative operands.
    Bits(Op, Box<E>, Box<E>),
    Cmp(Cmp, Box<E>, Box<E>),
    Fun(Fun, Box<E>),
    /// Redundant brackets.
    Br(Box<E>),
}

/// The variables set before the expression (#6 and #0 stay vacant).
const VARS: [(u32, f64); 6] = [
    (1, 12.5),
    (2, -3.0),
    (3, 7.0),
    (4, 0.25),
    (5, 90.0),
    (7, 3.0),
];

fn var_value(n: u32) -> Option<f64> {
    VARS.iter().find(|v| v.0 == n).map(|v| v.1)
}

fn leaf() -> impl Strategy<Value = E> {
    prop_oneof![
        4 => (-20_000i64..20_000).prop_map(E::Num),
        2 => (0i64..50).prop_map(|n| E::Num(n * 1000)),
        1 => Just(E::Num(0)),
        4 => prop_oneof![Just(0u32), Just(1), Just(2), Just(3), Just(4), Just(5), Just(6)]
            .prop_map(E::Var),
        1 => Just(E::Indirect),
    ]
}

/// A whole, non-negative operand of AND/OR/XOR.
fn int_leaf() -> impl Strategy<Value = E> {
    prop_oneof![
        3 => (0i64..1024).prop_map(|n| E::Num(n * 1000)),
        1 => prop_oneof![Just(3u32), Just(6), Just(0)].prop_map(E::Var),
    ]
}

fn expr() -> impl Strategy<Value = E> {
    leaf().prop_recursive(4, 24, 2, |inner| {
        let b = |e: E| Box::new(e);
        prop_oneof![
            3 => (
                prop_oneof![Just(Op::Add), Just(Op::Sub), Just(Op::Mul), Just(Op::Div)],
                inner.clone(),
                inner.clone()
            )
                .prop_map(move |(o, l, r)| E::Bin(o, b(l), b(r))),
            1 => (
                prop_oneof![Just(Op::And), Just(Op::Or), Just(Op::Xor)],
                int_leaf(),
                int_leaf()
            )
                .prop_map(move |(o, l, r)| E::Bits(o, b(l), b(r))),
            1 => (
                prop_oneof![
                    Just(Cmp::Eq),
                    Just(Cmp::Ne),
                    Just(Cmp::Gt),
                    Just(Cmp::Lt),
                    Just(Cmp::Ge),
                    Just(Cmp::Le)
                ],
                inner.clone(),
                inner.clone()
            )
                .prop_map(move |(c, l, r)| E::Cmp(c, b(l), b(r))),
            2 => (
                prop_oneof![
                    Just(Fun::Sin),
                    Just(Fun::Cos),
                    Just(Fun::Abs),
                    Just(Fun::Sqrt),
                    Just(Fun::Round),
                    Just(Fun::Fix),
                    Just(Fun::Fup)
                ],
                inner.clone()
            )
                .prop_map(move |(f, a)| E::Fun(f, b(a))),
            1 => inner.clone().prop_map(move |a| E::Neg(b(a))),
            1 => inner.prop_map(move |a| E::Br(b(a))),
        ]
    })
}

// ---- rendering ------------------------------------------------------------

/// Binding strength: 3 primary/function/unary, 2 multiplicative,
/// 1 additive, 0 comparison.
fn level(e: &E) -> u8 {
    match e {
        E::Bin(Op::Mul | Op::Div, ..) | E::Bits(Op::And, ..) => 2,
        E::Bin(..) | E::Bits(..) => 1,
        E::Cmp(..) => 0,
        _ => 3,
    }
}

fn op_level(o: Op) -> u8 {
    match o {
        Op::Mul | Op::Div | Op::And => 2,
        _ => 1,
    }
}

fn num_text(t: i64) -> String {
    let v = t.unsigned_abs();
    let s = if v.is_multiple_of(1000) {
        format!("{}", v / 1000)
    } else {
        let f = format!("{:03}", v % 1000);
        format!("{}.{}", v / 1000, f.trim_end_matches('0'))
    };
    if t < 0 {
        format!("-{s}")
    } else {
        s
    }
}

fn wrap(e: &E, need: bool) -> String {
    // Comparisons and redundant brackets bring their own.
    if need && !matches!(e, E::Cmp(..) | E::Br(..)) {
        format!("[{}]", render(e))
    } else {
        render(e)
    }
}

fn render(e: &E) -> String {
    match e {
        // A negative literal is a unary minus: bracket it as an operand.
        E::Num(t) if *t < 0 => format!("[{}]", num_text(*t)),
        E::Num(t) => num_text(*t),
        E::Var(n) => format!("#{n}"),
        E::Indirect => "#[#7]".into(),
        E::Neg(a) => format!("-{}", wrap(a, level(a) < 3)),
        E::Bin(o, l, r) | E::Bits(o, l, r) => {
            let p = op_level(*o);
            let s = match o {
                Op::Add => "+",
                Op::Sub => "-",
                Op::Mul => "*",
                Op::Div => "/",
                Op::And => " AND ",
                Op::Or => " OR ",
                Op::Xor => " XOR ",
            };
            // Left to right: the left operand may be of the same level.
            format!("{}{s}{}", wrap(l, level(l) < p), wrap(r, level(r) <= p))
        }
        E::Cmp(c, l, r) => {
            let s = match c {
                Cmp::Eq => "EQ",
                Cmp::Ne => "NE",
                Cmp::Gt => "GT",
                Cmp::Lt => "LT",
                Cmp::Ge => "GE",
                Cmp::Le => "LE",
            };
            // A comparison is only ever a whole bracket's content.
            format!("[{} {s} {}]", render(l), render(r))
        }
        E::Fun(f, a) => {
            let n = match f {
                Fun::Sin => "SIN",
                Fun::Cos => "COS",
                Fun::Abs => "ABS",
                Fun::Sqrt => "SQRT",
                Fun::Round => "ROUND",
                Fun::Fix => "FIX",
                Fun::Fup => "FUP",
            };
            format!("{n}[{}]", render(a))
        }
        E::Br(a) => format!("[{}]", render(a)),
    }
}

// ---- the independent evaluator ---------------------------------------------

#[derive(Debug, PartialEq)]
enum Out {
    Value(Option<f64>),
    MathAlarm,
}

fn ev(e: &E) -> Result<Option<f64>, ()> {
    let z = |x: Option<f64>| x.unwrap_or(0.0);
    Ok(match e {
        E::Num(t) => Some(*t as f64 / 1000.0),
        E::Var(n) => var_value(*n),
        E::Indirect => var_value(3),
        E::Neg(a) => ev(a)?.map(|v| -v),
        E::Br(a) => ev(a)?,
        E::Bin(o, l, r) | E::Bits(o, l, r) => {
            let (x, y) = (z(ev(l)?), z(ev(r)?));
            Some(match o {
                Op::Add => x + y,
                Op::Sub => x - y,
                Op::Mul => x * y,
                Op::Div => {
                    if y == 0.0 {
                        return Err(());
                    }
                    x / y
                }
                Op::And => ((x as u64) & (y as u64)) as f64,
                Op::Or => ((x as u64) | (y as u64)) as f64,
                Op::Xor => ((x as u64) ^ (y as u64)) as f64,
            })
        }
        E::Cmp(c, l, r) => {
            let (a, b) = (ev(l)?, ev(r)?);
            // EQ/NE: vacant equals only vacant; numbers within 1e-9 are
            // equal (kerf's tolerance for rounding noise).
            let eq = match (a, b) {
                (None, None) => true,
                (Some(p), Some(q)) => (p - q).abs() < 1e-9,
                _ => false,
            };
            let (p, q) = (z(a), z(b));
            let t = match c {
                Cmp::Eq => eq,
                Cmp::Ne => !eq,
                Cmp::Gt => p > q,
                Cmp::Lt => p < q,
                Cmp::Ge => p >= q,
                Cmp::Le => p <= q,
            };
            Some(if t { 1.0 } else { 0.0 })
        }
        E::Fun(f, a) => {
            let x = z(ev(a)?);
            Some(match f {
                Fun::Sin => (x * std::f64::consts::PI / 180.0).sin(),
                Fun::Cos => (x * std::f64::consts::PI / 180.0).cos(),
                Fun::Abs => x.abs(),
                Fun::Sqrt => {
                    if x < 0.0 {
                        return Err(());
                    }
                    x.sqrt()
                }
                Fun::Round => {
                    // Half away from zero.
                    let r = (x.abs() + 0.5).floor();
                    if x < 0.0 {
                        -r
                    } else {
                        r
                    }
                }
                Fun::Fix => x.trunc(),
                Fun::Fup => {
                    if x < 0.0 {
                        -(-x).ceil()
                    } else {
                        x.ceil()
                    }
                }
            })
        }
    })
}

/// Whether the tree has SIN or COS (whose last bit may differ between two
/// correct ways of converting degrees).
fn has_trig(e: &E) -> bool {
    match e {
        E::Num(_) | E::Var(_) | E::Indirect => false,
        E::Neg(a) | E::Br(a) => has_trig(a),
        E::Fun(f, a) => matches!(f, Fun::Sin | Fun::Cos) || has_trig(a),
        E::Bin(_, l, r) | E::Bits(_, l, r) | E::Cmp(_, l, r) => has_trig(l) || has_trig(r),
    }
}

/// A trigonometric value next to a rounding, comparison or domain edge
/// can fall either way with a 1-ulp difference: such trees are skipped
/// (rare). Without SIN/COS both evaluators do the same IEEE operations in
/// the same order, so nothing is skipped.
fn knife_edge(e: &E) -> bool {
    let near_int = |x: f64| (x - x.round()).abs() < 1e-9;
    let near_half = |x: f64| (x.abs().fract() - 0.5).abs() < 1e-9;
    let val = |e: &E| ev(e).ok().map(|v| v.unwrap_or(0.0));
    match e {
        E::Num(_) | E::Var(_) | E::Indirect => false,
        E::Neg(a) | E::Br(a) => knife_edge(a),
        E::Bin(o, l, r) | E::Bits(o, l, r) => {
            knife_edge(l)
                || knife_edge(r)
                || (*o == Op::Div && has_trig(r) && val(r).is_some_and(|y| y.abs() < 1e-9))
        }
        E::Cmp(_, l, r) => {
            if knife_edge(l) || knife_edge(r) {
                return true;
            }
            if !(has_trig(l) || has_trig(r)) {
                return false;
            }
            match (val(l), val(r)) {
                (Some(a), Some(b)) => (a - b).abs() < 1e-6,
                _ => false,
            }
        }
        E::Fun(f, a) => {
            if knife_edge(a) {
                return true;
            }
            if !has_trig(a) {
                return false;
            }
            let Some(x) = val(a) else { return false };
            match f {
                Fun::Round => near_half(x),
                Fun::Fix | Fun::Fup => near_int(x),
                Fun::Sqrt => x.abs() < 1e-9,
                _ => false,
            }
        }
    }
}

fn expected(e: &E) -> Out {
    match ev(e) {
        Ok(v) => Out::Value(v),
        Err(()) => Out::MathAlarm,
    }
}

// ---- running it ----------------------------------------------------------------

fn run(profile: &Profile, text: &str) -> (Out, Option<kerf_canon::Alarm>) {
    let mut it = Interp::new(profile.clone(), Settings::default());
    it.load_main(
        "p.nc",
        Box::new(std::io::Cursor::new(text.as_bytes().to_vec())),
    );
    loop {
        match it.step() {
            Step::Event(_) => {}
            Step::End => return (Out::Value(it.macro_var(100)), None),
            Step::Alarm(a) => return (Out::MathAlarm, Some(a)),
        }
    }
}

fn close(a: &Out, b: &Out) -> bool {
    match (a, b) {
        (Out::Value(Some(x)), Out::Value(Some(y))) => {
            (x - y).abs() <= 1e-9 * (1.0 + x.abs().max(y.abs()))
        }
        _ => a == b,
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 768, ..ProptestConfig::default() })]

    #[test]
    fn expressions_match_an_independent_evaluator(e in expr()) {
        prop_assume!(!knife_edge(&e));
        let profile = Profile::builtin("hx-mc").unwrap();
        let mut text = String::new();
        for (n, v) in VARS {
            text.push_str(&format!("#{n}={v:?}\n"));
        }
        let src = render(&e);
        text.push_str(&format!("#100={src}\nM30\n"));
        let want = expected(&e);
        let (got, alarm) = run(&profile, &text);
        if let Some(a) = &alarm {
            // Only the math alarm, at the #100 line (7th), positioned.
            prop_assert_eq!(a.code.as_str(), "F_82201", "{} -> {}", src, a);
            prop_assert_eq!(a.src.line, 7);
            prop_assert!(a.src.col >= 1);
        }
        prop_assert!(close(&got, &want), "#100={}: kerf {:?}, expected {:?}", src, got, want);
    }
}

#[test]
fn renderer_relies_on_precedence() {
    // The renderer leaves out brackets that precedence makes redundant, so
    // the properties above test the parser's precedence. Hand-checked:
    let e = E::Bin(
        Op::Sub,
        Box::new(E::Var(1)),
        Box::new(E::Bin(
            Op::Add,
            Box::new(E::Num(2000)),
            Box::new(E::Bin(
                Op::Mul,
                Box::new(E::Num(3000)),
                Box::new(E::Num(4000)),
            )),
        )),
    );
    assert_eq!(render(&e), "#1-[2+3*4]");
    // 12.5 - (2 + 12) = -1.5
    assert_eq!(ev(&e), Ok(Some(-1.5)));
    let e = E::Bits(Op::Or, Box::new(E::Num(5000)), Box::new(E::Num(2000)));
    let m = E::Bin(Op::Mul, Box::new(E::Num(3000)), Box::new(e));
    assert_eq!(render(&m), "3*[5 OR 2]");
    // 3 * (5 | 2) = 21
    assert_eq!(ev(&m), Ok(Some(21.0)));
}

#[test]
fn division_by_zero_is_the_math_alarm() {
    let profile = Profile::builtin("hx-mc").unwrap();
    for text in [
        "#100=1/0\nM30\n",
        "#100=#1/#0\nM30\n",
        "#100=1/[#1-#1]\nM30\n",
    ] {
        let (out, alarm) = run(&profile, text);
        assert_eq!(out, Out::MathAlarm, "{text}");
        let a = alarm.unwrap();
        assert_eq!((a.code.as_str(), a.src.line), ("F_82201", 1), "{text}");
    }
}
