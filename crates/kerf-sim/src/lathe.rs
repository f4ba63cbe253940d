//! The lathe's stock: the part is a solid of revolution, so it is held as
//! its half section in the (Z, radius) plane, exactly: polygons (outer
//! contours counter-clockwise, holes clockwise, with z as the first
//! coordinate and r the second). Each move subtracts the convex region
//! its insert sweeps with i_overlay's boolean difference.
//!
//! The section is cut into tiles of [`TILE`] mm along Z (8 mm: about an
//! insert's length, so a short move rebuilds one or two), each its own set
//! of polygons, so that a move only rebuilds the few tiles it reaches.
//! All coordinates live on one grid of `2^-k` mm (k chosen from the
//! stock's radius so that a tile fits i_overlay's 29-bit integer range;
//! 6e-8 mm for a 60 mm bar): a tile's polygons come back from each
//! boolean unchanged where the move did not touch them, and the tiles'
//! common edges meet exactly when the outline is merged.

use std::f64::consts::PI;

use i_overlay::core::fill_rule::FillRule;
use i_overlay::core::overlay::ShapeType;
use i_overlay::core::overlay_rule::OverlayRule;
use i_overlay::float::overlay::FloatOverlay;
use i_overlay::i_float::adapter::FloatPointAdapter;
use i_overlay::i_float::float::rect::FloatRect;

use std::cell::RefCell;

use crate::deferred::Pending;
use crate::hull::{Hull, Pt};

/// Width of a tile along Z, mm (a multiple of every grid step; 2, 4, 8
/// and 16 measured, 8 the fastest on short and whole-pass moves alike).
pub const TILE: f64 = 8.0;
/// A move that changes a tile's polygons but its volume by no more than
/// this does not touch it, mm³ (a move that does not reach the material
/// leaves the polygons as they were, exactly; one that only grazes them
/// may merge collinear edges).
pub const VOL_EPS: f64 = 1e-12;
/// Depth, in grid steps, that a region's removal from a tile must exceed
/// to be material for a crash check ([`Section::meets`]).
pub const CONTACT_STEPS: f64 = 2.0;
/// Margin of a tile's integer frame beyond its own Z range and the
/// stock's radius, mm.
const MARGIN: f64 = 1.0;
/// Margin around a tile's material to which a swept region is clipped
/// before the boolean, mm (2^-10: a whole number of grid steps).
const CLIP_MARGIN: f64 = 1.0 / 1024.0;

/// A contour: closed, its last point joined to its first.
pub type Contour = Vec<[f64; 2]>;
/// Shapes: each an outer contour followed by its holes.
pub type Shapes = Vec<Vec<Contour>>;

/// One tile: the material with z in [za, za + TILE].
#[derive(Clone, Debug, Default)]
struct Tile {
    za: f64,
    shapes: Shapes,
    /// Least and greatest radius of the material (0, 0 when empty).
    lo: f64,
    hi: f64,
    /// Least and greatest z of the material.
    zlo: f64,
    zhi: f64,
    vol: f64,
}

impl Tile {
    fn set(&mut self, shapes: Shapes, vol: f64) {
        let ps = || shapes.iter().flatten().flatten();
        self.lo = ps().map(|p| p[1]).fold(f64::INFINITY, f64::min);
        self.hi = ps().map(|p| p[1]).fold(f64::NEG_INFINITY, f64::max);
        self.zlo = ps().map(|p| p[0]).fold(f64::INFINITY, f64::min);
        self.zhi = ps().map(|p| p[0]).fold(f64::NEG_INFINITY, f64::max);
        if shapes.is_empty() {
            (self.lo, self.hi, self.zlo, self.zhi) = (0.0, 0.0, 0.0, 0.0);
        }
        self.shapes = shapes;
        self.vol = vol;
    }
}

/// The frame the tiles share: where they start, their integer frame's
/// half height and the grid.
#[derive(Clone, Debug)]
struct Frame {
    z0: f64,
    /// Half height of every tile's integer frame in r (centred on the
    /// axis), mm.
    rr: f64,
    /// Grid: `scale` integer steps per mm, a power of two.
    scale: f64,
    /// Whether a swept region is clipped to the tile's material box (true;
    /// false clips to the tile's frame only, the tests' reference).
    tight_clip: bool,
    /// Whether a slab's cut skips the boolean (slab.rs; true, false the
    /// tests' reference).
    slabs: bool,
}

/// The half section, with the cut still pending on it (deferred.rs):
/// every read applies it first.
#[derive(Clone, Debug)]
pub struct Section {
    frame: Frame,
    tiles: RefCell<Vec<Tile>>,
    pending: RefCell<Pending>,
}

impl Section {
    /// A bar or tube from `z_end` to `z_face`, radii `r_in`..`r_out`.
    pub fn new(r_in: f64, r_out: f64, z_end: f64, z_face: f64) -> Section {
        let rr = (r_out + 2.0 * MARGIN).max(TILE / 2.0 + MARGIN);
        let scale = (2f64.powi(29) / rr).log2().floor().exp2();
        let g = |v: f64| (v * scale).round() / scale;
        let (r_in, r_out, z_end, z_face) = (g(r_in), g(r_out), g(z_end), g(z_face));
        let z0 = (z_end / TILE).floor() * TILE;
        let n = ((z_face - z0) / TILE).ceil().max(1.0) as usize;
        let tiles = (0..n)
            .map(|k| {
                let za = z0 + k as f64 * TILE;
                let (a, b) = (za.max(z_end), (za + TILE).min(z_face));
                let mut t = Tile {
                    za,
                    ..Tile::default()
                };
                if b > a {
                    let c = vec![[a, r_in], [b, r_in], [b, r_out], [a, r_out]];
                    let shapes = vec![vec![c]];
                    let v = volume(&shapes);
                    t.set(shapes, v);
                }
                t
            })
            .collect();
        Section {
            frame: Frame {
                z0,
                rr,
                scale,
                tight_clip: true,
                slabs: true,
            },
            tiles: RefCell::new(tiles),
            pending: RefCell::new(Pending::default()),
        }
    }

    /// Whether a slab's cut skips the boolean (slab.rs; false: the
    /// boolean throughout, the tests' reference).
    #[cfg(test)]
    pub(crate) fn use_slabs(&mut self, on: bool) {
        self.frame.slabs = on;
    }

    /// The grid step of the coordinates, mm.
    pub fn grid(&self) -> f64 {
        1.0 / self.frame.scale
    }

    /// Least and greatest z the section may hold.
    pub fn z_range(&self) -> (f64, f64) {
        let n = self.tiles.borrow().len();
        (self.frame.z0, self.frame.z0 + n as f64 * TILE)
    }

    /// Volume of revolution of the material, mm³ (Pappus, exact for the
    /// polygons).
    pub fn volume(&self) -> f64 {
        self.settle();
        self.tiles.borrow().iter().map(|t| t.vol).sum()
    }

    /// Number of polygon vertices held (the model's memory is about 16
    /// bytes each).
    pub fn vertices(&self) -> usize {
        self.settle();
        self.tiles
            .borrow()
            .iter()
            .flat_map(|t| t.shapes.iter().flatten())
            .map(Vec::len)
            .sum()
    }

    /// Removes (when `write`) the material inside the convex hull `h` and
    /// its mirror about the axis (a sweep that reaches below r = 0 cuts
    /// the other side of the part too), and returns the volume it holds.
    pub fn sweep(&mut self, h: &Hull, write: bool) -> f64 {
        let poly = ccw(h);
        self.sweep_regions(std::slice::from_ref(&poly), write)
    }

    /// [`Self::sweep`] for any region: closed contours, counter-clockwise
    /// ones filled and clockwise ones holes (as i_overlay returns them).
    /// The pending cut is applied first where it may change the material
    /// inside the region's box.
    pub fn sweep_regions(&mut self, region: &[Contour], write: bool) -> f64 {
        let p = self.pending.get_mut();
        if !p.is_empty() && region.iter().any(|c| p.meets(&bbox(c))) {
            self.settle();
        }
        self.frame
            .sweep(self.tiles.get_mut(), region, write)
            .removed
    }

    /// The material `region` meets, for a crash check (nothing changes):
    /// the volume it holds in the tiles where that is more than a layer
    /// [`CONTACT_STEPS`] grid steps deep along the outline of the region
    /// clipped to the tile's material box, revolved at its greatest
    /// radius; 0 when it meets none. The boolean snaps the stock's edges
    /// and the region's to the grid, so a region that only meets the
    /// stock along a surface already cut (a rapid along a finished face,
    /// diameter or taper) may hold a sliver up to about a step wide along
    /// the edges they share, which this leaves out; anything deeper is
    /// material (on a 50 mm bar two steps are 1.2·10⁻⁷ mm). The pending
    /// cut is applied first where it may change the material inside the
    /// region's box.
    pub fn meets(&mut self, region: &[Contour]) -> f64 {
        let p = self.pending.get_mut();
        if !p.is_empty() && region.iter().any(|c| p.meets(&bbox(c))) {
            self.settle();
        }
        self.frame
            .sweep(self.tiles.get_mut(), region, false)
            .material
    }

    /// [`Self::meets`] on the stock as it was before the pending cut: 0
    /// here means 0 there (the pending cut only removes material).
    pub fn meets_unsettled(&mut self, region: &[Contour]) -> f64 {
        self.frame
            .sweep(self.tiles.get_mut(), region, false)
            .material
    }

    /// Removes, later, what the convex `outline` (counter-clockwise)
    /// sweeps along the straight move `a` → `b` (deferred.rs: merged with
    /// the moves it continues, batched with the others).
    pub fn cut_later(&mut self, outline: &[[f64; 2]], a: Pt, b: Pt) {
        if self.pending.get_mut().push(outline, a, b) {
            self.settle();
        }
    }

    /// Whether `outline` swept along `a` → `b` is inside the region the
    /// pending cut's open run removes (it retraces that move), so that it
    /// meets no material once the cut is applied.
    pub fn covered_later(&self, outline: &[[f64; 2]], a: Pt, b: Pt) -> bool {
        self.pending.borrow().covers(outline, a, b)
    }

    /// Whether [`Self::cut_later`] merges and batches moves (true, the
    /// default) or applies each on its own (the move-by-move reference).
    pub fn set_merge(&mut self, on: bool) {
        self.settle();
        self.pending.get_mut().merge = on;
    }

    /// The volume the cuts made with [`Self::cut_later`] removed, mm³
    /// (the pending one applied first).
    pub fn removed_later(&self) -> f64 {
        self.settle();
        self.pending.borrow().removed
    }

    /// Applies the pending cut.
    pub fn settle(&self) {
        let mut p = self.pending.borrow_mut();
        if p.is_empty() {
            return;
        }
        if let Some(regions) = p.regions() {
            let v = self
                .frame
                .sweep(&mut self.tiles.borrow_mut(), regions, true)
                .removed;
            p.removed += v;
        }
        p.clear();
    }

    /// The radius intervals of material on the line z = `z`, sorted.
    pub fn intervals_at(&self, z: f64) -> Vec<(f64, f64)> {
        self.settle();
        let tiles = self.tiles.borrow();
        let k = ((z - self.frame.z0) / TILE).floor();
        if k < 0.0 || k as usize >= tiles.len() {
            return Vec::new();
        }
        let mut rs = Vec::new();
        for c in tiles[k as usize].shapes.iter().flatten() {
            crossings(c, z, &mut rs);
        }
        rs.sort_by(f64::total_cmp);
        rs.chunks_exact(2).map(|w| (w[0], w[1])).collect()
    }

    /// The whole section's outline: the tiles merged (outer contours
    /// counter-clockwise, holes clockwise, so the material is on the left
    /// of every edge).
    pub fn outline(&self) -> Vec<Contour> {
        let (za, zb) = self.z_range();
        let n = self.vertices();
        let tiles = self.tiles.borrow();
        let mut ov = FloatOverlay::<[f64; 2], i64>::with_adapter(self.frame.adapter(za, zb), n);
        for c in tiles.iter().flat_map(|t| t.shapes.iter().flatten()) {
            ov = ov.unsafe_add_contour(c, ShapeType::Subject);
        }
        ov.overlay(OverlayRule::Subject, FillRule::NonZero)
            .into_iter()
            .flatten()
            .collect()
    }
}

/// A contour's bounding box: z from, z to, r from, r to.
pub type Bbox = [f64; 4];

/// The bounding box of a contour (inverted when it is empty).
pub fn bbox(c: &[[f64; 2]]) -> Bbox {
    let mut b = [
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
    ];
    for p in c {
        b = [
            b[0].min(p[0]),
            b[1].max(p[0]),
            b[2].min(p[1]),
            b[3].max(p[1]),
        ];
    }
    b
}

/// What a region holds of the stock: the volume (removed, when written)
/// and, when not written, the part of it that is material for a crash
/// check ([`Section::meets`]), mm³.
#[derive(Clone, Copy, Debug, Default)]
struct Swept {
    removed: f64,
    material: f64,
}

/// The least volume of a tile that the contours `clips` (a region
/// clipped to its material box) hold that is material: a layer
/// [`CONTACT_STEPS`] grid steps of `step` deep along their outline,
/// revolved at their greatest radius.
fn contact_tol(clips: &[Contour], step: f64) -> f64 {
    let (mut perimeter, mut r) = (0.0, 0.0f64);
    for c in clips {
        for (i, p) in c.iter().enumerate() {
            let q = c[(i + 1) % c.len()];
            let (dz, dr) = (q[0] - p[0], q[1] - p[1]);
            perimeter += (dz * dz + dr * dr).sqrt();
            r = r.max(p[1].abs());
        }
    }
    2.0 * PI * r * perimeter * CONTACT_STEPS * step
}

impl Frame {
    /// Removes (when `write`) the material of `tiles` inside `region` and
    /// its mirror about the axis; returns the volume it holds.
    fn sweep(&self, tiles: &mut [Tile], region: &[Contour], write: bool) -> Swept {
        let mut total = Swept::default();
        let boxes: Vec<Bbox> = region.iter().map(|c| bbox(c)).collect();
        let za = boxes.iter().map(|b| b[0]).fold(f64::INFINITY, f64::min);
        let zb = boxes.iter().map(|b| b[1]).fold(f64::NEG_INFINITY, f64::max);
        if za > zb {
            return total;
        }
        let k0 = ((za - self.z0) / TILE).floor().max(0.0) as usize;
        let k1 = ((zb - self.z0) / TILE).floor();
        if k1 < 0.0 || k0 >= tiles.len() {
            return total;
        }
        let k1 = (k1 as usize).min(tiles.len() - 1);
        let half_step = 0.5 / self.scale;
        let below_axis = boxes.iter().any(|b| b[2] < 0.0);
        let mut clips: Vec<Contour> = Vec::new();
        for t in &mut tiles[k0..=k1] {
            if t.shapes.is_empty() {
                continue;
            }
            let (zs, rs) = self.clip_box_of(t);
            let (used, reach) = clip_all(region, &boxes, below_axis, zs, rs, &mut clips);
            let clips = &clips[..used];
            // Neither the region nor its mirror reaches the tile's material.
            if clips.is_empty() || reach.0 > t.hi - half_step || reach.1 < t.lo + half_step {
                continue;
            }
            // A slab less whole-width bands without the boolean (slab.rs);
            // the reference (no tight clip) keeps the boolean throughout.
            let fast = self.tight_clip && self.slabs;
            let shapes = fast
                .then(|| crate::slab::difference(&t.shapes, clips, self.scale))
                .flatten()
                .unwrap_or_else(|| self.difference(t, clips));
            if shapes == t.shapes {
                continue;
            }
            let v = volume(&shapes);
            let removed = t.vol - v;
            if removed > VOL_EPS {
                total.removed += removed;
                // (A check only: a cut is written whatever its depth.)
                if !write && removed > contact_tol(clips, 1.0 / self.scale) {
                    total.material += removed;
                }
                if write {
                    t.set(shapes, v);
                }
            }
        }
        total
    }

    /// The box a swept region is clipped to in tile `t`: its material and
    /// a margin of CLIP_MARGIN (a whole number of grid steps), so that
    /// what the region removes is the same, with fewer edges for the
    /// boolean.
    fn clip_box_of(&self, t: &Tile) -> ((f64, f64), (f64, f64)) {
        let m = CLIP_MARGIN;
        let rmax = self.rr - MARGIN;
        if self.tight_clip {
            (
                (t.za.max(t.zlo - m), (t.za + TILE).min(t.zhi + m)),
                ((t.lo - m).max(0.0), (t.hi + m).min(rmax)),
            )
        } else {
            ((t.za, t.za + TILE), (0.0, rmax))
        }
    }

    /// The tile's integer frame.
    fn adapter<I: i_overlay::core::integer::OverlayInt>(
        &self,
        za: f64,
        zb: f64,
    ) -> FloatPointAdapter<[f64; 2], I> {
        let rect = FloatRect::new(za - MARGIN, zb + MARGIN, -self.rr, self.rr)
            .expect("a tile's frame is finite and ordered");
        FloatPointAdapter::with_scale(rect, self.scale)
    }

    fn difference(&self, t: &Tile, clips: &[Contour]) -> Shapes {
        let n: usize = t.shapes.iter().flatten().map(Vec::len).sum::<usize>()
            + clips.iter().map(Vec::len).sum::<usize>();
        let mut ov = FloatOverlay::<[f64; 2]>::with_adapter(self.adapter(t.za, t.za + TILE), n);
        for c in t.shapes.iter().flatten() {
            ov = ov.unsafe_add_contour(c, ShapeType::Subject);
        }
        for c in clips {
            ov = ov.unsafe_add_contour(c, ShapeType::Clip);
        }
        ov.overlay(OverlayRule::Difference, FillRule::NonZero)
    }
}

/// Every contour of `region` (and its mirror about the axis when
/// `below_axis`) clipped to z in `zs` and r in `rs`, into `clips`
/// (reusing its allocations); returns how many are not empty (the first
/// ones of `clips`) and the least and greatest r they reach. A contour
/// whose box `boxes` misses the box is skipped.
fn clip_all(
    region: &[Contour],
    boxes: &[Bbox],
    below_axis: bool,
    zs: (f64, f64),
    rs: (f64, f64),
    clips: &mut Vec<Contour>,
) -> (usize, (f64, f64)) {
    let signs: &[f64] = if below_axis { &[1.0, -1.0] } else { &[1.0] };
    let mut used = 0;
    let mut reach = (f64::INFINITY, f64::NEG_INFINITY);
    for (poly, b) in region.iter().zip(boxes) {
        if b[1] < zs.0 || b[0] > zs.1 {
            continue;
        }
        for &sign in signs {
            // The r range of the contour or its mirror.
            let (r0, r1) = if sign > 0.0 {
                (b[2], b[3])
            } else {
                (-b[3], -b[2])
            };
            if r1 < rs.0 || r0 > rs.1 {
                continue;
            }
            if used == clips.len() {
                clips.push(Vec::new());
            }
            let c = &mut clips[used];
            clip_box(poly, sign, zs, rs, c);
            for p in c.iter() {
                reach = (reach.0.min(p[1]), reach.1.max(p[1]));
            }
            if c.len() >= 3 {
                used += 1;
            }
        }
    }
    (used, reach)
}

/// The signed area of a closed polygon (positive counter-clockwise), by
/// the shoelace formula: the tests' independent measure of a region.
#[cfg(test)]
pub(crate) fn signed_area(c: &[[f64; 2]]) -> f64 {
    (0..c.len())
        .map(|i| {
            let (p, q) = (c[i], c[(i + 1) % c.len()]);
            p[0] * q[1] - q[0] * p[1]
        })
        .sum::<f64>()
        / 2.0
}

/// A convex hull as one counter-clockwise contour.
pub fn ccw(h: &Hull) -> Contour {
    let mut p: Contour = h.lower.iter().map(|q| [q.0, q.1]).collect();
    let n = h.upper.len();
    if n >= 2 {
        p.extend(h.upper[1..n - 1].iter().rev().map(|q| [q.0, q.1]));
    }
    p
}

/// The r where the closed contour `c` crosses z (edges half open in z,
/// so a vertex on the line counts once).
fn crossings(c: &[[f64; 2]], z: f64, out: &mut Vec<f64>) {
    for (i, p) in c.iter().enumerate() {
        let q = c[(i + 1) % c.len()];
        if (p[0] <= z) != (q[0] <= z) {
            let t = (z - p[0]) / (q[0] - p[0]);
            out.push(p[1] + t * (q[1] - p[1]));
        }
    }
}

/// Volume of revolution about r = 0 of shapes in the (z, r) plane,
/// `2π ∬ r dA` by Green's theorem: `-π/3 Σ (z₂ - z₁)(r₁² + r₁r₂ + r₂²)`
/// over the edges (outer contours counter-clockwise).
pub fn volume(shapes: &Shapes) -> f64 {
    let mut s = 0.0;
    for c in shapes.iter().flatten() {
        for (i, p) in c.iter().enumerate() {
            let q = c[(i + 1) % c.len()];
            s += (q[0] - p[0]) * (p[1] * p[1] + p[1] * q[1] + q[1] * q[1]);
        }
    }
    -PI / 3.0 * s
}

/// The contour `poly` (r multiplied by `sign`: -1 mirrors it about the
/// axis, keeping its orientation) clipped to z in `zs` and r in `rs`,
/// into `out` (Sutherland–Hodgman: the box is convex, the contour need
/// not be).
fn clip_box(poly: &[[f64; 2]], sign: f64, zs: (f64, f64), rs: (f64, f64), out: &mut Contour) {
    out.clear();
    if sign > 0.0 {
        out.extend(poly.iter().copied());
    } else {
        out.extend(poly.iter().rev().map(|p| [p[0], -p[1]]));
    }
    let mut tmp = Vec::with_capacity(out.len() + 4);
    for (axis, v, keep_above) in [
        (0, zs.0, true),
        (0, zs.1, false),
        (1, rs.0, true),
        (1, rs.1, false),
    ] {
        clip_half(out, axis, v, keep_above, &mut tmp);
        std::mem::swap(out, &mut tmp);
        if out.len() < 3 {
            out.clear();
            return;
        }
    }
}

/// Sutherland–Hodgman against one axis-parallel half plane.
fn clip_half(src: &[[f64; 2]], axis: usize, v: f64, above: bool, dst: &mut Contour) {
    dst.clear();
    let inside = |p: &[f64; 2]| if above { p[axis] >= v } else { p[axis] <= v };
    for (i, p) in src.iter().enumerate() {
        let q = &src[(i + 1) % src.len()];
        let (pi, qi) = (inside(p), inside(q));
        if pi {
            dst.push(*p);
        }
        if pi != qi {
            let t = (v - p[axis]) / (q[axis] - p[axis]);
            let mut x = [p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])];
            x[axis] = v;
            dst.push(x);
        }
    }
}

/// The region a convex outline (counter-clockwise, `hull`) sweeps along
/// the straight move p0 → p1, counter-clockwise, into `out`, in linear
/// time: the chain facing the move's direction placed at p1, the chain
/// facing back at p0, joined at the points extreme across the move.
pub fn swept_ccw(hull: &[[f64; 2]], p0: Pt, p1: Pt, out: &mut Contour) {
    out.clear();
    let n = hull.len();
    if n == 0 {
        return;
    }
    let v = (p1.0 - p0.0, p1.1 - p0.1);
    let side = |p: &[f64; 2]| v.0 * p[1] - v.1 * p[0];
    let (mut hi, mut lo) = (0, 0);
    for (i, p) in hull.iter().enumerate() {
        if side(p) > side(&hull[hi]) {
            hi = i;
        }
        if side(p) < side(&hull[lo]) {
            lo = i;
        }
    }
    let at = |i: usize, q: Pt| [hull[i][0] + q.0, hull[i][1] + q.1];
    let mut i = hi;
    loop {
        out.push(at(i, p0));
        if i == lo {
            break;
        }
        i = (i + 1) % n;
    }
    if v.0 == 0.0 && v.1 == 0.0 {
        out.clear();
        out.extend(hull.iter().map(|p| [p[0] + p0.0, p[1] + p0.1]));
        return;
    }
    let mut i = lo;
    loop {
        out.push(at(i, p1));
        if i == hi {
            break;
        }
        i = (i + 1) % n;
    }
}

/// The convex hull of an outline placed at two points (the region a
/// convex tool sweeps along a straight move), into `out`.
pub fn swept(outline: &[Pt], p0: Pt, p1: Pt, scratch: &mut Vec<Pt>, out: &mut Hull) {
    scratch.clear();
    for p in [p0, p1] {
        scratch.extend(outline.iter().map(|q| (q.0 + p.0, q.1 + p.1)));
    }
    Hull::of(scratch, out);
}

#[cfg(test)]
mod tests {
    use super::*;

    fn hull(pts: &[Pt]) -> Hull {
        let mut p = pts.to_vec();
        let mut h = Hull::default();
        Hull::of(&mut p, &mut h);
        h
    }

    #[test]
    fn a_square_swept_along_a_diagonal_is_a_hexagon() {
        // The unit square from (0, 0) to (2, 1): area 1 + |v × diagonal|
        // = 1 + the parallelogram of v and the square's width across v.
        let sq = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let mut out = Vec::new();
        swept_ccw(&sq, (0.0, 0.0), (2.0, 1.0), &mut out);
        let a: f64 = (0..out.len())
            .map(|i| {
                let (p, q) = (out[i], out[(i + 1) % out.len()]);
                p[0] * q[1] - q[0] * p[1]
            })
            .sum::<f64>()
            / 2.0;
        // Width across v = (2, 1)/√5: the square's extent (1·1 + 1·2)/√5.
        assert!((a - (1.0 + 3.0)).abs() < 1e-12, "{a} {out:?}");
        let mut h = Hull::default();
        let mut scratch = Vec::new();
        swept(
            &[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)],
            (0.0, 0.0),
            (2.0, 1.0),
            &mut scratch,
            &mut h,
        );
        let mut s = Section::new(0.0, 10.0, -20.0, 0.0);
        let mut t = s.clone();
        let mut c = out.clone();
        for p in c.iter_mut() {
            p[0] -= 8.0;
            p[1] += 8.0;
        }
        let mut hh = Hull::default();
        let mut pts: Vec<Pt> = h
            .lower
            .iter()
            .chain(&h.upper)
            .map(|p| (p.0 - 8.0, p.1 + 8.0))
            .collect();
        Hull::of(&mut pts, &mut hh);
        let (v1, v2) = (s.sweep_regions(&[c], true), t.sweep(&hh, true));
        assert!((v1 - v2).abs() < 1e-9 && v1 > 0.0, "{v1} {v2}");
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(150))]
        /// Random moves of a round-nosed insert over a tube: the region
        /// clipped to each tile's material box removes what the region
        /// clipped to the tile's frame removes, move by move, and leaves
        /// the same section, to within the grid: a clipped edge starts at
        /// its crossing of the box snapped to the grid (about 1e-7 mm), so
        /// where it meets the material may move by a few grid steps.
        #[test]
        fn clipping_to_the_material_changes_nothing(
            moves in proptest::collection::vec(
                ((-30.0f64..4.0, -2.0f64..16.0), (-30.0f64..4.0, -2.0f64..16.0)),
                1..6,
            ),
        ) {
            let nose: Vec<Pt> = (0..=16)
                .map(|k| {
                    let a = std::f64::consts::PI * (1.0 + k as f64 / 16.0);
                    (0.8 * a.cos(), 0.8 + 0.8 * a.sin())
                })
                .chain([(3.0, 6.0), (-3.0, 6.0)])
                .collect();
            let mut fast = Section::new(3.0, 12.0, -24.0, 0.0);
            let mut slow = fast.clone();
            slow.frame.tight_clip = false;
            let (mut region, mut h, mut scratch) = (Vec::new(), Hull::default(), Vec::new());
            for (a, b) in moves {
                swept(&nose, a, b, &mut scratch, &mut h);
                region.clear();
                region.push(ccw(&h));
                let (vf, vs) = (fast.sweep_regions(&region, true), slow.sweep_regions(&region, true));
                proptest::prop_assert!((vf - vs).abs() < 1e-4, "{vf} vs {vs}");
            }
            proptest::prop_assert!((fast.volume() - slow.volume()).abs() < 1e-4);
            // An interval's end is where the line z = const crosses an
            // edge; where that edge is nearly along the line a shift of
            // 1e-7 moves the crossing far more, so each end is judged by
            // its distance to the other section's outline.
            let (out_f, out_s) = (fast.outline(), slow.outline());
            for z in [-23.5, -17.0, -8.0, -3.3, -0.5] {
                let (a, b) = (fast.intervals_at(z), slow.intervals_at(z));
                proptest::prop_assert_eq!(a.len(), b.len());
                for ((p, q), (i, j)) in a.iter().zip(&b).flat_map(|(p, q)| {
                    [((p.0, q.0), (&out_s, &out_f)), ((p.1, q.1), (&out_s, &out_f))]
                }) {
                    let d = distance_to_outline([z, p], i).max(distance_to_outline([z, q], j));
                    proptest::prop_assert!(d < 1e-6, "{a:?} vs {b:?} at z {z}");
                }
            }
        }
    }

    /// The shortest distance from `p` to an edge of `outline`.
    fn distance_to_outline(p: [f64; 2], outline: &[Contour]) -> f64 {
        let mut best = f64::INFINITY;
        for c in outline {
            for (k, a) in c.iter().enumerate() {
                let b = c[(k + 1) % c.len()];
                let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
                let len2 = dx * dx + dy * dy;
                let t = if len2 > 0.0 {
                    (((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2).clamp(0.0, 1.0)
                } else {
                    0.0
                };
                let (ex, ey) = (a[0] + t * dx - p[0], a[1] + t * dy - p[1]);
                best = best.min((ex * ex + ey * ey).sqrt());
            }
        }
        best
    }

    #[test]
    fn pappus_volume_of_a_rectangle_and_a_triangle() {
        // Rectangle z 0..10, r 2..5: π (25 - 4) 10.
        let r = vec![vec![vec![[0.0, 2.0], [10.0, 2.0], [10.0, 5.0], [0.0, 5.0]]]];
        assert!((volume(&r) - PI * 21.0 * 10.0).abs() < 1e-9);
        // A cone: triangle (0,0) (h,0) (0,R) revolved: π R² h / 3.
        let t = vec![vec![vec![[0.0, 0.0], [6.0, 0.0], [0.0, 3.0]]]];
        assert!((volume(&t) - PI * 9.0 * 6.0 / 3.0).abs() < 1e-9);
    }

    #[test]
    fn a_rectangle_through_the_axis_cuts_both_sides() {
        // A bar r 10, z -20..0; a box z -5..-3, r -4..2 folds to r 0..4.
        let mut s = Section::new(0.0, 10.0, -20.0, 0.0);
        let v = s.sweep(
            &hull(&[(-5.0, -4.0), (-3.0, -4.0), (-3.0, 2.0), (-5.0, 2.0)]),
            true,
        );
        assert!((v - PI * 16.0 * 2.0).abs() < 1e-6, "{v}");
        assert_eq!(s.intervals_at(-4.0), vec![(4.0, 10.0)]);
        assert_eq!(s.intervals_at(-6.0), vec![(0.0, 10.0)]);
        assert!((s.volume() - PI * 100.0 * 20.0 + v).abs() < 1e-6);
    }

    #[test]
    fn a_groove_across_a_tile_edge_merges_into_one_outline() {
        // Tiles are 8 mm from z -24: a groove z -10..-6 r 6..11 spans the
        // edge at z -8 and leaves one outline of 8 vertices.
        let mut s = Section::new(0.0, 10.0, -20.0, 0.0);
        let v = s.sweep(
            &hull(&[(-5.0, 6.0), (-1.0, 6.0), (-1.0, 11.0), (-5.0, 11.0)]),
            true,
        );
        assert!((v - PI * (100.0 - 36.0) * 4.0).abs() < 1e-6, "{v}");
        let o = s.outline();
        assert_eq!(o.len(), 1, "{o:?}");
        assert_eq!(o[0].len(), 8, "{o:?}");
        // A second pass over the same region removes nothing.
        let again = s.sweep(
            &hull(&[(-5.0, 6.0), (-1.0, 6.0), (-1.0, 11.0), (-5.0, 11.0)]),
            true,
        );
        assert_eq!(again, 0.0);
    }
}
