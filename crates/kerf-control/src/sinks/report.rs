//! The run report (JSON): status, alarm, counts, lengths, bounding box of
//! cutting moves, final positions, tools, cycle time. Format: docs/formats.md.

use std::collections::BTreeMap;
use std::io::{self, Write};

use kerf_canon::{Alarm, Axis, Canon, Event, Motion, Pos};
use kerf_interp::Interp;
use kerf_motion::Planner;
use serde::Serialize;

use crate::sink::{Context, Sink};

/// The report sink: gathers a [`Summary`] from the event stream and
/// writes the [`Document`] as pretty JSON at the end.
pub struct Report<W: Write> {
    out: W,
    summary: Summary,
}

impl<W: Write> Report<W> {
    /// A report written onto `out` at the end of the run.
    pub fn new(out: W) -> Report<W> {
        Report {
            out,
            summary: Summary::new(&[]),
        }
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

    fn event(&mut self, e: &Event, from: &Pos, _cx: &Context) -> io::Result<()> {
        self.summary.event(e, from);
        Ok(())
    }

    fn finish(&mut self, cx: &Context, alarm: Option<&Alarm>) -> io::Result<()> {
        let doc = self.summary.finish(cx.interp, cx.planner, alarm);
        let text = serde_json::to_string_pretty(&doc).map_err(io::Error::other)?;
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
    tools: Vec<u32>,
    messages: Vec<MessageOut>,
}

/// Most operator messages kept in a report.
const MAX_MESSAGES: usize = 10_000;

/// One operator message (`Canon::Message`: #3006, Hurco probe records,
/// thread start angles) with its source line.
#[derive(Clone, Serialize)]
pub struct MessageOut {
    line: u32,
    text: String,
}

#[derive(Serialize)]
pub struct AlarmOut {
    code: String,
    message: String,
    file: String,
    line: u32,
    col: u32,
}

#[derive(Serialize)]
pub struct BBox {
    min: BTreeMap<&'static str, f64>,
    max: BTreeMap<&'static str, f64>,
}

#[derive(Serialize)]
pub struct Final {
    work: BTreeMap<&'static str, f64>,
    machine: BTreeMap<&'static str, f64>,
}

#[derive(Serialize)]
pub struct TimeOut {
    rapid: f64,
    cutting: f64,
    dwell: f64,
    tool_change: f64,
    other: f64,
}

/// The report document (docs/formats.md "Report").
#[derive(Serialize)]
pub struct Document {
    status: &'static str,
    alarm: Option<AlarmOut>,
    blocks: u64,
    motions: u64,
    feed_length_mm: f64,
    rapid_length_mm: f64,
    bbox: Option<BBox>,
    #[serde(rename = "final")]
    final_: Final,
    tools: Vec<u32>,
    messages: Vec<MessageOut>,
    cycle_time_s: f64,
    time_s: TimeOut,
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
            tools: Vec::new(),
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
            return;
        }
        let mut pts = [*from, m.to, m.to, m.to];
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
            pts[2][a1] = u0;
            pts[2][a2] = v0;
            pts[3][a1] = u1;
            pts[3][a2] = v1;
        }
        for p in pts {
            let b = self.bbox.get_or_insert((p, p));
            for (i, v) in p.iter().enumerate() {
                b.0[i] = b.0[i].min(*v);
                b.1[i] = b.1[i].max(*v);
            }
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
            messages: self.messages.clone(),
            cycle_time_s: r6(est.now()),
            time_s: TimeOut {
                rapid: r6(est.time.rapid),
                cutting: r6(est.time.cutting),
                dwell: r6(est.time.dwell),
                tool_change: r6(est.time.tool_change),
                other: r6(est.time.other),
            },
        }
    }
}
