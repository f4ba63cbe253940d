//! Throughput benchmark (harness = false): `cargo bench -p kerf-cli --bench throughput`.
//!
//! Runs over one large program (default `bench-inputs/surface_1m.nc` at the
//! workspace root, or the file named by `KERF_BENCH_INPUT`):
//!
//! - `parse`: the lexer/parser alone (`LineSource` + `parse_block`);
//! - `interp`: the interpreter through its library API, every canonical
//!   command taken in batches of 512 from `step_into()`, as the runner's
//!   interpreter thread takes them, and dropped (no output sinks);
//! - `interp_ahead`: the same with the main program read ahead
//!   (`Interp::set_read_ahead`: the lines read and scanned on a second
//!   thread), and its ratio to `interp`;
//!
//! - `macro`: a custom-macro program generated in memory (a WHILE loop of
//!   `KERF_BENCH_MACRO_ITERS` inner iterations, default 1 000 000, with
//!   arithmetic and an IF in each and one motion every 10), reporting
//!   executed statements (blocks) per second;
//!
//! - `comp`: cutter radius compensation: the same program in memory with
//!   `G41 D1` (D1 = `KERF_BENCH_COMP_D`, default 0.1 mm: the raster's turn-around arcs have radius 0.25, so a larger offset is an interference alarm on them) inserted after
//!   the first rapid, against the same in-memory text without it
//!   (`plain`); prints the ratio of the two throughputs;
//!
//! each 3 times, printing the median blocks/s and MB/s. Generate the input
//! with `python3 ../shared/bench/gen_programs.py --out bench-inputs` (see
//! docs/benchmarks.md). Optional env: `KERF_BENCH_MACHINE` (default hx-mc),
//! `KERF_BENCH_RUNS` (default 3).

use std::fs::File;
use std::hint::black_box;
use std::path::PathBuf;
use std::time::Instant;

use kerf_interp::{Filled, Interp, Profile, Settings, Step};
use kerf_motion::Planner;

use kerf_control::dynamics;
use kerf_lang::{parse_block, Block, LexOptions, LineSource, RawBlock};

struct Sample {
    secs: f64,
    blocks: u64,
    /// Set when the run stopped before the end of the text (alarm).
    note: String,
}

fn parse_only(path: &PathBuf) -> Sample {
    let f = File::open(path).expect("open input");
    let t = Instant::now();
    let mut src = LineSource::new(Box::new(f), 4096, false);
    let opts = LexOptions::default();
    let mut raw = RawBlock::default();
    let mut block = Block::default();
    let mut blocks = 0u64;
    let mut errors = 0u64;
    let mut words = 0u64;
    while src.next_block(&mut raw).expect("read") {
        blocks += 1;
        match parse_block(&raw.text, &opts, &mut block) {
            Ok(()) => words += block.words.len() as u64,
            Err(_) => errors += 1,
        }
    }
    black_box(words);
    let secs = t.elapsed().as_secs_f64();
    if errors > 0 {
        println!("        ({errors} blocks did not parse; timed all the same)");
    }
    Sample {
        secs,
        blocks,
        note: String::new(),
    }
}

fn interp(path: &PathBuf, machine: &str, ahead: bool) -> Sample {
    let f = File::open(path).expect("open input");
    run_reader(
        Box::new(f),
        &path.display().to_string(),
        machine,
        None,
        ahead,
    )
}

/// The program text with `G41 D1` after its first rapid (a line starting
/// `G00 X`/`G0 X`).
fn with_g41(text: &[u8]) -> Vec<u8> {
    let mut out = Vec::with_capacity(text.len() + 16);
    let mut done = false;
    for line in text.split_inclusive(|&b| b == b'\n') {
        out.extend_from_slice(line);
        if !done && (line.starts_with(b"G00 X") || line.starts_with(b"G0 X")) {
            out.extend_from_slice(b"G41 D1\n");
            done = true;
        }
    }
    out
}

fn run_reader(
    r: Box<dyn kerf_lang::ProgramRead>,
    name: &str,
    machine: &str,
    d1: Option<f64>,
    ahead: bool,
) -> Sample {
    let profile =
        Profile::builtin(machine).unwrap_or_else(|| panic!("no built-in machine {machine}"));
    let t = Instant::now();
    let mut it = Interp::new(profile, Settings::default());
    it.set_read_ahead(ahead);
    if let Some(v) = d1 {
        if let Some(d) = it.offsets_mut().d_mut(1) {
            d.geom = v;
        }
    }
    it.load_main(name, r);
    // Batches of 512 events, as the runner's interpreter thread fills
    // them (`Interp::step_into`).
    let (mut events, mut batch) = (0u64, Vec::with_capacity(512));
    let note = loop {
        let filled = it.step_into(&mut batch, 512);
        events += batch.len() as u64;
        black_box(&batch);
        batch.clear();
        match filled {
            Filled::Room => {}
            Filled::End => break String::new(),
            Filled::Alarm(a) => {
                break format!(
                "STOPPED ON ALARM at line {} col {}: {} (figures cover only the blocks before it)",
                a.src.line, a.src.col, a
            )
            }
        }
    };
    black_box(events);
    let secs = t.elapsed().as_secs_f64();
    Sample {
        secs,
        blocks: it.blocks(),
        note,
    }
}

/// The planner alone: the interpreter's events are collected in chunks of
/// 65 536 and only `Planner::push` (look-ahead, junctions, all limits) and
/// the draining of its finished records are timed. Counts motion events.
fn plan(path: &PathBuf, machine: &str) -> Sample {
    let profile =
        Profile::builtin(machine).unwrap_or_else(|| panic!("no built-in machine {machine}"));
    let d = dynamics::dynamics_of(&profile, 100.0, 100.0, false).expect("profile dynamics");
    let f = File::open(path).expect("open input");
    let mut it = Interp::new(profile, Settings::default());
    it.load_main(&path.display().to_string(), Box::new(f));
    let mut pl = Planner::new(d, it.machine_position(), it.work_position()[0]);
    let mut chunk = Vec::with_capacity(65_536);
    let mut secs = 0.0;
    let mut segments = 0u64;
    let mut done = 0u64;
    let mut note = String::new();
    loop {
        chunk.clear();
        let mut end = false;
        while chunk.len() < 65_536 {
            match it.step() {
                Step::Event(e) => chunk.push(e),
                Step::End => {
                    end = true;
                    break;
                }
                Step::Alarm(a) => {
                    note = format!("STOPPED ON ALARM: {a}");
                    end = true;
                    break;
                }
            }
        }
        let t = Instant::now();
        for e in &chunk {
            if e.motion().is_some() {
                segments += 1;
            }
            pl.push(e);
            while pl.next_done().is_some() {
                done += 1;
            }
        }
        if end {
            pl.finish();
            while pl.next_done().is_some() {
                done += 1;
            }
        }
        secs += t.elapsed().as_secs_f64();
        if end {
            break;
        }
    }
    black_box(done);
    println!(
        "        plan: {segments} motions, cycle time {:.3} s (rapid {:.3}, cutting {:.3}, other {:.3})",
        pl.now(),
        pl.time.rapid,
        pl.time.cutting,
        pl.time.other + pl.time.tool_change + pl.time.dwell
    );
    Sample {
        secs,
        blocks: segments,
        note,
    }
}

/// The macro benchmark program: `iters` inner iterations, 10 per motion.
fn macro_program(iters: u64) -> String {
    let outer = iters.div_ceil(10);
    format!(
        "G90 G54 G01 X0 Y0 Z0 F1000\n\
         #1 = 0\n\
         #3 = 0\n\
         #4 = 0\n\
         WHILE [#1 LT {outer}] DO1\n\
         #2 = 0\n\
         WHILE [#2 LT 10] DO2\n\
         #2 = #2 + 1\n\
         #4 = #4 + #2 * 0.5 - 1\n\
         IF [#4 GT 1000] THEN #4 = 0\n\
         END2\n\
         #1 = #1 + 1\n\
         #3 = 1 - #3\n\
         G01 X#3\n\
         END1\n\
         M30\n"
    )
}

fn macro_run(text: &str) -> Sample {
    let mut profile = Profile::builtin("hx-mc").expect("hx-mc");
    // 10M iterations make 11M backward jumps and 57M repeated blocks:
    // lift the loop guard above them.
    profile.params.insert("max_jumps".into(), 1e12);
    profile.params.insert("max_repeat_blocks".into(), 1e12);
    let t = Instant::now();
    let mut it = Interp::new(profile, Settings::default());
    it.load_main(
        "macro-bench.nc",
        Box::new(std::io::Cursor::new(text.as_bytes().to_vec())),
    );
    let mut motions = 0u64;
    let note = loop {
        match it.step() {
            Step::Event(e) => {
                if e.motion().is_some() {
                    motions += 1;
                }
                black_box(&e);
            }
            Step::End => break String::new(),
            Step::Alarm(a) => break format!("STOPPED ON ALARM: {a}"),
        }
    };
    black_box(motions);
    Sample {
        secs: t.elapsed().as_secs_f64(),
        blocks: it.blocks(),
        note,
    }
}

fn median(mut v: Vec<Sample>) -> Sample {
    v.sort_by(|a, b| a.secs.total_cmp(&b.secs));
    let n = v.len();
    v.swap_remove(n / 2)
}

/// The median run's blocks/s.
fn rate(runs: &[Sample]) -> f64 {
    let mut v: Vec<f64> = runs.iter().map(|s| s.blocks as f64 / s.secs).collect();
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn report(what: &str, runs: Vec<Sample>, bytes: u64) {
    let all: Vec<String> = runs.iter().map(|s| format!("{:.3}", s.secs)).collect();
    let m = median(runs);
    let bps = m.blocks as f64 / m.secs;
    // MB/s only means something when the whole file was read.
    let mbps = if m.note.is_empty() {
        format!("{:>8.1} MB/s", bytes as f64 / 1e6 / m.secs)
    } else {
        "     n/a MB/s".into()
    };
    println!(
        "{what:<12} median {:>7.3} s  {:>10} blocks  {:>12.0} blocks/s  {mbps}   (runs: {})",
        m.secs,
        m.blocks,
        bps,
        all.join(", ")
    );
    if !m.note.is_empty() {
        println!("        note: {}", m.note);
    }
}

fn main() {
    // `cargo bench` passes `--bench`; a filter argument may follow.
    let filter: Option<String> = std::env::args().skip(1).find(|a| !a.starts_with('-'));
    let runs: usize = std::env::var("KERF_BENCH_RUNS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(3)
        .max(1);
    if filter.as_deref().is_none_or(|f| "macro".contains(f)) {
        let iters: u64 = std::env::var("KERF_BENCH_MACRO_ITERS")
            .ok()
            .and_then(|s| s.parse().ok())
            .unwrap_or(1_000_000);
        let text = macro_program(iters);
        let samples: Vec<Sample> = (0..runs).map(|_| macro_run(&text)).collect();
        let all: Vec<String> = samples.iter().map(|s| format!("{:.3}", s.secs)).collect();
        let m = median(samples);
        println!(
            "macro   median {:>7.3} s  {:>10} statements  {:>12.0} statements/s  ({iters} loop iterations; runs: {})",
            m.secs,
            m.blocks,
            m.blocks as f64 / m.secs,
            all.join(", ")
        );
        if !m.note.is_empty() {
            println!("        note: {}", m.note);
        }
        if filter.as_deref() == Some("macro") {
            return;
        }
    }
    let path = match std::env::var_os("KERF_BENCH_INPUT") {
        Some(p) => PathBuf::from(p),
        None => PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../bench-inputs/surface_1m.nc"),
    };
    if !path.is_file() {
        println!("throughput: input {} not found; skipping.", path.display());
        println!("Generate it from the workspace root with:");
        println!("    python3 ../shared/bench/gen_programs.py --out bench-inputs");
        println!("or point KERF_BENCH_INPUT at a program.");
        return;
    }
    let machine = std::env::var("KERF_BENCH_MACHINE").unwrap_or_else(|_| "hx-mc".into());
    let bytes = std::fs::metadata(&path).map(|m| m.len()).unwrap_or(0);
    println!(
        "throughput: {} ({:.1} MB), machine {machine}, median of {runs}",
        path.display(),
        bytes as f64 / 1e6
    );
    let want = |name: &str| filter.as_deref().is_none_or(|f| name.contains(f));
    if want("parse") {
        report(
            "parse",
            (0..runs).map(|_| parse_only(&path)).collect(),
            bytes,
        );
    }
    if want("plan") {
        report(
            "plan",
            (0..runs).map(|_| plan(&path, &machine)).collect(),
            bytes,
        );
    }
    let mut single = None;
    if want("interp") {
        let r: Vec<Sample> = (0..runs).map(|_| interp(&path, &machine, false)).collect();
        single = Some(rate(&r));
        report("interp", r, bytes);
    }
    if want("interp_ahead") {
        let r: Vec<Sample> = (0..runs).map(|_| interp(&path, &machine, true)).collect();
        let ahead = rate(&r);
        report("interp_ahead", r, bytes);
        if let Some(one) = single {
            println!("        read ahead / one thread: {:.2}x", ahead / one);
        }
    }
    if want("comp") {
        let d: f64 = std::env::var("KERF_BENCH_COMP_D")
            .ok()
            .and_then(|s| s.parse().ok())
            .unwrap_or(0.1);
        let plain = std::fs::read(&path).expect("read input");
        let comp = with_g41(&plain);
        let mem = |t: &Vec<u8>, d1: Option<f64>| {
            run_reader(
                Box::new(std::io::Cursor::new(t.clone())),
                "mem",
                &machine,
                d1,
                false,
            )
        };
        let a: Vec<Sample> = (0..runs).map(|_| mem(&plain, None)).collect();
        let b: Vec<Sample> = (0..runs).map(|_| mem(&comp, Some(d))).collect();
        let (ma, mb) = (
            a.iter()
                .map(|s| s.blocks as f64 / s.secs)
                .fold(0.0, f64::max),
            b.iter()
                .map(|s| s.blocks as f64 / s.secs)
                .fold(0.0, f64::max),
        );
        report("plain", a, bytes);
        report("comp", b, bytes);
        println!(
            "comp/plain throughput ratio (best runs): {:.2} (G41 D1 = {d} mm)",
            mb / ma
        );
    }
}
