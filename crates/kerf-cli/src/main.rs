//! The `kerf` command: run, check or expand a part program against a
//! machine profile, serve the operator screen, and list the built-in
//! machines. Exit status: 0 the program ran to its end, 1 it stopped on an
//! alarm, 2 usage or I/O error, 3 it ran to its end but the simulation
//! (`--stock`) found a collision.
//!
//! Running is kerf-control's: this crate parses the arguments, opens the
//! output files, shows progress, prints and picks the exit status.

mod args;
mod diagnostic;
mod expand;
mod manual;
mod output_paths;
mod outputs;
mod progress;
mod serve;
mod summary;

use std::io::Write;
use std::process::ExitCode;

use clap::Parser;
use kerf_control::sinks::report::Document;
use kerf_control::sinks::SimSink;
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
        Cmd::Completions { shell } => manual::completions(shell),
        Cmd::Man => manual::man(),
        Cmd::Run { common, outputs } => run(&common, &outputs, false),
        Cmd::Check { common } => run(&common, &Outputs::default(), true),
        Cmd::Expand { common, to, out } => expand::expand(&common, &to, out.as_deref()),
        Cmd::Serve(a) => serve::run(a),
    }
}

/// Prints `kerf: MESSAGE` (a system message without its `(os error N)`)
/// and gives exit status 2.
fn usage_error(msg: impl std::fmt::Display) -> ExitCode {
    let msg = msg.to_string();
    eprintln!("kerf: {}", output_paths::strip_os_error(&msg));
    ExitCode::from(2)
}

/// Loads the job, opens every output before the run, runs it with a
/// progress bar, prints the result.
fn run(c: &Common, outputs: &Outputs, check: bool) -> ExitCode {
    if let Err(e) = outputs.validate() {
        return usage_error(e);
    }
    let job = c.job(check);
    let runner = match job.load() {
        Ok(r) => r,
        Err(e) => return usage_error(e),
    };
    let opened = outputs.report().and_then(|r| {
        let sim = outputs.sim(runner.interp().profile())?;
        Ok((r, outputs.open()?, sim))
    });
    let (mut report, mut sinks, mut sim) = match opened {
        Ok(s) => s,
        Err(e) => return usage_error(e),
    };
    let handle = sim.as_ref().map(SimSink::handle);
    if let Some(h) = &handle {
        report = report.with_sim(h.clone());
    }
    // The simulation finishes before the report, which carries its section.
    let mut refs: Vec<&mut dyn Sink> = Vec::new();
    if let Some(s) = sim.as_mut() {
        refs.push(s);
    }
    refs.push(&mut report);
    refs.extend(sinks.iter_mut().map(|s| s.as_mut() as &mut dyn Sink));
    let outcome = match progress::run_to_end(runner, &mut refs, c.quiet) {
        Ok(o) => o,
        Err(e) => return usage_error(e),
    };
    drop(refs);
    let doc = report.document().expect("the report is made at finish");
    let code = print_outcome(c, &job.program_name(), &outcome, doc, check);
    let collided = handle.and_then(|h| h.borrow().clone()).is_some_and(|s| {
        diagnostic::print_sim(&s);
        s.collisions > 0
    });
    if outcome.alarm.is_none() && collided {
        return ExitCode::from(3);
    }
    code
}

fn print_outcome(c: &Common, name: &str, o: &Outcome, doc: &Document, check: bool) -> ExitCode {
    diagnostic::print_warnings(&o.warnings);
    if o.warnings_dropped > 0 {
        eprintln!("kerf: {} more warnings not shown", o.warnings_dropped);
    }
    if c.json {
        let text = serde_json::to_string_pretty(doc).expect("report serialises");
        let _ = writeln!(std::io::stdout().lock(), "{text}");
    }
    if let Some(a) = &o.alarm {
        diagnostic::print_alarm(a, &o.alarm_file);
        return ExitCode::from(1);
    }
    if !c.quiet && !c.json {
        let verdict = if check { "ok" } else { "completed" };
        let _ = write!(
            std::io::stdout().lock(),
            "{}",
            summary::text(name, verdict, doc)
        );
    }
    ExitCode::SUCCESS
}
