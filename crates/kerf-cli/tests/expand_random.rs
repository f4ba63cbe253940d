//! The expansion round trip on generated programs (tests/common/generate.rs):
//! HX programs with moves in G90 and G91, R arcs in the three planes,
//! rotation (G68), scaling (G51), local coordinates (G52), two work offsets,
//! tool length compensation, macro variables, dwells and the spindle; PUMA
//! programs with diameter X, U/W, R arcs, G32, G90 cycles, G96/G97, tool
//! offsets; in random order from fixed seeds.
//! For each, the toolpath of the program and the toolpath of its `--to
//! fanuc` expansion run again are the same record for record (as
//! tests/expand.rs compares them); a program that stops on an alarm must
//! expand up to it. Everything runs in-process through kerf-control.

mod common;

use common::generate::{hurco_program, lathe_program, program, PROGRAMS};
use common::records::differs;
use kerf_canon::Alarm;
use kerf_control::sinks::{Expand, Toolpath};
use kerf_control::{Job, Sink};
use kerf_expand::Target;
use serde_json::Value;

/// The toolpath records and the alarm of a run of `text`.
fn run(machine: &str, name: &str, text: &str) -> (Vec<Value>, Option<Alarm>) {
    let runner = Job::text(name, text).machine(machine).load().unwrap();
    let mut out = Vec::new();
    let mut tp = Toolpath::new(&mut out);
    let outcome = runner.run(&mut [&mut tp as &mut dyn Sink]).unwrap();
    drop(tp);
    let records = String::from_utf8(out)
        .unwrap()
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    (records, outcome.alarm)
}

/// The `--to fanuc` expansion of `text` and the alarm it stopped on.
fn expand(machine: &str, name: &str, text: &str) -> (String, Option<Alarm>) {
    let mut runner = Job::text(name, text).machine(machine).load().unwrap();
    runner.interpret_only();
    let mut out = Vec::new();
    let mut sink = Expand::new(&mut out, Target::Fanuc);
    let outcome = runner.run(&mut [&mut sink as &mut dyn Sink]).unwrap();
    drop(sink);
    (String::from_utf8(out).unwrap(), outcome.alarm)
}

/// Round-trips the programs `make` generates on `machine`; returns
/// (programs completed, records compared, failures).
fn round_trips(machine: &str, make: fn(u64) -> String) -> (usize, usize, Vec<String>) {
    let (mut completed, mut records, mut failures) = (0, 0, Vec::new());
    for seed in 0..PROGRAMS {
        let text = make(seed);
        let (want, alarm) = run(machine, "gen.nc", &text);
        let (nc, alarm2) = expand(machine, "gen.nc", &text);
        let key = |a: &Option<Alarm>| a.as_ref().map(|a| (a.code.clone(), a.src.line));
        if key(&alarm) != key(&alarm2) {
            failures.push(format!(
                "seed {seed}: run alarm {alarm:?}, expand alarm {alarm2:?}"
            ));
            continue;
        }
        completed += alarm.is_none() as usize;
        let (got, again) = run(machine, "expanded.nc", &nc);
        if let Some(a) = again {
            failures.push(format!("seed {seed}: the expansion alarms {a:?}\n{nc}"));
            continue;
        }
        records += want.len();
        if want.len() != got.len() {
            failures.push(format!(
                "seed {seed}: {} records vs {}\n{text}",
                want.len(),
                got.len()
            ));
            continue;
        }
        if let Some((i, d)) = want
            .iter()
            .zip(&got)
            .enumerate()
            .find_map(|(i, (a, b))| differs(a, b).map(|d| (i, d)))
        {
            failures.push(format!(
                "seed {seed}: record {i} (line {}): {d}\n{text}",
                want[i]["line"]
            ));
        }
    }
    (completed, records, failures)
}

#[test]
fn generated_mill_programs_expand_to_the_same_motions() {
    let (completed, records, failures) = round_trips("hx-mc", program);
    println!("{PROGRAMS} programs, {completed} completed, {records} records compared");
    assert!(failures.is_empty(), "{}", failures.join("\n\n"));
    assert!(
        completed * 2 >= PROGRAMS as usize,
        "only {completed} programs completed"
    );
}

#[test]
fn generated_lathe_programs_expand_to_the_same_motions() {
    let (completed, records, failures) = round_trips("puma-lathe", lathe_program);
    println!("{PROGRAMS} programs, {completed} completed, {records} records compared");
    assert!(failures.is_empty(), "{}", failures.join("\n\n"));
    assert!(
        completed * 2 >= PROGRAMS as usize,
        "only {completed} programs completed"
    );
}

#[test]
fn generated_hurco_programs_expand_to_the_same_motions() {
    let (completed, records, failures) = round_trips("hurco-lathe", hurco_program);
    println!("{PROGRAMS} programs, {completed} completed, {records} records compared");
    assert!(failures.is_empty(), "{}", failures.join("\n\n"));
    assert!(
        completed * 2 >= PROGRAMS as usize,
        "only {completed} programs completed"
    );
}
