//! The sample sink: the smoothed axis setpoints every `dt` seconds as CSV
//! (`t,X,Y,…`), from the planner's timeline through kerf-motion's
//! [`Sampler`]. Format: docs/formats.md.

use std::io::{self, Write};

use kerf_canon::{Alarm, Axis};
use kerf_motion::{Piece, Sampler};

use super::toolpath::num;
use crate::sink::{Context, Live, Sink};

/// Writes one CSV line per sample period.
pub struct Sample<W: Write> {
    out: W,
    dt: f64,
    axes: Vec<Axis>,
    sampler: Option<Sampler>,
    /// Planned time covered by the pieces received so far, s.
    covered: f64,
    line: Vec<u8>,
}

impl<W: Write> Sample<W> {
    /// Samples every `dt` seconds (> 0) onto `out`.
    pub fn new(dt: f64, out: W) -> Sample<W> {
        Sample {
            out,
            dt,
            axes: Vec::new(),
            sampler: None,
            covered: 0.0,
            line: Vec::with_capacity(64),
        }
    }
}

impl<W: Write> Sink for Sample<W> {
    fn name(&self) -> &str {
        "sample"
    }

    fn wants_pieces(&self) -> bool {
        true
    }

    fn start(&mut self, cx: &Context) -> io::Result<()> {
        self.axes = super::axes_of(cx.interp.profile());
        let head: Vec<&str> = self.axes.iter().map(|a| a.name()).collect();
        writeln!(self.out, "t,{}", head.join(","))?;
        let p = cx.planner;
        self.sampler = Some(Sampler::new(
            self.dt,
            p.stages(),
            p.smoothing_time(),
            cx.interp.machine_position(),
        ));
        Ok(())
    }

    fn pieces(&mut self, batch: &[Piece], _cx: &Live) -> io::Result<()> {
        let Some(s) = self.sampler.as_mut() else {
            return Ok(());
        };
        for p in batch {
            self.covered = p.t0 + p.duration();
            s.add(p.clone());
        }
        let (out, axes, line) = (&mut self.out, &self.axes, &mut self.line);
        let mut err = None;
        s.run(self.covered, &mut |t, p| {
            if err.is_some() {
                return;
            }
            line.clear();
            num(line, t);
            for a in axes {
                line.push(b',');
                num(line, p[*a as usize]);
            }
            line.push(b'\n');
            if let Err(e) = out.write_all(line) {
                err = Some(e);
            }
        });
        err.map_or(Ok(()), Err)
    }

    fn finish(&mut self, _cx: &Context, _alarm: Option<&Alarm>) -> io::Result<()> {
        self.out.flush()
    }
}
