//! Manual operation: jog and handle (JOG mode) move one axis at the jog or
//! handle feed within its travel (the soft limits of the profile's
//! `[axes]`); REF returns axes to their reference position at rapid and
//! marks them referenced.

use kerf_canon::Axis;
use kerf_interp::machine::axis_by_name;

use super::command::{Op, Refusal};
use super::mode::Execution;
use super::moves::{machine_move, MoveKind};
use super::Runtime;

/// A hand move under way.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct ManualMove {
    /// Axes a reference return marks referenced when it arrives.
    pub referencing: Vec<Axis>,
}

impl Runtime {
    pub(super) fn manual_active(&self) -> bool {
        self.manual.is_some()
    }

    pub(super) fn manual_clear(&mut self) {
        self.manual = None;
    }

    /// The hand move arrived (or was stopped): READY.
    pub(super) fn manual_done(&mut self) {
        let t = self.clock.t;
        let pos = self.clock.position(t);
        self.interp.set_machine_position(pos);
        if let Some(m) = self.manual.take() {
            for a in m.referencing {
                self.referenced[a as usize] = true;
            }
        }
        if self.exec == Execution::Active {
            self.exec = Execution::Ready;
        }
    }

    /// Whether an axis has been referenced (REF mode) since power-on.
    pub fn referenced(&self, a: Axis) -> bool {
        self.referenced[a as usize]
    }

    fn axis_of(&self, op: Op, name: &str) -> Result<Axis, Refusal> {
        match axis_by_name(&name.to_ascii_lowercase()) {
            Some(a) if self.profile.has_axis(a) => Ok(a),
            _ => Err(self.refuse(op, format!("this machine has no axis '{name}'"))),
        }
    }

    /// Jog (or handle) `axis` by `distance` mm (degrees).
    pub(super) fn jog(
        &mut self,
        op: Op,
        axis: &str,
        distance: f64,
        handle: bool,
    ) -> Result<(), Refusal> {
        let a = self.axis_of(op, axis)?;
        if !distance.is_finite() || distance.abs() > 1e6 {
            return Err(self.refuse(op, format!("distance {distance}: not a jog distance")));
        }
        let from = self.clock.position(self.clock.t);
        let mut to = from;
        to[a as usize] += distance;
        let data = self.profile.axis(a).expect("axis checked");
        if to[a as usize] < data.min - 1e-9 || to[a as usize] > data.max + 1e-9 {
            return Err(self.refuse(
                op,
                format!(
                    "{} would go to {:.3}, outside its travel {:.3} .. {:.3}",
                    a.name().to_uppercase(),
                    to[a as usize],
                    data.min,
                    data.max
                ),
            ));
        }
        let feed = if handle {
            self.profile.param("handle_feed", 3000.0)
        } else {
            self.profile.param("jog_feed", 2000.0)
        };
        self.start_manual(op, from, to, MoveKind::Feed(feed), Vec::new())
    }

    /// Reference return of `axis` (or every axis) at rapid.
    pub(super) fn ref_return(&mut self, op: Op, axis: Option<&str>) -> Result<(), Refusal> {
        let axes: Vec<Axis> = match axis {
            Some(n) => vec![self.axis_of(op, n)?],
            None => Axis::ALL
                .into_iter()
                .filter(|&a| self.profile.has_axis(a))
                .collect(),
        };
        let from = self.clock.position(self.clock.t);
        let mut to = from;
        for &a in &axes {
            to[a as usize] = self.profile.axis(a).expect("present").reference;
        }
        self.start_manual(op, from, to, MoveKind::Rapid, axes)
    }

    /// Work = machine − this while the hands move (the interpreter's
    /// offsets in force).
    pub(super) fn work_shift(&self) -> kerf_canon::Pos {
        let w = self.interp.work_position();
        let m = self.interp.machine_position();
        let mut d = [0.0; kerf_canon::NAXES];
        for i in 0..kerf_canon::NAXES {
            d[i] = m[i] - w[i];
        }
        d
    }

    fn start_manual(
        &mut self,
        op: Op,
        from: kerf_canon::Pos,
        to: kerf_canon::Pos,
        kind: MoveKind,
        referencing: Vec<Axis>,
    ) -> Result<(), Refusal> {
        // Already there: the move is done at the next clock step.
        let e = if super::clock::moved(&from, &to) {
            Some(
                machine_move(&self.profile, from, to, kind, self.work_shift())
                    .map_err(|r| self.refuse(op, r.to_string()))?,
            )
        } else {
            None
        };
        self.restart_clock();
        if let Some(e) = e {
            self.note_motion(&e);
            self.clock.push(e);
        }
        self.clock.finish();
        self.manual = Some(ManualMove { referencing });
        self.exec = Execution::Active;
        Ok(())
    }
}
