//! The simulation: canonical events in, the stock model updated move by
//! move, crash events and volumes out.

use std::collections::BTreeSet;

use kerf_canon::{Canon, Event, Pos, SpindleDir, SrcRef};

use crate::envelope::Sweep;
use crate::events::{EventKind, SimEvent, SimReport};
use crate::holder::holder_first;
use crate::hull::{Hull, Pt};
use crate::lathe::{ccw, swept_ccw, Contour, Section};
use crate::lathe_tool::cutting_outline;
use crate::path::chords;
use crate::stock::Stock;
use crate::tool::{LatheTool, MillTool, Tool, ToolTable};
use crate::zmap::{ResolutionError, ZMap};

/// Events kept in the report; later ones are counted only.
pub const MAX_EVENTS: usize = 1000;
/// Radius of the flat end mill used for a tool whose D offset is 0, mm.
pub const FALLBACK_RADIUS: f64 = 5.0;
/// Chord tolerance of arcs on the lathe, mm.
pub const ARC_TOL_LATHE: f64 = 0.5e-3;
/// Bisection steps locating a first contact (2^-30 of the move).
const BISECT: usize = 30;

/// The stock model.
pub enum Model {
    /// Machining center height field.
    Mill(ZMap),
    /// Lathe half section.
    Lathe(Section),
}

/// The tool in use, with its derived geometry.
enum Current {
    Mill(MillTool),
    /// The outlines' convex hulls, counter-clockwise.
    Lathe {
        outline: Contour,
        holder: Contour,
    },
}

/// The simulation of one run.
pub struct Sim {
    stock: Stock,
    model: Model,
    tools: ToolTable,
    spindle_on: bool,
    offset: u32,
    current: Option<(u32, u32, Current)>,
    unknown: BTreeSet<u32>,
    events: Vec<SimEvent>,
    dropped: u64,
    collisions: u64,
    removed: f64,
    t_prev: f64,
    chords: Vec<[f64; 3]>,
    undo: Vec<(u32, f32)>,
    region: Contour,
    res: f64,
    rapid_rates: Option<[f64; 3]>,
}

impl Sim {
    /// A simulation of `stock` with `tools`; `res` the cell size (mill) or
    /// column width (lathe), mm, or None for the default.
    pub fn new(stock: Stock, tools: ToolTable, res: Option<f64>) -> Result<Sim, ResolutionError> {
        if let Some(r) = res {
            if !(r.is_finite() && (0.001..=10.0).contains(&r)) {
                return Err(ResolutionError::OutOfRange { res: r });
            }
        }
        let (model, res) = match stock {
            Stock::Box { min, max } => {
                let r = res.unwrap_or_else(|| ZMap::default_res(max[0] - min[0], max[1] - min[1]));
                let z = ZMap::new(min, max, r)?;
                let res = z.grid.dx.max(z.grid.dy);
                (Model::Mill(z), res)
            }
            Stock::Turn {
                r_out,
                r_in,
                z_face,
                z_end,
            } => {
                // The section is exact; its resolution is the arcs' chord
                // tolerance, whatever --sim-res says.
                let s = Section::new(r_in, r_out, z_end, z_face);
                (Model::Lathe(s), ARC_TOL_LATHE)
            }
        };
        Ok(Sim {
            stock,
            model,
            tools,
            spindle_on: false,
            offset: 0,
            current: None,
            unknown: BTreeSet::new(),
            events: Vec::new(),
            dropped: 0,
            collisions: 0,
            removed: 0.0,
            t_prev: 0.0,
            chords: Vec::new(),
            undo: Vec::new(),
            region: Vec::new(),
            res,
            rapid_rates: None,
        })
    }

    /// The X Y Z rapid rates (mm/min): a non-linear rapid is then
    /// simulated along its dog-leg, each axis at its own rate.
    pub fn set_rapid_rates(&mut self, rates: [f64; 3]) {
        self.rapid_rates = Some(rates);
    }

    /// Replaces the offsets the tools without geometry are simulated from.
    pub fn set_offsets(&mut self, o: crate::tool::OffsetData) {
        self.tools.offsets = o;
        self.current = None;
    }

    /// The stock model (for the STL and the picture), after every move
    /// so far.
    pub fn model(&self) -> &Model {
        self.settle();
        &self.model
    }

    /// The stock.
    pub fn stock(&self) -> &Stock {
        &self.stock
    }

    /// One canonical event. `start` is the work position before it; `t`
    /// the machine time at its end (for a motion or dwell), s.
    pub fn event(&mut self, e: &Event, start: &Pos, t: f64) {
        match &e.cmd {
            Canon::Spindle { dir, .. } => self.spindle_on = *dir != SpindleDir::Stop,
            Canon::Tool { offset, .. } => self.offset = *offset,
            Canon::Dwell { .. } => self.t_prev = self.t_prev.max(t),
            _ => {}
        }
        if e.motion().is_none() {
            return;
        }
        let rapid = matches!(e.cmd, Canon::Rapid { .. });
        // Chord tolerance: 0.5 µm on the lathe (its profile is exact),
        // a quarter cell (at most 1 µm) on the height field.
        let tol = match self.model {
            Model::Lathe(_) => ARC_TOL_LATHE,
            Model::Mill(_) => (self.res / 4.0).min(1e-3),
        };
        let mut pts = std::mem::take(&mut self.chords);
        match (&e.cmd, self.rapid_rates) {
            (Canon::Rapid { m, linear: false }, Some(rates)) => {
                pts.clear();
                let corners = kerf_geom::stroke::dogleg(start, &m.to, rates);
                pts.extend(corners.iter().skip(1).map(|p| [p[0], p[1], p[2]]));
            }
            _ => chords(&e.cmd, start, tol, &mut pts),
        }
        let mut p = [start[0], start[1], start[2]];
        let total: f64 = {
            let mut q = p;
            pts.iter()
                .map(|n| {
                    let d = dist(&q, n);
                    q = *n;
                    d
                })
                .sum()
        };
        let (t0, t1) = (self.t_prev, t.max(self.t_prev));
        let mut done = 0.0;
        for &n in &pts {
            let d = dist(&p, &n);
            let f = |x: f64| {
                if total > 0.0 {
                    t0 + (t1 - t0) * x / total
                } else {
                    t1
                }
            };
            let span = (f(done), f(done + d));
            self.segment(e, p, n, rapid, span);
            done += d;
            p = n;
        }
        self.chords = pts;
        self.t_prev = t1;
    }

    fn segment(&mut self, e: &Event, p0: [f64; 3], p1: [f64; 3], rapid: bool, t: (f64, f64)) {
        self.prepare_tool(e, p0, t.0);
        match &self.model {
            Model::Mill(_) => self.mill_segment(e.src, e.tool, p0, p1, rapid, t),
            Model::Lathe(_) => self.lathe_segment(e.src, e.tool, p0, p1, rapid, t),
        }
    }

    /// Makes `current` the tool of `e`, reporting a tool without geometry.
    fn prepare_tool(&mut self, e: &Event, at: [f64; 3], t: f64) {
        let key = (e.tool, self.offset);
        if matches!(&self.current, Some((n, o, _)) if (*n, *o) == key) {
            return;
        }
        let lathe = matches!(self.model, Model::Lathe(_));
        let known = self.tools.tools.get(&e.tool).cloned();
        let cur = match (known, lathe) {
            (Some(Tool::Mill(m)), false) => Current::Mill(m),
            (Some(Tool::Lathe(l)), true) => lathe_current(&l),
            (_, false) => {
                self.report_unknown(e, at, t);
                let r = self
                    .tools
                    .offsets
                    .radius
                    .get(&e.tool)
                    .copied()
                    .unwrap_or(0.0);
                Current::Mill(MillTool::flat(if r > 0.0 { r } else { FALLBACK_RADIUS }))
            }
            (_, true) => {
                self.report_unknown(e, at, t);
                let (r, tip) = self
                    .tools
                    .offsets
                    .nose
                    .get(&self.offset)
                    .copied()
                    .unwrap_or((0.0, 3));
                lathe_current(&LatheTool::from_offset(r.max(0.0), tip))
            }
        };
        self.current = Some((key.0, key.1, cur));
    }

    fn report_unknown(&mut self, e: &Event, at: [f64; 3], t: f64) {
        if self.unknown.insert(e.tool) {
            self.push(EventKind::ToolUnknown, e.src, e.tool, t, at, 0.0);
        }
    }

    fn push(&mut self, kind: EventKind, src: SrcRef, tool: u32, t: f64, at: [f64; 3], vol: f64) {
        if kind.is_collision() {
            if let Some(last) = self.events.last_mut() {
                if last.kind == kind && last.file == src.file && last.line == src.line {
                    last.volume_mm3 += vol;
                    return;
                }
            }
            self.collisions += 1;
        }
        if self.events.len() >= MAX_EVENTS {
            self.dropped += 1;
            return;
        }
        self.events.push(SimEvent {
            kind,
            file: src.file,
            line: src.line,
            t,
            at,
            volume_mm3: vol,
            tool,
        });
    }

    fn mill_segment(
        &mut self,
        src: SrcRef,
        tool_no: u32,
        p0: [f64; 3],
        p1: [f64; 3],
        rapid: bool,
        t: (f64, f64),
    ) {
        let (Model::Mill(z), Some((_, _, Current::Mill(tool)))) = (&mut self.model, &self.current)
        else {
            return;
        };
        let s = Sweep::new(p0, p1);
        let descends = p1[2] < p0[2] - crate::zmap::EPS;
        // The old heights are kept only when the move can be an event (its
        // first contact is then located on the stock before the move).
        let may_collide = rapid
            || !self.spindle_on
            || (descends && !tool.centre_cutting)
            || tool.flute_length < 1.0e4;
        if !may_collide {
            // No event: the move may be cut later on the worker's bands.
            z.cut_queued(tool, &s);
            return;
        }
        let centre_before = z.height_at(p1[0], p1[1]);
        self.undo.clear();
        let cut = z.cut(tool, &s, true, Some(&mut self.undo));
        let mut found: Vec<(EventKind, f64)> = Vec::new();
        if cut.removed > 0.0 {
            if rapid {
                found.push((EventKind::RapidIntoStock, cut.removed));
            } else if !self.spindle_on {
                found.push((EventKind::SpindleOffCut, cut.removed));
            }
            let plunge = descends && centre_before.is_some_and(|h| h > p1[2] + z.tol);
            if !tool.centre_cutting && plunge {
                found.push((EventKind::PlungeNonCentreCutting, cut.removed));
            }
        }
        if cut.holder > 0.0 {
            found.push((EventKind::HolderCollision, cut.holder));
        }
        z.add_removed(cut.removed);
        if found.is_empty() {
            return;
        }
        // Locate the first contact on the stock as it was before the move.
        z.restore(&mut self.undo);
        let mut located = Vec::new();
        for (kind, vol) in found {
            let holder = kind == EventKind::HolderCollision;
            let f = first_contact(|f| {
                let c = z.cut(tool, &Sweep::new(p0, lerp(&p0, &p1, f)), false, None);
                if holder {
                    c.holder > 0.0
                } else {
                    c.removed > 0.0
                }
            });
            located.push((kind, vol, f));
        }
        z.cut(tool, &s, true, None);
        for (kind, vol, f) in located {
            let at = lerp(&p0, &p1, f);
            self.push(kind, src, tool_no, t.0 + (t.1 - t.0) * f, at, vol);
        }
    }

    fn lathe_segment(
        &mut self,
        src: SrcRef,
        tool_no: u32,
        p0: [f64; 3],
        p1: [f64; 3],
        rapid: bool,
        t: (f64, f64),
    ) {
        let (Model::Lathe(sec), Some((_, _, Current::Lathe { outline, holder }))) =
            (&mut self.model, &self.current)
        else {
            return;
        };
        let (a, b) = ((p0[2], p0[0]), (p1[2], p1[0]));
        let at = |f: f64| (a.0 + (b.0 - a.0) * f, a.1 + (b.1 - a.1) * f);
        let mut found: Vec<(EventKind, f64, f64)> = Vec::new();
        let region = &mut self.region;
        // The volume removed (write) or the material met (a check).
        let mut sweep_of = |sec: &mut Section, shape: &[[f64; 2]], f: f64, write: bool| {
            swept_ccw(shape, a, at(f), region);
            let r = std::slice::from_ref(region);
            if write {
                sec.sweep_regions(r, true)
            } else {
                sec.meets(r)
            }
        };
        // Every check is against the stock before the move: the pending
        // cut is applied first where it may change what the check reads
        // (Section::sweep_regions), and a move retracing the pending cut's
        // open run meets nothing.
        let mut event_cut = false;
        if (rapid || !self.spindle_on) && !sec.covered_later(outline, a, b) {
            let v = sweep_of(sec, outline, 1.0, false);
            if v > 0.0 {
                let kind = if rapid {
                    EventKind::RapidIntoStock
                } else {
                    EventKind::SpindleOffCut
                };
                let f = first_contact(|f| sweep_of(sec, outline, f, false) > 0.0);
                found.push((kind, v, f));
                event_cut = true;
            }
        }
        // The holder along the whole move: what it reaches before the
        // insert has cut it (holder.rs). It is first measured against the
        // stock without the pending cut, which holds at least the
        // material (nothing there, nothing after it).
        let mut holder_hit = false;
        if !holder.is_empty() {
            let met_region = |f: f64| holder_first(&pts(outline), &pts(holder), a, at(f));
            let whole = met_region(1.0);
            if sec.meets_unsettled(&whole) > 0.0 {
                let v = sec.meets(&whole);
                if v > 0.0 {
                    let f = first_contact(|f| sec.meets(&met_region(f)) > 0.0);
                    found.push((EventKind::HolderCollision, v, f));
                    holder_hit = true;
                }
            }
        }
        if event_cut || holder_hit {
            // An event's move is cut at once, with what the holder met.
            self.removed += sweep_of(sec, outline, 1.0, true);
            if holder_hit {
                self.removed += sweep_of(sec, holder, 1.0, true);
            }
        } else if !rapid && self.spindle_on {
            sec.cut_later(outline, a, b);
        }
        for (kind, vol, f) in found {
            let at = lerp(&p0, &p1, f);
            self.push(kind, src, tool_no, t.0 + (t.1 - t.0) * f, at, vol);
        }
    }

    /// Whether the lathe merges consecutive feed moves into one swept
    /// region and removes several moves' regions in one boolean (true,
    /// the default; deferred.rs), or removes each move on its own (the
    /// move-by-move path, the reference the tests compare it with).
    pub fn set_lathe_merging(&mut self, on: bool) {
        if let Model::Lathe(s) = &mut self.model {
            s.set_merge(on);
        }
    }

    /// Threads the height field is cut by (1 or 2; the default is 2 on a
    /// machine with two cores or more, or `KERF_SIM_THREADS`; pipe.rs).
    /// The result is the same either way. Before the first move.
    pub fn set_threads(&mut self, n: usize) {
        if let Model::Mill(z) = &mut self.model {
            z.settle();
            z.threads = n.clamp(1, 2);
        }
    }

    /// The length in moves of the queue the second thread of the height
    /// field is handed its moves through (pipe.rs; tests make it short).
    /// Before the first move.
    pub fn set_queue(&mut self, moves: usize) {
        if let Model::Mill(z) = &mut self.model {
            z.queue = moves.max(1);
        }
    }

    /// Applies the pending cut: the lathe's, or the height field's queued
    /// moves (every read of the model does so itself; this is for timing a
    /// run to its end).
    pub fn settle(&self) {
        match &self.model {
            Model::Lathe(s) => s.settle(),
            Model::Mill(z) => z.settle(),
        }
    }

    /// Volumes and events so far.
    pub fn report(&self) -> SimReport {
        let remaining = match &self.model {
            Model::Mill(z) => z.volume(),
            Model::Lathe(s) => s.volume(),
        };
        // The height field's moves add to its own total (in program
        // order, whichever thread cut them).
        let removed = match &self.model {
            Model::Mill(z) => z.removed(),
            Model::Lathe(s) => self.removed + s.removed_later(),
        };
        SimReport {
            stock_mm3: self.stock.volume(),
            removed_mm3: removed,
            remaining_mm3: remaining,
            resolution_mm: self.res,
            events: self.events.clone(),
            events_dropped: self.dropped,
            collisions: self.collisions,
        }
    }
}

fn lathe_current(t: &LatheTool) -> Current {
    let hull = |pts: &[Pt]| {
        if pts.is_empty() {
            return Vec::new();
        }
        let mut p = pts.to_vec();
        let mut h = Hull::default();
        Hull::of(&mut p, &mut h);
        ccw(&h)
    };
    Current::Lathe {
        outline: hull(&cutting_outline(t)),
        holder: hull(&t.holder),
    }
}

/// A contour as points.
fn pts(c: &[[f64; 2]]) -> Vec<Pt> {
    c.iter().map(|p| (p[0], p[1])).collect()
}

fn dist(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    ((b[0] - a[0]).powi(2) + (b[1] - a[1]).powi(2) + (b[2] - a[2]).powi(2)).sqrt()
}

fn lerp(a: &[f64; 3], b: &[f64; 3], f: f64) -> [f64; 3] {
    [
        a[0] + (b[0] - a[0]) * f,
        a[1] + (b[1] - a[1]) * f,
        a[2] + (b[2] - a[2]) * f,
    ]
}

/// The least fraction of a move at which `touches` (monotone: once true,
/// true for every longer part of the move) becomes true.
fn first_contact(mut touches: impl FnMut(f64) -> bool) -> f64 {
    let (mut lo, mut hi) = (0.0, 1.0);
    for _ in 0..BISECT {
        let m = 0.5 * (lo + hi);
        if touches(m) {
            hi = m;
        } else {
            lo = m;
        }
    }
    hi
}
