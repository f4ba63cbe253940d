//! A watcher of the commands the axes finish: every canonical command, in
//! order, once the machine has carried it out (not when the interpreter
//! read it ahead). A screen's simulated part follows the cut with it; a
//! feed hold or a reset leaves the command under way out until (unless)
//! the axes finish it.

use kerf_canon::Event;

use super::Runtime;

/// Called with each command the axes finished.
pub type OnPassed = Box<dyn FnMut(&Event)>;

impl Runtime {
    /// Sets (or with `None` removes) the watcher of finished commands.
    ///
    /// ```
    /// use std::sync::{Arc, Mutex};
    /// use kerf_control::runtime::{Command, Execution, Mode, Runtime};
    ///
    /// let mut rt = Runtime::for_machine("hx-mc").unwrap();
    /// let lines = Arc::new(Mutex::new(Vec::new()));
    /// let l2 = lines.clone();
    /// rt.set_on_passed(Some(Box::new(move |e| l2.lock().unwrap().push(e.src.line))));
    /// rt.command(Command::Mode { mode: Mode::Mem }).unwrap();
    /// rt.load_program("p.nc", "G90 G54 G00 X-50. Y-50.\nG01 X-60. F600\nM30\n").unwrap();
    /// rt.command(Command::CycleStart).unwrap();
    /// rt.run_until_stopped(60.0);
    /// assert_eq!(rt.execution(), Execution::ProgramCompleted);
    /// let lines = lines.lock().unwrap();
    /// assert!(lines.contains(&1) && lines.contains(&2));
    /// ```
    pub fn set_on_passed(&mut self, f: Option<OnPassed>) {
        self.on_passed = f;
    }
}
