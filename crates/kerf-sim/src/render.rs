//! PNG pictures of the cut part, drawn on the CPU: the mill part shaded
//! in an isometric view; the lathe part as its half section beside a
//! shaded three-quarter view. Collision points are marked with red rings.

use std::io::{self, Write};

use std::f64::consts::PI;

use crate::mesh::{self, Tri};
use crate::sim::{Model, Sim};
use crate::trapezoids::trapezoids;

/// An RGB picture with a depth buffer.
pub struct Canvas {
    pub w: usize,
    pub h: usize,
    pub rgb: Vec<u8>,
    depth: Vec<f32>,
}

const BACKGROUND: [u8; 3] = [250, 250, 247];
const STOCK: [f64; 3] = [150.0, 162.0, 178.0];
const CUT: [f64; 3] = [214.0, 170.0, 92.0];
/// The lathe picture's cut-away faces.
const SECTION: [f64; 3] = [196.0, 96.0, 80.0];
const MARK: [u8; 3] = [220, 20, 20];

impl Canvas {
    /// A blank picture.
    pub fn new(w: usize, h: usize) -> Canvas {
        let mut rgb = vec![0; w * h * 3];
        for p in rgb.chunks_mut(3) {
            p.copy_from_slice(&BACKGROUND);
        }
        Canvas {
            w,
            h,
            rgb,
            depth: vec![f32::NEG_INFINITY; w * h],
        }
    }

    /// Sets a pixel (ignored outside).
    pub fn put(&mut self, x: i64, y: i64, c: [u8; 3]) {
        if x >= 0 && y >= 0 && (x as usize) < self.w && (y as usize) < self.h {
            let i = (y as usize * self.w + x as usize) * 3;
            self.rgb[i..i + 3].copy_from_slice(&c);
        }
    }

    /// The colour at a pixel.
    pub fn get(&self, x: usize, y: usize) -> [u8; 3] {
        let i = (y * self.w + x) * 3;
        [self.rgb[i], self.rgb[i + 1], self.rgb[i + 2]]
    }

    /// A ring with a cross, `r` pixels, for a collision point.
    pub fn mark(&mut self, x: f64, y: f64, r: f64) {
        let steps = (r * 8.0) as usize + 8;
        for k in 0..steps {
            let a = k as f64 / steps as f64 * std::f64::consts::TAU;
            for dr in [-1.0, 0.0, 1.0] {
                self.put(
                    (x + (r + dr) * a.cos()).round() as i64,
                    (y + (r + dr) * a.sin()).round() as i64,
                    MARK,
                );
            }
        }
        for d in -(r as i64) / 2..=(r as i64) / 2 {
            self.put(x.round() as i64 + d, y.round() as i64, MARK);
            self.put(x.round() as i64, y.round() as i64 + d, MARK);
        }
    }

    /// Fills a triangle given in screen coordinates (x, y, depth; larger
    /// depth is nearer) with one colour, depth-tested.
    fn fill(&mut self, p: [[f64; 3]; 3], c: [u8; 3]) {
        let x0 = p
            .iter()
            .map(|v| v[0])
            .fold(f64::INFINITY, f64::min)
            .floor()
            .max(0.0) as i64;
        let x1 = p
            .iter()
            .map(|v| v[0])
            .fold(f64::NEG_INFINITY, f64::max)
            .ceil()
            .min(self.w as f64 - 1.0) as i64;
        let y0 = p
            .iter()
            .map(|v| v[1])
            .fold(f64::INFINITY, f64::min)
            .floor()
            .max(0.0) as i64;
        let y1 = p
            .iter()
            .map(|v| v[1])
            .fold(f64::NEG_INFINITY, f64::max)
            .ceil()
            .min(self.h as f64 - 1.0) as i64;
        let area =
            (p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[1][1] - p[0][1]) * (p[2][0] - p[0][0]);
        if area.abs() < 1e-12 {
            return;
        }
        for y in y0..=y1 {
            for x in x0..=x1 {
                let (px, py) = (x as f64 + 0.5, y as f64 + 0.5);
                let w0 = ((p[1][0] - px) * (p[2][1] - py) - (p[1][1] - py) * (p[2][0] - px)) / area;
                let w1 = ((p[2][0] - px) * (p[0][1] - py) - (p[2][1] - py) * (p[0][0] - px)) / area;
                let w2 = 1.0 - w0 - w1;
                if w0 < -1e-9 || w1 < -1e-9 || w2 < -1e-9 {
                    continue;
                }
                let d = (w0 * p[0][2] + w1 * p[1][2] + w2 * p[2][2]) as f32;
                let i = y as usize * self.w + x as usize;
                if d > self.depth[i] {
                    self.depth[i] = d;
                    self.rgb[i * 3..i * 3 + 3].copy_from_slice(&c);
                }
            }
        }
    }

    /// Encodes the picture as PNG.
    pub fn write_png(&self, w: &mut dyn Write) -> io::Result<()> {
        let mut enc = png::Encoder::new(w, self.w as u32, self.h as u32);
        enc.set_color(png::ColorType::Rgb);
        enc.set_depth(png::BitDepth::Eight);
        let mut wr = enc.write_header().map_err(io::Error::other)?;
        wr.write_image_data(&self.rgb).map_err(io::Error::other)?;
        wr.finish().map_err(io::Error::other)
    }
}

/// An orthographic camera: `toward` points from the scene to the eye.
pub struct View {
    right: [f64; 3],
    up: [f64; 3],
    toward: [f64; 3],
    scale: f64,
    off: (f64, f64),
}

fn norm(v: [f64; 3]) -> [f64; 3] {
    let l = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    [v[0] / l, v[1] / l, v[2] / l]
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

impl View {
    /// A camera looking along -`toward` with `world_up` up, fitting the box
    /// `lo`..`hi` into the rectangle (x0, y0, w, h) of the canvas.
    pub fn fit(
        toward: [f64; 3],
        world_up: [f64; 3],
        lo: [f64; 3],
        hi: [f64; 3],
        rect: (f64, f64, f64, f64),
    ) -> View {
        let toward = norm(toward);
        let right = norm(cross(world_up, toward));
        let up = cross(toward, right);
        let mut v = View {
            right,
            up,
            toward,
            scale: 1.0,
            off: (0.0, 0.0),
        };
        let (mut a, mut b) = (
            (f64::INFINITY, f64::INFINITY),
            (f64::NEG_INFINITY, f64::NEG_INFINITY),
        );
        for k in 0..8 {
            let p = [
                if k & 1 == 0 { lo[0] } else { hi[0] },
                if k & 2 == 0 { lo[1] } else { hi[1] },
                if k & 4 == 0 { lo[2] } else { hi[2] },
            ];
            let (x, y) = (dot(p, right), -dot(p, up));
            a = (a.0.min(x), a.1.min(y));
            b = (b.0.max(x), b.1.max(y));
        }
        let s =
            ((rect.2 * 0.9) / (b.0 - a.0).max(1e-9)).min((rect.3 * 0.9) / (b.1 - a.1).max(1e-9));
        v.scale = s;
        v.off = (
            rect.0 + rect.2 / 2.0 - s * (a.0 + b.0) / 2.0,
            rect.1 + rect.3 / 2.0 - s * (a.1 + b.1) / 2.0,
        );
        v
    }

    /// Screen position and depth of a point.
    pub fn project(&self, p: [f64; 3]) -> [f64; 3] {
        [
            self.off.0 + self.scale * dot(p, self.right),
            self.off.1 - self.scale * dot(p, self.up),
            dot(p, self.toward),
        ]
    }

    /// Draws a triangle shaded by its normal; `cut` picks the cut colour.
    pub fn shade(&self, c: &mut Canvas, t: &Tri, cut: bool) {
        self.shade_as(c, t, if cut { CUT } else { STOCK });
    }

    /// Draws a triangle shaded by its normal in the colour `base`.
    pub fn shade_as(&self, c: &mut Canvas, t: &Tri, base: [f64; 3]) {
        let p: Vec<[f64; 3]> = t
            .iter()
            .map(|v| [v[0] as f64, v[1] as f64, v[2] as f64])
            .collect();
        let n = cross(
            [p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]],
            [p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]],
        );
        let l = dot(n, n).sqrt();
        if l == 0.0 {
            return;
        }
        let n = [n[0] / l, n[1] / l, n[2] / l];
        let light = norm([
            self.toward[0] + 0.4 * self.up[0] - 0.3 * self.right[0],
            self.toward[1] + 0.4 * self.up[1] - 0.3 * self.right[1],
            self.toward[2] + 0.4 * self.up[2] - 0.3 * self.right[2],
        ]);
        let k = 0.3 + 0.7 * dot(n, light).abs();
        let col = [
            (base[0] * k) as u8,
            (base[1] * k) as u8,
            (base[2] * k) as u8,
        ];
        c.fill(
            [self.project(p[0]), self.project(p[1]), self.project(p[2])],
            col,
        );
    }
}

/// Draws the simulation's picture.
pub fn render(sim: &Sim) -> Canvas {
    match sim.model() {
        Model::Mill(_) => mill(sim),
        Model::Lathe(_) => lathe(sim),
    }
}

fn mill(sim: &Sim) -> Canvas {
    let Model::Mill(z) = sim.model() else {
        unreachable!()
    };
    let mut c = Canvas::new(1200, 900);
    let lo = [z.grid.x0, z.grid.y0, z.zmin];
    let hi = [
        z.grid.x0 + z.grid.nx as f64 * z.grid.dx,
        z.grid.y0 + z.grid.ny as f64 * z.grid.dy,
        z.ztop,
    ];
    let v = View::fit(
        [1.0, -1.0, 1.0],
        [0.0, 0.0, 1.0],
        lo,
        hi,
        (0.0, 0.0, 1200.0, 900.0),
    );
    let top = z.ztop as f32 - 1e-4;
    let (xa, xb) = (lo[0] as f32, hi[0] as f32);
    let (ya, yb) = (lo[1] as f32, hi[1] as f32);
    mesh::mill(z, &mut |t| {
        // The skirt is cut where its top edge was lowered; the top where any
        // corner was.
        let side = t.iter().all(|p| p[0] == xa)
            || t.iter().all(|p| p[0] == xb)
            || t.iter().all(|p| p[1] == ya)
            || t.iter().all(|p| p[1] == yb);
        let cut = if side {
            t.iter().map(|p| p[2]).fold(f32::NEG_INFINITY, f32::max) < top
        } else {
            t.iter().any(|p| p[2] < top)
        };
        v.shade(&mut c, &t, cut);
    });
    for e in &sim.report().events {
        if e.kind.is_collision() {
            let p = v.project(e.at);
            c.mark(p[0], p[1], 12.0);
        }
    }
    c
}

fn lathe(sim: &Sim) -> Canvas {
    let Model::Lathe(s) = sim.model() else {
        unreachable!()
    };
    let (w, h) = (1600, 700);
    let mut c = Canvas::new(w, h);
    let (rmax, r_in, za, zb) = match sim.stock() {
        crate::Stock::Turn {
            r_out,
            r_in,
            z_face,
            z_end,
        } => (*r_out, *r_in, *z_end, *z_face),
        _ => (1.0, 0.0, 0.0, 1.0),
    };
    // Left: the half section, Z to the right, radius up, in (40..760, 40..660).
    let sc = (720.0 / (zb - za)).min(620.0 / rmax);
    let sx = |z: f64| 40.0 + (z - za) * sc;
    let sy = |r: f64| 660.0 - r * sc;
    for px in 0..(((zb - za) * sc) as usize) {
        // The raw stock, light: what is not drawn over it was cut away.
        for py in (sy(rmax).round() as i64)..(sy(r_in).round() as i64) {
            c.put(40 + px as i64, py, [236, 226, 204]);
        }
        let z = za + (px as f64 + 0.5) / sc;
        for (a, b) in s.intervals_at(z) {
            for py in (sy(b).round() as i64)..(sy(a).round() as i64) {
                c.put(40 + px as i64, py, [120, 132, 150]);
            }
        }
    }
    // The raw stock's outline and the spindle axis.
    for px in 0..(((zb - za) * sc) as i64) {
        c.put(40 + px, sy(rmax).round() as i64, [60, 60, 60]);
        if px % 12 < 8 {
            c.put(40 + px, sy(0.0).round() as i64, [60, 60, 60]);
        }
    }
    // Right: the part seen from three quarters, Z to the right, with the
    // quarter toward the eye (X > 0, Y > 0) cut away to show the section.
    let lo = [-rmax, -rmax, za];
    let hi = [rmax, rmax, zb];
    let v = View::fit(
        [0.9, 0.75, 0.55],
        [1.0, 0.0, 0.0],
        lo,
        hi,
        (800.0, 0.0, 800.0, 700.0),
    );
    let loops = s.outline();
    mesh::revolve(&loops, PI / 2.0, 2.0 * PI, &mut |t| {
        v.shade(&mut c, &t, true)
    });
    for t in trapezoids(&loops) {
        for (cs, sn) in [(1.0, 0.0), (0.0, 1.0)] {
            let p = |z: f64, r: f64| [(r * cs) as f32, (r * sn) as f32, z as f32];
            let q = [
                p(t.z.0, t.lo.0),
                p(t.z.1, t.lo.1),
                p(t.z.1, t.hi.1),
                p(t.z.0, t.hi.0),
            ];
            v.shade_as(&mut c, &[q[0], q[1], q[2]], SECTION);
            v.shade_as(&mut c, &[q[0], q[2], q[3]], SECTION);
        }
    }
    for e in &sim.report().events {
        if e.kind.is_collision() {
            c.mark(sx(e.at[2]), sy(e.at[0]), 10.0);
            let p = v.project(e.at);
            c.mark(p[0], p[1], 10.0);
        }
    }
    c
}
