//! Dialects: the per-control data tables (G codes with modal groups and
//! defaults, M codes with their execution category) and the few switches
//! in which the controls' languages differ. One interpreter reads them all.

pub mod hurco;
pub mod hx;
pub mod puma;

/// Which control's language a profile speaks.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Deserialize, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum DialectId {
    /// TurboTek HX machining-center control (000).
    Hx,
    /// Fanuc 0-T on the Daewoo PUMA 450, G-code system A (001).
    Puma,
    /// Hurco MAX turning-center control (002).
    Hurco,
}

/// How far kerf implements a code.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Support {
    /// Executed.
    Yes,
    /// Recognised; executed once the named issue lands. Until then using it
    /// stops with alarm `KERF-0100` "not yet supported".
    Later(&'static str),
}

/// One G code of a dialect.
#[derive(Clone, Copy, Debug)]
pub struct GCode {
    /// The code times ten: G01 = 10, G10.3 = 103, G84.2 = 842.
    pub code10: u16,
    /// Modal group; 0 = one-shot (non-modal).
    pub group: u8,
    /// Power-on / reset default of its group.
    pub default: bool,
    /// The manual's name for it.
    pub name: &'static str,
    pub support: Support,
}

/// When an M code acts relative to the motion of its block.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MWhen {
    /// Before the block's motion (spindle start, coolant on, …).
    Before,
    /// After the block's motion (spindle stop, program stop, end, …).
    After,
}

/// What an M code does to the modelled machine state.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MAction {
    /// Only an auxiliary event with the manual's name.
    Aux,
    SpindleCw,
    SpindleCcw,
    SpindleStop,
    CoolantMist,
    CoolantFlood,
    CoolantOff,
    /// M00.
    Stop,
    /// M01.
    OptionalStop,
    /// M02 / M30.
    End,
    /// M06 tool change.
    ToolChange,
    /// M98 subprogram call.
    SubCall,
    /// M99 subprogram return.
    SubReturn,
}

/// One M code of a dialect.
#[derive(Clone, Copy, Debug)]
pub struct MCode {
    pub code: u16,
    pub name: &'static str,
    pub when: MWhen,
    pub action: MAction,
}

/// The language of one control.
#[derive(Debug)]
pub struct Dialect {
    pub id: DialectId,
    pub gcodes: &'static [GCode],
    pub mcodes: &'static [MCode],
    /// Addresses (upper-case letters) the control accepts at all.
    pub letters: &'static [u8],
    /// Multi-letter parameter names (Hurco G78).
    pub long_names: &'static [&'static str],
    /// X is programmed as a diameter by default (lathes).
    pub diameter_default: bool,
    /// U/V/W are incremental X/Y/Z (Fanuc lathe G-code system A).
    pub uvw_incremental: bool,
    /// Hurco: loop commands in comments, `\` continuation.
    pub hurco_syntax: bool,
    /// Execute a block's codes in the order of 002 Table 1.
    pub hurco_order: bool,
}

impl Dialect {
    /// The dialect for an id.
    pub fn get(id: DialectId) -> &'static Dialect {
        match id {
            DialectId::Hx => &hx::DIALECT,
            DialectId::Puma => &puma::DIALECT,
            DialectId::Hurco => &hurco::DIALECT,
        }
    }

    /// Looks up a G code by its value times ten.
    pub fn gcode(&self, code10: u16) -> Option<&'static GCode> {
        self.gcodes.iter().find(|g| g.code10 == code10)
    }

    /// Looks up an M code.
    pub fn mcode(&self, code: u16) -> Option<&'static MCode> {
        self.mcodes.iter().find(|m| m.code == code)
    }
}

/// Shorthand for the tables.
pub(crate) const fn g(
    code10: u16,
    group: u8,
    default: bool,
    name: &'static str,
    support: Support,
) -> GCode {
    GCode {
        code10,
        group,
        default,
        name,
        support,
    }
}

/// Shorthand for the tables.
pub(crate) const fn m(code: u16, name: &'static str, when: MWhen, action: MAction) -> MCode {
    MCode {
        code,
        name,
        when,
        action,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every table is well formed: codes unique, exactly one default per
    /// modal group that has one, one-shot codes never default.
    #[test]
    fn tables_are_consistent() {
        for id in [DialectId::Hx, DialectId::Puma, DialectId::Hurco] {
            let d = Dialect::get(id);
            for (i, a) in d.gcodes.iter().enumerate() {
                for b in &d.gcodes[i + 1..] {
                    assert_ne!(a.code10, b.code10, "{id:?} duplicate G{}", a.code10);
                }
                if a.group == 0 {
                    assert!(!a.default, "{id:?} one-shot G{} marked default", a.code10);
                }
            }
            let mut groups: Vec<u8> = d
                .gcodes
                .iter()
                .map(|g| g.group)
                .filter(|&g| g != 0)
                .collect();
            groups.sort();
            groups.dedup();
            for grp in groups {
                let n = d
                    .gcodes
                    .iter()
                    .filter(|g| g.group == grp && g.default)
                    .count();
                assert!(n <= 1, "{id:?} group {grp} has {n} defaults");
            }
            for (i, a) in d.mcodes.iter().enumerate() {
                for b in &d.mcodes[i + 1..] {
                    assert_ne!(a.code, b.code, "{id:?} duplicate M{}", a.code);
                }
            }
        }
    }
}
