//! The `kerf` command: run, check or expand a part program against a
//! machine profile, and list the built-in machines. Exit status: 0 the program ran
//! to its end, 1 it stopped on an alarm, 2 usage or I/O error.
//!
//! Running is kerf-control's: this crate parses the arguments, opens the
//! output files, prints and picks the exit status.

mod args;
mod diagnostic;
mod expand;
mod outputs;

use std::io::Write;
use std::process::ExitCode;

use clap::Parser;
use kerf_control::{Outcome, Sink};
use kerf_interp::{machine::BUILTIN, Profile};

use args::{Cli, Cmd, Common, Outputs};

fn main() -> ExitCode {
    let cli = Cli::parse();
    match cli.cmd {
        Cmd::Machines => {
            for (name, _) in BUILTIN {
                let p = Profile::builtin(name).expect("built-in profile");
                println!("{name:<12} {}", p.description);
            }
            ExitCode::SUCCESS
        }
        Cmd::Run { common, outputs } => run(&common, &outputs, false),
        Cmd::Check { common } => run(&common, &Outputs::default(), true),
        Cmd::Expand { common, to, out } => expand::expand(&common, &to, out.as_deref()),
    }
}

fn usage_error(msg: impl std::fmt::Display) -> ExitCode {
    eprintln!("kerf: {msg}");
    ExitCode::from(2)
}

/// Loads the job, runs it through the sinks the options ask for, prints
/// the result.
fn run(c: &Common, outputs: &Outputs, check: bool) -> ExitCode {
    if let Err(e) = outputs.validate() {
        return usage_error(e);
    }
    let job = c.job();
    let mut runner = match job.load() {
        Ok(r) => r,
        Err(e) => return usage_error(e),
    };
    let mut sinks = match outputs.open() {
        Ok(s) => s,
        Err(e) => return usage_error(e),
    };
    if sinks.is_empty() {
        // No outputs asked for: only interpret (as `kerf check`).
        runner.interpret_only();
    }
    let mut refs: Vec<&mut dyn Sink> = sinks.iter_mut().map(|s| s.as_mut() as _).collect();
    match runner.run(&mut refs) {
        Ok(outcome) => print_outcome(&job.program_name(), &outcome, check),
        Err(e) => usage_error(e),
    }
}

fn print_outcome(name: &str, o: &Outcome, check: bool) -> ExitCode {
    if o.stalled > 0 {
        eprintln!(
            "kerf: warning: {} cutting moves with the spindle stopped (per-revolution feed or thread) timed as 0 s",
            o.stalled
        );
    }
    if let Some(a) = &o.alarm {
        diagnostic::print_alarm(a, &o.alarm_file);
        return ExitCode::from(1);
    }
    let mut out = std::io::stdout().lock();
    let _ = match (check, o.cycle_time) {
        (true, _) => writeln!(out, "{name}: ok ({} blocks)", o.blocks),
        (false, Some(t)) => writeln!(
            out,
            "{name}: completed ({} blocks, cycle time {t:.1} s)",
            o.blocks
        ),
        (false, None) => writeln!(out, "{name}: completed ({} blocks)", o.blocks),
    };
    ExitCode::SUCCESS
}
