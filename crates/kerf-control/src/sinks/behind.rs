//! [`Behind`]: a sink's work done by a thread of its own, so that a run
//! uses both cores: the interpreter and the planner on the caller's
//! thread, the output's text and system calls on the other
//! ([`super::ToolpathBehind`], [`super::ExpandBehind`]).
//!
//! The caller pushes items (copies of what the sink was handed) into a
//! batch of [`BATCH`]; full batches go to the thread over a bounded
//! channel and come back empty to be filled again, so nothing is
//! allocated per item and memory is bounded: at most [`IN_FLIGHT`] + 1
//! batches exist, and the caller waits when the thread is behind. The
//! thread takes the items in order; its first error is returned by the
//! next `push` or by `finish`.

use std::io;
use std::mem;
use std::sync::mpsc::{self, Receiver, SyncSender, TryRecvError};
use std::thread::{self, JoinHandle};

/// Items in one batch.
pub const BATCH: usize = 2048;
/// Batches handed to the thread and not yet returned, at most: enough
/// for the thread to go on for some milliseconds while the caller waits
/// for a core, and the other way round (about 4 MB of toolpath records).
pub const IN_FLIGHT: usize = 8;

/// Items of type `T` handed to a thread that ends with an `R`.
pub(crate) struct Behind<T: Send + 'static, R: Send + 'static> {
    batch: Vec<T>,
    full: Option<SyncSender<Vec<T>>>,
    empty: Receiver<Vec<T>>,
    /// Batches made so far (at most `IN_FLIGHT + 1`).
    made: usize,
    thread: Option<JoinHandle<io::Result<R>>>,
}

impl<T: Send + 'static, R: Send + 'static> Behind<T, R> {
    /// Starts the thread: it gives every item, in order, to `each` with
    /// `state` (in place in its batch: `each` may take what it keeps out
    /// of it, the rest is dropped with the batch's items after the last
    /// one), and after the last one makes the result with `end`.
    pub fn spawn<S, E, F>(mut state: S, mut each: E, end: F) -> Behind<T, R>
    where
        S: Send + 'static,
        E: FnMut(&mut S, &mut T) -> io::Result<()> + Send + 'static,
        F: FnOnce(S) -> io::Result<R> + Send + 'static,
    {
        let (full, full_rx) = mpsc::sync_channel::<Vec<T>>(IN_FLIGHT);
        let (empty_tx, empty) = mpsc::sync_channel::<Vec<T>>(IN_FLIGHT + 1);
        let thread = thread::spawn(move || {
            for mut b in full_rx {
                // In place: moving each item out of the batch would copy it.
                for item in b.iter_mut() {
                    each(&mut state, item)?;
                }
                b.clear();
                // The caller may have finished and stopped taking them back.
                let _ = empty_tx.send(b);
            }
            end(state)
        });
        Behind {
            batch: Vec::with_capacity(BATCH),
            full: Some(full),
            empty,
            made: 1,
            thread: Some(thread),
        }
    }

    /// The thread has stopped: its error (or one saying it stopped).
    fn failed(&mut self) -> io::Error {
        self.full = None;
        match self.thread.take().map(JoinHandle::join) {
            Some(Ok(Err(e))) => e,
            _ => io::Error::other("the output thread stopped"),
        }
    }

    /// Hands the batch to the thread and takes an empty one.
    fn send(&mut self) -> io::Result<()> {
        let next = match self.empty.try_recv() {
            Ok(b) => Some(b),
            Err(TryRecvError::Empty) if self.made <= IN_FLIGHT => {
                self.made += 1;
                Some(Vec::with_capacity(BATCH))
            }
            Err(TryRecvError::Empty) => self.empty.recv().ok(),
            Err(TryRecvError::Disconnected) => None,
        };
        let (Some(next), Some(full)) = (next, self.full.as_ref()) else {
            return Err(self.failed());
        };
        if full.send(mem::replace(&mut self.batch, next)).is_err() {
            return Err(self.failed());
        }
        Ok(())
    }

    /// Adds one item (sending the batch when it is full).
    pub fn push(&mut self, item: T) -> io::Result<()> {
        self.batch.push(item);
        if self.batch.len() >= BATCH {
            self.send()?;
        }
        Ok(())
    }

    /// Sends what is left, waits for the thread and returns its result.
    pub fn finish(mut self) -> io::Result<R> {
        if !self.batch.is_empty() {
            self.send()?;
        }
        self.full = None;
        match self.thread.take().map(JoinHandle::join) {
            Some(Ok(r)) => r,
            _ => Err(io::Error::other("the output thread stopped")),
        }
    }
}

/// The file ids whose names have gone to the thread: each is sent once,
/// before the first item that refers to it.
#[derive(Debug, Default)]
pub(crate) struct Named(Vec<bool>);

impl Named {
    /// True the first time `id` is asked for (its name must be sent).
    pub fn first(&mut self, id: u32) -> bool {
        let i = id as usize;
        if self.0.len() <= i {
            self.0.resize(i + 1, false);
        }
        !std::mem::replace(&mut self.0[i], true)
    }
}

/// An `io::Write` into a shared buffer, for tests (the thread owns the
/// writer, the test reads what it wrote).
#[cfg(test)]
#[derive(Clone, Default)]
pub(crate) struct SharedBuf(pub std::sync::Arc<std::sync::Mutex<Vec<u8>>>);

#[cfg(test)]
impl io::Write for SharedBuf {
    fn write(&mut self, b: &[u8]) -> io::Result<usize> {
        self.0.lock().unwrap().extend_from_slice(b);
        Ok(b.len())
    }
    fn flush(&mut self) -> io::Result<()> {
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn items_arrive_in_order_and_the_result_comes_back() {
        // More batches than are ever in flight, and a last one part full.
        let n = BATCH * (IN_FLIGHT + 3) + 5;
        let mut b: Behind<u64, (u64, u64)> = Behind::spawn(
            (0u64, 0u64),
            |s: &mut (u64, u64), x: &mut u64| {
                let x = *x;
                // Out of order would break the running check.
                assert_eq!(x, s.0);
                s.0 += 1;
                s.1 += x;
                Ok(())
            },
            Ok,
        );
        for x in 0..n as u64 {
            b.push(x).unwrap();
        }
        let n = n as u64;
        assert_eq!(b.finish().unwrap(), (n, n * (n - 1) / 2));
    }

    #[test]
    fn the_first_error_is_returned() {
        let mut b: Behind<u32, ()> = Behind::spawn(
            0u32,
            |seen: &mut u32, _| {
                *seen += 1;
                if *seen == 10 {
                    Err(io::Error::other("disk full"))
                } else {
                    Ok(())
                }
            },
            |_| Ok(()),
        );
        let mut err = None;
        for x in 0..(BATCH * 8) as u32 {
            if let Err(e) = b.push(x) {
                err = Some(e);
                break;
            }
        }
        let e = match err {
            Some(e) => e,
            None => b.finish().unwrap_err(),
        };
        assert_eq!(e.to_string(), "disk full");
    }
}
