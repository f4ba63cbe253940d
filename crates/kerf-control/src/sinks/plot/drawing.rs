//! The shapes of a plot, collected from the motions in view coordinates
//! (u to the right, v up, mm; G107's C developed to mm on its cylinder)
//! and bounded by the picture.
//!
//! Every shape is snapped to a grid of `quantum` mm for its key and a
//! shape already kept at that grid is not kept again; runs of lines too
//! short for the grid merge into one; when a panel holds more than its
//! budget the quantum doubles and the kept shapes are snapped again.
//! Nothing is lost that the picture could show while the quantum is
//! below a pixel; a program dense enough to pass that (a 1 M-block
//! raster) is drawn at the resolution the budget allows.

use std::collections::HashSet;
use std::f64::consts::PI;

use kerf_canon::{ArcDir, Canon, Event, Plane, Pos, RotaryMode};
use kerf_interp::MachineKind;

use super::depth::DepthMap;

/// Most shapes kept in the main panel (each at most a few dozen bytes of
/// SVG: the file stays under about 3 MB).
pub const MAX_SHAPES: usize = 60_000;

/// Most shapes kept in the G107 development panel.
pub const MAX_DEV_SHAPES: usize = 20_000;

/// The first grid, mm.
pub const FIRST_QUANTUM: f64 = 1e-4;

/// The rotary-axis interpolation a motion was made in (HX G112 / G107),
/// as the event stream reports it (`ModeChange::Rotary`): `Off` draws the
/// ordinary view; `Polar` draws X (signed radius) and C (degrees) as the
/// Cartesian contour on the part's face, C0 along +X; `Cylinder` draws
/// the developed surface in a panel of its own, C as the arc length
/// C·π·r/180 mm (G18: Z to the right, C up; G17: C to the right, Y up).
pub type Rot = RotaryMode;

/// Which panel of the picture.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum View {
    /// Mill XY (G112 contours included).
    MillXy,
    /// Lathe half-section: Z right, radius X up.
    LatheZx,
    /// G107 development in G18: Z right, C up.
    DevZc,
    /// G107 development in G17: C right, Y up.
    DevCy,
}

impl View {
    /// The horizontal and vertical axis titles.
    pub fn axis_titles(self) -> (&'static str, &'static str) {
        match self {
            View::MillXy => ("X mm", "Y mm"),
            View::LatheZx => ("Z mm", "X mm"),
            View::DevZc => ("Z mm", "C mm"),
            View::DevCy => ("C mm", "Y mm"),
        }
    }

    /// The panel's title.
    pub fn title(self) -> &'static str {
        match self {
            View::MillXy => "XY view, work coordinates",
            View::LatheZx => "ZX half-section, work coordinates, X a radius",
            View::DevZc | View::DevCy => "G107: the developed surface, C as arc length",
        }
    }
}

/// What a shape is drawn as.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Form {
    /// A straight segment from `a` to `b`.
    Line,
    /// A circular arc from `a` to `b` about `c`, `sweep` radians (positive
    /// counter-clockwise in the view, u right and v up).
    Arc {
        /// Centre, view coordinates.
        c: (f64, f64),
        /// Signed sweep angle, radians.
        sweep: f64,
    },
    /// A cut that does not move in the view (a drilled hole, a plunge):
    /// a marker at `a`.
    Hole,
}

/// One kept shape, view coordinates (exact; snapped only for the key).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Shape {
    /// 0 rapid, 1 + n the n-th tool that cut.
    pub class: u16,
    /// Start.
    pub a: (f64, f64),
    /// End.
    pub b: (f64, f64),
    /// Line, arc or hole.
    pub form: Form,
}

/// A shape snapped to the grid: equal keys draw the same at that grid.
type Key = (u16, u8, [i64; 6]);

impl Shape {
    fn key(&self, q: f64) -> Option<Key> {
        let s = |v: f64| (v / q).round() as i64;
        let (a, b) = ((s(self.a.0), s(self.a.1)), (s(self.b.0), s(self.b.1)));
        match self.form {
            Form::Line if a == b => None,
            Form::Line => {
                // A segment and its reverse draw the same.
                let (a, b) = if a <= b { (a, b) } else { (b, a) };
                Some((self.class, 0, [a.0, a.1, b.0, b.1, 0, 0]))
            }
            Form::Arc { c, sweep } => {
                let turn = (sweep / PI * 64.0).round() as i64;
                Some((self.class, 1, [a.0, a.1, s(c.0), s(c.1), turn, 0]))
            }
            Form::Hole => Some((self.class, 2, [a.0, a.1, 0, 0, 0, 0])),
        }
    }
}

/// The shapes of one panel, bounded (see the module doc).
pub struct Panel {
    /// What the panel shows.
    pub view: View,
    shapes: Vec<Shape>,
    seen: HashSet<Key>,
    quantum: f64,
    budget: usize,
    min: (f64, f64),
    max: (f64, f64),
    /// The extent of the cutting moves alone.
    cut_min: (f64, f64),
    cut_max: (f64, f64),
    /// A run of lines too short for the grid so far, growing until it
    /// spans a cell.
    pending: Option<Shape>,
    /// Shapes drawn in G112 (the title says so).
    pub polar: bool,
    /// The smallest and largest G107 cylinder radius drawn here, mm.
    pub radius: Option<(f64, f64)>,
    /// The end of the first rapid (the extent when nothing else is).
    start: Option<(f64, f64)>,
}

impl Panel {
    /// An empty panel keeping at most `budget` shapes.
    pub fn new(view: View, budget: usize) -> Panel {
        Panel {
            view,
            shapes: Vec::new(),
            seen: HashSet::new(),
            quantum: FIRST_QUANTUM,
            budget,
            min: (f64::MAX, f64::MAX),
            max: (f64::MIN, f64::MIN),
            cut_min: (f64::MAX, f64::MAX),
            cut_max: (f64::MIN, f64::MIN),
            pending: None,
            polar: false,
            radius: None,
            start: None,
        }
    }

    /// The grid the shapes are kept at, mm.
    pub fn quantum(&self) -> f64 {
        self.quantum
    }

    /// The kept shapes (the pending run included after [`Panel::flush`]).
    pub fn shapes(&self) -> &[Shape] {
        &self.shapes
    }

    /// The extent of everything drawn (the first rapid's end point when
    /// nothing was), None when nothing was.
    pub fn bounds(&self) -> Option<((f64, f64), (f64, f64))> {
        if self.min.0 <= self.max.0 {
            Some((self.min, self.max))
        } else {
            self.start.map(|p| (p, p))
        }
    }

    /// Where the program's first rapid ended (its first position: the
    /// rapid itself, from the power-on position, is not drawn), when it
    /// ended in this panel.
    pub fn start(&self) -> Option<(f64, f64)> {
        self.start
    }

    /// The extent of the cutting moves, None without any.
    pub fn cut_bounds(&self) -> Option<((f64, f64), (f64, f64))> {
        (self.cut_min.0 <= self.cut_max.0).then_some((self.cut_min, self.cut_max))
    }

    /// True when something other than holes was kept (or is pending).
    pub fn has_lines(&self) -> bool {
        self.pending.is_some() || self.shapes.iter().any(|s| s.form != Form::Hole)
    }

    /// The largest v of the cutting moves' end points (a lathe's largest
    /// radius cut), None without cuts.
    pub fn cut_top(&self) -> Option<f64> {
        self.shapes
            .iter()
            .filter(|s| s.class != 0)
            .map(|s| s.a.1.max(s.b.1))
            .reduce(f64::max)
    }

    /// Widens the extent to hold `p`.
    pub fn grow(&mut self, p: (f64, f64)) {
        self.min = (self.min.0.min(p.0), self.min.1.min(p.1));
        self.max = (self.max.0.max(p.0), self.max.1.max(p.1));
    }

    fn grow_cut(&mut self, p: (f64, f64)) {
        self.grow(p);
        self.cut_min = (self.cut_min.0.min(p.0), self.cut_min.1.min(p.1));
        self.cut_max = (self.cut_max.0.max(p.0), self.cut_max.1.max(p.1));
    }

    /// Keeps a shape (merged, snapped, deduplicated).
    pub fn keep(&mut self, s: Shape) {
        let cut = s.class != 0;
        self.grow_by(s.a, cut);
        self.grow_by(s.b, cut);
        if let Form::Arc { c, sweep } = s.form {
            self.grow_arc(s.a, c, sweep, cut);
        }
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

    /// The arc's extreme points in the view.
    fn grow_by(&mut self, p: (f64, f64), cut: bool) {
        if cut {
            self.grow_cut(p)
        } else {
            self.grow(p)
        }
    }

    fn grow_arc(&mut self, a: (f64, f64), c: (f64, f64), sweep: f64, cut: bool) {
        let r = (a.0 - c.0).hypot(a.1 - c.1);
        let a0 = (a.1 - c.1).atan2(a.0 - c.0);
        for k in -4..=8 {
            let q = k as f64 * PI / 2.0;
            let t = (q - a0) / sweep;
            if (0.0..=1.0).contains(&t) {
                self.grow_by((c.0 + r * q.cos(), c.1 + r * q.sin()), cut);
            }
        }
    }

    /// Keeps the pending run, if it shows at the grid.
    pub fn flush(&mut self) {
        if let Some(p) = self.pending.take() {
            self.insert(p);
        }
    }

    fn insert(&mut self, s: Shape) {
        let Some(k) = s.key(self.quantum) else { return };
        if self.seen.insert(k) {
            self.shapes.push(s);
        }
        while self.shapes.len() > self.budget {
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
}

/// The whole picture's content: the main panel, the G107 development
/// panel, the tools in order of first cut and the alarm point.
pub struct Drawing {
    kind: MachineKind,
    /// Main view, then the development.
    pub panels: [Panel; 2],
    /// Tools in order of first cut.
    pub tools: Vec<u32>,
    started: bool,
    last: Option<(usize, (f64, f64))>,
    /// Where an alarm stopped the run: panel index, point, label.
    pub stop: Option<(usize, (f64, f64), String)>,
    /// The lowest Z cut over the mill's XY view (cuts outside G112 and
    /// G107 only).
    depth: DepthMap,
}

/// Least share of the cut's bounding box the cut covers (at the depth
/// map's cell, about a pixel) for the depth picture to replace the lines.
pub const DEPTH_COVERAGE: f64 = 0.5;

/// Fewest cells cut for the depth picture (a few short cuts never are).
pub const DEPTH_CELLS: usize = 1000;

impl Drawing {
    /// An empty drawing in the view of this kind of machine.
    pub fn new(kind: MachineKind) -> Drawing {
        let main = match kind {
            MachineKind::Mill => View::MillXy,
            MachineKind::Lathe => View::LatheZx,
        };
        Drawing {
            kind,
            panels: [
                Panel::new(main, MAX_SHAPES),
                Panel::new(View::DevZc, MAX_DEV_SHAPES),
            ],
            tools: Vec::new(),
            started: false,
            last: None,
            stop: None,
            depth: DepthMap::default(),
        }
    }

    /// The depth map, when the picture shows it instead of the cuts'
    /// lines: a mill whose cuts cover at least [`DEPTH_COVERAGE`] of
    /// their bounding box in [`DEPTH_CELLS`] cells or more (a dense
    /// raster, which as lines would be a solid area).
    pub fn depth_view(&self) -> Option<&DepthMap> {
        let m = &self.depth;
        let dense = m.coverage() >= DEPTH_COVERAGE && m.cells() >= DEPTH_CELLS;
        (self.kind == MachineKind::Mill && dense).then_some(m)
    }

    /// Marks a cut made outside G112/G107 on the depth map: lines and
    /// plunges straight, arcs (helices included) as chords of at most a
    /// cell.
    fn mark_depth(&mut self, e: &Event, from: &Pos) {
        let Some(m) = e.motion() else { return };
        let xyz = |p: &Pos| [p[0], p[1], p[2]];
        let Canon::Arc {
            center, dir, plane, ..
        } = &e.cmd
        else {
            self.depth.line(xyz(from), xyz(&m.to));
            return;
        };
        let (p1, p2, p3) = plane.axes();
        let ccw = matches!(dir, ArcDir::Ccw);
        let (a, b, c) = (
            (from[p1], from[p2]),
            (m.to[p1], m.to[p2]),
            (center[p1], center[p2]),
        );
        let sw = kerf_canon::geom::sweep(a, b, c, ccw);
        let sweep = if ccw { sw } else { -sw };
        let r = (a.0 - c.0).hypot(a.1 - c.1);
        let a0 = (a.1 - c.1).atan2(a.0 - c.0);
        let n = ((r * sw / self.depth.cell()).ceil() as usize).clamp(1, 1024);
        let mut prev = xyz(from);
        for k in 1..=n {
            let t = k as f64 / n as f64;
            let mut p = *from;
            if k == n {
                p = m.to;
            } else {
                let ang = a0 + sweep * t;
                p[p1] = c.0 + r * ang.cos();
                p[p2] = c.1 + r * ang.sin();
                p[p3] = from[p3] + (m.to[p3] - from[p3]) * t;
            }
            self.depth.line(prev, xyz(&p));
            prev = xyz(&p);
        }
    }

    /// Mill or lathe.
    pub fn kind(&self) -> MachineKind {
        self.kind
    }

    /// Panel index and view coordinates of a point.
    fn view(&self, p: &Pos, rot: Rot) -> (usize, (f64, f64)) {
        const C: usize = 5;
        match (self.kind, rot) {
            (MachineKind::Lathe, _) => (0, (p[2], p[0])),
            (MachineKind::Mill, Rot::Off) => (0, (p[0], p[1])),
            (MachineKind::Mill, Rot::Polar) => {
                let c = p[C].to_radians();
                (0, (p[0] * c.cos(), p[0] * c.sin()))
            }
            (MachineKind::Mill, Rot::Cylinder { radius, plane }) => {
                let arc = p[C].to_radians() * radius;
                match plane {
                    Plane::XY => (1, (arc, p[1])),
                    _ => (1, (p[2], arc)),
                }
            }
        }
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

    /// Adds a motion starting at `from` (work coordinates), made in the
    /// rotary interpolation `rot`.
    pub fn add(&mut self, e: &Event, from: &Pos, rot: Rot) {
        let Some(m) = e.motion() else { return };
        let (panel, b) = self.view(&m.to, rot);
        self.last = Some((panel, b));
        if !self.started {
            // The first rapid comes from wherever the machine was at power
            // on (usually the reference position): draw from its end.
            self.started = true;
            if matches!(e.cmd, Canon::Rapid { .. }) {
                self.panels[panel].start = Some(b);
                return;
            }
        }
        let (_, a) = self.view(from, rot);
        let class = self.class(e);
        if class != 0 && rot == Rot::Off && self.kind == MachineKind::Mill {
            self.mark_depth(e, from);
        }
        let mut form = Form::Line;
        if let Canon::Arc {
            center, dir, plane, ..
        } = &e.cmd
        {
            if rot == Rot::Off && self.in_view(*plane) {
                let (_, c) = self.view(center, rot);
                let (p1, p2, _) = plane.axes();
                let ccw = matches!(dir, ArcDir::Ccw);
                let sw = kerf_canon::geom::sweep(
                    (from[p1], from[p2]),
                    (m.to[p1], m.to[p2]),
                    (center[p1], center[p2]),
                    ccw,
                );
                if (a.0 - c.0).hypot(a.1 - c.1) >= 1e-9 {
                    let sweep = if ccw { sw } else { -sw };
                    form = Form::Arc { c, sweep };
                }
            }
        }
        let moves = from.iter().zip(&m.to).any(|(f, t)| (f - t).abs() > 1e-9);
        if form == Form::Line && class != 0 && moves && (a.0 - b.0).hypot(a.1 - b.1) < 1e-9 {
            form = Form::Hole;
        }
        let p = &mut self.panels[panel];
        p.polar |= rot == Rot::Polar;
        if let Rot::Cylinder { radius, plane } = rot {
            p.view = if plane == Plane::XY {
                View::DevCy
            } else {
                View::DevZc
            };
            p.radius = Some(p.radius.map_or((radius, radius), |(lo, hi)| {
                (lo.min(radius), hi.max(radius))
            }));
        }
        p.keep(Shape { class, a, b, form });
    }

    /// True when arcs of this plane are circles in the main view (in both
    /// the view's u-v and the plane's axes counter-clockwise is positive).
    fn in_view(&self, plane: Plane) -> bool {
        match self.kind {
            MachineKind::Mill => plane == Plane::XY,
            MachineKind::Lathe => plane == Plane::ZX,
        }
    }

    /// Marks where the run stopped (on an alarm) with its label: the end
    /// of the last motion, or `at` (work coordinates) when the alarm came
    /// before any motion.
    pub fn mark_stop(&mut self, label: String, at: &Pos) {
        let (panel, p) = self.last.unwrap_or_else(|| self.view(at, Rot::Off));
        self.stop = Some((panel, p, label));
    }

    /// Keeps the pending runs (before drawing).
    pub fn flush(&mut self) {
        for p in &mut self.panels {
            p.flush();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use kerf_canon::{Feed, Motion, SrcRef};

    pub(crate) fn feed(tool: u32, x: f64, y: f64) -> Event {
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
            d.add(e, &from, Rot::Off);
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
        assert!(d.panels[0].shapes().len() <= 40_001);
        assert_eq!(d.panels[0].quantum(), FIRST_QUANTUM);
    }

    #[test]
    fn a_dense_raster_stays_within_the_budget() {
        // 400 rows 0.01 mm apart, every move distinct: the grid coarsens
        // until the shapes fit, and short moves merge instead of vanishing.
        let mut d = Drawing::new(MachineKind::Mill);
        run(&mut d, &raster(400, 0.01, 1));
        d.flush();
        let p = &d.panels[0];
        assert!(p.shapes().len() <= MAX_SHAPES);
        assert!(p.quantum() > FIRST_QUANTUM);
        let xs = p.shapes().iter().flat_map(|s| [s.a.0, s.b.0]);
        let (lo, hi) = xs.fold((f64::MAX, f64::MIN), |(l, h), x| (l.min(x), h.max(x)));
        assert_eq!((lo, hi), (0.0, 100.0));
        let drawn: f64 = p.shapes().iter().map(|s| (s.b.0 - s.a.0).abs()).sum();
        assert!(drawn >= 100.0 * 4.0, "at least the rows' extent: {drawn}");
    }

    #[test]
    fn polar_moves_are_drawn_on_the_face() {
        // X20 C90 in G112 is the point (0, 20) on the face; X-10 C0 is
        // (-10, 0): a signed radius.
        let mut d = Drawing::new(MachineKind::Mill);
        let mut e = feed(1, 20.0, 0.0);
        let from = [20.0, 0.0, 0.0, 0.0, 0.0, 0.0];
        if let Canon::Feed { m, .. } = &mut e.cmd {
            m.to[5] = 90.0;
        }
        d.add(&e, &from, Rot::Polar);
        let s = d.panels[0].shapes()[0];
        assert!((s.a.0 - 20.0).abs() < 1e-12 && s.a.1.abs() < 1e-12);
        assert!(s.b.0.abs() < 1e-12 && (s.b.1 - 20.0).abs() < 1e-12);
        assert!(d.panels[0].polar);
    }

    #[test]
    fn g107_moves_are_unrolled_to_mm_on_their_cylinder() {
        // G18 on a 30 mm cylinder: Z0 C0 to Z10 C90 ends a quarter of the
        // circumference up, 2·π·30/4 = 47.1239 mm; in G17 C is across
        // and Y up.
        let mut d = Drawing::new(MachineKind::Mill);
        let mut e = feed(1, 0.0, 0.0);
        if let Canon::Feed { m, .. } = &mut e.cmd {
            m.to = [0.0, 0.0, 10.0, 0.0, 0.0, 90.0];
        }
        let zx = Rot::Cylinder {
            radius: 30.0,
            plane: Plane::ZX,
        };
        d.add(&e, &[0.0; 6], zx);
        let s = d.panels[1].shapes()[0];
        assert_eq!(s.a, (0.0, 0.0));
        assert!((s.b.0 - 10.0).abs() < 1e-12 && (s.b.1 - 47.123_889_8).abs() < 1e-6);
        assert_eq!(d.panels[1].view, View::DevZc);
        let xy = Rot::Cylinder {
            radius: 10.0,
            plane: Plane::XY,
        };
        e.cmd = feed(1, 0.0, 5.0).cmd;
        if let Canon::Feed { m, .. } = &mut e.cmd {
            m.to[5] = 180.0;
        }
        d.add(&e, &[0.0; 6], xy);
        let s = *d.panels[1].shapes().last().unwrap();
        // Half of a 10 mm cylinder: π·10 = 31.4159 mm across, Y5 up.
        assert!((s.b.0 - 31.415_926_5).abs() < 1e-6 && (s.b.1 - 5.0).abs() < 1e-12);
        assert_eq!(d.panels[1].view, View::DevCy);
        assert_eq!(d.panels[1].radius, Some((10.0, 30.0)));
    }

    #[test]
    fn an_alarm_before_any_motion_is_marked_where_the_tool_is() {
        // A lathe at X250 Z400 (work): the cross at view (Z, X).
        let mut d = Drawing::new(MachineKind::Lathe);
        d.mark_stop(
            "alarm PS0010 line 1".into(),
            &[250.0, 0.0, 400.0, 0.0, 0.0, 0.0],
        );
        let (panel, p, _) = d.stop.clone().unwrap();
        assert_eq!((panel, p), (0, (400.0, 250.0)));
        // After a motion, the motion's end.
        let mut d = Drawing::new(MachineKind::Mill);
        d.add(&feed(1, 5.0, 6.0), &[0.0; 6], Rot::Off);
        d.mark_stop("alarm".into(), &[1.0; 6]);
        assert_eq!(d.stop.unwrap().1, (5.0, 6.0));
    }

    #[test]
    fn an_arc_bounds_its_extreme_points() {
        // A CCW half circle from (10, 0) to (-10, 0) about the origin
        // reaches v = 10 at its top.
        let mut d = Drawing::new(MachineKind::Mill);
        let to = [-10.0, 0.0, 0.0, 0.0, 0.0, 0.0];
        let arc = Event {
            src: SrcRef::default(),
            tool: 1,
            cmd: Canon::Arc {
                m: Motion { to, mto: to },
                center: [0.0; 6],
                mcenter: [0.0; 6],
                dir: ArcDir::Ccw,
                plane: Plane::XY,
                turns: 0,
                feed: Feed::PerMin(100.0),
            },
            prog: None,
        };
        d.add(&arc, &[10.0, 0.0, 0.0, 0.0, 0.0, 0.0], Rot::Off);
        let (lo, hi) = d.panels[0].bounds().unwrap();
        assert_eq!((lo, hi), ((-10.0, 0.0), (10.0, 10.0)));
        match d.panels[0].shapes()[0].form {
            Form::Arc { sweep, .. } => assert!((sweep - PI).abs() < 1e-12),
            f => panic!("{f:?}"),
        }
    }
}
