//! The lathe's pending cut: feed moves whose material the section has not
//! removed yet, so that several moves cost one boolean per tile instead
//! of one each.
//!
//! Two steps, both exact:
//!
//! - a **run**: consecutive moves of the same outline, each starting where
//!   the last ended and going on in the same direction along the same
//!   line, sweep together the region the outline sweeps from the run's
//!   start to its end (a convex outline translated along a segment sweeps
//!   the union of what it sweeps along the segment's pieces);
//! - a **batch**: the swept regions of up to [`BATCH`] runs (or
//!   [`BATCH_VERTICES`] vertices) removed in one boolean per tile, their
//!   union being the clip (removing A then B from the stock removes what
//!   removing A ∪ B does).
//!
//! Whatever reads the stock applies the pending cut first
//! (`lathe::Section`); a crash check applies it only where its box meets
//! the region checked ([`Pending::meets`]; elsewhere the stock is the same
//! with it or without), the holder's is first made against the stock
//! without it (which holds at least the material: nothing there, nothing
//! after), and a move retracing the open run ([`Pending::covers`]) meets
//! nothing (sim.rs).

use crate::hull::Pt;
use crate::lathe::{bbox, swept_ccw, Bbox, Contour};

/// Runs held before the batch is applied (1, 4, 8 and 16 measured: 8
/// the fewest instructions on whole G71 passes and on pecked grooves;
/// a batch's regions overlap, and their crossings cost the boolean too).
pub const BATCH: usize = 8;
/// Vertices held before the batch is applied.
pub const BATCH_VERTICES: usize = 1024;
/// How far a point may be from the run's line (and from its end, for the
/// next move's start) and still continue it, mm: far below the section's
/// grid (about 6e-8 mm on a 60 mm bar).
const ON_LINE: f64 = 1e-9;

/// The open run: one outline swept from `a` to `b` (no run when the
/// outline is empty).
#[derive(Clone, Debug, Default)]
struct Run {
    outline: Contour,
    /// The outline's box.
    obox: Bbox,
    a: Pt,
    b: Pt,
}

/// The pending cut.
#[derive(Clone, Debug)]
pub struct Pending {
    run: Run,
    /// Swept regions of the closed runs, counter-clockwise.
    batch: Vec<Contour>,
    /// Spare contours (allocations kept between batches).
    spare: Vec<Contour>,
    vertices: usize,
    /// The closed runs' regions' box, folded about the axis ([`fold`]).
    batch_box: Bbox,
    /// Whether moves are merged and batched (false: each move is applied
    /// on its own, the move-by-move reference).
    pub merge: bool,
    /// Volume the applied batches removed, mm³.
    pub removed: f64,
}

impl Default for Pending {
    fn default() -> Pending {
        Pending {
            run: Run::default(),
            batch: Vec::new(),
            spare: Vec::new(),
            vertices: 0,
            batch_box: EMPTY,
            merge: true,
            removed: 0.0,
        }
    }
}

impl Pending {
    /// Whether nothing is pending.
    pub fn is_empty(&self) -> bool {
        self.run.outline.is_empty() && self.batch.is_empty()
    }

    /// Adds the cut of `outline` (convex, counter-clockwise) swept from
    /// `a` to `b`; true when the batch should now be applied.
    pub fn push(&mut self, outline: &[[f64; 2]], a: Pt, b: Pt) -> bool {
        if self.merge && continues(&self.run, outline, a, b) {
            self.run.b = b;
            return false;
        }
        self.close_run();
        let r = &mut self.run;
        r.outline.extend_from_slice(outline);
        r.obox = bbox(outline);
        (r.a, r.b) = (a, b);
        !self.merge || self.batch.len() + 1 >= BATCH || self.vertices >= BATCH_VERTICES
    }

    /// Whether `outline` swept from `a` to `b` stays inside the open run's
    /// swept region (both ends on the run's segment: the move retraces
    /// part of it), so that it meets no material once the pending cut is
    /// applied.
    pub fn covers(&self, outline: &[[f64; 2]], a: Pt, b: Pt) -> bool {
        let r = &self.run;
        !r.outline.is_empty() && r.outline == outline && on_segment(r, a) && on_segment(r, b)
    }

    /// Whether the pending cut may change the material inside the box
    /// `b` (z from, z to, r from, r to; both folded about the axis, as
    /// the cut removes the mirror of what reaches below it).
    pub fn meets(&self, b: &Bbox) -> bool {
        let b = fold(b);
        let r = &self.run;
        let run_box = if r.outline.is_empty() {
            EMPTY
        } else {
            let o = &r.obox;
            fold(&[
                o[0] + r.a.0.min(r.b.0),
                o[1] + r.a.0.max(r.b.0),
                o[2] + r.a.1.min(r.b.1),
                o[3] + r.a.1.max(r.b.1),
            ])
        };
        [self.batch_box, run_box]
            .iter()
            .any(|p| p[0] <= b[1] && b[0] <= p[1] && p[2] <= b[3] && b[2] <= p[3])
    }

    /// The swept regions to remove (the open run closed), or None when
    /// nothing is pending. [`Self::clear`] after applying them.
    pub fn regions(&mut self) -> Option<&[Contour]> {
        self.close_run();
        (!self.batch.is_empty()).then_some(&self.batch[..])
    }

    /// Forgets the batch once applied.
    pub fn clear(&mut self) {
        self.spare.append(&mut self.batch);
        self.vertices = 0;
        self.batch_box = EMPTY;
    }

    /// Moves the open run's swept region into the batch.
    fn close_run(&mut self) {
        let r = &mut self.run;
        if r.outline.is_empty() {
            return;
        }
        let mut c = self.spare.pop().unwrap_or_default();
        swept_ccw(&r.outline, r.a, r.b, &mut c);
        self.vertices += c.len();
        let b = fold(&bbox(&c));
        let u = &mut self.batch_box;
        *u = [
            u[0].min(b[0]),
            u[1].max(b[1]),
            u[2].min(b[2]),
            u[3].max(b[3]),
        ];
        self.batch.push(c);
        // The run's allocation is kept for the next one.
        r.outline.clear();
    }
}

/// Whether the move a → b of `outline` continues the run `r`: the same
/// outline, starting at the run's end, going on along its line.
fn continues(r: &Run, outline: &[[f64; 2]], a: Pt, b: Pt) -> bool {
    if r.outline.is_empty() || r.outline != outline {
        return false;
    }
    let near = |p: Pt, q: Pt| (p.0 - q.0).abs() <= ON_LINE && (p.1 - q.1).abs() <= ON_LINE;
    if !near(a, r.b) {
        return false;
    }
    let u = (r.b.0 - r.a.0, r.b.1 - r.a.1);
    let v = (b.0 - r.b.0, b.1 - r.b.1);
    let len = u.0.hypot(u.1);
    if len == 0.0 {
        return false;
    }
    // The new end on the run's line (its distance from it) and ahead.
    let off = (u.0 * (b.1 - r.a.1) - u.1 * (b.0 - r.a.0)).abs() / len;
    off <= ON_LINE && u.0 * v.0 + u.1 * v.1 >= 0.0
}

/// The box of nothing.
const EMPTY: Bbox = [
    f64::INFINITY,
    f64::NEG_INFINITY,
    f64::INFINITY,
    f64::NEG_INFINITY,
];

/// A box with r replaced by |r| (what a region that reaches below the
/// axis cuts is its mirror above it).
fn fold(b: &Bbox) -> Bbox {
    if b[2] >= 0.0 || b[2] > b[3] {
        *b
    } else if b[3] <= 0.0 {
        [b[0], b[1], -b[3], -b[2]]
    } else {
        [b[0], b[1], 0.0, (-b[2]).max(b[3])]
    }
}

/// Whether `p` is on the run's segment (within [`ON_LINE`]).
fn on_segment(r: &Run, p: Pt) -> bool {
    let u = (r.b.0 - r.a.0, r.b.1 - r.a.1);
    let w = (p.0 - r.a.0, p.1 - r.a.1);
    let len = u.0.hypot(u.1);
    if len == 0.0 {
        return w.0.hypot(w.1) <= ON_LINE;
    }
    let along = (u.0 * w.0 + u.1 * w.1) / len;
    let off = (u.0 * w.1 - u.1 * w.0).abs() / len;
    off <= ON_LINE && (-ON_LINE..=len + ON_LINE).contains(&along)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lathe::signed_area;

    const SQ: [[f64; 2]; 4] = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];

    #[test]
    fn collinear_moves_are_one_swept_region() {
        // A unit square moved 1 + 2 + 3 along z: one region of area
        // 1 + 6 (the square's height times the travel).
        let mut p = Pending::default();
        assert!(!p.push(&SQ, (0.0, 0.0), (1.0, 0.0)));
        assert!(!p.push(&SQ, (1.0, 0.0), (3.0, 0.0)));
        assert!(!p.push(&SQ, (3.0, 0.0), (6.0, 0.0)));
        let r = p.regions().unwrap();
        assert_eq!(r.len(), 1);
        assert!((signed_area(&r[0]) - 7.0).abs() < 1e-12, "{r:?}");
    }

    #[test]
    fn a_turn_a_jump_a_reversal_or_another_outline_starts_a_run() {
        let mut p = Pending::default();
        let other = [[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [0.0, 1.0]];
        p.push(&SQ, (0.0, 0.0), (1.0, 0.0));
        p.push(&SQ, (1.0, 0.0), (2.0, 1e-6)); // turns by 1 µm over 1 mm
        p.push(&SQ, (2.0, 1e-6), (1.0, 1e-6)); // back
        p.push(&SQ, (5.0, 1e-6), (4.0, 1e-6)); // elsewhere
        p.push(&other, (4.0, 1e-6), (3.0, 1e-6));
        assert_eq!(p.regions().unwrap().len(), 5);
        p.clear();
        assert!(p.regions().is_none() && p.is_empty());
    }

    #[test]
    fn a_move_back_along_the_open_run_is_covered_by_it() {
        let mut p = Pending::default();
        p.push(&SQ, (0.0, 0.0), (0.0, -4.0));
        assert!(p.covers(&SQ, (0.0, -4.0), (0.0, -3.9)));
        assert!(p.covers(&SQ, (0.0, -1.0), (0.0, 0.0)));
        assert!(!p.covers(&SQ, (0.0, -4.0), (0.0, 0.1)), "beyond its start");
        assert!(!p.covers(&SQ, (0.0, -4.0), (1e-6, -3.0)), "off its line");
        assert!(!p.covers(
            &[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]],
            (0.0, -4.0),
            (0.0, -3.0)
        ));
        p.regions();
        assert!(!p.covers(&SQ, (0.0, -4.0), (0.0, -3.9)), "closed");
    }

    #[test]
    fn the_pending_box_is_the_runs_and_the_batchs_folded_about_the_axis() {
        let mut p = Pending::default();
        assert!(!p.meets(&[-1e9, 1e9, -1e9, 1e9]));
        // The square swept z 0..5 at r 2..3, then z 10..11 at r -3..-2.
        p.push(&SQ, (0.0, 2.0), (4.0, 2.0));
        assert!(p.meets(&[4.9, 6.0, 2.5, 2.6]));
        assert!(!p.meets(&[5.1, 6.0, 0.0, 9.0]));
        p.push(&SQ, (10.0, -3.0), (10.0, -3.0));
        // Its mirror r 2..3 (the first now in the batch).
        assert!(p.meets(&[10.5, 10.6, 2.1, 2.2]) && p.meets(&[0.5, 0.6, -2.6, -2.5]));
        assert!(!p.meets(&[6.0, 9.0, 0.0, 9.0]) && !p.meets(&[0.0, 12.0, 3.5, 9.0]));
    }

    #[test]
    fn the_batch_is_full_after_its_runs_and_every_move_without_merging() {
        let mut p = Pending::default();
        let full: Vec<bool> = (0..BATCH)
            .map(|k| p.push(&SQ, (k as f64 * 10.0, 0.0), (k as f64 * 10.0, 1.0)))
            .collect();
        assert_eq!(full.iter().filter(|f| **f).count(), 1);
        assert!(full[BATCH - 1]);
        let mut q = Pending {
            merge: false,
            ..Pending::default()
        };
        assert!(q.push(&SQ, (0.0, 0.0), (1.0, 0.0)));
        q.regions();
        q.clear();
        assert!(q.push(&SQ, (1.0, 0.0), (2.0, 0.0)));
        assert_eq!(q.regions().unwrap().len(), 1);
    }
}
