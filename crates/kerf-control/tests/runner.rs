//! The runner's contract with its sinks: which calls come, in what order,
//! with what start points, end times and pieces; errors carry the sink's
//! name; interpret-only runs plan nothing.

use std::io;

use kerf_canon::{Alarm, Canon, Event, Pos};
use kerf_control::{Context, Job, Live, Progress, RunError, Sink, Timed};
use kerf_motion::Piece;

/// Records every call a sink receives.
#[derive(Default)]
struct Recorder {
    pieces_wanted: bool,
    starts: usize,
    events: Vec<(Event, Pos)>,
    timed: Vec<(Event, Pos, Pos, f64, Option<f64>)>,
    pieces: Vec<Piece>,
    finished: Option<Option<String>>,
    fail_timed: bool,
}

impl Sink for Recorder {
    fn name(&self) -> &str {
        "recorder"
    }
    fn wants_pieces(&self) -> bool {
        self.pieces_wanted
    }
    fn start(&mut self, _cx: &Context) -> io::Result<()> {
        self.starts += 1;
        Ok(())
    }
    fn event(&mut self, e: &Event, from: &Pos, _cx: &Live) -> io::Result<()> {
        self.events.push((e.clone(), *from));
        Ok(())
    }
    fn timed(&mut self, t: &Timed, _cx: &Live) -> io::Result<()> {
        if self.fail_timed {
            return Err(io::Error::other("disk full"));
        }
        self.timed
            .push((t.event.clone(), t.from, t.to, t.t_end, t.feed_mm_min));
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

const PROGRAM: &str =
    "G90 G54 G17 G21\nG0 X10. Y5.\nM3 S1000\nG1 X20. F600.\nG4 P1000\nY15.\nM30\n";

#[test]
fn every_event_then_every_motion_and_dwell_with_its_end_time() {
    let runner = Job::text("p.nc", PROGRAM).load().unwrap();
    let mut rec = Recorder::default();
    let out = runner.run(&mut [&mut rec as &mut dyn Sink]).unwrap();
    assert!(out.alarm.is_none());
    assert_eq!(rec.starts, 1);
    assert_eq!(rec.finished, Some(None));
    // Rapid, feed X, dwell, feed Y: four records, in program order.
    let kinds: Vec<&str> = rec
        .timed
        .iter()
        .map(|(e, ..)| match e.cmd {
            Canon::Rapid { .. } => "rapid",
            Canon::Feed { .. } => "feed",
            Canon::Dwell { .. } => "dwell",
            _ => "other",
        })
        .collect();
    assert_eq!(kinds, ["rapid", "feed", "dwell", "feed"]);
    // Each record starts where the one before ended; the dwell stands still.
    for w in rec.timed.windows(2) {
        assert_eq!(w[0].2, w[1].1);
    }
    let (_, from, to, _, feed) = &rec.timed[1];
    assert_eq!((from[0], from[1], to[0], to[1]), (10.0, 5.0, 20.0, 5.0));
    assert_eq!(*feed, Some(600.0));
    let dwell = &rec.timed[2];
    assert_eq!(dwell.1, dwell.2);
    // End times grow; the dwell (P1000 = 1 s) lies between the two cuts.
    let t: Vec<f64> = rec.timed.iter().map(|r| r.3).collect();
    assert!(t.windows(2).all(|w| w[0] < w[1]), "{t:?}");
    assert!(t[2] - t[1] >= 1.0 - 1e-9, "{t:?}");
    // 10 mm at 600 mm/min takes at least 1 s.
    assert!(t[1] - t[0] >= 1.0, "{t:?}");
    // The cycle ends no sooner than the last record.
    assert!(out.cycle_time.unwrap() >= t[3] - 1e-9);
    // Every event was seen, motions with the start point before them.
    let motions: Vec<&(Event, Pos)> = rec
        .events
        .iter()
        .filter(|(e, _)| e.motion().is_some())
        .collect();
    assert_eq!(motions.len(), 3);
    assert_eq!((motions[2].1[0], motions[2].1[1]), (20.0, 5.0));
    assert!(rec.pieces.is_empty(), "pieces only when asked for");
}

#[test]
fn pieces_cover_the_planned_time_without_gaps() {
    let runner = Job::text("p.nc", PROGRAM).load().unwrap();
    let mut rec = Recorder {
        pieces_wanted: true,
        ..Recorder::default()
    };
    let out = runner.run(&mut [&mut rec as &mut dyn Sink]).unwrap();
    let mut t = 0.0;
    for p in &rec.pieces {
        assert!((p.t0 - t).abs() < 1e-9, "gap at {t}: piece at {}", p.t0);
        t = p.t0 + p.duration();
    }
    assert!(t > 2.0 && t <= out.cycle_time.unwrap() + 1e-9);
    // The last piece ends on the last point, X20 Y15 in machine
    // coordinates.
    let last = rec.pieces.last().unwrap();
    let end = last.pos_at(last.duration());
    let work_end = rec.timed.last().unwrap().2;
    let shift = out_shift(&rec);
    assert!((end[0] - work_end[0] - shift[0]).abs() < 1e-9);
    assert!((end[1] - work_end[1] - shift[1]).abs() < 1e-9);
}

/// Machine minus work position of the last motion.
fn out_shift(rec: &Recorder) -> [f64; 2] {
    let m = rec
        .events
        .iter()
        .rev()
        .find_map(|(e, _)| e.motion())
        .unwrap();
    [m.mto[0] - m.to[0], m.mto[1] - m.to[1]]
}

#[test]
fn interpret_only_hands_out_events_but_plans_nothing() {
    let mut runner = Job::text("p.nc", PROGRAM).load().unwrap();
    runner.interpret_only();
    let mut rec = Recorder::default();
    let out = runner.run(&mut [&mut rec as &mut dyn Sink]).unwrap();
    assert_eq!(out.cycle_time, None);
    assert!(rec.timed.is_empty());
    assert_eq!(
        rec.events
            .iter()
            .filter(|(e, _)| e.motion().is_some())
            .count(),
        3
    );
    assert_eq!(out.blocks, 7);
}

#[test]
fn a_failing_sink_stops_the_run_with_its_name() {
    let runner = Job::text("p.nc", PROGRAM).load().unwrap();
    let mut rec = Recorder {
        fail_timed: true,
        ..Recorder::default()
    };
    let err = runner.run(&mut [&mut rec as &mut dyn Sink]).unwrap_err();
    assert!(matches!(err, RunError::Sink(..)));
    assert_eq!(err.to_string(), "recorder: disk full");
}

#[test]
fn an_alarm_ends_the_run_and_reaches_finish() {
    // G2 without a radius or centre is an alarm on line 2.
    let mut runner = Job::text("a.nc", "G0 X0 Y0\nG2 X10. Y0 F100.\nM30\n")
        .load()
        .unwrap();
    let mut rec = Recorder::default();
    let mut steps = 0;
    while runner.step(&mut [&mut rec as &mut dyn Sink]).unwrap() == Progress::Running {
        steps += 1;
        assert!(steps < 100);
    }
    let out = runner.finish(&mut [&mut rec as &mut dyn Sink]).unwrap();
    let a = out.alarm.expect("alarm");
    assert_eq!(a.src.line, 2);
    assert_eq!(out.alarm_file, "a.nc");
    assert_eq!(rec.finished, Some(Some(a.code.clone())));
    // The rapid before the alarm was planned and handed out.
    assert_eq!(rec.timed.len(), 1);
}
