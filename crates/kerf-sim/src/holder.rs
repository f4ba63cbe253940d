//! The lathe holder's check along a whole straight move, exact: the
//! region of the stock (as it was before the move) that the holder
//! reaches before the insert does.
//!
//! Both outlines translate along the move's direction d. On a line
//! parallel to d, a point is reached by a convex outline from the time
//! its front (its greatest coordinate along d on that line) gets there.
//! Where the insert's front is ahead of the holder's (or level), the
//! insert reaches every point of the line first that it reaches at all,
//! so the holder meets only what the insert's sweep leaves. Where the
//! holder's front is ahead, it meets everything ahead of the insert's
//! front at the start. So the region is
//! `holder sweep − (insert sweep − lead)`, with `lead` the points ahead
//! of the insert's starting front on the lines where the holder leads.

use i_overlay::core::fill_rule::FillRule;
use i_overlay::core::overlay_rule::OverlayRule;
use i_overlay::float::single::SingleFloatOverlay;

use crate::hull::{Hull, Pt};
use crate::lathe::{ccw, swept, Contour};

/// The region the holder meets first along the move p0 → p1 (closed
/// contours, holes clockwise).
pub fn holder_first(insert: &[Pt], holder: &[Pt], p0: Pt, p1: Pt) -> Vec<Contour> {
    let (mut scratch, mut h) = (Vec::new(), Hull::default());
    swept(holder, p0, p1, &mut scratch, &mut h);
    let hs = ccw(&h);
    swept(insert, p0, p1, &mut scratch, &mut h);
    let is = ccw(&h);
    let lead = lead(insert, holder, p0, p1);
    let insert_first: Vec<Vec<Contour>> = if lead.is_empty() {
        vec![vec![is]]
    } else {
        vec![is].overlay(&lead, OverlayRule::Difference, FillRule::NonZero)
    };
    vec![hs]
        .overlay(&insert_first, OverlayRule::Difference, FillRule::NonZero)
        .into_iter()
        .flatten()
        .collect()
}

/// The outline's hull in (w, u): w across the move, u along it.
fn frame(outline: &[Pt], d: Pt) -> Hull {
    let mut pts: Vec<Pt> = outline
        .iter()
        .map(|q| (q.0 * -d.1 + q.1 * d.0, q.0 * d.0 + q.1 * d.1))
        .collect();
    let mut h = Hull::default();
    Hull::of(&mut pts, &mut h);
    h
}

/// Quadrilaterals (world coordinates) ahead of the insert's front at p0
/// on the lines where the holder's front is ahead of it.
fn lead(insert: &[Pt], holder: &[Pt], p0: Pt, p1: Pt) -> Vec<Contour> {
    let (dz, dr) = (p1.0 - p0.0, p1.1 - p0.1);
    let l = dz.hypot(dr);
    if l < 1e-12 {
        return Vec::new();
    }
    let d = (dz / l, dr / l);
    let (fi, fh) = (frame(insert, d), frame(holder, d));
    let (Some((ia, ib)), Some((ha, hb))) = (fi.z_range(), fh.z_range()) else {
        return Vec::new();
    };
    let (wa, wb) = (ia.max(ha), ib.min(hb));
    if wa >= wb {
        return Vec::new();
    }
    let front = |h: &Hull, w: f64| h.slice(w).map_or(f64::NEG_INFINITY, |s| s.1);
    let mut ws: Vec<f64> = fi
        .upper
        .iter()
        .chain(&fh.upper)
        .map(|p| p.0)
        .filter(|&w| w > wa && w < wb)
        .chain([wa, wb])
        .collect();
    ws.sort_by(f64::total_cmp);
    ws.dedup();
    // Far enough ahead: past the holder's front at the move's end.
    let far = fh
        .upper
        .iter()
        .map(|p| p.1)
        .fold(f64::NEG_INFINITY, f64::max)
        + l
        + 1.0;
    let world = |u: f64, w: f64| [p0.0 + u * d.0 - w * d.1, p0.1 + u * d.1 + w * d.0];
    let mut out = Vec::new();
    for s in ws.windows(2) {
        let g = |w: f64| front(&fh, w) - front(&fi, w);
        let (ga, gb) = (g(s[0]), g(s[1]));
        if ga <= 0.0 && gb <= 0.0 {
            continue;
        }
        // The part of [s0, s1] where g > 0 (g is linear there).
        let cut = |ga: f64, gb: f64| s[0] + (s[1] - s[0]) * ga / (ga - gb);
        let (a, b) = match (ga > 0.0, gb > 0.0) {
            (true, true) => (s[0], s[1]),
            (true, false) => (s[0], cut(ga, gb)),
            _ => (cut(ga, gb), s[1]),
        };
        if b - a < 1e-12 {
            continue;
        }
        let (ua, ub) = (front(&fi, a), front(&fi, b));
        // Counter-clockwise in (w, u) is clockwise in (z, r) when the
        // frame is a reflection; the fill rule makes either do.
        out.push(vec![
            world(ua, a),
            world(ub, b),
            world(far, b),
            world(far, a),
        ]);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lathe::{signed_area, volume};

    fn area(c: &[Contour]) -> f64 {
        c.iter().map(|c| signed_area(c)).sum()
    }

    #[test]
    fn a_trailing_holder_meets_only_what_the_insert_leaves() {
        // Insert: the unit square at the tip; holder: the square z 1..2,
        // r 0..1 behind it (to +z). Moving -z by 5: the insert sweeps z
        // -5..1, the holder -4..2: the holder alone covers z 1..2.
        let ins = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)];
        let hol = [(1.0, 0.0), (2.0, 0.0), (2.0, 1.0), (1.0, 1.0)];
        let r = holder_first(&ins, &hol, (0.0, 0.0), (-5.0, 0.0));
        assert!((area(&r) - 1.0).abs() < 1e-9, "{r:?}");
        let v = volume(&vec![r.clone()]);
        // Revolved: π (1² - 0²) · 1.
        assert!((v - std::f64::consts::PI).abs() < 1e-9, "{v}");
    }

    #[test]
    fn a_leading_holder_meets_what_lies_ahead_of_the_insert() {
        // The same pair moving +z by 5: the holder leads; it meets all it
        // sweeps (z 1..7), the insert's own sweep ahead of its start
        // included.
        let ins = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)];
        let hol = [(1.0, 0.0), (2.0, 0.0), (2.0, 1.0), (1.0, 1.0)];
        let r = holder_first(&ins, &hol, (0.0, 0.0), (5.0, 0.0));
        assert!((area(&r) - 6.0).abs() < 1e-9, "{r:?}");
        // A holder beside the insert (r 1..2 over the same z) moving +z:
        // their fronts are level on no common line, so the holder meets
        // its own sweep, z 0..6 × r 1..2.
        let side = [(0.0, 1.0), (1.0, 1.0), (1.0, 2.0), (0.0, 2.0)];
        let r = holder_first(&ins, &side, (0.0, 0.0), (5.0, 0.0));
        assert!((area(&r) - 6.0).abs() < 1e-9, "{r:?}");
    }
}
