//! The expansion sink: every canonical command written back as G-code for
//! a target control (kerf-expand's `Expander`), as `kerf expand` writes
//! it. Format: docs/expand.md.

use std::io::{self, Write};

use kerf_canon::{Alarm, Event, Pos};
use kerf_expand::{Control, Expander, Spelling, Target};
use kerf_interp::DialectId;

use crate::sink::{Context, Live, Sink};

/// The control kerf-expand writes for, from a profile's dialect.
pub fn control_of(d: DialectId) -> Control {
    match d {
        DialectId::Hx => Control::Hx,
        DialectId::Puma => Control::Puma,
        DialectId::Hurco => Control::Hurco,
    }
}

/// An expander onto `out` for `target`, set up from the run's profile
/// (dialect, axes) and start position, its heading written.
pub(crate) fn started<W: Write>(out: W, target: Target, cx: &Context) -> io::Result<Expander<W>> {
    let it = cx.interp;
    let p = it.profile();
    let sp = Spelling::new(target, control_of(p.dialect));
    let mut x = Expander::new(
        out,
        sp,
        super::axes_of(p),
        it.work_position(),
        it.machine_position(),
    );
    x.start(cx.file(0))?;
    Ok(x)
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
        self.x = Some(started(out, self.target, cx)?);
        Ok(())
    }

    fn event(&mut self, e: &Event, _from: &Pos, cx: &Live) -> io::Result<()> {
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Job;

    fn expand(text: &str, target: Target) -> (String, Option<Alarm>) {
        let mut runner = Job::text("part.nc", text).machine("hx-mc").load().unwrap();
        runner.interpret_only();
        let mut out = Vec::new();
        let mut sink = Expand::new(&mut out, target);
        let outcome = runner.run(&mut [&mut sink as &mut dyn Sink]).unwrap();
        drop(sink);
        (String::from_utf8(out).unwrap(), outcome.alarm)
    }

    #[test]
    fn writes_the_program_from_the_start_position() {
        // hx-mc starts at machine 0 with G54 at (-400, -250, -250): work
        // (400, 250, 250); the first move names every axis.
        let (text, alarm) = expand("G0 X10. Y5.\nG1 X20. F600.\nM30\n", Target::Fanuc);
        assert!(alarm.is_none());
        assert_eq!(
            text,
            "%\nO0001 (KERF EXPAND OF part.nc TO fanuc)\nG21\nG17 G40 G49 G80 G90\n\
             G00 X10. Y5. Z250. C0. (part.nc:1)\n\
             G94 G01 X20. F600. (part.nc:2)\n\
             M30 (part.nc:3)\n%\n"
        );
    }

    #[test]
    fn stops_at_the_alarm_with_a_comment() {
        // The arc's end is 50.99 mm from the centre, its start 40: F_82112.
        let (text, alarm) = expand("G0 X0 Y0\nG2 X50. Y50. I40. F100.\nM30\n", Target::LinuxCnc);
        assert_eq!(
            alarm.map(|a| (a.code, a.src.line)),
            Some(("F_82112".into(), 2))
        );
        let last: Vec<&str> = text.lines().rev().take(2).collect();
        assert_eq!(last[1], "G0 X0. Y0. Z250. C0. (part.nc:1)");
        assert!(
            last[0].starts_with("(ALARM F_82112 part.nc:2: arc end point"),
            "{}",
            last[0]
        );
    }
}
