// The path decimated in screen space for a moving camera: a frame's
// vertex count bounded by the screen, not the program.
//
// For the view-projection of the camera (orthographic: w = 1) each vertex
// is projected to pixels. The path becomes chords (Reumann-Witkam: a
// chord runs from its start while every vertex after it stays within
// `tol` pixels of the line through the start and the first vertex beyond
// `tol`, going forward along it), so a path within a pixel of a straight
// line costs one chord however many vertices it has. A chord is then
// tested on a grid of cells `cellPx` wide over the view grown by
// `margin`, at its ends and every cell's width between them: it is kept
// only when one of those points lies in a cell not yet marked with the
// chord's colour class, and those cells are marked. Where the path is
// denser than the cells (rows of a surface closer than a pixel, passes
// over each other) the later rows are dropped whole; every kept chord
// marks a cell, so at most cells × classes are kept, and past `max` the
// cells are made twice as wide. Chords outside the grid are not tested:
// a segment both of whose ends are beyond one edge of it (the region
// codes of Cohen-Sutherland clipping share a bit) cannot enter it.
//
// The output is segments (two vertices each, for THREE.LineSegments), in
// the chord's colour. The arrays are made once; a build allocates only
// when the grid grows (a larger canvas).

/** Most points a chord is tested at, its ends included. */
const SAMPLES = 64;

/**
 * Colour class (a bit of 0-7) of colour key `k` (kind × 256 + tool): by
 * kind (rapid, feed, arc, thread; the start point 4) or, when colouring
 * by tool, the tool palette's 8 entries.
 */
export function classBit(k, byTool) {
  if (byTool) return 1 << (k & 7);
  const kind = k >> 8;
  return 1 << (kind > 3 ? 4 : kind);
}

export class ScreenGrid {
  /** A copy of at most `max` segments. */
  constructor(max) {
    this.max = max;
    this.pos = new Float32Array(max * 6);
    this.col = new Uint8Array(max * 6);
    this.n = 0; // vertices (two a segment)
    this.cells = new Uint8Array(0);
    this.gw = 0;
    this.gh = 0;
    this.built = new Float64Array(16); // the view-projection it was made for
    this.builtN = -1; // path vertices it was made from
    this.buildMs = 0;
    this.builds = 0; // builds and their time since made (for the benchmark)
    this.buildTotalMs = 0;
    this.cellPx = 0; // the cells of the last build
    this.full = false; // the last pass stopped at `max`
  }

  /** Forgets the last build (a new path or new colours). */
  reset() {
    this.builtN = -1;
    this.cellPx = 0;
  }

  /** True when made for view-projection `m` (column-major) over `n` vertices. */
  fits(m, n) {
    if (n !== this.builtN) return false;
    for (let i = 0; i < 16; i++) if (m[i] !== this.built[i]) return false;
    return true;
  }

  /**
   * Makes the copy of the first `n` vertices of the path (`pos`, `col`,
   * colour `key` per vertex) for view-projection `m` and a view of
   * `w` × `h` pixels: chords within `tol` pixels, cells `cellPx` wide
   * (or wider: those of the last build when it needed them) over the
   * view grown by `margin` (1: the view itself). When `max` segments do
   * not hold it the cells are made twice as wide and the copy made again
   * (at most 4 times); the next build then starts from those cells, and
   * from half of them when this one used under a quarter of `max`.
   * Returns the vertices kept.
   */
  build(pos, col, key, n, m, w, h, cellPx, { tol = 1, margin = 1.25, byTool = false } = {}) {
    const t0 = performance.now();
    this.built.set(m);
    this.builtN = n;
    let px = Math.max(cellPx, this.cellPx);
    let rounds = 1;
    while (!this.pass(pos, col, key, n, m, w, h, px, tol, margin, byTool) && rounds < 5) {
      px *= 2;
      rounds++;
    }
    this.cellPx = this.k < this.max / 4 && px > cellPx ? Math.max(cellPx, px / 2) : px;
    this.buildMs = performance.now() - t0;
    this.builds++;
    this.buildTotalMs += this.buildMs;
    this.last = { rounds, cellPx: px, cells: this.gw * this.gh, n: this.n, full: this.full };
    return this.n;
  }

  /** One pass with cells `cellPx` wide; false when it stopped at `max`. */
  pass(pos, col, key, n, m, w, h, cellPx, tol, margin, byTool) {
    // NDC [-margin, margin] onto pixels [0, margin × w) × [0, margin × h).
    const W = margin * w, H = margin * h;
    const gw = Math.max(1, Math.ceil(W / cellPx));
    const gh = Math.max(1, Math.ceil(H / cellPx));
    if (this.cells.length < gw * gh) this.cells = new Uint8Array(gw * gh);
    else this.cells.fill(0, 0, gw * gh);
    this.gw = gw;
    this.gh = gh;
    const sx = w / 2, sy = h / 2, tol2 = tol * tol;
    // The projection to pixels: p = (M·v + margin) × s.
    const m0 = m[0] * sx, m4 = m[4] * sx, m8 = m[8] * sx, m12 = (m[12] + margin) * sx;
    const m1 = m[1] * sy, m5 = m[5] * sy, m9 = m[9] * sy, m13 = (m[13] + margin) * sy;
    this.k = 0; // segments kept
    this.full = false;
    // The chord: its start `a` (pixels ax, ay), its direction (ux, uy;
    // none while every vertex is within `tol` of the start) and how far
    // along it the last vertex was.
    let a = -1, ax = 0, ay = 0, ux = 0, uy = 0, dir = false, along = 0;
    let prevX = 0, prevY = 0, prevCode = 0;
    for (let i = 0; i < n && !this.full; i++) {
      const x = pos[i * 3], y = pos[i * 3 + 1], z = pos[i * 3 + 2];
      const px = m0 * x + m4 * y + m8 * z + m12;
      const py = m1 * x + m5 * y + m9 * z + m13;
      const code = (px < 0 ? 1 : px >= W ? 2 : 0) | (py < 0 ? 4 : py >= H ? 8 : 0);
      let start = a < 0;
      if (!start && ((code & prevCode) !== 0 || key[i] !== key[a])) {
        // The segment to this vertex is outside the grid, or the colour
        // changes here (the strip repeats a vertex, so the segment to it
        // has no length): the chord ends at the vertex before.
        this.chord(pos, col, key, a, i - 1, ax, ay, prevX, prevY, cellPx, byTool);
        start = true;
      } else if (!start) {
        const dx = px - ax, dy = py - ay;
        if (!dir) {
          const d2 = dx * dx + dy * dy;
          if (d2 > tol2) {
            const d = Math.sqrt(d2);
            ux = dx / d;
            uy = dy / d;
            dir = true;
            along = d;
          }
        } else {
          const across = dx * uy - dy * ux, on = dx * ux + dy * uy;
          if (across > tol || across < -tol || on < along - tol) {
            // Off the chord's line, or back along it: the chord ends at
            // the vertex before and the next one starts there.
            this.chord(pos, col, key, a, i - 1, ax, ay, prevX, prevY, cellPx, byTool);
            a = i - 1;
            ax = prevX;
            ay = prevY;
            const ex = px - ax, ey = py - ay, d = Math.sqrt(ex * ex + ey * ey);
            dir = d > tol;
            if (dir) {
              ux = ex / d;
              uy = ey / d;
              along = d;
            }
          } else if (on > along) {
            along = on;
          }
        }
      }
      if (start) {
        a = i;
        ax = px;
        ay = py;
        dir = false;
      }
      prevX = px;
      prevY = py;
      prevCode = code;
    }
    if (!this.full && a >= 0 && a < n - 1) this.chord(pos, col, key, a, n - 1, ax, ay, prevX, prevY, cellPx, byTool);
    this.n = this.k * 2;
    return !this.full;
  }

  /** Keeps the chord from vertex `a` to `b` (pixels ax, ay to bx, by) when it reaches a fresh cell. */
  chord(pos, col, key, a, b, ax, ay, bx, by, cellPx, byTool) {
    if (b <= a) return;
    if (!this.reaches(ax / cellPx, ay / cellPx, bx / cellPx, by / cellPx, classBit(key[b], byTool))) return;
    if (this.k >= this.max) {
      this.full = true;
      return;
    }
    this.put(this.k++, pos, col, a, b);
  }

  /**
   * True when the chord from grid point (ax, ay) to (bx, by) reaches a
   * cell not marked with `bit`; the cells it was tested at are marked.
   */
  reaches(ax, ay, bx, by, bit) {
    const cells = this.cells, gw = this.gw, gh = this.gh;
    const d = Math.max(Math.abs(bx - ax), Math.abs(by - ay));
    const steps = d < 1 ? 1 : Math.min(SAMPLES - 1, Math.ceil(d));
    let fresh = false;
    for (let s = 0; s <= steps; s++) {
      const t = s / steps;
      const x = ax + (bx - ax) * t, y = ay + (by - ay) * t;
      if (x < 0 || y < 0 || x >= gw || y >= gh) continue;
      const c = (y | 0) * gw + (x | 0);
      const v = cells[c];
      if ((v & bit) === 0) {
        cells[c] = v | bit;
        fresh = true;
      }
    }
    return fresh;
  }

  /** Segment `k`: path vertices `a` and `b`, both in `b`'s colour. */
  put(k, pos, col, a, b) {
    const o = k * 6, pa = a * 3, pb = b * 3;
    this.pos[o] = pos[pa]; this.pos[o + 1] = pos[pa + 1]; this.pos[o + 2] = pos[pa + 2];
    this.pos[o + 3] = pos[pb]; this.pos[o + 4] = pos[pb + 1]; this.pos[o + 5] = pos[pb + 2];
    this.col[o] = this.col[o + 3] = col[pb];
    this.col[o + 1] = this.col[o + 4] = col[pb + 1];
    this.col[o + 2] = this.col[o + 5] = col[pb + 2];
  }
}
