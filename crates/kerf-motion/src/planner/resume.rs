//! Planning again from rest: a controller runtime stops the axes on a
//! feed hold (decelerating on the planned path) and, at cycle start,
//! plans the rest of the program from the point where they stopped, with
//! the modal state the planner had when the interrupted move was pushed.

use super::*;

/// The planner's modal state between events: the spindle (speed,
/// direction, constant surface speed, clamp), the feed modes (exact stop,
/// G62, tapping, high-speed window, Hurco M49) and the overrides.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Modes {
    rpm: f64,
    css: Option<f64>,
    spindle_dir: SpindleDir,
    exact_mode: bool,
    corner_mode: bool,
    ignore_override: bool,
    tapping: bool,
    high_speed: bool,
    s_clamp: f64,
    max_rpm: f64,
    work_x: f64,
}

impl Modes {
    /// The same modes with the spindle turning (`dir`, `rpm`): a planner
    /// resumed with them adds no spindle ramp.
    pub fn with_spindle(mut self, dir: SpindleDir, rpm: f64) -> Modes {
        self.spindle_dir = dir;
        self.rpm = if dir == SpindleDir::Stop { 0.0 } else { rpm };
        self
    }

    /// Whether the planner is in tapping mode (G63, or inside a tapping
    /// cycle): the feed override and feed hold do not act.
    pub fn tapping(&self) -> bool {
        self.tapping
    }
}

impl Planner {
    /// The modal state now (before the next event is pushed).
    pub fn modes(&self) -> Modes {
        Modes {
            rpm: self.rpm,
            css: self.css,
            spindle_dir: self.spindle_dir,
            exact_mode: self.exact_mode,
            corner_mode: self.corner_mode,
            ignore_override: self.ignore_override,
            tapping: self.tapping,
            high_speed: self.high_speed,
            s_clamp: self.s_clamp,
            max_rpm: self.max_rpm,
            work_x: self.work_x,
        }
    }

    /// A planner at rest at machine position `pos`, time 0, nothing
    /// queued, with dynamics `d` and the modal state `m` (taken with
    /// [`Planner::modes`]): the spindle is already running at its speed,
    /// so no ramp is added. Keeps timeline pieces when `pieces` is true.
    pub fn resume(d: Dynamics, pos: Pos, m: &Modes, pieces: bool) -> Planner {
        let mut p = Planner::new(d, pos, m.work_x);
        p.rpm = m.rpm;
        p.css = m.css;
        p.spindle_dir = m.spindle_dir;
        p.exact_mode = m.exact_mode;
        p.corner_mode = m.corner_mode;
        p.ignore_override = m.ignore_override;
        p.tapping = m.tapping;
        p.high_speed = m.high_speed;
        p.window = if m.high_speed {
            p.d.lookahead_high_speed
        } else {
            p.d.lookahead
        }
        .max(1);
        p.s_clamp = m.s_clamp;
        p.max_rpm = m.max_rpm;
        if pieces {
            p.keep_pieces();
        }
        p
    }

    /// Sets the feed and rapid overrides (factors, 1 = 100 %) and the dry
    /// run switch for the events pushed from now on.
    pub fn set_overrides(&mut self, feed: f64, rapid: f64, dry_run: bool) {
        self.d.feed_override = feed;
        self.d.rapid_override = rapid;
        self.d.dry_run = dry_run;
    }

    /// The dynamics in force.
    pub fn dynamics(&self) -> &Dynamics {
        &self.d
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use kerf_canon::{Canon, Event, Feed, Motion, SrcRef};

    fn feed(x: f64, f: f64) -> Event {
        let mut to = [0.0; NAXES];
        to[0] = x;
        Event {
            src: SrcRef::default(),
            tool: 0,
            cmd: Canon::Feed {
                m: Motion { to, mto: to },
                feed: Feed::PerMin(f),
            },
            prog: None,
        }
    }

    #[test]
    fn resumed_planner_keeps_the_spindle_and_plans_from_rest() {
        let mut present = [false; NAXES];
        present[0] = true;
        let mut d = Dynamics::uniform(present, 10_000.0, 2000.0, 1e9, 10_000.0);
        d.spindle_accel = 1000.0;
        let mut p = Planner::new(d.clone(), [0.0; NAXES], 0.0);
        p.push(&Event {
            src: SrcRef::default(),
            tool: 0,
            cmd: Canon::Spindle {
                dir: SpindleDir::Cw,
                rpm: 1000.0,
                css: None,
            },
            prog: None,
        });
        // 1000 rpm at 1000 rpm/s: 1 s of ramp.
        assert!((p.now() - 1.0).abs() < 1e-12);
        let m = p.modes();
        let mut q = Planner::resume(d, [50.0, 0.0, 0.0, 0.0, 0.0, 0.0], &m, false);
        // F0.1 mm/rev at 1000 rpm = 100 mm/min: per-rev feeds use the kept speed.
        q.push(&Event {
            cmd: Canon::Feed {
                m: Motion {
                    to: [60.0, 0.0, 0.0, 0.0, 0.0, 0.0],
                    mto: [60.0, 0.0, 0.0, 0.0, 0.0, 0.0],
                },
                feed: Feed::PerRev(0.1),
            },
            ..feed(60.0, 0.0)
        });
        q.finish();
        // 10 mm at 100 mm/min from rest, path acceleration 1000 mm/s²
        // (half the axis's): L/v + v/a, plus the smoothing drain at the
        // stop (2 stages × T, T = 2·rapid_accel/jerk = 4 µs).
        let v = 100.0 / 60.0;
        let want = 10.0 / v + v / 1000.0 + 2.0 * 4e-6;
        assert!((q.now() - want).abs() < 1e-6, "{} vs {want}", q.now());
    }
}
