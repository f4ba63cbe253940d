//! [`WriteBehind`]: an `io::Write` whose bytes are written to the file by
//! a thread of their own, so that a large output (a million-record
//! toolpath is 230 MB) costs the run its formatting, not the system calls
//! and the kernel's copy into the page cache, which then happen on the
//! other core.
//!
//! Memory is bounded: at most three buffers of the capacity exist (one
//! being filled, at most two queued or being written); when both are
//! out, a write waits for the writer thread. The first error of the
//! underlying writer is returned by the next `write` or `flush`.

use std::io::{self, Write};
use std::mem;
use std::sync::mpsc::{self, Receiver, SyncSender, TryRecvError};
use std::thread::{self, JoinHandle};

/// Buffers handed to the writer thread and not yet returned, at most.
const IN_FLIGHT: usize = 2;

/// Writes on a thread of its own; see the module documentation.
pub struct WriteBehind {
    buf: Vec<u8>,
    cap: usize,
    full: Option<SyncSender<Vec<u8>>>,
    empty: Receiver<Vec<u8>>,
    in_flight: usize,
    thread: Option<JoinHandle<io::Result<()>>>,
}

impl WriteBehind {
    /// Writes to `w` on a new thread in pieces of about `cap` bytes
    /// (at least 1).
    pub fn new<W: Write + Send + 'static>(mut w: W, cap: usize) -> WriteBehind {
        let cap = cap.max(1);
        let (full, full_rx) = mpsc::sync_channel::<Vec<u8>>(IN_FLIGHT);
        let (empty_tx, empty) = mpsc::sync_channel::<Vec<u8>>(IN_FLIGHT);
        let thread = thread::spawn(move || {
            for mut b in full_rx {
                w.write_all(&b)?;
                w.flush()?;
                b.clear();
                if empty_tx.send(b).is_err() {
                    break;
                }
            }
            Ok(())
        });
        WriteBehind {
            buf: Vec::with_capacity(cap),
            cap,
            full: Some(full),
            empty,
            in_flight: 0,
            thread: Some(thread),
        }
    }

    /// The writer thread has stopped: its error (or, if it had none,
    /// one saying so).
    fn failed(&mut self) -> io::Error {
        self.full = None;
        match self.thread.take().map(|t| t.join()) {
            Some(Ok(Err(e))) => e,
            Some(Err(_)) => io::Error::other("the output thread panicked"),
            _ => io::Error::new(io::ErrorKind::BrokenPipe, "the output was closed"),
        }
    }

    /// Takes back one written buffer, waiting for it.
    fn take_back(&mut self) -> io::Result<Vec<u8>> {
        match self.empty.recv() {
            Ok(b) => {
                self.in_flight -= 1;
                Ok(b)
            }
            Err(_) => Err(self.failed()),
        }
    }

    /// Hands the filled buffer to the writer thread and takes one to fill.
    fn send(&mut self) -> io::Result<()> {
        let Some(full) = &self.full else {
            return Err(self.failed());
        };
        let b = mem::take(&mut self.buf);
        if full.send(b).is_err() {
            return Err(self.failed());
        }
        self.in_flight += 1;
        self.buf = match self.empty.try_recv() {
            Ok(b) => {
                self.in_flight -= 1;
                b
            }
            Err(TryRecvError::Empty) if self.in_flight < IN_FLIGHT => Vec::with_capacity(self.cap),
            Err(TryRecvError::Empty) => self.take_back()?,
            Err(TryRecvError::Disconnected) => return Err(self.failed()),
        };
        Ok(())
    }
}

impl Write for WriteBehind {
    fn write(&mut self, data: &[u8]) -> io::Result<usize> {
        if self.full.is_none() {
            return Err(self.failed());
        }
        if !self.buf.is_empty() && self.buf.len() + data.len() > self.cap {
            self.send()?;
        }
        self.buf.extend_from_slice(data);
        Ok(data.len())
    }

    /// Returns once everything written so far is in the underlying
    /// writer and flushed there.
    fn flush(&mut self) -> io::Result<()> {
        if !self.buf.is_empty() {
            self.send()?;
        }
        while self.in_flight > 0 {
            let b = self.take_back()?;
            if self.buf.capacity() < b.capacity() {
                self.buf = b;
            }
        }
        Ok(())
    }
}

impl Drop for WriteBehind {
    fn drop(&mut self) {
        let _ = self.flush();
        self.full = None;
        if let Some(t) = self.thread.take() {
            let _ = t.join();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::{Arc, Mutex};

    /// A writer into shared memory that fails once it holds `limit` bytes.
    #[derive(Clone)]
    struct Shared {
        bytes: Arc<Mutex<Vec<u8>>>,
        limit: usize,
    }

    impl Write for Shared {
        fn write(&mut self, data: &[u8]) -> io::Result<usize> {
            let mut b = self.bytes.lock().unwrap();
            if b.len() + data.len() > self.limit {
                return Err(io::Error::other("disk full"));
            }
            b.extend_from_slice(data);
            Ok(data.len())
        }
        fn flush(&mut self) -> io::Result<()> {
            Ok(())
        }
    }

    /// Every byte arrives, in order, for writes smaller and larger than
    /// the buffer, and flush waits for them.
    #[test]
    fn bytes_arrive_in_order() {
        let out = Shared {
            bytes: Arc::default(),
            limit: usize::MAX,
        };
        let mut w = WriteBehind::new(out.clone(), 100);
        let mut want = Vec::new();
        for i in 0..2_000u32 {
            let piece: Vec<u8> = (0..(i % 250)).map(|k| (i + k) as u8).collect();
            w.write_all(&piece).unwrap();
            want.extend_from_slice(&piece);
        }
        w.flush().unwrap();
        assert_eq!(*out.bytes.lock().unwrap(), want);
        // Writing goes on after a flush.
        w.write_all(b"end").unwrap();
        drop(w);
        want.extend_from_slice(b"end");
        assert_eq!(*out.bytes.lock().unwrap(), want);
    }

    /// The writer's error comes back from a later write or the flush, and
    /// stays an error.
    #[test]
    fn the_first_error_is_returned() {
        let out = Shared {
            bytes: Arc::default(),
            limit: 1_000,
        };
        let mut w = WriteBehind::new(out.clone(), 64);
        let mut failed = false;
        for _ in 0..100 {
            if w.write_all(&[b'x'; 50]).is_err() {
                failed = true;
                break;
            }
        }
        let e = w.flush().unwrap_err();
        assert!(failed || e.to_string() == "disk full", "{e}");
        assert!(w.write_all(&[b'x'; 100]).is_err());
        assert!(out.bytes.lock().unwrap().len() <= 1_000);
    }
}
