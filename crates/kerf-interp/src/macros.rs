//! Macro variables and expression evaluation with Fanuc vacant (`#0`)
//! semantics. Local `#1-#33` (and on the HX `#34-#99`), common
//! `#100-#199`, retained `#200-#699` (HX) or `#500-#999` (Fanuc) live in
//! [`Vars`]; system variables (`#1000` and up) are read and written by the
//! interpreter (`interp/sysvars.rs`).

use kerf_lang::{BinOp, Expr, ExprId, Func};

use crate::alarms::AlarmKind;

/// An evaluation failure (turned into an alarm by the caller).
#[derive(Debug)]
pub struct MacroError {
    pub kind: AlarmKind,
    pub message: String,
}

fn fail<T>(kind: AlarmKind, message: impl Into<String>) -> Result<T, MacroError> {
    Err(MacroError {
        kind,
        message: message.into(),
    })
}

/// The variable store. `None` is vacant.
#[derive(Clone, Debug)]
pub struct Vars {
    v: Vec<Option<f64>>,
    /// `plain[i]`: #i is one of the store's own variables (a table, so the
    /// hot path of every variable read is one load).
    is_plain: Vec<bool>,
    /// HX numbering (000 §14.2.3): #34-#99 locals, #200-#699 retained;
    /// otherwise Fanuc: #500-#999 retained.
    hx: bool,
}

/// Where a variable number falls.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum VarClass {
    /// #1-#199 and the retained range, held in [`Vars`].
    Plain,
    /// #1000 and up (and HX numbers below 1000 outside its ranges that
    /// are system variables): handled by the interpreter.
    System,
}

impl Default for Vars {
    fn default() -> Vars {
        Vars::new()
    }
}

impl Vars {
    /// All variables vacant.
    pub fn new() -> Vars {
        Vars::with_numbering(false)
    }

    /// All variables vacant, with the HX (000) or Fanuc numbering.
    pub fn with_numbering(hx: bool) -> Vars {
        let is_plain = (0..1000).map(|i| Vars::plain_in(hx, i)).collect();
        Vars {
            v: vec![None; 1000],
            is_plain,
            hx,
        }
    }

    /// The retained variables (kept across runs): #200-#699 on the HX,
    /// #500-#999 on the Fanuc controls.
    pub fn retained_range(&self) -> std::ops::RangeInclusive<usize> {
        if self.hx {
            200..=699
        } else {
            500..=999
        }
    }

    /// The retained variables that hold a value.
    pub fn retained(&self) -> Vec<(usize, f64)> {
        self.retained_range()
            .filter_map(|i| self.v[i].map(|v| (i, v)))
            .collect()
    }

    /// Sets a retained variable (ignored outside the retained range or for
    /// a value that is not finite).
    pub fn set_retained(&mut self, i: usize, v: f64) -> bool {
        if self.retained_range().contains(&i) && v.is_finite() {
            self.v[i] = Some(v);
            true
        } else {
            false
        }
    }

    /// True when `#i` is one of the store's own variables in the HX (`hx`)
    /// or Fanuc numbering.
    fn plain_in(hx: bool, i: usize) -> bool {
        i <= 33
            || (100..=199).contains(&i)
            || if hx {
                (34..=99).contains(&i) || (200..=699).contains(&i)
            } else {
                (500..=999).contains(&i)
            }
    }

    /// True when `#i` is one of the store's own variables.
    #[inline]
    fn plain(&self, i: usize) -> bool {
        self.is_plain.get(i).copied().unwrap_or(false)
    }

    /// Classifies a variable number (already checked to be a whole
    /// non-negative number).
    #[inline]
    pub fn class(&self, i: usize) -> VarClass {
        if self.plain(i) {
            VarClass::Plain
        } else {
            VarClass::System
        }
    }

    /// The plain variable `#n` if `n` is exactly its whole number: the
    /// common case of every read and write, with no further checks. None
    /// when `n` is not such a number (the caller takes the full path).
    #[inline]
    pub fn plain_index(&self, n: f64) -> Option<usize> {
        let k = n as usize;
        (k as f64 == n && self.plain(k)).then_some(k)
    }

    /// Checks that `n` is a whole, non-negative variable number.
    pub fn number(n: f64) -> Result<usize, MacroError> {
        if !n.is_finite() || n < 0.0 {
            return fail(
                AlarmKind::BadVariable,
                format!("#{n} is not a variable number"),
            );
        }
        let i = n.round();
        if (i - n).abs() > 1e-6 || i > 1e9 {
            return fail(
                AlarmKind::BadVariable,
                format!("#{n} is not a variable number"),
            );
        }
        Ok(i as usize)
    }

    fn index(&self, n: f64) -> Result<usize, MacroError> {
        if !n.is_finite() || n < 0.0 {
            return fail(
                AlarmKind::BadVariable,
                format!("#{n} is not a variable number"),
            );
        }
        let i = n.round();
        if (i - n).abs() > 1e-6 {
            return fail(
                AlarmKind::BadVariable,
                format!("#{n} is not a variable number"),
            );
        }
        let i = i as usize;
        if self.plain(i) {
            Ok(i)
        } else if i < 1000 {
            fail(
                AlarmKind::BadVariable,
                format!("#{i} is not a variable of this control"),
            )
        } else {
            fail(
                AlarmKind::NotYetSupported,
                format!("system variable #{i} is not yet supported (issue 3)"),
            )
        }
    }

    /// Reads plain variable `#i` (`class(i)` is `Plain`).
    #[inline]
    pub fn raw(&self, i: usize) -> Option<f64> {
        self.v[i]
    }

    /// Writes plain variable `#i` (`class(i)` is `Plain`, `i` > 0, the
    /// value finite or vacant).
    #[inline]
    pub fn set_raw(&mut self, i: usize, v: Option<f64>) {
        self.v[i] = v;
    }

    /// Reads `#n`.
    pub fn get(&self, n: f64) -> Result<Option<f64>, MacroError> {
        let i = self.index(n)?;
        Ok(self.v[i])
    }

    /// Writes `#n` (`None` makes it vacant).
    pub fn set(&mut self, n: f64, val: Option<f64>) -> Result<(), MacroError> {
        let i = self.index(n)?;
        if i == 0 {
            return fail(AlarmKind::BadVariable, "#0 is read-only (always vacant)");
        }
        if let Some(x) = val {
            if !x.is_finite() {
                return fail(AlarmKind::MathError, "value is not a finite number");
            }
        }
        self.v[i] = val;
        Ok(())
    }
}

impl Vars {
    /// Takes the local variables #1-#99 (for a macro call), leaving them
    /// vacant (#34-#99 exist on the HX only and are otherwise vacant).
    pub fn take_locals(&mut self) -> [Option<f64>; 99] {
        let mut out = [None; 99];
        for (i, o) in out.iter_mut().enumerate() {
            *o = self.v[i + 1].take();
        }
        out
    }

    /// Makes the local variables #1-#99 vacant (reset).
    pub fn clear_locals(&mut self) {
        self.v[1..100].fill(None);
    }

    /// Makes the common variables #100-#199 vacant (reset).
    pub fn clear_commons(&mut self) {
        self.v[100..200].fill(None);
    }

    /// Replaces the local variables #1-#33 (a macro's arguments).
    pub fn put_args(&mut self, l: &[Option<f64>; 33]) {
        self.v[1..34].copy_from_slice(l);
    }

    /// Replaces the local variables #1-#99 (return from a macro).
    pub fn put_locals(&mut self, l: &[Option<f64>; 99]) {
        self.v[1..100].copy_from_slice(l);
    }
}

/// Where expressions read variables from.
pub trait Lookup {
    /// Reads `#n`.
    fn get(&self, n: f64) -> Result<Option<f64>, MacroError>;
}

impl Lookup for Vars {
    #[inline]
    fn get(&self, n: f64) -> Result<Option<f64>, MacroError> {
        Vars::get(self, n)
    }
}

/// Rounds `x` half away from zero to a multiple of `inc` (a tiny margin
/// absorbs binary representation error: 1.2345 rounds to 1.235).
pub fn round_to(x: f64, inc: f64) -> f64 {
    let q = x / inc;
    (q + q.signum() * 1e-7).round() * inc
}

/// BCD to binary: each 4-bit nibble of the integer is one decimal digit.
fn bin(x: f64) -> Result<f64, MacroError> {
    if x < 0.0 || x.fract() != 0.0 || x > u32::MAX as f64 {
        return fail(
            AlarmKind::MathError,
            "BIN argument must be a whole number 0-2^32",
        );
    }
    let (mut v, mut out, mut scale) = (x as u64, 0u64, 1u64);
    while v > 0 {
        let d = v & 15;
        if d > 9 {
            return fail(AlarmKind::MathError, "BIN argument is not a BCD number");
        }
        out += d * scale;
        scale *= 10;
        v >>= 4;
    }
    Ok(out as f64)
}

/// Binary to BCD: each decimal digit becomes one 4-bit nibble.
fn bcd(x: f64) -> Result<f64, MacroError> {
    if x < 0.0 || x.fract() != 0.0 || x > 99_999_999.0 {
        return fail(
            AlarmKind::MathError,
            "BCD argument must be a whole number 0-99999999",
        );
    }
    let (mut v, mut out, mut shift) = (x as u64, 0u64, 0u32);
    while v > 0 {
        out |= (v % 10) << shift;
        shift += 4;
        v /= 10;
    }
    Ok(out as f64)
}

/// Evaluates an expression. Vacant propagates as in Fanuc custom macro B:
/// in arithmetic a vacant operand counts as 0 (a lone vacant stays vacant),
/// in EQ/NE vacant differs from 0, in the other comparisons it counts as 0.
/// `inc` is the least input increment of the address the expression is
/// the value of (0 outside addresses): ROUND rounds to it (000 §14.2.4).
pub fn eval<V: Lookup>(
    ex: &[Expr],
    e: ExprId,
    vars: &V,
    inc: f64,
) -> Result<Option<f64>, MacroError> {
    match ex[e as usize] {
        Expr::Num(v) => Ok(Some(v)),
        Expr::Var(i) => var(ex, i, vars),
        Expr::Neg(a) => Ok(operand(ex, a, vars, inc)?.map(|v| -v)),
        Expr::Bin(op, a, b) => {
            let x = operand(ex, a, vars, inc)?;
            let y = operand(ex, b, vars, inc)?;
            binary(op, x, y)
        }
        Expr::Call(f, a, b) => {
            let x = operand(ex, a, vars, inc)?.unwrap_or(0.0);
            let y = match b {
                Some(b) => Some(operand(ex, b, vars, inc)?.unwrap_or(0.0)),
                None => None,
            };
            call(f, x, y, inc).map(Some)
        }
    }
}

/// An operand: constants and `#n` with a literal n directly, anything
/// else by recursion (saves a call for the leaves of every expression).
#[inline(always)]
fn operand<V: Lookup>(
    ex: &[Expr],
    e: ExprId,
    vars: &V,
    inc: f64,
) -> Result<Option<f64>, MacroError> {
    match ex[e as usize] {
        Expr::Num(v) => Ok(Some(v)),
        Expr::Var(i) => var(ex, i, vars),
        _ => eval(ex, e, vars, inc),
    }
}

/// `#n` where node `i` is n.
#[inline(always)]
fn var<V: Lookup>(ex: &[Expr], i: ExprId, vars: &V) -> Result<Option<f64>, MacroError> {
    let n = match ex[i as usize] {
        Expr::Num(v) => v,
        _ => match eval(ex, i, vars, 0.0)? {
            Some(n) => n,
            None => return fail(AlarmKind::BadVariable, "variable number is vacant"),
        },
    };
    vars.get(n)
}

/// A binary operator on two values (vacant rules in [`eval`]).
#[inline]
fn binary(op: BinOp, x: Option<f64>, y: Option<f64>) -> Result<Option<f64>, MacroError> {
    let z = |x: Option<f64>| x.unwrap_or(0.0);
    let bool_ = |c: bool| Ok(Some(if c { 1.0 } else { 0.0 }));
    let (p, q) = (z(x), z(y));
    let r = match op {
        BinOp::Add => p + q,
        BinOp::Sub => p - q,
        BinOp::Mul => p * q,
        BinOp::Div => {
            if q == 0.0 {
                return fail(AlarmKind::MathError, "division by zero");
            }
            p / q
        }
        BinOp::Mod => {
            if q == 0.0 {
                return fail(AlarmKind::MathError, "division by zero");
            }
            p % q
        }
        BinOp::Or => ((p as i64) | (q as i64)) as f64,
        BinOp::Xor => ((p as i64) ^ (q as i64)) as f64,
        BinOp::And => ((p as i64) & (q as i64)) as f64,
        BinOp::Eq => return bool_(x == y || (x.is_some() && y.is_some() && (p - q).abs() < 1e-9)),
        BinOp::Ne => {
            return bool_(!(x == y || (x.is_some() && y.is_some() && (p - q).abs() < 1e-9)))
        }
        BinOp::Gt => return bool_(p > q),
        BinOp::Lt => return bool_(p < q),
        BinOp::Ge => return bool_(p >= q),
        BinOp::Le => return bool_(p <= q),
    };
    Ok(Some(r))
}

/// A function of one argument `x` (or two: `y`); vacant arguments are 0.
fn call(f: Func, x: f64, y: Option<f64>, inc: f64) -> Result<f64, MacroError> {
    let deg = |r: f64| r.to_degrees();
    let r = match f {
        Func::Sin => x.to_radians().sin(),
        Func::Cos => x.to_radians().cos(),
        Func::Tan => x.to_radians().tan(),
        Func::Asin => {
            if !(-1.0..=1.0).contains(&x) {
                return fail(AlarmKind::MathError, "ASIN argument out of [-1, 1]");
            }
            deg(x.asin())
        }
        Func::Acos => {
            if !(-1.0..=1.0).contains(&x) {
                return fail(AlarmKind::MathError, "ACOS argument out of [-1, 1]");
            }
            deg(x.acos())
        }
        Func::Atan => {
            let a = match y {
                Some(y) => deg(x.atan2(y)),
                None => deg(x.atan()),
            };
            if a < 0.0 && y.is_some() {
                a + 360.0
            } else {
                a
            }
        }
        Func::Sqrt => {
            if x < 0.0 {
                return fail(AlarmKind::MathError, "SQRT of a negative number");
            }
            x.sqrt()
        }
        Func::Abs => x.abs(),
        Func::Round if inc > 0.0 => round_to(x, inc),
        Func::Round => x.round(),
        Func::Fix => x.trunc(),
        Func::Fup => {
            if x >= 0.0 {
                x.ceil()
            } else {
                x.floor()
            }
        }
        Func::Ln => {
            if x <= 0.0 {
                return fail(AlarmKind::MathError, "LN of a number <= 0");
            }
            x.ln()
        }
        Func::Exp => x.exp(),
        Func::Pow => x.powf(y.unwrap_or(1.0)),
        Func::Adp => x,
        Func::Bin => bin(x)?,
        Func::Bcd => bcd(x)?,
    };
    if !r.is_finite() {
        return fail(AlarmKind::MathError, "result is not a finite number");
    }
    Ok(r)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// 000 §14.2.3: the HX has locals #1-#99, commons #100-#199 and
    /// retained #200-#699; Fanuc locals #1-#33, commons #100-#199 and
    /// retained #500-#999. Other numbers below 1000 are not variables.
    #[test]
    fn the_hx_and_fanuc_numberings() {
        let hx = Vars::with_numbering(true);
        let fanuc = Vars::new();
        for (i, in_hx, in_fanuc) in [
            (1, true, true),
            (33, true, true),
            (34, true, false),
            (99, true, false),
            (150, true, true),
            (200, true, false),
            (699, true, true),
            (700, false, true),
            (500, true, true),
            (999, false, true),
            (1000, false, false),
        ] {
            assert_eq!(hx.class(i) == VarClass::Plain, in_hx, "HX #{i}");
            assert_eq!(fanuc.class(i) == VarClass::Plain, in_fanuc, "Fanuc #{i}");
        }
        assert_eq!(hx.retained_range(), 200..=699);
        assert_eq!(fanuc.retained_range(), 500..=999);
    }

    #[test]
    fn reads_writes_and_their_errors() {
        let mut v = Vars::new();
        assert_eq!(v.get(100.0).unwrap(), None);
        v.set(100.0, Some(2.5)).unwrap();
        assert_eq!(v.get(100.0).unwrap(), Some(2.5));
        assert_eq!(v.plain_index(100.0), Some(100));
        assert_eq!(v.plain_index(100.5), None);
        assert_eq!(
            v.set(0.0, Some(1.0)).unwrap_err().kind,
            AlarmKind::BadVariable
        );
        assert_eq!(
            v.set(1.0, Some(f64::NAN)).unwrap_err().kind,
            AlarmKind::MathError
        );
        assert_eq!(v.get(40.0).unwrap_err().kind, AlarmKind::BadVariable);
        assert_eq!(v.get(-1.0).unwrap_err().kind, AlarmKind::BadVariable);
        assert_eq!(v.get(1.5).unwrap_err().kind, AlarmKind::BadVariable);
        assert_eq!(Vars::number(12.0000001).unwrap(), 12);
    }

    #[test]
    fn retained_locals_and_reset() {
        let mut v = Vars::new();
        assert!(v.set_retained(500, 1.25) && !v.set_retained(100, 1.0));
        assert!(!v.set_retained(501, f64::INFINITY));
        assert_eq!(v.retained(), [(500, 1.25)]);
        v.set(1.0, Some(7.0)).unwrap();
        v.set(101.0, Some(8.0)).unwrap();
        // A macro call takes the locals and gives them back on return.
        let saved = v.take_locals();
        assert_eq!((saved[0], v.get(1.0).unwrap()), (Some(7.0), None));
        let mut args = [None; 33];
        args[0] = Some(3.0);
        v.put_args(&args);
        assert_eq!(v.get(1.0).unwrap(), Some(3.0));
        v.put_locals(&saved);
        assert_eq!(v.get(1.0).unwrap(), Some(7.0));
        v.clear_locals();
        v.clear_commons();
        assert_eq!((v.get(1.0).unwrap(), v.get(101.0).unwrap()), (None, None));
        assert_eq!(v.retained(), [(500, 1.25)]);
    }

    /// 000 §14.2.4: X#1 with #1 = 1.2345 moves 1.235 (half away from zero).
    #[test]
    fn round_to_the_increment() {
        assert_eq!(round_to(1.2345, 0.001), 1.235);
        assert_eq!(round_to(-1.2345, 0.001), -1.235);
        assert_eq!(round_to(0.00049, 0.001), 0.0);
    }
}
