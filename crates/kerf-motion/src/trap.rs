//! Trapezoidal path-speed profile of one segment (acceleration-limited,
//! before the smoothing stages).

/// A planned trapezoid: accelerate from `v0` to `vp`, cruise, decelerate
/// to `v1`, at path acceleration `a`. Units mm, s.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Trap {
    /// Entry speed.
    pub v0: f64,
    /// Peak (cruise) speed.
    pub vp: f64,
    /// Exit speed.
    pub v1: f64,
    /// Path acceleration.
    pub a: f64,
    /// Acceleration time.
    pub ta: f64,
    /// Cruise time.
    pub tc: f64,
    /// Deceleration time.
    pub td: f64,
    /// Length.
    pub len: f64,
}

impl Trap {
    /// Plans `len` from `v0` to `v1` with cruise limit `vmax` and
    /// acceleration `a` (> 0). Speeds the length cannot reconcile are
    /// lowered so that the profile stays feasible; a zero length takes no time.
    pub fn plan(len: f64, v0: f64, v1: f64, vmax: f64, a: f64) -> Trap {
        if len <= 0.0 || a <= 0.0 || vmax <= 0.0 || !len.is_finite() {
            return Trap::default();
        }
        let vmax = vmax.max(1e-9);
        let mut v0 = v0.clamp(0.0, vmax);
        let mut v1 = v1.clamp(0.0, vmax);
        // Feasibility (the planner guarantees it up to rounding).
        let reach = (v0 * v0 + 2.0 * a * len).sqrt();
        if v1 > reach {
            v1 = reach;
        }
        let reach = (v1 * v1 + 2.0 * a * len).sqrt();
        if v0 > reach {
            v0 = reach;
        }
        let vp = ((2.0 * a * len + v0 * v0 + v1 * v1) / 2.0)
            .sqrt()
            .min(vmax)
            .max(v0)
            .max(v1);
        let da = (vp * vp - v0 * v0) / (2.0 * a);
        let dd = (vp * vp - v1 * v1) / (2.0 * a);
        let dc = (len - da - dd).max(0.0);
        Trap {
            v0,
            vp,
            v1,
            a,
            ta: (vp - v0) / a,
            tc: if vp > 0.0 { dc / vp } else { 0.0 },
            td: (vp - v1) / a,
            len,
        }
    }

    /// Total time.
    pub fn time(&self) -> f64 {
        self.ta + self.tc + self.td
    }

    /// Distance travelled at time `t` from the start (clamped to the length).
    pub fn s_at(&self, t: f64) -> f64 {
        let t = t.max(0.0);
        let s = if t < self.ta {
            self.v0 * t + 0.5 * self.a * t * t
        } else if t < self.ta + self.tc {
            let da = self.v0 * self.ta + 0.5 * self.a * self.ta * self.ta;
            da + self.vp * (t - self.ta)
        } else {
            let t2 = (t - self.ta - self.tc).min(self.td);
            let d0 = self.len - (self.vp * self.td - 0.5 * self.a * self.td * self.td);
            d0 + self.vp * t2 - 0.5 * self.a * t2 * t2
        };
        s.clamp(0.0, self.len)
    }
}
