//! The toolpath sink: one JSON object per canonical motion (and dwell), in
//! execution order, written when its end time is planned. Format:
//! docs/formats.md.

use std::io::{self, Write};

use kerf_canon::{Axis, Canon, Event, Feed, Pos};

use crate::sink::{Context, Sink, Timed};

/// Writes JSON Lines.
pub struct Toolpath<W: Write> {
    w: W,
    axes: Vec<Axis>,
    buf: String,
}

/// Appends a number rounded to 1 nm (no `-0`, no exponent).
pub fn num(out: &mut String, v: f64) {
    use std::fmt::Write as _;
    let r = (v * 1e6).round() / 1e6;
    let r = if r == 0.0 { 0.0 } else { r };
    if r.fract() == 0.0 && r.abs() < 1e15 {
        let _ = write!(out, "{}", r as i64);
        out.push_str(".0");
    } else {
        let _ = write!(out, "{r}");
    }
}

fn json_str(out: &mut String, s: &str) {
    out.push('"');
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            c if (c as u32) < 0x20 => out.push_str(&format!("\\u{:04x}", c as u32)),
            c => out.push(c),
        }
    }
    out.push('"');
}

impl<W: Write> Toolpath<W> {
    /// A writer onto `w`; the axes are the machine's, taken at the start
    /// of the run.
    pub fn new(w: W) -> Toolpath<W> {
        Toolpath {
            w,
            axes: Vec::new(),
            buf: String::with_capacity(512),
        }
    }

    fn pos(&mut self, key: &str, p: &Pos) {
        self.buf.push_str(",\"");
        self.buf.push_str(key);
        self.buf.push_str("\":{");
        for (i, a) in self.axes.iter().enumerate() {
            if i > 0 {
                self.buf.push(',');
            }
            self.buf.push('"');
            self.buf.push_str(a.name());
            self.buf.push_str("\":");
            num(&mut self.buf, p[*a as usize]);
        }
        self.buf.push('}');
    }

    /// Writes the record of one event (non-motion events write nothing).
    /// `here` is the work position after the event; `t` its end time.
    pub fn write(
        &mut self,
        e: &Event,
        file: &str,
        here: &Pos,
        t: f64,
        feed_mm_min: Option<f64>,
    ) -> io::Result<()> {
        let kind = match &e.cmd {
            Canon::Rapid { .. } => "rapid",
            Canon::Feed { .. } => "feed",
            Canon::Arc { .. } => "arc",
            Canon::Thread { .. } => "thread",
            Canon::Dwell { .. } => "dwell",
            _ => return Ok(()),
        };
        self.buf.clear();
        self.buf.push_str("{\"file\":");
        json_str(&mut self.buf, file);
        self.buf.push_str(",\"line\":");
        self.buf.push_str(&e.src.line.to_string());
        self.buf.push_str(",\"kind\":\"");
        self.buf.push_str(kind);
        self.buf.push('"');
        match &e.cmd {
            Canon::Rapid { m, .. }
            | Canon::Feed { m, .. }
            | Canon::Thread { m, .. }
            | Canon::Arc { m, .. } => {
                let (to, mto) = (m.to, m.mto);
                self.pos("to", &to);
                self.pos("mto", &mto);
                if let Some(p) = e.prog.as_deref() {
                    self.pos("prog", p);
                }
            }
            Canon::Dwell {
                seconds,
                revolutions,
            } => {
                let p = *here;
                self.pos("to", &p);
                self.buf.push_str(",\"seconds\":");
                num(&mut self.buf, *seconds);
                if *revolutions > 0.0 {
                    self.buf.push_str(",\"revolutions\":");
                    num(&mut self.buf, *revolutions);
                }
            }
            _ => {}
        }
        if let Canon::Arc { center, dir, .. } = &e.cmd {
            let c = *center;
            self.pos("center", &c);
            self.buf.push_str(",\"dir\":\"");
            self.buf.push_str(dir.name());
            self.buf.push('"');
        }
        let feed = match &e.cmd {
            Canon::Feed { feed, m } | Canon::Arc { feed, m, .. } => Some((*feed, m)),
            _ => None,
        };
        if let Some((f, _)) = feed {
            self.buf.push_str(",\"feed\":");
            num(&mut self.buf, feed_mm_min.unwrap_or(0.0));
            if let Feed::PerRev(v) = f {
                self.buf.push_str(",\"feed_per_rev\":");
                num(&mut self.buf, v);
            }
        }
        if let Canon::Thread { lead, .. } = &e.cmd {
            self.buf.push_str(",\"lead\":");
            num(&mut self.buf, *lead);
        }
        self.buf.push_str(",\"tool\":");
        self.buf.push_str(&e.tool.to_string());
        self.buf.push_str(",\"t_end\":");
        num(&mut self.buf, t);
        self.buf.push_str("}\n");
        self.w.write_all(self.buf.as_bytes())
    }
}

impl<W: Write> Sink for Toolpath<W> {
    fn name(&self) -> &str {
        "toolpath"
    }

    fn start(&mut self, cx: &Context) -> io::Result<()> {
        self.axes = super::axes_of(cx.interp.profile());
        Ok(())
    }

    fn timed(&mut self, t: &Timed, cx: &Context) -> io::Result<()> {
        let file = cx.file(t.event.src.file);
        self.write(t.event, file, &t.to, t.t_end, t.feed_mm_min)
    }

    fn finish(&mut self, _cx: &Context, _alarm: Option<&kerf_canon::Alarm>) -> io::Result<()> {
        self.w.flush()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_plain_decimals() {
        let mut s = String::new();
        for v in [1.0, -0.0, 0.1 + 0.2, -12.3456789, 1e-9, 2.5e7] {
            num(&mut s, v);
            s.push(' ');
        }
        assert_eq!(s, "1.0 0.0 0.3 -12.345679 0.0 25000000.0 ");
    }
}
