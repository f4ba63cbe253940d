//! Tool, spindle, feed and coolant: the cutting conditions as programmed
//! (T/M06, S and M03-M05, F, M07-M09), and what has been emitted of them.

use kerf_canon::SpindleDir;

/// The tool in use and the spindle, feed and coolant commands in force.
#[derive(Clone, Debug)]
pub(super) struct ToolSpindle {
    /// Programmed feed in mm/min or mm/rev (None until an F is given).
    pub(super) feed: Option<f64>,
    /// The spindle direction commanded.
    pub(super) spindle: SpindleDir,
    /// S as programmed (rpm, or surface speed in G96), in program units.
    pub(super) s: f64,
    /// The G50/G92 spindle speed clamp (rpm).
    pub(super) s_clamp: Option<f64>,
    /// Emitted spindle speed, to avoid repeating events.
    pub(super) last_rpm: f64,
    /// The tool in the spindle / active turret station.
    pub(super) number: u32,
    /// The tool selected by T for the next M06.
    pub(super) next: u32,
    /// The tool offset number in force (lathe T code).
    pub(super) offset: u32,
    /// Mist coolant on (M07).
    pub(super) mist: bool,
    /// Flood coolant on (M08).
    pub(super) flood: bool,
}

impl Default for ToolSpindle {
    /// At power-on: no tool, no F or S, spindle and coolant off.
    fn default() -> ToolSpindle {
        ToolSpindle {
            feed: None,
            spindle: SpindleDir::Stop,
            s: 0.0,
            s_clamp: None,
            last_rpm: 0.0,
            number: 0,
            next: 0,
            offset: 0,
            mist: false,
            flood: false,
        }
    }
}

impl ToolSpindle {
    /// RESET: the spindle and the coolant are off; the tool, its offset
    /// number, F, S and the speed clamp stay (interp/reset.rs).
    pub(super) fn reset(&mut self) {
        *self = ToolSpindle {
            feed: self.feed,
            s: self.s,
            s_clamp: self.s_clamp,
            number: self.number,
            next: self.next,
            offset: self.offset,
            ..ToolSpindle::default()
        };
    }

    /// Switches mist or flood coolant on, or both off (`None`); the state
    /// to emit: (mist, flood).
    pub(super) fn coolant(&mut self, on: Option<Coolant>) -> (bool, bool) {
        match on {
            Some(Coolant::Mist) => self.mist = true,
            Some(Coolant::Flood) => self.flood = true,
            None => {
                self.mist = false;
                self.flood = false;
            }
        }
        (self.mist, self.flood)
    }
}

/// A coolant that M07/M08 switch on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Coolant {
    /// M07.
    Mist,
    /// M08.
    Flood,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reset_stops_spindle_and_coolant_and_keeps_tool_feed_and_speed() {
        let mut t = ToolSpindle {
            feed: Some(250.0),
            spindle: SpindleDir::Cw,
            s: 1200.0,
            s_clamp: Some(3000.0),
            last_rpm: 1200.0,
            number: 4,
            next: 5,
            offset: 4,
            mist: true,
            flood: true,
        };
        t.reset();
        assert_eq!(t.spindle, SpindleDir::Stop);
        assert_eq!((t.last_rpm, t.mist, t.flood), (0.0, false, false));
        assert_eq!(
            (t.feed, t.s, t.s_clamp),
            (Some(250.0), 1200.0, Some(3000.0))
        );
        assert_eq!((t.number, t.next, t.offset), (4, 5, 4));
    }

    #[test]
    fn mist_and_flood_add_up_and_off_clears_both() {
        let mut t = ToolSpindle::default();
        assert_eq!(t.coolant(Some(Coolant::Mist)), (true, false));
        assert_eq!(t.coolant(Some(Coolant::Flood)), (true, true));
        assert_eq!(t.coolant(None), (false, false));
        assert_eq!(t.coolant(Some(Coolant::Flood)), (false, true));
    }
}
