//! `Runner::run` (the interpreter on a thread of its own, the planner and
//! the sinks on the caller's) hands the sinks exactly what stepping the
//! runner does: the same events with the same start points, the same
//! timed records and pieces, the same file names, the same warnings, the
//! same alarm at the same place, the same sink error after the same
//! calls. Each program is longer than a few batches of events.

use std::io;
use std::path::PathBuf;

use kerf_canon::{Alarm, Event, Pos};
use kerf_control::{Context, Job, Live, Outcome, Progress, RunError, Runner, Sink, Timed};
use kerf_motion::Piece;

/// A timed record as received: event, from, to, end time, time, feed,
/// file name.
type Record = (Event, Pos, Pos, f64, f64, Option<f64>, String);

/// Every call a sink receives, with the file names it was given.
#[derive(Default, Debug, PartialEq)]
struct Recorder {
    pieces_wanted: bool,
    events: Vec<(Event, Pos, String)>,
    timed: Vec<Record>,
    pieces: Vec<Piece>,
    warnings_seen: usize,
    finished: Option<Option<String>>,
    /// Fail at the N-th timed record (counting from 1).
    fail_at: Option<usize>,
}

impl Sink for Recorder {
    fn name(&self) -> &str {
        "recorder"
    }
    fn wants_pieces(&self) -> bool {
        self.pieces_wanted
    }
    fn event(&mut self, e: &Event, from: &Pos, cx: &Live) -> io::Result<()> {
        self.warnings_seen = self.warnings_seen.max(cx.warnings.len());
        let file = cx.file(e.src.file).to_string();
        self.events.push((e.clone(), *from, file));
        Ok(())
    }
    fn timed(&mut self, t: &Timed, cx: &Live) -> io::Result<()> {
        if Some(self.timed.len() + 1) == self.fail_at {
            return Err(io::Error::other("disk full"));
        }
        let file = cx.file(t.event.src.file).to_string();
        self.timed.push((
            t.event.clone(),
            t.from,
            t.to,
            t.t_end,
            t.time,
            t.feed_mm_min,
            file,
        ));
        Ok(())
    }
    fn pieces(&mut self, batch: &[Piece], _cx: &Live) -> io::Result<()> {
        self.pieces.extend_from_slice(batch);
        Ok(())
    }
    fn finish(&mut self, _cx: &Context, alarm: Option<&Alarm>) -> io::Result<()> {
        self.finished = Some(alarm.map(|a| a.code.clone()));
        Ok(())
    }
}

/// `n` short cutting moves back and forth on the HX, then `tail`.
fn program(n: usize, tail: &str) -> String {
    let mut p = String::from("G90 G54 G17 G21\nG0 X0. Y0. Z5.\nM3 S8000\nG1 Z-1. F1200.\n");
    for i in 0..n {
        let x = (i % 50) as f64 * 0.5;
        let y = (i / 50) as f64 * 0.25;
        p.push_str(&format!("X{x:.1} Y{y:.2}\n"));
    }
    p.push_str(tail);
    p
}

/// The outcome's fields that say how the run went.
fn summary(o: &Outcome) -> String {
    format!(
        "{:?} {} {} {:?} {} {:?} {}",
        o.alarm.as_ref().map(|a| (&a.code, a.src.line, a.src.col)),
        o.alarm_file,
        o.blocks,
        o.cycle_time.map(f64::to_bits),
        o.stalled,
        o.warnings,
        o.warnings_dropped
    )
}

/// Runs `load()` once by stepping and once with `run`; the recorders
/// start as `rec`. Returns both results and both recorders.
fn both(
    load: impl Fn() -> Runner,
    rec: impl Fn() -> Recorder,
) -> [(Result<String, String>, Recorder); 2] {
    let mut stepped = rec();
    let mut runner = load();
    let r = loop {
        match runner.step(&mut [&mut stepped as &mut dyn Sink]) {
            Ok(Progress::Running) => {}
            Ok(Progress::Ended) => break runner.finish(&mut [&mut stepped as &mut dyn Sink]),
            Err(e) => break Err(e),
        }
    };
    let a = r.map(|o| summary(&o)).map_err(|e: RunError| e.to_string());
    let mut threaded = rec();
    let b = load()
        .run(&mut [&mut threaded as &mut dyn Sink])
        .map(|o| summary(&o))
        .map_err(|e| e.to_string());
    [(a, stepped), (b, threaded)]
}

#[test]
fn a_long_program_is_handed_out_the_same() {
    let text = program(3000, "G0 Z5.\nM30\n");
    let [(a, ra), (b, rb)] = both(
        || Job::text("long.nc", text.as_str()).load().unwrap(),
        || Recorder {
            pieces_wanted: true,
            ..Recorder::default()
        },
    );
    assert!(a.is_ok(), "{a:?}");
    assert_eq!(a, b);
    // The rapid, the plunge, 3000 cuts and the rapid up.
    assert_eq!(ra.timed.len(), 1 + 1 + 3000 + 1);
    assert!(!ra.pieces.is_empty());
    assert_eq!(ra, rb);
}

#[test]
fn an_alarm_midway_stops_both_at_the_same_block() {
    // G2 without a radius or centre: an alarm after 2000 moves.
    let text = program(2000, "G2 X10. Y0 F100.\nG1 X5.\nM30\n");
    let [(a, ra), (b, rb)] = both(
        || Job::text("alarm.nc", text.as_str()).load().unwrap(),
        Recorder::default,
    );
    let a = a.unwrap();
    assert!(a.contains(", 2005, "), "the alarm on line 2005: {a}");
    assert_eq!(Ok(a), b);
    assert!(ra.finished.as_ref().unwrap().is_some());
    assert_eq!(ra, rb);
}

#[test]
fn a_failing_sink_stops_both_after_the_same_calls() {
    // The 1500th record fails: the interpreter's thread is batches ahead.
    let text = program(3000, "M30\n");
    let [(a, ra), (b, rb)] = both(
        || Job::text("fail.nc", text.as_str()).load().unwrap(),
        || Recorder {
            fail_at: Some(1500),
            ..Recorder::default()
        },
    );
    assert_eq!(a, Err("recorder: disk full".to_string()));
    assert_eq!(a, b);
    assert_eq!(ra.timed.len(), 1499);
    assert_eq!(ra.finished, None, "no finish after an error");
    assert_eq!(ra, rb);
}

#[test]
fn file_names_and_warnings_of_a_subprogram_arrive_with_its_events() {
    // A library subprogram called 600 times (several batches of events
    // from each file); it ends the main program without M30 (KERF-W005).
    let dir = tempdir("kerf-threaded-run");
    std::fs::write(dir.join("O1000.nc"), "O1000\nG91 G1 X0.1 F600.\nG90\nM99\n").unwrap();
    let text = "G90 G54 G21\nG0 X0. Y0.\nM3 S1000\nM98 P1000 L600\nG0 X0.\n";
    let [(a, ra), (b, rb)] = both(
        || Job::text("main.nc", text).lib(&dir).load().unwrap(),
        Recorder::default,
    );
    let a = a.unwrap();
    assert!(a.contains("KERF-W005"), "{a}");
    assert_eq!(Ok(a), b);
    let files: Vec<&str> = ra.timed.iter().map(|t| t.6.as_str()).collect();
    assert_eq!(
        files.iter().filter(|f| f.ends_with("O1000.nc")).count(),
        600
    );
    assert_eq!(files.first(), Some(&"main.nc"));
    assert_eq!(ra, rb);
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn interpret_only_runs_the_same() {
    let text = program(1500, "M30\n");
    let load = || {
        let mut r = Job::text("p.nc", text.as_str()).load().unwrap();
        r.interpret_only();
        r
    };
    let [(a, ra), (b, rb)] = both(load, Recorder::default);
    assert!(
        a.as_ref().unwrap().contains(" None "),
        "no cycle time: {a:?}"
    );
    assert_eq!(a, b);
    assert!(ra.timed.is_empty());
    assert_eq!(ra, rb);
}

fn tempdir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("{name}-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}
