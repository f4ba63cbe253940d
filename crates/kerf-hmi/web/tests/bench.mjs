// Backplot figures of docs/benchmarks.md ("Browser backplot"), in
// headless chromium against a release `kerf serve`:
//   cargo build --release -p kerf-cli
//   python3 ../shared/bench/gen_programs.py --out bench-inputs
//   KERF=target/release/kerf node crates/kerf-hmi/web/tests/bench.mjs bench-inputs/surface_1m.nc
// With no file it makes a 10-million-segment macro loop. It prints the
// time from the load request to the first frame with geometry, the time
// to the whole path, the points held, and the frame rate over 5 s of
// orbiting the camera.
import { readFileSync } from 'node:fs';
import { launch, serve } from './browser.mjs';

const file = process.argv[2];
const LOOP = `G90 G17 G21 G54 G00 X0. Y0. Z5.
G01 Z0. F6000.
#1 = 0
WHILE [#1 LT 10000000] DO1
G01 X[[#1 MOD 1000] * 0.3] Y[FIX[#1 / 1000] * 0.03] Z[SIN[#1 * 3.6]]
#1 = #1 + 1
END1
M30
`;
const text = file ? readFileSync(file, 'utf8') : LOOP;
const name = file ? file.split('/').pop() : 'loop_10m.nc';
const server = await serve(['--machine', 'hx-mc']);
const ctx = await launch();
const page = await ctx.newPage();
await page.goto(`${server.url}#graph`);
await page.waitForFunction(() => window.kerf && window.kerf.graph);
const r = await page.evaluate(async ({ text, name }) => {
  const g = window.kerf.graph;
  const t0 = performance.now();
  const load = fetch(`/api/program?name=${name}`, { method: 'POST', body: text });
  await new Promise((res) => {
    const f = () => (g.n > 2 && g.frames > 0 && g.firstFrameAt !== null && g.firstFrameAt > t0 ? res() : setTimeout(f, 5));
    f();
  });
  const first = g.firstFrameAt - t0;
  await load;
  await new Promise((res) => {
    const f = () => (window.kerf.state.path.done && g.points === window.kerf.state.path.points ? res() : setTimeout(f, 50));
    f();
  });
  const all = performance.now() - t0;
  g.view('iso');
  // Orbit: turn the camera about the target every frame for 5 s.
  const c = g.camera, tgt = g.controls.target;
  let frames = 0;
  const t1 = performance.now();
  await new Promise((res) => {
    const step = () => {
      const d = c.position.clone().sub(tgt);
      d.applyAxisAngle(c.up, 0.02);
      c.position.copy(tgt).add(d);
      c.lookAt(tgt);
      g.renderer.render(g.scene, c);
      frames++;
      if (performance.now() - t1 < 5000) requestAnimationFrame(step); else res();
    };
    requestAnimationFrame(step);
  });
  const fps = frames / ((performance.now() - t1) / 1000);
  return { first_frame_ms: first, whole_path_ms: all, points: g.points, vertices: g.n, fps, state: window.kerf.state.path };
}, { text, name });
console.log(JSON.stringify({ program: name, lines: text.split('\n').length - 1, ...r }));
await ctx.cleanup();
await server.stop();
