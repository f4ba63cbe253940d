// Which path vertices belong to which program line, both ways: picking
// the segment under a click (screen-space distance to every segment, no
// scene graph) and the vertices of one line (an index by line made by a
// counting sort, rebuilt when the path has grown).

/** Squared distance from (px, py) to the segment (ax, ay)-(bx, by). */
function segDist2(px, py, ax, ay, bx, by) {
  const dx = bx - ax, dy = by - ay;
  const l2 = dx * dx + dy * dy;
  let t = l2 > 0 ? ((px - ax) * dx + (py - ay) * dy) / l2 : 0;
  t = t < 0 ? 0 : t > 1 ? 1 : t;
  const ex = ax + t * dx - px, ey = ay + t * dy - py;
  return ex * ex + ey * ey;
}

/**
 * The vertex whose segment (from the vertex before it) passes nearest the
 * pixel (px, py) of a w×h view, within `tol` pixels; -1 when none.
 * `m` is the column-major view-projection matrix (orthographic: w = 1).
 */
export function pick(pos, n, m, w, h, px, py, tol = 6) {
  let best = -1, bestD = tol * tol;
  let ax = 0, ay = 0;
  for (let i = 0; i < n; i++) {
    const x = pos[i * 3], y = pos[i * 3 + 1], z = pos[i * 3 + 2];
    const sx = ((m[0] * x + m[4] * y + m[8] * z + m[12]) + 1) * 0.5 * w;
    const sy = (1 - (m[1] * x + m[5] * y + m[9] * z + m[13])) * 0.5 * h;
    if (i > 0) {
      const d = segDist2(px, py, ax, ay, sx, sy);
      if (d < bestD) { bestD = d; best = i; }
    }
    ax = sx; ay = sy;
  }
  return best;
}

/** Vertices by program line. */
export class LineIndex {
  constructor() { this.n = -1; }

  /** Rebuilds for the first `n` entries of `lines` unless it is of them. */
  update(lines, n) {
    if (n === this.n) return;
    let max = 0;
    for (let i = 0; i < n; i++) if (lines[i] > max) max = lines[i];
    const start = new Uint32Array(max + 2);
    for (let i = 0; i < n; i++) start[lines[i] + 1]++;
    for (let l = 1; l < start.length; l++) start[l] += start[l - 1];
    const fill = start.slice(0, max + 1);
    const order = new Uint32Array(n);
    for (let i = 0; i < n; i++) order[fill[lines[i]]++] = i;
    this.start = start;
    this.order = order;
    this.n = n;
  }

  /** The vertices of `line`, in path order (a subarray, no copy). */
  of(line) {
    if (!this.start || line < 0 || line + 1 >= this.start.length) return new Uint32Array(0);
    return this.order.subarray(this.start[line], this.start[line + 1]);
  }
}
