//! A tile's cut without the boolean, when both sides are slabs: the
//! material is rectangles over one z range (a bar's tile, or one less
//! bands across its whole width) and every clipped region is a rectangle
//! across that whole range (a roughing pass along the whole tile at one
//! radius), or stays a step clear of what they leave (the lift at a
//! pass's end over the tile beside it). The result is then the material's r intervals less the
//! regions', with the regions' edges snapped to the grid as the boolean
//! snaps them; any other case returns None (the boolean's).

use crate::lathe::{Contour, Shapes};

/// The material `shapes` less `clips` (each counter-clockwise), on the
/// grid of `scale` steps per mm, when both are slabs as above; None
/// otherwise. The rectangles come out as the boolean gives them, even
/// when nothing is cut (so that a tile left as it was compares equal, and
/// one reordered does not, exactly as with the boolean): from
/// the lowest r up, each counter-clockwise from its corner of least z
/// and greatest r.
pub fn difference(shapes: &Shapes, clips: &[Contour], scale: f64) -> Option<Shapes> {
    let (zs, mut rs) = slabs(shapes)?;
    let snap = |v: f64| (v * scale).round() / scale;
    // Regions that are not bands: each must stay clear of what the bands
    // leave (their snapped boxes a whole step away from it).
    let mut others = 0;
    if clips.iter().any(|c| signed_area(c) <= 0.0) {
        // A hole of the region (or nothing): the boolean's.
        return None;
    }
    for c in clips {
        let Some(b) = rectangle(c) else {
            others += 1;
            continue;
        };
        let (z0, z1, r0, r1) = (snap(b[0]), snap(b[1]), snap(b[2]), snap(b[3]));
        if z0 > zs.0 || z1 < zs.1 {
            return None;
        }
        if r1 <= r0 {
            continue;
        }
        cut(&mut rs, (r0, r1));
    }
    if others > 0 {
        let step = 1.0 / scale;
        for c in clips.iter().filter(|c| rectangle(c).is_none()) {
            let b = crate::lathe::bbox(c);
            let (z0, z1, r0, r1) = (snap(b[0]), snap(b[1]), snap(b[2]), snap(b[3]));
            let clear = |&(a, t): &(f64, f64)| {
                r0 >= t + step || r1 + step <= a || z0 >= zs.1 + step || z1 + step <= zs.0
            };
            if !rs.iter().all(clear) {
                return None;
            }
        }
    }
    Some(
        rs.iter()
            .map(|&(a, b)| vec![vec![[zs.0, b], [zs.0, a], [zs.1, a], [zs.1, b]]])
            .collect(),
    )
}

/// A slab's z range and its r intervals.
type Slabs = ((f64, f64), Vec<(f64, f64)>);

/// The z range and the sorted r intervals of `shapes` when each is one
/// axis-parallel rectangle (no hole) and all span the same z range.
fn slabs(shapes: &Shapes) -> Option<Slabs> {
    let mut zs = None;
    let mut rs = Vec::with_capacity(shapes.len());
    for s in shapes {
        let [c] = &s[..] else { return None };
        let b = rectangle(c)?;
        match zs {
            None => zs = Some((b[0], b[1])),
            Some(z) if z == (b[0], b[1]) => {}
            Some(_) => return None,
        }
        rs.push((b[2], b[3]));
    }
    rs.sort_by(|p, q| p.0.total_cmp(&q.0));
    Some((zs?, rs))
}

/// The box of `c` (z from, z to, r from, r to) when `c` is that box: its
/// vertices at its corners only and its area the box's, counter-clockwise.
fn rectangle(c: &[[f64; 2]]) -> Option<[f64; 4]> {
    let b = crate::lathe::bbox(c);
    if c.len() < 4 || b[0] >= b[1] || b[2] >= b[3] {
        return None;
    }
    let corner = |p: &[f64; 2]| (p[0] == b[0] || p[0] == b[1]) && (p[1] == b[2] || p[1] == b[3]);
    if !c.iter().all(corner) {
        return None;
    }
    // Vertices at the corners only: the shoelace sum is exact enough to
    // tell the whole box (its area) from three corners (half of it).
    let area = (0..c.len())
        .map(|i| {
            let (p, q) = (c[i], c[(i + 1) % c.len()]);
            (p[0] - b[0]) * (q[1] - b[2]) - (q[0] - b[0]) * (p[1] - b[2])
        })
        .sum::<f64>()
        / 2.0;
    let full = (b[1] - b[0]) * (b[3] - b[2]);
    ((area - full).abs() <= 1e-9 * full).then_some(b)
}

/// Twice the signed area of a closed contour (positive counter-clockwise).
fn signed_area(c: &[[f64; 2]]) -> f64 {
    (0..c.len())
        .map(|i| {
            let (p, q) = (c[i], c[(i + 1) % c.len()]);
            p[0] * q[1] - q[0] * p[1]
        })
        .sum()
}

/// Removes the r interval `cut` from the sorted disjoint intervals `rs`.
fn cut(rs: &mut Vec<(f64, f64)>, cut: (f64, f64)) {
    if !rs.iter().any(|&(a, b)| cut.0 < b && a < cut.1) {
        return;
    }
    let mut out = Vec::with_capacity(rs.len() + 1);
    for &(a, b) in rs.iter() {
        if cut.1 <= a || b <= cut.0 {
            out.push((a, b));
            continue;
        }
        if a < cut.0 {
            out.push((a, cut.0));
        }
        if cut.1 < b {
            out.push((cut.1, b));
        }
    }
    *rs = out;
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lathe::{swept_ccw, volume, Section};
    use i_overlay::core::fill_rule::FillRule;
    use i_overlay::core::overlay::ShapeType;
    use i_overlay::core::overlay_rule::OverlayRule;
    use i_overlay::float::overlay::FloatOverlay;
    use i_overlay::i_float::adapter::FloatPointAdapter;
    use i_overlay::i_float::float::rect::FloatRect;

    /// The grid of a 60 mm bar's section (2^-24 mm).
    const SCALE: f64 = 16_777_216.0;

    /// The boolean's difference, as lathe.rs makes it for a tile at z 0.
    fn boolean(shapes: &Shapes, clips: &[Contour]) -> Shapes {
        let rect = FloatRect::new(-1.0, 9.0, -33.0, 33.0).unwrap();
        let a = FloatPointAdapter::<[f64; 2], i32>::with_scale(rect, SCALE);
        let mut ov = FloatOverlay::<[f64; 2]>::with_adapter(a, 64);
        for c in shapes.iter().flatten() {
            ov = ov.unsafe_add_contour(c, ShapeType::Subject);
        }
        for c in clips {
            ov = ov.unsafe_add_contour(c, ShapeType::Clip);
        }
        ov.overlay(OverlayRule::Difference, FillRule::NonZero)
    }

    fn rect(z: (f64, f64), r: (f64, f64)) -> Contour {
        vec![[z.0, r.0], [z.1, r.0], [z.1, r.1], [z.0, r.1]]
    }

    #[test]
    fn a_pass_across_a_bar_tile_leaves_the_rectangle_below_it() {
        // z 0..8, r 0..30 less r 27.3.. across: z 0..8, r 0..27.3 snapped
        // (27.3 is not on the grid: the boolean snaps it to the nearest
        // step, as this does).
        let bar = vec![vec![rect((0.0, 8.0), (0.0, 30.0))]];
        let pass = rect((-0.5, 8.5), (27.3, 31.0));
        let got = difference(&bar, std::slice::from_ref(&pass), SCALE).unwrap();
        let r = (27.3 * SCALE).round() / SCALE;
        let want = vec![[0.0, r], [0.0, 0.0], [8.0, 0.0], [8.0, r]];
        assert_eq!(got, vec![vec![want]]);
        assert_eq!(got, boolean(&bar, &[pass]));
        // A band inside splits it in two; a pass short of the tile's end,
        // a slanted one or a material with a step is the boolean's.
        let mid = rect((0.0, 8.0), (10.0, 12.0));
        let two = difference(&bar, std::slice::from_ref(&mid), SCALE).unwrap();
        assert_eq!(two, boolean(&bar, &[mid]));
        assert_eq!(two.len(), 2);
        assert!(difference(&bar, &[rect((0.5, 8.5), (27.0, 31.0))], SCALE).is_none());
        let slant = vec![[0.0, 27.0], [8.0, 27.5], [8.0, 31.0], [0.0, 31.0]];
        assert!(difference(&bar, &[slant], SCALE).is_none());
        let step = vec![vec![vec![
            [0.0, 0.0],
            [8.0, 0.0],
            [8.0, 20.0],
            [4.0, 20.0],
            [4.0, 30.0],
            [0.0, 30.0],
        ]]];
        assert!(difference(&step, &[rect((0.0, 8.0), (25.0, 31.0))], SCALE).is_none());
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(300))]
        /// Random slabs less random horizontal passes: the same shapes as
        /// the boolean's (the same vertices, within the grid), the same
        /// volume.
        #[test]
        fn slabs_less_passes_are_the_booleans(
            z in (0.0f64..3.0, 5.0f64..8.0),
            cuts in proptest::collection::vec((0.0f64..30.0, 0.0f64..8.0, -1.0f64..0.0, 0.0f64..1.0), 1..4),
            passes in proptest::collection::vec((0.0f64..30.5, 0.01f64..12.0, -1.0f64..0.0, 0.0f64..1.0), 1..4),
        ) {
            let g = |v: f64| (v * 1024.0).round() / 1024.0;
            let (za, zb) = (g(z.0), g(z.1));
            let mut shapes = vec![vec![rect((za, zb), (0.0, 30.0))]];
            // Slabs made by the boolean from whole-width cuts.
            for (r, h, _, _) in &cuts {
                shapes = boolean(&shapes, &[rect((za, zb), (g(*r), g((r + h).min(31.0))))]);
            }
            let clips: Vec<Contour> = passes
                .iter()
                // Within the tile's frame (r up to 31 of its 33), as
                // lathe.rs clips every region before the boolean.
                .map(|&(r, h, d0, d1)| rect((za + d0.min(0.0), zb + d1), (r, (r + h).min(31.0))))
                .collect();
            let fast = difference(&shapes, &clips, SCALE);
            proptest::prop_assume!(fast.is_some());
            let (fast, slow) = (fast.unwrap(), boolean(&shapes, &clips));
            let (vf, vs) = (volume(&fast), volume(&slow));
            proptest::prop_assert!((vf - vs).abs() <= 1e-9 * vs.abs().max(1.0), "{vf} {vs}");
            proptest::prop_assert_eq!(fast.len(), slow.len());
            for (f, s) in fast.iter().flatten().zip(slow.iter().flatten()) {
                proptest::prop_assert_eq!(f.len(), s.len());
                for (p, q) in f.iter().zip(s) {
                    let d = (p[0] - q[0]).abs().max((p[1] - q[1]).abs());
                    proptest::prop_assert!(d <= 1.0 / SCALE, "{fast:?} vs {slow:?}");
                }
            }
        }

        /// Random G71-like passes of a round-nosed insert along a bar and
        /// crash checks of random rapids: the same volumes removed, the
        /// same material met and the same section as the boolean alone.
        #[test]
        fn a_section_cut_by_passes_is_the_booleans(
            moves in proptest::collection::vec(
                (proptest::bool::ANY, -40.0f64..2.0, -40.0f64..2.0, 4.0f64..31.0, -0.3f64..0.3),
                1..12,
            ),
        ) {
            let nose: Vec<[f64; 2]> = (0..=16)
                .map(|k| {
                    let a = std::f64::consts::PI * (1.0 + k as f64 / 16.0);
                    [0.8 * a.cos(), 0.8 + 0.8 * a.sin()]
                })
                .chain([[3.0, 6.0], [-3.0, 6.0]])
                .collect();
            let mut fast = Section::new(0.0, 30.0, -40.0, 0.0);
            let mut slow = fast.clone();
            slow.use_slabs(false);
            let mut region = vec![Vec::new()];
            for (write, a, b, r, slope) in moves {
                // Mostly level passes, some slanted or stepped ones.
                let dr = if slope.abs() < 0.15 { 0.0 } else { slope };
                swept_ccw(&nose, (a, r), (b, r + dr), &mut region[0]);
                if write {
                    let (vf, vs) = (fast.sweep_regions(&region, true), slow.sweep_regions(&region, true));
                    proptest::prop_assert!((vf - vs).abs() <= 1e-6, "{vf} vs {vs}");
                } else {
                    let (mf, ms) = (fast.meets(&region), slow.meets(&region));
                    proptest::prop_assert!((mf - ms).abs() <= 1e-6, "{mf} vs {ms}");
                    let (mf, ms) = (fast.meets_unsettled(&region), slow.meets_unsettled(&region));
                    proptest::prop_assert!((mf - ms).abs() <= 1e-6, "{mf} vs {ms}");
                }
            }
            proptest::prop_assert!((fast.volume() - slow.volume()).abs() <= 1e-6);
            proptest::prop_assert_eq!(fast.vertices(), slow.vertices());
            for z in [-39.5, -31.0, -24.0, -17.2, -8.0, -3.3, -0.2] {
                let (a, b) = (fast.intervals_at(z), slow.intervals_at(z));
                proptest::prop_assert_eq!(a.len(), b.len());
                for (p, q) in a.iter().zip(&b) {
                    proptest::prop_assert!((p.0 - q.0).abs().max((p.1 - q.1).abs()) <= 1e-6);
                }
            }
        }
    }
}
