//! The toolpath sink: one JSON object per canonical motion (and dwell), in
//! execution order, written when its end time is planned. Format:
//! docs/formats.md.

use std::io::{self, Write};

use kerf_canon::{Axis, Event, Pos, NAXES};

use crate::sink::{Context, Live, Sink, Timed};

/// Writes JSON Lines. The lines are gathered in the sink and handed to
/// the writer in pieces of 1 MiB (so a file needs no `BufWriter`), the
/// rest at `finish` or when the sink is dropped; [`Toolpath::write`]
/// hands its line over at once.
pub struct Toolpath<W: Write> {
    w: W,
    axes: Vec<Axis>,
    /// `,"x":` … per axis (5 bytes each).
    keys: Vec<[u8; 5]>,
    /// `{"file":"NAME","line":` per file id, made on first use.
    heads: Vec<Option<Vec<u8>>>,
    /// The last value of each axis of `to`, `mto`, `prog`, `center`, and
    /// of the feed.
    memo: [[Memo; NAXES]; 4],
    feed_memo: Memo,
    /// The last line number and its text.
    line_memo: LineText,
    /// Lines not yet handed to `w`: they go in pieces of [`PIECE`] bytes
    /// or more (one `write_all` per piece, not per line), and the rest at
    /// [`Toolpath::flush`], at `finish` or when the sink is dropped.
    buf: Vec<u8>,
}

/// Bytes of lines gathered before they are handed to the writer: a
/// file needs no `BufWriter` of its own (which would copy every byte once
/// more).
const PIECE: usize = 1 << 20;

pub use super::number::num;
use super::number::{int, put_fixed, Memo};
use super::toolpath_rec::{Kind, Rec};
use kerf_canon::digits::LineText;

/// `,"KEY":` of the memo rows (to, mto, prog, center), padded to a fixed
/// size with the length used (the object's brace follows).
const KEYS: [([u8; 12], usize); 4] = [
    (*b",\"to\":\0\0\0\0\0\0", 6),
    (*b",\"mto\":\0\0\0\0\0", 7),
    (*b",\"prog\":\0\0\0\0", 8),
    (*b",\"center\":\0\0", 10),
];

/// `{"file":"NAME","line":`
fn head_of(out: &mut Vec<u8>, file: &str) {
    out.extend_from_slice(b"{\"file\":");
    json_str(out, file);
    out.extend_from_slice(b",\"line\":");
}

fn json_str(out: &mut Vec<u8>, s: &str) {
    out.push(b'"');
    for c in s.chars() {
        match c {
            '"' => out.extend_from_slice(b"\\\""),
            '\\' => out.extend_from_slice(b"\\\\"),
            c if (c as u32) < 0x20 => {
                out.extend_from_slice(format!("\\u{:04x}", c as u32).as_bytes())
            }
            c => out.extend_from_slice(c.encode_utf8(&mut [0; 4]).as_bytes()),
        }
    }
    out.push(b'"');
}

impl<W: Write> Toolpath<W> {
    /// A writer onto `w`; the axes are the machine's, taken at the start
    /// of the run.
    pub fn new(w: W) -> Toolpath<W> {
        Toolpath {
            w,
            axes: Vec::new(),
            keys: Vec::new(),
            heads: Vec::new(),
            memo: [[Memo::default(); NAXES]; 4],
            feed_memo: Memo::default(),
            line_memo: LineText::default(),
            buf: Vec::new(),
        }
    }

    /// Hands the gathered lines to the writer.
    fn spill(&mut self) -> io::Result<()> {
        let r = self.w.write_all(&self.buf);
        self.buf.clear();
        r
    }

    /// `,"KEY":{"x":…}`; `slot` picks the memo row (0 to, 1 mto, 2 prog,
    /// 3 center) and its key. Made in a fixed array by copies of fixed
    /// size and appended at once.
    #[inline]
    fn pos(&mut self, slot: usize, p: &Pos) {
        if self.axes.is_empty() {
            return self.pos_slow(slot, p);
        }
        // The key (12), per axis its key (5) and text (24), the brace.
        let mut t = [0u8; 192];
        let (key, len) = &KEYS[slot];
        t[..12].copy_from_slice(key);
        let mut n = *len;
        let memo = &mut self.memo[slot];
        for (i, (a, k)) in self.axes.iter().zip(&self.keys).enumerate() {
            t[n..n + 5].copy_from_slice(k);
            if i == 0 {
                // The first key opens the object where its comma was.
                t[n] = b'{';
            }
            n += 5;
            let Some((text, len)) = memo[i].text(p[*a as usize]) else {
                return self.pos_slow(slot, p);
            };
            t[n..n + 24].copy_from_slice(text);
            n += len;
        }
        t[n] = b'}';
        put_fixed(&mut self.buf, &t, n + 1);
    }

    /// [`Toolpath::pos`] where a value takes `num`'s `{}` path (NaN,
    /// infinite, 1e9 or more), or without axes.
    #[cold]
    #[inline(never)]
    fn pos_slow(&mut self, slot: usize, p: &Pos) {
        let (key, len) = &KEYS[slot];
        put_fixed(&mut self.buf, key, *len);
        self.buf.push(b'{');
        let memo = &mut self.memo[slot];
        for (i, (a, k)) in self.axes.iter().zip(&self.keys).enumerate() {
            let k = if i == 0 { &k[1..] } else { &k[..] };
            self.buf.extend_from_slice(k);
            memo[i].put(&mut self.buf, p[*a as usize]);
        }
        self.buf.push(b'}');
    }

    fn set_axes(&mut self, axes: Vec<Axis>) {
        // Axis names are one letter.
        self.keys = axes
            .iter()
            .map(|a| [b',', b'"', a.name().as_bytes()[0], b'"', b':'])
            .collect();
        self.axes = axes;
    }

    /// Writes the record of one event (non-motion events write nothing).
    /// `here` is the work position after the event; `t` its end time.
    pub fn write(
        &mut self,
        e: &Event,
        file: &str,
        here: &Pos,
        t: f64,
        feed_mm_min: Option<f64>,
    ) -> io::Result<()> {
        let mut head = Vec::new();
        head_of(&mut head, file);
        self.record(e, &head, here, t, feed_mm_min)?;
        self.spill()
    }

    fn record(
        &mut self,
        e: &Event,
        head: &[u8],
        here: &Pos,
        t: f64,
        feed_mm_min: Option<f64>,
    ) -> io::Result<()> {
        match Rec::of(e, here, t, feed_mm_min) {
            Some(r) => self.line(&r, head),
            None => Ok(()),
        }
    }

    /// Writes the line of `r`, `head` its file's `{"file":…,"line":`.
    fn line(&mut self, r: &Rec, head: &[u8]) -> io::Result<()> {
        if self.buf.capacity() == 0 {
            // Room for a piece and the line that fills it, so that the
            // buffer is not grown again.
            self.buf.reserve(PIECE + 16 * 1024);
        }
        self.buf.extend_from_slice(head);
        self.line_memo.put(&mut self.buf, u64::from(r.line));
        let (key, len) = r.kind.key();
        put_fixed(&mut self.buf, key, len);
        self.pos(0, &r.to);
        if r.kind != Kind::Dwell {
            self.pos(1, &r.mto);
            if let Some(p) = r.prog.as_deref() {
                self.pos(2, p);
            }
        }
        match r.kind {
            Kind::Dwell => {
                self.buf.extend_from_slice(b",\"seconds\":");
                num(&mut self.buf, r.main);
                if r.value > 0.0 {
                    self.buf.extend_from_slice(b",\"revolutions\":");
                    num(&mut self.buf, r.value);
                }
            }
            Kind::Arc => {
                self.pos(3, &r.center);
                self.buf.extend_from_slice(b",\"dir\":\"");
                self.buf.extend_from_slice(r.dir.name().as_bytes());
                self.buf.push(b'"');
            }
            _ => {}
        }
        if matches!(r.kind, Kind::Feed | Kind::Arc) {
            self.buf.extend_from_slice(b",\"feed\":");
            self.feed_memo.put(&mut self.buf, r.main);
            if r.per_rev {
                self.buf.extend_from_slice(b",\"feed_per_rev\":");
                num(&mut self.buf, r.value);
            }
        }
        if r.kind == Kind::Thread {
            self.buf.extend_from_slice(b",\"lead\":");
            num(&mut self.buf, r.main);
        }
        self.buf.extend_from_slice(b",\"tool\":");
        int(&mut self.buf, u64::from(r.tool));
        self.buf.extend_from_slice(b",\"t_end\":");
        num(&mut self.buf, r.t_end);
        self.buf.extend_from_slice(b"}\n");
        if self.buf.len() >= PIECE {
            return self.spill();
        }
        Ok(())
    }
}

impl<W: Write> Toolpath<W> {
    /// Names file `id` for [`Toolpath::write_named`].
    pub(crate) fn name_file(&mut self, id: u32, name: &str) {
        let id = id as usize;
        if self.heads.len() <= id {
            self.heads.resize(id + 1, None);
        }
        let mut h = Vec::new();
        head_of(&mut h, name);
        self.heads[id] = Some(h);
    }

    /// The line of a record whose file was named by
    /// [`Toolpath::name_file`] (as [`Sink::timed`] writes it).
    pub(crate) fn write_named(&mut self, r: &Rec) -> io::Result<()> {
        let id = r.file as usize;
        if self.heads.len() <= id {
            self.heads.resize(id + 1, None);
        }
        // An unnamed file (not done by ToolpathBehind) has an empty name.
        let head = self.heads[id].take().unwrap_or_else(|| {
            let mut h = Vec::new();
            head_of(&mut h, "");
            h
        });
        let r = self.line(r, &head);
        self.heads[id] = Some(head);
        r
    }

    /// Hands the gathered lines to the writer and flushes it.
    pub(crate) fn flush(&mut self) -> io::Result<()> {
        self.spill()?;
        self.w.flush()
    }
}

impl<W: Write> Sink for Toolpath<W> {
    fn name(&self) -> &str {
        "toolpath"
    }

    fn start(&mut self, cx: &Context) -> io::Result<()> {
        self.set_axes(super::axes_of(cx.interp.profile()));
        Ok(())
    }

    fn timed(&mut self, t: &Timed, cx: &Live) -> io::Result<()> {
        let id = t.event.src.file as usize;
        if self.heads.len() <= id {
            self.heads.resize(id + 1, None);
        }
        // Taken out and put back so that the record can borrow it while
        // the writer is borrowed mutably.
        let head = match self.heads[id].take() {
            Some(h) => h,
            None => {
                let mut h = Vec::new();
                head_of(&mut h, cx.file(t.event.src.file));
                h
            }
        };
        let r = self.record(t.event, &head, &t.to, t.t_end, t.feed_mm_min);
        self.heads[id] = Some(head);
        r
    }

    fn finish(&mut self, _cx: &Context, _alarm: Option<&kerf_canon::Alarm>) -> io::Result<()> {
        self.flush()
    }
}

impl<W: Write> Drop for Toolpath<W> {
    /// The lines gathered and not yet handed to the writer go to it (a
    /// run stopped by another sink's error has not called `finish`), as
    /// when each line was written at once; an error here is not seen, as
    /// with `BufWriter`.
    fn drop(&mut self) {
        if !self.buf.is_empty() {
            let _ = self.spill();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use kerf_canon::{Canon, Feed, Motion, SrcRef};

    fn line(tp: &mut Toolpath<Vec<u8>>, to: Pos, mto: Pos) -> String {
        let e = Event {
            src: SrcRef {
                file: 0,
                line: 12,
                col: 1,
            },
            tool: 3,
            cmd: Canon::Feed {
                m: Motion { to, mto },
                feed: Feed::PerMin(100.0),
            },
            prog: None,
        };
        tp.w.clear();
        tp.write(&e, "a.nc", &to, 2.5, Some(100.0)).unwrap();
        String::from_utf8(tp.w.clone()).unwrap()
    }

    /// Keeps the bytes and counts the calls that brought them.
    #[derive(Default)]
    struct Calls {
        bytes: Vec<u8>,
        calls: usize,
    }

    impl Write for Calls {
        fn write(&mut self, b: &[u8]) -> io::Result<usize> {
            self.calls += 1;
            self.bytes.extend_from_slice(b);
            Ok(b.len())
        }
        fn flush(&mut self) -> io::Result<()> {
            Ok(())
        }
    }

    #[test]
    fn lines_go_in_pieces_and_the_rest_when_dropped() {
        // 30,000 records of about 170 bytes: some 5 MB, so a few pieces
        // and a part-filled one that only the drop hands over (no
        // `finish`, as when another sink's error stops a run).
        let (mut pieces, mut one_by_one) = (Calls::default(), Calls::default());
        let mut a = Toolpath::new(&mut pieces);
        let mut b = Toolpath::new(&mut one_by_one);
        let mut head = Vec::new();
        head_of(&mut head, "a.nc");
        for tp in [&mut a, &mut b] {
            tp.set_axes(vec![Axis::X, Axis::Y, Axis::Z]);
        }
        for i in 0..30_000u32 {
            let mut to = [0.0; NAXES];
            to[0] = f64::from(i) * 0.125;
            to[2] = -f64::from(i) / 3.0;
            let e = Event {
                src: SrcRef {
                    file: 0,
                    line: i + 1,
                    col: 1,
                },
                tool: 1,
                cmd: Canon::Feed {
                    m: Motion { to, mto: to },
                    feed: Feed::PerMin(600.0),
                },
                prog: None,
            };
            let t = f64::from(i) * 0.01;
            a.record(&e, &head, &to, t, Some(600.0)).unwrap();
            b.write(&e, "a.nc", &to, t, Some(600.0)).unwrap();
        }
        let held = a.buf.len();
        assert!(held > 0 && held < PIECE);
        drop((a, b));
        // Every line one write call when handed over at once.
        assert_eq!(one_by_one.calls, 30_000);
        let total = one_by_one.bytes.len();
        assert!(total > 3 * PIECE, "{total} bytes");
        // Whole pieces of at least PIECE bytes, then the rest.
        assert_eq!(pieces.calls, (total - held) / PIECE + 1);
        assert!(pieces.bytes == one_by_one.bytes, "the bytes differ");
    }

    #[test]
    fn positions_by_the_fixed_array_and_by_the_slow_path() {
        let mut tp = Toolpath::new(Vec::new());
        tp.set_axes(vec![Axis::X, Axis::Y, Axis::Z]);
        let mut to = [0.0; NAXES];
        to[0] = 1.25;
        to[1] = -0.0;
        to[2] = 123_456.000_000_4;
        let mut mto = to;
        mto[0] = -998.75;
        let head = "{\"file\":\"a.nc\",\"line\":12,\"kind\":\"feed\"";
        let tail = ",\"feed\":100.0,\"tool\":3,\"t_end\":2.5}\n";
        assert_eq!(
            line(&mut tp, to, mto),
            format!(
                "{head},\"to\":{{\"x\":1.25,\"y\":0.0,\"z\":123456.0}},\
                 \"mto\":{{\"x\":-998.75,\"y\":0.0,\"z\":123456.0}}{tail}"
            )
        );
        // The same again (every text from the memo), then values past 1e9
        // and NaN (the `{}` path) in the middle of a position.
        assert_eq!(line(&mut tp, to, mto), line(&mut tp, to, mto));
        to[1] = 2e9;
        mto[1] = f64::NAN;
        assert_eq!(
            line(&mut tp, to, mto),
            format!(
                "{head},\"to\":{{\"x\":1.25,\"y\":2000000000.0,\"z\":123456.0}},\
                 \"mto\":{{\"x\":-998.75,\"y\":NaN,\"z\":123456.0}}{tail}"
            )
        );
    }
}
