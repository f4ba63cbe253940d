//! Operator-panel switches and overrides.

use serde::{Deserialize, Serialize};

/// The program switches of the panel. They act from the next block the
/// interpreter reads (it reads ahead of the axes by the planner's
/// look-ahead), as on the control.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct Switches {
    /// Stop after each block.
    pub single_block: bool,
    /// M01 stops.
    pub optional_stop: bool,
    /// Cutting moves at the dry-run feed.
    pub dry_run: bool,
    /// Block delete levels switched on (0-10, as `--set block_skip`; `/`
    /// alone is level 1).
    pub block_skip: Vec<u8>,
}

impl Switches {
    /// The block-skip levels as the interpreter's bit mask (bit n = `/n`).
    pub fn skip_mask(&self) -> u16 {
        self.block_skip
            .iter()
            .fold(0u16, |m, &l| m | (1u16 << l.min(15)))
    }

    /// Checks the levels: 0-10 (000 §2.3.3 "/0 ~ /10" on the HX, 002
    /// `/0`-`/9` on the Hurco).
    pub fn validate(&self) -> Result<(), String> {
        for &l in &self.block_skip {
            if l > 10 {
                return Err(format!("block skip level {l}: levels are 0-10"));
            }
        }
        Ok(())
    }
}

/// Feed and rapid overrides, percent.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Overrides {
    /// Feed override, 1-200 %.
    pub feed: f64,
    /// Rapid override, 1-100 %.
    pub rapid: f64,
}

impl Default for Overrides {
    fn default() -> Overrides {
        Overrides {
            feed: 100.0,
            rapid: 100.0,
        }
    }
}

impl Overrides {
    /// Checks the ranges of the panel dials: feed 1-200 %, rapid 1-100 %.
    pub fn validate(&self) -> Result<(), String> {
        if !(self.feed.is_finite() && (1.0..=200.0).contains(&self.feed)) {
            return Err(format!(
                "feed override {}: the dial goes 1-200 %",
                self.feed
            ));
        }
        if !(self.rapid.is_finite() && (1.0..=100.0).contains(&self.rapid)) {
            return Err(format!(
                "rapid override {}: the dial goes 1-100 %",
                self.rapid
            ));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn skip_mask_and_ranges() {
        let s = Switches {
            block_skip: vec![1, 3],
            ..Default::default()
        };
        assert_eq!(s.skip_mask(), 0b1010);
        let zero = Switches {
            block_skip: vec![0, 10],
            ..Default::default()
        };
        assert_eq!(zero.skip_mask(), 0b100_0000_0001);
        assert!(zero.validate().is_ok());
        assert!(s.validate().is_ok());
        let bad = Switches {
            block_skip: vec![11],
            ..Default::default()
        };
        assert!(bad.validate().is_err());
        assert!(Overrides {
            feed: 0.0,
            rapid: 100.0
        }
        .validate()
        .is_err());
        assert!(Overrides {
            feed: 200.0,
            rapid: 100.0
        }
        .validate()
        .is_ok());
        assert!(Overrides {
            feed: 100.0,
            rapid: 101.0
        }
        .validate()
        .is_err());
    }
}
