//! Comparing two toolpath records (JSON Lines objects) as the same motion.

#![allow(dead_code)]

use serde_json::Value;

/// Positions agree to 1 µm.
pub const TOL: f64 = 1e-3;

fn close(a: &Value, b: &Value) -> bool {
    match (a.as_f64(), b.as_f64()) {
        (Some(x), Some(y)) => (x - y).abs() <= TOL * x.abs().max(1.0),
        _ => a == b,
    }
}

/// Differences between two records, or None when they are the same
/// motion: kind, direction, tool exactly; `to`, `mto`, `center` per axis
/// to 1 µm; feed, lead, dwell time to 1e-3 (relative above 1).
pub fn differs(a: &Value, b: &Value) -> Option<String> {
    for key in ["kind", "dir", "tool"] {
        if a.get(key) != b.get(key) {
            return Some(format!("{key} {:?} vs {:?}", a.get(key), b.get(key)));
        }
    }
    for key in ["to", "mto", "center"] {
        let (pa, pb) = (a.get(key), b.get(key));
        let same = match (pa.and_then(Value::as_object), pb.and_then(Value::as_object)) {
            (Some(x), Some(y)) => {
                x.len() == y.len()
                    && x.iter().all(|(k, v)| {
                        let w = y.get(k).and_then(Value::as_f64);
                        matches!((v.as_f64(), w), (Some(p), Some(q)) if (p - q).abs() <= TOL)
                    })
            }
            (None, None) => true,
            _ => false,
        };
        if !same {
            return Some(format!("{key} {pa:?} vs {pb:?}"));
        }
    }
    for key in ["feed", "feed_per_rev", "lead", "seconds", "revolutions"] {
        match (a.get(key), b.get(key)) {
            (Some(x), Some(y)) if close(x, y) => {}
            (None, None) => {}
            (x, y) => return Some(format!("{key} {x:?} vs {y:?}")),
        }
    }
    None
}
