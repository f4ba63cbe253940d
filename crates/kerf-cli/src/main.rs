//! The `kerf` command: run or check a part program against a machine
//! profile, and list the built-in machines. Exit status: 0 the program ran
//! to its end, 1 it stopped on an alarm, 2 usage or I/O error.

mod dynamics;
mod expand;
mod offsets;
mod plot;
mod report;
mod settings;
mod toolpath;

use std::collections::VecDeque;
use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::{Parser, Subcommand};
use kerf_canon::{Alarm, Axis, Canon, Event, Pos};
use kerf_interp::{machine::BUILTIN, Interp, Profile, Step};
use kerf_motion::{Planner, Sampler};

#[derive(Parser)]
#[command(
    name = "kerf",
    version,
    about = "A software CNC control: runs Fanuc-family part programs as the real control would"
)]
struct Cli {
    #[command(subcommand)]
    cmd: Cmd,
}

#[derive(clap::Args, Clone)]
struct Common {
    /// The part program.
    program: PathBuf,
    /// Machine profile: a built-in name (see `kerf machines`) or a TOML file.
    #[arg(long, default_value = "hx-mc")]
    machine: String,
    /// Folder of library programs (subprograms, macros); may repeat.
    #[arg(long = "lib")]
    lib: Vec<PathBuf>,
    /// Operator switches and parameters: block_skip=1,2 optional_stop=on
    /// single_block=on dry_run=on, "PI 144=1" … (see docs/formats.md).
    #[arg(long = "set", value_name = "KEY=VALUE")]
    set: Vec<String>,
    /// Work offsets file (TOML, see docs/formats.md).
    #[arg(long)]
    offsets: Option<PathBuf>,
    /// Folder keeping the retained macro variables across runs (#200-#699
    /// on the HX, #500-#999 on the Fanuc lathes; docs/formats.md).
    #[arg(long, value_name = "DIR")]
    state: Option<PathBuf>,
}

#[derive(Subcommand)]
enum Cmd {
    /// Run a program and write what it does.
    Run {
        #[command(flatten)]
        common: Common,
        /// Write every motion as JSON Lines.
        #[arg(long)]
        toolpath: Option<PathBuf>,
        /// Write a JSON summary of the run.
        #[arg(long)]
        report: Option<PathBuf>,
        /// Write an SVG plot of the toolpath.
        #[arg(long)]
        plot: Option<PathBuf>,
        /// Write the smoothed axis setpoints every DT seconds (e.g. 0.001)
        /// to FILE as CSV (docs/formats.md).
        #[arg(long, num_args = 2, value_names = ["DT", "FILE"])]
        sample: Vec<String>,
        /// Write the operator messages (Hurco probe records, #3006 …), one
        /// per line.
        #[arg(long)]
        log: Option<PathBuf>,
    },
    /// Check a program: run it without writing outputs; report alarms.
    Check {
        #[command(flatten)]
        common: Common,
    },
    /// Write the program as plain G-code for another control: every macro,
    /// call, cycle, compensation, transform and offset resolved
    /// (docs/expand.md).
    Expand {
        #[command(flatten)]
        common: Common,
        /// Target: `fanuc` (the same kind of control) or `linuxcnc`.
        #[arg(long, default_value = "fanuc")]
        to: String,
        /// Output file (default: standard output).
        #[arg(short = 'o', long = "output", value_name = "OUT.nc")]
        out: Option<PathBuf>,
    },
    /// List the built-in machine profiles.
    Machines,
}

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
        Cmd::Run {
            common,
            toolpath,
            report,
            plot,
            sample,
            log,
        } => {
            let sample = match sample.as_slice() {
                [] => None,
                [dt, file] => match dt.parse::<f64>() {
                    Ok(v) if (1e-5..=1.0).contains(&v) => Some((v, PathBuf::from(file))),
                    _ => {
                        return usage_error(format!(
                            "--sample {dt}: DT is a period in seconds, 0.00001-1"
                        ))
                    }
                },
                _ => return usage_error("--sample needs DT and FILE"),
            };
            run(&common, toolpath, report, plot, sample, log, false)
        }
        Cmd::Check { common } => run(&common, None, None, None, None, None, true),
        Cmd::Expand { common, to, out } => expand::expand(&common, &to, out),
    }
}

fn usage_error(msg: impl std::fmt::Display) -> ExitCode {
    eprintln!("kerf: {msg}");
    ExitCode::from(2)
}

fn load_profile(name: &str) -> Result<Profile, String> {
    if let Some(p) = Profile::builtin(name) {
        return Ok(p);
    }
    if name.ends_with(".toml") || Path::new(name).exists() {
        let text = std::fs::read_to_string(name).map_err(|e| format!("{name}: {e}"))?;
        return Profile::from_toml(&text).map_err(|e| format!("{name}: {e}"));
    }
    let names: Vec<&str> = BUILTIN.iter().map(|(n, _)| *n).collect();
    Err(format!(
        "unknown machine '{name}' (built-in: {})",
        names.join(", ")
    ))
}

fn run(
    c: &Common,
    toolpath: Option<PathBuf>,
    report_path: Option<PathBuf>,
    plot_path: Option<PathBuf>,
    sample: Option<(f64, PathBuf)>,
    log_path: Option<PathBuf>,
    check: bool,
) -> ExitCode {
    let mut profile = match load_profile(&c.machine) {
        Ok(p) => p,
        Err(e) => return usage_error(e),
    };
    // Overrides are the planner's: take them out before the interpreter's keys.
    let (mut feed_ovr, mut rapid_ovr) = (100.0, 100.0);
    let mut sets = Vec::new();
    for kv in &c.set {
        match kv.split_once('=').map(|(k, v)| (k.trim(), v.trim())) {
            Some((k @ ("feed_override" | "rapid_override"), v)) => {
                let Some(pct) = v.parse::<f64>().ok().filter(|p| (1.0..=1000.0).contains(p)) else {
                    return usage_error(format!("--set {k}={v}: expected a percentage 1-1000"));
                };
                if k == "feed_override" {
                    feed_ovr = pct;
                } else {
                    rapid_ovr = pct;
                }
            }
            _ => sets.push(kv.clone()),
        }
    }
    let settings = match settings::parse(&sets, &mut profile) {
        Ok(s) => s,
        Err(e) => return usage_error(e),
    };
    let dynamics = match dynamics::dynamics_of(&profile, feed_ovr, rapid_ovr, settings.dry_run) {
        Ok(d) => d,
        Err(e) => return usage_error(format!("machine {}: {e}", c.machine)),
    };
    let file = match File::open(&c.program) {
        Ok(f) => f,
        Err(e) => return usage_error(format!("{}: {e}", c.program.display())),
    };
    let name = c.program.display().to_string();
    let max_rpm = profile.spindle.max_rpm;
    let kind = profile.kind;
    let axes: Vec<Axis> = Axis::ALL
        .iter()
        .copied()
        .filter(|a| profile.has_axis(*a))
        .collect();
    let mut it = Interp::new(profile, settings);
    for dir in &c.lib {
        if !dir.is_dir() {
            return usage_error(format!("--lib {}: not a folder", dir.display()));
        }
        it.add_lib_dir(dir.clone());
    }
    if let Some(dir) = &c.state {
        if let Err(e) = std::fs::create_dir_all(dir) {
            return usage_error(format!("--state {}: {e}", dir.display()));
        }
        if let Err(e) = kerf_interp::state::load_retained(dir, &mut it) {
            return usage_error(e);
        }
        if let Err(e) = kerf_interp::state::load_offsets(dir, &mut it) {
            return usage_error(e);
        }
    }
    // An offsets file given with the run goes on top of the kept memory.
    if let Some(path) = &c.offsets {
        if let Err(e) = offsets::load(path, &mut it) {
            return usage_error(e);
        }
    }
    it.load_main(&name, Box::new(file));

    let mut tp = match toolpath.as_ref().map(File::create).transpose() {
        Ok(f) => {
            f.map(|f| toolpath::Writer::new(BufWriter::with_capacity(1 << 16, f), axes.clone()))
        }
        Err(e) => return usage_error(format!("{}: {e}", toolpath.unwrap().display())),
    };
    let mut rep = report::Summary::new(&axes);
    let mut plotter = plot_path.as_ref().map(|_| plot::Plot::new(kind));
    let mut planner = Planner::new(dynamics, it.machine_position(), it.work_position()[0]);
    planner.max_rpm = max_rpm;
    let mut sampler = match &sample {
        Some((dt, path)) => match File::create(path) {
            Ok(f) => {
                planner.keep_pieces();
                let mut w = BufWriter::with_capacity(1 << 16, f);
                let head: Vec<&str> = axes.iter().map(|a| a.name()).collect();
                if let Err(e) = writeln!(w, "t,{}", head.join(",")) {
                    return usage_error(format!("{}: {e}", path.display()));
                }
                let s = Sampler::new(
                    *dt,
                    planner.stages(),
                    planner.smoothing_time(),
                    it.machine_position(),
                );
                Some((s, w, 0.0f64))
            }
            Err(e) => return usage_error(format!("{}: {e}", path.display())),
        },
        None => None,
    };
    // Records waiting for their end time (bounded by the look-ahead window).
    let mut pending: VecDeque<(Event, Pos, Option<f64>)> = VecDeque::new();
    let mut start_work = it.work_position();
    let mut alarm: Option<Alarm> = None;
    let mut log = match log_path.as_ref().map(File::create).transpose() {
        Ok(f) => f.map(BufWriter::new),
        Err(e) => return usage_error(format!("{}: {e}", log_path.unwrap().display())),
    };
    let sinks = tp.is_some()
        || report_path.is_some()
        || plotter.is_some()
        || sampler.is_some()
        || log.is_some();
    let mut io_err: Option<String> = None;
    let mut drain = |planner: &mut Planner,
                     pending: &mut VecDeque<(Event, Pos, Option<f64>)>,
                     it: &Interp,
                     tp: &mut Option<toolpath::Writer<BufWriter<File>>>|
     -> Result<(), String> {
        while let Some(d) = planner.next_done() {
            let Some((e, here, feed)) = pending.pop_front() else {
                break;
            };
            if let Some(w) = tp.as_mut() {
                w.write(&e, it.file_name(e.src.file), &here, d.t_end, feed)
                    .map_err(|err| format!("toolpath: {err}"))?;
            }
        }
        if let Some((s, w, covered)) = sampler.as_mut() {
            while let Some(p) = planner.next_piece() {
                *covered = p.t0 + p.duration();
                s.add(p);
            }
            let mut err = None;
            let axes = &axes;
            s.run(*covered, &mut |t, p| {
                if err.is_some() {
                    return;
                }
                let mut line = String::with_capacity(64);
                toolpath::num(&mut line, t);
                for a in axes {
                    line.push(',');
                    toolpath::num(&mut line, p[*a as usize]);
                }
                line.push('\n');
                if let Err(e) = w.write_all(line.as_bytes()) {
                    err = Some(e);
                }
            });
            if let Some(e) = err {
                return Err(format!("sample: {e}"));
            }
        }
        Ok(())
    };
    loop {
        match it.step() {
            Step::Event(e) if !sinks => {
                // No outputs asked for: only interpret (as `kerf check`).
                drop(e);
            }
            Step::Event(e) => {
                let from = start_work;
                if let Some(m) = e.motion() {
                    rep.motion(&e, &from, m);
                    if let Some(p) = plotter.as_mut() {
                        p.add(&e, &from);
                    }
                    start_work = m.to;
                }
                if let Canon::Tool { tool, .. } = e.cmd {
                    rep.tool(tool);
                }
                if let Canon::Message(text) = &e.cmd {
                    rep.message(e.src.line, text);
                    if let Some(l) = log.as_mut() {
                        if let Err(err) = writeln!(l, "{text}") {
                            return usage_error(format!("log: {err}"));
                        }
                    }
                }
                let feed = match &e.cmd {
                    Canon::Feed { feed, m } => {
                        Some(planner.feed_mm_min(*feed, kerf_motion::geom::line_len(&from, &m.to)))
                    }
                    Canon::Arc { feed, .. } => Some(planner.feed_mm_min(*feed, 0.0)),
                    _ => None,
                };
                planner.push(&e);
                if e.motion().is_some() || matches!(e.cmd, Canon::Dwell { .. }) {
                    pending.push_back((e, start_work, feed));
                }
                if let Err(err) = drain(&mut planner, &mut pending, &it, &mut tp) {
                    io_err = Some(err);
                    break;
                }
            }
            Step::End => break,
            Step::Alarm(a) => {
                alarm = Some(a);
                break;
            }
        }
    }
    planner.finish();
    if io_err.is_none() {
        if let Err(err) = drain(&mut planner, &mut pending, &it, &mut tp) {
            io_err = Some(err);
        }
    }
    if let Some(err) = io_err {
        return usage_error(err);
    }
    if planner.stalled > 0 {
        eprintln!(
            "kerf: warning: {} cutting moves with the spindle stopped (per-revolution feed or thread) timed as 0 s",
            planner.stalled
        );
    }
    if let Some(w) = tp.as_mut() {
        if let Err(e) = w.finish() {
            return usage_error(format!("toolpath: {e}"));
        }
    }
    if let Some((_, mut w, _)) = sampler {
        if let Err(e) = w.flush() {
            return usage_error(format!("sample: {e}"));
        }
    }
    if let Some(l) = log.as_mut() {
        if let Err(e) = l.flush() {
            return usage_error(format!("log: {e}"));
        }
    }
    if let Some(a) = &alarm {
        print_alarm(a, it.file_name(a.src.file));
    }
    // Retained variables survive an alarm as on the control.
    if let Some(dir) = &c.state {
        if let Err(e) = kerf_interp::state::save_retained(dir, &it)
            .and_then(|_| kerf_interp::state::save_offsets(dir, &it))
        {
            return usage_error(format!("--state {}: {e}", dir.display()));
        }
    }
    if let Some(path) = report_path {
        let r = rep.finish(&it, &planner, alarm.as_ref());
        let text = serde_json::to_string_pretty(&r).expect("report serialises");
        if let Err(e) = std::fs::write(&path, text + "\n") {
            return usage_error(format!("{}: {e}", path.display()));
        }
    }
    if let (Some(p), Some(path)) = (plotter, plot_path) {
        if let Err(e) = std::fs::write(&path, p.svg()) {
            return usage_error(format!("{}: {e}", path.display()));
        }
    }
    if alarm.is_none() {
        let mut out = std::io::stdout().lock();
        if check {
            let _ = writeln!(out, "{name}: ok ({} blocks)", it.blocks());
        } else if sinks {
            let _ = writeln!(
                out,
                "{name}: completed ({} blocks, cycle time {:.1} s)",
                it.blocks(),
                planner.now()
            );
        } else {
            let _ = writeln!(out, "{name}: completed ({} blocks)", it.blocks());
        }
    }
    if alarm.is_some() {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    }
}

/// `FILE:LINE:COL: alarm CODE: MESSAGE`, the source line, a caret.
fn print_alarm(a: &Alarm, file: &str) {
    let mut err = std::io::stderr().lock();
    let _ = writeln!(
        err,
        "{}:{}:{}: alarm {}: {}",
        file, a.src.line, a.src.col, a.code, a.message
    );
    if let Some(line) = source_line(file, a.src.line) {
        let shown: String = line
            .chars()
            .map(|c| if c == '\t' { ' ' } else { c })
            .collect();
        let _ = writeln!(err, "  {shown}");
        let col = (a.src.col as usize).saturating_sub(1).min(shown.len());
        let _ = writeln!(err, "  {}^", " ".repeat(col));
    }
}

fn source_line(file: &str, line: u32) -> Option<String> {
    use std::io::{BufRead, Read};
    let f = File::open(file).ok()?;
    let mut r = std::io::BufReader::new(f);
    let mut buf = Vec::new();
    for n in 1..=line {
        buf.clear();
        // Bound what one line may cost: read at most 4 KiB of it.
        let got = (&mut r).take(4096).read_until(b'\n', &mut buf).ok()?;
        if got == 0 {
            return None;
        }
        if n == line {
            let s = String::from_utf8_lossy(&buf);
            return Some(s.trim_end_matches(['\n', '\r']).to_string());
        }
        if buf.last() != Some(&b'\n') {
            // The rest of an over-long line.
            let mut sink = Vec::new();
            r.read_until(b'\n', &mut sink).ok()?;
        }
    }
    None
}
