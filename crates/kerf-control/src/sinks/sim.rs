//! The simulation sink (`--stock`): feeds kerf-sim every canonical
//! command in execution order with the time its motion ends, writes the
//! STL and the PNG at the end, and leaves the report's `sim` section in a
//! [`SimHandle`] that the report sink and the caller read.
//!
//! Motions get their end time only when the planner has fixed it
//! ([`Sink::timed`]), so the commands between two motions (spindle, tool)
//! wait in a queue bounded by the planner's look-ahead window.

use std::cell::RefCell;
use std::collections::VecDeque;
use std::io::{self, Write};
use std::rc::Rc;

use kerf_canon::{Alarm, Canon, Event, Pos};
use kerf_interp::machine::MachineKind;
use kerf_interp::{Interp, Profile};
use kerf_sim::{render, stl, OffsetData, Sim, SimReport, Stock, ToolTable};
use serde::Serialize;

use crate::sink::{Context, Live, Sink, Timed};

/// One simulation event in the report.
#[derive(Clone, Debug, Serialize)]
pub struct SimEventOut {
    /// `rapid_into_stock`, `holder_collision`, `spindle_off_cut`,
    /// `plunge_non_centre_cutting` or `tool_unknown`.
    pub kind: &'static str,
    /// File and 1-based line of the block.
    pub file: String,
    pub line: u32,
    /// Machine time, s.
    pub t: f64,
    /// Tool tip at the first contact, work coordinates (lathe X a radius).
    pub at: [f64; 3],
    /// Material involved, mm³.
    pub volume_mm3: f64,
    /// Tool number.
    pub tool: u32,
}

/// The report's `sim` section (docs/formats.md).
#[derive(Clone, Debug, Serialize)]
pub struct SimOut {
    pub stock_mm3: f64,
    pub removed_mm3: f64,
    pub remaining_mm3: f64,
    pub resolution_mm: f64,
    /// Collision events found (kept in `events` or not).
    pub collisions: u64,
    pub events: Vec<SimEventOut>,
    /// Events past the first 1,000, counted only.
    pub events_dropped: u64,
}

/// Where the sim sink leaves its section for the report and the caller.
pub type SimHandle = Rc<RefCell<Option<SimOut>>>;

/// The simulation sink.
pub struct SimSink {
    sim: Sim,
    /// Motions and dwells seen by `event`, and handed to the sim.
    seen: u64,
    done: u64,
    /// Commands waiting for the motion before them: (motions seen before, event, from).
    queue: VecDeque<(u64, Event, Pos)>,
    t: f64,
    stl: Option<Box<dyn Write>>,
    png: Option<Box<dyn Write>>,
    out: SimHandle,
}

fn timed_kind(e: &Event) -> bool {
    e.motion().is_some() || matches!(e.cmd, Canon::Dwell { .. })
}

/// A `--stock` that does not fit the machine (kerf_sim::StockError is one
/// that does not parse).
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum StockFitError {
    /// A box side outside the X or Y travel (machine coordinates at the
    /// first work offset).
    #[error("--stock: {axis} {min}..{max} is machine {lo}..{hi}, outside the {axis} travel {travel_min}..{travel_max}")]
    Travel {
        /// `X` or `Y`.
        axis: String,
        /// The box side as given (work coordinates).
        min: f64,
        max: f64,
        /// The same in machine coordinates.
        lo: f64,
        hi: f64,
        /// The axis travel.
        travel_min: f64,
        travel_max: f64,
    },
    /// A bar or tube wider than the lathe's X travel allows.
    #[error(
        "--stock: diameter {diameter} is more than the X travel allows ({radius} mm of radius)"
    )]
    Diameter { diameter: f64, radius: f64 },
    /// A box on a lathe (`machine` names it).
    #[error("--stock box: is a machining center stock; {0} is a lathe (bar: or tube:)")]
    BoxOnLathe(String),
    /// A bar or tube on a machining center.
    #[error("--stock bar:/tube: is a lathe stock; {0} is a machining center (box:)")]
    TurnOnMill(String),
}

/// Checks that the stock suits the machine: a box on the machining
/// center, within the X/Y travel at the first work offset; a bar or tube
/// on a lathe, its radius within the X travel.
pub fn check_stock(stock: &Stock, p: &Profile) -> Result<(), StockFitError> {
    match (stock, p.kind) {
        (Stock::Box { min, max }, MachineKind::Mill) => {
            let origin = p.work_offsets.values().next();
            for (i, name) in [(0, "x"), (1, "y")] {
                let (Some(ax), o) = (
                    p.axes.get(name),
                    origin.and_then(|w| w.get(name)).copied().unwrap_or(0.0),
                ) else {
                    continue;
                };
                let (lo, hi) = (min[i] + o, max[i] + o);
                if lo < ax.min - 1e-9 || hi > ax.max + 1e-9 {
                    return Err(StockFitError::Travel {
                        axis: name.to_uppercase(),
                        min: min[i],
                        max: max[i],
                        lo,
                        hi,
                        travel_min: ax.min,
                        travel_max: ax.max,
                    });
                }
            }
            Ok(())
        }
        (Stock::Turn { r_out, .. }, MachineKind::Lathe) => match p.axes.get("x") {
            Some(ax) if 2.0 * r_out > 2.0 * (ax.max - ax.min) => Err(StockFitError::Diameter {
                diameter: 2.0 * r_out,
                radius: ax.max - ax.min,
            }),
            _ => Ok(()),
        },
        (Stock::Box { .. }, MachineKind::Lathe) => Err(StockFitError::BoxOnLathe(p.name.clone())),
        (Stock::Turn { .. }, MachineKind::Mill) => Err(StockFitError::TurnOnMill(p.name.clone())),
    }
}

/// The offsets a tool without geometry is simulated from.
pub fn offset_data(it: &Interp) -> OffsetData {
    let t = it.offsets();
    let mut o = OffsetData::default();
    for n in 1..=t.count() {
        let d = t.d(n);
        if d != 0.0 {
            o.radius.insert(n as u32, d);
        }
        let l = t.lathe(n);
        o.nose.insert(n as u32, (l.total_r(), l.tip));
    }
    o
}

impl SimSink {
    /// A simulation of `stock` with `tools` (the offsets are read at the
    /// start of the run) at cell size `res`; `stl`/`png` written at the end.
    pub fn new(
        stock: Stock,
        tools: ToolTable,
        res: Option<f64>,
        stl: Option<Box<dyn Write>>,
        png: Option<Box<dyn Write>>,
    ) -> Result<SimSink, kerf_sim::ResolutionError> {
        Ok(SimSink {
            sim: Sim::new(stock, tools, res)?,
            seen: 0,
            done: 0,
            queue: VecDeque::new(),
            t: 0.0,
            stl,
            png,
            out: Rc::new(RefCell::new(None)),
        })
    }

    /// The simulation (its stock model after the run).
    pub fn sim(&self) -> &Sim {
        &self.sim
    }

    /// The handle the `sim` section will be in after the run.
    pub fn handle(&self) -> SimHandle {
        self.out.clone()
    }

    /// Feeds the queued commands that follow the motions done so far.
    fn flush_queue(&mut self) {
        while let Some((before, _, _)) = self.queue.front() {
            if *before > self.done {
                break;
            }
            let (_, e, from) = self.queue.pop_front().expect("front");
            self.sim.event(&e, &from, self.t);
        }
    }

    fn section(r: &SimReport, cx: &Context) -> SimOut {
        SimOut {
            stock_mm3: r6(r.stock_mm3),
            removed_mm3: r6(r.removed_mm3),
            remaining_mm3: r6(r.remaining_mm3),
            resolution_mm: r6(r.resolution_mm),
            collisions: r.collisions,
            events: r
                .events
                .iter()
                .map(|e| SimEventOut {
                    kind: e.kind.name(),
                    file: cx.file(e.file).to_string(),
                    line: e.line,
                    t: r6(e.t),
                    at: e.at.map(r6),
                    volume_mm3: r6(e.volume_mm3),
                    tool: e.tool,
                })
                .collect(),
            events_dropped: r.events_dropped,
        }
    }
}

fn r6(v: f64) -> f64 {
    let r = (v * 1e6).round() / 1e6;
    if r == 0.0 {
        0.0
    } else {
        r
    }
}

impl Sink for SimSink {
    fn name(&self) -> &str {
        "sim"
    }

    fn start(&mut self, cx: &Context) -> io::Result<()> {
        self.sim.set_offsets(offset_data(cx.interp));
        let axes = &cx.interp.profile().axes;
        let rate = |n: &str| axes.get(n).map_or(0.0, |a| a.rapid);
        self.sim.set_rapid_rates([rate("x"), rate("y"), rate("z")]);
        Ok(())
    }

    fn event(&mut self, e: &Event, from: &Pos, _cx: &Live) -> io::Result<()> {
        if timed_kind(e) {
            self.seen += 1;
        } else if self.seen == self.done {
            self.sim.event(e, from, self.t);
        } else {
            self.queue.push_back((self.seen, e.clone(), *from));
        }
        Ok(())
    }

    fn timed(&mut self, t: &Timed, _cx: &Live) -> io::Result<()> {
        self.t = t.t_end;
        self.sim.event(t.event, &t.from, t.t_end);
        self.done += 1;
        self.flush_queue();
        Ok(())
    }

    fn finish(&mut self, cx: &Context, _alarm: Option<&Alarm>) -> io::Result<()> {
        self.done = u64::MAX;
        self.flush_queue();
        if let Some(w) = self.stl.as_mut() {
            stl::write(&self.sim, w.as_mut())?;
            w.flush()?;
        }
        if let Some(w) = self.png.as_mut() {
            render::render(&self.sim).write_png(w.as_mut())?;
            w.flush()?;
        }
        *self.out.borrow_mut() = Some(Self::section(&self.sim.report(), cx));
        Ok(())
    }
}
