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
