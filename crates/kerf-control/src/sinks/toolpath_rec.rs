//! [`Rec`]: what one toolpath line needs of a timed event, and nothing
//! more. [`super::ToolpathBehind`] copies a `Rec` to its thread instead of
//! a clone of the whole event (a match over every command's variant and
//! a larger copy into and out of the batch), and [`super::Toolpath`]
//! writes every line from one, so both write the same bytes.

use kerf_canon::{ArcDir, Canon, Event, Feed, Pos, NAXES};

/// The kind of a record (`"kind"` in docs/formats.md).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Kind {
    /// `Canon::Rapid`.
    Rapid,
    /// `Canon::Feed`.
    Feed,
    /// `Canon::Arc`.
    Arc,
    /// `Canon::Thread`.
    Thread,
    /// `Canon::Dwell`.
    Dwell,
}

impl Kind {
    /// `"kind":"…"` with its comma: `,"kind":"rapid"` and so on, padded
    /// to a fixed size, with the length used.
    pub(crate) fn key(self) -> (&'static [u8; 18], usize) {
        match self {
            Kind::Rapid => (b",\"kind\":\"rapid\"\0\0\0", 15),
            Kind::Feed => (b",\"kind\":\"feed\"\0\0\0\0", 14),
            Kind::Arc => (b",\"kind\":\"arc\"\0\0\0\0\0", 13),
            Kind::Thread => (b",\"kind\":\"thread\"\0\0", 16),
            Kind::Dwell => (b",\"kind\":\"dwell\"\0\0\0", 15),
        }
    }
}

/// One toolpath line's values.
#[derive(Clone, Debug)]
pub(crate) struct Rec {
    /// The event's file id (`SrcRef::file`).
    pub file: u32,
    /// Its line.
    pub line: u32,
    /// Its tool.
    pub tool: u32,
    /// What it is.
    pub kind: Kind,
    /// An arc's direction (`Cw` otherwise).
    pub dir: ArcDir,
    /// A feed or arc programmed per revolution (`value` is then its F).
    pub per_rev: bool,
    /// The motion's `to`, or a dwell's position.
    pub to: Pos,
    /// The motion's `mto` (zero for a dwell).
    pub mto: Pos,
    /// An arc's centre (zero otherwise).
    pub center: Pos,
    /// The programmed end point of a compensated move.
    pub prog: Option<Box<Pos>>,
    /// Seconds from program start when it ends.
    pub t_end: f64,
    /// The effective feed in mm/min (feed, arc; 0 when not given), the
    /// lead (thread) or the seconds (dwell).
    pub main: f64,
    /// The programmed feed per revolution (`per_rev`) or a dwell's
    /// revolutions.
    pub value: f64,
}

impl Rec {
    /// The record of `e` ending at `t_end`, `here` the work position
    /// after it; None for an event that writes no line.
    #[inline]
    pub(crate) fn of(e: &Event, here: &Pos, t_end: f64, feed_mm_min: Option<f64>) -> Option<Rec> {
        const ZERO: Pos = [0.0; NAXES];
        let mut r = Rec {
            file: e.src.file,
            line: e.src.line,
            tool: e.tool,
            kind: Kind::Rapid,
            dir: ArcDir::Cw,
            per_rev: false,
            to: ZERO,
            mto: ZERO,
            center: ZERO,
            prog: None,
            t_end,
            main: feed_mm_min.unwrap_or(0.0),
            value: 0.0,
        };
        let (kind, m) = match &e.cmd {
            Canon::Rapid { m, .. } => (Kind::Rapid, m),
            Canon::Feed { m, feed } => {
                (r.per_rev, r.value) = per_rev(*feed);
                (Kind::Feed, m)
            }
            Canon::Arc {
                m,
                center,
                dir,
                feed,
                ..
            } => {
                (r.per_rev, r.value) = per_rev(*feed);
                r.center = *center;
                r.dir = *dir;
                (Kind::Arc, m)
            }
            Canon::Thread { m, lead } => {
                r.main = *lead;
                (Kind::Thread, m)
            }
            Canon::Dwell {
                seconds,
                revolutions,
            } => {
                r.kind = Kind::Dwell;
                r.to = *here;
                r.main = *seconds;
                r.value = *revolutions;
                return Some(r);
            }
            _ => return None,
        };
        r.kind = kind;
        r.to = m.to;
        r.mto = m.mto;
        r.prog = e.prog.clone();
        Some(r)
    }
}

/// Whether `f` is per revolution, and its value then.
#[inline]
fn per_rev(f: Feed) -> (bool, f64) {
    match f {
        Feed::PerRev(v) => (true, v),
        _ => (false, 0.0),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use kerf_canon::{Motion, Plane, SrcRef};

    #[test]
    fn the_kind_keys_are_the_json_text() {
        for (k, text) in [
            (Kind::Rapid, ",\"kind\":\"rapid\""),
            (Kind::Feed, ",\"kind\":\"feed\""),
            (Kind::Arc, ",\"kind\":\"arc\""),
            (Kind::Thread, ",\"kind\":\"thread\""),
            (Kind::Dwell, ",\"kind\":\"dwell\""),
        ] {
            let (key, len) = k.key();
            assert_eq!(&key[..len], text.as_bytes());
            assert!(key[len..].iter().all(|b| *b == 0));
        }
    }

    #[test]
    fn a_record_keeps_what_its_line_shows() {
        let mut to = [0.0; NAXES];
        to[0] = 1.0;
        let mut c = [0.0; NAXES];
        c[1] = 2.0;
        let e = Event {
            src: SrcRef {
                file: 3,
                line: 7,
                col: 1,
            },
            tool: 4,
            cmd: Canon::Arc {
                m: Motion { to, mto: c },
                center: c,
                mcenter: to,
                plane: Plane::XY,
                dir: ArcDir::Ccw,
                turns: 0,
                feed: Feed::PerRev(0.2),
            },
            prog: Some(Box::new(c)),
        };
        let r = Rec::of(&e, &[9.0; NAXES], 1.5, Some(120.0)).unwrap();
        assert_eq!((r.file, r.line, r.tool, r.kind), (3, 7, 4, Kind::Arc));
        assert_eq!((r.to, r.mto, r.center), (to, c, c));
        assert_eq!(
            (r.dir, r.per_rev, r.value, r.main),
            (ArcDir::Ccw, true, 0.2, 120.0)
        );
        assert_eq!(r.prog.as_deref(), Some(&c));
        let d = Event {
            cmd: Canon::Dwell {
                seconds: 2.0,
                revolutions: 3.0,
            },
            prog: None,
            ..e.clone()
        };
        let r = Rec::of(&d, &[9.0; NAXES], 1.5, None).unwrap();
        assert_eq!(
            (r.kind, r.to, r.main, r.value),
            (Kind::Dwell, [9.0; NAXES], 2.0, 3.0)
        );
        let m = Event {
            cmd: Canon::Message("hi".into()),
            ..d
        };
        assert!(Rec::of(&m, &[0.0; NAXES], 0.0, None).is_none());
    }
}
