//! [`ToolpathBehind`]: the [`Toolpath`] sink with its formatting and its
//! writes on a thread of its own ([`Behind`]), so that a run with
//! `--toolpath` uses both cores: the interpreter and the planner on the
//! caller's thread, the JSON text (about 2,000 instructions a record, half
//! the interpreter's block) and the system calls on the other.
//!
//! The caller's side copies what each timed record's line shows (a
//! [`Rec`]: the end points, time, feed and the few numbers of its kind,
//! not the whole event) into the batch; nothing is allocated per record
//! but a compensated move's boxed programmed end point. A file name is sent
//! once, before its first record. The records are the same bytes, in the
//! same order, as [`Toolpath`] writes on its own.

use std::io::{self, Write};

use super::behind::{Behind, Named};
use super::toolpath::Toolpath;
use super::toolpath_rec::Rec;
use crate::sink::{Context, Live, Sink, Timed};

/// What the thread is handed. Nearly every item is the large variant, so
/// it is kept inline: a box would be an allocation per item.
#[allow(clippy::large_enum_variant)]
enum Item {
    /// A file id and its name, before the file's first record.
    Name(u32, String),
    /// One timed record.
    Rec(Rec),
}

fn take<W: Write>(tp: &mut Toolpath<W>, item: &mut Item) -> io::Result<()> {
    match item {
        Item::Name(id, name) => {
            tp.name_file(*id, name);
            Ok(())
        }
        Item::Rec(r) => tp.write_named(r),
    }
}

/// A toolpath written by a thread of its own; see the module
/// documentation.
pub struct ToolpathBehind<W: Write + Send + 'static> {
    /// The sink until `start` moves it to the thread.
    idle: Option<Toolpath<W>>,
    behind: Option<Behind<Item, ()>>,
    named: Named,
    /// The file of the last record (its name has been sent).
    last_file: u32,
}

impl<W: Write + Send + 'static> ToolpathBehind<W> {
    /// Formats and writes `tp`'s records on a thread started by
    /// [`Sink::start`].
    pub fn new(tp: Toolpath<W>) -> ToolpathBehind<W> {
        ToolpathBehind {
            idle: Some(tp),
            behind: None,
            named: Named::default(),
            last_file: u32::MAX,
        }
    }
}

impl<W: Write + Send + 'static> Sink for ToolpathBehind<W> {
    fn name(&self) -> &str {
        "toolpath"
    }

    fn start(&mut self, cx: &Context) -> io::Result<()> {
        let Some(mut tp) = self.idle.take() else {
            return Ok(());
        };
        tp.start(cx)?;
        self.behind = Some(Behind::spawn(tp, take, |mut tp| tp.flush()));
        Ok(())
    }

    fn timed(&mut self, t: &Timed, cx: &Live) -> io::Result<()> {
        let Some(b) = self.behind.as_mut() else {
            return Err(io::Error::other("the toolpath was not started"));
        };
        let id = t.event.src.file;
        if id != self.last_file {
            self.last_file = id;
            if self.named.first(id) {
                b.push(Item::Name(id, cx.file(id).to_string()))?;
            }
        }
        match Rec::of(t.event, &t.to, t.t_end, t.feed_mm_min) {
            Some(r) => b.push(Item::Rec(r)),
            None => Ok(()),
        }
    }

    fn finish(&mut self, _cx: &Context, _alarm: Option<&kerf_canon::Alarm>) -> io::Result<()> {
        match self.behind.take() {
            Some(b) => b.finish(),
            None => Ok(()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sinks::behind::{BATCH, IN_FLIGHT};

    use kerf_canon::{Canon, Event, Motion, SrcRef};
    use kerf_interp::{Interp, Profile, Settings};
    use kerf_motion::{Dynamics, Planner};

    use crate::sinks::behind::SharedBuf as Shared;

    /// Fails every write.
    struct Broken;

    impl Write for Broken {
        fn write(&mut self, _: &[u8]) -> io::Result<usize> {
            Err(io::Error::other("disk full"))
        }
        fn flush(&mut self) -> io::Result<()> {
            Ok(())
        }
    }

    fn feed(i: usize) -> Event {
        let mut to = [0.0; kerf_canon::NAXES];
        to[0] = i as f64 * 0.125;
        to[2] = -(i as f64) / 3.0;
        Event {
            src: SrcRef {
                file: 0,
                line: i as u32 + 1,
                col: 1,
            },
            tool: 1,
            cmd: Canon::Rapid {
                m: Motion { to, mto: to },
                linear: false,
            },
            prog: i.is_multiple_of(7).then(|| Box::new(to)),
        }
    }

    /// Feeds `n` records to `sink` as the runner would.
    fn run(sink: &mut dyn Sink, n: usize) -> io::Result<()> {
        let it = Interp::new(Profile::builtin("hx-mc").unwrap(), Settings::default());
        let d = Dynamics::uniform(
            [true; kerf_canon::NAXES],
            10_000.0,
            1_000.0,
            10_000.0,
            5_000.0,
        );
        let planner = Planner::new(d, [0.0; kerf_canon::NAXES], 0.0);
        let cx = Context {
            interp: &it,
            planner: &planner,
            warnings: &[],
        };
        sink.start(&cx)?;
        for i in 0..n {
            let e = feed(i);
            let to = e.motion().unwrap().to;
            let t = Timed {
                event: &e,
                from: to,
                to,
                t_end: i as f64 * 0.01,
                time: 0.01,
                feed_mm_min: None,
            };
            sink.timed(&t, &cx.live())?;
        }
        sink.finish(&cx, None)
    }

    #[test]
    fn the_same_bytes_as_the_toolpath_on_its_own() {
        // More than two batches in flight, and a last one part full.
        let n = BATCH * (IN_FLIGHT + 2) + 17;
        let (a, b) = (Shared::default(), Shared::default());
        run(&mut Toolpath::new(a.clone()), n).unwrap();
        run(&mut ToolpathBehind::new(Toolpath::new(b.clone())), n).unwrap();
        let (a, b) = (a.0.lock().unwrap(), b.0.lock().unwrap());
        assert_eq!(a.iter().filter(|c| **c == b'\n').count(), n);
        assert!(*a == *b, "the records differ");
    }

    #[test]
    fn a_write_error_is_returned() {
        let e = run(&mut ToolpathBehind::new(Toolpath::new(Broken)), BATCH * 4).unwrap_err();
        assert_eq!(e.to_string(), "disk full");
    }
}
