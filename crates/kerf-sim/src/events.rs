//! What the simulation reports: crash events and the volumes.

/// Kinds of simulation events (docs/sim.md).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum EventKind {
    /// A rapid (G00) removed material.
    RapidIntoStock,
    /// The shank or holder met material.
    HolderCollision,
    /// Material was removed with the spindle stopped.
    SpindleOffCut,
    /// A tool that does not cut at its centre plunged into material.
    PlungeNonCentreCutting,
    /// A tool without geometry, simulated from its offsets (a warning).
    ToolUnknown,
}

impl EventKind {
    /// The name used in the report.
    pub fn name(self) -> &'static str {
        match self {
            EventKind::RapidIntoStock => "rapid_into_stock",
            EventKind::HolderCollision => "holder_collision",
            EventKind::SpindleOffCut => "spindle_off_cut",
            EventKind::PlungeNonCentreCutting => "plunge_non_centre_cutting",
            EventKind::ToolUnknown => "tool_unknown",
        }
    }

    /// True for the collisions (exit status 3); false for the warning.
    pub fn is_collision(self) -> bool {
        self != EventKind::ToolUnknown
    }
}

/// One event: what, where in the program, when, where on the machine.
#[derive(Clone, Debug, PartialEq)]
pub struct SimEvent {
    pub kind: EventKind,
    /// File index (as in the events' `SrcRef`) and 1-based line.
    pub file: u32,
    pub line: u32,
    /// Machine time, s.
    pub t: f64,
    /// Work coordinates X Y Z of the tool tip at the first contact (lathe
    /// X as a radius), mm.
    pub at: [f64; 3],
    /// Material involved, mm³.
    pub volume_mm3: f64,
    /// The tool number.
    pub tool: u32,
}

/// The result of a simulation.
#[derive(Clone, Debug, PartialEq)]
pub struct SimReport {
    pub stock_mm3: f64,
    pub removed_mm3: f64,
    pub remaining_mm3: f64,
    /// Cell size (mill: X and Y, the larger; lathe: Z column width), mm.
    pub resolution_mm: f64,
    pub events: Vec<SimEvent>,
    /// Events not kept after the first [`crate::MAX_EVENTS`].
    pub events_dropped: u64,
    /// Collision events found, kept or not.
    pub collisions: u64,
}

impl SimReport {
    /// True when any event is a collision.
    pub fn collided(&self) -> bool {
        self.collisions > 0
    }
}
