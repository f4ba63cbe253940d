//! Tool offset memory: the control's offset pages.
//!
//! - Mills (000 §13): H (tool length) and D (cutter radius) tables, each
//!   entry a geometry value and a wear value; the value in force is their
//!   sum. H00 and D00 are always 0 and cannot be written.
//! - Lathes (001 offset pages, 002 tool offsets): one entry per offset
//!   number with X (on the diameter/radius the profile programs, stored
//!   in mm of radius here), Z, nose radius R and the imaginary tip
//!   direction T (0-9), again as geometry + wear (T has no wear).
//!
//! All lengths are stored in mm (lathe X as a radius); conversion from
//! program units happens at the edges (G10, system variables, the
//! `--offsets` file). Offset number 0 exists in every table and reads 0.

/// One mill offset (H or D): geometry and wear, mm.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct MillOffset {
    /// Geometry value, mm.
    pub geom: f64,
    /// Wear value, mm (added to the geometry).
    pub wear: f64,
}

impl MillOffset {
    /// The value in force: geometry + wear.
    pub fn value(&self) -> f64 {
        self.geom + self.wear
    }
}

/// One lathe tool offset: X/Z/R geometry and wear (mm, X as a radius) and
/// the imaginary tool tip direction.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct LatheOffset {
    /// X geometry, mm of radius.
    pub x: f64,
    /// Z geometry, mm.
    pub z: f64,
    /// Nose radius geometry, mm.
    pub r: f64,
    /// Imaginary tool tip direction 0-9 (001 p.29).
    pub tip: u8,
    /// X wear, mm of radius.
    pub wear_x: f64,
    /// Z wear, mm.
    pub wear_z: f64,
    /// Nose radius wear, mm.
    pub wear_r: f64,
}

impl LatheOffset {
    /// X in force (geometry + wear), mm of radius.
    pub fn total_x(&self) -> f64 {
        self.x + self.wear_x
    }
    /// Z in force (geometry + wear), mm.
    pub fn total_z(&self) -> f64 {
        self.z + self.wear_z
    }
    /// Nose radius in force (geometry + wear), mm.
    pub fn total_r(&self) -> f64 {
        self.r + self.wear_r
    }
}

/// The offset memory of one control: H, D and lathe tables, each indexed
/// by offset number (0 is the always-zero entry).
#[derive(Clone, Debug)]
pub struct OffsetTable {
    h: Vec<MillOffset>,
    d: Vec<MillOffset>,
    lathe: Vec<LatheOffset>,
}

impl OffsetTable {
    /// A table with offset numbers 0..=`count` in each page, all zero.
    pub fn new(count: usize) -> OffsetTable {
        OffsetTable {
            h: vec![MillOffset::default(); count + 1],
            d: vec![MillOffset::default(); count + 1],
            lathe: vec![LatheOffset::default(); count + 1],
        }
    }

    /// The highest offset number.
    pub fn count(&self) -> usize {
        self.h.len() - 1
    }

    /// Whether `n` names an offset (0..=count).
    pub fn valid(&self, n: usize) -> bool {
        n < self.h.len()
    }

    /// H`n` in force (geometry + wear), mm; 0 for H00 or out of range.
    pub fn h(&self, n: usize) -> f64 {
        self.h.get(n).map(MillOffset::value).unwrap_or(0.0)
    }

    /// D`n` in force (geometry + wear), mm; 0 for D00 or out of range.
    pub fn d(&self, n: usize) -> f64 {
        self.d.get(n).map(MillOffset::value).unwrap_or(0.0)
    }

    /// The H entry `n` for reading.
    pub fn h_entry(&self, n: usize) -> Option<&MillOffset> {
        self.h.get(n)
    }

    /// The D entry `n` for reading.
    pub fn d_entry(&self, n: usize) -> Option<&MillOffset> {
        self.d.get(n)
    }

    /// The H entry `n` for writing; `None` for H00 and out of range.
    pub fn h_mut(&mut self, n: usize) -> Option<&mut MillOffset> {
        if n == 0 {
            return None;
        }
        self.h.get_mut(n)
    }

    /// The D entry `n` for writing; `None` for D00 and out of range.
    pub fn d_mut(&mut self, n: usize) -> Option<&mut MillOffset> {
        if n == 0 {
            return None;
        }
        self.d.get_mut(n)
    }

    /// Lathe offset `n` (all zero for 0 or out of range).
    pub fn lathe(&self, n: usize) -> LatheOffset {
        self.lathe.get(n).copied().unwrap_or_default()
    }

    /// Lathe offset `n` for writing; `None` for 0 and out of range.
    pub fn lathe_mut(&mut self, n: usize) -> Option<&mut LatheOffset> {
        if n == 0 {
            return None;
        }
        self.lathe.get_mut(n)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn zero_entry_reads_zero_and_cannot_be_written() {
        let mut t = OffsetTable::new(4);
        assert!(t.h_mut(0).is_none());
        assert!(t.lathe_mut(0).is_none());
        assert_eq!(t.h(0), 0.0);
        assert!(t.valid(4));
        assert!(!t.valid(5));
        assert!(t.d_mut(5).is_none());
    }

    #[test]
    fn value_in_force_is_geometry_plus_wear() {
        let mut t = OffsetTable::new(4);
        *t.h_mut(2).unwrap() = MillOffset {
            geom: 100.0,
            wear: -0.25,
        };
        assert_eq!(t.h(2), 99.75);
        let l = t.lathe_mut(3).unwrap();
        l.x = 10.0;
        l.wear_x = 0.5;
        l.r = 0.8;
        l.wear_r = -0.1;
        assert_eq!(t.lathe(3).total_x(), 10.5);
        assert!((t.lathe(3).total_r() - 0.7).abs() < 1e-12);
    }
}
