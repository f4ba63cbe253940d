// Load on loopback, in the browser: 100 WebSocket clients of
// `kerf serve` running a program for KERF_LOAD_SECS seconds (default 10,
// at most 120; the figure is 60), each counting its states (every
// one parsed, ACTIVE, machine time never going back), while another page
// measures click to repaint (OPT STOP, 200 clicks spread over the run):
// `click_ms` the whole click, `request_ms` its request as the page's
// network stack timed it, `server_ms` 200 commands sent from this process
// (the server and loopback alone).
//   cargo build --release -p kerf-cli
//   KERF=target/release/kerf KERF_LOAD_SECS=60 node crates/kerf-hmi/web/tests/load.mjs
// Prints one JSON line; exits 1 when a client failed or a bar is missed
// (the bars are not judged, only printed, when the load average is over
// the core count: the clients, the browser and the server share them).
import { loadavg, cpus } from 'node:os';
import { launch, serve } from './browser.mjs';

const CLIENTS = 100;
const secs = Math.min(Math.max(Number(process.env.KERF_LOAD_SECS) || 10, 1), 120);
// A square of 100 mm sides at F300, over and over: 80 s a lap.
const SQUARE = 'G90 G17 G21 G54\nG00 X0. Y0. Z5.\nWHILE [1 EQ 1] DO1\nG01 X100. F300.\nY100.\nX0.\nY0.\nEND1\nM30\n';

const server = await serve(['--machine', 'hx-mc']);
const post = (path, body) => fetch(new URL(path, server.url), { method: 'POST', body }).then((r) => r.json());
await post('/api/program?name=square.nc', SQUARE);
await post('/api/command', JSON.stringify({ cmd: 'mode', mode: 'MEM' }));
await post('/api/command', JSON.stringify({ cmd: 'cycle_start' }));

// The 100 clients are another browser (other machines' screens); with
// KERF_LOAD_SAME_BROWSER=1 they are a page of the operator's own browser,
// which may put them in the screen's renderer process: its main thread
// then parses 100 sockets' states (5000 a second) between the clicks.
const ctx = await launch();
const same = process.env.KERF_LOAD_SAME_BROWSER === '1';
const other = same ? ctx : await launch();
const clients = await other.newPage();
await clients.goto(`${server.url}assets/style.css`); // a page of this origin
const counting = clients.evaluate(async ({ n, secs }) => {
  const one = () => new Promise((res) => {
    const ws = new WebSocket(`ws://${location.host}/api/stream`);
    const c = { states: 0, error: null, tLast: 0 };
    ws.onmessage = (ev) => {
      if (typeof ev.data !== 'string') return;
      try {
        const s = JSON.parse(ev.data);
        if (s.execution !== 'ACTIVE') throw new Error(`not ACTIVE: ${s.execution}`);
        if (s.t < c.tLast) throw new Error(`machine time went back: ${c.tLast} → ${s.t}`);
        c.tLast = s.t;
        c.states++;
      } catch (e) { c.error ||= String(e); }
    };
    ws.onerror = () => { c.error ||= 'socket error'; };
    ws.onclose = () => { c.error ||= 'closed'; };
    setTimeout(() => { ws.onclose = null; ws.close(); res(c); }, secs * 1000);
  });
  return Promise.all(Array.from({ length: n }, one));
}, { n: CLIENTS, secs });

// The server alone, without a browser: 200 commands from this process
// over the run (block skip 9 on and off: the square has no skipped
// block), each timed from sending to the answer.
const direct = (async () => {
  await new Promise((r) => setTimeout(r, 1000));
  const out = [];
  const gap = (secs * 1000 * 0.8) / 200;
  for (let i = 0; i < 200; i++) {
    const t0 = performance.now();
    await post('/api/command', JSON.stringify({ cmd: 'switch', block_skip: i % 2 ? [] : [9] }));
    out.push(performance.now() - t0);
    await new Promise((r) => setTimeout(r, gap));
  }
  return out.sort((a, b) => a - b);
})();

const screen = await ctx.newPage();
await screen.goto(server.url);
await screen.waitForFunction(() => window.kerf && window.kerf.state);
const { clicks, requests } = await screen.evaluate(async (secs) => {
  const b = document.querySelector('[data-switch=optional_stop]');
  const out = [];
  // The command's request as the page's network stack timed it (from
  // sending to the answer's last byte: loopback and the server); the rest
  // of a click is the page's own (the answer handled, the switch drawn).
  const requests = [];
  performance.setResourceTimingBufferSize(1000);
  new PerformanceObserver((l) => {
    for (const e of l.getEntries()) if (e.name.endsWith('/api/command')) requests.push(e.responseEnd - e.startTime);
  }).observe({ type: 'resource' });
  const gap = (secs * 1000 * 0.8) / 200;
  for (let i = 0; i < 200; i++) {
    const was = b.classList.contains('on');
    const t0 = performance.now();
    const changed = new Promise((res) => {
      const mo = new MutationObserver(() => { if (b.classList.contains('on') !== was) { mo.disconnect(); res(); } });
      mo.observe(b, { attributes: true });
    });
    b.click();
    await changed;
    await new Promise((r) => requestAnimationFrame(r));
    out.push(performance.now() - t0);
    await new Promise((r) => setTimeout(r, gap));
  }
  await new Promise((r) => setTimeout(r, 100));
  return { clicks: out.sort((a, b) => a - b), requests: requests.sort((a, b) => a - b) };
}, secs);
const counts = await counting;
const server_ms = await direct;
if (!same) await other.cleanup();
await ctx.cleanup();
await server.stop();

const rates = counts.map((c) => c.states / secs).sort((a, b) => a - b);
const errors = counts.filter((c) => c.error).map((c) => c.error);
const kinds = {};
for (const e of errors) { const k = e.replace(/[-\d.]+/g, 'N'); kinds[k] = (kinds[k] || 0) + 1; }
const p99 = clicks[Math.ceil(clicks.length * 0.99) - 1];
const rp99 = requests[Math.ceil(requests.length * 0.99) - 1];
const load = loadavg()[0];
const judged = load <= cpus().length;
console.log(JSON.stringify({
  clients: CLIENTS, secs, errors: errors.length, first_error: errors[0] || null, error_kinds: kinds,
  states_per_s: { min: rates[0], median: rates[CLIENTS >> 1], max: rates[CLIENTS - 1] },
  click_ms: { median: clicks[100], p99, max: clicks[clicks.length - 1] },
  server_ms: { median: server_ms[100], p99: server_ms[197], max: server_ms[199] },
  request_ms: { n: requests.length, median: requests[requests.length >> 1], p99: rp99, max: requests[requests.length - 1] },
  clients_in: same ? 'the same browser' : 'another browser', load_average: load, cores: cpus().length, judged,
}));
if (errors.length || (judged && (rates[0] < 20 || p99 >= 50))) process.exit(1);
