#!/usr/bin/env python3
"""Independent reference timing of kerf's motion law (docs/motion.md).

Written from docs/motion.md, docs/formats.md and machines/*.toml only,
without reading kerf-motion's source: an outside check of issue 8's
acceptance (kerf and an independent computation agree within 1 %).

Usage:
    kerf run PROG.nc --machine NAME --toolpath tp.jsonl --report rep.json
    python3 tools/motion_reference.py PROG.nc tp.jsonl machines/NAME.toml \
        [--report rep.json] [--rapid-override P] [--window N] [-v]

(--window overrides motion.lookahead, e.g. 100 for a G10.3 program.)
tools/motionref/ holds the comparison programs and run_kerf.sh.

Prints the reference cycle time (and kerf's, from the report, with the
relative difference); -v prints every record's t_end beside kerf's.

What it reads: every motion and dwell from the toolpath (machine
coordinates `mto`, `kind`, `feed`, `feed_per_rev`, `center`, `dir`,
`seconds`); what the toolpath does not carry it takes from a plain scan of
the program text, block by block (straight programs only: no macros,
loops or subprograms): G09/G61/G62/G63/G64, G17/G18/G19, G96/G97 S, the
spindle clamp (PUMA G50 S, HX/Hurco G92 S), S, M03/M04/M05, M06, lathe T,
M08/M09 and other M codes. Python 3.11+ standard library only.
"""
import argparse
import cmath
import json
import math
import re
import sys
import tomllib

SLOTS = "xyzabc"


class Profile:
    def __init__(self, path):
        with open(path, "rb") as f:
            p = tomllib.load(f)
        self.dialect = p["dialect"]
        self.kind = p["kind"]
        self.axes = [a for a in SLOTS if a in p["axes"]]
        m = p["motion"]
        ax = m["axes"]
        self.a = {i: ax[i]["accel"] for i in self.axes}
        self.j = {i: ax[i]["jerk"] for i in self.axes}
        self.ra = {i: ax[i]["rapid_accel"] for i in self.axes}
        self.w = {i: ax[i]["in_position_mm"] for i in self.axes}
        self.V = {i: p["axes"][i]["rapid"] / 60.0 for i in self.axes}
        self.k = 2 if m["accel_type"] == "bell" else 1
        self.T = max(max(self.a[i] / self.j[i], 2 * self.ra[i] / self.j[i]) for i in self.axes)
        self.K = float(m.get("position_gain", 30.0))
        self.tol = m["path_tolerance_mm"]
        self.window = m["lookahead"]
        self.spindle_accel = m["spindle_accel_rpm_s"]
        self.aux = m["aux_time_s"]
        self.max_cutting = p["feed"]["max_cutting"]
        self.max_rpm = p["spindle"]["max_rpm"]
        self.tool_change = p["tools"]["change_time_s"]
        self.g54 = p.get("work_offsets", {}).get("g54", {})
        self.start = {i: p["axes"][i].get("start", p["axes"][i]["reference"]) for i in self.axes}
        if self.k == 2:
            self.m1, self.m2 = self.T / 6, self.T ** 2 / 24
        else:
            self.m1, self.m2 = self.T / 8, self.T ** 2 / 48


# ---------------------------------------------------------------- geometry

def vsub(a, b):
    return {k: a[k] - b.get(k, 0.0) for k in a}


def norm(v):
    return math.sqrt(sum(x * x for x in v.values()))


def unit(v):
    n = norm(v)
    return {k: (x / n if n > 0 else 0.0) for k, x in v.items()}


PLANES = {17: ("x", "y", "z"), 18: ("z", "x", "y"), 19: ("y", "z", "x")}


class Move:
    """One cutting move: length, cruise limit, path acceleration, tangents."""

    def __init__(self, prof, start, end, feed, arc=None, plane=17):
        self.start, self.end, self.arc = start, end, arc
        self.F = feed / 60.0
        a_half = {i: prof.a[i] / 2 for i in prof.axes}
        if arc is None:
            d = vsub(end, start)
            self.L = norm(d)
            self.u0 = self.u1 = unit(d)
            u = self.u0
            self.v = min([self.F] + [prof.V[i] / abs(u[i]) for i in prof.axes if abs(u[i]) > 1e-12])
            self.A = min([a_half[i] / abs(u[i]) for i in prof.axes if abs(u[i]) > 1e-12] or [1.0])
            return
        p, q, n = PLANES[plane]
        centre, cw = arc
        z0 = complex(start[p] - centre[p], start[q] - centre[q])
        z1 = complex(end[p] - centre[p], end[q] - centre[q])
        R = abs(z0)
        th0, th1 = cmath.phase(z0), cmath.phase(z1)
        sweep = th1 - th0
        if cw:
            while sweep >= -1e-12:
                sweep -= 2 * math.pi
        else:
            while sweep <= 1e-12:
                sweep += 2 * math.pi
        h = end.get(n, 0.0) - start.get(n, 0.0)
        self.p, self.q, self.n = p, q, n
        self.R, self.th0, self.sweep, self.h = R, th0, sweep, h
        self.L = math.hypot(R * sweep, h)
        self.u0, self.u1 = self.tangent(th0), self.tangent(th0 + sweep)
        moving = [p, q] + ([n] if abs(h) > 1e-12 and n in prof.axes else [])
        amin = min(prof.a[i] for i in moving)
        jmin = min(prof.j[i] for i in moving)
        self.A = amin / 2
        self.v = min(self.F, min(prof.V[i] for i in moving), math.sqrt(amin / 2 * R),
                     (jmin / 2 * R * R) ** (1 / 3),
                     math.sqrt(24 * R * prof.tol / (prof.k * prof.T ** 2)))

    def tangent(self, th):
        s = 1.0 if self.sweep > 0 else -1.0
        ct = self.R * abs(self.sweep) / self.L
        u = {self.p: -math.sin(th) * s * ct, self.q: math.cos(th) * s * ct}
        u[self.n] = self.h / self.L
        return u


def trapezoid(v0, v1, v, A, L):
    """Peak speed and phase durations (accel, cruise, decel)."""
    if L <= 0:
        return 0.0, 0.0, 0.0, 0.0
    vp = min(v, math.sqrt(max(0.0, (2 * A * L + v0 * v0 + v1 * v1) / 2)))
    vp = max(vp, v0, v1)
    ta, td = (vp - v0) / A, (vp - v1) / A
    dc = L - (vp * vp - v0 * v0) / (2 * A) - (vp * vp - v1 * v1) / (2 * A)
    tc = max(0.0, dc) / vp if vp > 0 else 0.0
    return vp, ta, tc, td


def junction(prof, m1, m2):
    """Speed limit at the junction m1 -> m2 (0 = exact stop), docs/motion.md."""
    c = sum(m1.u1.get(i, 0) * m2.u0.get(i, 0) for i in prof.axes)
    th = math.acos(max(-1.0, min(1.0, c)))
    lim = [m1.v, m2.v]
    Lmin = min(m1.L, m2.L)
    for i in prof.axes:
        du = abs(m2.u0.get(i, 0) - m1.u1.get(i, 0))
        if du > 1e-12:
            lim.append(prof.a[i] / 2 * prof.T / du)
            lim.append(math.sqrt(prof.a[i] / 2 * Lmin / du))
    s = math.sin(th / 2)
    if s > 1e-12:
        A = max(m1.A, m2.A)
        vc = (prof.tol / (2 * s) - prof.m2 * A) / prof.m1
        if vc <= 0:
            return 0.0
        lim.append(vc)
        lim.append(math.sqrt(24 * (Lmin / th) * prof.tol / (prof.k * prof.T ** 2)))
    return max(0.0, min(lim))


# ------------------------------------------------------------ servo error

class Servo:
    def __init__(self, prof):
        self.prof = prof
        self.eps = {i: 0.0 for i in prof.axes}

    def line(self, u, v0, a, dt):
        K = self.prof.K
        if dt <= 0 or math.isinf(K):
            return
        x = K * dt
        E = math.exp(-x)
        g = v0 * (1 - E) / K + a * (x - (1 - E)) / K ** 2
        for i in self.eps:
            self.eps[i] = self.eps[i] * E + u.get(i, 0.0) * g

    def rest(self, dt):
        self.line({}, 0.0, 0.0, dt)

    def arc_const(self, m, th_a, th_b, dt):
        K = self.prof.K
        if dt <= 0 or math.isinf(K):
            return
        E = math.exp(-K * dt)
        w = (th_b - th_a) / dt
        g = 1j * w * m.R * (cmath.exp(1j * th_b) - E * cmath.exp(1j * th_a)) / (K + 1j * w)
        self.eps[m.p] = self.eps[m.p] * E + g.real
        self.eps[m.q] = self.eps[m.q] * E + g.imag
        if m.n in self.eps:
            vn = (m.h / dt) if dt > 0 else 0.0
            self.eps[m.n] = self.eps[m.n] * E + vn * (1 - E) / K

    def wait(self):
        p = self.prof
        if math.isinf(p.K):
            return 0.0
        f = ((1 - math.exp(-p.K * p.T)) / (p.K * p.T)) ** p.k
        wt = 0.0
        for i, e in self.eps.items():
            e = abs(f * e)
            if e > p.w[i]:
                wt = max(wt, math.log(e / p.w[i]) / p.K)
        self.eps = {i: 0.0 for i in p.axes}
        return wt


def servo_move(sv, m, v0, vp, v1, ta, tc, td):
    """Carry the following error through one cutting move's three phases."""
    A = m.A
    if m.arc is None:
        sv.line(m.u0, v0, A, ta)
        sv.line(m.u0, vp, 0.0, tc)
        sv.line(m.u0, vp, -A, td)
        return
    # arc: angle as a function of path distance
    k = m.sweep / m.L
    s = 0.0
    for (vs, acc, dt) in ((v0, A, ta), (vp, 0.0, tc), (vp, -A, td)):
        if dt <= 0:
            continue
        d = vs * dt + acc * dt * dt / 2
        tha, thb = m.th0 + k * s, m.th0 + k * (s + d)
        if acc == 0.0:
            sv.arc_const(m, tha, thb, dt)
        else:
            n = max(1, min(256, math.ceil(abs(thb - tha) / 0.02)))
            h = dt / n       # equal time steps, tangent at the middle instant
            for st in range(n):
                t0, tm = st * h, (st + 0.5) * h
                thm = m.th0 + k * (s + vs * tm + acc * tm * tm / 2)
                sv.line(m.tangent(thm), vs + acc * t0, acc, h)
        s += d


# ------------------------------------------------------------ program scan

WORD = re.compile(r"([A-Z])\s*([-+]?\d*\.?\d*)")


def scan(path):
    """Per line: list of (letter, value) words (comments stripped)."""
    out = {}
    for n, text in enumerate(open(path, encoding="latin-1"), 1):
        t = re.sub(r"\([^)]*\)", "", text.upper()).split(";")[0]
        ws = [(l, float(v)) for l, v in WORD.findall(t) if v not in ("", "+", "-", ".")]
        out[n] = ws
    return out


# ------------------------------------------------------------ timeline

class Reference:
    def __init__(self, prof, window=None, rapid_override=100.0):
        self.p = prof
        self.t = 0.0
        self.window = window or prof.window
        self.rov = rapid_override / 100.0
        self.pending = []      # cutting moves not yet at rest: (Move, rec)
        self.t_end = []        # (rec, t_end)
        self.buckets = {"rapid": 0.0, "cutting": 0.0, "dwell": 0.0, "tool_change": 0.0, "other": 0.0}

    def add(self, bucket, dt):
        self.t += dt
        self.buckets[bucket] += dt

    def stop(self, sv, bucket):
        self.add(bucket, self.p.k * self.p.T + sv.wait())

    def flush(self, exact_after=None):
        """Plan the pending run of cutting moves, ending at rest."""
        ms = self.pending
        if not ms:
            return
        self.pending = []
        n = len(ms)
        J = [0.0 if (i in (exact_after or set())) else junction(self.p, ms[i][0], ms[i + 1][0])
             for i in range(n - 1)] + [0.0]
        for i, (m, r) in enumerate(ms):
            if r.get("_exact"):
                J[i] = 0.0
        # look-ahead: move i is released when the N-th move after it
        # arrives; it is planned to stop at the end of move i+N
        vend = []
        v0 = 0.0
        N = self.window
        for i in range(n):
            last = min(n - 1, i + N)
            vb = 0.0
            for jdx in range(last, i, -1):
                m = ms[jdx][0]
                vb = min(J[jdx - 1], math.sqrt(vb * vb + 2 * m.A * m.L))
            m = ms[i][0]
            v1 = min(vb, J[i], math.sqrt(v0 * v0 + 2 * m.A * m.L))
            vend.append((v0, v1))
            v0 = v1
        sv = Servo(self.p)
        for (m, r), (a, b) in zip(ms, vend):
            vp, ta, tc, td = trapezoid(a, b, m.v, m.A, m.L)
            servo_move(sv, m, a, vp, b, ta, tc, td)
            self.add("cutting", ta + tc + td)
            if b <= 1e-12:
                self.stop(sv, "cutting")
                self.t_end.append((r, self.t))
            else:
                self.t_end.append((r, self.t + self.p.k * self.p.T / 2))

    def rapid(self, rec, start, end, linear=False):
        self.flush()
        p = self.p
        sv = Servo(p)
        d = vsub(end, start)
        if linear:
            u = unit(d)
            ax = [i for i in p.axes if abs(u[i]) > 1e-12]
            if ax:
                v = min(p.V[i] * self.rov / abs(u[i]) for i in ax)
                A = min(p.ra[i] / abs(u[i]) for i in ax)
                vp, ta, tc, td = trapezoid(0, 0, v, A, norm(d))
                sv.line(u, 0, A, ta)
                sv.line(u, vp, 0, tc)
                sv.line(u, vp, -A, td)
                self.add("rapid", ta + tc + td)
        else:
            dur = 0.0
            ph = {}
            for i in p.axes:
                if abs(d[i]) > 1e-12:
                    vp, ta, tc, td = trapezoid(0, 0, p.V[i] * self.rov, p.ra[i], abs(d[i]))
                    ph[i] = (vp, ta, tc, td)
                    dur = max(dur, ta + tc + td)
            for i, (vp, ta, tc, td) in ph.items():
                one = Servo(p)
                u = {i: math.copysign(1.0, d[i])}
                one.line(u, 0, p.ra[i], ta)
                one.line(u, vp, 0, tc)
                one.line(u, vp, -p.ra[i], td)
                one.rest(dur - ta - tc - td)
                sv.eps[i] = one.eps[i]
            self.add("rapid", dur)
        self.stop(sv, "rapid")
        self.t_end.append((rec, self.t))


def run(prog, toolpath, prof, window=None, rapid_override=100.0):
    words = scan(prog)
    recs = [json.loads(l) for l in open(toolpath) if l.strip()]
    by_line = {}
    for r in recs:
        by_line.setdefault(r["line"], []).append(r)
    ref = Reference(prof, window, rapid_override)
    lathe = prof.kind == "lathe"
    plane = 18 if lathe else 17
    mode = 64
    rpm = 0.0
    running = False
    css = None          # G96 surface speed m/min, or None
    clamp = math.inf
    s_word = 0.0
    pos = dict(prof.start)
    work = {i: pos[i] - prof.g54.get(i, 0.0) for i in prof.axes}

    def spindle_to(new):
        nonlocal rpm
        ref.flush()
        ref.add("other", abs(new - rpm) / prof.spindle_accel + prof.aux)
        rpm = new

    def css_rpm(x):
        r = 1000 * css / (2 * math.pi * abs(x)) if abs(x) > 1e-9 else math.inf
        return min(prof.max_rpm, clamp, r)

    for line in sorted(words):
        ws = words[line]
        g = [int(round(v * 10)) for l, v in ws if l == "G"]   # G09 -> 90, G64 -> 640
        ms = [int(v) for l, v in ws if l == "M"]
        S = [v for l, v in ws if l == "S"]
        for c in g:
            if c in (610, 620, 630, 640):
                mode = c // 10
            if c in (170, 180, 190):
                plane = c // 10
            if c == 970:
                css = None
        clamp_block = (prof.dialect == "puma" and 500 in g) or (prof.dialect != "puma" and 920 in g)
        if S and clamp_block:
            clamp = S[0]
        elif S and 960 in g:
            css = S[0]
        elif S:
            s_word = S[0]
        x_now = work.get("x", 0.0)
        target = (css_rpm(x_now) if css else s_word)
        # before the motion: tool change, spindle start/speed, coolant on
        if 6 in ms or (lathe and any(l == "T" for l, _ in ws) and not clamp_block):
            ref.flush()
            ref.add("tool_change", prof.tool_change)
        if 3 in ms or 4 in ms:
            running = True
            spindle_to(target)
        elif running and S and not clamp_block and target != rpm:
            spindle_to(target)
        for mc in ms:
            if mc in (7, 8):
                ref.flush()
                ref.add("other", prof.aux)
        exact_block = 90 in g or mode in (61, 63)
        for r in by_line.get(line, []):
            kind = r["kind"]
            if kind == "dwell":
                ref.flush()
                secs = r.get("seconds")
                if secs is None:
                    secs = r["revolutions"] / rpm * 60 if rpm > 0 else 0.0
                ref.add("dwell", secs)
                ref.t_end.append((r, ref.t))
                continue
            end = {i: r["mto"][i] for i in prof.axes}
            if kind == "rapid":
                ref.rapid(r, pos, end, linear=(prof.dialect != "hx"))
            else:
                arc = None
                if kind == "arc":
                    off = {i: r["mto"][i] - r["to"][i] for i in r["to"]}
                    centre = {i: r["center"][i] + off[i] for i in r["center"]}
                    arc = (centre, r["dir"] == "cw")
                fpr = r.get("feed_per_rev")
                if css and fpr and kind == "feed" and arc is None:
                    # 16 pieces, each at the feed of its middle work X
                    x0w = work["x"]
                    x1w = r["to"]["x"]
                    pieces = []
                    for k in range(16):
                        a = {i: pos[i] + (end[i] - pos[i]) * k / 16 for i in prof.axes}
                        b = {i: pos[i] + (end[i] - pos[i]) * (k + 1) / 16 for i in prof.axes}
                        xm = x0w + (x1w - x0w) * (k + 0.5) / 16
                        f = min(prof.max_cutting, fpr * css_rpm(xm))
                        pieces.append(Move(prof, a, b, f))
                    for k, m in enumerate(pieces):
                        rr = r if k == 15 else {"_piece": True}
                        ref.pending.append((m, rr))
                else:
                    m = Move(prof, pos, end, r.get("feed", 0.0), arc, plane)
                    ref.pending.append((m, r))
                if exact_block:
                    ref.flush()
            pos = end
            work = {i: r["to"][i] for i in r["to"]}
        # after the motion: spindle stop, coolant off, other M codes, ends
        for mc in ms:
            if mc == 5:
                ref.flush()
                running = False
                spindle_to(0.0)
            elif mc in (9,) or (mc not in (2, 30, 3, 4, 5, 6, 7, 8, 98, 99)):
                ref.flush()
                ref.add("other", prof.aux)
            elif mc in (2, 30):
                ref.flush()
                if prof.dialect == "hurco" and running:
                    running = False
                    spindle_to(0.0)
    ref.flush()
    return ref, recs


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("program")
    ap.add_argument("toolpath")
    ap.add_argument("machine")
    ap.add_argument("--report")
    ap.add_argument("--rapid-override", type=float, default=100.0)
    ap.add_argument("--window", type=int)
    ap.add_argument("-v", action="store_true")
    o = ap.parse_args()
    prof = Profile(o.machine)
    ref, recs = run(o.program, o.toolpath, prof, o.window, o.rapid_override)
    if o.v:
        for r, t in ref.t_end:
            if r.get("_piece"):
                continue
            kt = r.get("t_end", float("nan"))
            print(f"  line {r['line']:4} {r['kind']:6} kerf {kt:11.6f} ref {t:11.6f} diff {kt - t:+.6f}")
    dmax = max([abs(r["t_end"] - t) for r, t in ref.t_end if "t_end" in r] or [0.0])
    out = f"reference {ref.t:.6f} s  max |t_end diff| {dmax:.6f} s"
    if o.report:
        rep = json.load(open(o.report))
        k = rep["cycle_time_s"]
        out += f"  kerf {k:.6f} s  diff {(k - ref.t) / ref.t * 100:+.3f} %"
        if o.v:
            out += "\n  kerf " + json.dumps(rep["time_s"]) + "\n  ref  " + json.dumps(
                {b: round(v, 6) for b, v in ref.buckets.items()})
    print(out)


if __name__ == "__main__":
    main()
