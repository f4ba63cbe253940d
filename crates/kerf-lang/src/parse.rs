//! The block parser: text of one logical block → [`Block`].
//!
//! Works on bytes, one pass, no allocation beyond the reused vectors of the
//! output block. Spaces and tabs are ignored everywhere outside comments
//! (`G0 1` is `G01`, `X 10.` is `X10.`), as on the controls.

use crate::block::*;

/// What the parser accepts; set by the interpreter from the dialect.
#[derive(Clone, Copy, Debug)]
pub struct LexOptions {
    /// Multi-letter parameter names (Hurco G78 `angIn`, `ZEnd`, `minD` …),
    /// matched case-insensitively; empty when the dialect has none.
    pub long_names: &'static [&'static str],
    /// Recognise Hurco loop (repeat) commands inside comments.
    pub loop_comments: bool,
    /// Maximum digits in one number.
    pub max_digits: u8,
    /// Maximum bracket nesting depth in expressions.
    pub max_nesting: u8,
}

impl Default for LexOptions {
    fn default() -> LexOptions {
        LexOptions {
            long_names: &[],
            loop_comments: false,
            max_digits: 12,
            max_nesting: 5,
        }
    }
}

/// Why a block could not be parsed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LexErrorKind {
    /// A character that is not part of the language (e.g. `@`).
    UnexpectedChar(u8),
    /// An address with no value after it.
    MissingValue,
    /// `(` without `)`.
    UnterminatedComment,
    /// `[` without `]`, or `]` without `[`.
    UnbalancedBracket,
    /// Brackets nested deeper than the control allows.
    NestingTooDeep,
    /// A number with more digits than the control reads.
    TooManyDigits,
    /// A sequence or program number that is not a plain integer.
    BadNumber,
    /// Malformed macro expression.
    BadExpression,
    /// Malformed macro statement (IF/WHILE/GOTO/END, assignment).
    BadStatement,
    /// Text after a complete macro statement.
    TrailingText,
    /// A second N or program number in the block.
    DuplicateNumber,
}

impl LexErrorKind {
    /// Human-readable message.
    pub fn message(&self) -> String {
        match self {
            LexErrorKind::UnexpectedChar(c) => {
                if c.is_ascii_graphic() {
                    format!("unexpected character '{}'", *c as char)
                } else {
                    format!("unexpected byte 0x{c:02x}")
                }
            }
            LexErrorKind::MissingValue => "address without a value".into(),
            LexErrorKind::UnterminatedComment => "comment not closed: '(' without ')'".into(),
            LexErrorKind::UnbalancedBracket => "unbalanced '[' ']'".into(),
            LexErrorKind::NestingTooDeep => "brackets nested too deeply".into(),
            LexErrorKind::TooManyDigits => "number has too many digits".into(),
            LexErrorKind::BadNumber => "sequence or program number must be a plain integer".into(),
            LexErrorKind::BadExpression => "malformed expression".into(),
            LexErrorKind::BadStatement => "malformed macro statement".into(),
            LexErrorKind::TrailingText => "unexpected text after the statement".into(),
            LexErrorKind::DuplicateNumber => {
                "more than one sequence/program number in the block".into()
            }
        }
    }
}

/// A parse error at a byte index of the block text.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LexError {
    pub kind: LexErrorKind,
    /// Byte index in the block text.
    pub at: u32,
}

type R<T> = Result<T, LexError>;

struct P<'a> {
    t: &'a [u8],
    i: usize,
    o: LexOptions,
    depth: u8,
}

fn err<T>(kind: LexErrorKind, at: usize) -> R<T> {
    Err(LexError {
        kind,
        at: at as u32,
    })
}

/// Parses one block of text into `out` (which is cleared first).
pub fn parse_block(text: &[u8], opts: &LexOptions, out: &mut Block) -> Result<(), LexError> {
    out.clear();
    let mut p = P::new(text, opts);
    p.block::<true>(out)
}

/// [`parse_block`] without its fast path for a plain word (an address
/// letter and an unsigned or negative number written without blanks):
/// every word goes through the general value reader. Gives the same
/// block as [`parse_block`] for every text; kept so that tests can show
/// it. (Both read a number by [`plain_number`] where it can; the unit
/// test below shows it reads what the digit-by-digit reader reads.)
#[doc(hidden)]
pub fn parse_block_general(
    text: &[u8],
    opts: &LexOptions,
    out: &mut Block,
) -> Result<(), LexError> {
    out.clear();
    let mut p = P::new(text, opts);
    p.block::<false>(out)
}

/// Longest keyword or function name (`WHILE`, `ROUND`, ...).
const KW_MAX: usize = 8;

/// A keyword read by `P::keyword`, upper-cased, on the stack.
struct Kw {
    buf: [u8; KW_MAX],
    len: usize,
}

impl Kw {
    fn bytes(&self) -> &[u8] {
        &self.buf[..self.len]
    }
}

/// A blank between words or after a number, as the parser skips it.
#[inline]
pub fn is_blank(c: u8) -> bool {
    c == b' ' || c == b'\t' || c == b'\r' || c == 0x0c
}

impl<'a> P<'a> {
    /// A parser at the start of `t`.
    #[inline]
    fn new(t: &'a [u8], opts: &LexOptions) -> P<'a> {
        P {
            t,
            i: 0,
            o: *opts,
            depth: 0,
        }
    }

    #[inline]
    fn skip(&mut self) {
        while self.i < self.t.len() && is_blank(self.t[self.i]) {
            self.i += 1;
        }
        if self.depth > 0 && self.t.get(self.i) == Some(&b'(') {
            self.skip_inner_comment();
        }
    }

    /// A comment inside `[ ]` is skipped like a space (the brackets around
    /// it still balance); an unclosed one is left for the bracket check.
    fn skip_inner_comment(&mut self) {
        while self.t.get(self.i) == Some(&b'(') {
            match memchr::memchr(b')', &self.t[self.i + 1..]) {
                Some(k) => self.i += k + 2,
                None => return,
            }
            while self.i < self.t.len() && is_blank(self.t[self.i]) {
                self.i += 1;
            }
        }
    }

    #[inline]
    fn peek(&mut self) -> Option<u8> {
        self.skip();
        self.t.get(self.i).copied()
    }

    /// The block's words; `FAST`: plain words by [`P::plain_value`].
    fn block<const FAST: bool>(&mut self, b: &mut Block) -> R<()> {
        if self.peek() == Some(b'%') {
            // Tape start/end mark; whatever follows on the line is ignored.
            b.percent = true;
            return Ok(());
        }
        loop {
            let Some(c) = self.peek() else { return Ok(()) };
            let start = self.i;
            match c {
                b'(' => self.comment(b)?,
                b';' => {
                    // End of block; the rest of the line is a remark.
                    return Ok(());
                }
                b'/' => {
                    self.i += 1;
                    let level = match self.peek() {
                        Some(d @ b'0'..=b'9') => {
                            self.i += 1;
                            // 000 §2.3.3: levels "/0 ~ /10" on the HX.
                            if d == b'1' && self.peek() == Some(b'0') {
                                self.i += 1;
                                10
                            } else {
                                (d - b'0') as u16
                            }
                        }
                        _ => 1,
                    };
                    let idx = b.words.len() as u16;
                    match b.deletes.last_mut() {
                        Some((at, mask)) if *at == idx => *mask |= 1 << level,
                        _ => b.deletes.push((idx, 1 << level)),
                    }
                }
                b':' if b.words.is_empty() && b.stmt.is_none() => {
                    self.i += 1;
                    self.program_number(b, start)?;
                }
                b'#' if b.words.is_empty() && b.stmt.is_none() => {
                    b.stmt_at = start as u32;
                    let var = self.var_target(b)?;
                    if self.peek() != Some(b'=') {
                        return err(LexErrorKind::BadStatement, self.i);
                    }
                    self.i += 1;
                    let value = self.expr(b)?;
                    b.stmt = Some(Stmt::Assign { var, value });
                    self.after_stmt(b)?;
                    return Ok(());
                }
                b',' => {
                    self.i += 1;
                    match self.peek() {
                        Some(l) if l.is_ascii_alphabetic() => {
                            self.i += 1;
                            let val = self.value(b, start)?;
                            b.words.push(Word {
                                addr: Addr::Comma(l.to_ascii_uppercase()),
                                val,
                                at: start as u32,
                            });
                        }
                        _ => return err(LexErrorKind::UnexpectedChar(b','), start),
                    }
                }
                c if c.is_ascii_alphabetic() => {
                    // Fast path: one address letter followed by a plain number.
                    let next = self.t.get(self.i + 1).copied().unwrap_or(b' ');
                    let l = c.to_ascii_uppercase();
                    if (next.is_ascii_digit() || next == b'-' || next == b'.')
                        && !matches!(l, b'N' | b'O')
                    {
                        self.i += 1;
                        let val = match self.plain_value::<FAST>() {
                            Some(v) => v,
                            None => self.value(b, start)?,
                        };
                        b.words.push(Word {
                            addr: Addr::L(l),
                            val,
                            at: start as u32,
                        });
                    } else {
                        self.letters(b, start)?
                    }
                }
                c => return err(LexErrorKind::UnexpectedChar(c), start),
            }
        }
    }

    fn comment(&mut self, b: &mut Block) -> R<()> {
        let open = self.i;
        let close = match memchr::memchr(b')', &self.t[open + 1..]) {
            Some(k) => open + 1 + k,
            None => return err(LexErrorKind::UnterminatedComment, open),
        };
        b.comments.push(((open + 1) as u32, close as u32));
        if self.o.loop_comments {
            if let Some(l) = loop_command(&self.t[open + 1..close]) {
                b.loop_cmd = Some(l);
            }
        }
        self.i = close + 1;
        Ok(())
    }

    fn program_number(&mut self, b: &mut Block, start: usize) -> R<()> {
        if b.program.is_some() {
            return err(LexErrorKind::DuplicateNumber, start);
        }
        b.program = Some(self.integer(start, 8)?);
        Ok(())
    }

    /// A plain unsigned integer (spaces allowed between digits).
    fn integer(&mut self, start: usize, max: usize) -> R<u32> {
        let mut v: u64 = 0;
        let mut n = 0;
        while let Some(c) = self.peek() {
            if c.is_ascii_digit() {
                v = v * 10 + (c - b'0') as u64;
                n += 1;
                self.i += 1;
                if n > max {
                    return err(LexErrorKind::TooManyDigits, start);
                }
            } else {
                break;
            }
        }
        if n == 0 {
            return err(LexErrorKind::MissingValue, start);
        }
        if matches!(self.peek(), Some(b'.')) {
            return err(LexErrorKind::BadNumber, self.i);
        }
        Ok(v as u32)
    }

    /// A run of letters: a keyword, a long name, or a one-letter address.
    fn letters(&mut self, b: &mut Block, start: usize) -> R<()> {
        let mut j = self.i;
        while j < self.t.len() && self.t[j].is_ascii_alphabetic() {
            j += 1;
        }
        let run = &self.t[self.i..j];
        if run.len() >= 2 {
            if b.words.is_empty() && b.stmt.is_none() {
                let mut up = [0u8; 8];
                if run.len() <= 8 {
                    for (k, c) in run.iter().enumerate() {
                        up[k] = c.to_ascii_uppercase();
                    }
                    let kw = &up[..run.len()];
                    let is_kw = matches!(kw, b"IF" | b"WHILE" | b"GOTO" | b"END" | b"DO");
                    if is_kw {
                        self.i = j;
                        b.stmt_at = start as u32;
                        self.statement(b, kw, start)?;
                        return self.after_stmt(b);
                    }
                }
            }
            if !self.o.long_names.is_empty() {
                if let Some((k, len)) = self.long_name(run) {
                    self.i += len;
                    let val = self.value(b, start)?;
                    b.words.push(Word {
                        addr: Addr::Long(k as u16),
                        val,
                        at: start as u32,
                    });
                    return Ok(());
                }
            }
        }
        let l = self.t[self.i].to_ascii_uppercase();
        self.i += 1;
        match l {
            b'N' => {
                if b.n.is_some() {
                    return err(LexErrorKind::DuplicateNumber, start);
                }
                b.n = Some(self.integer(start, 9)?);
            }
            b'O' if b.words.is_empty() && b.stmt.is_none() => self.program_number(b, start)?,
            _ => {
                let val = self.value(b, start)?;
                b.words.push(Word {
                    addr: Addr::L(l),
                    val,
                    at: start as u32,
                });
            }
        }
        Ok(())
    }

    /// The longest long name that is a (case-insensitive) prefix of `run`.
    fn long_name(&self, run: &[u8]) -> Option<(usize, usize)> {
        let mut best: Option<(usize, usize)> = None;
        for (k, name) in self.o.long_names.iter().enumerate() {
            let n = name.as_bytes();
            if n.len() >= 2
                && n.len() <= run.len()
                && run[..n.len()].eq_ignore_ascii_case(n)
                && best.is_none_or(|(_, l)| n.len() > l)
            {
                best = Some((k, n.len()));
            }
        }
        best
    }

    fn statement(&mut self, b: &mut Block, kw: &[u8], start: usize) -> R<()> {
        match kw {
            b"GOTO" => {
                let t = self.operand(b)?;
                b.stmt = Some(Stmt::Goto(t));
            }
            b"IF" => {
                if self.peek() != Some(b'[') {
                    return err(LexErrorKind::BadStatement, self.i);
                }
                let cond = self.primary(b)?;
                let at = self.i;
                match self.keyword().as_ref().map(Kw::bytes) {
                    Some(b"GOTO") => {
                        let target = self.operand(b)?;
                        b.stmt = Some(Stmt::IfGoto { cond, target });
                    }
                    Some(b"THEN") => {
                        if self.peek() != Some(b'#') {
                            return err(LexErrorKind::BadStatement, self.i);
                        }
                        let var = self.var_target(b)?;
                        if self.peek() != Some(b'=') {
                            return err(LexErrorKind::BadStatement, self.i);
                        }
                        self.i += 1;
                        let value = self.expr(b)?;
                        b.stmt = Some(Stmt::IfThen { cond, var, value });
                    }
                    _ => return err(LexErrorKind::BadStatement, at),
                }
            }
            b"WHILE" => {
                if self.peek() != Some(b'[') {
                    return err(LexErrorKind::BadStatement, self.i);
                }
                let cond = self.primary(b)?;
                let at = self.i;
                if self.keyword().as_ref().map(Kw::bytes) != Some(b"DO") {
                    return err(LexErrorKind::BadStatement, at);
                }
                let label = self.integer(at, 9)?;
                b.stmt = Some(Stmt::While { cond, label });
            }
            b"DO" => {
                let label = self.integer(start, 9)?;
                b.stmt = Some(Stmt::Do { label });
            }
            b"END" => {
                let label = self.integer(start, 9)?;
                b.stmt = Some(Stmt::End { label });
            }
            _ => return err(LexErrorKind::BadStatement, start),
        }
        Ok(())
    }

    /// Reads an upper-cased alphabetic keyword at the cursor (no
    /// allocation: keywords are short; a longer run of letters reads as
    /// one that matches nothing).
    fn keyword(&mut self) -> Option<Kw> {
        self.skip();
        let s = self.i;
        while self.i < self.t.len() && self.t[self.i].is_ascii_alphabetic() {
            self.i += 1;
        }
        if self.i == s {
            return None;
        }
        let mut kw = Kw {
            buf: [b'?'; KW_MAX],
            len: KW_MAX,
        };
        if self.i - s <= KW_MAX {
            kw.len = self.i - s;
            for (d, c) in kw.buf.iter_mut().zip(&self.t[s..self.i]) {
                *d = c.to_ascii_uppercase();
            }
        }
        Some(kw)
    }

    /// True when the letters at the cursor are exactly `kw` (any case).
    #[inline]
    fn word_is(&self, kw: &[u8]) -> bool {
        let t = &self.t[self.i..];
        t.len() >= kw.len()
            && t[..kw.len()].eq_ignore_ascii_case(kw)
            && !t.get(kw.len()).is_some_and(|c| c.is_ascii_alphabetic())
    }

    fn after_stmt(&mut self, b: &mut Block) -> R<()> {
        loop {
            match self.peek() {
                None | Some(b';') => return Ok(()),
                Some(b'(') => self.comment(b)?,
                Some(_) => return err(LexErrorKind::TrailingText, self.i),
            }
        }
    }

    fn push(&self, b: &mut Block, e: Expr) -> ExprId {
        b.exprs.push(e);
        (b.exprs.len() - 1) as ExprId
    }

    /// `#n` or `#[expr]` as an assignment target: returns the index expression.
    fn var_target(&mut self, b: &mut Block) -> R<ExprId> {
        let at = self.i;
        let v = self.primary(b)?;
        match b.exprs[v as usize] {
            Expr::Var(idx) => Ok(idx),
            _ => err(LexErrorKind::BadStatement, at),
        }
    }

    /// A GOTO target: a number, a variable or a bracketed expression.
    fn operand(&mut self, b: &mut Block) -> R<ExprId> {
        match self.peek() {
            Some(b'#' | b'[' | b'0'..=b'9' | b'.') => self.unary(b),
            _ => err(LexErrorKind::BadStatement, self.i),
        }
    }

    /// A word's value when it is a number [`plain_number`] reads, right
    /// at the cursor or after a `-`: what [`P::value`] gives there, read
    /// without its general steps. None (cursor unmoved) for anything
    /// else, and always when `FAST` is false.
    #[inline(always)]
    fn plain_value<const FAST: bool>(&mut self) -> Option<Val> {
        if !FAST {
            return None;
        }
        let t = self.t;
        let neg = t.get(self.i) == Some(&b'-');
        let s = self.i + neg as usize;
        if !t.get(s).is_some_and(u8::is_ascii_digit) {
            return None;
        }
        let (mut num, end) = plain_number(t, s, self.o.max_digits as usize)?;
        if neg {
            num.value = -num.value;
        }
        self.i = end;
        Some(Val::Num(num))
    }

    /// The value of a word.
    fn value(&mut self, b: &mut Block, addr_at: usize) -> R<Val> {
        // Fast path: digits right after the address.
        if let Some(c) = self.t.get(self.i) {
            if c.is_ascii_digit() {
                return Ok(Val::Num(self.number(addr_at)?));
            }
        }
        let save = self.i;
        let mut neg = false;
        match self.peek() {
            Some(b'-') => {
                neg = true;
                self.i += 1;
            }
            Some(b'+') => self.i += 1,
            _ => {}
        }
        match self.peek() {
            Some(b'#' | b'[') => {
                let e = self.primary(b)?;
                let e = if neg { self.push(b, Expr::Neg(e)) } else { e };
                Ok(Val::Expr(e))
            }
            Some(b'0'..=b'9' | b'.') => {
                let mut n = self.number(addr_at)?;
                if neg {
                    n.value = -n.value;
                }
                Ok(Val::Num(n))
            }
            _ => {
                self.i = save;
                err(LexErrorKind::MissingValue, addr_at)
            }
        }
    }

    /// Unsigned decimal number; spaces between digits are ignored.
    ///
    /// The common form is read by [`plain_number`]; anything else is read
    /// again by [`P::number_slow`], which gives the same value for the
    /// common form.
    #[inline]
    fn number(&mut self, at: usize) -> R<Num> {
        match plain_number(self.t, self.i, self.o.max_digits as usize) {
            Some((num, end)) => {
                self.i = end;
                Ok(num)
            }
            None => self.number_slow(at),
        }
    }

    /// [`P::number`] digit by digit: blanks between the digits, and the
    /// errors.
    #[cold]
    #[inline(never)]
    fn number_slow(&mut self, at: usize) -> R<Num> {
        let t = self.t;
        let mut i = self.i;
        let mut mant: u64 = 0;
        let mut digits: u32 = 0;
        // Digits that count against the limit: leading zeros of the
        // integer part do not (`X0.42928932` has the 8 digits of
        // `X.42928932`).
        let mut counted: u32 = 0;
        let mut frac: i32 = 0;
        let mut point = false;
        let max = (self.o.max_digits as u32).min(18);
        while i < t.len() {
            let c = t[i];
            if c.is_ascii_digit() {
                digits += 1;
                if c != b'0' || mant != 0 || point {
                    counted += 1;
                }
                if counted > max {
                    return err(LexErrorKind::TooManyDigits, at);
                }
                mant = mant * 10 + (c - b'0') as u64;
                frac += point as i32;
            } else if c == b'.' && !point {
                point = true;
            } else if !is_blank(c) {
                break;
            }
            i += 1;
        }
        self.i = i;
        if digits == 0 {
            return err(LexErrorKind::MissingValue, at);
        }
        let value = if frac == 0 {
            mant as f64
        } else {
            mant as f64 / POW10[frac as usize]
        };
        Ok(Num {
            value,
            point,
            digits: digits.min(255) as u8,
        })
    }

    // ---- expressions ---------------------------------------------------

    fn expr(&mut self, b: &mut Block) -> R<ExprId> {
        let l = self.additive(b)?;
        let save = self.i;
        let op = match self.keyword().as_ref().map(Kw::bytes) {
            Some(b"EQ") => BinOp::Eq,
            Some(b"NE") => BinOp::Ne,
            Some(b"GT") => BinOp::Gt,
            Some(b"LT") => BinOp::Lt,
            Some(b"GE") => BinOp::Ge,
            Some(b"LE") => BinOp::Le,
            _ => {
                self.i = save;
                return Ok(l);
            }
        };
        let r = self.additive(b)?;
        Ok(self.push(b, Expr::Bin(op, l, r)))
    }

    fn additive(&mut self, b: &mut Block) -> R<ExprId> {
        let mut l = self.multiplicative(b)?;
        loop {
            let save = self.i;
            let op = match self.peek() {
                Some(b'+') => {
                    self.i += 1;
                    BinOp::Add
                }
                Some(b'-') => {
                    self.i += 1;
                    BinOp::Sub
                }
                Some(c) if c.is_ascii_alphabetic() => {
                    if self.word_is(b"OR") {
                        self.i += 2;
                        BinOp::Or
                    } else if self.word_is(b"XOR") {
                        self.i += 3;
                        BinOp::Xor
                    } else {
                        self.i = save;
                        return Ok(l);
                    }
                }
                _ => return Ok(l),
            };
            let r = self.multiplicative(b)?;
            l = self.push(b, Expr::Bin(op, l, r));
        }
    }

    fn multiplicative(&mut self, b: &mut Block) -> R<ExprId> {
        let mut l = self.unary(b)?;
        loop {
            let save = self.i;
            let op = match self.peek() {
                Some(b'*') => {
                    self.i += 1;
                    BinOp::Mul
                }
                Some(b'/') => {
                    self.i += 1;
                    BinOp::Div
                }
                Some(c) if c.is_ascii_alphabetic() => {
                    if self.word_is(b"AND") {
                        self.i += 3;
                        BinOp::And
                    } else if self.word_is(b"MOD") {
                        self.i += 3;
                        BinOp::Mod
                    } else {
                        self.i = save;
                        return Ok(l);
                    }
                }
                _ => return Ok(l),
            };
            let r = self.unary(b)?;
            l = self.push(b, Expr::Bin(op, l, r));
        }
    }

    fn unary(&mut self, b: &mut Block) -> R<ExprId> {
        match self.peek() {
            Some(b'-') => {
                self.i += 1;
                self.enter()?;
                let e = self.unary(b)?;
                self.depth -= 1;
                Ok(self.push(b, Expr::Neg(e)))
            }
            Some(b'+') => {
                self.i += 1;
                self.enter()?;
                let e = self.unary(b);
                self.depth -= 1;
                e
            }
            _ => self.primary(b),
        }
    }

    fn enter(&mut self) -> R<()> {
        self.depth += 1;
        if self.depth > self.o.max_nesting.saturating_mul(4).max(8) {
            return err(LexErrorKind::NestingTooDeep, self.i);
        }
        Ok(())
    }

    fn bracketed(&mut self, b: &mut Block) -> R<ExprId> {
        // cursor on '['
        let open = self.i;
        self.i += 1;
        self.depth += 1;
        if self.depth > self.o.max_nesting {
            return err(LexErrorKind::NestingTooDeep, open);
        }
        let e = self.expr(b)?;
        if self.peek() != Some(b']') {
            return err(LexErrorKind::UnbalancedBracket, open);
        }
        self.i += 1;
        self.depth -= 1;
        Ok(e)
    }

    fn primary(&mut self, b: &mut Block) -> R<ExprId> {
        let at = self.i;
        match self.peek() {
            Some(b'[') => self.bracketed(b),
            Some(b'#') => {
                self.i += 1;
                let idx = match self.peek() {
                    Some(b'[') => self.bracketed(b)?,
                    Some(b'0'..=b'9') => {
                        let n = self.number(at)?;
                        if n.point {
                            return err(LexErrorKind::BadExpression, at);
                        }
                        self.push(b, Expr::Num(n.value))
                    }
                    _ => return err(LexErrorKind::BadExpression, at),
                };
                Ok(self.push(b, Expr::Var(idx)))
            }
            Some(b'0'..=b'9' | b'.') => {
                let n = self.number(at)?;
                Ok(self.push(b, Expr::Num(n.value)))
            }
            Some(c) if c.is_ascii_alphabetic() => {
                let kw = self.keyword();
                let name: &[u8] = kw.as_ref().map_or(&[], Kw::bytes);
                let Some(f) = Func::from_name(name) else {
                    return err(LexErrorKind::BadExpression, at);
                };
                if self.peek() != Some(b'[') {
                    return err(LexErrorKind::BadExpression, self.i);
                }
                let open = self.i;
                self.i += 1;
                self.depth += 1;
                if self.depth > self.o.max_nesting {
                    return err(LexErrorKind::NestingTooDeep, open);
                }
                let a = self.expr(b)?;
                let mut second = None;
                if self.peek() == Some(b',') {
                    self.i += 1;
                    second = Some(self.expr(b)?);
                }
                if self.peek() != Some(b']') {
                    return err(LexErrorKind::UnbalancedBracket, open);
                }
                self.i += 1;
                self.depth -= 1;
                if f == Func::Atan && second.is_none() {
                    // ATAN[a]/[b] form.
                    let save = self.i;
                    if self.peek() == Some(b'/') {
                        self.i += 1;
                        if self.peek() == Some(b'[') {
                            second = Some(self.bracketed(b)?);
                        } else {
                            self.i = save;
                        }
                    }
                }
                if second.is_some() && !matches!(f, Func::Atan | Func::Pow) {
                    return err(LexErrorKind::BadExpression, at);
                }
                if f == Func::Pow && second.is_none() {
                    return err(LexErrorKind::BadExpression, at);
                }
                Ok(self.push(b, Expr::Call(f, a, second)))
            }
            Some(b']') => err(LexErrorKind::UnbalancedBracket, at),
            _ => err(LexErrorKind::BadExpression, at),
        }
    }
}

/// A number as [`plain_digits`] reads it: the integer of its digits and
/// how many of them stand after the point, its value not yet worked out.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PlainDigits {
    /// The digits as one integer (`12.50` is 1250).
    pub mant: u64,
    /// Digits after the point.
    pub frac: usize,
    /// Whether a decimal point was written.
    pub point: bool,
    /// Digits written in all.
    pub count: usize,
    /// Index after the number and the blanks that follow it.
    pub end: usize,
}

impl PlainDigits {
    /// The value the parser gives: `mant / 10^frac`, one division by an
    /// exact power of ten.
    #[inline(always)]
    pub fn value(&self) -> f64 {
        // At most 18 digits (as plain_digits gives them): below 2^63,
        // where the signed conversion (one instruction) rounds as the
        // unsigned one.
        debug_assert!(self.mant < 1 << 63);
        let m = self.mant as i64 as f64;
        if self.frac == 0 {
            m
        } else {
            m / POW10[self.frac]
        }
    }
}

/// [`plain_digits`] with the number's value: the number and the index
/// after it and after the blanks that follow it.
#[inline(always)]
pub fn plain_number(t: &[u8], s: usize, max: usize) -> Option<(Num, usize)> {
    let d = plain_digits(t, s, max)?;
    let num = Num {
        value: d.value(),
        point: d.point,
        digits: d.count as u8,
    };
    Some((num, d.end))
}

/// The parser's fast path for an unsigned number at `s` in `t`: digits,
/// a point, digits, with no blank between them and at most `max` digits
/// (at most 18). Gives the digits read and the index after the number and
/// after the blanks that follow it; `None` where the parser reads digit
/// by digit instead (no digit, past `max` digits, digits or a first point
/// after blanks), which is also where a reader mirroring the parser must
/// hand the block to it. Inlined into both (the parser's hot path);
/// [`plain_number`] is this with the value worked out.
#[inline(always)]
pub fn plain_digits(t: &[u8], s: usize, max: usize) -> Option<PlainDigits> {
    let mut i = s;
    let mut mant: u64 = 0;
    // Wrapping: a run long enough to overflow is past the digit limit and
    // refused below.
    while let Some(d) = t.get(i).map(|c| c.wrapping_sub(b'0')).filter(|d| *d < 10) {
        mant = mant.wrapping_mul(10).wrapping_add(d as u64);
        i += 1;
    }
    let int_end = i;
    let point = t.get(i) == Some(&b'.');
    if point {
        i += 1;
        while let Some(d) = t.get(i).map(|c| c.wrapping_sub(b'0')).filter(|d| *d < 10) {
            mant = mant.wrapping_mul(10).wrapping_add(d as u64);
            i += 1;
        }
    }
    let frac = i - int_end - point as usize;
    let digits = int_end - s + frac;
    // Blanks after the number are read with it (as the slow path does);
    // digits or a first point after them continue it.
    let mut j = i;
    while j < t.len() && is_blank(t[j]) {
        j += 1;
    }
    let more = t
        .get(j)
        .is_some_and(|c| c.is_ascii_digit() || (*c == b'.' && !point));
    if digits == 0 || digits > max.min(18) || more {
        // Leading zeros may bring a long run under the limit; blanks
        // between digits, errors: digit by digit.
        return None;
    }
    Some(PlainDigits {
        mant,
        frac,
        point,
        count: digits,
        end: j,
    })
}

const POW10: [f64; 19] = [
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16,
    1e17, 1e18,
];

/// Recognises a Hurco loop command in comment text: `LOOP n` / `REPEAT n`
/// (optionally followed by `TIMES`) starts a section, `END LOOP`, `ENDLOOP`,
/// `END REPEAT`, `LOOP END` or `END` ends it. Case and spacing are free.
pub fn loop_command(text: &[u8]) -> Option<LoopCmd> {
    let s: Vec<u8> = text
        .iter()
        .filter(|c| !is_blank(**c))
        .map(|c| c.to_ascii_uppercase())
        .collect();
    let s = s.as_slice();
    if matches!(
        s,
        b"ENDLOOP" | b"ENDREPEAT" | b"LOOPEND" | b"REPEATEND" | b"END"
    ) {
        return Some(LoopCmd::End);
    }
    for kw in [&b"LOOP"[..], b"REPEAT"] {
        if let Some(rest) = s.strip_prefix(kw) {
            let rest = rest.strip_prefix(b"=").unwrap_or(rest);
            let rest = rest.strip_suffix(b"TIMES").unwrap_or(rest);
            if !rest.is_empty() && rest.len() <= 9 && rest.iter().all(|c| c.is_ascii_digit()) {
                let count = std::str::from_utf8(rest).ok()?.parse().ok()?;
                return Some(LoopCmd::Start { count });
            }
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// What the digit-by-digit reader gives at the start of `t`.
    fn slow(t: &[u8], max: u8) -> R<(Num, usize)> {
        let o = LexOptions {
            max_digits: max,
            ..LexOptions::default()
        };
        let mut p = P::new(t, &o);
        let n = p.number_slow(0)?;
        Ok((n, p.i))
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(5000))]

        /// Where `plain_number` reads a number, the digit-by-digit reader
        /// reads the same one (value to the bit, point, digits, end).
        #[test]
        fn plain_number_reads_what_the_digit_reader_reads(
            t in "[0-9]{0,16}[.]?[0-9]{0,12}[ \t]{0,2}[0-9.XY;]{0,2}",
            max in 1u8..=18,
        ) {
            if let Some((n, end)) = plain_number(t.as_bytes(), 0, max as usize) {
                let (m, slow_end) = slow(t.as_bytes(), max).expect("the digit reader reads it too");
                prop_assert_eq!(n.value.to_bits(), m.value.to_bits(), "{:?}", t);
                prop_assert_eq!((n.point, n.digits, end), (m.point, m.digits, slow_end), "{:?}", t);
            }
        }
    }
}
