//! Machine state and coordinate frames: the machine position (owned by
//! the move seam, interp/mover.rs) and everything that relates it to the
//! program's coordinates — the work offset table, the G92/G50 shift, the
//! G52 local system, scaling and rotation, polar coordinates, G112/G107,
//! the tool length offset — with the stored stroke area, the G28
//! intermediate point and the last skip position.
//!
//! The frames nest as on the control: machine = work origin + shift +
//! local + tool length offset + program coordinates.

use std::cell::Cell;

use kerf_canon::{Pos, NAXES};

use super::mover::Mover;
use super::polar_interp::RotInterp;
use super::work_offsets::WorkOffsets;
use crate::machine::Profile;

/// The machine position and the coordinate frames.
#[derive(Clone, Debug)]
pub(super) struct Frames {
    /// Current position, machine coordinates: set only by the move seam
    /// (interp/mover.rs).
    pub(super) mover: Mover,
    /// The work offset table (G54-G59, Hurco E1-E9999) and the active
    /// system (interp/work_offsets.rs); written through
    /// [`Frames::work_mut`].
    work: WorkOffsets,
    /// G92 / G50 shift (the HX "work shift" of 000 §7.2.4, also set by
    /// `G10 L2 P0`); written through [`Frames::shift_mut`].
    shift: Pos,
    /// G52 local coordinate system offset (work coordinates; the same for
    /// every work system); written through [`Frames::local_mut`].
    local: Pos,
    /// Scaling (G51) and rotation (G68) in force.
    pub(super) xf: crate::xform::Xform,
    /// Position where the last skip signal came (program coordinates).
    pub(super) skip_pos: Option<Pos>,
    /// Stored stroke check 2 area (G22 X Y Z I J K), machine coordinates.
    pub(super) stroke_area: Option<crate::stroke::Area>,
    /// G16 polar coordinate command in force.
    pub(super) polar: bool,
    /// Origin of the polar coordinates (program coordinates in the plane).
    pub(super) polar_origin: std::cell::Cell<(f64, f64)>,
    /// G112 polar / G107 cylindrical interpolation in force.
    pub(super) rot: RotInterp,
    /// Tool length offset vector (G43/G44), added to the control point;
    /// written through [`Frames::tlo_mut`].
    tlo: Pos,
    /// Active H number (0 = none).
    pub(super) h: u32,
    /// G28 intermediate point (programmed coordinates), per axis.
    pub(super) g28_mid: [Option<f64>; NAXES],
    /// The origins as last worked out from the four fields above; None
    /// once any of them may have changed (every `*_mut` clears it).
    origins: KeptOrigins,
}

/// The origins kept between moves. Worked out from the frames, not part
/// of their state: its `Debug` shows no value, so a snapshot of the
/// frames (interp/runtime_hooks.rs) is the same whether it is filled.
///
/// Each origin is its own cell, read alone (a move reads one at a time:
/// one `Option` of both copied per read cost more than the read).
#[derive(Clone, Default)]
struct KeptOrigins {
    /// The two origins below are those of the frames as they are.
    valid: Cell<bool>,
    /// [`Origins::work_tlo`].
    work_tlo: Cell<Pos>,
    /// [`Origins::prog`].
    prog: Cell<Pos>,
}

impl KeptOrigins {
    /// Forgets the origins (a frame may have changed).
    #[inline]
    fn clear(&self) {
        self.valid.set(false);
    }
}

impl std::fmt::Debug for KeptOrigins {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("KeptOrigins")
    }
}

/// The origins every move asks for, worked out together from the work
/// offset, shift, local offset and tool length offset, by the same sums
/// in the same order as each would be alone (so bit for bit the same).
#[derive(Clone, Copy, Debug)]
struct Origins {
    /// [`Frames::origin`] + the tool length offset, per axis.
    work_tlo: Pos,
    /// [`Frames::prog_origin`].
    prog: Pos,
}

impl Frames {
    /// The frames at power-on: at the profile's start position, G54-G59
    /// as the profile gives them (a missing one as its G54), no shift,
    /// no local system, no transform, no tool length offset.
    pub(super) fn power_on(profile: &Profile) -> Frames {
        let mut wcs = [[0.0; NAXES]; 6];
        for (i, w) in wcs.iter_mut().enumerate() {
            let key = format!("g5{}", 4 + i);
            if let Some(m) = profile
                .work_offsets
                .get(&key)
                .or_else(|| profile.work_offsets.get("g54"))
            {
                *w = Profile::pos_of(m);
            }
        }
        Frames {
            mover: Mover::new(profile.start_position()),
            work: WorkOffsets::new(wcs),
            shift: [0.0; NAXES],
            local: [0.0; NAXES],
            xf: Default::default(),
            skip_pos: None,
            stroke_area: None,
            polar: false,
            polar_origin: std::cell::Cell::new((0.0, 0.0)),
            rot: RotInterp::Off,
            tlo: [0.0; NAXES],
            h: 0,
            g28_mid: [None; NAXES],
            origins: KeptOrigins::default(),
        }
    }

    /// The frames after RESET (interp/reset.rs): `fresh` (the power-on
    /// frames) with what RESET keeps of `self` — the position, the work
    /// offset entries, the shift, the G22 area, the G28 point, and the
    /// tool length offset vector when `keep_tlo`.
    pub(super) fn after_reset(&self, mut fresh: Frames, keep_tlo: bool) -> Frames {
        fresh.mover = self.mover;
        fresh.work.keep_entries_of(&self.work);
        fresh.shift = self.shift;
        fresh.stroke_area = self.stroke_area;
        fresh.g28_mid = self.g28_mid;
        if keep_tlo {
            fresh.tlo = self.tlo;
        }
        fresh.origins.clear();
        fresh
    }

    /// The work offset table and the active work system.
    pub(super) fn work(&self) -> &WorkOffsets {
        &self.work
    }

    /// The work offset table, to change an entry or the selection.
    pub(super) fn work_mut(&mut self) -> &mut WorkOffsets {
        self.origins.clear();
        &mut self.work
    }

    /// The G92 / G50 shift.
    pub(super) fn shift(&self) -> &Pos {
        &self.shift
    }

    /// The G92 / G50 shift, to change it.
    pub(super) fn shift_mut(&mut self) -> &mut Pos {
        self.origins.clear();
        &mut self.shift
    }

    /// The G52 local offset.
    pub(super) fn local(&self) -> &Pos {
        &self.local
    }

    /// The G52 local offset, to change it.
    pub(super) fn local_mut(&mut self) -> &mut Pos {
        self.origins.clear();
        &mut self.local
    }

    /// The tool length offset vector.
    pub(super) fn tlo(&self) -> &Pos {
        &self.tlo
    }

    /// The tool length offset vector, to change it.
    pub(super) fn tlo_mut(&mut self) -> &mut Pos {
        self.origins.clear();
        &mut self.tlo
    }

    /// The origins, worked out again only after a change.
    #[inline]
    fn origins(&self) -> &KeptOrigins {
        if !self.origins.valid.get() {
            let o = self.work_out_origins();
            self.origins.work_tlo.set(o.work_tlo);
            self.origins.prog.set(o.prog);
            self.origins.valid.set(true);
        }
        &self.origins
    }

    #[cold]
    fn work_out_origins(&self) -> Origins {
        let work = self.origin();
        let mut work_tlo = work;
        let mut prog = work;
        for i in 0..NAXES {
            work_tlo[i] = work[i] + self.tlo[i];
            prog[i] += self.tlo[i] + self.local[i];
        }
        Origins { work_tlo, prog }
    }

    /// The origin of work coordinates in machine coordinates: the active
    /// work offset plus the G92/G50 shift.
    pub(super) fn origin(&self) -> Pos {
        let w = self.work.origin();
        let mut o = [0.0; NAXES];
        for i in 0..NAXES {
            o[i] = w[i] + self.shift[i];
        }
        o
    }

    /// [`Frames::origin`] plus the tool length offset: the origin of the
    /// work coordinates of the tool tip.
    pub(super) fn origin_with_tlo(&self) -> Pos {
        self.origins().work_tlo.get()
    }

    /// Origin of programmed coordinates: the work origin plus the G52
    /// local offset and the tool length offset.
    pub(super) fn prog_origin(&self) -> Pos {
        self.origins().prog.get()
    }

    /// Current position in programmed coordinates (tool tip).
    pub(super) fn programmed_position(&self) -> Pos {
        let o = self.prog_origin();
        let mut p = self.mover.pos();
        for i in 0..NAXES {
            p[i] -= o[i];
        }
        p
    }

    /// Current position of the tool tip in the active work coordinate
    /// system (the G52 local system not taken off).
    pub(super) fn work_position(&self) -> Pos {
        let o = self.origin_with_tlo();
        let mut p = self.mover.pos();
        for i in 0..NAXES {
            p[i] -= o[i];
        }
        p
    }
}

#[cfg(test)]
mod tests {
    use super::super::work_offsets::WorkId;
    use super::*;

    fn frames() -> Frames {
        Frames::power_on(&Profile::builtin("hx-mc").unwrap())
    }

    #[test]
    fn the_frames_nest_work_shift_local_and_tool_length() {
        let mut f = frames();
        f.work_mut()
            .set(WorkId::G5x(1), [100.0, 50.0, -200.0, 0.0, 0.0, 0.0]);
        f.work_mut().select(WorkId::G5x(1));
        *f.shift_mut() = [1.0, 2.0, 3.0, 0.0, 0.0, 0.0];
        *f.local_mut() = [10.0, 20.0, 30.0, 0.0, 0.0, 0.0];
        *f.tlo_mut() = [0.0, 0.0, 150.0, 0.0, 0.0, 0.0];
        // G55 + shift.
        assert_eq!(f.origin(), [101.0, 52.0, -197.0, 0.0, 0.0, 0.0]);
        // + G52 + tool length: -197 + 30 + 150 = -17.
        assert_eq!(f.prog_origin(), [111.0, 72.0, -17.0, 0.0, 0.0, 0.0]);
        f.mover = Mover::new([111.0, 72.0, -7.0, 0.0, 0.0, 0.0]);
        assert_eq!(f.programmed_position(), [0.0, 0.0, 10.0, 0.0, 0.0, 0.0]);
        // The work position keeps the G52 offset: 111 - 101 = 10.
        assert_eq!(f.work_position(), [10.0, 20.0, 40.0, 0.0, 0.0, 0.0]);
    }

    #[test]
    fn reset_keeps_position_offsets_shift_and_stroke_area_only() {
        let mut f = frames();
        f.mover = Mover::new([5.0, 6.0, 7.0, 0.0, 0.0, 0.0]);
        f.work_mut().set(WorkId::G5x(2), [9.0; NAXES]);
        f.work_mut().select(WorkId::G5x(2));
        *f.shift_mut() = [1.0; NAXES];
        *f.local_mut() = [2.0; NAXES];
        *f.tlo_mut() = [0.0, 0.0, 80.0, 0.0, 0.0, 0.0];
        f.h = 3;
        f.polar = true;
        f.g28_mid[0] = Some(4.0);
        let g54 = f.work.get(WorkId::G5x(0));
        let r = f.after_reset(frames(), false);
        assert_eq!(r.mover.pos(), [5.0, 6.0, 7.0, 0.0, 0.0, 0.0]);
        assert_eq!(r.shift, [1.0; NAXES]);
        assert_eq!(r.g28_mid[0], Some(4.0));
        // G54 is selected again (with the shift), G56's entry kept.
        assert_eq!(r.origin(), g54.map(|v| v + 1.0));
        let mut g56 = r.clone();
        g56.work_mut().select(WorkId::G5x(2));
        assert_eq!(g56.origin(), [10.0; NAXES]);
        assert_eq!(
            (r.local, r.tlo, r.h, r.polar),
            ([0.0; NAXES], [0.0; NAXES], 0, false)
        );
        // A control that keeps the tool offset over RESET.
        let kept = f.after_reset(frames(), true);
        assert_eq!(kept.tlo[2], 80.0);
    }

    #[test]
    fn every_change_of_a_frame_is_seen_by_the_next_move() {
        // The origins are kept between moves; each writer clears them.
        let mut f = frames();
        *f.work_mut().g5x_mut(0).unwrap() = [0.0; NAXES];
        f.mover = Mover::new([10.0, 20.0, 30.0, 0.0, 0.0, 0.0]);
        assert_eq!(f.programmed_position(), [10.0, 20.0, 30.0, 0.0, 0.0, 0.0]);
        f.shift_mut()[0] = 1.0;
        assert_eq!(f.programmed_position()[0], 9.0);
        f.local_mut()[1] = 2.0;
        assert_eq!(f.programmed_position()[1], 18.0);
        f.tlo_mut()[2] = 5.0;
        assert_eq!(f.programmed_position()[2], 25.0);
        // Work position: the G52 offset stays in, the tool length not.
        assert_eq!(f.work_position(), [9.0, 20.0, 25.0, 0.0, 0.0, 0.0]);
        f.work_mut().g5x_mut(0).unwrap()[0] = 4.0;
        assert_eq!(f.programmed_position()[0], 5.0);
        f.work_mut()
            .set(WorkId::G5x(1), [0.0, 0.0, 7.0, 0.0, 0.0, 0.0]);
        f.work_mut().select(WorkId::G5x(1));
        assert_eq!(f.prog_origin(), [1.0, 2.0, 12.0, 0.0, 0.0, 0.0]);
        // RESET keeps the shift and the entries (G54 X = 4), selects G54
        // again and drops the local and tool offsets: the origins come
        // from the frames it returns, not from the G55 ones kept before.
        let r = f.after_reset(frames(), false);
        assert_eq!(r.prog_origin(), [5.0, 0.0, 0.0, 0.0, 0.0, 0.0]);
    }

    #[test]
    fn the_kept_origins_are_not_part_of_the_state() {
        // Snapshots compare the frames' Debug text: a move that fills the
        // kept origins must not make two equal states differ.
        let fresh = frames();
        let used = frames();
        let _ = used.programmed_position();
        assert_eq!(format!("{fresh:?}"), format!("{used:?}"));
    }

    #[test]
    fn the_kept_origins_are_the_sums_bit_for_bit() {
        // Values whose sums round differently by grouping: the kept
        // origin is (work + shift) + (tlo + local), as it always was.
        let mut f = frames();
        *f.work_mut().g5x_mut(0).unwrap() = [0.1, 1e16, 0.3, 0.0, 0.0, 0.0];
        *f.shift_mut() = [0.2, 1.0, 0.6, 0.0, 0.0, 0.0];
        *f.local_mut() = [0.7, 1.0, 1e-17, 0.0, 0.0, 0.0];
        *f.tlo_mut() = [0.3, 1.0, 0.1, 0.0, 0.0, 0.0];
        let want: Vec<f64> = (0..3)
            .map(|i| {
                let (w, s, t, l) = (
                    [0.1, 1e16, 0.3][i],
                    [0.2, 1.0, 0.6][i],
                    [0.3, 1.0, 0.1][i],
                    [0.7, 1.0, 1e-17][i],
                );
                (w + s) + (t + l)
            })
            .collect();
        for _ in 0..2 {
            let o = f.prog_origin();
            assert_eq!(
                o[..3].iter().map(|v| v.to_bits()).collect::<Vec<_>>(),
                want.iter().map(|v| v.to_bits()).collect::<Vec<_>>()
            );
        }
        // (1e16 + 1) + (1 + 1) is 1e16 + 2 here, where 1e16 + 1 + 1 + 1
        // one at a time would be 1e16: the grouping is kept.
        assert_eq!(f.prog_origin()[1], 1e16 + 2.0);
    }

    #[test]
    fn power_on_takes_the_profiles_work_offsets() {
        let p = Profile::builtin("hx-mc").unwrap();
        let f = Frames::power_on(&p);
        let want = p
            .work_offsets
            .get("g54")
            .map(Profile::pos_of)
            .unwrap_or([0.0; NAXES]);
        assert_eq!(f.origin(), want);
        assert_eq!(f.mover.pos(), p.start_position());
    }
}
