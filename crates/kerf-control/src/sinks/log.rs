//! The log sink: the operator messages (`Canon::Message`: #3006, Hurco
//! probe records, thread start angles …), one per line, in order.

use std::io::{self, Write};

use kerf_canon::{Alarm, Canon, Event, Pos};

use crate::sink::{Context, Live, Sink};

/// Writes each operator message as one line.
pub struct Log<W: Write> {
    out: W,
}

impl<W: Write> Log<W> {
    /// A log written onto `out`.
    pub fn new(out: W) -> Log<W> {
        Log { out }
    }
}

impl<W: Write> Sink for Log<W> {
    fn name(&self) -> &str {
        "log"
    }

    fn event(&mut self, e: &Event, _from: &Pos, _cx: &Live) -> io::Result<()> {
        if let Canon::Message(text) = &e.cmd {
            writeln!(self.out, "{text}")?;
        }
        Ok(())
    }

    fn finish(&mut self, _cx: &Context, _alarm: Option<&Alarm>) -> io::Result<()> {
        self.out.flush()
    }
}
