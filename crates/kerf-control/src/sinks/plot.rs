//! SVG plot of the toolpath: the XY view for mills, the XZ half-section for
//! lathes (Z to the right, radius X up). Rapids dashed, cuts solid.

use std::io::{self, Write};

use kerf_canon::{Alarm, Canon, Event, Pos};
use kerf_interp::MachineKind;

use crate::sink::{Context, Sink};

/// The plot sink: draws every motion, writes the SVG at the end.
pub struct Plot<W: Write> {
    out: W,
    drawing: Drawing,
}

impl<W: Write> Plot<W> {
    /// A plot written onto `out` at the end of the run.
    pub fn new(out: W) -> Plot<W> {
        Plot {
            out,
            drawing: Drawing::new(MachineKind::Mill),
        }
    }
}

impl<W: Write> Sink for Plot<W> {
    fn name(&self) -> &str {
        "plot"
    }

    fn start(&mut self, cx: &Context) -> io::Result<()> {
        self.drawing = Drawing::new(cx.interp.profile().kind);
        Ok(())
    }

    fn event(&mut self, e: &Event, from: &Pos, _cx: &Context) -> io::Result<()> {
        self.drawing.add(e, from);
        Ok(())
    }

    fn finish(&mut self, _cx: &Context, _alarm: Option<&Alarm>) -> io::Result<()> {
        self.out.write_all(self.drawing.svg().as_bytes())?;
        self.out.flush()
    }
}

/// Collects path segments in view coordinates.
pub struct Drawing {
    kind: MachineKind,
    /// (rapid?, SVG path data) per segment.
    segs: Vec<(bool, String)>,
    min: (f64, f64),
    max: (f64, f64),
    started: bool,
}

impl Drawing {
    /// An empty drawing in the view of this kind of machine.
    pub fn new(kind: MachineKind) -> Drawing {
        Drawing {
            kind,
            segs: Vec::new(),
            min: (f64::MAX, f64::MAX),
            max: (f64::MIN, f64::MIN),
            started: false,
        }
    }

    /// View coordinates (SVG y grows downward, so v is negated).
    fn view(&self, p: &Pos) -> (f64, f64) {
        match self.kind {
            MachineKind::Mill => (p[0], -p[1]),
            MachineKind::Lathe => (p[2], -p[0]),
        }
    }

    fn grow(&mut self, q: (f64, f64)) {
        self.min = (self.min.0.min(q.0), self.min.1.min(q.1));
        self.max = (self.max.0.max(q.0), self.max.1.max(q.1));
    }

    /// Adds a motion starting at `from` (work coordinates).
    pub fn add(&mut self, e: &Event, from: &Pos) {
        let Some(m) = e.motion() else { return };
        if !self.started {
            // The first rapid comes from wherever the machine was at power
            // on (usually the reference position): draw from its end.
            self.started = true;
            if matches!(e.cmd, Canon::Rapid { .. }) {
                self.grow(self.view(&m.to));
                return;
            }
        }
        let a = self.view(from);
        let b = self.view(&m.to);
        self.grow(a);
        self.grow(b);
        let d = match &e.cmd {
            Canon::Arc {
                center, dir, plane, ..
            } => {
                let c = self.view(center);
                let r = (a.0 - c.0).hypot(a.1 - c.1);
                let (p1, p2, _) = plane.axes();
                let in_view = match self.kind {
                    MachineKind::Mill => (p1, p2) == (0, 1),
                    MachineKind::Lathe => (p1, p2) == (2, 0),
                };
                if !in_view || r < 1e-9 {
                    format!("M{:.4} {:.4}L{:.4} {:.4}", a.0, a.1, b.0, b.1)
                } else {
                    let ccw = matches!(dir, kerf_canon::ArcDir::Ccw);
                    let sw = kerf_canon::geom::sweep(
                        (from[p1], from[p2]),
                        (m.to[p1], m.to[p2]),
                        (center[p1], center[p2]),
                        ccw,
                    );
                    self.grow((c.0 - r, c.1 - r));
                    self.grow((c.0 + r, c.1 + r));
                    // The view flips v, so CCW in the plane is clockwise on screen (sweep flag 0).
                    let sweep_flag = if ccw { 0 } else { 1 };
                    if sw > std::f64::consts::PI * 1.999 {
                        let mid = (2.0 * c.0 - a.0, 2.0 * c.1 - a.1);
                        format!("M{:.4} {:.4}A{r:.4} {r:.4} 0 0 {sweep_flag} {:.4} {:.4}A{r:.4} {r:.4} 0 0 {sweep_flag} {:.4} {:.4}", a.0, a.1, mid.0, mid.1, b.0, b.1)
                    } else {
                        let large = if sw > std::f64::consts::PI { 1 } else { 0 };
                        format!(
                            "M{:.4} {:.4}A{r:.4} {r:.4} 0 {large} {sweep_flag} {:.4} {:.4}",
                            a.0, a.1, b.0, b.1
                        )
                    }
                }
            }
            _ => format!("M{:.4} {:.4}L{:.4} {:.4}", a.0, a.1, b.0, b.1),
        };
        self.segs.push((matches!(e.cmd, Canon::Rapid { .. }), d));
    }

    /// The SVG document.
    pub fn svg(&self) -> String {
        let (min, max) = if self.segs.is_empty() {
            ((0.0, 0.0), (1.0, 1.0))
        } else {
            (self.min, self.max)
        };
        let w = (max.0 - min.0).max(1.0);
        let h = (max.1 - min.1).max(1.0);
        let pad = 0.05 * w.max(h);
        let stroke = 0.003 * w.max(h);
        let mut s = format!(
            "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"{:.4} {:.4} {:.4} {:.4}\" width=\"800\" height=\"{:.0}\">\n",
            min.0 - pad,
            min.1 - pad,
            w + 2.0 * pad,
            h + 2.0 * pad,
            800.0 * (h + 2.0 * pad) / (w + 2.0 * pad)
        );
        s.push_str(&format!("<g fill=\"none\" stroke-width=\"{stroke:.4}\">\n"));
        if self.kind == MachineKind::Lathe {
            s.push_str(&format!(
                "<line x1=\"{:.4}\" y1=\"0\" x2=\"{:.4}\" y2=\"0\" stroke=\"#888\" stroke-dasharray=\"{:.4} {:.4}\"/>\n",
                min.0 - pad,
                max.0 + pad,
                stroke * 8.0,
                stroke * 3.0
            ));
        }
        for (rapid, d) in &self.segs {
            if *rapid {
                s.push_str(&format!(
                    "<path d=\"{d}\" stroke=\"#d33\" stroke-dasharray=\"{:.4} {:.4}\"/>\n",
                    stroke * 4.0,
                    stroke * 3.0
                ));
            } else {
                s.push_str(&format!("<path d=\"{d}\" stroke=\"#036\"/>\n"));
            }
        }
        s.push_str("</g>\n</svg>\n");
        s
    }
}
