//! The expansion sink: every canonical command written back as G-code for
//! a target control (kerf-expand's `Expander`), as `kerf expand` writes
//! it. Format: docs/expand.md.

use std::io::{self, Write};

use kerf_canon::{Alarm, Event, Pos};
use kerf_expand::{Control, Expander, Spelling, Target};
use kerf_interp::DialectId;

use crate::sink::{Context, Sink};

/// The control kerf-expand writes for, from a profile's dialect.
pub fn control_of(d: DialectId) -> Control {
    match d {
        DialectId::Hx => Control::Hx,
        DialectId::Puma => Control::Puma,
        DialectId::Hurco => Control::Hurco,
    }
}

/// Writes the program as plain G-code onto `out`.
pub struct Expand<W: Write> {
    target: Target,
    out: Option<W>,
    x: Option<Expander<W>>,
    blocks: u64,
}

impl<W: Write> Expand<W> {
    /// G-code for `target` written onto `out` (the machine's control and
    /// axes are read from the run's profile at the start).
    pub fn new(out: W, target: Target) -> Expand<W> {
        Expand {
            target,
            out: Some(out),
            x: None,
            blocks: 0,
        }
    }

    /// Output blocks written (after the run).
    pub fn blocks(&self) -> u64 {
        self.blocks
    }
}

impl<W: Write> Sink for Expand<W> {
    fn name(&self) -> &str {
        "expand"
    }

    fn start(&mut self, cx: &Context) -> io::Result<()> {
        let Some(out) = self.out.take() else {
            return Ok(());
        };
        let it = cx.interp;
        let p = it.profile();
        let sp = Spelling::new(self.target, control_of(p.dialect));
        let mut x = Expander::new(
            out,
            sp,
            super::axes_of(p),
            it.work_position(),
            it.machine_position(),
        );
        x.start(cx.file(0))?;
        self.x = Some(x);
        Ok(())
    }

    fn event(&mut self, e: &Event, _from: &Pos, cx: &Context) -> io::Result<()> {
        match self.x.as_mut() {
            Some(x) => x.event(e, cx.file(e.src.file)),
            None => Ok(()),
        }
    }

    fn finish(&mut self, cx: &Context, alarm: Option<&Alarm>) -> io::Result<()> {
        let Some(mut x) = self.x.take() else {
            return Ok(());
        };
        if let Some(a) = alarm {
            x.alarm(a, cx.file(a.src.file))?;
        }
        self.blocks = x.blocks();
        x.finish().map(drop)
    }
}
