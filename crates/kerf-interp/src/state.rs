//! Retained macro variables kept across runs in a state directory
//! (`kerf run --state DIR`). One text file per machine profile,
//! `DIR/<profile>.vars`:
//!
//! ```text
//! # kerf retained macro variables
//! #500 = 12.5
//! #501 = -0.001
//! ```
//!
//! Only variables that hold a value are written; values are written with
//! the shortest text that reads back to the same `f64`. The file is
//! replaced atomically: written to a temporary file in the same directory,
//! flushed to disk (fsync), then renamed over the old one (and the
//! directory synced), so a crash leaves either the old or the new file,
//! never a torn one.

use std::fs::{self, File};
use std::io::{self, Write};
use std::path::{Path, PathBuf};

use crate::Interp;

/// The state file of a profile in `dir`.
pub fn state_file(dir: &Path, profile: &str) -> PathBuf {
    let safe: String = profile
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '-' || c == '_' {
                c
            } else {
                '_'
            }
        })
        .collect();
    dir.join(format!("{safe}.vars"))
}

/// Loads the retained variables of `it`'s profile from `dir` (a missing
/// file means none are set). A malformed line is an error naming it.
pub fn load_retained(dir: &Path, it: &mut Interp) -> Result<(), String> {
    let path = state_file(dir, &it.profile().name);
    let text = match fs::read_to_string(&path) {
        Ok(t) => t,
        Err(e) if e.kind() == io::ErrorKind::NotFound => return Ok(()),
        Err(e) => return Err(format!("{}: {e}", path.display())),
    };
    for (n, line) in text.lines().enumerate() {
        let line = line.trim();
        if line.is_empty() || line.starts_with("# ") || line == "#" {
            continue;
        }
        let bad = || format!("{}:{}: expected '#N = VALUE'", path.display(), n + 1);
        let rest = line.strip_prefix('#').ok_or_else(bad)?;
        let (num, val) = rest.split_once('=').ok_or_else(bad)?;
        let i: usize = num.trim().parse().map_err(|_| bad())?;
        let v: f64 = val.trim().parse().map_err(|_| bad())?;
        if !it.set_retained_var(i, v) {
            return Err(format!(
                "{}:{}: #{i} is not a retained variable of this control",
                path.display(),
                n + 1
            ));
        }
    }
    Ok(())
}

/// Writes the retained variables of `it` to `dir` atomically.
pub fn save_retained(dir: &Path, it: &Interp) -> io::Result<()> {
    let path = state_file(dir, &it.profile().name);
    let mut text = String::from("# kerf retained macro variables\n");
    for (i, v) in it.retained_vars() {
        text.push_str(&format!("#{i} = {v:?}\n"));
    }
    let tmp = dir.join(format!(
        ".{}.tmp{}",
        path.file_name().and_then(|n| n.to_str()).unwrap_or("state"),
        std::process::id()
    ));
    let write = || -> io::Result<()> {
        let mut f = File::create(&tmp)?;
        f.write_all(text.as_bytes())?;
        f.sync_all()?;
        drop(f);
        fs::rename(&tmp, &path)?;
        // Make the rename itself durable (not possible on every system).
        if let Ok(d) = File::open(dir) {
            let _ = d.sync_all();
        }
        Ok(())
    };
    let r = write();
    if r.is_err() {
        let _ = fs::remove_file(&tmp);
    }
    r
}
