//! Feed hold on the planned path: from the timeline piece the axes are on
//! at the instant of the hold, decelerate at that piece's path
//! acceleration along its path (and the following pieces, each at its
//! own acceleration) to a stop. A non-linear rapid stops each axis on its
//! own trapezoid; standing still stops at once.

use kerf_canon::{Pos, NAXES};
use kerf_motion::{Piece, PieceKind, Trap};

/// Path speed of a trapezoid `t` seconds after its start.
pub fn speed_at(tr: &Trap, t: f64) -> f64 {
    let t = t.max(0.0);
    let v = if t < tr.ta {
        tr.v0 + tr.a * t
    } else if t < tr.ta + tr.tc {
        tr.vp
    } else {
        tr.vp - tr.a * (t - tr.ta - tr.tc).min(tr.td)
    };
    if tr.len <= 0.0 {
        0.0
    } else {
        v.max(0.0)
    }
}

/// The stop: the deceleration pieces from `t` (absolute times, as the
/// pieces'), and the machine position where the axes stand still.
#[derive(Clone, Debug)]
pub struct Stop {
    pub pieces: Vec<Piece>,
    pub at: Pos,
    /// When the axes stand still, s.
    pub t_stop: f64,
}

/// Decelerates from time `t` on `pieces` (in time order, covering `t`);
/// `rest` is the position when no piece covers `t`.
pub fn decelerate(pieces: &[Piece], t: f64, rest: Pos) -> Stop {
    let Some(i) = pieces
        .iter()
        .position(|p| t >= p.t0 && t < p.t0 + p.duration())
    else {
        let at = pieces
            .iter()
            .rev()
            .find(|p| p.t0 <= t)
            .map(|p| p.pos_at(p.duration()))
            .unwrap_or(rest);
        return Stop {
            pieces: Vec::new(),
            at,
            t_stop: t,
        };
    };
    let p = &pieces[i];
    let tau = t - p.t0;
    match &p.kind {
        PieceKind::Hold { pos, .. } => Stop {
            pieces: Vec::new(),
            at: *pos,
            t_stop: t,
        },
        PieceKind::Axes { p0, p1, traps } => axes_stop(p0, p1, traps, tau, t),
        PieceKind::Move { .. } => path_stop(&pieces[i..], tau, t),
    }
}

fn axes_stop(p0: &Pos, p1: &Pos, traps: &[Trap; NAXES], tau: f64, t: f64) -> Stop {
    let mut from = *p0;
    let mut to = *p0;
    let mut out = [Trap::default(); NAXES];
    for k in 0..NAXES {
        let tr = &traps[k];
        let sign = if p1[k] >= p0[k] { 1.0 } else { -1.0 };
        let s = tr.s_at(tau);
        from[k] = p0[k] + sign * s;
        let v = speed_at(tr, tau);
        let d = if tr.a > 0.0 {
            (v * v / (2.0 * tr.a)).min(tr.len - s)
        } else {
            0.0
        };
        out[k] = Trap::plan(d, v, 0.0, v, tr.a);
        to[k] = from[k] + sign * d;
    }
    let piece = Piece {
        t0: t,
        kind: PieceKind::Axes {
            p0: from,
            p1: to,
            traps: Box::new(out),
        },
    };
    let dur = piece.duration();
    Stop {
        pieces: vec![piece],
        at: to,
        t_stop: t + dur,
    }
}

/// Along path pieces: the first from `tau` into it.
fn path_stop(pieces: &[Piece], tau: f64, t: f64) -> Stop {
    let mut out = Vec::new();
    let mut t0 = t;
    let mut v = None;
    let mut at = pieces[0].pos_at(tau);
    for (j, p) in pieces.iter().enumerate() {
        let PieceKind::Move { geom, trap } = &p.kind else {
            break;
        };
        let (s0, v0) = if j == 0 {
            (trap.s_at(tau), speed_at(trap, tau))
        } else {
            (0.0, v.unwrap_or(0.0))
        };
        at = geom.at(if trap.len > 0.0 { s0 / trap.len } else { 1.0 });
        if v0 <= 1e-12 || trap.a <= 0.0 {
            break;
        }
        let rem = (trap.len - s0).max(0.0);
        let d = v0 * v0 / (2.0 * trap.a);
        let (len, v1) = if d <= rem {
            (d, 0.0)
        } else {
            (rem, (v0 * v0 - 2.0 * trap.a * rem).max(0.0).sqrt())
        };
        let u0 = s0 / trap.len;
        let u1 = (s0 + len) / trap.len;
        let tr = Trap::plan(len, v0, v1, v0, trap.a);
        let piece = Piece {
            t0,
            kind: PieceKind::Move {
                geom: geom.sub(u0, u1.min(1.0)),
                trap: tr,
            },
        };
        t0 += piece.duration();
        at = geom.at(u1.min(1.0));
        out.push(piece);
        if v1 <= 1e-9 {
            break;
        }
        v = Some(v1);
    }
    Stop {
        pieces: out,
        at,
        t_stop: t0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use kerf_motion::geom::Geom;

    fn x(v: f64) -> Pos {
        [v, 0.0, 0.0, 0.0, 0.0, 0.0]
    }

    #[test]
    fn stops_at_v_squared_over_two_a_along_the_path() {
        // 100 mm at 10 mm/s, a = 1000 mm/s²: cruise after 0.01 s / 0.05 mm.
        let trap = Trap::plan(100.0, 0.0, 0.0, 10.0, 1000.0);
        let p = Piece {
            t0: 5.0,
            kind: PieceKind::Move {
                geom: Geom::Line {
                    p0: x(0.0),
                    p1: x(100.0),
                },
                trap,
            },
        };
        let s = decelerate(std::slice::from_ref(&p), 8.0, x(0.0));
        // At 3 s into the move: 0.05 + 10·2.99 = 29.95 mm; stops 0.05 mm on.
        assert!((s.at[0] - 30.0).abs() < 1e-9, "{:?}", s.at);
        assert!((s.t_stop - 8.01).abs() < 1e-9);
        // Crossing into the next piece: 10 mm/s with 0.02 mm left.
        let a = Trap::plan(29.97, 0.0, 10.0, 10.0, 1000.0);
        let b = Trap::plan(10.0, 10.0, 0.0, 10.0, 1000.0);
        let pa = Piece {
            t0: 0.0,
            kind: PieceKind::Move {
                geom: Geom::Line {
                    p0: x(0.0),
                    p1: x(29.97),
                },
                trap: a,
            },
        };
        let pb = Piece {
            t0: a.time(),
            kind: PieceKind::Move {
                geom: Geom::Line {
                    p0: x(29.97),
                    p1: x(39.97),
                },
                trap: b,
            },
        };
        let t = a.time() - 0.002; // 0.02 mm before the junction
        let s = decelerate(&[pa, pb], t, x(0.0));
        assert!((s.at[0] - (29.97 - 0.02 + 0.05)).abs() < 1e-9, "{:?}", s.at);
        assert_eq!(s.pieces.len(), 2);
    }
}
