//! The toolpath writer alone (harness = false):
//! `cargo bench -p kerf-control --bench toolpath`.
//!
//! Writes `KERF_BENCH_RECORDS` (default 2,000,000) feed records like those
//! of bench-inputs/surface_1m.nc (4 axes, three-decimal coordinates, a
//! growing end time) through `Sink::timed` into `io::sink()`, 5 times, and
//! prints the median records/s and MB/s. No file system in the way: this
//! is the formatting cost.

use std::hint::black_box;
use std::io::{self, Write};
use std::time::Instant;

use kerf_canon::{Canon, Event, Feed, Motion, SrcRef};
use kerf_control::sinks::Toolpath;
use kerf_control::{Context, Sink, Timed};
use kerf_interp::{Interp, Profile, Settings};
use kerf_motion::Planner;

/// Counts the bytes written.
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

/// CPU seconds of this process (user + system) from /proc/self/stat, so
/// that a loaded machine does not count other programs' time; None where
/// that file does not exist.
fn cpu_seconds() -> Option<f64> {
    let s = std::fs::read_to_string("/proc/self/stat").ok()?;
    // Fields after the command name (which is in parentheses).
    let rest = &s[s.rfind(')')? + 2..];
    let f: Vec<&str> = rest.split_whitespace().collect();
    let ticks: f64 = f.get(11)?.parse::<f64>().ok()? + f.get(12)?.parse::<f64>().ok()?;
    Some(ticks / 100.0)
}

fn main() {
    let n: usize = std::env::var("KERF_BENCH_RECORDS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(2_000_000);
    let profile = Profile::builtin("hx-mc").expect("hx-mc");
    let d = kerf_control::dynamics::dynamics_of(&profile, 100.0, 100.0, false).expect("dynamics");
    let mut it = Interp::new(profile, Settings::default());
    it.load_main(
        "bench-inputs/surface_1m.nc",
        Box::new(io::Cursor::new(Vec::new())),
    );
    let planner = Planner::new(d, it.machine_position(), 0.0);
    let events: Vec<Event> = (0..1000)
        .map(|k| {
            let x = (k % 200) as f64 * 0.5 + 10.125;
            let y = (k / 200) as f64 * 0.75 - 3.5;
            let to = [x, y, -1.25, 0.0, 0.0, 0.0];
            let mto = [x - 400.0, y - 250.0, -251.25, 0.0, 0.0, 0.0];
            Event {
                src: SrcRef {
                    file: 0,
                    line: 1000 + k,
                    col: 1,
                },
                tool: 3,
                cmd: Canon::Feed {
                    m: Motion { to, mto },
                    feed: Feed::PerMin(1200.0),
                },
                prog: None,
            }
        })
        .collect();
    let mut rates = Vec::new();
    for _ in 0..5 {
        let mut w = Toolpath::new(Count(0));
        let cx = Context {
            interp: &it,
            planner: &planner,
            warnings: &[],
        };
        w.start(&cx).expect("start");
        let live = cx.live();
        let (t0, c0) = (Instant::now(), cpu_seconds());
        for i in 0..n {
            let e = &events[i % events.len()];
            let to = e.motion().map(|m| m.to).unwrap_or_default();
            let t = Timed {
                event: e,
                from: to,
                to,
                t_end: i as f64 * 0.0123457,
                time: 0.0123457,
                feed_mm_min: Some(1200.0),
            };
            w.timed(&t, &live).expect("write");
        }
        let secs = match (c0, cpu_seconds()) {
            (Some(a), Some(b)) if b > a => b - a,
            _ => t0.elapsed().as_secs_f64(),
        };
        w.finish(&cx, None).expect("finish");
        black_box(&w);
        rates.push((n as f64 / secs, secs));
    }
    rates.sort_by(|a, b| a.0.total_cmp(&b.0));
    let (rate, secs) = rates[2];
    println!(
        "toolpath writer: {n} records in {secs:.3} s of CPU (median of 5): {:.2} M records/s",
        rate / 1e6
    );
}
