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

/// A switch or dial setting the operator panel does not have.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum PanelError {
    /// A block skip level above 10.
    #[error("block skip level {0}: levels are 0-10")]
    SkipLevel(u8),
    /// A feed override outside 1-200 %.
    #[error("feed override {0}: the dial goes 1-200 %")]
    FeedOverride(f64),
    /// A rapid override outside 1-100 %.
    #[error("rapid override {0}: the dial goes 1-100 %")]
    RapidOverride(f64),
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
    pub fn validate(&self) -> Result<(), PanelError> {
        for &l in &self.block_skip {
            if l > 10 {
                return Err(PanelError::SkipLevel(l));
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
    pub fn validate(&self) -> Result<(), PanelError> {
        if !(self.feed.is_finite() && (1.0..=200.0).contains(&self.feed)) {
            return Err(PanelError::FeedOverride(self.feed));
        }
        if !(self.rapid.is_finite() && (1.0..=100.0).contains(&self.rapid)) {
            return Err(PanelError::RapidOverride(self.rapid));
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
        assert_eq!(bad.validate(), Err(PanelError::SkipLevel(11)));
        let e = Overrides {
            feed: 0.0,
            rapid: 100.0,
        }
        .validate();
        assert_eq!(e, Err(PanelError::FeedOverride(0.0)));
        assert_eq!(
            e.unwrap_err().to_string(),
            "feed override 0: the dial goes 1-200 %"
        );
        assert!(Overrides {
            feed: 200.0,
            rapid: 100.0
        }
        .validate()
        .is_ok());
        assert_eq!(
            Overrides {
                feed: 100.0,
                rapid: 101.0
            }
            .validate(),
            Err(PanelError::RapidOverride(101.0))
        );
    }
}
