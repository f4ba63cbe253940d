//! SVG plot of the toolpath: the XY view for mills, the XZ half-section for
//! lathes (Z to the right, radius X up, the spindle centre line dashed).
//! Rapids dashed red, cuts solid in one colour per tool, plunges that do
//! not move in the view (drilled holes) as rings, the point where an alarm
//! stopped the run as a red cross; a legend and a scale bar in mm.
//!
//! Memory and file size are bounded by the picture, not the program: every
//! shape is snapped to a grid of `quantum` mm and a shape already drawn at
//! that grid is not kept again; when more than [`MAX_SHAPES`] are kept the
//! quantum doubles and the kept shapes are snapped again. Nothing is lost
//! that the 800-pixel picture could show while the quantum is below a
//! pixel; a program dense enough to pass that (a 1 M-block raster) is drawn
//! at the resolution the budget allows.

use std::collections::HashSet;
use std::fmt::Write as _;
use std::io::{self, Write};

use kerf_canon::{Alarm, Canon, Event, Pos};
use kerf_interp::MachineKind;

use crate::sink::{Context, Sink};

/// Most shapes kept (each at most a few dozen bytes of SVG: the file stays
/// under about 3 MB).
pub const MAX_SHAPES: usize = 60_000;

/// The first grid, mm.
const FIRST_QUANTUM: f64 = 1e-4;

/// Cut colours, by tool in order of first use.
const COLOURS: &[&str] = &[
    "#036", "#1a7f37", "#8250df", "#bf8700", "#0969da", "#cf222e", "#57606a", "#e16f24",
];

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

    fn finish(&mut self, _cx: &Context, alarm: Option<&Alarm>) -> io::Result<()> {
        if alarm.is_some() {
            self.drawing.mark_stop();
        }
        self.out.write_all(self.drawing.svg().as_bytes())?;
        self.out.flush()
    }
}

/// What a shape is drawn as.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Form {
    Line,
    /// An SVG arc from `a` to `b` of radius `r`; `mid` set for a full
    /// circle (drawn as two halves through it).
    Arc {
        r: f64,
        large: bool,
        sweep: bool,
        mid: Option<(f64, f64)>,
    },
    /// A plunge that does not move in the view: a ring at `a`.
    Hole,
}

/// One kept shape, view coordinates (exact; snapped only for the key).
#[derive(Clone, Copy, Debug)]
struct Shape {
    /// 0 rapid, 1 + n the n-th tool that cut.
    class: u16,
    a: (f64, f64),
    b: (f64, f64),
    form: Form,
}

/// A shape snapped to the grid: equal keys draw the same at that grid.
type Key = (u16, u8, [i64; 5]);

impl Shape {
    fn key(&self, q: f64) -> Option<Key> {
        let s = |v: f64| (v / q).round() as i64;
        let (a, b) = ((s(self.a.0), s(self.a.1)), (s(self.b.0), s(self.b.1)));
        match self.form {
            Form::Line if a == b => None,
            Form::Line => {
                // A segment and its reverse draw the same.
                let (a, b) = if a <= b { (a, b) } else { (b, a) };
                Some((self.class, 0, [a.0, a.1, b.0, b.1, 0]))
            }
            Form::Arc {
                r, large, sweep, ..
            } => Some((
                self.class,
                1 + u8::from(large) + 2 * u8::from(sweep),
                [a.0, a.1, b.0, b.1, s(r)],
            )),
            Form::Hole => Some((self.class, 5, [a.0, a.1, 0, 0, 0])),
        }
    }
}

/// Collects the path in view coordinates, bounded (see the module doc).
pub struct Drawing {
    kind: MachineKind,
    shapes: Vec<Shape>,
    seen: HashSet<Key>,
    quantum: f64,
    /// Tools in order of first cut.
    tools: Vec<u32>,
    min: (f64, f64),
    max: (f64, f64),
    started: bool,
    last: Option<(f64, f64)>,
    stop: Option<(f64, f64)>,
    /// A run of lines too short for the grid so far, growing until it
    /// spans a cell.
    pending: Option<Shape>,
}

impl Drawing {
    /// An empty drawing in the view of this kind of machine.
    pub fn new(kind: MachineKind) -> Drawing {
        Drawing {
            kind,
            shapes: Vec::new(),
            seen: HashSet::new(),
            quantum: FIRST_QUANTUM,
            tools: Vec::new(),
            min: (f64::MAX, f64::MAX),
            max: (f64::MIN, f64::MIN),
            started: false,
            last: None,
            stop: None,
            pending: None,
        }
    }

    /// The grid the shapes are kept at, mm.
    pub fn quantum(&self) -> f64 {
        self.quantum
    }

    /// Shapes kept.
    pub fn shapes(&self) -> usize {
        self.shapes.len()
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

    fn class(&mut self, e: &Event) -> u16 {
        if matches!(e.cmd, Canon::Rapid { .. }) {
            return 0;
        }
        let i = match self.tools.iter().position(|t| *t == e.tool) {
            Some(i) => i,
            None => {
                self.tools.push(e.tool);
                self.tools.len() - 1
            }
        };
        (i + 1).min(u16::MAX as usize) as u16
    }

    /// Adds a motion starting at `from` (work coordinates).
    pub fn add(&mut self, e: &Event, from: &Pos) {
        let Some(m) = e.motion() else { return };
        let b = self.view(&m.to);
        self.last = Some(b);
        if !self.started {
            // The first rapid comes from wherever the machine was at power
            // on (usually the reference position): draw from its end.
            self.started = true;
            if matches!(e.cmd, Canon::Rapid { .. }) {
                self.grow(b);
                return;
            }
        }
        let a = self.view(from);
        self.grow(a);
        self.grow(b);
        let class = self.class(e);
        let mut form = Form::Line;
        if let Canon::Arc {
            center, dir, plane, ..
        } = &e.cmd
        {
            let (p1, p2, _) = plane.axes();
            let in_view = match self.kind {
                MachineKind::Mill => (p1, p2) == (0, 1),
                MachineKind::Lathe => (p1, p2) == (2, 0),
            };
            let c = self.view(center);
            let r = (a.0 - c.0).hypot(a.1 - c.1);
            if in_view && r >= 1e-9 {
                let ccw = matches!(dir, kerf_canon::ArcDir::Ccw);
                let sw = kerf_canon::geom::sweep(
                    (from[p1], from[p2]),
                    (m.to[p1], m.to[p2]),
                    (center[p1], center[p2]),
                    ccw,
                );
                self.grow((c.0 - r, c.1 - r));
                self.grow((c.0 + r, c.1 + r));
                let full = sw > std::f64::consts::PI * 1.999;
                form = Form::Arc {
                    r,
                    large: !full && sw > std::f64::consts::PI,
                    // The view flips v, so CCW in the plane is clockwise on
                    // screen (sweep flag 0).
                    sweep: !ccw,
                    mid: full.then_some((2.0 * c.0 - a.0, 2.0 * c.1 - a.1)),
                };
            }
        }
        if form == Form::Line && class != 0 && (a.0 - b.0).hypot(a.1 - b.1) < 1e-9 {
            form = Form::Hole;
        }
        self.keep(Shape { class, a, b, form });
    }

    fn keep(&mut self, s: Shape) {
        if s.form == Form::Line {
            if let Some(p) = self.pending.as_mut() {
                if p.class == s.class && p.b == s.a && p.key(self.quantum).is_none() {
                    // Continues a run too short to show: extend it.
                    p.b = s.b;
                    if p.key(self.quantum).is_some() {
                        self.flush();
                    }
                    return;
                }
            }
            self.flush();
            if s.key(self.quantum).is_none() {
                self.pending = Some(s);
                return;
            }
        } else {
            self.flush();
        }
        self.insert(s);
    }

    /// Keeps the pending run, if it shows at the grid.
    fn flush(&mut self) {
        if let Some(p) = self.pending.take() {
            self.insert(p);
        }
    }

    fn insert(&mut self, s: Shape) {
        let Some(k) = s.key(self.quantum) else { return };
        if self.seen.insert(k) {
            self.shapes.push(s);
        }
        while self.shapes.len() > MAX_SHAPES {
            self.coarsen();
        }
    }

    /// Doubles the grid and keeps one shape per key.
    fn coarsen(&mut self) {
        self.quantum *= 2.0;
        self.seen.clear();
        let q = self.quantum;
        let seen = &mut self.seen;
        self.shapes
            .retain(|s| s.key(q).is_some_and(|k| seen.insert(k)));
    }

    /// Marks where the run stopped (on an alarm).
    pub fn mark_stop(&mut self) {
        self.stop = self.last;
    }

    /// The SVG document.
    pub fn svg(&mut self) -> String {
        self.flush();
        let (min, max) = if self.shapes.is_empty() && self.last.is_none() {
            ((0.0, 0.0), (1.0, 1.0))
        } else if self.min.0 > self.max.0 {
            let p = self.last.unwrap_or((0.0, 0.0));
            (p, p)
        } else {
            (self.min, self.max)
        };
        // The lathe's spindle centre line (v = 0) is always in view.
        let (min, max) = if self.kind == MachineKind::Lathe {
            ((min.0, min.1.min(0.0)), (max.0, max.1.max(0.0)))
        } else {
            (min, max)
        };
        let w = (max.0 - min.0).max(1.0);
        let h = (max.1 - min.1).max(1.0);
        let pad = 0.08 * w.max(h);
        // The legend gets a band of its own above the drawing.
        let font = w.max(h) * 0.025;
        let band = font * 1.3 * (self.tools.len() + 1) as f64;
        let view = (
            min.0 - pad,
            min.1 - pad - band,
            w + 2.0 * pad,
            h + 2.0 * pad + band,
        );
        // About 1.2 pixels of the 800-pixel-wide picture.
        let stroke = 1.2 * view.2 / 800.0;
        // Coordinates to a tenth of the grid or of a pixel, whichever is
        // finer, at most 4 decimals.
        let px = view.2 / 800.0;
        let dec = (-(self.quantum.min(px) / 10.0).log10())
            .ceil()
            .clamp(0.0, 4.0) as usize;
        let mut s = format!(
            "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"{:.4} {:.4} {:.4} {:.4}\" width=\"800\" height=\"{:.0}\">\n",
            view.0,
            view.1,
            view.2,
            view.3,
            800.0 * view.3 / view.2
        );
        let _ = writeln!(
            s,
            "<rect x=\"{:.4}\" y=\"{:.4}\" width=\"{:.4}\" height=\"{:.4}\" fill=\"#fff\"/>",
            view.0, view.1, view.2, view.3
        );
        let _ = writeln!(s, "<g fill=\"none\" stroke-width=\"{stroke:.4}\">");
        if self.kind == MachineKind::Lathe {
            let _ = writeln!(
                s,
                "<line x1=\"{:.4}\" y1=\"0\" x2=\"{:.4}\" y2=\"0\" stroke=\"#888\" stroke-dasharray=\"{:.4} {:.4}\"/>",
                view.0,
                view.0 + view.2,
                stroke * 8.0,
                stroke * 3.0
            );
        }
        for class in 0..=self.tools.len() as u16 {
            self.paths(&mut s, class, stroke, dec);
        }
        if let Some(p) = self.stop {
            let d = stroke * 6.0;
            let _ = writeln!(
                s,
                "<path d=\"M{:.4} {:.4}l{:.4} {:.4}m0 {:.4}l{:.4} {:.4}\" stroke=\"#d00\" stroke-width=\"{:.4}\"/>",
                p.0 - d,
                p.1 - d,
                2.0 * d,
                2.0 * d,
                -2.0 * d,
                -2.0 * d,
                2.0 * d,
                stroke * 2.0
            );
        }
        s.push_str("</g>\n");
        self.legend(&mut s, view, stroke, font);
        s.push_str("</svg>\n");
        s
    }

    /// One `<path>` with every shape of a class, segments that continue
    /// each other chained; rings for holes.
    fn paths(&self, s: &mut String, class: u16, stroke: f64, dec: usize) {
        let mut d = String::new();
        let mut holes = String::new();
        let mut at: Option<(f64, f64)> = None;
        let pt = |out: &mut String, cmd: char, p: (f64, f64)| {
            out.push(cmd);
            coord(out, p.0, dec);
            out.push(' ');
            coord(out, p.1, dec);
        };
        for sh in self.shapes.iter().filter(|x| x.class == class) {
            if sh.form == Form::Hole {
                let r = stroke * 1.8;
                pt(&mut holes, 'M', (sh.a.0 - r, sh.a.1));
                let _ = write!(
                    holes,
                    "a{r:.4} {r:.4} 0 1 0 {:.4} 0a{r:.4} {r:.4} 0 1 0 {:.4} 0",
                    2.0 * r,
                    -2.0 * r
                );
                continue;
            }
            if at != Some(sh.a) {
                pt(&mut d, 'M', sh.a);
            }
            match sh.form {
                Form::Arc {
                    r,
                    large,
                    sweep,
                    mid,
                } => {
                    let (l, f) = (u8::from(large), u8::from(sweep));
                    let arc = |d: &mut String, large: u8, to: (f64, f64)| {
                        d.push('A');
                        coord(d, r, dec);
                        d.push(' ');
                        coord(d, r, dec);
                        let _ = write!(d, " 0 {large} {f}");
                        pt(d, ' ', to);
                    };
                    if let Some(m) = mid {
                        arc(&mut d, 0, m);
                    }
                    arc(&mut d, l, sh.b);
                }
                _ => pt(&mut d, 'L', sh.b),
            }
            at = Some(sh.b);
        }
        let colour = self.colour(class);
        if !d.is_empty() {
            if class == 0 {
                let _ = writeln!(
                    s,
                    "<path d=\"{d}\" stroke=\"{colour}\" stroke-dasharray=\"{:.4} {:.4}\"/>",
                    stroke * 4.0,
                    stroke * 3.0
                );
            } else {
                let _ = writeln!(s, "<path d=\"{d}\" stroke=\"{colour}\"/>");
            }
        }
        if !holes.is_empty() {
            let _ = writeln!(s, "<path d=\"{holes}\" stroke=\"{colour}\"/>");
        }
    }

    fn colour(&self, class: u16) -> &'static str {
        if class == 0 {
            "#d33"
        } else {
            COLOURS[(class as usize - 1) % COLOURS.len()]
        }
    }

    /// The legend (rapid, each tool) at the top left and a scale bar of a
    /// round number of mm at the bottom left.
    fn legend(&self, s: &mut String, view: (f64, f64, f64, f64), stroke: f64, font: f64) {
        let x = view.0 + font * 0.6;
        let mut y = view.1 + font * 1.3;
        let _ = writeln!(
            s,
            "<g font-family=\"sans-serif\" font-size=\"{font:.4}\" stroke-width=\"{:.4}\">",
            stroke * 1.5
        );
        let mut entry = |s: &mut String, label: String, colour: &str, dashed: bool| {
            let dash = if dashed {
                format!(
                    " stroke-dasharray=\"{:.4} {:.4}\"",
                    stroke * 4.0,
                    stroke * 3.0
                )
            } else {
                String::new()
            };
            let _ = writeln!(
                s,
                "<line x1=\"{x:.4}\" y1=\"{:.4}\" x2=\"{:.4}\" y2=\"{:.4}\" stroke=\"{colour}\"{dash}/><text x=\"{:.4}\" y=\"{y:.4}\" fill=\"#222\">{label}</text>",
                y - font * 0.35,
                x + font * 2.0,
                y - font * 0.35,
                x + font * 2.5
            );
            y += font * 1.3;
        };
        entry(s, "rapid".into(), self.colour(0), true);
        for (i, t) in self.tools.iter().enumerate() {
            entry(s, format!("T{t}"), self.colour(i as u16 + 1), false);
        }
        // Scale bar: 1, 2 or 5 × 10^k mm, about a fifth of the width.
        let target = view.2 / 5.0;
        let k = 10f64.powf(target.log10().floor());
        let len = [5.0, 2.0, 1.0]
            .into_iter()
            .map(|m| m * k)
            .find(|l| *l <= target)
            .unwrap_or(k);
        let by = view.1 + view.3 - font * 0.8;
        let _ = writeln!(
            s,
            "<path d=\"M{x:.4} {:.4}v{:.4}h{len:.4}v{:.4}\" fill=\"none\" stroke=\"#222\"/><text x=\"{:.4}\" y=\"{:.4}\" fill=\"#222\">{} mm</text>",
            by - font * 0.3,
            font * 0.3,
            -font * 0.3,
            x + len + font * 0.4,
            by + font * 0.2,
            trim(len)
        );
        s.push_str("</g>\n");
    }
}

/// Appends `v` with at most `dec` decimals, trailing zeros and `-0` left
/// out.
fn coord(out: &mut String, v: f64, dec: usize) {
    let t = format!("{v:.dec$}");
    let t = if t.contains('.') {
        t.trim_end_matches('0').trim_end_matches('.')
    } else {
        &t
    };
    out.push_str(if t == "-0" { "0" } else { t });
}

/// A round number without trailing zeros.
fn trim(v: f64) -> String {
    let t = format!("{v:.4}");
    t.trim_end_matches('0').trim_end_matches('.').to_string()
}

#[cfg(test)]
mod tests {
    use super::*;
    use kerf_canon::{Feed, Motion, SrcRef};

    fn feed(tool: u32, x: f64, y: f64) -> Event {
        let p = [x, y, 0.0, 0.0, 0.0, 0.0];
        Event {
            src: SrcRef::default(),
            tool,
            cmd: Canon::Feed {
                m: Motion { to: p, mto: p },
                feed: Feed::PerMin(100.0),
            },
            prog: None,
        }
    }

    fn run(d: &mut Drawing, evs: &[Event]) {
        let mut from = [0.0; 6];
        for e in evs {
            d.add(e, &from);
            from = e.motion().unwrap().to;
        }
    }

    /// A raster of `rows` lines of 1,000 segments of 0.1 mm over 100 mm,
    /// `gap` mm apart, repeated `passes` times (Z levels).
    fn raster(rows: usize, gap: f64, passes: usize) -> Vec<Event> {
        let mut evs = Vec::new();
        for _ in 0..passes {
            for row in 0..rows {
                let y = row as f64 * gap;
                for k in 0..1000 {
                    let x = if row.is_multiple_of(2) {
                        k as f64 * 0.1
                    } else {
                        100.0 - k as f64 * 0.1
                    };
                    evs.push(feed(1, x, y));
                }
            }
        }
        evs
    }

    #[test]
    fn repeated_passes_are_kept_once_at_full_detail() {
        // 10 passes over 40 rows 1 mm apart: 400,000 moves, 40,000 distinct.
        let mut d = Drawing::new(MachineKind::Mill);
        run(&mut d, &raster(40, 1.0, 10));
        assert!(d.shapes() <= 40_001, "{}", d.shapes());
        assert_eq!(d.quantum(), FIRST_QUANTUM);
    }

    #[test]
    fn a_dense_raster_stays_within_the_budget() {
        // 400 rows 0.01 mm apart, every move distinct: the grid coarsens
        // until the shapes fit, and short moves merge instead of vanishing.
        let mut d = Drawing::new(MachineKind::Mill);
        run(&mut d, &raster(400, 0.01, 1));
        assert!(d.shapes() <= MAX_SHAPES);
        let svg = d.svg();
        assert!(svg.len() < 5_000_000, "{}", svg.len());
        // Short moves merged, none lost: the kept shapes still run from X0
        // to X100 and cover every row's length.
        let xs = d.shapes.iter().flat_map(|s| [s.a.0, s.b.0]);
        let (lo, hi) = xs.fold((f64::MAX, f64::MIN), |(l, h), x| (l.min(x), h.max(x)));
        assert_eq!((lo, hi), (0.0, 100.0));
        let drawn: f64 = d.shapes.iter().map(|s| (s.b.0 - s.a.0).abs()).sum();
        assert!(drawn >= 100.0 * 4.0, "at least the rows' extent: {drawn}");
    }

    #[test]
    fn tools_get_colours_and_plunges_rings() {
        let mut d = Drawing::new(MachineKind::Mill);
        let plunge = Event {
            cmd: Canon::Feed {
                m: Motion {
                    to: [10.0, 0.0, -5.0, 0.0, 0.0, 0.0],
                    mto: [10.0, 0.0, -5.0, 0.0, 0.0, 0.0],
                },
                feed: Feed::PerMin(100.0),
            },
            ..feed(2, 0.0, 0.0)
        };
        run(&mut d, &[feed(1, 10.0, 0.0), plunge, feed(2, 20.0, 0.0)]);
        let svg = d.svg();
        assert!(svg.contains(">T1<") && svg.contains(">T2<"), "{svg}");
        assert!(svg.contains(COLOURS[0]) && svg.contains(COLOURS[1]));
        // The plunge at X10 is a ring (two half arcs), drawn in T2's colour.
        // Stroke 1.2 px of (20 + 2·1.6) mm / 800 px, ring radius 1.8 strokes.
        let r = 1.8 * 1.2 * 23.2 / 800.0;
        assert!(svg.contains(&format!("a{r:.4} {r:.4} 0 1 0")), "{svg}");
    }
}
