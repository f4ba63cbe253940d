//! The modal state: one named, typed field per modal group, set from the
//! meaning the dialect's table gives a code ([`Means`]), never from the
//! code's number or its group's number. Group numbers appear only where
//! the control shows them: the modal page ([`Modal::code_of_group`]) and
//! the system variables #4001-#4031.
use kerf_canon::Plane;

use crate::dialect::meaning::{
    CompSide, CuttingMode, CycleReturn, Distance, FeedMode, HoleCycle, Kind, LengthComp,
    MotionMode, Units,
};
use crate::dialect::{Dialect, GCode, Means};

/// The code of a group in force: its meaning, and its number (value×10;
/// 0 when no code of the group is in force) for the modal page.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Active<T> {
    /// What the code in force means.
    pub(crate) means: T,
    /// Its number, for display only.
    pub(crate) code10: u16,
}

impl<T> Active<T> {
    pub(crate) const fn none(means: T) -> Self {
        Active { means, code10: 0 }
    }
}

/// The modal G state of the interpreter.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct Modal {
    pub(crate) motion: Active<MotionMode>,
    pub(crate) css: Active<bool>,
    pub(crate) distance: Active<Distance>,
    pub(crate) feed_mode: Active<FeedMode>,
    pub(crate) units: Active<Units>,
    pub(crate) cutter_comp: Active<CompSide>,
    pub(crate) stroke: Active<bool>,
    /// The canned (drill) cycle in force (None: G80).
    pub(crate) cycle: Active<Option<HoleCycle>>,
    pub(crate) scaling: Active<bool>,
    pub(crate) modal_call: Active<bool>,
    pub(crate) length_comp: Active<LengthComp>,
    /// G54 + n.
    pub(crate) work: Active<u8>,
    /// None on the controls without the group.
    pub(crate) cutting_mode: Active<Option<CuttingMode>>,
    pub(crate) plane: Active<Plane>,
    pub(crate) polar_command: Active<bool>,
    pub(crate) rotation: Active<bool>,
    pub(crate) cycle_return: Active<CycleReturn>,
    pub(crate) polar_interp: Active<bool>,
    pub(crate) high_speed: Active<bool>,
    pub(crate) cylindrical: Active<bool>,
    pub(crate) stitch: Active<bool>,
    /// X as a diameter.
    pub(crate) diameter: Active<bool>,
}

impl Modal {
    /// The state before any code is applied: the plane of the machine
    /// kind and X as the dialect's default; [`Modal::power_on`] then
    /// applies the table's defaults.
    fn blank(plane: Plane, diameter: bool) -> Modal {
        Modal {
            motion: Active::none(MotionMode::Rapid),
            css: Active::none(false),
            distance: Active::none(Distance::Absolute),
            feed_mode: Active::none(FeedMode::PerMin),
            units: Active::none(Units::Metric),
            cutter_comp: Active::none(CompSide::Off),
            // A control without G22/G23 checks a stored area always.
            stroke: Active::none(true),
            cycle: Active::none(None),
            scaling: Active::none(false),
            modal_call: Active::none(false),
            length_comp: Active::none(LengthComp::Off),
            work: Active::none(0),
            cutting_mode: Active::none(None),
            plane: Active::none(plane),
            polar_command: Active::none(false),
            rotation: Active::none(false),
            cycle_return: Active::none(CycleReturn::Initial),
            polar_interp: Active::none(false),
            high_speed: Active::none(false),
            cylindrical: Active::none(false),
            stitch: Active::none(false),
            diameter: Active::none(diameter),
        }
    }

    /// The power-on state of a dialect: every group's default code.
    pub(crate) fn power_on(d: &Dialect, plane: Plane) -> Modal {
        let mut m = Modal::blank(plane, d.diameter_default);
        for g in d.gcodes.iter().filter(|g| g.default) {
            m.set(g);
        }
        m
    }

    /// The power-on state of a machine: the group defaults of its
    /// dialect in its plane (ZX on a lathe), and on the HX the power-on
    /// parameters PI 144-147 (000 §3.2: G01, G18/G19, G91, G20).
    pub(crate) fn at_power_on(profile: &crate::machine::Profile, dialect: &Dialect) -> Modal {
        let plane = if profile.kind == crate::machine::MachineKind::Lathe {
            Plane::ZX
        } else {
            Plane::XY
        };
        let mut m = Modal::power_on(dialect, plane);
        if dialect.caps.power_on_params {
            let p = |n: &str, d: f64| profile.param(n, d) as i64;
            if p("PI 144", 0.0) == 1 {
                m.set_meaning(dialect, Means::Motion(MotionMode::Linear));
            }
            match p("PI 145", 0.0) {
                1 => m.set_meaning(dialect, Means::Plane(Plane::ZX)),
                2 => m.set_meaning(dialect, Means::Plane(Plane::YZ)),
                _ => {}
            }
            if p("PI 146", 0.0) == 1 {
                m.set_meaning(dialect, Means::Distance(Distance::Incremental));
            }
            if p("PI 147", 1.0) == 0 {
                m.set_meaning(dialect, Means::Units(Units::Inch));
            }
        }
        m
    }

    /// Puts a code of the table in force (a one-shot code changes nothing).
    pub(crate) fn set(&mut self, g: &GCode) {
        let c = g.code10;
        fn a<T>(means: T, code10: u16) -> Active<T> {
            Active { means, code10 }
        }
        match g.means {
            Means::OneShot(_) => {}
            Means::Motion(v) => self.motion = a(v, c),
            Means::Css(v) => self.css = a(v, c),
            Means::Distance(v) => self.distance = a(v, c),
            Means::FeedMode(v) => self.feed_mode = a(v, c),
            Means::Units(v) => self.units = a(v, c),
            Means::CutterComp(v) => self.cutter_comp = a(v, c),
            Means::Stroke(v) => self.stroke = a(v, c),
            Means::Cycle(v) => self.cycle = a(v, c),
            Means::Scaling(v) => self.scaling = a(v, c),
            Means::ModalCall(v) => self.modal_call = a(v, c),
            Means::LengthComp(v) => self.length_comp = a(v, c),
            Means::Work(v) => self.work = a(v, c),
            Means::CuttingMode(v) => self.cutting_mode = a(Some(v), c),
            Means::Plane(v) => self.plane = a(v, c),
            Means::PolarCommand(v) => self.polar_command = a(v, c),
            Means::Rotation(v) => self.rotation = a(v, c),
            Means::CycleReturn(v) => self.cycle_return = a(v, c),
            Means::PolarInterp(v) => self.polar_interp = a(v, c),
            Means::HighSpeed(v) => self.high_speed = a(v, c),
            Means::Cylindrical(v) => self.cylindrical = a(v, c),
            Means::Stitch(v) => self.stitch = a(v, c),
            Means::Diameter(v) => self.diameter = a(v, c),
        }
    }

    /// The number of the code in force of one kind (0 if none).
    pub(crate) fn code(&self, k: Kind) -> u16 {
        match k {
            Kind::OneShot => 0,
            Kind::Motion => self.motion.code10,
            Kind::Css => self.css.code10,
            Kind::Distance => self.distance.code10,
            Kind::FeedMode => self.feed_mode.code10,
            Kind::Units => self.units.code10,
            Kind::CutterComp => self.cutter_comp.code10,
            Kind::Stroke => self.stroke.code10,
            Kind::Cycle => self.cycle.code10,
            Kind::Scaling => self.scaling.code10,
            Kind::ModalCall => self.modal_call.code10,
            Kind::LengthComp => self.length_comp.code10,
            Kind::Work => self.work.code10,
            Kind::CuttingMode => self.cutting_mode.code10,
            Kind::Plane => self.plane.code10,
            Kind::PolarCommand => self.polar_command.code10,
            Kind::Rotation => self.rotation.code10,
            Kind::CycleReturn => self.cycle_return.code10,
            Kind::PolarInterp => self.polar_interp.code10,
            Kind::HighSpeed => self.high_speed.code10,
            Kind::Cylindrical => self.cylindrical.code10,
            Kind::Stitch => self.stitch.code10,
            Kind::Diameter => self.diameter.code10,
        }
    }

    /// The number of the code in force in group `group` of dialect `d`,
    /// as the modal page and #4001-#4031 show it (0: no such group, or
    /// none of its codes in force).
    pub(crate) fn code_of_group(&self, d: &Dialect, group: u8) -> u16 {
        if group == 0 {
            return 0;
        }
        match d.gcodes.iter().find(|g| g.group == group) {
            Some(g) => self.code(g.means.kind()),
            None => 0,
        }
    }

    /// Puts the code of dialect `d` that means `means` in force, if the
    /// dialect has one (the HX power-on parameters, G66/G67 calls, a
    /// cycle cancelled by a motion code). It searches the table: not for
    /// every block.
    pub(crate) fn set_meaning(&mut self, d: &Dialect, means: Means) {
        if let Some(g) = d.gcodes.iter().find(|g| g.means == means) {
            self.set(g);
        }
    }

    /// Absolute dimensions (G90).
    pub(crate) fn absolute(&self) -> bool {
        self.distance.means == Distance::Absolute
    }

    /// Metric input (G21).
    pub(crate) fn metric(&self) -> bool {
        self.units.means == Units::Metric
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dialect::DialectId;

    const ALL: [DialectId; 3] = [DialectId::Hx, DialectId::Puma, DialectId::Hurco];

    /// Every modal group of every dialect is one kind of state: all the
    /// codes of a group set the same field, and no two groups share one.
    #[test]
    fn every_group_is_one_field() {
        for id in ALL {
            let d = Dialect::get(id);
            for a in d.gcodes {
                for b in d.gcodes {
                    let same_group = a.group == b.group;
                    let same_kind = a.means.kind() == b.means.kind();
                    assert_eq!(
                        same_group, same_kind,
                        "{id:?} G{} (group {}) and G{} (group {})",
                        a.code10, a.group, b.code10, b.group
                    );
                }
                assert_eq!(
                    a.group == 0,
                    a.means.kind() == Kind::OneShot,
                    "{id:?} G{}",
                    a.code10
                );
            }
        }
    }

    /// A modal code put in force is the code its group shows, and it
    /// changes no other group.
    #[test]
    fn set_shows_the_code_in_its_group_only() {
        for id in ALL {
            let d = Dialect::get(id);
            let plane = if id == DialectId::Hx {
                Plane::XY
            } else {
                Plane::ZX
            };
            for g in d.gcodes.iter().filter(|g| g.group != 0) {
                let mut m = Modal::power_on(d, plane);
                let before = m.clone();
                m.set(g);
                assert_eq!(
                    m.code_of_group(d, g.group),
                    g.code10,
                    "{id:?} G{}",
                    g.code10
                );
                for other in d.gcodes.iter().filter(|o| o.group != g.group) {
                    assert_eq!(
                        m.code_of_group(d, other.group),
                        before.code_of_group(d, other.group),
                        "{id:?} G{} changed group {}",
                        g.code10,
                        other.group
                    );
                }
            }
        }
    }

    /// The power-on state from the manuals' defaults: HX G00 G17 G90 G94
    /// G21 G40 G49 G54 G64 G80 G98 (000 §3.2), PUMA G00 G18 G21 G40 G97 G99
    /// (001 `#`), Hurco G00 G08 G21 G40 G90 G94 G97 G98.
    /// 000 §3.2: PI 144 = 1 powers on in G01, PI 145 = 2 in G19, PI 146
    /// = 1 in G91, PI 147 = 0 in G20; the PUMA has no such parameters.
    #[test]
    fn the_hx_power_on_parameters() {
        let mut p = crate::machine::Profile::builtin("hx-mc").unwrap();
        let d = Dialect::get(p.dialect);
        let plain = Modal::at_power_on(&p, d);
        assert_eq!(plain.motion.means, MotionMode::Rapid);
        assert_eq!(plain.plane.means, Plane::XY);
        assert!(plain.absolute() && plain.metric());
        for (k, v) in [
            ("PI 144", 1.0),
            ("PI 145", 2.0),
            ("PI 146", 1.0),
            ("PI 147", 0.0),
        ] {
            p.params.insert(k.into(), v);
        }
        let m = Modal::at_power_on(&p, d);
        assert_eq!(m.motion.means, MotionMode::Linear);
        assert_eq!(m.plane.means, Plane::YZ);
        assert!(!m.absolute() && !m.metric());
        let mut lathe = crate::machine::Profile::builtin("puma-lathe").unwrap();
        lathe.params.insert("PI 144".into(), 1.0);
        let l = Modal::at_power_on(&lathe, Dialect::get(lathe.dialect));
        assert_eq!(l.motion.means, MotionMode::Rapid);
        assert_eq!(l.plane.means, Plane::ZX);
    }

    #[test]
    fn power_on_defaults() {
        let hx = Modal::power_on(Dialect::get(DialectId::Hx), Plane::XY);
        assert_eq!(hx.motion.means, MotionMode::Rapid);
        assert_eq!(hx.plane.code10, 170);
        assert!(hx.absolute() && hx.metric());
        assert_eq!(hx.feed_mode.means, FeedMode::PerMin);
        assert_eq!(hx.length_comp.means, LengthComp::Off);
        assert_eq!(hx.work.means, 0);
        assert_eq!(hx.cutting_mode.means, Some(CuttingMode::Cutting));
        assert_eq!(hx.cycle_return.means, CycleReturn::Initial);
        assert!(hx.stroke.means && hx.cycle.means.is_none() && !hx.diameter.means);
        let puma = Modal::power_on(Dialect::get(DialectId::Puma), Plane::ZX);
        assert_eq!(puma.feed_mode.means, FeedMode::PerRev);
        assert_eq!(puma.feed_mode.code10, 990);
        assert_eq!(puma.plane.means, Plane::ZX);
        assert_eq!(puma.cutting_mode.means, None);
        assert!(puma.diameter.means && !puma.css.means);
        let hurco = Modal::power_on(Dialect::get(DialectId::Hurco), Plane::ZX);
        assert!(hurco.diameter.means);
        assert_eq!(hurco.diameter.code10, 80);
        assert_eq!(hurco.feed_mode.means, FeedMode::PerMin);
        assert_eq!(hurco.cycle_return.code10, 980);
    }

    /// The same meaning under different numbers: feed per revolution is
    /// G95 on the HX and G99 on the PUMA; G99 on the HX is the R-point
    /// return; the Hurco's legacy G70 is inch like its G20.
    #[test]
    fn meanings_not_numbers() {
        let code = |id, c| Dialect::get(id).gcode(c).unwrap().means;
        use crate::dialect::meaning::Means as M;
        assert_eq!(code(DialectId::Hx, 950), M::FeedMode(FeedMode::PerRev));
        assert_eq!(code(DialectId::Puma, 990), M::FeedMode(FeedMode::PerRev));
        assert_eq!(
            code(DialectId::Hx, 990),
            M::CycleReturn(CycleReturn::RPoint)
        );
        assert_eq!(code(DialectId::Hurco, 700), M::Units(Units::Inch));
        assert_eq!(code(DialectId::Puma, 900), M::Motion(MotionMode::TurnCycle));
        assert_eq!(code(DialectId::Hx, 900), M::Distance(Distance::Absolute));
        assert_eq!(
            code(DialectId::Hurco, 590),
            M::OneShot(crate::dialect::meaning::OneShot::CancelWorkShift)
        );
        let mut m = Modal::power_on(Dialect::get(DialectId::Hurco), Plane::ZX);
        m.set(Dialect::get(DialectId::Hurco).gcode(700).unwrap());
        assert!(!m.metric());
        assert_eq!(m.units.code10, 700);
    }
}
