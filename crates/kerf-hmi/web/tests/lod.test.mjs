// The view-decimated copy of GRAPH (web/lod.js), without a browser.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { ViewCopy } from '../lod.js';

// Identity view-projection: NDC x, y are world x, y.
const I = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1];

function path(points, keys) {
  const n = points.length;
  const pos = new Float32Array(n * 3), col = new Uint8Array(n * 3), key = new Uint16Array(n);
  points.forEach((p, i) => { pos.set(p, i * 3); key[i] = keys ? keys[i] : 1; col[i * 3] = key[i]; });
  return { pos, col, key, n };
}

test('inside the view vertices closer than the step to the last kept are left out', () => {
  // 1001 vertices 0.001 apart from x -0.5 to 0.5: with a step of 0.0095
  // every 10th is kept (9 × 0.001 < 0.0095 <= 10 × 0.001): 0, 10, … 1000.
  const p = path(Array.from({ length: 1001 }, (_, i) => [-0.5 + i * 0.001, 0, 0]));
  const c = new ViewCopy(1000);
  assert.equal(c.build(p.pos, p.col, p.key, p.n, I, 0.0095, 1), 101);
  assert.ok(Math.abs(c.pos[3] - -0.49) < 1e-6, `second vertex x ${c.pos[3]}`);
  assert.ok(Math.abs(c.pos[100 * 3] - 0.5) < 1e-6);
  assert.ok(c.fits(I, p.n));
  assert.ok(!c.fits(I, p.n + 1));
});

test('outside the view a run beyond one edge keeps only its ends', () => {
  // Right of the view (x > 1): 2, 3, 4; inside: 0; right: 5, 6; right
  // and above: (6, 5); above: (0, 5); left and above: (-5, 5). Left out:
  // x 3 (between 2 and 4, all right of the view), x 6 (between 5 and
  // (6, 5), right) and (0, 5) (between (6, 5) and (-5, 5), all above).
  const pts = [[2, 0, 0], [3, 0, 0], [4, 0, 0], [0, 0, 0], [5, 0, 0], [6, 0, 0], [6, 5, 0], [0, 5, 0], [-5, 5, 0]];
  const p = path(pts);
  const c = new ViewCopy(100);
  assert.equal(c.build(p.pos, p.col, p.key, p.n, I, 0.01, 1), 6);
  const xy = Array.from({ length: c.n }, (_, k) => [c.pos[k * 3], c.pos[k * 3 + 1]]);
  assert.deepEqual(xy, [[2, 0], [4, 0], [0, 0], [5, 0], [6, 5], [-5, 5]]);
});

test('a run that turns a corner of the view keeps the vertex at the turn', () => {
  // Above (0, 5), then left (-5, 0), then below (0, -5): no edge all
  // three are beyond (the segments pass the view's corners), so every
  // vertex stays.
  const p = path([[0, 5, 0], [-5, 0, 0], [0, -5, 0]]);
  const c = new ViewCopy(100);
  assert.equal(c.build(p.pos, p.col, p.key, p.n, I, 0.01, 1), 3);
});

test('a colour change keeps the old run\'s last vertex and the new one', () => {
  // Ten vertices 0.01 apart, the colour changing at the 6th; step 1 (far
  // more than the path): first, the 5th (old colour), the 6th, the last.
  const p = path(Array.from({ length: 10 }, (_, i) => [i * 0.01, 0, 0]), [1, 1, 1, 1, 1, 2, 2, 2, 2, 2]);
  const c = new ViewCopy(100);
  assert.equal(c.build(p.pos, p.col, p.key, p.n, I, 1, 1), 4);
  assert.deepEqual(Array.from({ length: 4 }, (_, k) => c.col[k * 3]), [1, 1, 2, 2]);
});

test('past its size the step doubles until the copy fits', () => {
  const p = path(Array.from({ length: 1000 }, (_, i) => [-0.5 + i * 0.001, 0, 0]));
  const c = new ViewCopy(100);
  c.build(p.pos, p.col, p.key, p.n, I, 0.00095, 1);
  assert.ok(c.n <= 100, `${c.n} vertices`);
  // 0.00095 doubled to 0.0152 keeps every 16th vertex (15 × 0.001 <
  // 0.0152 <= 16 × 0.001): 0, 16, … 992 and the last, 64; at 0.0076
  // every 8th would be 126, over 100.
  assert.ok(Math.abs(c.step - 0.0152) < 1e-12, `step ${c.step}`);
  assert.equal(c.n, 64);
});

test('a path with more colour changes than the copy holds is kept by distance', () => {
  // 3000 vertices 0.001 apart, the colour changing at every one: keeping
  // the changes would need all of them; the copy of 100 then keeps by
  // distance alone and is full, not a few vertices.
  const n = 3000;
  const p = path(Array.from({ length: n }, (_, i) => [-0.9 + i * 0.0006, 0, 0]), Array.from({ length: n }, (_, i) => i % 2));
  const c = new ViewCopy(100);
  c.build(p.pos, p.col, p.key, p.n, I, 0.0001, 1);
  assert.ok(c.n <= 100 && c.n > 50, `${c.n} vertices`);
  assert.ok(Math.abs(c.pos[(c.n - 1) * 3] - p.pos[(n - 1) * 3]) < 1e-9, 'ends at the path\'s end');
});
