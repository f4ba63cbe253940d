//! The backplot of the loaded program: the interpreter runs over the text
//! once (no motion, no planner) on a background thread and the motions
//! become points of a polyline, arcs cut into chords. Points are kept in
//! the binary record the browser draws from directly (docs/hmi.md
//! "Toolpath records"), and decimated so that at most [`MAX_POINTS`] are
//! held whatever the size of the program.

use std::io::Cursor;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use kerf_canon::{Canon, Event, Pos};
use kerf_interp::{Interp, Profile, Settings, Step};

use crate::repeat::Repeats;

/// Bytes per point record.
pub const RECORD: usize = 20;
/// Most points held; past it the path is decimated.
pub const MAX_POINTS: usize = 2_000_000;
/// Chord tolerance for arcs, mm.
const CHORD_TOL: f64 = 0.005;
/// Most blocks the trace runs (a program that loops for ever ends here).
const MAX_BLOCKS: u64 = 50_000_000;
/// Longest time the trace runs.
const MAX_TIME: Duration = Duration::from_secs(120);
/// Consecutive moves that only retrace the path after which the trace
/// stops (a program that loops for ever draws nothing new).
#[cfg(not(test))]
const MAX_RETRACED: u64 = 1_000_000;
/// The same, small enough for a test in a debug build.
#[cfg(test)]
const MAX_RETRACED: u64 = 1_000;

/// Move kinds in a record.
pub mod kind {
    /// Rapid traverse.
    pub const RAPID: u8 = 0;
    /// Linear feed.
    pub const FEED: u8 = 1;
    /// Arc (chord of).
    pub const ARC: u8 = 2;
    /// Thread.
    pub const THREAD: u8 = 3;
    /// The start point.
    pub const START: u8 = 255;
}

/// The points made so far, shared between the tracer and the senders.
#[derive(Debug, Default)]
pub struct PathStore {
    /// Which trace this is (changes at every load and every decimation).
    pub id: u32,
    /// The records, `RECORD` bytes each.
    pub bytes: Vec<u8>,
    /// The trace ran to the program's end (or its limit).
    pub done: bool,
    /// Shortest distance kept between points of one run, mm (0 until the
    /// path had to be decimated).
    pub min_step: f64,
    /// Why the trace ended early, if it did (an alarm, a limit).
    pub note: Option<String>,
    /// The simulated part as binary STL (work coordinates, mm), when the
    /// server was given a stock and the trace is done: the whole
    /// program's result.
    pub part: Option<Arc<Vec<u8>>>,
    /// The part as cut so far by the run under way (live_part.rs), shown
    /// instead of `part` once a run of this program has started.
    pub live: Option<Arc<Vec<u8>>>,
    /// Changes whenever the part shown changes (a client refetches it).
    pub part_seq: u32,
    /// Programs loaded so far (a run's part belongs to one of them).
    pub loads: u32,
}

impl PathStore {
    /// The part shown: the one cut so far, else the trace's.
    pub fn shown_part(&self) -> Option<Arc<Vec<u8>>> {
        self.live.clone().or_else(|| self.part.clone())
    }
}

impl PathStore {
    /// Number of points.
    pub fn points(&self) -> usize {
        self.bytes.len() / RECORD
    }
}

/// A running trace: dropping it (or [`Trace::cancel`]) stops the thread.
pub struct Trace {
    stop: Arc<AtomicBool>,
}

impl Trace {
    /// Stops the trace at the next block.
    pub fn cancel(&self) {
        self.stop.store(true, Ordering::Relaxed);
    }
}

impl Drop for Trace {
    fn drop(&mut self) {
        self.cancel();
    }
}

/// Empties the store for a new path (its `id` bumped: clients reload).
pub fn clear(store: &Mutex<PathStore>) {
    let mut s = lock(store);
    s.id = s.id.wrapping_add(1);
    s.bytes.clear();
    s.done = false;
    s.min_step = 0.0;
    s.note = None;
    s.part = None;
    s.live = None;
    s.part_seq = s.part_seq.wrapping_add(1);
    s.loads = s.loads.wrapping_add(1);
}

/// Starts tracing `text` on `profile` into `store` (its content replaced,
/// `id` bumped).
pub fn start(
    profile: Profile,
    libs: Vec<std::path::PathBuf>,
    stock: Option<kerf_sim::Stock>,
    name: &str,
    text: Arc<str>,
    store: Arc<Mutex<PathStore>>,
) -> Trace {
    let stop = Arc::new(AtomicBool::new(false));
    clear(&store);
    let flag = stop.clone();
    let name = name.to_string();
    std::thread::spawn(move || {
        let settings = Settings {
            max_blocks: MAX_BLOCKS,
            ..Settings::default()
        };
        let mut it = Interp::new(profile, settings);
        for d in libs {
            it.add_lib_dir(d);
        }
        it.load_main(&name, Box::new(Cursor::new(Text(text))));
        // The cut part: every event through the simulator on its stock.
        let mut sim = stock.and_then(|st| {
            let mut sim = kerf_sim::Sim::new(
                st,
                kerf_sim::ToolTable::default(),
                Some(view_resolution(&st)),
            )
            .ok()?;
            sim.set_offsets(kerf_control::sinks::sim::offset_data(&it));
            Some(sim)
        });
        run(&mut it, &store, &flag, sim.as_mut());
        if let Some(sim) = sim {
            if !flag.load(Ordering::Relaxed) {
                let mut stl = Vec::new();
                if kerf_sim::stl::write(&sim, &mut stl).is_ok() {
                    let mut s = lock(&store);
                    if !flag.load(Ordering::Relaxed) {
                        s.part = Some(Arc::new(stl));
                        s.part_seq = s.part_seq.wrapping_add(1);
                    }
                }
            }
        }
    });
    Trace { stop }
}

/// The shared program text as bytes (read by the tracer without a copy).
struct Text(Arc<str>);

impl AsRef<[u8]> for Text {
    fn as_ref(&self) -> &[u8] {
        self.0.as_bytes()
    }
}

fn lock(s: &Mutex<PathStore>) -> std::sync::MutexGuard<'_, PathStore> {
    s.lock().unwrap_or_else(|p| p.into_inner())
}

/// The simulation's cell size for the view: the stock's largest extent in
/// 300 cells (a part of some 10^5 triangles, light for the browser).
pub fn view_resolution(st: &kerf_sim::Stock) -> f64 {
    let extent = match st {
        kerf_sim::Stock::Box { min, max } => (0..3).map(|i| max[i] - min[i]).fold(0.0, f64::max),
        kerf_sim::Stock::Turn {
            r_out,
            z_face,
            z_end,
            ..
        } => (2.0 * r_out).max(z_face - z_end),
    };
    (extent / 300.0).max(0.01)
}

/// Points are made in batches and published under the lock.
fn run(
    it: &mut Interp,
    store: &Mutex<PathStore>,
    stop: &AtomicBool,
    mut sim: Option<&mut kerf_sim::Sim>,
) {
    let began = Instant::now();
    let mut b = Builder::new(it.work_position());
    let mut note = None;
    let mut n = 0u64;
    loop {
        n += 1;
        if n.is_multiple_of(4096) || (sim.is_some() && n.is_multiple_of(64)) {
            if stop.load(Ordering::Relaxed) {
                return;
            }
            if began.elapsed() > MAX_TIME {
                note = Some(format!("trace stopped after {} s", MAX_TIME.as_secs()));
                break;
            }
            b.publish(store, stop);
        }
        if b.retraced {
            note = Some(format!(
                "repeats itself: stopped after {MAX_RETRACED} retraced moves"
            ));
            break;
        }
        match it.step() {
            Step::Event(e) => {
                if let Some(sim) = sim.as_deref_mut() {
                    sim.event(&e, &b.at, 0.0);
                }
                b.event(&e);
            }
            Step::End => break,
            Step::Alarm(a) => {
                note = Some(format!(
                    "alarm {} at line {}: {}",
                    a.code, a.src.line, a.message
                ));
                break;
            }
        }
    }
    if stop.load(Ordering::Relaxed) {
        return;
    }
    b.publish(store, stop);
    let mut s = lock(store);
    if stop.load(Ordering::Relaxed) {
        return;
    }
    s.done = true;
    s.note = note;
}

/// Turns motions into records.
struct Builder {
    /// Records not yet published.
    fresh: Vec<u8>,
    last: [f32; 3],
    last_kind: u8,
    min_step: f64,
    at: Pos,
    /// The moves drawn so far.
    repeats: Repeats,
    /// The last [`MAX_RETRACED`] moves had all been drawn before.
    retraced: bool,
}

impl Builder {
    fn new(start: Pos) -> Builder {
        let mut b = Builder {
            fresh: Vec::with_capacity(1 << 16),
            last: [f32::NAN; 3],
            last_kind: kind::START,
            min_step: 0.0,
            at: start,
            repeats: Repeats::new(MAX_RETRACED),
            retraced: false,
        };
        b.push(&start, 0, kind::START, 0, true);
        b
    }

    fn event(&mut self, e: &Event) {
        let line = e.src.line;
        let tool = e.tool;
        let (k, m) = match &e.cmd {
            Canon::Rapid { m, .. } => (kind::RAPID, m),
            Canon::Feed { m, .. } => (kind::FEED, m),
            Canon::Thread { m, .. } => (kind::THREAD, m),
            Canon::Arc {
                m,
                center,
                dir,
                plane,
                turns,
                ..
            } => {
                let from = self.at;
                for p in arc_points(
                    &from,
                    &m.to,
                    center,
                    plane.axes(),
                    *dir == kerf_canon::ArcDir::Ccw,
                    *turns,
                ) {
                    self.push(&p, line, kind::ARC, tool, false);
                }
                (kind::ARC, m)
            }
            _ => return,
        };
        // An arc's end point is kept whatever the decimation.
        self.push(&m.to, line, k, tool, k == kind::ARC);
        self.retraced = self.repeats.retraces(&move_words(k, &self.at, &m.to, e));
        self.at = m.to;
    }

    /// Adds a point; a point closer than `min_step` to the last one of
    /// the same kind is left out unless `keep`.
    fn push(&mut self, p: &Pos, line: u32, k: u8, tool: u32, keep: bool) {
        let q = [p[0] as f32, p[1] as f32, p[2] as f32];
        if k == self.last_kind && !keep && self.min_step > 0.0 {
            let d = (0..3)
                .map(|i| (q[i] - self.last[i]) as f64)
                .map(|v| v * v)
                .sum::<f64>()
                .sqrt();
            if d < self.min_step {
                return;
            }
        }
        self.last = q;
        self.last_kind = k;
        for v in q {
            self.fresh.extend_from_slice(&v.to_le_bytes());
        }
        self.fresh.extend_from_slice(&line.to_le_bytes());
        self.fresh.push(k);
        self.fresh.push(tool.min(255) as u8);
        self.fresh.extend_from_slice(&[0, 0]);
    }

    /// Moves the fresh records into the store, decimating when full.
    /// Nothing is published once the trace is cancelled (checked under
    /// the lock: a cancelled trace never writes into its successor's path).
    fn publish(&mut self, store: &Mutex<PathStore>, stop: &AtomicBool) {
        let mut s = lock(store);
        if stop.load(Ordering::Relaxed) {
            return;
        }
        s.bytes.extend_from_slice(&self.fresh);
        self.fresh.clear();
        while s.points() > MAX_POINTS {
            self.min_step = if self.min_step == 0.0 {
                0.05
            } else {
                self.min_step * 2.0
            };
            let kept = decimate(&s.bytes, self.min_step);
            s.bytes = kept;
            s.min_step = self.min_step;
            s.id = s.id.wrapping_add(1);
        }
    }
}

/// What the picture draws of the move `e` from `from` to `to` (its kind,
/// ends, and an arc's centre and direction) as words for [`Repeats`].
fn move_words(k: u8, from: &Pos, to: &Pos, e: &Event) -> [u32; 11] {
    let bits = |p: &Pos, i: usize| (p[i] as f32).to_bits();
    let mut w = [0u32; 11];
    w[0] = u32::from(k);
    for i in 0..3 {
        w[1 + i] = bits(from, i);
        w[4 + i] = bits(to, i);
    }
    if let Canon::Arc {
        center, dir, turns, ..
    } = &e.cmd
    {
        for i in 0..3 {
            w[7 + i] = bits(center, i);
        }
        w[10] = u32::from(*dir == kerf_canon::ArcDir::Ccw) | turns << 1;
    }
    w
}

/// Keeps the points at least `step` from the last kept point of the same
/// run of one kind, and every point where the kind changes.
pub fn decimate(bytes: &[u8], step: f64) -> Vec<u8> {
    let mut out = Vec::with_capacity(bytes.len() / 2);
    let mut last: Option<([f32; 3], u8)> = None;
    let n = bytes.len() / RECORD;
    for i in 0..n {
        let r = &bytes[i * RECORD..(i + 1) * RECORD];
        let p = record_point(r);
        let k = r[16];
        let next_kind = (i + 1 < n).then(|| bytes[(i + 1) * RECORD + 16]);
        let keep = match last {
            None => true,
            Some((q, lk)) => {
                lk != k
                    || next_kind != Some(k)
                    || (0..3)
                        .map(|j| ((p[j] - q[j]) as f64).powi(2))
                        .sum::<f64>()
                        .sqrt()
                        >= step
            }
        };
        if keep {
            out.extend_from_slice(r);
            last = Some((p, k));
        }
    }
    out
}

/// The x, y, z of one record.
pub fn record_point(r: &[u8]) -> [f32; 3] {
    let f = |o: usize| f32::from_le_bytes([r[o], r[o + 1], r[o + 2], r[o + 3]]);
    [f(0), f(4), f(8)]
}

/// Interior chord points of an arc (the end point not included), so that
/// no chord is further than `CHORD_TOL` from the circle; at most 720 per
/// turn.
fn arc_points(
    from: &Pos,
    to: &Pos,
    c: &Pos,
    (a, b, n): (usize, usize, usize),
    ccw: bool,
    turns: u32,
) -> Vec<Pos> {
    let s = (from[a], from[b]);
    let e = (to[a], to[b]);
    let cc = (c[a], c[b]);
    let r = (s.0 - cc.0).hypot(s.1 - cc.1);
    let sweep =
        kerf_canon::geom::sweep(s, e, cc, ccw) + std::f64::consts::TAU * turns.min(1000) as f64;
    if r.is_nan() || r <= 1e-9 || !sweep.is_finite() {
        return Vec::new();
    }
    let step = if r > CHORD_TOL {
        (2.0 * (1.0 - CHORD_TOL / r).acos()).max(std::f64::consts::TAU / 720.0)
    } else {
        std::f64::consts::FRAC_PI_2
    };
    let count = ((sweep / step).ceil() as usize).clamp(1, 720 * 1001);
    let a0 = (s.1 - cc.1).atan2(s.0 - cc.0);
    let sign = if ccw { 1.0 } else { -1.0 };
    let mut out = Vec::with_capacity(count.saturating_sub(1));
    for i in 1..count {
        let f = i as f64 / count as f64;
        let ang = a0 + sign * sweep * f;
        let mut p = *from;
        for k in 0..p.len() {
            p[k] = from[k] + (to[k] - from[k]) * f;
        }
        p[a] = cc.0 + r * ang.cos();
        p[b] = cc.1 + r * ang.sin();
        p[n] = from[n] + (to[n] - from[n]) * f;
        out.push(p);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn trace(machine: &str, text: &str) -> PathStore {
        let store = Arc::new(Mutex::new(PathStore::default()));
        let p = Profile::builtin(machine).unwrap();
        let _t = start(p, vec![], None, "t.nc", text.into(), store.clone());
        let began = Instant::now();
        while !lock(&store).done {
            assert!(began.elapsed() < Duration::from_secs(20), "trace hangs");
            std::thread::sleep(Duration::from_millis(5));
        }
        Arc::try_unwrap(store)
            .map(|m| m.into_inner().unwrap())
            .unwrap_or_else(|a| std::mem::take(&mut *lock(&a)))
    }

    fn points(s: &PathStore) -> Vec<([f32; 3], u32, u8)> {
        s.bytes
            .chunks(RECORD)
            .map(|r| {
                let line = u32::from_le_bytes([r[12], r[13], r[14], r[15]]);
                (record_point(r), line, r[16])
            })
            .collect()
    }

    #[test]
    fn lines_and_a_quarter_arc_become_points_on_the_circle() {
        // G54 is the profile's; positions are work coordinates.
        let s = trace(
            "hx-mc",
            "G90 G17 G54 G00 X10. Y0 Z5.\nG01 X20. F500.\nG03 X10. Y10. I-10. J0\nM30\n",
        );
        let p = points(&s);
        assert_eq!(p[0].2, kind::START);
        assert_eq!((p[1].0, p[1].1, p[1].2), ([10.0, 0.0, 5.0], 1, kind::RAPID));
        assert_eq!((p[2].0, p[2].1, p[2].2), ([20.0, 0.0, 5.0], 2, kind::FEED));
        let arc: Vec<_> = p[3..].iter().filter(|q| q.2 == kind::ARC).collect();
        // r = 10, tol 0.005: step = 2 acos(1 - 0.0005) = 0.06325 rad; a
        // quarter turn (1.5708 rad) needs ceil(24.8) = 25 chords.
        assert_eq!(arc.len(), 25);
        for q in &arc {
            let r = ((q.0[0] - 10.0).powi(2) + q.0[1].powi(2)).sqrt();
            assert!((r - 10.0).abs() < 1e-4, "{q:?} off the circle");
            assert_eq!(q.1, 3);
        }
        assert_eq!(arc.last().unwrap().0, [10.0, 10.0, 5.0]);
        assert!(s.note.is_none());
    }

    #[test]
    fn an_alarm_ends_the_trace_with_its_line() {
        let s = trace("hx-mc", "G00 X1.\nG01 X2.\nM30\n");
        // G01 without any F is F_82011-type alarm on the HX: the trace
        // keeps what came before and names the line.
        let note = s.note.clone().unwrap_or_default();
        assert!(note.contains("line 2"), "{note}");
        assert_eq!(points(&s).len(), 2);
    }

    #[test]
    fn a_program_that_loops_for_ever_stops_once_it_only_retraces() {
        let s = trace(
            "hx-mc",
            "G90 G17 G54 G00 X0 Y0 Z5.\nWHILE [1 EQ 1] DO1\nG01 X10. F500.\nY10.\nX0.\nY0.\nEND1\nM30\n",
        );
        let note = s.note.clone().unwrap_or_default();
        assert!(note.contains("repeats itself"), "{note}");
        // The start, the rapid, the square's 4 new sides, then the
        // MAX_RETRACED sides that retrace them (the last one drawn
        // before the trace stops).
        assert_eq!(points(&s).len(), 2 + 4 + MAX_RETRACED as usize);
        assert!(s.done);
    }

    #[test]
    fn a_long_loop_that_draws_new_moves_runs_to_its_end() {
        // 3,000 distinct moves, three times the retrace limit, all traced.
        let s = trace(
            "hx-mc",
            "G90 G17 G54 G00 X0 Y0 Z5.\n#1=0\nWHILE [#1 LT 3000] DO1\nG01 X[#1 MOD 100] Y[FIX[#1/100]] F500.\n#1=#1+1\nEND1\nM30\n",
        );
        assert!(s.note.is_none(), "{:?}", s.note);
        assert_eq!(points(&s).len(), 2 + 3000);
    }

    #[test]
    fn decimation_keeps_kind_changes_and_run_ends() {
        let mut b = Builder::new([0.0; 6]);
        for i in 1..=100 {
            b.push(
                &[i as f64 * 0.01, 0.0, 0.0, 0.0, 0.0, 0.0],
                1,
                kind::FEED,
                1,
                false,
            );
        }
        b.push(&[1.0, 5.0, 0.0, 0.0, 0.0, 0.0], 2, kind::RAPID, 1, false);
        let all = b.fresh.clone();
        let kept = decimate(&all, 0.1);
        let pts: Vec<_> = kept.chunks(RECORD).map(record_point).collect();
        // start, the first feed point (kind change), every 0.1 mm (ten
        // steps of 0.01 each), the last feed point, the rapid.
        assert_eq!(pts.first().unwrap(), &[0.0, 0.0, 0.0]);
        assert_eq!(pts[1], [0.01, 0.0, 0.0]);
        assert!(pts.contains(&[1.0, 0.0, 0.0]));
        assert_eq!(pts.last().unwrap(), &[1.0, 5.0, 0.0]);
        assert!(pts.len() <= 14, "{} points kept", pts.len());
    }
}
