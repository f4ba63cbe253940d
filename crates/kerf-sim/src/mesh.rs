//! Closed triangle meshes of the cut part, handed out one triangle at a
//! time (the STL writer counts them in a first pass, writes them in a
//! second; nothing holds the whole mesh).
//!
//! - Mill: the height field averaged over square blocks of cells, one
//!   vertex per block centre, a border ring on the stock's edge at the
//!   border blocks' heights, two triangles per quad, a vertical skirt
//!   round the edge and a fan bottom. The piecewise-linear top encloses
//!   exactly Σ height × area of the blocks, i.e. the remaining volume.
//! - Lathe: the half section's polygons (merged across tiles) revolved
//!   in N facets with N chosen for a chord error of at most 1 µm; radii
//!   are scaled by the facet factor so that the faceted solid's volume is
//!   the round one's, exactly (each cross-section is an N-gon of the
//!   circle's area).

use std::f64::consts::PI;

use crate::lathe::{Contour, Section};
use crate::zmap::{ZMap, BLOCK};

/// A triangle, counter-clockwise seen from outside.
pub type Tri = [[f32; 3]; 3];

/// Most block-centre vertices of the mill's top surface.
pub const MAX_TOP_VERTICES: usize = 2 << 20;
/// Height a cut-through cell keeps in the mesh above the stock bottom,
/// so that the top never touches the skirt's bottom edge, mm.
pub const THROUGH_GAP: f64 = 1e-4;
/// Chord error of the lathe part's facets, mm.
pub const REVOLVE_TOL: f64 = 1e-3;

/// The block size (cells) the mill mesh uses.
pub fn mill_block(z: &ZMap) -> usize {
    let mut k = 1;
    while k < BLOCK
        && (z.grid.nx / k) * (z.grid.ny / k) > MAX_TOP_VERTICES
        && z.grid.nx.is_multiple_of(2 * k)
        && z.grid.ny.is_multiple_of(2 * k)
    {
        k *= 2;
    }
    k
}

/// Triangles of the mill part.
pub fn mill(z: &ZMap, emit: &mut dyn FnMut(Tri)) {
    let k = mill_block(z);
    let (mx, my) = (z.grid.nx / k, z.grid.ny / k);
    let (bx, by) = (k as f64 * z.grid.dx, k as f64 * z.grid.dy);
    let x1 = z.grid.x0 + z.grid.nx as f64 * z.grid.dx;
    let y1 = z.grid.y0 + z.grid.ny as f64 * z.grid.dy;
    let floor = z.zmin + THROUGH_GAP;
    let height = |bi: usize, bj: usize| -> f64 {
        let mut s = 0.0;
        for j in bj * k..(bj + 1) * k {
            for i in bi * k..(bi + 1) * k {
                s += z.at(i, j);
            }
        }
        (s / (k * k) as f64).max(floor)
    };
    // Vertex (i, j), i in 0..=mx+1: 0 and mx+1 on the edge, else block centres.
    let vx = |i: usize| match i {
        0 => z.grid.x0,
        i if i == mx + 1 => x1,
        i => z.grid.x0 + (i as f64 - 0.5) * bx,
    };
    let vy = |j: usize| match j {
        0 => z.grid.y0,
        j if j == my + 1 => y1,
        j => z.grid.y0 + (j as f64 - 0.5) * by,
    };
    let clampi = |i: usize, m: usize| i.saturating_sub(1).min(m - 1);
    let mut row0: Vec<f64> = (0..mx + 2).map(|i| height(clampi(i, mx), 0)).collect();
    let mut row1 = vec![0.0; mx + 2];
    let p = |i: usize, j: usize, h: f64| [vx(i) as f32, vy(j) as f32, h as f32];
    for j in 0..=my {
        let bj = clampi(j + 1, my);
        for (i, v) in row1.iter_mut().enumerate() {
            *v = height(clampi(i, mx), bj);
        }
        for i in 0..=mx {
            let (a, b) = (p(i, j, row0[i]), p(i + 1, j, row0[i + 1]));
            let (c, d) = (p(i + 1, j + 1, row1[i + 1]), p(i, j + 1, row1[i]));
            emit([a, b, c]);
            emit([a, c, d]);
        }
        std::mem::swap(&mut row0, &mut row1);
    }
    // The border ring, counter-clockwise from above, with its heights.
    let mut ring: Vec<(usize, usize)> = Vec::with_capacity(2 * (mx + my) + 8);
    ring.extend((0..=mx).map(|i| (i, 0)));
    ring.extend((0..=my).map(|j| (mx + 1, j)));
    ring.extend((1..=mx + 1).rev().map(|i| (i, my + 1)));
    ring.extend((1..=my + 1).rev().map(|j| (0, j)));
    let hr = |(i, j): (usize, usize)| height(clampi(i, mx), clampi(j, my));
    let centre = [
        ((z.grid.x0 + x1) / 2.0) as f32,
        ((z.grid.y0 + y1) / 2.0) as f32,
        z.zmin as f32,
    ];
    for n in 0..ring.len() {
        let (a, b) = (ring[n], ring[(n + 1) % ring.len()]);
        let (at, bt) = (p(a.0, a.1, hr(a)), p(b.0, b.1, hr(b)));
        let (ab, bb) = (p(a.0, a.1, z.zmin), p(b.0, b.1, z.zmin));
        emit([ab, bb, bt]);
        emit([ab, bt, at]);
        emit([centre, bb, ab]);
    }
}

/// Facets round the axis for a chord error of [`REVOLVE_TOL`] at radius `r`.
pub fn facets(r: f64) -> usize {
    if r <= REVOLVE_TOL {
        return 8;
    }
    let n = (PI / (1.0 - REVOLVE_TOL / r).acos()).ceil() as usize;
    n.clamp(8, 4096)
}

/// Triangles of the lathe part. The spindle axis is Z; the part lies in
/// work coordinates (X, Y about the axis).
pub fn lathe(s: &Section, emit: &mut dyn FnMut(Tri)) {
    revolve(&s.outline(), 0.0, 2.0 * PI, emit);
}

/// Edges of closed contours, each with the material on its left.
fn edges(loops: &[Contour]) -> Vec<Edge> {
    let mut out = Vec::new();
    for c in loops {
        for (i, p) in c.iter().enumerate() {
            let q = c[(i + 1) % c.len()];
            out.push(((p[0], p[1]), (q[0], q[1])));
        }
    }
    out
}

/// A point (z, r) and a directed edge of the section.
type Edge = ((f64, f64), (f64, f64));

/// The surface swept by the section's edges turning about Z from angle
/// `a0` to `a1` (radians; a full turn closes the solid).
pub fn revolve(loops: &[Contour], a0: f64, a1: f64, emit: &mut dyn FnMut(Tri)) {
    let edges = edges(loops);
    let rmax = edges.iter().map(|e| e.0 .1.max(e.1 .1)).fold(0.0, f64::max);
    let n = facets(rmax);
    // Facet factor: the N-gon of radius r has area (N/2) sin(2π/N) r².
    let f = (n as f64 / 2.0 * (2.0 * PI / n as f64).sin() / PI).sqrt();
    // Facets of 2π/n from `a0`; a full turn reuses its first ring.
    let m = (((a1 - a0) * n as f64 / (2.0 * PI)).round() as usize).clamp(1, n);
    let (cs, sn): (Vec<f64>, Vec<f64>) = (0..=m)
        .map(|i| {
            let a = a0 + 2.0 * PI * (i % n) as f64 / n as f64;
            (a.cos() / f, a.sin() / f)
        })
        .unzip();
    let v = |p: (f64, f64), i: usize| -> [f32; 3] {
        if p.1 == 0.0 {
            return [0.0, 0.0, p.0 as f32];
        }
        [(p.1 * cs[i]) as f32, (p.1 * sn[i]) as f32, p.0 as f32]
    };
    for &(a, b) in &edges {
        if a.1 == 0.0 && b.1 == 0.0 {
            continue;
        }
        for i in 0..m {
            let (pa, qa, pb, qb) = (v(a, i), v(a, i + 1), v(b, i), v(b, i + 1));
            if a.1 != 0.0 {
                emit([pa, pb, qa]);
            }
            if b.1 != 0.0 {
                emit([qa, pb, qb]);
            }
        }
    }
}
