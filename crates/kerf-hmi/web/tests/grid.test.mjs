// The screen-grid copy GRAPH draws while the camera moves (web/grid.js),
// without a browser. The view is 100 × 100 pixels with the identity
// view-projection and no margin, so NDC (x, y) is pixel ((x + 1) × 50,
// (y + 1) × 50): the paths below are written in pixels.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { ScreenGrid, classBit } from '../grid.js';

const I = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1];
const FEED = 1 * 256, RAPID = 0;

/** A path of pixel points (x, y) with colour keys (feed when none). */
function path(points, keys) {
  const n = points.length;
  const pos = new Float32Array(n * 3), col = new Uint8Array(n * 3), key = new Uint16Array(n);
  points.forEach(([x, y], i) => {
    pos[i * 3] = x / 50 - 1;
    pos[i * 3 + 1] = y / 50 - 1;
    key[i] = keys ? keys[i] : FEED;
    col[i * 3] = key[i] >> 8;
  });
  return { pos, col, key, n };
}

const build = (g, p, cellPx = 2, tol = 1) => g.build(p.pos, p.col, p.key, p.n, I, 100, 100, cellPx, { tol, margin: 1 });
/** The kept segments in pixels, rounded to 0.01. */
const segments = (g) => Array.from({ length: g.n / 2 }, (_, k) => [0, 1, 3, 4].map((o) => Math.round((g.pos[k * 6 + o] + 1) * 5000) / 100));

test('a straight run of vertices is one chord', () => {
  // 81 vertices 1 px apart along y = 50: each within 0 px of the line
  // through the first and the second (1 px > tol 0.5 away).
  const p = path(Array.from({ length: 81 }, (_, i) => [10 + i, 50]));
  const g = new ScreenGrid(100);
  assert.equal(build(g, p, 2, 0.5), 2);
  assert.deepEqual(segments(g), [[10, 50, 90, 50]]);
});

test('a bump within the tolerance stays in the chord, one beyond it breaks it', () => {
  // Vertices 10 px apart along y = 50, the middle one (50, 50 + b).
  const bump = (b) => path([10, 20, 30, 40, 50, 60, 70, 80, 90].map((x) => [x, x === 50 ? 50 + b : 50]));
  const g = new ScreenGrid(100);
  assert.equal(build(g, bump(0.8)), 2); // 0.8 px off the line: within 1
  // 3 px: off the line at (50, 53); from (40, 50) the line to it leaves
  // (60, 50) 5.7 px away, from (50, 53) the line to (60, 50) leaves
  // (70, 50) 2.9 px away: four chords, each reaching cells of row 25
  // (y 50-52) or 26 not reached before.
  assert.equal(build(g, bump(3)), 8);
  assert.deepEqual(segments(g), [[10, 50, 40, 50], [40, 50, 50, 53], [50, 53, 60, 50], [60, 50, 90, 50]]);
});

test('a row over the cells of a row kept before is dropped', () => {
  // There along y = 50 (px), back along y = 50.05 (the same cells of
  // 2 px), then there again along y = 60. The return's first vertex
  // (90, 50.05) is 0.05 px off the first chord's line and not behind it,
  // so that chord ends there; the return from it reaches only cells of
  // row 25 marked by the first: dropped. The step to y = 60 and the last
  // row reach new cells.
  const xs = [10, 30, 50, 70, 90];
  const p = path([
    ...xs.map((x) => [x, 50]),
    ...[...xs].reverse().map((x) => [x, 50.05]),
    ...xs.map((x) => [x, 60]),
  ]);
  const g = new ScreenGrid(100);
  assert.equal(build(g, p), 6);
  assert.deepEqual(segments(g), [[10, 50, 90, 50.05], [10, 50.05, 10, 60], [10, 60, 90, 60]]);
});

test('a colour over the cells of another is kept', () => {
  // Feeds along y = 50, then a rapid back over them (the strip repeats
  // the corner vertex in the rapid's colour): the rapid's class has no
  // marks, so both are drawn, the rapid in its colour.
  const p = path([[10, 50], [90, 50], [90, 50], [10, 50]], [FEED, FEED, RAPID, RAPID]);
  const g = new ScreenGrid(100);
  assert.equal(build(g, p), 4);
  assert.deepEqual(segments(g), [[10, 50, 90, 50], [90, 50, 10, 50]]);
  assert.deepEqual([g.col[0], g.col[6]], [1, 0]);
  assert.notEqual(classBit(FEED, false), classBit(RAPID, false));
  // By tool: tools 1 and 9 share the palette's entry 1.
  assert.equal(classBit(1 * 256 + 1, true), classBit(0 * 256 + 9, true));
});

test('a run beyond one edge of the view is dropped, one crossing it is kept', () => {
  // Above the view (y > 100) from x 10 to 90, then down through it to
  // (90, -20) and left below it to (10, -20): only the crossing is kept.
  const p = path([[10, 150], [50, 150], [90, 150], [90, -20], [50, -20], [10, -20]]);
  const g = new ScreenGrid(100);
  assert.equal(build(g, p), 2);
  assert.deepEqual(segments(g), [[90, 150, 90, -20]]);
});

test('past its size the cells are made twice as wide', () => {
  // A zigzag of 10 rows 2 px apart (y = 1, 3, … 19), each from x 1 to
  // 99 and back, joined at the ends. Cells of 2 px: every row and every
  // join reaches a new row of cells, 19 chords, over 10. Cells of 4 px:
  // rows 0-1, 2-3, … share a row of cells, so rows 0, 2, 4, 6, 8 and the
  // joins into them (1→2, 3→4, 5→6, 7→8) are kept: 9 chords.
  const pts = [];
  for (let k = 0; k < 10; k++) {
    const y = 1 + 2 * k;
    pts.push(k % 2 ? [99, y] : [1, y], k % 2 ? [1, y] : [99, y]);
  }
  const p = path(pts);
  const g = new ScreenGrid(10);
  assert.equal(build(g, p), 18);
  assert.equal(g.last.rounds, 2);
  assert.equal(g.last.cellPx, 4);
  assert.deepEqual(segments(g).map((s) => [s[1], s[3]]), [[1, 1], [3, 5], [5, 5], [7, 9], [9, 9], [11, 13], [13, 13], [15, 17], [17, 17]]);
  assert.ok(g.fits(I, p.n) && !g.fits(I, p.n - 1));
});
