//! `kerf expand`: the program run through the runner (interpreting only,
//! no planning) with kerf-control's expansion sink, up to its end or its
//! alarm.

use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::Path;
use std::process::ExitCode;

use kerf_control::{sinks::ExpandBehind, Sink};
use kerf_expand::Target;

use crate::args::Common;
use crate::{diagnostic, progress, usage_error};

/// Runs `kerf expand`. Exit status as `kerf run`: 0 the program ran to its
/// end, 1 it stopped on an alarm (the output holds everything before it),
/// 2 usage or I/O error. `--state` is read, never written; `--quiet` drops
/// the summary line; a progress bar as for `run`.
pub fn expand(c: &Common, to: &str, out: Option<&Path>) -> ExitCode {
    let target: Target = match to.parse() {
        Ok(t) => t,
        Err(e) => return usage_error(format!("--to: {e}")),
    };
    if c.json {
        return usage_error("--json is for run and check (expand writes G-code)");
    }
    let job = c.job(true);
    let mut runner = match job.load() {
        Ok(r) => r,
        Err(e) => return usage_error(e),
    };
    runner.interpret_only();
    // Written by a thread of its own (the interpreter keeps this one).
    let w: Box<dyn Write + Send> = match out {
        Some(p) => match File::create(p) {
            Ok(f) => Box::new(f),
            Err(e) => return usage_error(format!("{}: {e}", p.display())),
        },
        None => Box::new(std::io::stdout()),
    };
    let mut sink = ExpandBehind::new(BufWriter::with_capacity(1 << 16, w), target);
    let mut refs: [&mut dyn Sink; 1] = [&mut sink];
    let outcome = match progress::run_to_end(runner, &mut refs, c.quiet) {
        Ok(o) => o,
        Err(e) => return usage_error(e),
    };
    diagnostic::print_warnings(&outcome.warnings);
    if outcome.warnings_dropped > 0 {
        eprintln!("kerf: {} more warnings not shown", outcome.warnings_dropped);
    }
    if let Some(a) = &outcome.alarm {
        diagnostic::print_alarm(a, &outcome.alarm_file);
        return ExitCode::from(1);
    }
    if let (Some(p), false) = (out, c.quiet) {
        println!(
            "{}: expanded for {target} ({} blocks read, {} blocks written to {})",
            job.program_name(),
            outcome.blocks,
            sink.blocks(),
            p.display()
        );
    }
    ExitCode::SUCCESS
}
