//! [`ToolpathBehind`]: the [`Toolpath`] sink with its formatting and its
//! writes on a thread of its own, so that a run with `--toolpath` uses
//! both cores: the interpreter and the planner on the caller's thread,
//! the JSON text (about 2,000 instructions a record, as much as the
//! interpreter's block) and the system calls on the other.
//!
//! The caller's side copies each timed record (the event, its end point,
//! time and feed) into a batch of [`BATCH`] records; full batches go to
//! the thread over a bounded channel and come back empty to be filled
//! again, so nothing is allocated per record (an event with a programmed
//! end point, `Event::prog`, copies its box) and memory is bounded: at
//! most [`IN_FLIGHT`] + 1 batches exist. A file name is sent once, in the
//! batch of its first record. The records are the same bytes, in the
//! same order, as [`Toolpath`] writes on its own; the thread's first
//! error is returned by the next `timed` or by `finish`.

use std::io::{self, Write};
use std::mem;
use std::sync::mpsc::{self, Receiver, SyncSender, TryRecvError};
use std::thread::{self, JoinHandle};

use kerf_canon::{Event, Pos};

use super::toolpath::Toolpath;
use crate::sink::{Context, Sink, Timed};

/// Records in one batch.
pub const BATCH: usize = 1024;
/// Batches handed to the thread and not yet returned, at most.
pub const IN_FLIGHT: usize = 2;

/// One timed record as the thread formats it.
struct Rec {
    event: Event,
    to: Pos,
    t_end: f64,
    feed_mm_min: Option<f64>,
}

/// Records and the file names first used by them.
#[derive(Default)]
struct Batch {
    names: Vec<(u32, String)>,
    recs: Vec<Rec>,
}

/// The thread's side: formats and writes each batch, returns it empty.
fn format_loop<W: Write>(
    mut tp: Toolpath<W>,
    full: Receiver<Batch>,
    empty: SyncSender<Batch>,
) -> io::Result<()> {
    for mut b in full {
        for (id, name) in b.names.drain(..) {
            tp.name_file(id, &name);
        }
        for r in &b.recs {
            tp.write_named(&r.event, &r.to, r.t_end, r.feed_mm_min)?;
        }
        b.recs.clear();
        // The caller may have finished and stopped taking batches back.
        let _ = empty.send(b);
    }
    tp.flush()
}

/// Connected to the formatting thread (after `start`).
struct Running {
    full: SyncSender<Batch>,
    empty: Receiver<Batch>,
    thread: JoinHandle<io::Result<()>>,
}

/// A toolpath written by a thread of its own; see the module
/// documentation.
pub struct ToolpathBehind<W: Write + Send + 'static> {
    /// The sink until `start` moves it to the thread.
    idle: Option<Toolpath<W>>,
    running: Option<Running>,
    batch: Batch,
    /// Batches made so far (at most `IN_FLIGHT + 1`).
    made: usize,
    /// Per file id: its name has been sent.
    named: Vec<bool>,
}

impl<W: Write + Send + 'static> ToolpathBehind<W> {
    /// Formats and writes `tp`'s records on a thread started by
    /// [`Sink::start`].
    pub fn new(tp: Toolpath<W>) -> ToolpathBehind<W> {
        ToolpathBehind {
            idle: Some(tp),
            running: None,
            batch: Batch {
                names: Vec::new(),
                recs: Vec::with_capacity(BATCH),
            },
            made: 1,
            named: Vec::new(),
        }
    }

    /// The thread has stopped: its error (or one saying it stopped).
    fn failed(&mut self) -> io::Error {
        match self.running.take().map(|r| r.thread.join()) {
            Some(Ok(Err(e))) => e,
            _ => io::Error::other("the toolpath thread stopped"),
        }
    }

    /// Hands the batch to the thread and takes an empty one.
    fn send(&mut self) -> io::Result<()> {
        let Some(r) = &self.running else {
            return Err(io::Error::other("the toolpath was not started"));
        };
        let next = match r.empty.try_recv() {
            Ok(b) => Some(b),
            Err(TryRecvError::Empty) if self.made <= IN_FLIGHT => {
                self.made += 1;
                Some(Batch {
                    names: Vec::new(),
                    recs: Vec::with_capacity(BATCH),
                })
            }
            Err(TryRecvError::Empty) => r.empty.recv().ok(),
            Err(TryRecvError::Disconnected) => None,
        };
        let Some(next) = next else {
            return Err(self.failed());
        };
        let full = mem::replace(&mut self.batch, next);
        if r.full.send(full).is_err() {
            return Err(self.failed());
        }
        Ok(())
    }
}

impl<W: Write + Send + 'static> Sink for ToolpathBehind<W> {
    fn name(&self) -> &str {
        "toolpath"
    }

    fn start(&mut self, cx: &Context) -> io::Result<()> {
        let Some(mut tp) = self.idle.take() else {
            return Ok(());
        };
        tp.start(cx)?;
        let (full, full_rx) = mpsc::sync_channel::<Batch>(IN_FLIGHT);
        let (empty_tx, empty) = mpsc::sync_channel::<Batch>(IN_FLIGHT + 1);
        let thread = thread::spawn(move || format_loop(tp, full_rx, empty_tx));
        self.running = Some(Running {
            full,
            empty,
            thread,
        });
        Ok(())
    }

    fn timed(&mut self, t: &Timed, cx: &Context) -> io::Result<()> {
        let id = t.event.src.file;
        let i = id as usize;
        if self.named.len() <= i {
            self.named.resize(i + 1, false);
        }
        if !self.named[i] {
            self.named[i] = true;
            self.batch.names.push((id, cx.file(id).to_string()));
        }
        self.batch.recs.push(Rec {
            event: t.event.clone(),
            to: t.to,
            t_end: t.t_end,
            feed_mm_min: t.feed_mm_min,
        });
        if self.batch.recs.len() >= BATCH {
            self.send()?;
        }
        Ok(())
    }

    fn finish(&mut self, _cx: &Context, _alarm: Option<&kerf_canon::Alarm>) -> io::Result<()> {
        if self.running.is_none() {
            return Ok(());
        }
        if !self.batch.recs.is_empty() || !self.batch.names.is_empty() {
            self.send()?;
        }
        let Some(r) = self.running.take() else {
            return Ok(());
        };
        drop(r.full);
        match r.thread.join() {
            Ok(res) => res,
            Err(_) => Err(io::Error::other("the toolpath thread stopped")),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::{Arc, Mutex};

    use kerf_canon::{Canon, Motion, SrcRef};
    use kerf_interp::{Interp, Profile, Settings};
    use kerf_motion::{Dynamics, Planner};

    /// An `io::Write` into a shared buffer (the thread owns the writer).
    #[derive(Clone, Default)]
    struct Shared(Arc<Mutex<Vec<u8>>>);

    impl Write for Shared {
        fn write(&mut self, b: &[u8]) -> io::Result<usize> {
            self.0.lock().unwrap().extend_from_slice(b);
            Ok(b.len())
        }
        fn flush(&mut self) -> io::Result<()> {
            Ok(())
        }
    }

    /// Fails every write.
    struct Broken;

    impl Write for Broken {
        fn write(&mut self, _: &[u8]) -> io::Result<usize> {
            Err(io::Error::other("disk full"))
        }
        fn flush(&mut self) -> io::Result<()> {
            Ok(())
        }
    }

    fn feed(i: usize) -> Event {
        let mut to = [0.0; kerf_canon::NAXES];
        to[0] = i as f64 * 0.125;
        to[2] = -(i as f64) / 3.0;
        Event {
            src: SrcRef {
                file: 0,
                line: i as u32 + 1,
                col: 1,
            },
            tool: 1,
            cmd: Canon::Rapid {
                m: Motion { to, mto: to },
                linear: false,
            },
            prog: i.is_multiple_of(7).then(|| Box::new(to)),
        }
    }

    /// Feeds `n` records to `sink` as the runner would.
    fn run(sink: &mut dyn Sink, n: usize) -> io::Result<()> {
        let it = Interp::new(Profile::builtin("hx-mc").unwrap(), Settings::default());
        let d = Dynamics::uniform(
            [true; kerf_canon::NAXES],
            10_000.0,
            1_000.0,
            10_000.0,
            5_000.0,
        );
        let planner = Planner::new(d, [0.0; kerf_canon::NAXES], 0.0);
        let cx = Context {
            interp: &it,
            planner: &planner,
            warnings: &[],
        };
        sink.start(&cx)?;
        for i in 0..n {
            let e = feed(i);
            let to = e.motion().unwrap().to;
            let t = Timed {
                event: &e,
                from: to,
                to,
                t_end: i as f64 * 0.01,
                time: 0.01,
                feed_mm_min: None,
            };
            sink.timed(&t, &cx)?;
        }
        sink.finish(&cx, None)
    }

    #[test]
    fn the_same_bytes_as_the_toolpath_on_its_own() {
        // More than two batches in flight, and a last one part full.
        let n = BATCH * (IN_FLIGHT + 2) + 17;
        let (a, b) = (Shared::default(), Shared::default());
        run(&mut Toolpath::new(a.clone()), n).unwrap();
        run(&mut ToolpathBehind::new(Toolpath::new(b.clone())), n).unwrap();
        let (a, b) = (a.0.lock().unwrap(), b.0.lock().unwrap());
        assert_eq!(a.iter().filter(|c| **c == b'\n').count(), n);
        assert!(*a == *b, "the records differ");
    }

    #[test]
    fn a_write_error_is_returned() {
        let e = run(&mut ToolpathBehind::new(Toolpath::new(Broken)), BATCH * 4).unwrap_err();
        assert_eq!(e.to_string(), "disk full");
    }
}
