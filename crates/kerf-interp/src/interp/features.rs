//! The state of the features, grouped by the control that has them:
//!
//! - [`CommonFeatures`]: features every control has — cutter / nose
//!   radius compensation, corners held for `,C`/`,R` or a chamfer, a tool
//!   length offset change in G91, an alarm raised after a block;
//! - [`HxFeatures`]: the TurboTek HX's canned cycles (G73-G89) and its
//!   calls by G/M/T code (PI 85-105);
//! - the PUMA's lathe cycles and G-code system B:
//!   [`PumaFeatures`](super::lathe::PumaFeatures) in interp/lathe.rs;
//! - the Hurco's fixture offsets, offset activation, drill cycles and
//!   probe data: [`HurcoState`](super::hurco::HurcoState) in
//!   interp/hurco.rs.

use kerf_canon::{Alarm, Pos, SrcRef};

use super::calls::CodeCalls;
use super::comp::CompState;
use super::corners::Pending;
use super::cycles::{CycleData, CycleParams};
use crate::dialect::Dialect;
use crate::machine::Profile;

/// Features of every control: what is held back while compensation or
/// a corner waits for the next move.
#[derive(Default)]
pub(super) struct CommonFeatures {
    /// A move carrying `,C`/`,R`, held until the next move is known; while
    /// it is held, events are kept back in it (interp/corners.rs).
    pub(super) corner: Option<Box<Pending>>,
    /// Cutter / tool nose radius compensation (interp/comp.rs); None when
    /// cancelled with nothing held.
    pub(super) comp: Option<Box<CompState>>,
    /// The programmed end point (work) of the compensated moves being
    /// emitted (`Event::prog`).
    pub(super) comp_prog: Option<Pos>,
    /// G71-G73 with nose radius compensation: the compensated pieces of
    /// the finishing shape (plane points, the block, and whether it is the
    /// block's own path rather than a corner piece) are kept here instead
    /// of emitted (interp/lathe_mrc.rs).
    pub(super) comp_capture: Option<Vec<(crate::comp::Seg, SrcRef, bool)>>,
    /// A tool length offset change in G91: (the block, the change of the
    /// offset vector), which that block's incremental move adds.
    tlo_inc: Option<(u64, Pos)>,
    /// An alarm raised after the current block's commands have run (G27).
    pub(super) after_block: Option<Alarm>,
}

impl CommonFeatures {
    /// Drops what is held (an alarm, RESET).
    pub(super) fn drop_held(&mut self) {
        self.corner = None;
        self.comp = None;
    }

    /// Records that block number `block` changed the tool length offset
    /// by `d` in G91.
    pub(super) fn set_tlo_change(&mut self, block: u64, d: Pos) {
        self.tlo_inc = Some((block, d));
    }

    /// The change of the tool length offset on axis slot `i` made by
    /// block number `block` (0 when another block made it).
    #[inline]
    pub(super) fn tlo_change(&self, block: u64, i: usize) -> f64 {
        match self.tlo_inc {
            Some((b, d)) if b == block => d[i],
            _ => 0.0,
        }
    }
}

/// The TurboTek HX's own features.
pub(super) struct HxFeatures {
    /// Canned cycle data and parameters (interp/cycles.rs).
    pub(super) cyc: CycleData,
    /// Calls by G/M/T code (HX PI 85-105); None when not set up.
    pub(super) code_calls: Option<Box<CodeCalls>>,
}

impl HxFeatures {
    /// The cycle parameters (PI 61-66, 70, 71, 129) and the code calls of
    /// `profile` (only on a control with the HX's variables).
    pub(super) fn new(profile: &Profile, dialect: &Dialect) -> HxFeatures {
        let code_calls = if dialect.caps.hx_variables {
            CodeCalls::from_profile(profile, dialect)
        } else {
            None
        };
        let mut cyc = CycleData::default();
        cyc.params = CycleParams::from_profile(profile);
        HxFeatures { cyc, code_calls }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_tool_length_change_belongs_to_its_block_only() {
        let mut c = CommonFeatures::default();
        assert_eq!(c.tlo_change(1, 2), 0.0);
        c.set_tlo_change(7, [0.0, 0.0, -12.5, 0.0, 0.0, 0.0]);
        assert_eq!(c.tlo_change(7, 2), -12.5);
        assert_eq!(c.tlo_change(7, 0), 0.0);
        // The next block moves without it.
        assert_eq!(c.tlo_change(8, 2), 0.0);
    }

    /// PI 85-104 name the G and M codes that call O9010-O9029; M02 and
    /// M30 (the program end) cannot be made calls, nor can the PUMA have
    /// code calls at all.
    #[test]
    fn code_calls_come_from_the_hx_parameters() {
        let mut p = Profile::builtin("hx-mc").unwrap();
        let d = Dialect::get(p.dialect);
        assert!(HxFeatures::new(&p, d).code_calls.is_none());
        p.params.insert("PI 95".into(), 30.0);
        p.params.insert("PI 96".into(), 2.0);
        assert!(HxFeatures::new(&p, d).code_calls.is_none());
        p.params.insert("PI 97".into(), 50.0);
        let cc = HxFeatures::new(&p, d).code_calls.expect("M50 calls O9022");
        assert_eq!(cc.m_calls(), [(50, 9022)]);
        let mut lathe = Profile::builtin("puma-lathe").unwrap();
        lathe.params.insert("PI 97".into(), 50.0);
        assert!(HxFeatures::new(&lathe, Dialect::get(lathe.dialect))
            .code_calls
            .is_none());
    }

    #[test]
    fn cycle_parameters_are_read_and_hole_data_is_empty() {
        let mut p = Profile::builtin("hx-mc").unwrap();
        p.params.insert("PI 129".into(), -0.5);
        let hx = HxFeatures::new(&p, Dialect::get(p.dialect));
        let mut want = CycleData::default();
        want.params = CycleParams::from_profile(&p);
        assert_eq!(format!("{:?}", hx.cyc), format!("{want:?}"));
        // PI 129 is a distance: its sign is dropped.
        assert!(format!("{:?}", hx.cyc.params).contains("d: 0.5"));
    }
}
