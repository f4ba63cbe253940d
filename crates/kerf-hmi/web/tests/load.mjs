// Load on loopback: 100 WebSocket clients of `kerf serve` running a
// program for KERF_LOAD_SECS seconds (default 10,
// at most 120; the figure is 60), each counting its states (every
// one parsed, ACTIVE, machine time never going back), while another page
// measures click to repaint in chromium (OPT STOP, 200 clicks spread
// over the run; the clients' process: KERF_LOAD_CLIENTS below):
// `click_ms` the whole click, `request_ms` its request as the page's
// network stack timed it, `page_ms` the rest (the answer handled until
// the switch changed, then the wait for the next frame), `server_ms` 200 commands sent from this process
// (the server and loopback alone); `cpu_s` the CPU seconds the server
// and the node clients used.
//   cargo build --release -p kerf-cli
//   KERF=target/release/kerf KERF_LOAD_SECS=60 node crates/kerf-hmi/web/tests/load.mjs
// Prints one JSON line; exits 1 when a client failed or a bar is missed
// (the bars are not judged, only printed, when the load average before
// the run, the machine's other work, is over the core count).
import { loadavg, cpus } from 'node:os';
import { spawn } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { launch, serve } from './browser.mjs';
import { countStates } from './load_count.mjs';

const CLIENTS = 100;
const secs = Math.min(Math.max(Number(process.env.KERF_LOAD_SECS) || 10, 1), 120);
// A square of 100 mm sides at F300, three laps: 80 s a lap, 4 min in all
// (longer than the longest run). Not an endless loop: the backplot's trace
// of one runs to the 50-million-block guard, a core busy for the first
// 20-40 s of the run, and sends every client 1.1 M points (22 MB) before
// the path is rebuilt.
const SQUARE = 'G90 G17 G21 G54\nG00 X0. Y0. Z5.\n#100=0\nWHILE [#100 LT 3] DO1\nG01 X100. F300.\nY100.\nX0.\nY0.\n#100=#100+1\nEND1\nM30\n';

// The machine's load before the run (other work); the test's own
// processes (server, clients, chromium) then add 2-3 to it on 2 cores.
const loadBefore = loadavg()[0];
const server = await serve(['--machine', 'hx-mc']);
const post = (path, body) => fetch(new URL(path, server.url), { method: 'POST', body }).then((r) => r.json());
await post('/api/program?name=square.nc', SQUARE);
await post('/api/command', JSON.stringify({ cmd: 'mode', mode: 'MEM' }));
await post('/api/command', JSON.stringify({ cmd: 'cycle_start' }));

// Where the 100 clients run (KERF_LOAD_CLIENTS): `node` (default) a node
// process of their own, no browser (other machines' screens: the bar is
// judged with these); `browser` another chromium, which on this 2-core
// machine spends about a core parsing 100 sockets' states; `same-browser`
// a page of the operator's own browser (it may share the screen's
// renderer process).
const where = process.env.KERF_LOAD_CLIENTS || 'node';
if (!['node', 'browser', 'same-browser'].includes(where)) throw new Error(`KERF_LOAD_CLIENTS: node, browser or same-browser, not ${where}`);
const ctx = await launch();
const other = where === 'browser' ? await launch() : ctx;
const streamUrl = `${server.url.replace(/^http/, 'ws')}api/stream`;
let counting;
if (where === 'node') {
  const flags = typeof WebSocket === 'undefined' ? ['--experimental-websocket', '--no-warnings'] : [];
  const here = new URL('.', import.meta.url).pathname;
  const child = spawn(process.execPath, [...flags, `${here}load_clients.mjs`, streamUrl, String(CLIENTS), String(secs)], {
    stdio: ['ignore', 'pipe', 'inherit'],
  });
  let out = '';
  child.stdout.on('data', (d) => { out += d; });
  counting = new Promise((res, rej) => child.once('exit', (code) => (code === 0 ? res(JSON.parse(out)) : rej(new Error(`load clients exited ${code}`)))));
} else {
  const clients = await other.newPage();
  await clients.goto(`${server.url}assets/style.css`); // a page of this origin
  counting = clients.evaluate(countStates, { url: streamUrl, n: CLIENTS, secs });
}

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
const { clicks, requests, handled, frame } = await screen.evaluate(async (secs) => {
  const b = document.querySelector('[data-switch=optional_stop]');
  const out = [];
  // The command's request as the page's network stack timed it (from
  // sending to the answer's last byte: loopback and the server); the rest
  // of a click is the page's own (the answer handled, the switch drawn).
  const requests = [];
  const ends = []; // each command request's [start, answer's last byte]
  performance.setResourceTimingBufferSize(1000);
  new PerformanceObserver((l) => {
    for (const e of l.getEntries()) {
      if (!e.name.endsWith('/api/command')) continue;
      requests.push(e.responseEnd - e.startTime);
      ends.push([e.startTime, e.responseEnd]);
    }
  }).observe({ type: 'resource' });
  const marks = []; // each click's [start, switch changed, next frame]
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
    const t1 = performance.now();
    await new Promise((r) => requestAnimationFrame(r));
    const t2 = performance.now();
    out.push(t2 - t0);
    marks.push([t0, t1, t2]);
    await new Promise((r) => setTimeout(r, gap));
  }
  await new Promise((r) => setTimeout(r, 100));
  // The page's own part of each click, split at its request's answer:
  // the answer handled until the switch changed, then the wait for the
  // next frame.
  const handled = [];
  const frame = [];
  for (const [t0, t1, t2] of marks) {
    const e = ends.find(([st, end]) => st >= t0 && end <= t1);
    if (e) handled.push(t1 - e[1]);
    frame.push(t2 - t1);
  }
  const up = (a, b) => a - b;
  return { clicks: out.sort(up), requests: requests.sort(up), handled: handled.sort(up), frame: frame.sort(up) };
}, secs);
const counted = await counting;
const counts = Array.isArray(counted) ? counted : counted.counts;
const clientsCpu = Array.isArray(counted) ? null : counted.cpu_s;
const serverCpu = cpuSeconds(server.proc.pid);
const server_ms = await direct;
if (other !== ctx) await other.cleanup();
await ctx.cleanup();
await server.stop();

/** CPU seconds (user + system) process `pid` has used (Linux /proc; null elsewhere). */
function cpuSeconds(pid) {
  try {
    const f = readFileSync(`/proc/${pid}/stat`, 'utf8').split(') ')[1].split(' ');
    return (Number(f[11]) + Number(f[12])) / 100; // utime, stime in clock ticks (USER_HZ 100)
  } catch { return null; }
}

/** n, median, p99 and max of sorted `a`. */
function spread(a) {
  return { n: a.length, median: a[a.length >> 1], p99: a[Math.ceil(a.length * 0.99) - 1], max: a[a.length - 1] };
}

const rates = counts.map((c) => c.states / secs).sort((a, b) => a - b);
const errors = counts.filter((c) => c.error).map((c) => c.error);
const kinds = {};
for (const e of errors) { const k = e.replace(/[-\d.]+/g, 'N'); kinds[k] = (kinds[k] || 0) + 1; }
const p99 = clicks[Math.ceil(clicks.length * 0.99) - 1];
const rp99 = requests[Math.ceil(requests.length * 0.99) - 1];
const load = loadavg()[0];
const judged = loadBefore <= cpus().length;
console.log(JSON.stringify({
  clients: CLIENTS, secs, errors: errors.length, first_error: errors[0] || null, error_kinds: kinds,
  states_per_s: { min: rates[0], median: rates[CLIENTS >> 1], max: rates[CLIENTS - 1] },
  click_ms: { median: clicks[100], p99, max: clicks[clicks.length - 1] },
  server_ms: { median: server_ms[100], p99: server_ms[197], max: server_ms[199] },
  request_ms: { n: requests.length, median: requests[requests.length >> 1], p99: rp99, max: requests[requests.length - 1] },
  page_ms: { answer_to_switch: spread(handled), switch_to_frame: spread(frame) },
  clients_in: where,
  cpu_s: { server: serverCpu, clients: clientsCpu }, load_average: { before: loadBefore, after: load }, cores: cpus().length, judged,
}));
if (errors.length || (judged && (rates[0] < 20 || p99 >= 50))) process.exit(1);
