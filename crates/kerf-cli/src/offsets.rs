//! `--offsets FILE`: work offsets in TOML, one table per work system with
//! the machine coordinates of its zero:
//!
//! ```toml
//! [g54]
//! x = -400.0
//! y = -250.0
//! z = -250.0
//!
//! [h]          # tool length offsets H1-H128, mm
//! 1 = 50.0
//! ```

use std::collections::BTreeMap;
use std::path::Path;

use kerf_interp::machine::{axis_by_name, AxisMap};
use kerf_interp::{Interp, Profile};

/// Loads the file into the interpreter's work offset table.
pub fn load(path: &Path, it: &mut Interp) -> Result<(), String> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let map: BTreeMap<String, AxisMap> =
        toml::from_str(&text).map_err(|e| format!("{}: {e}", path.display()))?;
    for (k, axes) in &map {
        if k.eq_ignore_ascii_case("h") {
            for (n, v) in axes {
                let n: usize = n
                    .parse()
                    .map_err(|_| format!("{}: [h] keys are offset numbers", path.display()))?;
                if n == 0 || n > 128 {
                    return Err(format!("{}: H{n} out of range (H1-H128)", path.display()));
                }
                it.set_h(n, *v);
            }
            continue;
        }
        let idx = match k.to_ascii_lowercase().as_str() {
            "g54" => 0,
            "g55" => 1,
            "g56" => 2,
            "g57" => 3,
            "g58" => 4,
            "g59" => 5,
            other => {
                return Err(format!(
                    "{}: unknown work system '{other}' (g54 … g59)",
                    path.display()
                ))
            }
        };
        for a in axes.keys() {
            match axis_by_name(a) {
                Some(ax) if it.profile().has_axis(ax) => {}
                _ => {
                    return Err(format!(
                        "{}: [{k}] names axis '{a}' the machine does not have",
                        path.display()
                    ))
                }
            }
        }
        it.set_work_offset(idx, Profile::pos_of(axes));
    }
    Ok(())
}
