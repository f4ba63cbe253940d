//! The simulated part following the cut: a thread of its own owns a
//! simulation of the server's stock (`--stock`) and takes every command
//! the axes finish (the runtime's watcher, `Runtime::set_on_passed`); at
//! most every [`PERIOD`] while the part changes, its STL goes into the
//! path store as the part shown, so GRAPH shows the part as cut so far.
//! A cycle start of the program from its beginning starts again from the
//! stock; loading a program drops the part cut (the trace's whole-program
//! part is shown until the next run starts).

use std::sync::mpsc::{self, RecvTimeoutError};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use kerf_canon::{Event, Pos};
use kerf_sim::tool::OffsetData;
use kerf_sim::{Sim, Stock, ToolTable};

use crate::path::PathStore;

/// Shortest time between two parts written while the cut goes on.
pub const PERIOD: Duration = Duration::from_millis(500);

enum Msg {
    /// A new run: the stock again, the offsets, the tool where it stands.
    Start(Box<OffsetData>, Pos),
    /// A command the axes finished.
    Event(Box<Event>),
}

/// The controller's end: what it sends to the part's thread. Dropping
/// every copy ends the thread.
#[derive(Clone)]
pub struct PartFeed {
    tx: mpsc::Sender<Msg>,
}

impl PartFeed {
    /// A run starts from the program's beginning with the tool at `at`
    /// (work coordinates) and these offsets: the part is the stock again.
    pub fn start(&self, offsets: OffsetData, at: Pos) {
        let _ = self.tx.send(Msg::Start(Box::new(offsets), at));
    }

    /// The axes finished `e`.
    pub fn event(&self, e: &Event) {
        let _ = self.tx.send(Msg::Event(Box::new(e.clone())));
    }
}

/// Starts the part's thread for `stock`, writing into `store`.
pub fn spawn(stock: Stock, store: Arc<Mutex<PathStore>>) -> PartFeed {
    let (tx, rx) = mpsc::channel();
    std::thread::Builder::new()
        .name("kerf-part".into())
        .spawn(move || follow(stock, &store, rx))
        .ok();
    PartFeed { tx }
}

/// The cut under way: its simulation, where the tool is, the load it
/// belongs to, and whether it changed since it was last written.
struct Cut {
    sim: Sim,
    at: Pos,
    loads: u32,
    dirty: bool,
}

fn follow(stock: Stock, store: &Mutex<PathStore>, rx: mpsc::Receiver<Msg>) {
    let mut cut: Option<Cut> = None;
    let mut written = Instant::now() - PERIOD;
    loop {
        match rx.recv_timeout(PERIOD) {
            Ok(Msg::Start(offsets, at)) => {
                let loads = lock(store).loads;
                cut = Sim::new(
                    stock,
                    ToolTable::default(),
                    Some(crate::path::view_resolution(&stock)),
                )
                .ok()
                .map(|mut sim| {
                    sim.set_offsets(*offsets);
                    Cut {
                        sim,
                        at,
                        loads,
                        dirty: true,
                    }
                });
            }
            Ok(Msg::Event(e)) => {
                if let Some(c) = cut.as_mut() {
                    c.sim.event(&e, &c.at, 0.0);
                    if let Some(m) = e.motion() {
                        c.at = m.to;
                        c.dirty = true;
                    }
                }
            }
            Err(RecvTimeoutError::Timeout) => {}
            Err(RecvTimeoutError::Disconnected) => break,
        }
        if let Some(c) = cut.as_mut() {
            if c.dirty && written.elapsed() >= PERIOD {
                write(c, store);
                written = Instant::now();
            }
        }
    }
}

/// The part as cut so far into the store, unless another program was
/// loaded since the run started.
fn write(c: &mut Cut, store: &Mutex<PathStore>) {
    c.dirty = false;
    let mut stl = Vec::new();
    if kerf_sim::stl::write(&c.sim, &mut stl).is_err() {
        return;
    }
    let mut s = lock(store);
    if s.loads == c.loads {
        s.live = Some(Arc::new(stl));
        s.part_seq = s.part_seq.wrapping_add(1);
    }
}

fn lock(s: &Mutex<PathStore>) -> std::sync::MutexGuard<'_, PathStore> {
    s.lock().unwrap_or_else(|p| p.into_inner())
}
