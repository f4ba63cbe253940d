// The path decimated for one view (level of detail): what a frame of a
// large path draws. For the view-projection of the camera it keeps
//  - inside the view (with a margin): a vertex at least `step` (world
//    units, the size of a pixel or so at that zoom) from the last one kept,
//    every change of colour and the vertex before it;
//  - outside: only the first and last vertex of each run of vertices
//    beyond one same edge of the view (left, right, above, below: the
//    bits of Cohen-Sutherland clipping's region codes, the run's codes
//    sharing a bit). A half-plane is convex, so neither the run's path
//    nor the chord that replaces it enters the view, and a segment that
//    may cross the view keeps its true end points.
// Past `max` vertices the step doubles and the copy is made again (when
// the colour changes alone fill half of it, they stop being kept and the
// step starts again). The arrays are made once; a rebuild allocates
// nothing.

/** Region code of NDC (x, y) against the box |x|, |y| <= m (0: inside). */
function region(x, y, m) {
  return (x < -m ? 1 : x > m ? 2 : 0) | (y < -m ? 4 : y > m ? 8 : 0);
}

export class ViewCopy {
  constructor(max) {
    this.max = max;
    this.pos = new Float32Array((max + 2) * 3);
    this.col = new Uint8Array((max + 2) * 3);
    this.n = 0;
    this.step = 0;
    this.built = new Float64Array(16); // the view-projection it was made for
    this.builtN = -1; // path vertices it was made from
    this.buildMs = 0;
    this.scale = 1; // the last build's step over the step asked for
    this.noChanges = false; // colour changes were too many to keep
  }

  /** Forgets what the last builds learnt (a new path). */
  reset() {
    this.builtN = -1;
    this.scale = 1;
    this.noChanges = false;
  }

  /** True when made for view-projection `m` (column-major) over `n` vertices. */
  fits(m, n) {
    if (n !== this.builtN) return false;
    for (let i = 0; i < 16; i++) if (m[i] !== this.built[i]) return false;
    return true;
  }

  /**
   * Makes the copy of the first `n` vertices of the full path (`pos`,
   * `col`, colour `key` per vertex) for view-projection `m` (orthographic:
   * w = 1), keeping vertices `step0` apart in the view box grown by
   * `margin` (1: the view itself).
   */
  build(pos, col, key, n, m, step0, margin = 1.5) {
    const t0 = performance.now();
    this.built.set(m);
    this.builtN = n;
    // From the step asked for: a pass that runs over `max` stops there,
    // so the short steps cost little; colour changes are not tried again
    // on a path that had too many of them.
    let step = step0;
    let changes = !this.noChanges;
    let rounds = 0;
    this.failed = true;
    for (let round = 0; round < 60; round++) {
      rounds++;
      if (this.take(pos, col, key, n, m, step, margin, changes)) {
        this.failed = false;
        break;
      }
      if (changes && (this.forced > this.max / 2 || round >= 20)) {
        // The colour changes alone fill the copy: a longer step cannot
        // make room, so from now on distance alone counts, from the
        // first step again.
        changes = false;
        step = step0;
        this.noChanges = true;
        continue;
      }
      step *= 2;
    }
    this.step = step;
    this.scale = step / step0;
    this.noChanges = !changes;
    this.buildMs = performance.now() - t0;
    // Edges crossed more often than the copy holds: no step helps (the
    // caller draws something else).
    if (this.failed) this.n = 0;
    this.last = { rounds, step0, step, n: this.n, changes, failed: this.failed };
    return this.n;
  }

  /** One pass; false when it ran over `max` (`changes`: keep colour changes). */
  take(pos, col, key, n, m, step, margin, changes) {
    const s2 = step * step;
    let k = 0; // vertices kept
    this.forced = 0; // of them, kept for a change of colour
    let last = -1; // full-path index of the last kept
    let lastCode = -1;
    let runBits = 0; // the edges every vertex of the outside run is beyond
    for (let i = 0; i < n; i++) {
      const x = pos[i * 3], y = pos[i * 3 + 1], z = pos[i * 3 + 2];
      const code = region(m[0] * x + m[4] * y + m[8] * z + m[12], m[1] * x + m[5] * y + m[9] * z + m[13], margin);
      let keep;
      if (last < 0 || i === n - 1) {
        keep = true;
      } else if (code !== 0) {
        // Outside: left out while this vertex and the next are beyond an
        // edge every vertex of the run since the last kept is beyond.
        const j = i + 1;
        const nx = pos[j * 3], ny = pos[j * 3 + 1], nz = pos[j * 3 + 2];
        const next = region(m[0] * nx + m[4] * ny + m[8] * nz + m[12], m[1] * nx + m[5] * ny + m[9] * nz + m[13], margin);
        const common = runBits & code;
        keep = (common & next) === 0;
        if (!keep) runBits = common;
      } else if (lastCode !== 0) {
        keep = true; // back inside
      } else if (changes && key[i] !== key[last]) {
        // The old colour's last vertex, then this one in the new colour.
        if (last !== i - 1) {
          if (k >= this.max) return false;
          this.put(k++, pos, col, i - 1);
        }
        this.forced++;
        keep = true;
      } else {
        const dx = x - pos[last * 3], dy = y - pos[last * 3 + 1], dz = z - pos[last * 3 + 2];
        keep = dx * dx + dy * dy + dz * dz >= s2;
      }
      if (keep) {
        if (k >= this.max) return false;
        this.put(k++, pos, col, i);
        last = i;
        lastCode = code;
        runBits = code;
      }
    }
    this.n = k;
    return true;
  }

  put(k, pos, col, i) {
    const a = k * 3, b = i * 3;
    this.pos[a] = pos[b]; this.pos[a + 1] = pos[b + 1]; this.pos[a + 2] = pos[b + 2];
    this.col[a] = col[b]; this.col[a + 1] = col[b + 1]; this.col[a + 2] = col[b + 2];
  }
}
