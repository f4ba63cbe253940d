//! Two threads cutting the height field, decoupled by ownership: the bands
//! of 16 rows with an even index belong to the caller's thread, those with
//! an odd index to a worker thread kept for the run. Every queued move is
//! cut by both threads in program order, each over its own bands only
//! (bands.rs, `cut_parity`), so each cell sees the same moves in the same
//! order as on one thread and its heights are the same bit for bit. The
//! caller cuts its bands of a move at once and hands the move to the
//! worker through a bounded queue; it waits only when the queue is full or
//! at a barrier ([`Pipe::settle`]: whatever reads the stock or may be an
//! event drains the worker first).
//!
//! A move's removed volume is its bands' sums added in band order, times
//! the cell area, added to the running total, as on one thread: each
//! thread keeps its per-move per-band sums and the caller merges them in
//! band order once both threads are past the move.

use crate::bands::{cut_parity, Raw};
use crate::envelope::Sweep;
use crate::tool::MillTool;
use std::cell::{Cell, RefCell};
use std::collections::VecDeque;
use std::sync::{Arc, Condvar, Mutex, MutexGuard};
use std::thread::JoinHandle;

/// Moves the caller may be ahead of the worker by (about 0.3 MB of
/// queued sweeps and per-band sums).
pub const QUEUE: usize = 4096;
/// Moves queued before an idle worker is woken (a barrier or a full queue
/// wakes it at once).
const WAKE: usize = 32;
/// Most moves the worker takes from the queue at once.
const BATCH: usize = 64;

/// What the worker is handed, in program order.
enum Msg {
    /// The tool of the moves that follow.
    Tool(Box<MillTool>),
    /// A move to cut over the worker's bands, and whether it follows the
    /// previous one ([`crate::kernels::Pass::without_start`]).
    Move(Sweep, bool),
    /// Makes the worker panic (tests of the panic's propagation).
    #[cfg(test)]
    Fail,
}

/// Each move's bands and their sums, in order: `counts[k]` entries of
/// `bands` are move k's.
#[derive(Default)]
struct Sums {
    bands: VecDeque<(u32, f64)>,
    counts: VecDeque<u32>,
}

impl Sums {
    fn push(&mut self, move_bands: &[(u32, f64)]) {
        self.bands.extend(move_bands.iter().copied());
        self.counts.push_back(move_bands.len() as u32);
    }

    fn append(&mut self, other: &mut Sums) {
        self.bands.append(&mut other.bands);
        self.counts.append(&mut other.counts);
    }

    fn is_empty(&self) -> bool {
        self.counts.is_empty()
    }
}

#[derive(Default)]
struct State {
    queue: VecDeque<Msg>,
    /// Moves handed over whose worker's sums have not been taken back.
    in_flight: usize,
    /// The worker's sums of the moves it has done.
    done: Sums,
    /// The worker waits for moves; the caller waits for the worker.
    idle: bool,
    waiting: bool,
    panicked: bool,
    quit: bool,
}

#[derive(Default)]
struct Shared {
    state: Mutex<State>,
    /// Signalled for the worker: moves queued, or quit.
    wake: Condvar,
    /// Signalled for a waiting caller: moves done, or a panic.
    ready: Condvar,
}

/// The caller's side: its own sums, the worker's taken back, the scratch.
#[derive(Default)]
struct Mine {
    own: Sums,
    theirs: Sums,
    scratch: Vec<(u32, f64)>,
}

/// The worker thread and the caller's side of the queue.
pub struct Pipe {
    shared: Arc<Shared>,
    thread: Option<JoinHandle<()>>,
    raw: Raw,
    /// Stock bottom and threshold (`ZMap::zmin`, `ZMap::tol`).
    zt: (f64, f64),
    area: f64,
    cap: usize,
    last_tool: Option<MillTool>,
    mine: RefCell<Mine>,
    /// Moves queued since the last settle.
    dirty: Cell<bool>,
}

fn lock(s: &Shared) -> MutexGuard<'_, State> {
    s.state.lock().unwrap_or_else(|e| e.into_inner())
}

fn wait<'a>(c: &Condvar, g: MutexGuard<'a, State>) -> MutexGuard<'a, State> {
    c.wait(g).unwrap_or_else(|e| e.into_inner())
}

/// Locks the state and waits (waking an idle worker) until `ready` holds
/// of it. Panics if the worker did.
fn wait_until(s: &Shared, ready: impl Fn(&State) -> bool) -> MutexGuard<'_, State> {
    let mut st = lock(s);
    check(&st);
    while !ready(&st) {
        st.waiting = true;
        if st.idle {
            s.wake.notify_one();
        }
        st = wait(&s.ready, st);
        check(&st);
    }
    st.waiting = false;
    st
}

/// Panics in the caller when the worker has.
fn check(st: &State) {
    if st.panicked {
        panic!("kerf-sim: the height field's worker thread panicked");
    }
}

impl Pipe {
    /// Starts the worker over the odd bands of `raw` (the arrays must stay
    /// where they are, unfreed, while the pipe lives), or None when the
    /// system refuses a thread. `cap` is the queue's length in moves.
    pub fn start(raw: Raw, zt: (f64, f64), area: f64, cap: usize) -> Option<Pipe> {
        let shared = Arc::new(Shared::default());
        let s = Arc::clone(&shared);
        let theirs = raw;
        let thread = std::thread::Builder::new()
            .name("kerf-sim-worker".into())
            .spawn(move || serve(&s, &theirs, zt))
            .ok()?;
        Some(Pipe {
            shared,
            thread: Some(thread),
            raw,
            zt,
            area,
            cap: cap.max(1),
            last_tool: None,
            mine: RefCell::default(),
            dirty: Cell::new(false),
        })
    }

    /// Cuts `s` of `tool` (no shank or holder; heights written, no old
    /// heights kept): the caller's bands now, the worker's when it gets
    /// there. Adds every move both threads are past to `total`, mm³.
    /// `follows`: the move starts where the previous one of the same tool
    /// ended.
    pub fn cut(&mut self, tool: &MillTool, s: &Sweep, follows: bool, total: &Cell<f64>) {
        let new_tool = self.last_tool.as_ref() != Some(tool);
        if new_tool {
            self.last_tool = Some(tool.clone());
        }
        let mine = self.mine.get_mut();
        {
            let cap = self.cap;
            let mut st = wait_until(&self.shared, |st| st.in_flight < cap);
            if new_tool {
                st.queue.push_back(Msg::Tool(Box::new(tool.clone())));
            }
            st.queue.push_back(Msg::Move(*s, follows));
            st.in_flight += 1;
            if st.idle && st.queue.len() >= WAKE.min(self.cap) {
                self.shared.wake.notify_one();
            }
            mine.theirs.append(&mut st.done);
        }
        self.dirty.set(true);
        mine.scratch.clear();
        // SAFETY: the even bands are this thread's alone (the worker cuts
        // the odd ones only), and the arrays outlive the pipe.
        unsafe { cut_parity(&self.raw, (tool, s, follows), self.zt, 0, &mut mine.scratch) };
        mine.own.push(&mine.scratch);
        merge(mine, self.area, total);
    }

    /// Waits until the worker has cut every queued move and adds what is
    /// left of the moves' volumes to `total`: the heights may then be
    /// read, and written on this thread, until the next [`Self::cut`].
    /// Panics if the worker did.
    pub fn settle(&self, total: &Cell<f64>) {
        if !self.dirty.get() {
            return;
        }
        let mut mine = self.mine.borrow_mut();
        {
            let mut st = wait_until(&self.shared, |st| st.in_flight == 0);
            mine.theirs.append(&mut st.done);
        }
        merge(&mut mine, self.area, total);
        debug_assert!(mine.own.is_empty() && mine.theirs.is_empty());
        self.dirty.set(false);
    }

    /// Makes the worker panic at its next move (tests).
    #[cfg(test)]
    fn fail(&mut self) {
        let mut st = lock(&self.shared);
        st.queue.push_back(Msg::Fail);
        self.shared.wake.notify_one();
    }
}

impl std::fmt::Debug for Pipe {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Pipe(queue {})", self.cap)
    }
}

impl Drop for Pipe {
    fn drop(&mut self) {
        lock(&self.shared).quit = true;
        self.shared.wake.notify_one();
        if let Some(t) = self.thread.take() {
            let _ = t.join();
        }
    }
}

/// Adds to `total` every move both threads are past: its bands' sums
/// merged in band order, times the cell area.
fn merge(m: &mut Mine, area: f64, total: &Cell<f64>) {
    while !m.own.is_empty() && !m.theirs.is_empty() {
        let a = m.own.counts.pop_front().unwrap_or(0) as usize;
        let b = m.theirs.counts.pop_front().unwrap_or(0) as usize;
        let (mut i, mut j, mut sum) = (0, 0, 0.0);
        while i < a || j < b {
            let x = (i < a).then(|| m.own.bands[i]);
            let y = (j < b).then(|| m.theirs.bands[j]);
            match (x, y) {
                (Some(x), Some(y)) if x.0 < y.0 => (sum, i) = (sum + x.1, i + 1),
                (Some(_), Some(y)) | (None, Some(y)) => (sum, j) = (sum + y.1, j + 1),
                (Some(x), None) => (sum, i) = (sum + x.1, i + 1),
                (None, None) => break,
            }
        }
        m.own.bands.drain(..a);
        m.theirs.bands.drain(..b);
        total.set(total.get() + sum * area);
    }
}

/// The worker's loop: take up to [`BATCH`] moves, cut them over the odd
/// bands, hand their sums back; a panic is recorded for the caller.
fn serve(s: &Shared, raw: &Raw, zt: (f64, f64)) {
    let (mut batch, mut tool, mut out) = (Vec::new(), None::<Box<MillTool>>, Sums::default());
    let mut scratch = Vec::new();
    let mut st = lock(s);
    loop {
        if st.quit {
            return;
        }
        if st.queue.is_empty() {
            st.idle = true;
            st = wait(&s.wake, st);
            st.idle = false;
            continue;
        }
        let n = st.queue.len().min(BATCH);
        batch.extend(st.queue.drain(..n));
        drop(st);
        let ok = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            for m in batch.drain(..) {
                match m {
                    Msg::Tool(t) => tool = Some(t),
                    Msg::Move(sw, follows) => {
                        let t = tool.as_deref().expect("a tool before the first move");
                        scratch.clear();
                        // SAFETY: the odd bands are this thread's alone.
                        unsafe { cut_parity(raw, (t, &sw, follows), zt, 1, &mut scratch) };
                        out.push(&scratch);
                    }
                    #[cfg(test)]
                    Msg::Fail => panic!("a test's failure"),
                }
            }
        }))
        .is_ok();
        st = lock(s);
        st.in_flight -= out.counts.len();
        st.done.append(&mut out);
        st.panicked |= !ok;
        if st.waiting || !ok {
            s.ready.notify_one();
        }
        if !ok {
            return;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::zmap::ZMap;

    /// A worker that panics makes the caller's next wait panic instead of
    /// hanging.
    #[test]
    fn a_panic_in_the_worker_surfaces_in_the_caller() {
        let mut z = ZMap::new([0.0, 0.0, -5.0], [20.0, 15.0, 0.0], 0.1).unwrap();
        let t = MillTool::flat(1.0);
        let s = Sweep::new([1.0, 1.0, -1.0], [19.0, 14.0, -1.0]);
        z.cut_queued(&t, &s);
        z.pipe_mut().unwrap().fail();
        let r = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            for _ in 0..100 {
                z.cut_queued(&t, &s);
            }
            z.volume()
        }));
        assert!(r.is_err());
    }
}
