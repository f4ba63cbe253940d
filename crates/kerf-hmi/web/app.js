// The operator screen: one WebSocket for the state and the backplot, the
// JSON API for commands (docs/hmi.md). Pages render from the newest state;
// only the visible page does work.
import { Screens } from './screens.js';

const token = new URLSearchParams(location.search).get('token');
const $ = (id) => document.getElementById(id);

/** Calls the API; resolves to {ok, status, body}. Never throws. */
export async function api(method, path, body, contentType = 'application/json') {
  const headers = {};
  if (token) headers.Authorization = `Bearer ${token}`;
  if (body !== undefined) headers['Content-Type'] = contentType;
  try {
    const r = await fetch(path, { method, headers, body });
    const type = r.headers.get('content-type') || '';
    const data = type.includes('json') ? await r.json() : await r.arrayBuffer();
    return { ok: r.ok, status: r.status, body: data };
  } catch (e) {
    return { ok: false, status: 0, body: { error: { code: 'network', message: String(e) } } };
  }
}

const app = {
  machine: null,
  state: null,
  page: 'pos',
  screens: null,
  graph: null,
  stats: { states: 0, lastStateAt: 0 },
  lastSeq: -1, // `seq` of the newest state taken
};
window.kerf = app; // for the browser tests and the console

/** Shows a line under the panel (the answer to the last command). */
export function say(text, bad = false) {
  const m = $('panel-msg');
  m.textContent = text;
  m.style.color = bad ? '#ff6060' : '';
}

/** Sends one command; the answer's state is drawn at once. */
export async function command(body) {
  const r = await api('POST', '/api/command', JSON.stringify(body));
  if (r.ok) {
    onState(r.body.state, true);
    say(`${body.cmd}: ok`);
  } else {
    say(`${body.cmd}: ${r.body.error ? r.body.error.message : r.status}`, true);
  }
  return r;
}

/**
 * A new state. The answer to a command is drawn at once (the operator's
 * click repaints in the same task); the stream's states (30 a second) are
 * drawn once per animation frame, the newest only, so a busy page does
 * not spend its main thread on states it cannot show.
 */
function onState(s, now = false) {
  // States are numbered as the server publishes them: one older than
  // the one shown (a stream message overtaken by a command's answer) is
  // dropped, so the screen never steps back.
  if (s.seq < app.lastSeq) return;
  app.lastSeq = s.seq;
  app.state = s;
  app.stats.states++;
  app.stats.lastStateAt = performance.now();
  if (now) {
    drawState();
  } else if (!app.drawPending) {
    app.drawPending = true;
    requestAnimationFrame(drawState);
  }
}

function drawState() {
  app.drawPending = false;
  const s = app.state;
  if (s === app.drawn) return;
  app.drawn = s;
  drawStatus(s);
  app.screens.draw(app.page, s);
  if (app.graph) app.graph.state(s, app.page === 'graph');
}

/** Sets a text only when it changes (no style work for the same text). */
function setText(el, text) {
  if (el.textContent !== text) el.textContent = text;
}

function drawStatus(s) {
  setText($('st-mode'), s.mode);
  setText($('st-exec'), s.execution.replace('_', ' '));
  const a = s.alarm;
  const st = $('st-alarm');
  setText(st, a ? `ALM ${a.code}` : '');
  st.className = a ? 'st-alarm' : '';
  setText($('st-time'), clock(s.t));
  for (const b of document.querySelectorAll('[data-mode]')) b.classList.toggle('on', b.dataset.mode === s.mode);
  for (const b of document.querySelectorAll('[data-switch]')) b.classList.toggle('on', !!s.switches[b.dataset.switch]);
  for (const b of document.querySelectorAll('[data-skip]')) b.classList.toggle('on', s.switches.block_skip.includes(+b.dataset.skip));
  for (const b of document.querySelectorAll('[data-rapid]')) b.classList.toggle('on', +b.dataset.rapid === s.overrides.rapid);
  setText($('feed-ovr-val'), String(s.overrides.feed));
  setText($('rapid-ovr-val'), String(s.overrides.rapid));
  if (document.activeElement !== $('feed-ovr')) $('feed-ovr').value = s.overrides.feed;
  $('cycle-start').classList.toggle('lit', s.execution === 'ACTIVE');
  $('feed-hold').classList.toggle('lit', s.execution === 'FEED_HOLD');
  setText($('title-prog'), s.program.name || 'O----');
  setText($('title-line'), s.program.line ? `LINE ${s.program.line}` : 'LINE -');
}

/** h:mm:ss.s */
export function clock(t) {
  const h = Math.floor(t / 3600), m = Math.floor(t / 60) % 60, sec = t % 60;
  return `${h}:${String(m).padStart(2, '0')}:${sec.toFixed(1).padStart(4, '0')}`;
}

function show(page) {
  app.page = page;
  for (const s of document.querySelectorAll('.page')) s.hidden = s.dataset.page !== page;
  for (const b of document.querySelectorAll('[data-show]')) b.classList.toggle('on', b.dataset.show === page);
  $('title-page').textContent = { pos: 'POSITION', prog: 'PROGRAM', mdi: 'MDI', offset: 'OFFSET / SETTING', alarm: 'ALARM', graph: 'GRAPHIC' }[page];
  if (page === 'graph') openGraph();
  if (app.state) {
    app.screens.enter(page, app.state);
    app.screens.draw(page, app.state);
  }
}

async function openGraph() {
  if (!app.graph) {
    const { Graph } = await import('./graph.js');
    app.graph = new Graph($('graph-view'), app.machine, $('graph-info'));
    app.graph.onPick = (line) => select(line, 'graph');
    if (app.selected) app.graph.select(app.selected);
    if (app.pendingPath) for (const m of app.pendingPath.splice(0)) app.graph.records(m);
    app.pendingPath = null;
    if (app.state) app.graph.state(app.state, true);
  }
  app.graph.visible();
}

/**
 * Selects a line of the program, from a click on the path in GRAPH or on
 * a line of PROG: PROG shows it (until the program runs) with RESTART
 * set to it, GRAPH draws its segments.
 */
export function select(line, from) {
  app.selected = line;
  app.screens.select(line);
  if (app.graph && from !== 'graph') app.graph.select(line);
  say(`line ${line} selected`);
}
app.select = select;

function connect() {
  const proto = location.protocol === 'https:' ? 'wss' : 'ws';
  const ws = new WebSocket(`${proto}://${location.host}/api/stream${token ? `?token=${token}` : ''}`);
  ws.binaryType = 'arraybuffer';
  ws.onopen = () => {
    $('st-link').textContent = 'ONLINE';
    app.lastSeq = -1; // a restarted server numbers from 0 again
  };
  ws.onclose = () => {
    $('st-link').textContent = 'OFFLINE';
    setTimeout(connect, 1000);
  };
  ws.onmessage = (ev) => {
    if (typeof ev.data === 'string') {
      const s = JSON.parse(ev.data);
      if (s.type === 'state') onState(s);
    } else if (app.graph) {
      app.graph.records(ev.data);
    } else {
      // Kept until GRAPH is first opened; the graph module loads then.
      (app.pendingPath ||= []).push(ev.data);
    }
  };
}

function wirePanel() {
  for (const b of document.querySelectorAll('[data-show]')) b.onclick = () => show(b.dataset.show);
  for (const b of document.querySelectorAll('[data-mode]')) b.onclick = () => command({ cmd: 'mode', mode: b.dataset.mode });
  $('cycle-start').onclick = () => command({ cmd: 'cycle_start' });
  $('feed-hold').onclick = () => command({ cmd: 'feed_hold' });
  $('reset').onclick = () => command({ cmd: 'reset' });
  for (const b of document.querySelectorAll('[data-switch]')) {
    b.onclick = () => command({ cmd: 'switch', [b.dataset.switch]: !app.state.switches[b.dataset.switch] });
  }
  const keys = $('skip-keys');
  for (let l = 1; l <= 9; l++) {
    const b = document.createElement('button');
    b.type = 'button';
    b.textContent = l;
    b.dataset.skip = l;
    b.onclick = () => {
      const on = new Set(app.state.switches.block_skip);
      on.has(l) ? on.delete(l) : on.add(l);
      command({ cmd: 'switch', block_skip: [...on].sort() });
    };
    keys.append(b);
  }
  const axis = $('jog-axis');
  for (const a of app.machine.axes) axis.append(new Option(a, a));
  const jog = (sign) => {
    const step = +$('jog-step').value;
    // Handle increments are 0.001, 0.01, 0.1 mm a pulse; longer steps jog.
    if (step <= 0.1) command({ cmd: 'handle', axis: axis.value, pulses: sign, increment: step });
    else command({ cmd: 'jog', axis: axis.value, distance: sign * step });
  };
  $('jog-minus').onclick = () => jog(-1);
  $('jog-plus').onclick = () => jog(1);
  $('ref-all').onclick = () => command({ cmd: 'ref_return' });
  $('origin').onclick = () => command({ cmd: 'origin' });
  $('feed-ovr').onchange = (e) => command({ cmd: 'override', feed: +e.target.value });
  for (const b of document.querySelectorAll('[data-rapid]')) b.onclick = () => command({ cmd: 'override', rapid: +b.dataset.rapid });
  // Function keys as on a keyboard: F1-F6 the pages.
  const order = ['pos', 'prog', 'mdi', 'offset', 'alarm', 'graph'];
  addEventListener('keydown', (e) => {
    const n = /^F([1-6])$/.exec(e.key);
    if (n) { e.preventDefault(); show(order[+n[1] - 1]); }
  });
}

async function start() {
  const m = await api('GET', '/api/machine');
  app.machine = m.ok ? m.body : { name: '?', kind: 'mill', style: 'fanuc', axes: ['X', 'Y', 'Z'] };
  document.body.className = app.machine.style;
  $('title-machine').textContent = `${app.machine.name}  ${app.machine.description || ''}`;
  app.screens = new Screens(app, { api, command, say });
  wirePanel();
  const s = await api('GET', '/api/state');
  if (s.ok) onState(s.body, true);
  show(location.hash ? location.hash.slice(1) : 'pos');
  connect();
}

start();
