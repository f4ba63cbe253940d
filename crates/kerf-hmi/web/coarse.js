// The coarse copy of the backplot drawn while the camera moves and while
// the path streams in: at most `max` vertices, made as the points arrive
// by the server's decimation rule (a vertex closer than `step` to the
// last one kept of the same colour is left out; every change of colour
// and the vertex before it are kept); past `max` the step doubles and the
// copy is remade from the full path.

export class Coarse {
  constructor(max) {
    this.max = max;
    this.pos = new Float32Array((max + 2) * 3);
    this.col = new Uint8Array((max + 2) * 3);
    this.src = new Uint32Array(max + 2); // the full-path vertex of each
    this.clear();
  }

  clear() {
    this.n = 0;
    this.step = 0;
    // Colour changes are kept until they alone would overflow the copy
    // (a path with more changes than `max`): then only distance counts.
    this.keepChanges = true;
    this.forced = 0; // vertices kept for a colour change in this pass
    this.changed = true;
  }

  /**
   * Takes full-path vertex `i`: `pos` and `col` the full path's arrays,
   * `key` its colour key per vertex (kind and tool).
   */
  add(pos, col, key, i) {
    this.take(pos, col, key, i);
    if (this.n > this.max) this.remake(pos, col, key, i + 1);
  }

  /** The last of the first `n` vertices, so the copy ends where the path does. */
  finish(pos, col, n) {
    if (n > 0 && (this.n === 0 || this.src[this.n - 1] !== n - 1)) this.put(pos, col, n - 1);
  }

  take(pos, col, key, i) {
    if (this.n > 0) {
      const j = this.src[this.n - 1];
      if (key[i] === key[j] || !this.keepChanges) {
        if (this.dist2(pos, j, i) < this.step * this.step) return;
      } else {
        this.forced++;
        if (j !== i - 1) this.put(pos, col, i - 1); // the old run's last vertex, in its colour
      }
    }
    this.put(pos, col, i);
  }

  dist2(pos, a, b) {
    const dx = pos[a * 3] - pos[b * 3], dy = pos[a * 3 + 1] - pos[b * 3 + 1], dz = pos[a * 3 + 2] - pos[b * 3 + 2];
    return dx * dx + dy * dy + dz * dz;
  }

  put(pos, col, i) {
    if (this.n >= this.max + 2) {
      this.n = this.max + 2; // over: the caller remakes
      return;
    }
    const k = this.n * 3;
    this.pos[k] = pos[i * 3]; this.pos[k + 1] = pos[i * 3 + 1]; this.pos[k + 2] = pos[i * 3 + 2];
    this.col[k] = col[i * 3]; this.col[k + 1] = col[i * 3 + 1]; this.col[k + 2] = col[i * 3 + 2];
    this.src[this.n] = i;
    this.n++;
    this.changed = true;
  }

  /** Remakes the copy from the first `n` full vertices with a longer step. */
  remake(pos, col, key, n) {
    if (this.step === 0) {
      // A first step from the size of what is there: 1/4000 of its extent.
      const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
      for (let i = 0; i < n * 3; i++) {
        const v = pos[i], a = i % 3;
        if (v < lo[a]) lo[a] = v;
        if (v > hi[a]) hi[a] = v;
      }
      this.step0 = Math.max(Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]) / 4000, 1e-6);
      this.step = this.step0 / 2;
    }
    for (let round = 0; ; round++) {
      this.step *= 2;
      this.n = 0;
      this.forced = 0;
      for (let i = 0; i < n && this.n <= this.max; i++) this.take(pos, col, key, i);
      if (this.n <= this.max) return;
      // Half the copy kept for colour changes alone: a longer step cannot
      // make room, so from now on only distance counts.
      // The step starts again from the first one.
      if (this.keepChanges && (this.forced > this.max / 2 || round > 60)) {
        this.keepChanges = false;
        this.step = this.step0 / 2;
      }
    }
  }

  /** Colours again from the full path's colours. */
  recolour(col) {
    for (let k = 0; k < this.n; k++) {
      const i = this.src[k];
      this.col[k * 3] = col[i * 3]; this.col[k * 3 + 1] = col[i * 3 + 1]; this.col[k * 3 + 2] = col[i * 3 + 2];
    }
    this.changed = true;
  }
}
