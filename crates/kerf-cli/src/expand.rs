//! `kerf expand`: the program run through the interpreter and written back
//! as plain G-code for a target control (kerf-expand), up to its end or
//! its alarm.

use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::PathBuf;
use std::process::ExitCode;

use kerf_canon::Axis;
use kerf_expand::{Control, Expander, Spelling, Target};
use kerf_interp::{dialect::DialectId, Interp, Step};

use crate::{load_profile, offsets, print_alarm, settings, usage_error, Common};

/// The control kerf-expand writes for, from the profile's dialect.
fn control_of(d: DialectId) -> Control {
    match d {
        DialectId::Hx => Control::Hx,
        DialectId::Puma => Control::Puma,
        DialectId::Hurco => Control::Hurco,
    }
}

/// The interpreter set up as `kerf run` sets it up (profile, `--set`,
/// `--lib`, `--state` read but never written, `--offsets`), with the
/// program loaded.
fn interp_for(c: &Common) -> Result<(Interp, Control, Vec<Axis>), String> {
    let mut profile = load_profile(&c.machine)?;
    let settings = settings::parse(&c.set, &mut profile)?;
    let file = File::open(&c.program).map_err(|e| format!("{}: {e}", c.program.display()))?;
    let control = control_of(profile.dialect);
    let axes: Vec<Axis> = Axis::ALL
        .iter()
        .copied()
        .filter(|a| profile.has_axis(*a))
        .collect();
    let mut it = Interp::new(profile, settings);
    for dir in &c.lib {
        if !dir.is_dir() {
            return Err(format!("--lib {}: not a folder", dir.display()));
        }
        it.add_lib_dir(dir.clone());
    }
    if let Some(dir) = &c.state {
        kerf_interp::state::load_retained(dir, &mut it)?;
        kerf_interp::state::load_offsets(dir, &mut it)?;
    }
    if let Some(path) = &c.offsets {
        offsets::load(path, &mut it)?;
    }
    it.load_main(&c.program.display().to_string(), Box::new(file));
    Ok((it, control, axes))
}

/// Runs `kerf expand`. Exit status as `kerf run`: 0 the program ran to its
/// end, 1 it stopped on an alarm (the output holds everything before it),
/// 2 usage or I/O error.
pub fn expand(c: &Common, to: &str, out: Option<PathBuf>) -> ExitCode {
    let target: Target = match to.parse() {
        Ok(t) => t,
        Err(e) => return usage_error(format!("--to {e}")),
    };
    let (mut it, control, axes) = match interp_for(c) {
        Ok(x) => x,
        Err(e) => return usage_error(e),
    };
    let sink: Box<dyn Write> = match &out {
        Some(p) => match File::create(p) {
            Ok(f) => Box::new(f),
            Err(e) => return usage_error(format!("{}: {e}", p.display())),
        },
        None => Box::new(std::io::stdout().lock()),
    };
    let w = BufWriter::with_capacity(1 << 16, sink);
    let sp = Spelling::new(target, control);
    let mut x = Expander::new(w, sp, axes, it.work_position(), it.machine_position());
    let name = c.program.display().to_string();
    let io = |e: std::io::Error| {
        let place = out
            .as_ref()
            .map_or("stdout".into(), |p| p.display().to_string());
        usage_error(format!("{place}: {e}"))
    };
    if let Err(e) = x.start(&name) {
        return io(e);
    }
    let mut alarm = None;
    loop {
        match it.step() {
            Step::Event(e) => {
                if let Err(err) = x.event(&e, it.file_name(e.src.file)) {
                    return io(err);
                }
            }
            Step::End => break,
            Step::Alarm(a) => {
                if let Err(err) = x.alarm(&a, it.file_name(a.src.file)) {
                    return io(err);
                }
                alarm = Some(a);
                break;
            }
        }
    }
    let blocks = x.blocks();
    if let Err(e) = x.finish() {
        return io(e);
    }
    if let Some(a) = &alarm {
        print_alarm(a, it.file_name(a.src.file));
        return ExitCode::from(1);
    }
    if let Some(p) = &out {
        println!(
            "{name}: expanded for {target} ({} blocks read, {blocks} blocks written to {})",
            it.blocks(),
            p.display()
        );
    }
    ExitCode::SUCCESS
}
