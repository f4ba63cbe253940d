//! A tiny program builder: canonical events made by hand and fed to the
//! simulation, each motion taking one second.
#![allow(dead_code)]

use kerf_canon::{ArcDir, Canon, Event, Feed, Motion, Plane, Pos, SpindleDir, SrcRef};
use kerf_sim::{Sim, Stock, ToolTable};

pub struct Run {
    pub sim: Sim,
    pub pos: Pos,
    pub t: f64,
    pub tool: u32,
}

fn pos(x: f64, y: f64, z: f64) -> Pos {
    [x, y, z, 0.0, 0.0, 0.0]
}

impl Run {
    pub fn new(stock: &str, tools: ToolTable, res: Option<f64>) -> Run {
        let sim = Sim::new(Stock::parse(stock).unwrap(), tools, res).unwrap();
        Run {
            sim,
            pos: pos(0.0, 0.0, 500.0),
            t: 0.0,
            tool: 1,
        }
    }

    /// Starts at a position (no motion).
    pub fn at(mut self, x: f64, y: f64, z: f64) -> Run {
        self.pos = pos(x, y, z);
        self
    }

    fn send(&mut self, line: u32, cmd: Canon, timed: bool) {
        let e = Event {
            src: SrcRef {
                file: 0,
                line,
                col: 1,
            },
            tool: self.tool,
            cmd,
            prog: None,
        };
        if timed {
            self.t += 1.0;
        }
        let start = self.pos;
        if let Some(m) = e.motion() {
            self.pos = m.to;
        }
        self.sim.event(&e, &start, self.t);
    }

    pub fn spindle(&mut self, on: bool) {
        let dir = if on { SpindleDir::Cw } else { SpindleDir::Stop };
        self.send(
            1,
            Canon::Spindle {
                dir,
                rpm: 1000.0,
                css: None,
            },
            false,
        );
    }

    pub fn tool(&mut self, n: u32, offset: u32) {
        self.tool = n;
        self.send(
            1,
            Canon::Tool {
                tool: n,
                offset,
                change: true,
            },
            false,
        );
    }

    pub fn rapid(&mut self, line: u32, x: f64, y: f64, z: f64) {
        let to = pos(x, y, z);
        self.send(
            line,
            Canon::Rapid {
                m: Motion { to, mto: to },
                linear: true,
            },
            true,
        );
    }

    pub fn feed(&mut self, line: u32, x: f64, y: f64, z: f64) {
        let to = pos(x, y, z);
        self.send(
            line,
            Canon::Feed {
                m: Motion { to, mto: to },
                feed: Feed::PerMin(100.0),
            },
            true,
        );
    }

    /// Lathe move in (X radius, Z).
    pub fn lfeed(&mut self, line: u32, x: f64, z: f64) {
        self.feed(line, x, 0.0, z);
    }

    pub fn lrapid(&mut self, line: u32, x: f64, z: f64) {
        self.rapid(line, x, 0.0, z);
    }

    /// An arc in `plane` to `to` about `c` (work coordinates).
    pub fn arc(
        &mut self,
        line: u32,
        to: [f64; 3],
        c: [f64; 3],
        ccw: bool,
        plane: Plane,
        turns: u32,
    ) {
        let to = pos(to[0], to[1], to[2]);
        let center = pos(c[0], c[1], c[2]);
        let dir = if ccw { ArcDir::Ccw } else { ArcDir::Cw };
        self.send(
            line,
            Canon::Arc {
                m: Motion { to, mto: to },
                center,
                mcenter: center,
                dir,
                plane,
                turns,
                feed: Feed::PerMin(100.0),
            },
            true,
        );
    }
}
