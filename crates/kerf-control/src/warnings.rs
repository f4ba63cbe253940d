//! Warnings: what a real control accepts but is most likely a mistake.
//! Each is a [`Warning`] with a code, a message and the source position
//! (docs/alarms.md "Warnings"). The [`Detector`] watches the event stream
//! and the planner while the runner runs; the decimal-point check reads
//! the program text ([`crate::lint`]).
//!
//! | code | what |
//! | --- | --- |
//! | `KERF-W001` | a dimension word without a decimal point in a program that otherwise writes them |
//! | `KERF-W002` | a lathe-style program (feeds below 1 mm/min, constant surface speed) on a mill profile |
//! | `KERF-W003` | an empty program |
//! | `KERF-W004` | a per-revolution feed or thread with the spindle stopped (timed as 0 s) |
//! | `KERF-W005` | a program that ends without M02/M30 |
//! | `KERF-W006` | a main program that ends in M99 (a bar-feed loop): kerf ran `main_passes` passes, the control repeats until reset |

use kerf_canon::{Axis, Canon, Event, Feed, Pos, SrcRef};
use kerf_interp::{Interp, MachineKind, Profile};

use crate::sink::Files;

/// Most warnings kept in one run; the rest are counted.
pub const MAX_WARNINGS: usize = 1000;

/// One warning with its source position.
#[derive(Clone, Debug, PartialEq)]
pub struct Warning {
    /// `KERF-W001` …
    pub code: &'static str,
    /// What was seen and what to do.
    pub message: String,
    /// The file, as alarms name it.
    pub file: String,
    /// 1-based line.
    pub line: u32,
    /// 1-based column (0 when the warning is about the whole file).
    pub col: u32,
}

/// The warnings of a run, in the order found, at most [`MAX_WARNINGS`].
#[derive(Clone, Debug, Default)]
pub struct Warnings {
    /// The warnings kept.
    pub list: Vec<Warning>,
    /// How many more were found and not kept.
    pub dropped: u64,
}

impl Warnings {
    /// Adds a warning (counted only once the list is full).
    pub fn push(&mut self, w: Warning) {
        if self.list.len() < MAX_WARNINGS {
            self.list.push(w);
        } else {
            self.dropped += 1;
        }
    }

    fn at(&mut self, files: Files, src: SrcRef, code: &'static str, message: String) {
        self.push(Warning {
            code,
            message,
            file: files.name(src.file).to_string(),
            line: src.line,
            col: src.col,
        });
    }
}

/// Watches a run for the warnings the event stream and the planner show.
#[derive(Debug, Default)]
pub struct Detector {
    events: u64,
    /// Inside a stretch of cutting moves the planner could not time.
    stalled: bool,
    /// The code of the last `End` event (0: end of text or `%`).
    end: Option<(u32, SrcRef)>,
    /// First sign of a lathe program on a mill: where and why.
    lathe: Option<(SrcRef, String)>,
}

impl Detector {
    /// Looks at one event; `from` is the work position before it,
    /// `stalled` says whether the planner could not time it (a cut with
    /// no feed because the spindle is stopped); `files` names the file
    /// the event points into.
    pub fn event(
        &mut self,
        e: &Event,
        from: &Pos,
        stalled: bool,
        profile: &Profile,
        files: Files,
        out: &mut Warnings,
    ) {
        self.events += 1;
        if stalled && !self.stalled {
            out.at(
                files,
                e.src,
                "KERF-W004",
                "cutting with the spindle stopped (a per-revolution feed or a thread \
                 with no spindle speed): the control would wait here; timed as 0 s"
                    .into(),
            );
        }
        if e.motion().is_some() {
            self.stalled = stalled;
        }
        if let Canon::End { code } = e.cmd {
            self.end = Some((code, e.src));
        }
        if self.lathe.is_none() && profile.kind == MachineKind::Mill {
            self.lathe = lathe_sign(e, || turns_rotary(from, e)).map(|why| (e.src, why));
        }
    }

    /// At the end of a run that was not stopped by an alarm.
    pub fn end(&mut self, it: &Interp, alarm: bool, out: &mut Warnings) {
        if let Some((src, why)) = self.lathe.take() {
            let p = it.profile();
            out.at(
                Files::Interp(it),
                src,
                "KERF-W002",
                format!(
                    "this looks like a lathe program ({why}) but the machine is the mill {}: \
                     choose the lathe with --machine puma-lathe or --machine hurco-lathe",
                    p.name
                ),
            );
        }
        if alarm {
            return;
        }
        if it.blocks() == 0 && self.events <= 1 {
            out.push(Warning {
                code: "KERF-W003",
                message: "empty program: no blocks to run".into(),
                file: it.file_name(0).to_string(),
                line: 1,
                col: 0,
            });
            return;
        }
        match self.end {
            Some((2 | 30, _)) => {}
            Some((99, src)) => out.at(
                Files::Interp(it),
                src,
                "KERF-W006",
                "the main program ends in M99: the control repeats it until reset; kerf ran the passes of --set main_passes (default 1)".into(),
            ),
            Some((_, src)) => out.at(
                Files::Interp(it),
                src,
                "KERF-W005",
                "the program ends without M02 or M30".into(),
            ),
            None => {}
        }
    }
}

/// Whether motion `e` from work position `from` turns a rotary axis.
fn turns_rotary(from: &Pos, e: &Event) -> bool {
    e.motion().is_some_and(|m| {
        [Axis::A, Axis::B, Axis::C]
            .iter()
            .any(|&a| from[a as usize] != m.to[a as usize])
    })
}

/// Why an event looks like it was written for a lathe, if it does.
/// `turns` says whether the move turns a rotary axis (asked only of a
/// slow feed): its F is then a
/// rate of the combined move in degrees and mm (the feeds of a G112 or
/// G107 program written out as plain X and C moves, `kerf expand`'s
/// output, fall below 1 where a chord is mostly rotation), no sign of a
/// lathe's feed per revolution.
fn lathe_sign(e: &Event, turns: impl Fn() -> bool) -> Option<String> {
    match &e.cmd {
        Canon::Feed {
            feed: Feed::PerMin(v),
            ..
        }
        | Canon::Arc {
            feed: Feed::PerMin(v),
            ..
        } if *v > 0.0 && *v < 1.0 && !turns() => Some(format!(
            "F{v} is {v} mm/min here: a lathe's feed per revolution?"
        )),
        Canon::Spindle { css: Some(v), .. } => Some(format!("constant surface speed G96 S{v}")),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use kerf_canon::Motion;

    fn feed(x: f64, c: f64, f: f64, line: u32) -> Event {
        let mut to = [0.0; 6];
        to[Axis::X as usize] = x;
        to[Axis::C as usize] = c;
        Event {
            src: SrcRef {
                file: 0,
                line,
                col: 1,
            },
            tool: 1,
            cmd: Canon::Feed {
                m: Motion { to, mto: to },
                feed: Feed::PerMin(f),
            },
            prog: None,
        }
    }

    /// The line of the lathe sign found in `events` on the HX, if any.
    fn lathe_line(events: &[Event]) -> Option<u32> {
        let p = Profile::builtin("hx-mc").unwrap();
        let names = ["t.nc".to_string()];
        let (mut d, mut out) = (Detector::default(), Warnings::default());
        // The run starts at the work origin.
        let mut from = [0.0; 6];
        for e in events {
            d.event(e, &from, false, &p, Files::Names(&names), &mut out);
            from = e.motion().unwrap().to;
        }
        d.lathe.map(|(src, _)| src.line)
    }

    #[test]
    fn a_slow_feed_of_x_and_z_alone_is_a_lathe_sign() {
        // 001 p.9: G01 X150. Z100. F0.2, mm/rev on the lathe.
        assert_eq!(
            lathe_line(&[feed(0.0, 0.0, 500.0, 1), feed(150.0, 0.0, 0.2, 2)]),
            Some(2)
        );
        // The first motion too.
        assert_eq!(lathe_line(&[feed(150.0, 0.0, 0.2, 1)]), Some(1));
        // The first motion turning C from the origin is not.
        assert_eq!(lathe_line(&[feed(150.0, 0.9, 0.2, 1)]), None);
    }

    #[test]
    fn a_slow_feed_that_turns_c_is_not() {
        // `kerf expand` of 000 §4.6's G112 example: the first chord of
        // "C10." from X20 C0 is X20.002 C0.895 at F0.64, a rate of the
        // combined move, as the expanded program's line 7 writes it.
        let evs = [feed(20.0, 0.0, 100.0, 6), feed(20.002, 0.895, 0.64, 7)];
        assert_eq!(lathe_line(&evs), None);
        // A later slow feed without rotation is still found.
        let more = [evs[0].clone(), evs[1].clone(), feed(30.0, 0.895, 0.5, 8)];
        assert_eq!(lathe_line(&more), Some(8));
    }
}
