//! Binary STL of the cut part, and the checks the tests (and anyone) can
//! run on an STL: every edge shared by exactly two triangles, and the
//! enclosed volume by the divergence theorem.

use std::collections::HashMap;
use std::io::{self, Write};

use crate::mesh::{self, Tri};
use crate::sim::{Model, Sim};

/// Calls `emit` with every triangle of the part.
pub fn triangles(sim: &Sim, emit: &mut dyn FnMut(Tri)) {
    match sim.model() {
        Model::Mill(z) => mesh::mill(z, emit),
        Model::Lathe(s) => mesh::lathe(s, emit),
    }
}

/// Writes the part as binary STL: 80-byte header, count, and 50 bytes per
/// triangle (normal, three vertices, attribute 0).
pub fn write(sim: &Sim, w: &mut dyn Write) -> io::Result<u64> {
    let mut n: u64 = 0;
    triangles(sim, &mut |_| n += 1);
    if n > u32::MAX as u64 {
        return Err(io::Error::other("more than 2^32 triangles"));
    }
    let mut head = [0u8; 80];
    let text = b"kerf-sim cut part, mm, work coordinates";
    head[..text.len()].copy_from_slice(text);
    w.write_all(&head)?;
    w.write_all(&(n as u32).to_le_bytes())?;
    let mut err = None;
    let mut buf = Vec::with_capacity(50 * 4096);
    triangles(sim, &mut |t| {
        if err.is_some() {
            return;
        }
        let nrm = normal(&t);
        for v in std::iter::once(nrm).chain(t) {
            for c in v {
                buf.extend_from_slice(&c.to_le_bytes());
            }
        }
        buf.extend_from_slice(&[0, 0]);
        if buf.len() >= 50 * 4096 {
            if let Err(e) = w.write_all(&buf) {
                err = Some(e);
            }
            buf.clear();
        }
    });
    if let Some(e) = err {
        return Err(e);
    }
    w.write_all(&buf)?;
    Ok(n)
}

fn normal(t: &Tri) -> [f32; 3] {
    let a = [t[1][0] - t[0][0], t[1][1] - t[0][1], t[1][2] - t[0][2]];
    let b = [t[2][0] - t[0][0], t[2][1] - t[0][1], t[2][2] - t[0][2]];
    let c = [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ];
    let l = (c[0] * c[0] + c[1] * c[1] + c[2] * c[2]).sqrt();
    if l > 0.0 {
        [c[0] / l, c[1] / l, c[2] / l]
    } else {
        [0.0; 3]
    }
}

/// What [`check`] found in an STL.
#[derive(Clone, Debug, PartialEq)]
pub struct StlCheck {
    pub triangles: usize,
    /// Edges not shared by exactly two triangles.
    pub bad_edges: usize,
    /// Edges used twice in the same direction (inconsistent orientation).
    pub flipped_edges: usize,
    /// Enclosed volume, Σ v0 · (v1 × v2) / 6, mm³.
    pub volume: f64,
}

/// Reads a binary STL and checks it; None if it is not one.
pub fn check(bytes: &[u8]) -> Option<StlCheck> {
    let n = u32::from_le_bytes(bytes.get(80..84)?.try_into().ok()?) as usize;
    if bytes.len() != 84 + 50 * n {
        return None;
    }
    let mut edges: HashMap<([u32; 3], [u32; 3]), (u32, u32)> = HashMap::new();
    let mut volume = 0.0;
    for k in 0..n {
        let o = 84 + 50 * k + 12;
        let mut v = [[0f32; 3]; 3];
        for (i, vi) in v.iter_mut().enumerate() {
            for (c, x) in vi.iter_mut().enumerate() {
                let p = o + 12 * i + 4 * c;
                *x = f32::from_le_bytes(bytes[p..p + 4].try_into().ok()?);
            }
        }
        let d: Vec<[f64; 3]> = v
            .iter()
            .map(|p| [p[0] as f64, p[1] as f64, p[2] as f64])
            .collect();
        volume += (d[0][0] * (d[1][1] * d[2][2] - d[1][2] * d[2][1])
            - d[0][1] * (d[1][0] * d[2][2] - d[1][2] * d[2][0])
            + d[0][2] * (d[1][0] * d[2][1] - d[1][1] * d[2][0]))
            / 6.0;
        for i in 0..3 {
            let a = v[i].map(f32::to_bits);
            let b = v[(i + 1) % 3].map(f32::to_bits);
            let (key, fwd) = if a < b {
                ((a, b), true)
            } else {
                ((b, a), false)
            };
            let e = edges.entry(key).or_insert((0, 0));
            if fwd {
                e.0 += 1;
            } else {
                e.1 += 1;
            }
        }
    }
    let bad_edges = edges.values().filter(|(f, b)| f + b != 2).count();
    let flipped_edges = edges
        .values()
        .filter(|(f, b)| f + b == 2 && *f != 1)
        .count();
    Some(StlCheck {
        triangles: n,
        bad_edges,
        flipped_edges,
        volume,
    })
}
