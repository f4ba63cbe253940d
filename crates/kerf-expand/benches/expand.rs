//! Expansion benchmark (harness = false): `cargo bench -p kerf-expand`.
//!
//! Over one large program (default `bench-inputs/surface_1m.nc` at the
//! workspace root, or `KERF_BENCH_INPUT`), on hx-mc:
//!
//! - `write`: the expander alone. The program's events are collected once
//!   (in memory: about 1 M events for surface_1m), then written as G-code
//!   to `io::sink()`; output blocks per second and MB/s of text.
//! - `pipeline`: the interpreter and the expander together, streaming, as
//!   `kerf expand` runs them (no file).
//!
//! Each `KERF_BENCH_RUNS` times (default 3); the median and the best run
//! are printed (the best is the one least disturbed by other load).

use std::fs::File;
use std::io::{self, Write};
use std::path::PathBuf;
use std::time::Instant;

use kerf_canon::{Axis, Event};
use kerf_expand::{Control, Expander, Spelling, Target};
use kerf_interp::{Interp, Profile, Settings, Step};

/// Counts the bytes written, drops them.
struct Count(u64);

impl Write for Count {
    fn write(&mut self, b: &[u8]) -> io::Result<usize> {
        self.0 += b.len() as u64;
        Ok(b.len())
    }
    fn flush(&mut self) -> io::Result<()> {
        Ok(())
    }
}

fn interp(path: &PathBuf) -> Interp {
    let profile = Profile::builtin("hx-mc").expect("hx-mc");
    let settings = Settings {
        max_blocks: 0,
        ..Settings::default()
    };
    let mut it = Interp::new(profile, settings);
    it.load_main("input.nc", Box::new(File::open(path).expect("open input")));
    it
}

fn expander(it: &Interp) -> Expander<io::BufWriter<Count>> {
    let sp = Spelling::new(Target::Fanuc, Control::Hx);
    let axes = vec![Axis::X, Axis::Y, Axis::Z, Axis::C];
    let w = io::BufWriter::with_capacity(1 << 16, Count(0));
    Expander::new(w, sp, axes, it.work_position(), it.machine_position())
}

/// (seconds, blocks written, bytes written).
fn write_only(events: &[Event], it: &Interp) -> (f64, u64, u64) {
    let mut x = expander(it);
    let t = Instant::now();
    x.start("input.nc").unwrap();
    for e in events {
        x.event(e, "input.nc").unwrap();
    }
    let blocks = x.blocks();
    let w = x.finish().unwrap();
    let secs = t.elapsed().as_secs_f64();
    (secs, blocks, w.into_inner().ok().map_or(0, |c| c.0))
}

fn pipeline(path: &PathBuf) -> (f64, u64, u64) {
    let t = Instant::now();
    let mut it = interp(path);
    let mut x = expander(&it);
    x.start("input.nc").unwrap();
    while let Step::Event(e) = it.step() {
        x.event(&e, "input.nc").unwrap();
    }
    let blocks = x.blocks();
    let w = x.finish().unwrap();
    let secs = t.elapsed().as_secs_f64();
    (secs, blocks, w.into_inner().ok().map_or(0, |c| c.0))
}

fn report(what: &str, mut runs: Vec<(f64, u64, u64)>) {
    runs.sort_by(|a, b| a.0.total_cmp(&b.0));
    let (s, blocks, bytes) = runs[runs.len() / 2];
    let best = runs[0].0;
    println!(
        "{what:<9} median {:.3} s  {blocks} blocks  {:.2} M blocks/s  {:.0} MB/s  (best {:.2} M blocks/s)",
        s,
        blocks as f64 / s / 1e6,
        bytes as f64 / s / 1e6,
        blocks as f64 / best / 1e6
    );
}

fn main() {
    let filter: Option<String> = std::env::args().skip(1).find(|a| !a.starts_with('-'));
    let want = |n: &str| filter.as_deref().is_none_or(|f| n.contains(f));
    let path = match std::env::var_os("KERF_BENCH_INPUT") {
        Some(p) => PathBuf::from(p),
        None => PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../bench-inputs/surface_1m.nc"),
    };
    if !path.is_file() {
        println!("no input {} (see docs/benchmarks.md)", path.display());
        return;
    }
    let runs: usize = std::env::var("KERF_BENCH_RUNS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(3);
    if want("write") {
        let mut it = interp(&path);
        let mut events = Vec::new();
        while let Step::Event(e) = it.step() {
            events.push(e);
        }
        let start = interp(&path);
        report(
            "write",
            (0..runs).map(|_| write_only(&events, &start)).collect(),
        );
    }
    if want("pipeline") {
        report("pipeline", (0..runs).map(|_| pipeline(&path)).collect());
    }
}
