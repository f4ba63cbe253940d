//! Macro statements and program flow: assignments, IF, GOTO, WHILE/DO/END
//! with the loop rules of 000 §14.2.5, and the Hurco repeat commands.

use super::*;

impl Interp {
    // ---- macro statements ----------------------------------------------------------

    #[inline]
    pub(super) fn eval(&mut self, e: kerf_lang::ExprId, at: u32) -> R<Option<f64>> {
        // A constant (the variable number of most assignments) needs no
        // evaluation.
        if let Some(&kerf_lang::Expr::Num(v)) = self.prog.block.exprs.get(e as usize) {
            return Ok(Some(v));
        }
        self.eval_in(e, at, 0.0)
    }

    /// Evaluates the value of an address whose least input increment is
    /// `inc` (ROUND rounds to it).
    pub(super) fn eval_in(&mut self, e: kerf_lang::ExprId, at: u32, inc: f64) -> R<Option<f64>> {
        let r = crate::macros::eval(&self.prog.block.exprs, e, &sysvars::Env(self), inc);
        r.map_err(|m| self.alarm(m.kind, at, m.message))
    }

    pub(super) fn statement(&mut self, stmt: Stmt) -> R<bool> {
        let at = self.prog.block.stmt_at;
        match stmt {
            Stmt::Assign { var, value } => {
                let idx = self.eval(var, at)?;
                let v = self.eval(value, at)?;
                self.assign(idx, v, at)?;
            }
            Stmt::IfThen { cond, var, value } => {
                if self.cond(cond, at)? {
                    let idx = self.eval(var, at)?;
                    let v = self.eval(value, at)?;
                    self.assign(idx, v, at)?;
                }
            }
            Stmt::Goto(t) => {
                let n = self.eval(t, at)?;
                self.goto(n, at)?;
            }
            Stmt::IfGoto { cond, target } => {
                if self.cond(cond, at)? {
                    let n = self.eval(target, at)?;
                    self.goto(n, at)?;
                }
            }
            Stmt::While { cond, label } => {
                self.check_loop_label(label, at)?;
                let enter = self.cond(cond, at)?;
                self.loop_head(label, enter, at)?;
            }
            Stmt::Do { label } => {
                // DO m without WHILE: an endless loop, left by GOTO.
                self.check_loop_label(label, at)?;
                self.loop_head(label, true, at)?;
            }
            Stmt::End { label } => match self.prog.loops.last() {
                Some(&l) if l.label == label => {
                    self.count_jump(at)?;
                    self.seek(l.start)?;
                }
                Some(&l) if self.prog.loops.iter().any(|o| o.label == label) => {
                    return Err(self.alarm(
                        AlarmKind::BadLoop,
                        at,
                        format!("END{label} crosses the loop DO{}", l.label),
                    ))
                }
                _ => {
                    return Err(self.alarm(
                        AlarmKind::BadLoop,
                        at,
                        format!(
                        "END{label} without a matching WHILE ... DO{label} (a jump into a loop?)"
                    ),
                    ))
                }
            },
        }
        Ok(true)
    }

    pub(super) fn cond(&mut self, c: kerf_lang::ExprId, at: u32) -> R<bool> {
        Ok(self.eval(c, at)?.unwrap_or(0.0) != 0.0)
    }

    pub(super) fn assign(&mut self, idx: Option<f64>, v: Option<f64>, at: u32) -> R<()> {
        let Some(i) = idx else {
            return Err(self.alarm(AlarmKind::BadVariable, at, "variable number is vacant"));
        };
        // Fast path: a plain variable other than #0 given by its exact
        // number, a finite or vacant value.
        if let Some(k) = self.vars.plain_index(i) {
            if k > 0 && v.is_none_or(f64::is_finite) {
                self.vars.set_raw(k, v);
                return Ok(());
            }
        }
        if (3000.0..=3006.0).contains(&i) && self.system_write(i, v, at)? {
            return Ok(());
        }
        let r = match Vars::number(i) {
            Ok(n) if self.vars.class(n) == crate::macros::VarClass::System => self.sys_write(n, v),
            Ok(n) if n > 0 && v.is_none_or(f64::is_finite) => {
                self.vars.set_raw(n, v);
                Ok(())
            }
            _ => self.vars.set(i, v),
        };
        r.map_err(|m| self.alarm(m.kind, at, m.message))
    }

    pub(super) fn count_jump(&mut self, at: u32) -> R<()> {
        self.guard
            .count_jump()
            .map_err(|over| self.loop_limit(over, at))
    }

    pub(super) fn seek(&mut self, m: Mark) -> R<()> {
        let r = self.prog.src.as_mut().map(|s| s.seek(m));
        match r {
            Some(Err(e)) => Err(self.alarm(AlarmKind::Io, 0, format!("seek failed: {e}"))),
            _ => Ok(()),
        }
    }

    /// GOTO n: search forward, then from the start of the program.
    pub(super) fn goto(&mut self, n: Option<f64>, at: u32) -> R<()> {
        let Some(n) = n else {
            return Err(self.alarm(AlarmKind::BadVariable, at, "GOTO target is vacant"));
        };
        if !(0.0..=99_999.0).contains(&n) {
            return Err(self.alarm(
                AlarmKind::SequenceNotFound,
                at,
                format!("GOTO {}: sequence number out of range", fmt_num(n)),
            ));
        }
        let target = n.round() as u32;
        let err_src = self.prog.cur;
        self.count_jump(at)?;
        if self.seek_sequence(target, true) {
            let to = self.prog.src.as_ref().expect("loaded").tell().offset;
            self.leave_loops(to);
            return Ok(());
        }
        Err(AlarmKind::SequenceNotFound.at(
            self.cfg.dialect.id,
            SrcRef {
                col: at + 1,
                ..err_src
            },
            format!("GOTO {target}: sequence number N{target} not found"),
        ))
    }

    /// The loop labels the control accepts: DO1-DO3 on the Fanuc
    /// profiles, any label 1-9999 on the HX (its sample uses DO 210).
    pub(super) fn check_loop_label(&self, label: u32, at: u32) -> R<()> {
        let max = self.cfg.dialect.caps.max_loop_label;
        if label == 0 || label > max {
            return Err(self.alarm(
                AlarmKind::BadLoop,
                at,
                format!("DO{label}: loop label out of range (1-{max})"),
            ));
        }
        Ok(())
    }

    /// A WHILE (or bare DO) block: enters the loop or skips past its END.
    pub(super) fn loop_head(&mut self, label: u32, enter: bool, at: u32) -> R<()> {
        let mark = self.prog.raw.mark;
        if let Some(i) = self.prog.loops.iter().rposition(|l| l.start == mark) {
            // The loop head again: loops opened inside it were left.
            if enter {
                self.prog.loops.truncate(i + 1);
                return Ok(());
            }
            let end = self.prog.loops[i].end;
            self.prog.loops.truncate(i);
            return self.seek(end);
        }
        if self.prog.loops.iter().any(|l| l.label == label) {
            return Err(self.alarm(
                AlarmKind::BadLoop,
                at,
                format!("DO{label} inside a loop with the same label"),
            ));
        }
        if self.prog.loops.len() >= MAX_LOOP_DEPTH {
            return Err(self.alarm(
                AlarmKind::BadLoop,
                at,
                format!("WHILE loops nested more than {MAX_LOOP_DEPTH} deep"),
            ));
        }
        let here = self.prog.src.as_ref().expect("loaded").tell();
        // The scan's result depends on the loop head and the labels open
        // around it; remember the last few (an inner loop is entered again
        // on every pass of its outer loop).
        let key = (self.prog.file_id, mark.offset, self.prog.open_labels());
        let end = match self.prog.loop_end(&key) {
            Some(end) => {
                if !enter {
                    self.seek(end)?;
                }
                end
            }
            None => {
                let end = self.scan_loop(label, at)?;
                self.prog.remember_loop_end(key, end);
                end
            }
        };
        if enter {
            self.seek(here)?;
            self.prog.loops.push(LoopFrame {
                label,
                start: mark,
                end,
            });
        }
        Ok(())
    }

    /// Scans forward from the block after `WHILE ... DO label` to its END,
    /// checking the loop rules of 000 §14.2.5 on the way: loops inside it
    /// must close before it (no crossing), must not reuse an open label and
    /// must not nest too deep; the END must be in the same program. Leaves
    /// the source after the END and returns that position.
    pub(super) fn scan_loop(&mut self, label: u32, at: u32) -> R<Mark> {
        let err_src = self.prog.cur;
        let open = self.prog.loops.len();
        let outer = self.prog.open_labels();
        let outer = &outer[..open];
        let src = self.prog.src.as_mut().expect("loaded");
        let mut raw = RawBlock::default();
        let mut blk = Block::default();
        let mut inner: Vec<u32> = Vec::new();
        let dialect = self.cfg.dialect.id;
        let file = self.prog.file_id;
        let bad = |raw: &RawBlock, msg: String| {
            AlarmKind::BadLoop.at(
                dialect,
                SrcRef {
                    file,
                    line: raw.mark.line,
                    col: 1,
                },
                msg,
            )
        };
        while let Ok(true) = src.next_block(&mut raw) {
            if parse_block(&raw.text, &self.cfg.lex, &mut blk).is_err() {
                continue;
            }
            if blk.percent
                || (blk.program.is_some() && self.prog.calls.header != Some(raw.mark.offset))
            {
                break;
            }
            match blk.stmt {
                Some(Stmt::While { label: l, .. }) | Some(Stmt::Do { label: l }) => {
                    if l == label || inner.contains(&l) || outer.contains(&l) {
                        return Err(bad(
                            &raw,
                            format!("DO{l} inside a loop with the same label"),
                        ));
                    }
                    if open + 1 + inner.len() >= MAX_LOOP_DEPTH {
                        return Err(bad(
                            &raw,
                            format!("WHILE loops nested more than {MAX_LOOP_DEPTH} deep"),
                        ));
                    }
                    inner.push(l);
                }
                Some(Stmt::End { label: l }) => {
                    if inner.last() == Some(&l) {
                        inner.pop();
                    } else if inner.is_empty() && l == label {
                        return Ok(src.tell());
                    } else if l == label || inner.contains(&l) || outer.contains(&l) {
                        let open_l = inner.last().copied().unwrap_or(label);
                        return Err(bad(&raw, format!("END{l} crosses the loop DO{open_l}")));
                    }
                    // Any other END alarms if it is ever executed.
                }
                _ => {}
            }
        }
        Err(AlarmKind::BadLoop.at(
            self.cfg.dialect.id,
            SrcRef {
                col: at + 1,
                ..err_src
            },
            format!("WHILE ... DO{label} without END{label}"),
        ))
    }

    /// After a jump to `to`: the loops whose range does not hold it are left.
    pub(super) fn leave_loops(&mut self, to: u64) {
        self.prog
            .loops
            .retain(|l| l.start.offset <= to && to < l.end.offset);
    }

    /// Hurco loop (repeat) commands.
    pub(super) fn hurco_loop(&mut self, l: kerf_lang::LoopCmd) -> R<()> {
        match l {
            kerf_lang::LoopCmd::Start { count } => {
                if count == 0 {
                    return Err(self.alarm(
                        AlarmKind::OutOfRange,
                        0,
                        "loop count must be at least 1",
                    ));
                }
                if self.prog.hurco_loops.len() >= 8 {
                    return Err(self.alarm(
                        AlarmKind::BadLoop,
                        0,
                        "loop commands nested more than 8 deep",
                    ));
                }
                let after = self.prog.src.as_ref().expect("loaded").tell();
                self.prog.hurco_loops.push((count - 1, after));
            }
            kerf_lang::LoopCmd::End => match self.prog.hurco_loops.last_mut() {
                Some((left, mark)) => {
                    if *left > 0 {
                        *left -= 1;
                        let m = *mark;
                        self.count_jump(0)?;
                        self.seek(m)?;
                    } else {
                        self.prog.hurco_loops.pop();
                    }
                }
                None => {
                    return Err(self.alarm(AlarmKind::BadLoop, 0, "loop end without a loop start"))
                }
            },
        }
        Ok(())
    }
}
