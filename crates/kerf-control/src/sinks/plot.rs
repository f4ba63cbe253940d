//! The plot of the toolpath (`--plot FILE.svg` or `FILE.png`): the XY
//! view for mills, the ZX half-section for lathes (Z to the right, radius
//! X up, the spindle centre line dashed and the chuck on the −Z side),
//! axes with ticks labelled in mm, rapids dashed red, cuts solid in one
//! colour per tool, holes and plunges as rings, the alarm point as a red
//! cross, the program start as a square, a legend beside the drawing. HX
//! G112 contours are drawn on the part's face (X and C as the Cartesian
//! point), G107 moves in a panel of their own on the developed surface (Z
//! or Y against C unrolled to mm: the arc length C·π·r/180 on the
//! cylinder of radius r). Both modes are read from the
//! `ModeChange::Rotary` events.
//!
//! - [`drawing`]: the shapes, collected and bounded by the picture;
//! - [`depth`]: the lowest Z cut per cell of the mill's view, drawn
//!   instead of the cuts' lines when they cover the area (a 3-D surface
//!   raster), by [`shade`] as a relief coloured by Z;
//! - [`layout`]: the pixel geometry (areas, scale, ticks);
//! - [`scene`]: the picture as drawing items;
//! - [`svg`] and [`raster`]: the two writers.

pub mod depth;
pub mod drawing;
pub mod layout;
pub mod raster;
pub mod scene;
pub mod shade;
pub mod svg;

use std::io::{self, Write};
use std::path::Path;

use kerf_canon::{Alarm, Canon, Event, ModeChange, Pos};
use kerf_interp::MachineKind;

use crate::sink::{Context, Live, Sink};

pub use drawing::{Drawing, Rot, MAX_SHAPES};
pub use layout::Layout;

/// The file format of a plot.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PlotFormat {
    /// SVG text.
    Svg,
    /// An 8-bit RGBA PNG.
    Png,
}

impl PlotFormat {
    /// PNG for a path ending in `.png` (any case), SVG otherwise.
    pub fn of_path(p: &Path) -> PlotFormat {
        match p.extension().and_then(|e| e.to_str()) {
            Some(e) if e.eq_ignore_ascii_case("png") => PlotFormat::Png,
            _ => PlotFormat::Svg,
        }
    }
}

/// The plot sink: draws every motion, writes the picture at the end.
pub struct Plot<W: Write> {
    out: W,
    format: PlotFormat,
    drawing: Drawing,
    /// The rotary interpolation in force, from the last
    /// `ModeChange::Rotary` event.
    rot: Rot,
}

impl<W: Write> Plot<W> {
    /// An SVG plot written onto `out` at the end of the run.
    pub fn new(out: W) -> Plot<W> {
        Plot::with_format(out, PlotFormat::Svg)
    }

    /// A plot in `format` written onto `out` at the end of the run.
    pub fn with_format(out: W, format: PlotFormat) -> Plot<W> {
        Plot {
            out,
            format,
            drawing: Drawing::new(MachineKind::Mill),
            rot: Rot::Off,
        }
    }
}

/// The picture of a drawing in a format.
pub fn render(d: &mut Drawing, format: PlotFormat) -> io::Result<Vec<u8>> {
    d.flush();
    let rows = legend_rows(d);
    let keep = d.stop.as_ref().map(|(i, p, _)| (*i, *p));
    let layout = Layout::new(&d.panels, d.kind() == MachineKind::Lathe, rows, keep);
    let items = scene::build(d, &layout);
    match format {
        PlotFormat::Svg => Ok(svg::write(&items, layout.width, layout.height).into_bytes()),
        PlotFormat::Png => raster::write(&items, layout.width, layout.height),
    }
}

/// Rows of the legend: rapid, the tools, holes, the centre line, the
/// program start (a row kept even when the start falls outside the view,
/// at the legend's end: left blank), the alarm.
fn legend_rows(d: &Drawing) -> usize {
    let holes = d
        .panels
        .iter()
        .flat_map(|p| p.shapes())
        .any(|s| s.form == drawing::Form::Hole);
    let cuts = if d.depth_view().is_some() {
        2
    } else {
        d.tools.len()
    };
    1 + cuts
        + usize::from(holes)
        + usize::from(d.kind() == MachineKind::Lathe)
        + usize::from(d.panels.iter().any(|p| p.start().is_some()))
        + usize::from(d.stop.is_some())
}

impl<W: Write> Sink for Plot<W> {
    fn name(&self) -> &str {
        "plot"
    }

    fn start(&mut self, cx: &Context) -> io::Result<()> {
        let p = cx.interp.profile();
        self.drawing = Drawing::new(p.kind);
        self.rot = Rot::Off;
        Ok(())
    }

    fn event(&mut self, e: &Event, from: &Pos, _cx: &Live) -> io::Result<()> {
        match e.cmd {
            Canon::Mode(ModeChange::Rotary(m)) => self.rot = m,
            _ if e.motion().is_some() => self.drawing.add(e, from, self.rot),
            _ => {}
        }
        Ok(())
    }

    fn finish(&mut self, cx: &Context, alarm: Option<&Alarm>) -> io::Result<()> {
        if let Some(a) = alarm {
            let label = format!("alarm {} line {}", a.code, a.src.line);
            self.drawing.mark_stop(label, &cx.interp.work_position());
        }
        let bytes = render(&mut self.drawing, self.format)?;
        self.out.write_all(&bytes)?;
        self.out.flush()
    }
}

#[cfg(test)]
mod tests;
