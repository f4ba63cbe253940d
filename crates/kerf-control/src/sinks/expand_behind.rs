//! [`ExpandBehind`]: the expansion sink ([`super::Expand`]) with kerf-expand's
//! writer on a thread of its own ([`Behind`]), so that `kerf expand`
//! uses both cores: the interpreter on the caller's thread, the G-code
//! text and the writes on the other. The caller's side copies a rapid or
//! feed move into the batch as a small record ([`Item::Move`]: its motion,
//! feed and source line) and any other event whole, boxed; a file name is sent once, before its first
//! event; the alarm that stopped the run is written after the last one.
//! The output is the same bytes as [`super::Expand`] writes on its own.

use std::io::{self, Write};

use kerf_canon::{Alarm, Canon, Event, Feed, Motion, Pos};
use kerf_expand::{Expander, Target};

use super::behind::{Behind, Named};
use super::expand::started;
use crate::sink::{Context, Live, Sink};

/// What the thread is handed. A rapid or feed move (nearly every item)
/// is a small record of what its block needs; any other event goes whole,
/// boxed, so that the item stays small.
enum Item {
    /// A file id and its name, before the file's first event.
    Name(u32, String),
    /// A `Canon::Rapid` (`feed` None) or `Canon::Feed`, from file `file`
    /// line `line`.
    Move {
        file: u32,
        line: u32,
        feed: Option<Feed>,
        m: Motion,
    },
    /// Any other canonical command.
    Event(Box<Event>),
    /// The alarm that stopped the run, after the last event.
    Alarm(Box<Alarm>),
}

impl Item {
    /// The item for `e`.
    #[inline]
    fn of(e: &Event) -> Item {
        match &e.cmd {
            Canon::Rapid { m, .. } => Item::Move {
                file: e.src.file,
                line: e.src.line,
                feed: None,
                m: *m,
            },
            Canon::Feed { m, feed } => Item::Move {
                file: e.src.file,
                line: e.src.line,
                feed: Some(*feed),
                m: *m,
            },
            _ => Item::Event(Box::new(e.clone())),
        }
    }
}

/// The writer and the file names it has been sent.
struct Writer<W: Write> {
    x: Expander<W>,
    names: Vec<String>,
}

impl<W: Write> Writer<W> {
    fn name(&self, id: u32) -> &str {
        self.names.get(id as usize).map_or("", String::as_str)
    }

    fn take(&mut self, item: &mut Item) -> io::Result<()> {
        match item {
            Item::Name(id, name) => {
                let i = *id as usize;
                if self.names.len() <= i {
                    self.names.resize(i + 1, String::new());
                }
                self.names[i] = std::mem::take(name);
                Ok(())
            }
            Item::Move {
                file,
                line,
                feed,
                m,
            } => {
                let Writer { x, names } = self;
                let file = names.get(*file as usize).map_or("", String::as_str);
                x.line_move(m, *feed, file, *line)
            }
            Item::Event(e) => {
                let Writer { x, names } = self;
                let file = names.get(e.src.file as usize).map_or("", String::as_str);
                x.event(e, file)
            }
            Item::Alarm(a) => {
                let file = self.name(a.src.file).to_string();
                self.x.alarm(a, &file)
            }
        }
    }

    /// Output blocks written, after the last flush.
    fn end(self) -> io::Result<u64> {
        let blocks = self.x.blocks();
        self.x.finish().map(|_| blocks)
    }
}

/// Writes the program as plain G-code onto `out`, on a thread of its own.
pub struct ExpandBehind<W: Write + Send + 'static> {
    target: Target,
    out: Option<W>,
    behind: Option<Behind<Item, u64>>,
    named: Named,
    /// The file id of the previous event (its name has been sent).
    last_file: u32,
    blocks: u64,
}

impl<W: Write + Send + 'static> ExpandBehind<W> {
    /// G-code for `target` written onto `out` (the machine's control and
    /// axes are read from the run's profile at the start).
    pub fn new(out: W, target: Target) -> ExpandBehind<W> {
        ExpandBehind {
            target,
            out: Some(out),
            behind: None,
            named: Named::default(),
            last_file: u32::MAX,
            blocks: 0,
        }
    }

    /// Output blocks written (after the run).
    pub fn blocks(&self) -> u64 {
        self.blocks
    }

    /// Sends the name of file `id` if it has not been sent.
    fn name(&mut self, id: u32, name: &str) -> io::Result<()> {
        if !self.named.first(id) {
            return Ok(());
        }
        match self.behind.as_mut() {
            Some(b) => b.push(Item::Name(id, name.to_string())),
            None => Ok(()),
        }
    }
}

impl<W: Write + Send + 'static> Sink for ExpandBehind<W> {
    fn name(&self) -> &str {
        "expand"
    }

    fn start(&mut self, cx: &Context) -> io::Result<()> {
        let Some(out) = self.out.take() else {
            return Ok(());
        };
        let w = Writer {
            x: started(out, self.target, cx)?,
            names: Vec::new(),
        };
        self.behind = Some(Behind::spawn(w, Writer::take, Writer::end));
        Ok(())
    }

    fn event(&mut self, e: &Event, _from: &Pos, cx: &Live) -> io::Result<()> {
        if e.src.file != self.last_file {
            self.last_file = e.src.file;
            self.name(e.src.file, cx.file(e.src.file))?;
        }
        match self.behind.as_mut() {
            Some(b) => b.push(Item::of(e)),
            None => Ok(()),
        }
    }

    fn finish(&mut self, cx: &Context, alarm: Option<&Alarm>) -> io::Result<()> {
        if let Some(a) = alarm {
            self.name(a.src.file, cx.file(a.src.file))?;
            if let Some(b) = self.behind.as_mut() {
                b.push(Item::Alarm(Box::new(a.clone())))?;
            }
        }
        if let Some(b) = self.behind.take() {
            self.blocks = b.finish()?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sinks::Expand;
    use crate::Job;

    use crate::sinks::behind::SharedBuf as Shared;

    /// (text, output blocks, alarm code) through `sink`.
    fn run(text: &str, sink: &mut dyn Sink) -> Option<String> {
        let mut runner = Job::text("part.nc", text).machine("hx-mc").load().unwrap();
        runner.interpret_only();
        runner.run(&mut [sink]).unwrap().alarm.map(|a| a.code)
    }

    #[test]
    fn the_same_text_as_the_expansion_on_its_own() {
        // A macro loop of 3,000 moves (several batches) and a full circle.
        let text = "#1=0\nWHILE[#1LT3000]DO1\nG1 X[#1*0.01] Y[#1MOD7] F500.\n#1=#1+1\nEND1\n\
                    G0 X10. Y0\nG2 I-5.\nM30\n";
        let mut alone = Vec::new();
        let mut sink = Expand::new(&mut alone, Target::Fanuc);
        assert_eq!(run(text, &mut sink), None);
        let blocks = sink.blocks();
        drop(sink);
        let out = Shared::default();
        let mut behind = ExpandBehind::new(out.clone(), Target::Fanuc);
        assert_eq!(run(text, &mut behind), None);
        assert_eq!(behind.blocks(), blocks);
        assert!(blocks > 3000, "{blocks}");
        assert!(*out.0.lock().unwrap() == alone, "the texts differ");
    }

    #[test]
    fn the_alarm_comes_after_the_last_block() {
        // The arc's end is 50.99 mm from the centre, its start 40: F_82112.
        let text = "G0 X0 Y0\nG2 X50. Y50. I40. F100.\nM30\n";
        let mut alone = Vec::new();
        let mut sink = Expand::new(&mut alone, Target::LinuxCnc);
        assert_eq!(run(text, &mut sink).as_deref(), Some("F_82112"));
        drop(sink);
        let out = Shared::default();
        let mut behind = ExpandBehind::new(out.clone(), Target::LinuxCnc);
        assert_eq!(run(text, &mut behind).as_deref(), Some("F_82112"));
        let text = String::from_utf8(out.0.lock().unwrap().clone()).unwrap();
        assert_eq!(text.as_bytes(), &alone[..]);
        assert!(text
            .lines()
            .last()
            .unwrap()
            .starts_with("(ALARM F_82112 part.nc:2"));
    }
}
