//! kerf-motion: turns canonical commands into time.
//!
//! This first version is a constant-velocity estimator: every move runs at
//! its programmed (or rapid) rate from start to end, with no acceleration,
//! jerk or look-ahead; the planner with machine dynamics replaces it later
//! (it will keep this interface). It reads only kerf-canon, never the
//! interpreter.

// Axis arithmetic indexes several parallel position arrays by slot.
#![allow(clippy::needless_range_loop)]

use kerf_canon::{Axis, Canon, Event, Feed, Pos, NAXES};

/// The machine data the estimator needs.
#[derive(Clone, Debug)]
pub struct Dynamics {
    /// Rapid rate per axis slot, mm/min (deg/min); 0 for absent axes.
    pub rapid: [f64; NAXES],
    /// Maximum cutting feed, mm/min.
    pub max_feed: f64,
    /// Tool change / turret index time, s.
    pub tool_change_s: f64,
}

/// Time totals by category, seconds.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Breakdown {
    pub rapid: f64,
    pub cutting: f64,
    pub dwell: f64,
    pub tool_change: f64,
}

impl Breakdown {
    /// Sum of all categories.
    pub fn total(&self) -> f64 {
        self.rapid + self.cutting + self.dwell + self.tool_change
    }
}

/// Accumulates time over a stream of events.
#[derive(Clone, Debug)]
pub struct Estimator {
    dyn_: Dynamics,
    last: Option<Pos>,
    rpm: f64,
    /// Totals so far.
    pub time: Breakdown,
    /// Cutting path length so far, mm.
    pub feed_length: f64,
    /// Rapid path length so far, mm.
    pub rapid_length: f64,
    /// Path length of the last cutting move, mm.
    pub last_cut_length: f64,
}

impl Estimator {
    /// A new estimator starting at machine position `start`.
    pub fn new(dyn_: Dynamics, start: Pos) -> Estimator {
        Estimator {
            dyn_,
            last: Some(start),
            rpm: 0.0,
            time: Breakdown::default(),
            feed_length: 0.0,
            rapid_length: 0.0,
            last_cut_length: 0.0,
        }
    }

    /// Elapsed time so far, s.
    pub fn now(&self) -> f64 {
        self.time.total()
    }

    /// The spindle speed last commanded, rpm.
    pub fn rpm(&self) -> f64 {
        self.rpm
    }

    /// Effective feed in mm/min for a programmed feed (per-rev via the
    /// spindle speed; inverse time via the move length).
    pub fn feed_mm_min(&self, f: Feed, len: f64) -> f64 {
        let v = match f {
            Feed::PerMin(v) => v,
            Feed::PerRev(v) => v * self.rpm,
            Feed::InverseTime(v) => len * v,
        };
        v.min(self.dyn_.max_feed)
    }

    /// Accounts for one event; returns the time at its end.
    pub fn push(&mut self, e: &Event) -> f64 {
        let start = self.last.unwrap_or([0.0; NAXES]);
        match &e.cmd {
            Canon::Rapid { m, linear } => {
                let len = dist(&start, &m.mto);
                self.rapid_length += len;
                // Without acceleration both rapid styles take the time of the
                // slowest axis: non-linear moves each axis at its own rate,
                // linear ones slow the path so that no axis exceeds its rate.
                let _ = linear;
                let mut t: f64 = 0.0;
                for a in Axis::ALL {
                    let d = (m.mto[a as usize] - start[a as usize]).abs();
                    if d > 0.0 && self.dyn_.rapid[a as usize] > 0.0 {
                        t = t.max(d / self.dyn_.rapid[a as usize]);
                    }
                }
                self.time.rapid += t * 60.0;
                self.last = Some(m.mto);
            }
            Canon::Feed { m, feed } => {
                let len = dist(&start, &m.mto);
                self.cut(len, *feed);
                self.last = Some(m.mto);
            }
            Canon::Arc {
                m,
                mcenter,
                plane,
                dir,
                ..
            } => {
                let (a1, a2, _) = plane.axes();
                let s = (start[a1], start[a2]);
                let en = (m.mto[a1], m.mto[a2]);
                let c = (mcenter[a1], mcenter[a2]);
                let r = (s.0 - c.0).hypot(s.1 - c.1);
                let sw = kerf_canon::geom::sweep(s, en, c, matches!(dir, kerf_canon::ArcDir::Ccw));
                let planar = r * sw;
                let mut other = 0.0;
                for i in 0..NAXES {
                    if i != a1 && i != a2 {
                        let d = m.mto[i] - start[i];
                        other += d * d;
                    }
                }
                let len = (planar * planar + other).sqrt();
                if let Canon::Arc { feed, .. } = &e.cmd {
                    self.cut(len, *feed);
                }
                self.last = Some(m.mto);
            }
            Canon::Thread { m, lead } => {
                let len = dist(&start, &m.mto);
                self.feed_length += len;
                if self.rpm > 0.0 && *lead > 0.0 {
                    self.time.cutting += len / (lead * self.rpm) * 60.0;
                }
                self.last = Some(m.mto);
            }
            Canon::Dwell {
                seconds,
                revolutions,
            } => {
                let mut t = *seconds;
                if *revolutions > 0.0 && self.rpm > 0.0 {
                    t += revolutions / self.rpm * 60.0;
                }
                self.time.dwell += t;
            }
            Canon::Spindle { rpm, .. } => self.rpm = *rpm,
            Canon::Tool { change: true, .. } => self.time.tool_change += self.dyn_.tool_change_s,
            _ => {}
        }
        self.now()
    }

    fn cut(&mut self, len: f64, feed: Feed) {
        self.feed_length += len;
        self.last_cut_length = len;
        let f = self.feed_mm_min(feed, len);
        if f > 0.0 {
            self.time.cutting += len / f * 60.0;
        }
    }
}

fn dist(a: &Pos, b: &Pos) -> f64 {
    // Linear axes only for path length.
    let mut s = 0.0;
    for i in 0..3 {
        let d = b[i] - a[i];
        s += d * d;
    }
    s.sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;
    use kerf_canon::{ArcDir, Motion, Plane, SrcRef};

    fn dynm() -> Dynamics {
        Dynamics {
            rapid: [10000.0, 5000.0, 5000.0, 0.0, 0.0, 0.0],
            max_feed: 5000.0,
            tool_change_s: 2.0,
        }
    }

    fn ev(cmd: Canon) -> Event {
        Event {
            src: SrcRef::default(),
            tool: 0,
            cmd,
        }
    }

    fn mo(x: f64, y: f64) -> Motion {
        let p = [x, y, 0.0, 0.0, 0.0, 0.0];
        Motion { to: p, mto: p }
    }

    #[test]
    fn rapid_each_axis_at_its_own_rate() {
        let mut e = Estimator::new(dynm(), [0.0; NAXES]);
        // X 100 at 10 m/min = 0.6 s; Y 100 at 5 m/min = 1.2 s; the move takes 1.2 s.
        let t = e.push(&ev(Canon::Rapid {
            m: mo(100.0, 100.0),
            linear: false,
        }));
        assert!((t - 1.2).abs() < 1e-12);
    }

    #[test]
    fn feed_and_arc_times() {
        let mut e = Estimator::new(dynm(), [0.0; NAXES]);
        e.push(&ev(Canon::Feed {
            m: mo(100.0, 0.0),
            feed: Feed::PerMin(600.0),
        }));
        assert!((e.now() - 10.0).abs() < 1e-12);
        // Half circle radius 50 back to (0,0) about (50,0): length 50π at 600 mm/min.
        let c = [50.0, 0.0, 0.0, 0.0, 0.0, 0.0];
        e.push(&ev(Canon::Arc {
            m: mo(0.0, 0.0),
            center: c,
            mcenter: c,
            dir: ArcDir::Ccw,
            plane: Plane::XY,
            turns: 0,
            feed: Feed::PerMin(600.0),
        }));
        assert!((e.now() - 10.0 - 50.0 * std::f64::consts::PI / 10.0).abs() < 1e-9);
        assert!((e.feed_length - 100.0 - 50.0 * std::f64::consts::PI).abs() < 1e-9);
    }

    #[test]
    fn per_rev_feed_uses_spindle_speed_and_dwell_revolutions() {
        let mut e = Estimator::new(dynm(), [0.0; NAXES]);
        e.push(&ev(Canon::Spindle {
            dir: kerf_canon::SpindleDir::Cw,
            rpm: 1000.0,
            css: None,
        }));
        e.push(&ev(Canon::Feed {
            m: mo(10.0, 0.0),
            feed: Feed::PerRev(0.1),
        }));
        // 0.1 mm/rev × 1000 rpm = 100 mm/min: 10 mm takes 6 s.
        assert!((e.now() - 6.0).abs() < 1e-12);
        e.push(&ev(Canon::Dwell {
            seconds: 0.0,
            revolutions: 500.0,
        }));
        assert!((e.now() - 36.0).abs() < 1e-12);
    }
}
