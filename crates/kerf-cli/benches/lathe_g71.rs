//! G71 roughing benchmark (harness = false): `cargo bench -p kerf-cli --bench lathe_g71`.
//!
//! A program generated in memory runs one G71 type I cycle
//! `KERF_BENCH_G71_CYCLES` times (default 2,000) in a WHILE loop on the
//! puma-lathe: a 200-segment finishing shape (100 straights and 100
//! tapers, Ø20 → Ø80 over 200 mm), Δd 1 mm from Ø84, so each cycle reads
//! and evaluates the 201 shape blocks, cuts 32 levels against the shape and
//! emits about 340 moves. Reports the median over `KERF_BENCH_RUNS` runs
//! (default 3) of cycles/s and the time per cycle; the target is
//! under 1 ms per cycle. Results in docs/benchmarks.md.

use std::hint::black_box;
use std::time::Instant;

use kerf_interp::{Interp, Profile, Settings, Step};

/// The program: `cycles` G71 cycles on a 200-segment shape.
fn program(cycles: u64) -> String {
    let mut p = format!(
        "G97 S500 M03\n#1 = 0\nWHILE [#1 LT {cycles}] DO1\nG00 X84. Z2.\nG71 U1. R0.5\nG71 P100 Q300 U0.4 W0.1 F0.25\nN100 G00 X20.\n"
    );
    let mut x = 20.0;
    for i in 0..200 {
        let z = -(i as f64 + 1.0);
        let n = 101 + i;
        if i % 2 == 0 {
            p.push_str(&format!("N{n} G01 Z{z:.1}\n"));
        } else {
            x += 0.6;
            p.push_str(&format!("N{n} X{x:.1} Z{z:.1}\n"));
        }
    }
    p.push_str("#1 = #1 + 1\nEND1\nM30\n");
    p
}

fn run(text: &str) -> (f64, u64, String) {
    let profile = Profile::builtin("puma-lathe").expect("puma-lathe");
    let t = Instant::now();
    let mut it = Interp::new(profile, Settings::default());
    it.load_main(
        "g71-bench.nc",
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
    (t.elapsed().as_secs_f64(), motions, note)
}

fn main() {
    let cycles: u64 = std::env::var("KERF_BENCH_G71_CYCLES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(2000);
    let runs: usize = std::env::var("KERF_BENCH_RUNS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(3)
        .max(1);
    let text = program(cycles);
    let mut samples: Vec<(f64, u64, String)> = (0..runs).map(|_| run(&text)).collect();
    let all: Vec<String> = samples.iter().map(|s| format!("{:.3}", s.0)).collect();
    samples.sort_by(|a, b| a.0.total_cmp(&b.0));
    let (secs, motions, note) = samples.swap_remove(samples.len() / 2);
    println!(
        "g71     median {secs:>7.3} s  {cycles} cycles  {:>10.0} cycles/s  {:>7.1} µs/cycle  {:>5} motions/cycle  {:>10.0} motions/s  (runs: {})",
        cycles as f64 / secs,
        secs / cycles as f64 * 1e6,
        motions / cycles.max(1),
        motions as f64 / secs,
        all.join(", ")
    );
    if !note.is_empty() {
        println!("        note: {note}");
    }
}
