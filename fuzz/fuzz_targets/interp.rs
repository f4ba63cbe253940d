//! Fuzz target `interp`: arbitrary bytes run as a main program on every
//! built-in machine until the end, an alarm, or a step cap. The interpreter
//! must never panic, hang or exhaust memory (design.md: "No input, however
//! malformed or hostile, may panic, hang, or exhaust memory").
#![no_main]

use kerf_interp::{Interp, Settings, Step};
use libfuzzer_sys::fuzz_target;

mod machines;
use machines::profiles;

/// Most canonical commands taken from one run before we stop it.
const MAX_STEPS: usize = 5_000;
/// The interpreter's own loop guard (blocks executed).
const MAX_BLOCKS: u64 = 5_000;

fuzz_target!(|data: &[u8]| {
    for profile in profiles() {
        let settings = Settings {
            max_blocks: MAX_BLOCKS,
            block_skip: 0b10,
            ..Settings::default()
        };
        let mut it = Interp::new(profile.clone(), settings);
        it.load_main("fuzz.nc", Box::new(std::io::Cursor::new(data.to_vec())));
        for _ in 0..MAX_STEPS {
            match it.step() {
                Step::Event(_) => {}
                Step::End => break,
                Step::Alarm(a) => {
                    // Every alarm carries a usable source position and text.
                    assert!(a.src.line >= 1, "alarm with line 0: {a:?}");
                    assert!(
                        !a.code.is_empty() && !a.message.is_empty(),
                        "empty alarm: {a:?}"
                    );
                    let _ = it.file_name(a.src.file);
                    break;
                }
            }
        }
    }
});
