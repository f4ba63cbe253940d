//! The expansion round trip on generated HX programs: moves in G90 and
//! G91, R arcs in the three planes, rotation (G68), scaling (G51), local
//! coordinates (G52), two work offsets, tool length compensation, macro
//! variables, dwells and the spindle, in random order from fixed seeds.
//! For each, the toolpath of the program and the toolpath of its `--to
//! fanuc` expansion run again are the same record for record (as
//! tests/expand.rs compares them); a program that stops on an alarm must
//! expand up to it. Everything runs in-process through kerf-control.

mod common;

use common::generate::{program, PROGRAMS};
use common::records::differs;
use kerf_canon::Alarm;
use kerf_control::sinks::{Expand, Toolpath};
use kerf_control::{Job, Sink};
use kerf_expand::Target;
use serde_json::Value;

/// The toolpath records and the alarm of a run of `text`.
fn run(name: &str, text: &str) -> (Vec<Value>, Option<Alarm>) {
    let runner = Job::text(name, text).machine("hx-mc").load().unwrap();
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
fn expand(name: &str, text: &str) -> (String, Option<Alarm>) {
    let mut runner = Job::text(name, text).machine("hx-mc").load().unwrap();
    runner.interpret_only();
    let mut out = Vec::new();
    let mut sink = Expand::new(&mut out, Target::Fanuc);
    let outcome = runner.run(&mut [&mut sink as &mut dyn Sink]).unwrap();
    drop(sink);
    (String::from_utf8(out).unwrap(), outcome.alarm)
}

#[test]
fn generated_programs_expand_to_the_same_motions() {
    let (mut completed, mut records, mut failures) = (0, 0, Vec::new());
    for seed in 0..PROGRAMS {
        let text = program(seed);
        let (want, alarm) = run("gen.nc", &text);
        let (nc, alarm2) = expand("gen.nc", &text);
        if alarm.as_ref().map(|a| (&a.code, a.src.line))
            != alarm2.as_ref().map(|a| (&a.code, a.src.line))
        {
            failures.push(format!(
                "seed {seed}: run alarm {alarm:?}, expand alarm {alarm2:?}"
            ));
            continue;
        }
        completed += alarm.is_none() as usize;

        let (got, again) = run("expanded.nc", &nc);
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
    println!("{PROGRAMS} programs, {completed} completed, {records} records compared");
    assert!(failures.is_empty(), "{}", failures.join("\n\n"));
    assert!(
        completed * 2 >= PROGRAMS as usize,
        "only {completed} programs completed"
    );
}
