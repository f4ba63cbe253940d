//! Macro variables and expression evaluation with Fanuc vacant (`#0`)
//! semantics. This is the core the custom-macro issue builds on: local
//! `#1-#33`, common `#100-#199` and `#500-#999` are kept; system variables
//! are not yet modelled and alarm when used.

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
}

impl Default for Vars {
    fn default() -> Vars {
        Vars::new()
    }
}

impl Vars {
    /// All variables vacant.
    pub fn new() -> Vars {
        Vars {
            v: vec![None; 1000],
        }
    }

    fn index(n: f64) -> Result<usize, MacroError> {
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
        if i == 0 || (1..=33).contains(&i) || (100..=199).contains(&i) || (500..=999).contains(&i) {
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

    /// Reads `#n`.
    pub fn get(&self, n: f64) -> Result<Option<f64>, MacroError> {
        let i = Self::index(n)?;
        Ok(self.v[i])
    }

    /// Writes `#n` (`None` makes it vacant).
    pub fn set(&mut self, n: f64, val: Option<f64>) -> Result<(), MacroError> {
        let i = Self::index(n)?;
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
    /// Takes the local variables #1-#33 (for a macro call), leaving them
    /// vacant.
    pub fn take_locals(&mut self) -> [Option<f64>; 33] {
        let mut out = [None; 33];
        for (i, o) in out.iter_mut().enumerate() {
            *o = self.v[i + 1].take();
        }
        out
    }

    /// Replaces the local variables #1-#33 (macro call or return).
    pub fn put_locals(&mut self, l: &[Option<f64>; 33]) {
        self.v[1..34].copy_from_slice(l);
    }
}

/// Evaluates an expression. Vacant propagates as in Fanuc custom macro B:
/// in arithmetic a vacant operand counts as 0 (a lone vacant stays vacant),
/// in EQ/NE vacant differs from 0, in the other comparisons it counts as 0.
pub fn eval(ex: &[Expr], e: ExprId, vars: &Vars) -> Result<Option<f64>, MacroError> {
    let z = |x: Option<f64>| x.unwrap_or(0.0);
    Ok(match ex[e as usize] {
        Expr::Num(v) => Some(v),
        Expr::Var(i) => {
            let n = eval(ex, i, vars)?;
            let Some(n) = n else {
                return fail(AlarmKind::BadVariable, "variable number is vacant");
            };
            vars.get(n)?
        }
        Expr::Neg(a) => eval(ex, a, vars)?.map(|v| -v),
        Expr::Bin(op, a, b) => {
            let x = eval(ex, a, vars)?;
            let y = eval(ex, b, vars)?;
            let bool_ = |c: bool| Some(if c { 1.0 } else { 0.0 });
            match op {
                BinOp::Eq => {
                    return Ok(bool_(
                        x == y || (x.is_some() && y.is_some() && (z(x) - z(y)).abs() < 1e-9),
                    ))
                }
                BinOp::Ne => {
                    return Ok(bool_(
                        !(x == y || (x.is_some() && y.is_some() && (z(x) - z(y)).abs() < 1e-9)),
                    ))
                }
                BinOp::Gt => return Ok(bool_(z(x) > z(y))),
                BinOp::Lt => return Ok(bool_(z(x) < z(y))),
                BinOp::Ge => return Ok(bool_(z(x) >= z(y))),
                BinOp::Le => return Ok(bool_(z(x) <= z(y))),
                _ => {}
            }
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
                _ => unreachable!(),
            };
            Some(r)
        }
        Expr::Call(f, a, b) => {
            let x = z(eval(ex, a, vars)?);
            let y = match b {
                Some(b) => Some(z(eval(ex, b, vars)?)),
                None => None,
            };
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
                Func::Bin | Func::Bcd => {
                    return fail(
                        AlarmKind::NotYetSupported,
                        "BIN/BCD are not yet supported (issue 3)",
                    );
                }
            };
            if !r.is_finite() {
                return fail(AlarmKind::MathError, "result is not a finite number");
            }
            Some(r)
        }
    })
}
