//! Canonical motions as straight chords: lines as they are, arcs and
//! helices split so that no chord is farther than a tolerance from the
//! arc.

use kerf_canon::{ArcDir, Canon, Plane, Pos};

/// Most chords one arc is split into (per move, all turns included).
pub const MAX_CHORDS: usize = 200_000;

/// The end points of the chords of `cmd` starting at `start` (work
/// coordinates, X Y Z), the start itself not included. Non-motions give
/// nothing. `tol` is the chord tolerance, mm.
pub fn chords(cmd: &Canon, start: &Pos, tol: f64, out: &mut Vec<[f64; 3]>) {
    out.clear();
    match cmd {
        Canon::Rapid { m, .. } | Canon::Feed { m, .. } | Canon::Thread { m, .. } => {
            out.push([m.to[0], m.to[1], m.to[2]]);
        }
        Canon::Arc {
            m,
            center,
            dir,
            plane,
            turns,
            ..
        } => arc_chords(start, &m.to, center, *dir, *plane, *turns, tol, out),
        _ => {}
    }
}

#[allow(clippy::too_many_arguments)]
fn arc_chords(
    start: &Pos,
    end: &Pos,
    center: &Pos,
    dir: ArcDir,
    plane: Plane,
    turns: u32,
    tol: f64,
    out: &mut Vec<[f64; 3]>,
) {
    let (a, b, n) = plane.axes();
    let s = (start[a], start[b]);
    let e = (end[a], end[b]);
    let c = (center[a], center[b]);
    let ccw = dir == ArcDir::Ccw;
    let r0 = (s.0 - c.0).hypot(s.1 - c.1);
    let r1 = (e.0 - c.0).hypot(e.1 - c.1);
    let sweep = kerf_canon::geom::sweep(s, e, c, ccw) + turns as f64 * std::f64::consts::TAU;
    let r = r0.max(r1);
    // Chord of angle da has sagitta r (1 - cos(da/2)) <= tol.
    let da = if r > tol {
        2.0 * (1.0 - tol / r).clamp(-1.0, 1.0).acos()
    } else {
        sweep
    };
    let k = ((sweep / da.max(1e-9)).ceil() as usize).clamp(1, MAX_CHORDS);
    let a0 = (s.1 - c.1).atan2(s.0 - c.0);
    let sign = if ccw { 1.0 } else { -1.0 };
    for i in 1..=k {
        let f = i as f64 / k as f64;
        let mut p = [start[0], start[1], start[2]];
        if i == k {
            p = [end[0], end[1], end[2]];
        } else {
            let ang = a0 + sign * sweep * f;
            let rr = r0 + (r1 - r0) * f;
            p[a] = c.0 + rr * ang.cos();
            p[b] = c.1 + rr * ang.sin();
            p[n] = start[n] + (end[n] - start[n]) * f;
        }
        out.push(p);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use kerf_canon::{Feed, Motion};

    #[test]
    fn a_half_circle_is_chorded_within_tolerance_and_ends_exactly() {
        let mut to = [0.0; 6];
        to[0] = 20.0;
        to[2] = -3.0;
        let cmd = Canon::Arc {
            m: Motion { to, mto: to },
            center: [10.0, 0.0, 0.0, 0.0, 0.0, 0.0],
            mcenter: [0.0; 6],
            dir: ArcDir::Ccw,
            plane: Plane::XY,
            turns: 0,
            feed: Feed::PerMin(100.0),
        };
        let mut out = Vec::new();
        chords(&cmd, &[0.0; 6], 0.001, &mut out);
        // 2 acos(1 - 0.001/10) = 0.02828 rad per chord: ceil(pi / that) = 112.
        assert_eq!(out.len(), 112);
        assert_eq!(*out.last().unwrap(), [20.0, 0.0, -3.0]);
        // CCW from (0,0) about (10,0) goes through y < 0, the helix descends evenly.
        let mid = out[55];
        assert!(mid[1] < -9.9 && (mid[2] + 3.0 * 56.0 / 112.0).abs() < 1e-12);
        for w in out.windows(2) {
            let m = [(w[0][0] + w[1][0]) / 2.0, (w[0][1] + w[1][1]) / 2.0];
            let sag = 10.0 - (m[0] - 10.0).hypot(m[1]);
            assert!(sag <= 0.001 + 1e-12, "{sag}");
        }
    }
}
