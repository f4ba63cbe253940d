//! Moves the runtime makes itself (jog, handle, reference return, the
//! re-entry of a program restart) are built by the interpreter's move
//! seam like every program move: a scratch interpreter on the same
//! profile, with the work zero at the machine zero and no offsets, runs
//! one positioning or feed block in machine coordinates, with its travel
//! and stroke checks. The motion's work point is then set to `work_shift`
//! away (so the screen's work position stays the machine's own).

use kerf_canon::{Alarm, Axis, Event, Pos, NAXES};
use kerf_interp::{DialectId, Interp, Profile, Settings, Step};

/// How a machine move goes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum MoveKind {
    /// Positioning at rapid.
    Rapid,
    /// Linear at this feed, mm/min.
    Feed(f64),
}

/// Why a machine move cannot be made.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub(super) enum MoveError {
    /// The block made no motion.
    #[error("no move")]
    NoMove,
    /// The move seam's alarm (travel, stroke): its message.
    #[error("{}", .0.message)]
    Alarm(Alarm),
}

/// The motion event from `from` to `to` (machine coordinates); its work
/// point is machine − `work_shift`. An alarm of the seam (travel) is the
/// error.
pub(super) fn machine_move(
    profile: &Profile,
    from: Pos,
    to: Pos,
    kind: MoveKind,
    work_shift: Pos,
) -> Result<Event, MoveError> {
    let mut it = Interp::new(profile.clone(), Settings::default());
    for i in 0..6 {
        it.set_work_offset(i, [0.0; NAXES]);
    }
    it.set_machine_position(from);
    let diameter = it.diameter_programming();
    let mut text = String::from("G90 ");
    text.push_str(match (kind, profile.dialect) {
        (MoveKind::Rapid, _) => "G00",
        (MoveKind::Feed(_), DialectId::Puma) => "G98 G01",
        (MoveKind::Feed(_), _) => "G94 G01",
    });
    for a in Axis::ALL {
        if profile.has_axis(a) && (to[a as usize] - from[a as usize]).abs() > 1e-9 {
            let v = if a == Axis::X && diameter {
                2.0 * to[0]
            } else {
                to[a as usize]
            };
            text.push_str(&format!(" {}{:.4}", a.name().to_uppercase(), v));
        }
    }
    if let MoveKind::Feed(f) = kind {
        text.push_str(&format!(" F{f:.3}"));
    }
    text.push('\n');
    it.load_text("move", &text);
    loop {
        match it.step() {
            Step::Event(mut e) if e.motion().is_some() => {
                set_work(&mut e, &work_shift);
                return Ok(e);
            }
            Step::Event(_) => {}
            Step::End => return Err(MoveError::NoMove),
            Step::Alarm(a) => return Err(MoveError::Alarm(a)),
        }
    }
}

fn set_work(e: &mut Event, shift: &Pos) {
    use kerf_canon::Canon;
    if let Canon::Rapid { m, .. } | Canon::Feed { m, .. } = &mut e.cmd {
        for i in 0..NAXES {
            m.to[i] = m.mto[i] - shift[i];
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn moves_in_machine_coordinates_on_every_dialect() {
        for name in ["hx-mc", "puma-lathe", "hurco-lathe"] {
            let p = Profile::builtin(name).unwrap();
            let from = p.start_position();
            let mut to = from;
            to[0] -= 10.0;
            to[2] -= 5.0;
            let e = machine_move(&p, from, to, MoveKind::Feed(1000.0), [1.0; NAXES]).unwrap();
            let m = e.motion().unwrap();
            assert!((m.mto[0] - to[0]).abs() < 1e-9, "{name}: {:?}", m.mto);
            assert!((m.mto[2] - to[2]).abs() < 1e-9, "{name}");
            assert!((m.to[0] - (to[0] - 1.0)).abs() < 1e-9, "{name}");
            assert!(
                matches!(e.cmd, kerf_canon::Canon::Feed { feed: kerf_canon::Feed::PerMin(f), .. } if f == 1000.0)
            );
            let r = machine_move(&p, from, to, MoveKind::Rapid, [0.0; NAXES]).unwrap();
            assert!(matches!(r.cmd, kerf_canon::Canon::Rapid { .. }), "{name}");
        }
    }
}
