// GRAPH: the backplot in three.js. The server sends the planned path as
// binary point records (docs/hmi.md "Toolpath records"); they go straight
// into typed arrays of one line strip (a point repeated where the colour
// changes, so each segment has one colour). Orthographic camera with
// OrbitControls: orbit, pan, zoom; TOP/FRONT/SIDE/ISO views per machine.
import * as THREE from 'three';
import { OrbitControls } from './vendor/OrbitControls.js';
import { pick, LineIndex } from './lines.js';
import { Coarse } from './coarse.js';
import { ViewCopy } from './lod.js';
import { ScreenGrid } from './grid.js';

const RECORD = 20;
const KIND_COLOURS = {
  0: [0xe0, 0x50, 0x50], // rapid
  1: [0x40, 0xd0, 0xff], // feed
  2: [0x60, 0xff, 0x80], // arc
  3: [0xff, 0xd0, 0x40], // thread
  255: [0x80, 0x80, 0x80], // start
};
const TOOL_PALETTE = [
  [0xff, 0x70, 0x70], [0x70, 0xc0, 0xff], [0x90, 0xff, 0x70], [0xff, 0xd0, 0x50],
  [0xd0, 0x80, 0xff], [0x50, 0xff, 0xe0], [0xff, 0x90, 0x30], [0xff, 0x70, 0xd0],
];

/**
 * Most vertices of the coarse copy drawn while the camera moves or the
 * path streams in (the full path is drawn when both are still).
 */
const COARSE_MAX = 10000;

/** A path of at most this many vertices is drawn whole in every frame. */
const FULL_MAX = 50000;
/**
 * Larger paths are drawn decimated for the view. While the camera moves,
 * in screen space (grid.js): chords within MOVE_TOL_PX of the path, kept
 * only where they reach a cell MOVE_CELL_PX wide (or wider, to hold them)
 * no chord of their colour reached before, at most MOVE_SEGMENTS (a
 * software rasteriser spends a microsecond or more on each, a GPU
 * nothing); made again every MOVE_REBUILD_MS, or at once when the zoom
 * changed by a quarter. On a software rasteriser the moving view is
 * drawn at MOVE_SCALE of its resolution. With the camera still, at most
 * STILL_MAX vertices STILL_PX apart (lod.js), at full resolution: at that
 * spacing the frame looks as the whole path's does.
 */
const MOVE_SEGMENTS = { software: 4000, gpu: 60000 };
const MOVE_CELL_PX = 2;
const MOVE_TOL_PX = 1;
const MOVE_SCALE = 0.5;
const MOVE_REBUILD_MS = 200;
const STILL_MAX = 400000;
const STILL_PX = 0.5;
/**
 * The still copy is drawn only while its vertices are at most this many
 * pixels apart (past it, corners are visibly cut).
 */
const STILL_SPREAD_PX = 4;

/** Most segments one highlighted line draws. */
const HIGHLIGHT_MAX = 200000;

/** Box3.expandByPoint without making a Vector3. */
function grow(b, x, y, z) {
  if (x < b.min.x) b.min.x = x;
  if (y < b.min.y) b.min.y = y;
  if (z < b.min.z) b.min.z = z;
  if (x > b.max.x) b.max.x = x;
  if (y > b.max.y) b.max.y = y;
  if (z > b.max.z) b.max.z = z;
}

/** True when WebGL is drawn by a software rasteriser (no GPU). */
function softwareGL() {
  const c = document.createElement('canvas');
  const gl = c.getContext('webgl2') || c.getContext('webgl');
  if (!gl) return false;
  const ext = gl.getExtension('WEBGL_debug_renderer_info');
  const name = ext ? String(gl.getParameter(ext.UNMASKED_RENDERER_WEBGL)) : '';
  const lose = gl.getExtension('WEBGL_lose_context');
  if (lose) lose.loseContext();
  return /swiftshader|llvmpipe|softpipe|software/i.test(name);
}

export class Graph {
  constructor(el, machine, info) {
    this.el = el;
    this.machine = machine;
    this.info = info;
    this.lathe = machine.kind === 'lathe';
    this.byTool = false;
    this.pathId = -1;
    this.n = 0; // vertices used
    this.points = 0; // records received
    this.cap = 0;
    this.kinds = null; // kind per vertex (for recolouring)
    this.tools = null;
    this.lines = null; // program line per vertex
    this.keys = null; // colour key per vertex (kind, tool)
    this.coarse = new Coarse(COARSE_MAX);
    this.moving = false; // the camera is being dragged
    this.index = new LineIndex();
    this.indexAt = 0;
    this.selected = 0; // the line picked (or chosen on PROG), 0: none
    this.current = 0; // the executing line shown
    this.onPick = null; // called with the line picked
    this.box = new THREE.Box3(); // every point but the start
    this.cutBox = new THREE.Box3(); // feeds, arcs, threads
    this.frames = 0;
    this.frameTimes = [];
    this.firstFrameAt = null;

    // Multisampling costs a software rasteriser (SwiftShader, llvmpipe) 4
    // samples a pixel of every line, where the frame's cost is the pixels
    // the path covers; a GPU does it for free.
    this.software = softwareGL();
    this.renderer = new THREE.WebGLRenderer({ antialias: !this.software, preserveDrawingBuffer: true });
    this.pixelRatio = Math.min(devicePixelRatio, 2);
    this.renderer.setPixelRatio(this.pixelRatio);
    el.append(this.renderer.domElement);
    this.scene = new THREE.Scene();
    this.scene.background = new THREE.Color(machine.style === 'hurco' ? 0xf4f6f9 : 0x05070a);
    this.camera = new THREE.OrthographicCamera(-100, 100, 100, -100, -1e6, 1e6);
    this.controls = null;

    this.material = new THREE.LineBasicMaterial({ vertexColors: true });
    this.line = null;
    this.grow(1 << 14);
    const cg = new THREE.BufferGeometry();
    cg.setAttribute('position', new THREE.BufferAttribute(this.coarse.pos, 3));
    cg.setAttribute('color', new THREE.BufferAttribute(this.coarse.col, 3, true));
    cg.setDrawRange(0, 0);
    this.coarseLine = new THREE.Line(cg, this.material);
    this.coarseLine.frustumCulled = false;
    this.coarseLine.visible = false;
    this.scene.add(this.coarseLine);
    this.moveGrid = new ScreenGrid(this.software ? MOVE_SEGMENTS.software : MOVE_SEGMENTS.gpu);
    this.stillCopy = new ViewCopy(STILL_MAX);
    this.moveLine = this.copyLine(this.moveGrid, THREE.LineSegments);
    this.stillLine = this.copyLine(this.stillCopy);
    this.vp = new THREE.Matrix4();
    this.drewLod = null; // which copy the last frame drew

    this.axes = new THREE.AxesHelper(20);
    this.scene.add(this.axes);
    this.tool = this.makeTool();
    this.scene.add(this.tool);
    const dark = machine.style === 'hurco';
    this.hlCurrent = this.makeHighlight(dark ? 0x000000 : 0xffffff);
    this.hlSelected = this.makeHighlight(0xff30ff);
    this.hlCurrent.renderOrder = 4; // the executing block over a selection
    this.wirePick();

    new ResizeObserver(() => this.resize()).observe(el);
    for (const b of document.querySelectorAll('[data-view]')) b.onclick = () => this.view(b.dataset.view);
    const byTool = document.getElementById('graph-by-tool');
    byTool.onchange = () => { this.byTool = byTool.checked; this.recolour(); };
    this.resize();
    this.view(this.lathe ? 'front' : 'iso');
  }

  /** A line (or `Kind` of line) drawing a copy's arrays. */
  copyLine(copy, Kind = THREE.Line) {
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.BufferAttribute(copy.pos, 3));
    g.setAttribute('color', new THREE.BufferAttribute(copy.col, 3, true));
    g.setDrawRange(0, 0);
    const l = new Kind(g, this.material);
    l.frustumCulled = false;
    l.visible = false;
    this.scene.add(l);
    return l;
  }

  /**
   * Makes `copy` again for the camera now when it was made for another
   * view or path (while moving, at most every MOVE_REBUILD_MS unless the
   * zoom changed by a quarter): moving, the screen grid (grid.js) with
   * cells `px` pixels wide; still, the view copy (lod.js) with vertices
   * `px` pixels apart, or (`grid`) the screen grid made for this view.
   */
  refresh(copy, line, px, moving, grid = moving) {
    this.camera.updateMatrixWorld();
    const m = this.vp.multiplyMatrices(this.camera.projectionMatrix, this.camera.matrixWorldInverse).elements;
    if (copy.fits(m, this.n)) return;
    const canvas = this.renderer.domElement;
    const worldPx = (this.camera.top - this.camera.bottom) / this.camera.zoom / Math.max(canvas.height, 1);
    if (moving && copy.builtN === this.n) {
      const zoom = copy.worldPx / worldPx;
      // A copy is 3-D: one made for a view a little turned still draws
      // right, only its density lags; so it is made again at most every
      // MOVE_REBUILD_MS, or four times its own build time (the build at
      // most a fifth of the frames' time), unless the zoom changed.
      const wait = Math.max(MOVE_REBUILD_MS, 4 * copy.buildMs);
      if (performance.now() - copy.at < wait && zoom < 1.25 && zoom > 0.8) return;
    }
    const g = this.line.geometry;
    const pos = g.attributes.position.array, col = g.attributes.color.array;
    if (grid) copy.build(pos, col, this.keys, this.n, m, canvas.width, canvas.height, px, { tol: MOVE_TOL_PX, byTool: this.byTool });
    else copy.build(pos, col, this.keys, this.n, m, worldPx * px);
    copy.worldPx = worldPx;
    copy.at = performance.now();
    const lg = line.geometry;
    lg.attributes.position.clearUpdateRanges();
    lg.attributes.color.clearUpdateRanges();
    lg.attributes.position.addUpdateRange(0, copy.n * 3);
    lg.attributes.color.addUpdateRange(0, copy.n * 3);
    lg.attributes.position.needsUpdate = true;
    lg.attributes.color.needsUpdate = true;
    lg.setDrawRange(0, copy.n);
  }

  makeTool() {
    const g = new THREE.ConeGeometry(2, 8, 16);
    // Tip at the origin, pointing along -Z (mill) or -X (lathe insert).
    g.translate(0, 4, 0);
    if (this.lathe) g.rotateZ(Math.PI / 2);
    else g.rotateX(Math.PI / 2);
    const colour = this.machine.style === 'hurco' ? 0x202830 : 0xffffff;
    const m = new THREE.Mesh(g, new THREE.MeshBasicMaterial({ color: colour, transparent: true, opacity: 0.85 }));
    m.renderOrder = 2;
    return m;
  }

  /** A line drawn over the path (depth test off) for one program line. */
  makeHighlight(colour) {
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.BufferAttribute(new Float32Array(6), 3));
    g.setDrawRange(0, 0);
    const l = new THREE.LineSegments(g, new THREE.LineBasicMaterial({ color: colour, depthTest: false, transparent: true }));
    l.frustumCulled = false;
    l.renderOrder = 3;
    this.scene.add(l);
    return l;
  }

  /** The index by line, brought up to the path (at most once a second while it streams in). */
  lineIndex() {
    const now = performance.now();
    if (this.index.n !== this.n && (this.done || now - this.indexAt > 1000)) {
      this.index.update(this.lines, this.n);
      this.indexAt = now;
    }
    return this.index;
  }

  /** Draws the segments of program line `line` with `hl` (none for 0). */
  showLine(hl, line) {
    const v = line > 0 ? this.lineIndex().of(line) : new Uint32Array(0);
    const src = this.line.geometry.attributes.position.array;
    const count = Math.min(v.length, HIGHLIGHT_MAX);
    let a = hl.geometry.attributes.position;
    if (a.array.length < count * 6) {
      a = new THREE.BufferAttribute(new Float32Array(count * 6), 3);
      hl.geometry.setAttribute('position', a);
    }
    let k = 0;
    for (let j = 0; j < count; j++) {
      const i = v[j];
      if (i === 0) continue;
      a.array.set(src.subarray((i - 1) * 3, i * 3 + 3), k * 6);
      k++;
    }
    a.needsUpdate = true;
    hl.geometry.setDrawRange(0, k * 2);
    hl.shownLine = line;
    hl.shownN = this.n;
    return k;
  }

  /** Selects a program line (from a pick or from PROG): drawn in magenta. */
  select(line) {
    this.selected = line;
    this.showLine(this.hlSelected, line);
    this.render();
  }

  /** A click (not a drag) on the view picks the nearest segment's line. */
  wirePick() {
    const el = this.renderer.domElement;
    let down = null;
    el.addEventListener('pointerdown', (e) => { down = e.button === 0 ? [e.clientX, e.clientY] : null; });
    el.addEventListener('pointerup', (e) => {
      if (!down || Math.hypot(e.clientX - down[0], e.clientY - down[1]) > 4) return;
      const r = el.getBoundingClientRect();
      const line = this.pickAt(e.clientX - r.left, e.clientY - r.top, r.width, r.height);
      if (line > 0) {
        this.select(line);
        if (this.onPick) this.onPick(line);
      }
    });
  }

  /** The program line of the segment nearest pixel (x, y) of a w×h view; 0 when none. */
  pickAt(x, y, w, h) {
    this.camera.updateMatrixWorld();
    const m = new THREE.Matrix4().multiplyMatrices(this.camera.projectionMatrix, this.camera.matrixWorldInverse);
    const i = pick(this.line.geometry.attributes.position.array, this.n, m.elements, w, h, x, y);
    return i > 0 ? this.lines[i] : 0;
  }

  /** Makes room for `need` vertices (keeping those drawn). */
  grow(need) {
    if (need <= this.cap) return;
    let cap = Math.max(this.cap * 2, 1 << 14);
    while (cap < need) cap *= 2;
    const pos = new Float32Array(cap * 3);
    const col = new Uint8Array(cap * 3);
    const kinds = new Uint8Array(cap);
    const tools = new Uint8Array(cap);
    const lines = new Uint32Array(cap);
    const keys = new Uint16Array(cap);
    if (this.line) {
      pos.set(this.line.geometry.attributes.position.array.subarray(0, this.n * 3));
      col.set(this.line.geometry.attributes.color.array.subarray(0, this.n * 3));
      kinds.set(this.kinds.subarray(0, this.n));
      tools.set(this.tools.subarray(0, this.n));
      lines.set(this.lines.subarray(0, this.n));
      keys.set(this.keys.subarray(0, this.n));
      this.scene.remove(this.line);
      this.line.geometry.dispose();
    }
    const geo = new THREE.BufferGeometry();
    geo.setAttribute('position', new THREE.BufferAttribute(pos, 3));
    geo.setAttribute('color', new THREE.BufferAttribute(col, 3, true));
    geo.setDrawRange(0, this.n);
    this.line = new THREE.Line(geo, this.material);
    this.line.frustumCulled = false;
    this.scene.add(this.line);
    this.cap = cap;
    this.kinds = kinds;
    this.tools = tools;
    this.lines = lines;
    this.keys = keys;
  }

  colour(kind, tool) {
    const c = this.byTool ? TOOL_PALETTE[tool % TOOL_PALETTE.length] : (KIND_COLOURS[kind] || KIND_COLOURS[1]);
    // The light (Hurco) screen: the same hues, darker.
    return this.machine.style === 'hurco' ? c.map((v) => Math.round(v * 0.6)) : c;
  }

  clear(id) {
    this.pathId = id;
    this.n = 0;
    this.points = 0;
    this.box.makeEmpty();
    this.cutBox.makeEmpty();
    this.fitted = false;
    this.line.geometry.setDrawRange(0, 0);
    this.index = new LineIndex();
    this.coarse.clear();
    this.moveGrid.reset();
    this.stillCopy.reset();
    for (const hl of [this.hlCurrent, this.hlSelected]) { hl.geometry.setDrawRange(0, 0); hl.shownLine = 0; }
  }

  /** One binary message: 16-byte header, then records. */
  records(buf) {
    const dv = new DataView(buf);
    const id = dv.getUint32(0, true), first = dv.getUint32(4, true), count = dv.getUint32(8, true);
    if (this.firstRecordsAt === undefined && count > 0) this.firstRecordsAt = performance.now();
    if (id !== this.pathId) this.clear(id);
    if (first !== this.points) return; // out of order: the next state resends
    this.grow(this.n + count * 2 + 2);
    const pos = this.line.geometry.attributes.position.array;
    const col = this.line.geometry.attributes.color.array;
    const start = this.n;
    let lastKind = this.n ? this.kinds[this.n - 1] : -1;
    let lastTool = this.n ? this.tools[this.n - 1] : -1;
    for (let i = 0; i < count; i++) {
      const o = 16 + i * RECORD;
      const x = dv.getFloat32(o, true), y = dv.getFloat32(o + 4, true), z = dv.getFloat32(o + 8, true);
      const kind = dv.getUint8(o + 16), tool = dv.getUint8(o + 17), ln = dv.getUint32(o + 12, true);
      if (this.n > 0 && (kind !== lastKind || tool !== lastTool)) {
        // Repeat the previous point in the new colour: the segment to
        // this point is drawn in one colour.
        const p = (this.n - 1) * 3;
        this.put(pos, col, pos[p], pos[p + 1], pos[p + 2], kind, tool, ln);
      }
      this.put(pos, col, x, y, z, kind, tool, ln);
      if (kind !== 255) {
        grow(this.box, x, y, z);
        if (kind !== 0) {
          // A cut runs from the point before it.
          grow(this.cutBox, x, y, z);
          if (this.n > 1) {
            const p = (this.n - 2) * 3;
            grow(this.cutBox, pos[p], pos[p + 1], pos[p + 2]);
          }
        }
      }
      lastKind = kind;
      lastTool = tool;
    }
    this.points += count;
    const g = this.line.geometry;
    g.attributes.position.addUpdateRange(start * 3, (this.n - start) * 3);
    g.attributes.color.addUpdateRange(start * 3, (this.n - start) * 3);
    g.attributes.position.needsUpdate = true;
    g.attributes.color.needsUpdate = true;
    g.setDrawRange(0, this.n);
    // Frame the first points at once and the whole path when it is complete.
    const done = dv.getUint32(12, true) === 1;
    if (done) {
      this.complete();
      return;
    }
    if (!this.fitted && this.n > 1) this.view(this.lastView || (this.lathe ? 'front' : 'iso'));
    this.done = false;
    // While the path streams in, draw at most four times a second (the
    // coarse copy when the path is larger than it).
    const now = performance.now();
    if (done || !this.lastStreamDraw || now - this.lastStreamDraw > 250) {
      this.lastStreamDraw = now;
      this.render();
    }
  }

  /** The whole path is in: the coarse copy ends where it does, framed, drawn. */
  complete() {
    this.done = true;
    const g = this.line.geometry;
    this.coarse.finish(g.attributes.position.array, g.attributes.color.array, this.n);
    if (this.n > 1) this.view(this.lastView || (this.lathe ? 'front' : 'iso'));
    this.render();
  }

    put(pos, col, x, y, z, kind, tool, line) {
    const i = this.n * 3;
    pos[i] = x; pos[i + 1] = y; pos[i + 2] = z;
    const c = this.colour(kind, tool);
    col[i] = c[0]; col[i + 1] = c[1]; col[i + 2] = c[2];
    this.kinds[this.n] = kind;
    this.tools[this.n] = tool;
    this.lines[this.n] = line;
    this.keys[this.n] = kind * 256 + tool;
    this.coarse.add(pos, col, this.keys, this.n);
    this.n++;
  }

  recolour() {
    const col = this.line.geometry.attributes.color.array;
    for (let i = 0; i < this.n; i++) {
      const c = this.colour(this.kinds[i], this.tools[i]);
      col.set(c, i * 3);
    }
    this.line.geometry.attributes.color.clearUpdateRanges();
    this.line.geometry.attributes.color.needsUpdate = true;
    this.coarse.recolour(col);
    this.moveGrid.reset();
    this.stillCopy.builtN = -1;
    this.render();
  }

  /**
   * The simulated part (binary STL from the server) as a translucent
   * mesh: fetched again whenever the state's `part_seq` changes (the part
   * cut so far while the program runs), one fetch at a time.
   */
  async loadPart(seq) {
    this.partSeq = seq;
    if (this.partLoading) return;
    this.partLoading = true;
    try {
      for (let want = seq; ; want = this.partSeq) {
        await this.fetchPart();
        if (this.partSeq === want) break;
      }
    } finally {
      this.partLoading = false;
    }
  }

  async fetchPart() {
    const r = await fetch('/api/part.stl');
    if (!r.ok) return;
    const dv = new DataView(await r.arrayBuffer());
    const n = dv.byteLength >= 84 ? dv.getUint32(80, true) : 0;
    if (84 + n * 50 > dv.byteLength) return;
    const pos = new Float32Array(n * 9);
    const nor = new Float32Array(n * 9);
    for (let i = 0; i < n; i++) {
      const o = 84 + i * 50;
      for (let v = 0; v < 3; v++) {
        for (let k = 0; k < 3; k++) {
          pos[i * 9 + v * 3 + k] = dv.getFloat32(o + 12 + v * 12 + k * 4, true);
          nor[i * 9 + v * 3 + k] = dv.getFloat32(o + k * 4, true);
        }
      }
    }
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.BufferAttribute(pos, 3));
    g.setAttribute('normal', new THREE.BufferAttribute(nor, 3));
    if (this.part) { this.scene.remove(this.part); this.part.geometry.dispose(); }
    this.partMaterial ||= new THREE.MeshNormalMaterial({ transparent: true, opacity: 0.55, side: THREE.DoubleSide, depthWrite: false });
    this.part = new THREE.Mesh(g, this.partMaterial);
    this.part.renderOrder = 1;
    this.scene.add(this.part);
    this.partTriangles = n;
    this.partLoads = (this.partLoads || 0) + 1;
    this.render();
  }

  /** The newest machine state: the tool's live position. */
  state(s, shown) {
    // The server may finish the trace after sending the last points: the
    // state then says the path is complete.
    if (!this.done && s.path.done && s.path.id === this.pathId && this.points === s.path.points) this.complete();
    if (s.path.part && this.partSeq !== s.path.part_seq) this.loadPart(s.path.part_seq);
    if (!s.path.part && this.part) {
      this.scene.remove(this.part);
      this.part.geometry.dispose();
      this.part = null;
      this.partTriangles = 0;
      this.partSeq = undefined;
    }
    // The executing block on the path (blocks of the main program).
    const cur = s.program.file === s.program.name ? s.program.line : 0;
    if (cur !== this.hlCurrent.shownLine || (cur && this.hlCurrent.shownN !== this.n && this.done)) this.showLine(this.hlCurrent, cur);
    if (this.selected && this.hlSelected.shownN !== this.n && this.done) this.showLine(this.hlSelected, this.selected);
    const w = s.position.work;
    // A frame only when the tool has moved (states come at 30 Hz; a frame
    // of a large path costs more than that in software GL).
    const moved = this.tool.position.x !== (w.X || 0) || this.tool.position.y !== (w.Y || 0) || this.tool.position.z !== (w.Z || 0);
    this.tool.position.set(w.X || 0, w.Y || 0, w.Z || 0);
    if (this.info) {
      this.info.textContent = `${this.points} PTS${s.path.done ? '' : ' …'}${s.path.note ? ` (${s.path.note})` : ''}${this.selected ? `  SEL LINE ${this.selected}` : ''}  X${(w.X || 0).toFixed(3)} ${this.lathe ? '' : `Y${(w.Y || 0).toFixed(3)} `}Z${(w.Z || 0).toFixed(3)}`;
      // The line is cut to the view's width; the whole of it on hover.
      this.info.title = this.info.textContent;
    }
    if (shown && (moved || cur !== this.lastDrawnLine)) this.render();
    this.lastDrawnLine = cur;
  }

  visible() {
    this.resize();
  }

  resize() {
    const w = this.el.clientWidth || 1, h = this.el.clientHeight || 1;
    this.renderer.setSize(w, h, false);
    this.aspect = w / h;
    this.frameCamera();
    this.render();
  }

  frameCamera() {
    const half = this.half || 100;
    this.camera.left = -half * this.aspect;
    this.camera.right = half * this.aspect;
    this.camera.top = half;
    this.camera.bottom = -half;
    this.camera.updateProjectionMatrix();
  }

  /** top | front | side | iso | fit */
  view(name) {
    if (name !== 'fit') this.lastView = name;
    // Frame the cutting moves (rapids to and from the reference point
    // would shrink the part to a dot); all moves when nothing cuts.
    const box = !this.cutBox.isEmpty() ? this.cutBox
      : !this.box.isEmpty() ? this.box
        : new THREE.Box3(new THREE.Vector3(-50, -50, -50), new THREE.Vector3(50, 50, 50));
    const centre = box.getCenter(new THREE.Vector3());
    const size = box.getSize(new THREE.Vector3());
    const radius = Math.max(size.length() / 2, 1);
    const v = this.lastView || 'iso';
    // Direction from the target to the camera and the screen's up.
    const dirs = this.lathe
      ? { front: [[0, 1, 0], [1, 0, 0]], top: [[1, 0, 0], [0, -1, 0]], side: [[0, 0, 1], [1, 0, 0]], iso: [[0.6, 0.6, 0.5], [1, 0, 0]] }
      : { top: [[0, 0, 1], [0, 1, 0]], front: [[0, -1, 0], [0, 0, 1]], side: [[1, 0, 0], [0, 0, 1]], iso: [[1, -1, 1], [0, 0, 1]] };
    const [d, up] = dirs[v] || dirs.iso;
    const dir = new THREE.Vector3(...d).normalize();
    this.camera.up.set(...up);
    this.camera.position.copy(centre).addScaledVector(dir, radius * 4);
    this.half = radius * 1.1;
    this.camera.zoom = 1;
    this.frameCamera();
    this.camera.lookAt(centre);
    // OrbitControls takes the camera's up when it is made: a new one per
    // view, so orbiting turns about that view's up axis.
    if (this.controls) this.controls.dispose();
    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.controls.enableDamping = false;
    this.controls.screenSpacePanning = true;
    this.controls.target.copy(centre);
    this.controls.addEventListener('change', () => this.render());
    this.controls.addEventListener('start', () => { this.moving = true; });
    this.controls.addEventListener('end', () => { this.moving = false; this.render(); });
    this.controls.update();
    this.axes.scale.setScalar(Math.max(radius / 5, 1) / 20);
    this.tool.scale.setScalar(Math.max(radius / 40, 0.5));
    this.fitted = !this.box.isEmpty();
    this.render();
  }

  /**
   * Draws the scene now. A path of FULL_MAX vertices or fewer is drawn
   * whole; a larger one as the coarse copy while it streams in, then
   * decimated for the view: on the screen grid while the camera moves
   * (grid.js), STILL_MAX vertices when it is still (lod.js), or the
   * screen grid again when no such copy holds the view.
   */
  draw() {
    let show = this.line;
    if (this.n <= FULL_MAX || !this.done) this.scaleFor(false);
    if (this.n > FULL_MAX && !this.done) {
      show = this.coarseLine;
      if (this.coarse.changed) {
        const g = this.coarseLine.geometry;
        g.attributes.position.needsUpdate = true;
        g.attributes.color.needsUpdate = true;
        g.setDrawRange(0, this.coarse.n);
        this.coarse.changed = false;
      }
    } else if (this.n > FULL_MAX) {
      const moving = this.moving;
      this.scaleFor(moving);
      const copy = moving ? this.moveGrid : this.stillCopy;
      show = moving ? this.moveLine : this.stillLine;
      this.refresh(copy, show, moving ? MOVE_CELL_PX : STILL_PX, moving);
      // A view the still copy cannot hold within STILL_SPREAD_PX (passes
      // drawn over each other more often than it has room for: keeping
      // vertices apart cannot thin a path that only retraces itself, it
      // cuts its corners): the screen grid, which drops the passes that
      // reach no cell not drawn before.
      if (!moving && (copy.failed || copy.scale * STILL_PX > STILL_SPREAD_PX)) {
        this.refresh(this.moveGrid, this.moveLine, MOVE_CELL_PX, false, true);
        show = this.moveLine;
      }
    }
    this.line.visible = show === this.line;
    this.coarseLine.visible = show === this.coarseLine;
    this.moveLine.visible = show === this.moveLine;
    this.stillLine.visible = show === this.stillLine;
    this.drewCoarse = show === this.coarseLine;
    this.drewLod = show === this.moveLine ? 'move' : show === this.stillLine ? 'still' : show === this.line ? 'full' : 'coarse';
    this.drewVertices = show === this.line ? this.n : show === this.coarseLine ? this.coarse.n
      : (show === this.moveLine ? this.moveGrid : this.stillCopy).n;
    this.renderer.render(this.scene, this.camera);
  }

  /**
   * On a software rasteriser a frame costs its pixels: while the camera
   * moves over a large path the view is drawn at MOVE_SCALE of its
   * resolution (the browser scales it up), at full resolution again when
   * it is still.
   */
  scaleFor(moving) {
    const ratio = this.pixelRatio * (moving && this.software ? MOVE_SCALE : 1);
    if (this.renderer.getPixelRatio() === ratio) return;
    this.renderer.setPixelRatio(ratio);
    this.renderer.setSize(this.el.clientWidth || 1, this.el.clientHeight || 1, false);
  }

  render() {
    if (this.pending) return;
    this.pending = true;
    requestAnimationFrame((t) => {
      this.pending = false;
      this.draw();
      this.frames++;
      if (this.n > 1 && this.firstFrameAt === null) this.firstFrameAt = performance.now();
      this.frameTimes.push(t);
      if (this.frameTimes.length > 120) this.frameTimes.shift();
    });
  }
}
