//! Fuzz target `inputs`: the text a user hands kerf besides the program.
//! Byte 0 chooses the reader, the rest is its input:
//!
//! - 0, 1: a `--tools` file (kerf_sim::parse_tools), mill and lathe meaning;
//! - 2: a `--stock` spec (kerf_sim::Stock::parse); an accepted stock must
//!   have a finite, non-negative volume;
//! - 3: a body sent to the browser screen's command endpoint
//!   (kerf_hmi::command::parse);
//! - 4, 5: an `--offsets` file (kerf_control::offsets::load) into the
//!   interpreter of `hx-mc` and of `puma-lathe`.
//!
//! Nothing may panic, hang or allocate without bound; every refusal is an
//! error value.
#![no_main]

use std::io::Write;
use std::sync::OnceLock;

use kerf_interp::{Interp, Profile, Settings};
use libfuzzer_sys::fuzz_target;

/// A per-process scratch file for the path-based offsets reader.
fn scratch() -> &'static std::path::PathBuf {
    static P: OnceLock<std::path::PathBuf> = OnceLock::new();
    P.get_or_init(|| std::env::temp_dir().join(format!("kerf-fuzz-offsets-{}.toml", std::process::id())))
}

fn load_offsets(machine: &str, text: &[u8]) {
    let profile = Profile::builtin(machine).expect("built-in profile");
    let mut it = Interp::new(profile, Settings::default());
    let path = scratch();
    let mut f = std::fs::File::create(path).expect("scratch file");
    f.write_all(text).expect("scratch write");
    drop(f);
    let _ = kerf_control::offsets::load(path, &mut it);
}

fuzz_target!(|data: &[u8]| {
    let Some((&which, rest)) = data.split_first() else {
        return;
    };
    match which % 6 {
        0 | 1 => {
            if let Ok(text) = std::str::from_utf8(rest) {
                let _ = kerf_sim::parse_tools(text, which % 6 == 1);
            }
        }
        2 => {
            if let Ok(text) = std::str::from_utf8(rest) {
                if let Ok(stock) = kerf_sim::Stock::parse(text) {
                    let v = stock.volume();
                    assert!(v.is_finite() && v >= 0.0, "stock {text:?} volume {v}");
                }
            }
        }
        3 => {
            let _ = kerf_hmi::command::parse(rest);
        }
        4 => load_offsets("hx-mc", rest),
        _ => load_offsets("puma-lathe", rest),
    }
});
