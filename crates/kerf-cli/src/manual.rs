//! `kerf completions SHELL` and `kerf man`: generated from the clap
//! definitions, so they list exactly the options `kerf` takes.

use std::io::Write;
use std::process::ExitCode;

use clap::CommandFactory;

use crate::args::Cli;

fn emit(bytes: &[u8]) -> ExitCode {
    // A closed pipe (`kerf man | head`) is not an error worth a panic.
    let _ = std::io::stdout().lock().write_all(bytes);
    ExitCode::SUCCESS
}

/// Prints the completion script for `shell`.
pub fn completions(shell: clap_complete::Shell) -> ExitCode {
    let mut buf = Vec::new();
    clap_complete::generate(shell, &mut Cli::command(), "kerf", &mut buf);
    emit(&buf)
}

/// Prints the manual page (roff).
pub fn man() -> ExitCode {
    let mut buf = Vec::new();
    if let Err(e) = clap_mangen::Man::new(Cli::command()).render(&mut buf) {
        eprintln!("kerf: {e}");
        return ExitCode::from(2);
    }
    emit(&buf)
}
