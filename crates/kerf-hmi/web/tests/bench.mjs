// Backplot figures of docs/benchmarks.md ("Browser backplot"), in
// headless chromium against a release `kerf serve`:
//   cargo build --release -p kerf-cli
//   python3 ../shared/bench/gen_programs.py --out bench-inputs
//   KERF=target/release/kerf node crates/kerf-hmi/web/tests/bench.mjs bench-inputs/surface_1m.nc
// With no file it makes a 10-million-segment macro loop. It prints the
// time from the load request to the first frame with geometry, the time
// to the whole path, the points held, and the frame rate over 5 s of
// orbiting the camera (whole view and zoomed 20 times) with the vertices
// drawn, and one frame with the camera still. With KERF_BENCH_SHOTS=DIR it
// saves the view moving and still, whole and zoomed, as PNGs in DIR.
import { readFileSync } from 'node:fs';
import { launch, serve } from './browser.mjs';

const file = process.argv[2];
const LOOP = `G90 G17 G21 G54 G00 X-150. Y-150. Z5.
G01 Z0. F6000.
#1 = 0
WHILE [#1 LT 10000000] DO1
G01 X[[#1 MOD 1000] * 0.3 - 150.] Y[FIX[#1 / 1000] * 0.03 - 150.] Z[SIN[#1 * 3.6]]
#1 = #1 + 1
END1
M30
`;
const text = file ? readFileSync(file, 'utf8') : LOOP;
const name = file ? file.split('/').pop() : 'loop_10m.nc';
const server = await serve(['--machine', 'hx-mc']);
const ctx = await launch();
const page = await ctx.newPage();
page.on('pageerror', (e) => console.error('page error:', e));
page.on('console', (m) => console.error('page:', m.text()));
page.on('crash', () => console.error('page crashed'));
await page.goto(`${server.url}#graph`);
await page.waitForFunction(() => window.kerf && window.kerf.graph);
const r = await page.evaluate(async ({ text, name }) => {
  const g = window.kerf.graph;
  const gl = g.renderer.getContext();
  // A frame is done when its pixels can be read (the GL queue drained).
  const finish = () => gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4));
  const wait = (f, ms) => new Promise((res) => { const k = () => (f() ? res() : setTimeout(k, ms)); k(); });
  // The file as the page's LOAD FILE sends it: a Blob, not a JS string.
  const body = new Blob([text]);
  const t0 = performance.now();
  let loaded = null;
  const load = fetch(`/api/program?name=${name}`, { method: 'POST', body }).then(() => { loaded = performance.now() - t0; });
  await wait(() => g.n > 2 && g.firstFrameAt !== null && g.firstFrameAt > t0, 2);
  finish();
  const drawn = performance.now() - t0;
  const first = { records: g.firstRecordsAt - t0, frame: g.firstFrameAt - t0, drawn, points: g.points, coarse: g.drewCoarse };
  console.log(`first frame ${JSON.stringify(first)}`);
  await load;
  console.log(`loaded in ${loaded} ms`);
  await wait(() => window.kerf.state.path.done && g.points === window.kerf.state.path.points && g.done, 20);
  const all = performance.now() - t0;
  console.log(`whole path ${all} ms, ${g.n} vertices, ${g.coarse.n} coarse`);
  g.view('iso');
  // Orbit: the camera turned about the target every frame for 5 s, as a
  // drag does (the copy decimated for the view drawn while it moves), at
  // the whole view and zoomed 20 times on the part's centre. Frames are
  // counted when drawn (the GL queue drained every 10th frame, so a slow
  // rasteriser cannot hide behind the queue). No allocation per frame.
  const d = g.camera.position.clone();
  const orbit = async (zoom, secs) => {
    g.camera.zoom = zoom;
    g.camera.updateProjectionMatrix();
    g.moving = true;
    g.moveGrid.builds = 0;
    g.moveGrid.buildTotalMs = 0;
    const c = g.camera, tgt = g.controls.target;
    let frames = 0, vertices = 0, lod = null;
    const t1 = performance.now();
    await new Promise((res) => {
      const step = () => {
        d.copy(c.position).sub(tgt).applyAxisAngle(c.up, 0.02);
        c.position.copy(tgt).add(d);
        c.lookAt(tgt);
        g.draw();
        if (++frames % 10 === 0) finish();
        vertices = Math.max(vertices, g.drewVertices);
        lod = g.drewLod;
        if (performance.now() - t1 < secs * 1000) requestAnimationFrame(step); else res();
      };
      requestAnimationFrame(step);
    });
    finish();
    const fps = frames / ((performance.now() - t1) / 1000);
    const canvas = `${g.renderer.domElement.width}x${g.renderer.domElement.height}`;
    const builds = { count: g.moveGrid.builds, ms: Math.round(g.moveGrid.buildTotalMs) };
    // One frame with the camera still at this zoom: the still copy made
    // for the view and drawn, to the end.
    g.moving = false;
    finish();
    const t2 = performance.now();
    g.draw();
    finish();
    const still = { ms: performance.now() - t2, vertices: g.drewVertices, lod: g.drewLod, build_ms: g.stillCopy.buildMs };
    console.log(`orbit at zoom ${zoom}: ${fps.toFixed(1)} frames/s, ${vertices} vertices (${lod}, canvas ${canvas}, builds ${JSON.stringify(builds)}); still frame ${JSON.stringify(still)}`);
    return { fps, vertices, lod, canvas, builds, move_build_ms: g.moveGrid.buildMs, move_build: g.moveGrid.last, still: { ...still, build: g.stillCopy.last } };
  };
  const whole = await orbit(1, 5);
  const zoomed = await orbit(20, 5);
  const fps = whole.fps;
  const fullFrame = whole.still.ms;
  return {
    load_ms: loaded, first_records_ms: first.records, first_frame_ms: first.frame, first_frame_drawn_ms: first.drawn,
    first_frame_points: first.points, whole_path_ms: all, points: g.points, vertices: g.n,
    coarse_vertices: g.coarse.n, orbit_fps: fps, still_frame_ms: fullFrame, orbit: whole, orbit_zoom20: zoomed,
    state: window.kerf.state.path,
  };
}, { text, name });
console.log(JSON.stringify({ program: name, lines: text.split('\n').length - 1, ...r }));
const shots = process.env.KERF_BENCH_SHOTS;
for (const [zoom, moving] of shots ? [[1, true], [1, false], [20, true], [20, false]] : []) {
  await page.evaluate(({ zoom, moving }) => {
    const g = window.kerf.graph;
    g.view('iso');
    g.camera.zoom = zoom;
    g.camera.updateProjectionMatrix();
    g.moving = moving;
    g.draw();
  }, { zoom, moving });
  await page.screenshot({ path: `${shots}/${name}-zoom${zoom}-${moving ? 'moving' : 'still'}.png` });
}
await ctx.cleanup();
await server.stop();
