//! The parsed form of one block. A [`Block`] is reused from block to block
//! (its vectors are cleared, not freed) so parsing allocates nothing once
//! the buffers have grown to the program's largest block.

/// Index of an expression node in [`Block::exprs`].
pub type ExprId = u32;

/// An address: a single letter, HX's `,C` / `,R`, or a Hurco multi-letter
/// parameter name.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Addr {
    /// `A`..`Z` (always upper case).
    L(u8),
    /// `,C`, `,R` … (upper-case letter after the comma).
    Comma(u8),
    /// A multi-letter parameter name, as an index into the name table given
    /// in [`crate::LexOptions::long_names`].
    Long(u16),
}

/// A literal number as written.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Num {
    /// Value as written (decimal point honoured, sign applied).
    pub value: f64,
    /// Whether a decimal point was written.
    pub point: bool,
    /// Count of digits written (for range checks).
    pub digits: u8,
}

/// The value of a word.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Val {
    /// A literal number.
    Num(Num),
    /// A macro expression (`#24`, `-#110`, `[#1+#2]`).
    Expr(ExprId),
}

/// One word: address and value, with the byte index in the block text.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Word {
    pub addr: Addr,
    pub val: Val,
    /// Byte index of the address letter in the block text.
    pub at: u32,
}

/// Binary operators of custom macro B.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BinOp {
    Add,
    Sub,
    Mul,
    Div,
    Or,
    Xor,
    And,
    Mod,
    Eq,
    Ne,
    Gt,
    Lt,
    Ge,
    Le,
}

/// Macro functions.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Func {
    Sin,
    Cos,
    Tan,
    Asin,
    Acos,
    Atan,
    Sqrt,
    Abs,
    Round,
    Fix,
    Fup,
    Ln,
    Exp,
    Pow,
    Adp,
    Bin,
    Bcd,
}

impl Func {
    pub(crate) fn from_name(n: &[u8]) -> Option<Func> {
        Some(match n {
            b"SIN" => Func::Sin,
            b"COS" => Func::Cos,
            b"TAN" => Func::Tan,
            b"ASIN" => Func::Asin,
            b"ACOS" => Func::Acos,
            b"ATAN" | b"ATN" => Func::Atan,
            b"SQRT" | b"SQR" => Func::Sqrt,
            b"ABS" => Func::Abs,
            b"ROUND" | b"RND" => Func::Round,
            b"FIX" => Func::Fix,
            b"FUP" => Func::Fup,
            b"LN" => Func::Ln,
            b"EXP" => Func::Exp,
            b"POW" => Func::Pow,
            b"ADP" => Func::Adp,
            b"BIN" => Func::Bin,
            b"BCD" => Func::Bcd,
            _ => return None,
        })
    }
}

/// An expression node.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Expr {
    /// A constant.
    Num(f64),
    /// `#n` with a literal number, or `#[expr]` (the node is the index).
    Var(ExprId),
    /// Unary minus.
    Neg(ExprId),
    /// Binary operation.
    Bin(BinOp, ExprId, ExprId),
    /// Function of one argument, or two (`ATAN[a]/[b]`, `ATAN[a,b]`, `POW[a,b]`).
    Call(Func, ExprId, Option<ExprId>),
}

/// A macro statement (a block that is not a list of words).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Stmt {
    /// `#i = expr`: target index expression and value.
    Assign { var: ExprId, value: ExprId },
    /// `GOTO n` (n is an expression).
    Goto(ExprId),
    /// `IF [cond] GOTO n`.
    IfGoto { cond: ExprId, target: ExprId },
    /// `IF [cond] THEN #i = expr`.
    IfThen {
        cond: ExprId,
        var: ExprId,
        value: ExprId,
    },
    /// `WHILE [cond] DO m`.
    While { cond: ExprId, label: u32 },
    /// `DO m` without WHILE (an endless loop).
    Do { label: u32 },
    /// `END m`.
    End { label: u32 },
}

/// A Hurco loop (repeat) command found in a comment.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LoopCmd {
    /// Start of a repeated section: repeat `count` times in all.
    Start { count: u32 },
    /// End of the innermost repeated section.
    End,
}

/// One parsed block.
#[derive(Debug, Default)]
pub struct Block {
    /// `%` tape mark line.
    pub percent: bool,
    /// Program number (`O1234`, `:1234`).
    pub program: Option<u32>,
    /// Sequence number.
    pub n: Option<u32>,
    /// Block delete markers: (index into `words` from which the rest of the
    /// block is skipped, bit mask of levels 0-9 that skip it). A marker at
    /// index 0 before any word skips the whole block, statement included.
    pub deletes: Vec<(u16, u16)>,
    /// Words in the order written.
    pub words: Vec<Word>,
    /// Macro statement, if the block is one.
    pub stmt: Option<Stmt>,
    /// Byte index of the statement keyword.
    pub stmt_at: u32,
    /// Expression arena for `words` and `stmt`.
    pub exprs: Vec<Expr>,
    /// Comment spans (byte ranges of the text inside the parentheses).
    pub comments: Vec<(u32, u32)>,
    /// Hurco loop command.
    pub loop_cmd: Option<LoopCmd>,
}

impl Block {
    /// Makes `self` a copy of `other`, reusing `self`'s buffers (no
    /// allocation once they have grown to `other`'s sizes).
    pub fn copy_from(&mut self, other: &Block) {
        self.percent = other.percent;
        self.program = other.program;
        self.n = other.n;
        self.deletes.clone_from(&other.deletes);
        self.words.clone_from(&other.words);
        self.stmt = other.stmt;
        self.stmt_at = other.stmt_at;
        self.exprs.clone_from(&other.exprs);
        self.comments.clone_from(&other.comments);
        self.loop_cmd = other.loop_cmd;
    }

    /// Bytes of heap the block's vectors hold (for bounding caches).
    pub fn heap_bytes(&self) -> usize {
        use std::mem::size_of;
        self.deletes.capacity() * size_of::<(u16, u16)>()
            + self.words.capacity() * size_of::<Word>()
            + self.exprs.capacity() * size_of::<Expr>()
            + self.comments.capacity() * size_of::<(u32, u32)>()
    }

    /// Empties the block for reuse.
    pub fn clear(&mut self) {
        self.percent = false;
        self.program = None;
        self.n = None;
        self.deletes.clear();
        self.words.clear();
        self.stmt = None;
        self.stmt_at = 0;
        self.exprs.clear();
        self.comments.clear();
        self.loop_cmd = None;
    }

    /// True when nothing executable is in the block.
    pub fn is_empty(&self) -> bool {
        self.words.is_empty()
            && self.stmt.is_none()
            && self.loop_cmd.is_none()
            && self.program.is_none()
            && !self.percent
    }
}
