//! The sampler: axis setpoints at a fixed period, as an interpolator
//! feeding servos would produce them. The planner's timeline (pieces,
//! before smoothing) is evaluated every `dt` seconds and passed through
//! the smoothing stages (moving averages of `n = max(1, round(T/dt))`
//! samples each, one per stage), so the samples are the smoothed command.

use std::collections::VecDeque;

use kerf_canon::{Pos, NAXES};

use crate::planner::Piece;

/// Moving average of the last `n` positions.
#[derive(Debug)]
struct Stage {
    buf: VecDeque<Pos>,
    sum: Pos,
    n: usize,
}

impl Stage {
    fn new(n: usize, start: Pos) -> Stage {
        let mut sum = [0.0; NAXES];
        for i in 0..NAXES {
            sum[i] = start[i] * n as f64;
        }
        Stage {
            buf: std::iter::repeat_n(start, n).collect(),
            sum,
            n,
        }
    }

    fn step(&mut self, p: Pos) -> Pos {
        let old = self.buf.pop_front().unwrap_or(p);
        self.buf.push_back(p);
        let mut out = [0.0; NAXES];
        for i in 0..NAXES {
            self.sum[i] += p[i] - old[i];
            out[i] = self.sum[i] / self.n as f64;
        }
        out
    }
}

/// Turns pieces into smoothed samples at a fixed period.
#[derive(Debug)]
pub struct Sampler {
    dt: f64,
    /// Index of the next sample (its time is `k·dt`).
    k: u64,
    stages: Vec<Stage>,
    pending: VecDeque<Piece>,
    last: Pos,
}

impl Sampler {
    /// A sampler with period `dt` (> 0) for a planner with `stages`
    /// smoothing stages of width `t_smooth`, starting at `start`.
    pub fn new(dt: f64, stages: usize, t_smooth: f64, start: Pos) -> Sampler {
        let n = ((t_smooth / dt).round() as usize).max(1);
        Sampler {
            dt,
            k: 0,
            stages: (0..stages).map(|_| Stage::new(n, start)).collect(),
            pending: VecDeque::new(),
            last: start,
        }
    }

    /// Adds a piece of the timeline (in order).
    pub fn add(&mut self, p: Piece) {
        self.pending.push_back(p);
    }

    fn raw_at(&mut self, t: f64) -> Pos {
        while let Some(p) = self.pending.front() {
            let end = p.t0 + p.duration();
            if t <= end + 1e-12 {
                return p.pos_at(t - p.t0);
            }
            self.last = p.pos_at(p.duration());
            self.pending.pop_front();
        }
        self.last
    }

    /// Emits every sample whose time is at most `upto` (the planned time
    /// so far) through `out(t, position)`.
    pub fn run(&mut self, upto: f64, out: &mut dyn FnMut(f64, &Pos)) {
        loop {
            let t = self.k as f64 * self.dt;
            if t > upto + 1e-9 {
                return;
            }
            let mut p = self.raw_at(t);
            for s in &mut self.stages {
                p = s.step(p);
            }
            out(t, &p);
            self.k += 1;
        }
    }
}
