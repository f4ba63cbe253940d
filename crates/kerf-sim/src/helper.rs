//! A second thread kept for the whole run that helps with a move's work:
//! the caller publishes a job (a closure on its own stack), runs it
//! itself, and before returning either takes the job back (the helper
//! never started it) or waits for the helper to finish it. The job is
//! written so that whoever runs it claims pieces of work one at a time
//! (bands.rs: an atomic counter over the move's bands), so a helper that
//! gets no time slice on a busy machine costs the caller nothing but the
//! publishing: the caller does every piece itself.

use std::sync::{Arc, Condvar, Mutex};
use std::thread::JoinHandle;

/// A job as the helper sees it: a pointer to the caller's closure, valid
/// until the caller has seen the helper finish (or taken the job back).
#[derive(Clone, Copy)]
struct Job(*const (dyn Fn() + Sync));

// SAFETY: the closure is Sync and outlives its use (see `Helper::run`).
unsafe impl Send for Job {}

#[derive(Default)]
struct State {
    job: Option<Job>,
    busy: bool,
    panicked: bool,
    quit: bool,
}

#[derive(Default)]
struct Shared {
    state: Mutex<State>,
    /// Signalled when a job is published or the helper is told to quit.
    wake: Condvar,
    /// Signalled when the helper finishes a job.
    done: Condvar,
}

/// The helper thread.
pub struct Helper {
    shared: Arc<Shared>,
    thread: Option<JoinHandle<()>>,
}

impl Helper {
    /// Starts the thread, or None when the system refuses one.
    pub fn start() -> Option<Helper> {
        let shared = Arc::new(Shared::default());
        let s = Arc::clone(&shared);
        let thread = std::thread::Builder::new()
            .name("kerf-sim-helper".into())
            .spawn(move || serve(&s))
            .ok()?;
        Some(Helper {
            shared,
            thread: Some(thread),
        })
    }

    /// Runs `job` on this thread and, if it gets there in time, on the
    /// helper too; returns when neither runs it any more.
    pub fn run(&self, job: &(dyn Fn() + Sync)) {
        // SAFETY: only the lifetime is erased; `Finish` (below) does not
        // let this function return or unwind before the helper is done
        // with the pointer.
        let ptr: *const (dyn Fn() + Sync + 'static) = unsafe { std::mem::transmute(job) };
        {
            let mut st = lock(&self.shared.state);
            st.job = Some(Job(ptr));
        }
        self.shared.wake.notify_one();
        let finish = Finish(&self.shared);
        job();
        drop(finish);
    }
}

/// On drop (return or unwind of [`Helper::run`]): the job taken back if
/// the helper has not started it, else waited for; a panic of the
/// helper's run resumed here.
struct Finish<'a>(&'a Shared);

impl Drop for Finish<'_> {
    fn drop(&mut self) {
        let mut st = lock(&self.0.state);
        st.job = None;
        while st.busy {
            st = self.0.done.wait(st).unwrap_or_else(|e| e.into_inner());
        }
        if std::mem::take(&mut st.panicked) && !std::thread::panicking() {
            drop(st);
            panic!("the simulation's helper thread panicked");
        }
    }
}

impl Drop for Helper {
    fn drop(&mut self) {
        lock(&self.shared.state).quit = true;
        self.shared.wake.notify_one();
        if let Some(t) = self.thread.take() {
            let _ = t.join();
        }
    }
}

fn lock(m: &Mutex<State>) -> std::sync::MutexGuard<'_, State> {
    m.lock().unwrap_or_else(|e| e.into_inner())
}

/// The helper's loop: take a job, run it, say so.
fn serve(s: &Shared) {
    let mut st = lock(&s.state);
    loop {
        if st.quit {
            return;
        }
        let Some(job) = st.job.take() else {
            st = s.wake.wait(st).unwrap_or_else(|e| e.into_inner());
            continue;
        };
        st.busy = true;
        drop(st);
        // SAFETY: the caller waits in `Finish` while `busy` is set.
        let f = unsafe { &*job.0 };
        let ok = std::panic::catch_unwind(std::panic::AssertUnwindSafe(f)).is_ok();
        st = lock(&s.state);
        st.busy = false;
        st.panicked |= !ok;
        s.done.notify_all();
    }
}

/// The helper of a height field: started on first use, not shared by a
/// clone (a clone starts its own).
#[derive(Default)]
pub struct LazyHelper(Option<Helper>);

impl LazyHelper {
    /// The helper, started now if it was not.
    pub fn get(&mut self) -> Option<&Helper> {
        if self.0.is_none() {
            self.0 = Helper::start();
        }
        self.0.as_ref()
    }
}

impl Clone for LazyHelper {
    fn clone(&self) -> LazyHelper {
        LazyHelper(None)
    }
}

impl std::fmt::Debug for LazyHelper {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "LazyHelper({})", self.0.is_some())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::atomic::{AtomicUsize, Ordering};

    #[test]
    fn every_piece_is_done_once_by_one_thread_or_the_other() {
        let h = Helper::start().unwrap();
        for round in 0..200 {
            let next = AtomicUsize::new(0);
            let done: Vec<AtomicUsize> = (0..64).map(|_| AtomicUsize::new(0)).collect();
            h.run(&|| loop {
                let k = next.fetch_add(1, Ordering::Relaxed);
                if k >= done.len() {
                    break;
                }
                done[k].fetch_add(round + 1, Ordering::Relaxed);
            });
            // After run returns nothing touches `done` any more.
            assert!(done.iter().all(|d| d.load(Ordering::Relaxed) == round + 1));
        }
    }
}
