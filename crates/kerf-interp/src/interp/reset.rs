//! RESET (000 §14.4 (5), fanuc-semantics §7.9): what the control clears
//! when the operator presses RESET, so an embedding runtime can stop a run
//! and start it again from the program head.

use super::*;

impl Interp {
    /// Resets the control as the RESET key does, leaving the interpreter
    /// ready to run the main program again from its start:
    ///
    /// - every subprogram and macro call is left (the main program's file,
    ///   start and O header are current again), the WHILE/DO loops and the
    ///   Hurco repeat loops are closed, G66 modal calls are cancelled, the
    ///   main-program `M99 L` count is dropped;
    /// - local variables #1-#33 (and #34-#99 on the HX) become vacant, unless
    ///   the profile parameter `clear_locals_on_reset` is 0 (Fanuc
    ///   No.6001#7 CLV = 1);
    /// - common variables #100-#199 become vacant, unless the profile
    ///   parameter `clear_commons_on_reset` is 0 (Fanuc No.6001#6 CCV = 1;
    ///   000 §14.4 (5) clears them and names a parameter whose value is
    ///   unreadable); retained variables (#200-#699 HX, #500-#999 Fanuc)
    ///   are kept;
    /// - #3003 and #3004 go back to 0 (fanuc-semantics §7.8);
    /// - the modal G codes return to their power-on state (on the HX the
    ///   reset states of PI 144-146), except inch/metric (G20/G21), which
    ///   keeps its value (PI 147 is a power-on state); the tool length
    ///   offset is cancelled (G49) and the spindle and coolant are off;
    /// - the transforms (G16, G51, G68, G112/G107) and G52 return to their
    ///   power-on state with the modal codes, canned-cycle data is cleared
    ///   and a move held for its ,C/,R is dropped;
    /// - kept: positions, work offsets, the G92/G50 shift, the G22 area,
    ///   the tool in the
    ///   spindle, F and S, the H and D tables, interface signals, clocks,
    ///   the G28 intermediate point;
    /// - pending commands and a pending alarm are dropped, the loop-guard
    ///   counters start again, and the next [`Interp::step`] reads the
    ///   first block of the main program.
    ///
    /// Reset emits no event: the runtime that presses RESET knows the
    /// spindle and coolant are off.
    pub fn reset(&mut self) {
        self.prog
            .cache
            .give_back(&mut self.prog.raw, &mut self.prog.block);
        self.reset_calls();
        self.prog.loops.clear();
        self.prog.hurco_loops.clear();
        if self.cfg.profile.param("clear_locals_on_reset", 1.0) != 0.0 {
            self.vars.clear_locals();
        }
        if self.cfg.profile.param("clear_commons_on_reset", 1.0) != 0.0 {
            self.vars.clear_commons();
        }
        self.sys.c3003 = 0.0;
        self.sys.c3004 = 0.0;
        let units = self.modal.units;
        self.modal = modal::Modal::at_power_on(&self.cfg.profile, self.cfg.dialect);
        self.modal.units = units;
        let keep_tlo = self.cfg.dialect.caps.reset_keeps_tool_offset;
        let fresh = frames::Frames::power_on(&self.cfg.profile);
        self.frames = self.frames.after_reset(fresh, keep_tlo);
        self.tool.reset();
        // Canned-cycle data goes with the cycle mode (G80 is the power-on
        // state); a move held for its ,C/,R is dropped.
        self.hx.cyc.clear();
        if keep_tlo {
            // The T offset stays active with its number; drill data and an
            // offset change waiting for its move go.
            self.hurco.drill = Default::default();
            self.hurco.pending = None;
        }
        self.common.drop_held();
        // Lathe single-cycle data and M76 go with the modes (the G70-G76
        // first-block values are parameters and stay).
        self.puma.single = None;
        self.puma.chamfer_on = false;
        self.puma.ddi_base = None;
        self.queue.clear();
        self.common.after_block = None;
        self.finished = false;
        self.guard.restart();
        let start = self.prog.program_start;
        // Lazy: an error would show at the next read.
        if let Some(src) = self.prog.src.as_mut() {
            let _ = src.seek(start);
        }
    }
}
