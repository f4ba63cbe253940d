//! The built-in profiles the `interp` and `pipeline` targets run every
//! input on, loaded once per fuzzing process.

use std::sync::OnceLock;

use kerf_interp::Profile;

/// The three built-in machines.
const MACHINES: [&str; 3] = ["hx-mc", "puma-lathe", "hurco-lathe"];

/// The built-in profiles, parsed on first use.
pub fn profiles() -> &'static Vec<Profile> {
    static P: OnceLock<Vec<Profile>> = OnceLock::new();
    P.get_or_init(|| {
        MACHINES
            .iter()
            .map(|m| Profile::builtin(m).expect("built-in profile"))
            .collect()
    })
}
