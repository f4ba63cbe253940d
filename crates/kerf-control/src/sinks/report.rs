//! The run report (JSON): status, alarm, counts, lengths, bounding box of
//! cutting moves, final positions, tools, cycle time. Format: docs/formats.md.

use std::collections::BTreeMap;
use std::io::{self, Write};

use kerf_canon::{Alarm, Axis, Canon, Event, Motion, Pos, NAXES};
use kerf_interp::Interp;
use kerf_motion::Planner;
use serde::Serialize;

use crate::sink::{Context, Live, Sink, Timed};
use crate::warnings::Warning;

/// The report sink: gathers a [`Summary`] from the event stream and
/// writes the [`Document`] as pretty JSON at the end; the document stays
/// readable afterwards ([`Report::document`]) for a caller's own summary.
pub struct Report<W: Write> {
    out: W,
    summary: Summary,
    doc: Option<Document>,
    sim: Option<super::SimHandle>,
}

impl<W: Write> Report<W> {
    /// A report written onto `out` at the end of the run (`io::sink()`
    /// to keep it only in memory).
    pub fn new(out: W) -> Report<W> {
        Report {
            out,
            summary: Summary::new(&[]),
            doc: None,
            sim: None,
        }
    }

    /// Adds the `sim` section that a [`super::SimSink`] finishing before
    /// this sink leaves in `h`.
    pub fn with_sim(mut self, h: super::SimHandle) -> Report<W> {
        self.sim = Some(h);
        self
    }

    /// The report, once the run has finished.
    pub fn document(&self) -> Option<&Document> {
        self.doc.as_ref()
    }
}

impl<W: Write> Sink for Report<W> {
    fn name(&self) -> &str {
        "report"
    }

    fn start(&mut self, cx: &Context) -> io::Result<()> {
        self.summary = Summary::new(&super::axes_of(cx.interp.profile()));
        Ok(())
    }

    fn event(&mut self, e: &Event, from: &Pos, _cx: &Live) -> io::Result<()> {
        self.summary.event(e, from);
        Ok(())
    }

    fn timed(&mut self, t: &Timed, _cx: &Live) -> io::Result<()> {
        self.summary.timed(t);
        Ok(())
    }

    fn finish(&mut self, cx: &Context, alarm: Option<&Alarm>) -> io::Result<()> {
        let mut doc = self.summary.finish(cx.interp, cx.planner, alarm);
        doc.warnings = cx.warnings.iter().map(WarningOut::from).collect();
        doc.sim = self.sim.as_ref().and_then(|h| h.borrow().clone());
        let text = serde_json::to_string_pretty(&doc).map_err(io::Error::other)?;
        self.doc = Some(doc);
        self.out.write_all(text.as_bytes())?;
        self.out.write_all(b"\n")?;
        self.out.flush()
    }
}

/// Accumulates what the report needs while the run streams past.
pub struct Summary {
    axes: Vec<Axis>,
    motions: u64,
    bbox: Option<(Pos, Pos)>,
    /// The end of the last motion when it was a cutting move (already in
    /// the box); NaN otherwise (a NaN start adds nothing to a box either).
    last_cut_to: Pos,
    tools: Vec<u32>,
    /// Cutting seconds per tool, in the order tools first cut.
    cutting: Vec<(u32, f64)>,
    messages: Vec<MessageOut>,
}

/// Most operator messages kept in a report.
const MAX_MESSAGES: usize = 10_000;

/// One operator message (`Canon::Message`: #3006, Hurco probe records,
/// thread start angles) with its source line.
#[derive(Clone, Debug, Serialize)]
pub struct MessageOut {
    /// Source line of the block.
    pub line: u32,
    /// The text.
    pub text: String,
}

/// The alarm that stopped the run.
#[derive(Clone, Debug, Serialize)]
pub struct AlarmOut {
    /// Alarm code (`F_82007` …).
    pub code: String,
    /// Message.
    pub message: String,
    /// File, line and column of the block.
    pub file: String,
    /// 1-based line.
    pub line: u32,
    /// 1-based column.
    pub col: u32,
}

/// One warning (`KERF-W001` …, docs/alarms.md "Warnings").
#[derive(Clone, Debug, Serialize)]
pub struct WarningOut {
    /// Warning code.
    pub code: String,
    /// Message.
    pub message: String,
    /// File of the block.
    pub file: String,
    /// 1-based line.
    pub line: u32,
    /// 1-based column (0: the whole file).
    pub col: u32,
}

impl From<&Warning> for WarningOut {
    fn from(w: &Warning) -> WarningOut {
        WarningOut {
            code: w.code.to_string(),
            message: w.message.clone(),
            file: w.file.clone(),
            line: w.line,
            col: w.col,
        }
    }
}

/// Bounding box of the cutting moves, work coordinates.
#[derive(Clone, Debug, Serialize)]
pub struct BBox {
    /// Smallest coordinate per axis.
    pub min: BTreeMap<&'static str, f64>,
    /// Largest coordinate per axis.
    pub max: BTreeMap<&'static str, f64>,
}

/// Positions at the end of the run.
#[derive(Clone, Debug, Serialize)]
pub struct Final {
    /// Work coordinates.
    pub work: BTreeMap<&'static str, f64>,
    /// Machine coordinates.
    pub machine: BTreeMap<&'static str, f64>,
}

/// The planned time by category, s.
#[derive(Clone, Debug, Serialize)]
pub struct TimeOut {
    /// Rapids with their settling.
    pub rapid: f64,
    /// Feeds, arcs and threads with their settling.
    pub cutting: f64,
    /// Dwells.
    pub dwell: f64,
    /// Tool changes and turret indexing.
    pub tool_change: f64,
    /// Spindle ramps and M/S/T handshakes.
    pub other: f64,
}

/// Cutting time of one tool.
#[derive(Clone, Debug, Serialize)]
pub struct ToolTime {
    /// Tool number (0: no tool selected).
    pub tool: u32,
    /// Seconds of feeds, arcs and threads with this tool.
    pub cutting_s: f64,
}

/// The report document (docs/formats.md "Report").
#[derive(Clone, Debug, Serialize)]
pub struct Document {
    /// `completed` or `alarm`.
    pub status: &'static str,
    /// The alarm, if any.
    pub alarm: Option<AlarmOut>,
    /// Blocks executed.
    pub blocks: u64,
    /// Motion events.
    pub motions: u64,
    /// Cutting path length, mm.
    pub feed_length_mm: f64,
    /// Rapid path length, mm.
    pub rapid_length_mm: f64,
    /// Bounding box of the cutting moves.
    pub bbox: Option<BBox>,
    /// Final positions.
    #[serde(rename = "final")]
    pub final_: Final,
    /// Tools used, in order.
    pub tools: Vec<u32>,
    /// Cutting time per tool, in the order the tools first cut.
    pub tool_times: Vec<ToolTime>,
    /// Operator messages (the first 10,000).
    pub messages: Vec<MessageOut>,
    /// Warnings, in the order found.
    pub warnings: Vec<WarningOut>,
    /// Planned cycle time, s.
    pub cycle_time_s: f64,
    /// The cycle time by category.
    pub time_s: TimeOut,
    /// The simulation (`--stock` only).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub sim: Option<super::sim::SimOut>,
}

fn r6(v: f64) -> f64 {
    let r = (v * 1e6).round() / 1e6;
    if r == 0.0 {
        0.0
    } else {
        r
    }
}

impl Summary {
    /// An empty summary for a machine with these axes.
    pub fn new(axes: &[Axis]) -> Summary {
        Summary {
            axes: axes.to_vec(),
            motions: 0,
            bbox: None,
            last_cut_to: [f64::NAN; NAXES],
            tools: Vec::new(),
            cutting: Vec::new(),
            messages: Vec::new(),
        }
    }

    /// Takes one event starting at work position `from`: motions, tools,
    /// operator messages.
    pub fn event(&mut self, e: &Event, from: &Pos) {
        if let Some(m) = e.motion() {
            self.motion(e, from, m);
        }
        match &e.cmd {
            Canon::Tool { tool, .. } => self.tool(*tool),
            Canon::Message(text) => self.message(e.src.line, text),
            _ => {}
        }
    }

    /// Counts a motion; cutting moves grow the bounding box (work coordinates).
    pub fn motion(&mut self, e: &Event, from: &Pos, m: &Motion) {
        self.motions += 1;
        let cutting = matches!(
            e.cmd,
            Canon::Feed { .. } | Canon::Arc { .. } | Canon::Thread { .. }
        );
        if !cutting {
            self.last_cut_to = [f64::NAN; NAXES];
            return;
        }
        // A line's box is its two ends, and a start that ended the last
        // cutting move (the same bits) is in the box already: a point
        // added twice changes no minimum or maximum. The points are added
        // in the order start, end, an arc's two corners.
        let same = from
            .iter()
            .zip(&self.last_cut_to)
            .all(|(a, b)| a.to_bits() == b.to_bits());
        if !same {
            self.add(from);
        }
        self.add(&m.to);
        if let Canon::Arc {
            center, plane, dir, ..
        } = &e.cmd
        {
            let (a1, a2, _) = plane.axes();
            let (u0, v0, u1, v1) = kerf_canon::geom::bbox(
                (from[a1], from[a2]),
                (m.to[a1], m.to[a2]),
                (center[a1], center[a2]),
                matches!(dir, kerf_canon::ArcDir::Ccw),
            );
            let (mut c0, mut c1) = (m.to, m.to);
            c0[a1] = u0;
            c0[a2] = v0;
            c1[a1] = u1;
            c1[a2] = v1;
            self.add(&c0);
            self.add(&c1);
        }
        self.last_cut_to = m.to;
    }

    /// Grows the box to take in `p`.
    #[inline]
    fn add(&mut self, p: &Pos) {
        let b = self.bbox.get_or_insert((*p, *p));
        for (i, v) in p.iter().enumerate() {
            b.0[i] = b.0[i].min(*v);
            b.1[i] = b.1[i].max(*v);
        }
    }

    /// Adds a cutting record's time to its tool.
    pub fn timed(&mut self, t: &Timed) {
        if !matches!(
            t.event.cmd,
            Canon::Feed { .. } | Canon::Arc { .. } | Canon::Thread { .. }
        ) {
            return;
        }
        let tool = t.event.tool;
        match self.cutting.iter_mut().find(|(n, _)| *n == tool) {
            Some((_, s)) => *s += t.time,
            None => self.cutting.push((tool, t.time)),
        }
    }

    /// Records an operator message (the first 10,000).
    pub fn message(&mut self, line: u32, text: &str) {
        if self.messages.len() < MAX_MESSAGES {
            self.messages.push(MessageOut {
                line,
                text: text.to_string(),
            });
        }
    }

    /// Records a tool used.
    pub fn tool(&mut self, t: u32) {
        if t != 0 && !self.tools.contains(&t) {
            self.tools.push(t);
        }
    }

    fn map(&self, p: &Pos) -> BTreeMap<&'static str, f64> {
        self.axes
            .iter()
            .map(|a| (a.name(), r6(p[*a as usize])))
            .collect()
    }

    /// The report.
    pub fn finish(&self, it: &Interp, est: &Planner, alarm: Option<&Alarm>) -> Document {
        Document {
            status: if alarm.is_some() {
                "alarm"
            } else {
                "completed"
            },
            alarm: alarm.map(|a| AlarmOut {
                code: a.code.clone(),
                message: a.message.clone(),
                file: it.file_name(a.src.file).to_string(),
                line: a.src.line,
                col: a.src.col,
            }),
            blocks: it.blocks(),
            motions: self.motions,
            feed_length_mm: r6(est.feed_length),
            rapid_length_mm: r6(est.rapid_length),
            bbox: self.bbox.map(|(lo, hi)| BBox {
                min: self.map(&lo),
                max: self.map(&hi),
            }),
            final_: Final {
                work: self.map(&it.work_position()),
                machine: self.map(&it.machine_position()),
            },
            tools: self.tools.clone(),
            tool_times: self
                .cutting
                .iter()
                .map(|&(tool, t)| ToolTime {
                    tool,
                    cutting_s: r6(t),
                })
                .collect(),
            messages: self.messages.clone(),
            warnings: Vec::new(),
            cycle_time_s: r6(est.now()),
            time_s: TimeOut {
                rapid: r6(est.time.rapid),
                cutting: r6(est.time.cutting),
                dwell: r6(est.time.dwell),
                tool_change: r6(est.time.tool_change),
                other: r6(est.time.other),
            },
            sim: None,
        }
    }
}
