// The picking arithmetic of GRAPH (web/lines.js), without a browser.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { pick, LineIndex } from '../lines.js';

test('the index gives the vertices of each line in path order', () => {
  // Vertices of lines 0 1 1 3 1: line 1 is vertices 1, 2 and 4.
  const ix = new LineIndex();
  ix.update(new Uint32Array([0, 1, 1, 3, 1]), 5);
  assert.deepEqual([...ix.of(1)], [1, 2, 4]);
  assert.deepEqual([...ix.of(3)], [3]);
  assert.deepEqual([...ix.of(2)], []);
  assert.deepEqual([...ix.of(9)], []);
});

test('a pick is the segment nearest the pixel, within the tolerance', () => {
  // Identity view-projection on a 100×100 view: NDC (x, y) is pixel
  // ((x + 1) 50, (1 - y) 50). Vertices (-1,0) (0,0) (0,1) are pixels
  // (0,50) (50,50) (50,0): segment 1 along y = 50, segment 2 along x = 50.
  const m = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1];
  const pos = new Float32Array([-1, 0, 0, 0, 0, 0, 0, 1, 0]);
  assert.equal(pick(pos, 3, m, 100, 100, 25, 53), 1); // 3 px from segment 1
  assert.equal(pick(pos, 3, m, 100, 100, 48, 20), 2); // 2 px from segment 2
  assert.equal(pick(pos, 3, m, 100, 100, 25, 57), -1); // 7 px: outside 6
  assert.equal(pick(pos, 3, m, 100, 100, 90, 90), -1);
});

test('the coarse copy keeps colour changes and stays within its size', async () => {
  const { Coarse } = await import('../coarse.js');
  // 1001 feed vertices 0.01 mm apart along X (0 … 10 mm), then a rapid
  // (its first vertex the duplicate of the last feed one) to (10, 5).
  const n = 1003;
  const pos = new Float32Array(n * 3), col = new Uint8Array(n * 3), key = new Uint16Array(n);
  for (let i = 0; i <= 1000; i++) { pos[i * 3] = i * 0.01; key[i] = 1; }
  pos[1001 * 3] = 10; key[1001] = 0;
  pos[1002 * 3] = 10; pos[1002 * 3 + 1] = 5; key[1002] = 0;
  const c = new Coarse(100);
  for (let i = 0; i < n; i++) c.add(pos, col, key, i);
  c.finish(pos, col, n);
  assert.ok(c.n <= 102, `${c.n} vertices`);
  // The copy first overflows at vertex 100 (X 1.00 mm): a first step of
  // 1.00 / 4000 = 0.00025 mm, doubled while over 100 vertices: at 2^9 ·
  // 0.00025 = 0.128 mm every 13th feed vertex (0.13 mm) is kept, 77 of
  // them over 10 mm, with the ends and the rapid.
  assert.ok(Math.abs(c.step - 0.128) < 1e-9, `step ${c.step}`);
  const src = [...c.src.subarray(0, c.n)];
  assert.equal(src[0], 0);
  assert.ok(src.includes(1000), 'the last feed vertex');
  assert.ok(src.includes(1001), 'the colour change');
  assert.equal(src[src.length - 1], 1002);
});

test('a path with more colour changes than the copy holds still fits it', async () => {
  const { Coarse } = await import('../coarse.js');
  // 3000 vertices along X, 0.01 mm apart, the colour changing at every
  // one: keeping every change would need all 3000; the copy of 100 keeps
  // vertices by distance only then, and ends at the path's end.
  const n = 3000;
  const pos = new Float32Array(n * 3), col = new Uint8Array(n * 3), key = new Uint16Array(n);
  for (let i = 0; i < n; i++) { pos[i * 3] = i * 0.01; key[i] = i % 2; }
  const c = new Coarse(100);
  for (let i = 0; i < n; i++) c.add(pos, col, key, i);
  c.finish(pos, col, n);
  assert.ok(c.n <= 102, `${c.n} vertices`);
  assert.equal(c.keepChanges, false);
  assert.equal(c.src[c.n - 1], n - 1);
  // By distance alone the copy is full, not a few vertices: the step is
  // the shortest doubling of the first (extent/4000) that fits 100.
  assert.ok(c.n > 50, `${c.n} vertices`);
});
