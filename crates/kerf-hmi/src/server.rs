//! The server's shared state and the clock: the runtime behind one lock,
//! the loaded program's text, the backplot, and the ticker that advances
//! machine time and publishes the state once per tick for every client.

use std::path::PathBuf;
use std::sync::{Arc, Mutex, MutexGuard, Weak};
use std::time::{Duration, Instant};

use kerf_interp::Profile;
use tokio::sync::watch;

use crate::control::Control;
use crate::path::{PathStore, Trace};
use crate::serve_error::ServeError;
use crate::state::State;

/// Period of the ticker: 30 Hz (the stream's contract is 20 Hz or more
/// while running; 50 Hz cost the server and 100 clients two thirds more
/// work for states no screen needs).
pub const TICK: Duration = Duration::from_micros(33_333);

/// The loaded program's text with its line starts (for the PROG page).
pub struct Program {
    /// Name it was loaded under.
    pub name: String,
    /// The text.
    pub text: Arc<str>,
    /// Byte offset of each line's start.
    pub lines: Vec<usize>,
}

impl Program {
    /// Indexes `text`.
    pub fn new(name: &str, text: Arc<str>) -> Program {
        let mut lines = vec![0];
        lines.extend(text.match_indices('\n').map(|(i, _)| i + 1));
        if lines.last() == Some(&text.len()) && !text.is_empty() {
            lines.pop();
        }
        Program {
            name: name.to_string(),
            text,
            lines,
        }
    }

    /// Line `n` (1-based) without its line end.
    pub fn line(&self, n: usize) -> Option<&str> {
        let start = *self.lines.get(n.checked_sub(1)?)?;
        let end = self.lines.get(n).copied().unwrap_or(self.text.len());
        Some(self.text[start..end].trim_end_matches(['\n', '\r']))
    }

    /// Number of lines.
    pub fn count(&self) -> usize {
        if self.text.is_empty() {
            0
        } else {
            self.lines.len()
        }
    }
}

/// One published state: the value and its JSON, made once per tick.
pub struct Frame {
    /// The state.
    pub state: State,
    /// `state` as JSON text with `"type":"state"`, shared by every client
    /// (cloning it copies no bytes).
    pub json: axum::extract::ws::Utf8Bytes,
}

/// Work for the controller's thread, given the controller and the server.
type Job = Box<dyn FnOnce(&mut dyn Control, &Shared) + Send>;

/// Makes the controller on its own thread.
pub type MakeControl =
    Box<dyn FnOnce() -> Result<Box<dyn Control>, crate::serve_error::MakeError> + Send>;

/// What every handler shares.
pub struct Shared {
    jobs: Mutex<std::sync::mpsc::Sender<Job>>,
    /// The machine profile (for the backplot and `/api/machine`).
    pub profile: Profile,
    /// Library folders.
    pub libs: Vec<PathBuf>,
    /// The stock the cut part is simulated from (`--stock`), if any.
    pub stock: Mutex<Option<kerf_sim::Stock>>,
    /// The loaded program.
    pub program: Mutex<Option<Arc<Program>>>,
    /// The backplot.
    pub path: Arc<Mutex<PathStore>>,
    trace: Mutex<Option<Trace>>,
    /// The newest state.
    pub frames: watch::Sender<Arc<Frame>>,
    /// Held while a state is published (one at a time, numbered in turn).
    publishing: Mutex<()>,
    /// Token needed for state-changing requests (None on loopback).
    pub token: Option<String>,
    /// Machine time per wall-clock second.
    pub rate: f64,
}

fn lock<T: ?Sized>(m: &Mutex<T>) -> MutexGuard<'_, T> {
    m.lock().unwrap_or_else(|p| p.into_inner())
}

impl Shared {
    /// Starts the controller made by `make` on a thread of its own.
    pub fn new(
        make: MakeControl,
        profile: Profile,
        libs: Vec<PathBuf>,
        token: Option<String>,
        rate: f64,
    ) -> Result<Arc<Shared>, ServeError> {
        let (jobs, rx) = std::sync::mpsc::channel::<Job>();
        let (ready_tx, ready_rx) = std::sync::mpsc::channel();
        let (weak_tx, weak_rx) = std::sync::mpsc::channel::<Weak<Shared>>();
        std::thread::Builder::new()
            .name("kerf-control".into())
            .spawn(move || {
                let c = match make() {
                    Ok(c) => c,
                    Err(e) => {
                        let _ = ready_tx.send(Err(e));
                        return;
                    }
                };
                let _ = ready_tx.send(Ok(c.state()));
                if let Ok(weak) = weak_rx.recv() {
                    control_loop(c, rx, weak, rate);
                }
            })
            .map_err(ServeError::Thread)?;
        let state = ready_rx
            .recv()
            .map_err(|_| ServeError::ControlGone)?
            .map_err(ServeError::Control)?;
        let mut state = state;
        state.path = path_info(&PathStore::default());
        let frame = make_frame(state);
        let (tx, _) = watch::channel(Arc::new(frame));
        let shared = Arc::new(Shared {
            jobs: Mutex::new(jobs),
            profile,
            libs,
            stock: Mutex::new(None),
            program: Mutex::new(None),
            path: Arc::new(Mutex::new(PathStore::default())),
            trace: Mutex::new(None),
            frames: tx,
            publishing: Mutex::new(()),
            token,
            rate,
        });
        let _ = weak_tx.send(Arc::downgrade(&shared));
        Ok(shared)
    }

    /// Runs `f` on the controller's thread and waits for its answer
    /// (blocking the calling thread: not for the runtime's, see [`Shared::ask`]).
    pub fn with<R: Send + 'static>(
        &self,
        f: impl FnOnce(&mut dyn Control) -> R + Send + 'static,
    ) -> Result<R, crate::error::ApiError> {
        let (tx, rx) = std::sync::mpsc::sync_channel(1);
        self.send(Box::new(move |c, _| {
            let _ = tx.send(f(c));
        }))?;
        rx.recv().map_err(|_| failed())
    }

    /// Runs `f` on the controller's thread (with the server, to publish
    /// from there) and resolves to its answer: a handler awaits it without
    /// holding a thread, so an answer takes one hop to the controller's
    /// thread and one back.
    pub async fn ask<R: Send + 'static>(
        &self,
        f: impl FnOnce(&mut dyn Control, &Shared) -> R + Send + 'static,
    ) -> Result<R, crate::error::ApiError> {
        let (tx, rx) = tokio::sync::oneshot::channel();
        self.send(Box::new(move |c, s| {
            let _ = tx.send(f(c, s));
        }))?;
        rx.await.map_err(|_| failed())
    }

    fn send(&self, job: Job) -> Result<(), crate::error::ApiError> {
        lock(&self.jobs)
            .send(job)
            .map_err(|_| crate::error::ApiError::internal("the controller has stopped"))
    }

    /// Loads a program: the backplot's trace starts first (on a thread of
    /// its own, so the browser gets points while the runtime takes the
    /// text), then the runtime and the PROG text. When the runtime refuses,
    /// the trace of the program loaded before is started again.
    pub fn load(
        &self,
        name: &str,
        text: impl Into<Arc<str>>,
    ) -> Result<Arc<Program>, crate::error::ApiError> {
        let text: Arc<str> = text.into();
        self.start_trace(name, text.clone());
        let (n, t) = (name.to_string(), text.clone());
        let loaded = self
            .with(move |c| c.load(&n, &t))
            .and_then(|r| r.map_err(crate::error::ApiError::from));
        if let Err(e) = loaded {
            match self.program() {
                Some(old) => self.start_trace(&old.name, old.text.clone()),
                None => {
                    if let Some(t) = lock(&self.trace).take() {
                        t.cancel();
                    }
                    crate::path::clear(&self.path);
                }
            }
            self.publish();
            return Err(e);
        }
        let prog = Arc::new(Program::new(name, text));
        *lock(&self.program) = Some(prog.clone());
        self.publish();
        Ok(prog)
    }

    fn start_trace(&self, name: &str, text: Arc<str>) {
        // The old trace stops before the store is emptied for the new one.
        if let Some(old) = lock(&self.trace).take() {
            old.cancel();
        }
        let stock = *lock(&self.stock);
        let t = crate::path::start(
            self.profile.clone(),
            self.libs.clone(),
            stock,
            name,
            text,
            self.path.clone(),
        );
        *lock(&self.trace) = Some(t);
    }

    /// Sets the stock the part is simulated from (`--stock`): the trace
    /// of each program loaded from now on makes its whole-program part,
    /// and the controller feeds a simulation of the cut as it goes
    /// (live_part.rs).
    pub fn set_stock(&self, stock: Option<kerf_sim::Stock>) -> Result<(), crate::error::ApiError> {
        *lock(&self.stock) = stock;
        let feed = stock.map(|st| crate::live_part::spawn(st, self.path.clone()));
        self.with(move |c| c.follow_part(feed))
    }

    /// The loaded program.
    pub fn program(&self) -> Option<Arc<Program>> {
        lock(&self.program).clone()
    }

    /// Fills an alarm's block text from the loaded program when it came
    /// from the main program and the runtime left it empty.
    pub fn fill_block(&self, a: &mut crate::state::AlarmInfo) {
        if !a.block.is_empty() || a.line == 0 {
            return;
        }
        if let Some(p) = self.program() {
            if a.file == p.name || a.file.is_empty() {
                if let Some(l) = p.line(a.line as usize) {
                    a.block = l.chars().take(512).collect();
                }
            }
        }
    }

    /// Publishes the state now (after a command, so clients see it at
    /// once), from the controller's thread.
    pub fn publish(&self) {
        let (tx, rx) = std::sync::mpsc::sync_channel(1);
        if self
            .send(Box::new(move |c, s| {
                s.publish_state(c.state());
                let _ = tx.send(());
            }))
            .is_ok()
        {
            let _ = rx.recv();
        }
    }

    /// Publishes a state just read from the controller: numbered one
    /// more than the state before it (`seq`), unless it is the same or
    /// older. Its JSON is made before the newest state is replaced, so
    /// the clients' tasks reading the newest state never wait on it.
    pub fn publish_state(&self, mut state: State) {
        if let Some(a) = state.alarm.as_mut() {
            self.fill_block(a);
        }
        state.path = path_info(&lock(&self.path));
        let _turn = lock(&self.publishing);
        let old = self.frames.borrow().clone();
        // A state read before the newest one published (a command's,
        // overtaken by a tick) is not sent: machine time never goes back
        // for a client.
        if state.t < old.state.t {
            return;
        }
        state.seq = old.state.seq;
        if state == old.state {
            return;
        }
        state.seq += 1;
        self.frames.send_replace(Arc::new(make_frame(state)));
    }
}

fn failed() -> crate::error::ApiError {
    crate::error::ApiError::internal("the controller failed on this request")
}

fn path_info(path: &PathStore) -> crate::state::PathInfo {
    crate::state::PathInfo {
        id: path.id,
        points: path.points() as u32,
        done: path.done,
        note: path.note.clone(),
        part: path.part.is_some() || path.live.is_some(),
        part_seq: path.part_seq,
    }
}

fn make_frame(state: State) -> Frame {
    let mut v = serde_json::to_value(&state).unwrap_or_default();
    if let Some(o) = v.as_object_mut() {
        o.insert("type".into(), "state".into());
    }
    Frame {
        json: v.to_string().into(),
        state,
    }
}

/// The controller's thread: jobs as they come and, every [`TICK`], the
/// clock advanced by the wall time that passed × `rate` and the state
/// published (one wake-up per tick, nothing else in between). Ends when
/// the server is dropped.
fn control_loop(
    mut c: Box<dyn Control>,
    rx: std::sync::mpsc::Receiver<Job>,
    weak: Weak<Shared>,
    rate: f64,
) {
    use std::sync::mpsc::RecvTimeoutError;
    let mut last = Instant::now();
    let mut next = last + TICK;
    loop {
        match rx.recv_timeout(next.saturating_duration_since(Instant::now())) {
            // A job that panics loses its answer (the caller gets an
            // error); the controller goes on.
            Ok(job) => {
                let Some(shared) = weak.upgrade() else { break };
                let c = &mut *c;
                let _ = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| job(c, &shared)));
            }
            Err(RecvTimeoutError::Timeout) => {
                let now = Instant::now();
                // A stalled process (suspended, starved) does not jump the machine.
                let wall = now.duration_since(last).as_secs_f64().min(0.25);
                last = now;
                next += TICK;
                if next < now {
                    next = now + TICK;
                }
                let state = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
                    c.advance(wall * rate);
                    c.state()
                }));
                let Some(shared) = weak.upgrade() else { break };
                if let Ok(state) = state {
                    shared.publish_state(state);
                }
            }
            Err(RecvTimeoutError::Disconnected) => break,
        }
    }
}
