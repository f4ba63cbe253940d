//! The progress bar on stderr: shown only when stderr is a terminal and
//! the run has taken more than a second; blocks, bytes read of the
//! program, elapsed time.

use std::io::IsTerminal;
use std::time::{Duration, Instant};

use indicatif::{ProgressBar, ProgressStyle};
use kerf_control::{Outcome, RunError, Runner, Sink, Tick};

/// Runs `runner` to its end through `sinks` (the interpreter on a thread
/// of its own: [`Runner::run`]), with the bar on stderr, and finishes it.
pub fn run_to_end(
    runner: Runner,
    sinks: &mut [&mut dyn Sink],
    quiet: bool,
) -> Result<Outcome, RunError> {
    let mut bar = Progress::new(quiet);
    let out = runner.run_with_progress(sinks, &mut |t| bar.tick(t));
    bar.done();
    out
}

/// After how long a run shows the bar.
const DELAY: Duration = Duration::from_secs(1);

/// Ticks (each a batch of a few hundred events) between looks at the
/// clock.
const EVERY: u32 = 8;

/// Drives the bar from the runner's progress.
pub struct Progress {
    on: bool,
    start: Instant,
    steps: u32,
    bar: Option<ProgressBar>,
}

impl Progress {
    /// A bar that will show if stderr is a terminal and `quiet` is off.
    pub fn new(quiet: bool) -> Progress {
        Progress {
            on: !quiet && std::io::stderr().is_terminal(),
            start: Instant::now(),
            steps: 0,
            bar: None,
        }
    }

    /// Called after every batch of events the runner hands out.
    pub fn tick(&mut self, t: Tick) {
        if !self.on {
            return;
        }
        self.steps += 1;
        if self.steps < EVERY {
            return;
        }
        self.steps = 0;
        if self.bar.is_none() && self.start.elapsed() < DELAY {
            return;
        }
        let (read, len) = t.source.unwrap_or((0, 0));
        let since = self.start.elapsed();
        let bar = self.bar.get_or_insert_with(|| new_bar(len, since));
        bar.set_position(read);
        bar.set_message(format!("{} blocks", t.blocks));
    }

    /// Removes the bar.
    pub fn done(self) {
        if let Some(b) = self.bar {
            b.finish_and_clear();
        }
    }
}

/// A bar of `len` bytes shown `since` the run started (its clock counts
/// from the run's start, not from when it appears).
fn new_bar(len: u64, since: Duration) -> ProgressBar {
    let bar = ProgressBar::new(len).with_elapsed(since);
    let style =
        ProgressStyle::with_template("{elapsed_precise} [{bar:30}] {bytes}/{total_bytes} {msg}")
            .unwrap_or_else(|_| ProgressStyle::default_bar())
            .progress_chars("=> ");
    bar.set_style(style);
    bar
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_bar_counts_from_the_run_start() {
        // A bar that appears 1.5 s into the run shows at least 1.5 s.
        let bar = new_bar(100, Duration::from_millis(1500));
        assert!(bar.elapsed() >= Duration::from_millis(1500));
        assert!(bar.elapsed() < Duration::from_secs(60));
    }
}
