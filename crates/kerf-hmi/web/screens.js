// The pages other than GRAPH: POS, PROG, MDI, OFFSET/SETTING, ALARM.
// `enter` runs when a page is shown (fetches what it needs), `draw` on
// every state for the visible page (cheap: text of fixed cells).

const $ = (id) => document.getElementById(id);
/** Sets a text only when it changes. */
const setText = (el, text) => { if (el.textContent !== text) el.textContent = text; };
const fmt = (v, d = 3) => (v === undefined || v === null ? '' : Number(v).toFixed(d));
const LINES_SHOWN = 24;
const CHUNK = 200;

export class Screens {
  constructor(app, io) {
    this.app = app;
    this.io = io;
    this.chunks = new Map(); // chunk index -> lines
    this.progKey = null; // name + total of the program the chunks are of
    this.progTop = -1;
    this.selected = 0; // the line selected (GRAPH pick or a click here)
    this.focusSelected = false; // PROG shows the selection until the program runs
    this.alarmSeq = -1;
    this.offsets = null;
    this.buildPos();
    this.wireRelative();
    this.wireProg();
    this.wireMdi();
    this.wireOffsets();
  }

  enter(page, s) {
    if (page === 'offset') this.loadOffsets();
    if (page === 'alarm') this.alarmSeq = -1;
    if (page === 'prog') this.progTop = -1;
    if (page === 'mdi') $('mdi-text').focus();
  }

  draw(page, s) {
    if (page === 'pos') this.drawPos(s);
    else if (page === 'prog') this.drawProg(s);
    else if (page === 'mdi') this.drawMdi(s);
    else if (page === 'alarm') this.drawAlarm(s);
    else if (page === 'offset' && s.alarm_seq !== this.ofsSeq) {
      // Offsets change when a program writes them (G10, G37): reread
      // after alarms/messages and when the program ends.
      this.ofsSeq = s.alarm_seq;
    }
  }

  // ---- POS ----
  buildPos() {
    const axes = this.app.machine.axes;
    for (const id of ['pos-work', 'pos-relative', 'pos-machine', 'pos-dtg']) {
      const t = $(id);
      t.innerHTML = '';
      for (const a of axes) {
        const tr = document.createElement('tr');
        // The lathe's relative counters are U and W, as on its POS page.
        const label = id === 'pos-relative' && this.app.machine.kind === 'lathe' ? ({ X: 'U', Z: 'W' }[a] || a) : a;
        tr.innerHTML = `<td class="ax">${label}</td><td class="v" id="${id}-${a}">0.000</td>`;
        t.append(tr);
      }
    }
  }

  /**
   * ORIGIN and PRESET of the RELATIVE counters, as on the control: an
   * axis typed then ORIGIN zeroes it (nothing typed: every axis); an axis
   * and a value then PRESET sets it. On a lathe U and W name X and Z.
   */
  wireRelative() {
    const lathe = this.app.machine.kind === 'lathe';
    const parse = () => {
      const t = $('rel-entry').value.trim().toUpperCase();
      if (!t) return { axis: null, value: null };
      const m = /^([A-Z])\s*([-+]?(?:\d+\.?\d*|\.\d+))?$/.exec(t);
      if (!m) return null;
      let axis = m[1];
      if (lathe) axis = { U: 'X', W: 'Z' }[axis] || axis;
      return { axis, value: m[2] === undefined ? null : +m[2] };
    };
    const send = (preset) => {
      const e = parse();
      if (!e || (preset && (e.axis === null || e.value === null))) {
        this.io.say(preset ? 'PRESET: type an axis and a value (X12.5)' : 'ORIGIN: type an axis or nothing', true);
        return;
      }
      const body = { cmd: 'origin' };
      if (e.axis) body.axis = e.axis;
      if (preset) body.value = e.value;
      this.io.command(body).then((r) => { if (r.ok) $('rel-entry').value = ''; });
    };
    $('rel-origin').onclick = () => send(false);
    $('rel-preset').onclick = () => send(true);
  }

  drawPos(s) {
    const p = s.position;
    for (const a of this.app.machine.axes) {
      setText($(`pos-work-${a}`), fmt(p.work[a]));
      setText($(`pos-relative-${a}`), fmt(p.relative[a]));
      setText($(`pos-machine-${a}`), fmt(p.machine[a]));
      setText($(`pos-dtg-${a}`), fmt(p.distance_to_go[a]));
    }
    setText($('feed-actual'), fmt(s.feed.actual, 0));
    // mm/min, or mm/rev in G95/G99 (a small number: shown to 0.001).
    setText($('feed-prog'), fmt(s.feed.programmed, s.feed.programmed < 10 ? 3 : 0));
    setText($('spindle-actual'), fmt(s.spindle.rpm, 0));
    setText($('spindle-prog'), fmt(s.spindle.programmed, 0));
    setText($('spindle-dir'), s.spindle.direction.toUpperCase());
    setText($('tool'), String(s.tool).padStart(2, '0'));
    setText($('run-time'), this.clock(s.t));
    setText($('pos-block'), s.program.block);
  }

  clock(t) {
    const h = Math.floor(t / 3600), m = Math.floor(t / 60) % 60, sec = t % 60;
    return `${h}:${String(m).padStart(2, '0')}:${sec.toFixed(1).padStart(4, '0')}`;
  }

  // ---- PROG ----
  wireProg() {
    $('prog-file').onchange = async (e) => {
      const f = e.target.files[0];
      if (!f) return;
      const text = await f.text();
      await this.load(f.name, text);
      e.target.value = '';
    };
    $('restart-btn').onclick = () => {
      const n = +$('restart-line').value;
      this.io.command({ cmd: 'restart', line: n });
    };
    $('prog-save').onclick = () => this.load($('prog-edit-name').value || 'program.nc', $('prog-text').value);
  }

  /** Shows `line` selected; PROG moves to it and RESTART is set to it. */
  select(line) {
    this.selected = line;
    this.focusSelected = true;
    this.progTop = -1;
    $('restart-line').value = line;
    if (this.app.page === 'prog' && this.app.state) this.drawProg(this.app.state);
  }

  async load(name, text) {
    const r = await this.io.api('POST', `/api/program?name=${encodeURIComponent(name)}`, text, 'text/plain');
    if (r.ok) this.io.say(`loaded ${r.body.name}: ${r.body.lines} lines`);
    else this.io.say(`load: ${r.body.error ? r.body.error.message : r.status}`, true);
    this.chunks.clear();
    this.progTop = -1;
    return r;
  }

  async chunk(i) {
    if (this.chunks.has(i)) return this.chunks.get(i);
    const p = (async () => {
      const r = await this.io.api('GET', `/api/program?from=${i * CHUNK + 1}&count=${CHUNK}`);
      return r.ok ? r.body : { lines: [], total: 0, name: null };
    })();
    this.chunks.set(i, p);
    return p;
  }

  async drawProg(s) {
    const edit = s.mode === 'EDIT';
    $('prog-edit').hidden = !edit;
    $('prog-list').hidden = edit;
    $('prog-modal').textContent = s.modal.join(' ');
    const r = s.restart;
    $('restart-plan').textContent = r
      ? `RESTART AT LINE ${r.line}: T${r.tool} S${r.spindle_rpm} ${r.spindle_direction.toUpperCase()} F${r.feed ?? '-'}  RE-ENTRY: ${r.path.map((l) => `${l.kind.toUpperCase()} ${Object.entries(l.to).map(([k, v]) => `${k.toUpperCase()}${v.toFixed(3)}`).join(' ')}`).join(' → ')}`
      : '';
    const key = `${s.program.name}|${s.path.id}`;
    if (key !== this.progKey) {
      this.progKey = key;
      this.chunks.clear();
      this.progTop = -1;
      this.editLoaded = false;
    }
    if (!s.program.name) {
      $('prog-name').textContent = 'no program';
      return;
    }
    $('prog-name').textContent = s.program.name;
    if (edit && !this.editLoaded) {
      this.editLoaded = true;
      $('prog-edit-name').value = s.program.name;
      const first = await this.chunk(0);
      const all = [...first.lines];
      for (let i = 1; i * CHUNK < Math.min(first.total, 20000); i++) all.push(...(await this.chunk(i)).lines);
      $('prog-text').value = all.join('\n') + '\n';
    }
    if (s.execution === 'ACTIVE') this.focusSelected = false;
    const line = Math.max(1, this.focusSelected && this.selected ? this.selected : s.program.line);
    const top = Math.max(1, line - 6);
    if (top !== this.progTop) {
      this.progTop = top;
      const want = [];
      for (let n = top; n < top + LINES_SHOWN; n++) want.push(n);
      const rows = await Promise.all(want.map(async (n) => {
        const c = await this.chunk(Math.floor((n - 1) / CHUNK));
        $('prog-total').textContent = `${c.total} LINES`;
        return c.lines[(n - 1) % CHUNK];
      }));
      if (top !== this.progTop) return; // a newer draw took over
      const ol = $('prog-list');
      ol.innerHTML = '';
      rows.forEach((text, i) => {
        if (text === undefined) return;
        const li = document.createElement('li');
        li.dataset.n = top + i;
        li.textContent = text || ' ';
        li.onclick = () => this.app.select(top + i, 'prog');
        ol.append(li);
      });
    }
    for (const li of $('prog-list').children) {
      const n = +li.dataset.n;
      li.classList.toggle('current', n === s.program.line);
      li.classList.toggle('next', n > s.program.line && n <= s.program.line + 3);
      li.classList.toggle('selected', n === this.selected);
    }
  }

  // ---- MDI ----
  wireMdi() {
    $('mdi-run').onclick = async () => {
      const block = $('mdi-text').value;
      const r = await this.io.command({ cmd: 'mdi', block });
      $('mdi-status').textContent = r.ok ? 'EXECUTED' : (r.body.error ? r.body.error.message : 'ERROR');
    };
    $('mdi-text').onkeydown = (e) => {
      if (e.key === 'Enter' && (e.ctrlKey || e.metaKey)) $('mdi-run').click();
    };
  }

  drawMdi(s) {
    const g = $('mdi-modal');
    const html = s.modal.map((m) => `<span>${m}</span>`).join('');
    if (g.innerHTML !== html) g.innerHTML = html;
    $('mdi-f').textContent = fmt(s.feed.programmed, 0);
    $('mdi-s').textContent = fmt(s.spindle.programmed, 0);
    $('mdi-t').textContent = s.tool;
  }

  // ---- OFFSET / SETTING ----
  wireOffsets() {
    for (const b of document.querySelectorAll('[data-tab]')) {
      b.onclick = () => {
        for (const o of document.querySelectorAll('[data-tab]')) o.classList.toggle('on', o === b);
        for (const t of document.querySelectorAll('.tab')) t.hidden = t.id !== `ofs-${b.dataset.tab}`;
        if (b.dataset.tab === 'macro') this.loadVariables();
        if (b.dataset.tab === 'setting') this.drawSettings();
      };
    }
  }

  async loadOffsets() {
    const r = await this.io.api('GET', '/api/offsets');
    if (!r.ok) return;
    this.offsets = r.body;
    this.drawTools();
    this.drawWork();
  }

  cell(table, key, field, value) {
    const id = `ofs-${table}-${key}${field ? `-${field}` : ''}`;
    const digits = field === 'tip' ? 0 : 3;
    return `<td><input id="${id}" data-table="${table}" data-key="${key}" data-field="${field || ''}" value="${fmt(value ?? 0, digits)}"></td>`;
  }

  drawTools() {
    const o = this.offsets;
    const n = this.app.machine.offsets;
    let html;
    if (this.app.machine.kind === 'lathe') {
      html = '<table><tr><th>NO.</th><th>X</th><th>Z</th><th>R</th><th>T</th><th>WEAR X</th><th>WEAR Z</th><th>WEAR R</th></tr>';
      for (let i = 1; i <= n; i++) {
        const t = (o.tool && o.tool[i]) || {};
        html += `<tr><th>${String(i).padStart(2, '0')}</th>`;
        for (const f of ['x', 'z', 'r', 'tip', 'wear_x', 'wear_z', 'wear_r']) html += this.cell('tool', i, f, t[f]);
        html += '</tr>';
      }
    } else {
      html = '<table><tr><th>NO.</th><th>H GEOM</th><th>H WEAR</th><th>D GEOM</th><th>D WEAR</th></tr>';
      for (let i = 1; i <= n; i++) {
        html += `<tr><th>${String(i).padStart(3, '0')}</th>`;
        for (const t of ['h', 'h_wear', 'd', 'd_wear']) html += this.cell(t, i, null, o[t] && o[t][i]);
        html += '</tr>';
      }
    }
    $('ofs-tool').innerHTML = html + '</table>';
    this.wireCells($('ofs-tool'));
  }

  drawWork() {
    const o = this.offsets;
    const axes = this.app.machine.axes.map((a) => a.toLowerCase());
    const systems = Object.keys(o).filter((k) => /^(g5[4-9]|g54\.1)/.test(k) || k === 'ext');
    const names = systems.length ? systems : ['g54', 'g55', 'g56', 'g57', 'g58', 'g59'];
    let html = `<table><tr><th></th>${axes.map((a) => `<th>${a.toUpperCase()}</th>`).join('')}</tr>`;
    for (const g of names) {
      html += `<tr><th>${g.toUpperCase()}</th>`;
      for (const a of axes) html += this.cell(g, a, null, o[g] && o[g][a]);
      html += '</tr>';
    }
    $('ofs-work').innerHTML = html + '</table>';
    this.wireCells($('ofs-work'));
  }

  wireCells(root) {
    for (const inp of root.querySelectorAll('input')) {
      inp.onchange = async () => {
        const v = Number(inp.value);
        const { table, key, field } = inp.dataset;
        if (!Number.isFinite(v)) {
          $('ofs-status').textContent = `${inp.value}: not a number`;
          return;
        }
        const body = field ? { [table]: { [key]: { [field]: v } } } : { [table]: { [key]: v } };
        const r = await this.io.api('PUT', '/api/offsets', JSON.stringify(body));
        if (r.ok) {
          this.offsets = r.body;
          $('ofs-status').textContent = `${table.toUpperCase()} ${key}${field ? ` ${field}` : ''} = ${fmt(v)}: written`;
          inp.value = fmt(v, field === 'tip' ? 0 : 3);
        } else {
          $('ofs-status').textContent = r.body.error ? r.body.error.message : `error ${r.status}`;
        }
      };
    }
  }

  async loadVariables() {
    const r = await this.io.api('GET', '/api/variables');
    if (!r.ok) return;
    const rows = Object.entries(r.body).map(([k, v]) => `<tr><th>${k}</th><td>${fmt(v, 4)}</td></tr>`);
    $('ofs-macro').innerHTML = `<table><tr><th>NO.</th><th>DATA</th></tr>${rows.join('') || '<tr><td colspan="2">all vacant</td></tr>'}</table>`;
  }

  drawSettings() {
    const s = this.app.state;
    const m = this.app.machine;
    const rows = [
      ['MACHINE', `${m.name} (${m.kind})`],
      ['SINGLE BLOCK', s.switches.single_block ? 'ON' : 'OFF'],
      ['OPTIONAL STOP', s.switches.optional_stop ? 'ON' : 'OFF'],
      ['DRY RUN', s.switches.dry_run ? 'ON' : 'OFF'],
      ['BLOCK SKIP', s.switches.block_skip.join(',') || 'OFF'],
      ['FEED OVERRIDE', `${s.overrides.feed} %`],
      ['RAPID OVERRIDE', `${s.overrides.rapid} %`],
    ];
    const html = (list) => `<table>${list.map(([k, v]) => `<tr><th style="text-align:left">${k}</th><td style="text-align:left">${v}</td></tr>`).join('')}</table>`;
    $('ofs-setting').innerHTML = html(rows);
    // The control parameters follow (read from the runtime).
    this.io.api('GET', '/api/parameters').then((r) => {
      if (!r.ok) return;
      const params = Object.entries(r.body).map(([k, v]) => [`PARAM ${k}`, v]);
      $('ofs-setting').innerHTML = html([...rows, ...params]);
    });
  }

  // ---- ALARM ----
  async drawAlarm(s) {
    const a = s.alarm;
    const cur = $('alarm-current');
    if (a) {
      cur.className = 'alarm-on';
      cur.textContent = `${a.code}  ${a.message}   ${a.file}:${a.line}:${a.col}`;
      const pre = `${a.line}: `;
      $('alarm-block').textContent = a.block ? `${pre}${a.block}\n${' '.repeat(pre.length + Math.max(0, a.col - 1))}^` : '';
    } else {
      cur.className = 'alarm-none';
      cur.textContent = 'NO ALARM';
      $('alarm-block').textContent = '';
    }
    if (s.alarm_seq === this.alarmSeq) return;
    this.alarmSeq = s.alarm_seq;
    const r = await this.io.api('GET', '/api/alarms');
    if (!r.ok) return;
    const tb = $('alarm-history').tBodies[0];
    tb.innerHTML = '';
    for (const h of [...r.body.alarms].reverse()) {
      const tr = document.createElement('tr');
      tr.innerHTML = `<td>${h.seq}</td><td>${this.clock(h.t)}</td><td>${h.kind === 'alarm' ? h.code : 'MSG'}</td><td></td><td>${h.file}:${h.line}</td>`;
      tr.children[3].textContent = h.message;
      tb.append(tr);
    }
  }
}
