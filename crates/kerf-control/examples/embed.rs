//! Embedding kerf: run a part program through the library and read what
//! the machine does, without the `kerf` command.
//!
//! ```sh
//! cargo run -p kerf-control --example embed
//! cargo run -p kerf-control --example embed -- examples/puma/g01_linear.nc puma-lathe
//! ```
//!
//! A [`Sink`] receives every canonical command as the interpreter emits it
//! (`event`) and every motion once the planner has fixed its end time
//! (`timed`); this one counts motions per kind and keeps the longest cut.

use std::io;

use kerf_canon::{Alarm, Canon, Event, Pos};
use kerf_control::{Context, Job, Live, Sink, Timed};

/// Counts what happens and remembers the slowest cutting move.
#[derive(Default)]
struct Watch {
    rapids: u64,
    cuts: u64,
    messages: Vec<String>,
    /// (seconds, line) of the cutting move that took longest.
    longest: Option<(f64, u32)>,
}

impl Sink for Watch {
    fn name(&self) -> &str {
        "watch"
    }

    fn event(&mut self, e: &Event, _from: &Pos, _cx: &Live) -> io::Result<()> {
        match &e.cmd {
            Canon::Rapid { .. } => self.rapids += 1,
            Canon::Feed { .. } | Canon::Arc { .. } | Canon::Thread { .. } => self.cuts += 1,
            Canon::Message(text) => self.messages.push(text.clone()),
            _ => {}
        }
        Ok(())
    }

    fn timed(&mut self, t: &Timed, _cx: &Live) -> io::Result<()> {
        let cutting = matches!(t.event.cmd, Canon::Feed { .. } | Canon::Arc { .. });
        if cutting && self.longest.is_none_or(|(s, _)| t.time > s) {
            self.longest = Some((t.time, t.event.src.line));
        }
        Ok(())
    }

    fn finish(&mut self, cx: &Context, alarm: Option<&Alarm>) -> io::Result<()> {
        if let Some(a) = alarm {
            println!(
                "stopped by alarm {} at line {}: {}",
                a.code, a.src.line, a.message
            );
        }
        println!(
            "{} blocks, {} rapids, {} cuts, cycle time {:.1} s",
            cx.interp.blocks(),
            self.rapids,
            self.cuts,
            cx.planner.now()
        );
        Ok(())
    }
}

const DEMO: &str = "G90 G54 G17 G21\nG0 X0 Y0 Z5.\nM3 S1200\nG1 Z-1. F200.\n\
X40. F600.\nG3 X40. Y30. R15.\nG1 X0\nY0\nG0 Z50.\nM30\n";

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let job = match args.first() {
        Some(path) => Job::file(path),
        None => Job::text("demo.nc", DEMO),
    };
    let job = job.machine(args.get(1).map_or("hx-mc", String::as_str));
    let runner = match job.load() {
        Ok(r) => r,
        Err(e) => {
            eprintln!("{e}");
            std::process::exit(2);
        }
    };
    let mut watch = Watch::default();
    match runner.run(&mut [&mut watch]) {
        Ok(outcome) => {
            for w in &outcome.warnings {
                println!("warning {} at line {}: {}", w.code, w.line, w.message);
            }
            if let Some((s, line)) = watch.longest {
                println!("longest cut: line {line}, {s:.2} s");
            }
        }
        Err(e) => eprintln!("{e}"),
    }
}
