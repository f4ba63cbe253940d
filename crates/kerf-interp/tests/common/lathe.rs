//! Lathe traces shared by the lathe cycle tests: moves as (kind, X
//! diameter, Z, feed or lead), expected values written from radius points.

use kerf_canon::{Canon, Feed};
use kerf_interp::Run;

use super::round;

/// (kind, X diameter, Z, feed or lead) of every move: `R` rapid, `F` feed,
/// `A` arc, `T` thread.
pub fn trace(r: &Run) -> Vec<(&'static str, f64, f64, f64)> {
    r.events
        .iter()
        .filter_map(|e| {
            let f = |f: &Feed| match *f {
                Feed::PerRev(v) | Feed::PerMin(v) | Feed::InverseTime(v) => v,
            };
            let (k, v) = match &e.cmd {
                Canon::Rapid { .. } => ("R", 0.0),
                Canon::Feed { feed, .. } => ("F", f(feed)),
                Canon::Arc { feed, .. } => ("A", f(feed)),
                Canon::Thread { lead, .. } => ("T", *lead),
                _ => return None,
            };
            let m = e.motion().unwrap();
            Some((k, round(2.0 * m.to[0]), round(m.to[2]), round(v)))
        })
        .collect()
}

/// A move to a radius point, in the form of [`trace`].
pub fn mv(k: &'static str, x: f64, z: f64, f: f64) -> (&'static str, f64, f64, f64) {
    (k, round(2.0 * x), round(z), f)
}

/// One G71 type I roughing level from the start point's Z2 with e = 0.5
/// (radius values): rapid to the level, feed to `z`, escape 45° by e,
/// rapid back to Z2 (001's G71 figure).
pub fn g71_level(l: f64, z: f64, f: f64) -> [(&'static str, f64, f64, f64); 4] {
    [
        mv("R", l, 2.0, 0.0),
        mv("F", l, z, f),
        mv("R", l + 0.5, z + 0.5, 0.0),
        mv("R", l + 0.5, 2.0, 0.0),
    ]
}
