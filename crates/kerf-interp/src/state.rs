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
//!
//! The tool offset memory is kept beside it in `DIR/<profile>.offsets`
//! (only entries that are not all zero; lengths in mm, lathe X as a
//! radius):
//!
//! ```text
//! # kerf tool offsets: H|D n geometry wear / T n x z r tip wear_x wear_z wear_r
//! H 1 100.0 -0.25
//! D 8 5.0 0.0
//! T 2 0.75 -0.93 0.4 3 0.0 0.0 0.0
//! ```

use std::fs::{self, File};
use std::io::{self, Write};
use std::path::{Path, PathBuf};

use crate::offsets::{LatheOffset, MillOffset};
use crate::Interp;

/// Why a state file could not be read: the file, and the line at fault.
#[derive(Debug, thiserror::Error)]
pub enum StateError {
    /// The file exists but could not be read.
    #[error("{}: {source}", path.display())]
    Read {
        /// The file.
        path: PathBuf,
        /// What the system said.
        source: io::Error,
    },
    /// A line that is not in the file's format.
    #[error("{}:{line}: {why}", path.display())]
    Line {
        /// The file.
        path: PathBuf,
        /// 1-based line number.
        line: usize,
        /// What is wrong with it.
        why: String,
    },
}

/// Reads a state file; None when it does not exist.
fn read_state(path: &Path) -> Result<Option<String>, StateError> {
    match fs::read_to_string(path) {
        Ok(t) => Ok(Some(t)),
        Err(e) if e.kind() == io::ErrorKind::NotFound => Ok(None),
        Err(source) => Err(StateError::Read {
            path: path.to_path_buf(),
            source,
        }),
    }
}

/// The state file of a profile in `dir`.
pub fn state_file(dir: &Path, profile: &str) -> PathBuf {
    state_path(dir, profile, "vars")
}

/// The offset memory file of a profile in `dir`.
pub fn offsets_file(dir: &Path, profile: &str) -> PathBuf {
    state_path(dir, profile, "offsets")
}

fn state_path(dir: &Path, profile: &str, ext: &str) -> PathBuf {
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
    dir.join(format!("{safe}.{ext}"))
}

/// Loads the retained variables of `it`'s profile from `dir` (a missing
/// file means none are set). A malformed line is an error naming it.
pub fn load_retained(dir: &Path, it: &mut Interp) -> Result<(), StateError> {
    let path = state_file(dir, &it.profile().name);
    let Some(text) = read_state(&path)? else {
        return Ok(());
    };
    for (n, line) in text.lines().enumerate() {
        let line = line.trim();
        if line.is_empty() || line.starts_with("# ") || line == "#" {
            continue;
        }
        let at = |why: String| StateError::Line {
            path: path.clone(),
            line: n + 1,
            why,
        };
        let bad = || at("expected '#N = VALUE'".into());
        let rest = line.strip_prefix('#').ok_or_else(bad)?;
        let (num, val) = rest.split_once('=').ok_or_else(bad)?;
        let i: usize = num.trim().parse().map_err(|_| bad())?;
        let v: f64 = val.trim().parse().map_err(|_| bad())?;
        if !it.set_retained_var(i, v) {
            return Err(at(format!(
                "#{i} is not a retained variable of this control"
            )));
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
    write_atomic(dir, &path, &text)
}

/// Loads the offset memory of `it`'s profile from `dir` (a missing file
/// leaves it as it is). A malformed line is an error naming it.
pub fn load_offsets(dir: &Path, it: &mut Interp) -> Result<(), StateError> {
    let path = offsets_file(dir, &it.profile().name);
    let Some(text) = read_state(&path)? else {
        return Ok(());
    };
    for (n, line) in text.lines().enumerate() {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let bad = |why: &str| StateError::Line {
            path: path.clone(),
            line: n + 1,
            why: why.to_string(),
        };
        let mut f = line.split_whitespace();
        let page = f.next().unwrap_or("");
        let num: usize = f
            .next()
            .and_then(|x| x.parse().ok())
            .ok_or_else(|| bad("expected an offset number"))?;
        let vals: Vec<f64> = f
            .map(|x| x.parse::<f64>())
            .collect::<Result<_, _>>()
            .map_err(|_| bad("expected numbers"))?;
        if vals.iter().any(|v| !v.is_finite()) {
            return Err(bad("values must be finite"));
        }
        let table = it.offsets_mut();
        match (page, vals.as_slice()) {
            ("H" | "D", &[geom, wear]) => {
                let e = if page == "H" {
                    table.h_mut(num)
                } else {
                    table.d_mut(num)
                }
                .ok_or_else(|| bad("no such offset number on this machine"))?;
                e.geom = geom;
                e.wear = wear;
            }
            ("T", &[x, z, r, tip, wx, wz, wr]) => {
                if tip.fract() != 0.0 || !(0.0..=9.0).contains(&tip) {
                    return Err(bad("tip direction must be 0-9"));
                }
                let e = table
                    .lathe_mut(num)
                    .ok_or_else(|| bad("no such offset number on this machine"))?;
                *e = LatheOffset {
                    x,
                    z,
                    r,
                    tip: tip as u8,
                    wear_x: wx,
                    wear_z: wz,
                    wear_r: wr,
                };
            }
            _ => {
                return Err(bad(
                    "expected 'H|D n geometry wear' or 'T n x z r tip wear_x wear_z wear_r'",
                ))
            }
        }
    }
    Ok(())
}

/// Writes the offset memory of `it` to `dir` atomically.
pub fn save_offsets(dir: &Path, it: &Interp) -> io::Result<()> {
    let path = offsets_file(dir, &it.profile().name);
    let t = it.offsets();
    let mut text = String::from(
        "# kerf tool offsets: H|D n geometry wear / T n x z r tip wear_x wear_z wear_r\n",
    );
    for n in 1..=t.count() {
        for (page, e) in [("H", t.h_entry(n)), ("D", t.d_entry(n))] {
            if let Some(e) = e.filter(|e| **e != MillOffset::default()) {
                text.push_str(&format!("{page} {n} {:?} {:?}\n", e.geom, e.wear));
            }
        }
    }
    for n in 1..=t.count() {
        let o = t.lathe(n);
        if o != LatheOffset::default() {
            text.push_str(&format!(
                "T {n} {:?} {:?} {:?} {} {:?} {:?} {:?}\n",
                o.x, o.z, o.r, o.tip, o.wear_x, o.wear_z, o.wear_r
            ));
        }
    }
    write_atomic(dir, &path, &text)
}

/// Replaces `path` (in `dir`) with `text`: a temporary file `.NAME.tmpPID`
/// in the same folder, fsync, rename, folder fsync. A reader sees the old
/// file or the new one, never a torn one.
pub fn write_atomic(dir: &Path, path: &Path, text: &str) -> io::Result<()> {
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
        fs::rename(&tmp, path)?;
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Profile, Settings};

    fn interp() -> Interp {
        Interp::new(Profile::builtin("hx-mc").unwrap(), Settings::default())
    }

    #[test]
    fn a_bad_line_names_the_file_and_the_line() {
        let dir = std::env::temp_dir().join(format!("kerf-state-test-{}", std::process::id()));
        fs::create_dir_all(&dir).unwrap();
        let vars = state_file(&dir, "hx-mc");
        // #100 is a common variable, not retained (000 §14.2.3: #200-#699).
        fs::write(
            &vars,
            "# kerf retained macro variables\n#200 = 1.5\n#100 = 2\n",
        )
        .unwrap();
        let e = load_retained(&dir, &mut interp()).unwrap_err();
        assert!(
            matches!(&e, StateError::Line { path, line: 3, .. } if *path == vars),
            "{e:?}"
        );
        let want = format!(
            "{}:3: #100 is not a retained variable of this control",
            vars.display()
        );
        assert_eq!(e.to_string(), want);
        fs::write(offsets_file(&dir, "hx-mc"), "H 1 abc 0\n").unwrap();
        let e = load_offsets(&dir, &mut interp()).unwrap_err();
        assert!(
            e.to_string().ends_with(".offsets:1: expected numbers"),
            "{e}"
        );
        let _ = fs::remove_dir_all(&dir);
    }
}
