//! `--offsets FILE`: work offsets and tool offset memory in TOML
//! (docs/formats.md "Offsets"):
//!
//! ```toml
//! [g54]          # machine coordinates of the G54 work zero
//! x = -400.0
//! y = -250.0
//! z = -250.0
//!
//! [h]            # tool length offsets (geometry), mm
//! 1 = 50.0
//! [h_wear]
//! 1 = -0.02
//! [d]            # cutter radius offsets (geometry), mm
//! 8 = 5.0
//! [d_wear]
//! 8 = 0.01
//!
//! [tool.2]       # lathe tool offset 02
//! x = 0.75       # as on the offset page: a diameter on diameter programming
//! z = -0.93
//! r = 0.4
//! tip = 3
//!
//! [fixture.2]    # Hurco fixture offset E2: machine coordinates of its
//! z = -300.0     # part zero, mm (X a radius), like [g54] (= E1)
//! ```

use std::path::{Path, PathBuf};

use kerf_interp::machine::{axis_by_name, AxisMap};
use kerf_interp::offsets::MillOffset;
use kerf_interp::{Interp, Profile};
use toml::{Table, Value};

use crate::job::LoadError;

/// An offsets file that could not be read: the file and what is wrong.
#[derive(Debug, thiserror::Error)]
#[error("{}: {problem}", path.display())]
pub struct OffsetsError {
    /// The file.
    pub path: PathBuf,
    /// What is wrong with it (boxed: TOML's errors are large).
    pub problem: Box<Problem>,
}

/// What is wrong with an offsets file (the message names the table and
/// key as the file writes them).
#[derive(Debug, thiserror::Error)]
pub enum Problem {
    /// It could not be read.
    #[error("{0}")]
    Read(#[from] std::io::Error),
    /// It is not TOML.
    #[error("{0}")]
    Toml(#[from] toml::de::Error),
    /// A top-level key that is not a table.
    #[error("'{0}' must be a table")]
    NotTable(String),
    /// A value that must be a number (named as `[page] key`).
    #[error("{0} must be a number")]
    NotNumber(String),
    /// An offset number outside 1 to the machine's count.
    #[error("[{page}] key '{key}' is not an offset number (1-{max} on this machine)")]
    OffsetNumber {
        /// The table.
        page: String,
        /// The key as written.
        key: String,
        /// The machine's last offset number.
        max: usize,
    },
    /// `[tool.N]` that is not a table.
    #[error("[tool.{0}] must be a table")]
    ToolNotTable(String),
    /// A lathe tip direction that is not 0-9 (named as `[tool.N] tip`).
    #[error("{0}: tip direction is 0-9")]
    Tip(String),
    /// A lathe tool field that does not exist.
    #[error("{0}: unknown field (x, z, r, tip, wear_x, wear_z, wear_r)")]
    ToolField(String),
    /// A table that is none of the offset pages.
    #[error("unknown table '{0}' (g54 … g59, h, h_wear, d, d_wear, tool.N, fixture.N)")]
    UnknownTable(String),
    /// A work or fixture table whose values are not axis positions.
    #[error("[{table}]: {source}")]
    Axes {
        /// The table (`g54`, `fixture.2`).
        table: String,
        /// What TOML said.
        source: toml::de::Error,
    },
    /// An axis the machine does not have.
    #[error("[{table}] names axis '{axis}' the machine does not have")]
    MissingAxis {
        /// The table.
        table: String,
        /// The axis as written.
        axis: String,
    },
    /// `[fixture.N]` with N outside 1-9999.
    #[error("[fixture.{0}]: not a fixture offset number (1-9999)")]
    FixtureNumber(String),
}

impl From<OffsetsError> for LoadError {
    fn from(e: OffsetsError) -> LoadError {
        LoadError(e.to_string())
    }
}

/// Loads the file into the interpreter's work offsets and offset memory.
pub fn load(path: &Path, it: &mut Interp) -> Result<(), OffsetsError> {
    load_table(path, it).map_err(|problem| OffsetsError {
        path: path.to_path_buf(),
        problem: Box::new(problem),
    })
}

fn load_table(path: &Path, it: &mut Interp) -> Result<(), Problem> {
    let text = std::fs::read_to_string(path)?;
    let top: Table = toml::from_str(&text)?;
    for (k, v) in &top {
        let key = k.to_ascii_lowercase();
        let Value::Table(t) = v else {
            return Err(Problem::NotTable(k.clone()));
        };
        match key.as_str() {
            "h" | "h_wear" | "d" | "d_wear" => mill_page(&key, t, it)?,
            "tool" => {
                for (n, e) in t {
                    lathe_entry(n, e, it)?;
                }
            }
            "fixture" => {
                for (n, e) in t {
                    fixture_entry(n, e, it)?;
                }
            }
            _ => work_system(&key, v, it)?,
        }
    }
    Ok(())
}

fn number(v: &Value, what: &str) -> Result<f64, Problem> {
    match v {
        Value::Float(f) => Ok(*f),
        Value::Integer(i) => Ok(*i as f64),
        _ => Err(Problem::NotNumber(what.to_string())),
    }
}

fn offset_number(n: &str, page: &str, it: &Interp) -> Result<usize, Problem> {
    let max = it.offsets().count();
    match n.parse::<usize>() {
        Ok(i) if (1..=max).contains(&i) => Ok(i),
        _ => Err(Problem::OffsetNumber {
            page: page.to_string(),
            key: n.to_string(),
            max,
        }),
    }
}

/// The axis positions of a work or fixture table, every axis one the
/// machine has.
fn axes_of(table: &str, v: &Value, it: &Interp) -> Result<AxisMap, Problem> {
    let axes: AxisMap = v.clone().try_into().map_err(|source| Problem::Axes {
        table: table.to_string(),
        source,
    })?;
    for a in axes.keys() {
        match axis_by_name(a) {
            Some(ax) if it.profile().has_axis(ax) => {}
            _ => {
                return Err(Problem::MissingAxis {
                    table: table.to_string(),
                    axis: a.clone(),
                })
            }
        }
    }
    Ok(axes)
}

fn mill_page(page: &str, t: &Table, it: &mut Interp) -> Result<(), Problem> {
    for (n, v) in t {
        let i = offset_number(n, page, it)?;
        let x = number(v, &format!("[{page}] {n}"))?;
        let table = it.offsets_mut();
        let e: &mut MillOffset = if page.starts_with('h') {
            table.h_mut(i)
        } else {
            table.d_mut(i)
        }
        .expect("offset number checked");
        if page.ends_with("_wear") {
            e.wear = x;
        } else {
            e.geom = x;
        }
    }
    Ok(())
}

fn lathe_entry(n: &str, v: &Value, it: &mut Interp) -> Result<(), Problem> {
    let i = offset_number(n, "tool", it)?;
    let Value::Table(t) = v else {
        return Err(Problem::ToolNotTable(n.to_string()));
    };
    // X values are written as on the offset page: a diameter on a control
    // that programs X as a diameter; stored as a radius.
    let xs = if it.diameter_programming() { 0.5 } else { 1.0 };
    let e = it
        .offsets_mut()
        .lathe_mut(i)
        .expect("offset number checked");
    for (k, v) in t {
        let what = format!("[tool.{n}] {k}");
        let x = number(v, &what)?;
        match k.as_str() {
            "x" => e.x = x * xs,
            "z" => e.z = x,
            "r" => e.r = x,
            "wear_x" => e.wear_x = x * xs,
            "wear_z" => e.wear_z = x,
            "wear_r" => e.wear_r = x,
            "tip" if x.fract() == 0.0 && (0.0..=9.0).contains(&x) => e.tip = x as u8,
            "tip" => return Err(Problem::Tip(what)),
            _ => return Err(Problem::ToolField(what)),
        }
    }
    Ok(())
}

fn work_system(k: &str, v: &Value, it: &mut Interp) -> Result<(), Problem> {
    let idx = match k {
        "g54" => 0,
        "g55" => 1,
        "g56" => 2,
        "g57" => 3,
        "g58" => 4,
        "g59" => 5,
        other => return Err(Problem::UnknownTable(other.to_string())),
    };
    let axes = axes_of(k, v, it)?;
    it.set_work_offset(idx, Profile::pos_of(&axes));
    Ok(())
}

/// `[fixture.N]`: Hurco fixture offset E`N` (1-9999), machine coordinates
/// of its part zero in mm, X as a radius ([g54] is E1).
fn fixture_entry(n: &str, v: &Value, it: &mut Interp) -> Result<(), Problem> {
    let bad = || Problem::FixtureNumber(n.to_string());
    let i: u32 = n.parse().map_err(|_| bad())?;
    let axes = axes_of(&format!("fixture.{n}"), v, it)?;
    if !it.set_fixture_offset(i, Profile::pos_of(&axes)) {
        return Err(bad());
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn interp() -> Interp {
        Interp::new(
            Profile::builtin("puma-lathe").unwrap(),
            kerf_interp::Settings::default(),
        )
    }

    fn load_text(text: &str) -> Result<Interp, OffsetsError> {
        let dir = std::env::temp_dir().join(format!("kerf-offsets-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join(format!(
            "{:x}.toml",
            text.len() * 31 + text.bytes().map(usize::from).sum::<usize>()
        ));
        std::fs::write(&path, text).unwrap();
        let mut it = interp();
        let r = load(&path, &mut it);
        let _ = std::fs::remove_file(&path);
        r.map(|_| it)
    }

    #[test]
    fn errors_name_the_file_the_table_and_the_key() {
        let err = |t: &str| load_text(t).err().expect("an error");
        let e = err("[tool.99]\nx = 1.0\n");
        assert!(
            matches!(*e.problem, Problem::OffsetNumber { max: 16, .. }),
            "{e:?}"
        );
        let msg = e.to_string();
        assert!(
            msg.ends_with(": [tool] key '99' is not an offset number (1-16 on this machine)"),
            "{msg}"
        );
        assert!(msg.starts_with(&e.path.display().to_string()));
        let e = err("[g54]\ny = 1.0\n");
        assert!(e
            .to_string()
            .ends_with(": [g54] names axis 'y' the machine does not have"));
        let e = err("[tool.2]\ntip = 12\n");
        assert!(e
            .to_string()
            .ends_with(": [tool.2] tip: tip direction is 0-9"));
        let e = err("[fixture.0]\nz = 1.0\n");
        assert!(matches!(*e.problem, Problem::FixtureNumber(_)));
    }

    #[test]
    fn a_lathe_x_is_stored_as_a_radius() {
        // The PUMA programs X as a diameter: x = 0.75 is a radius of 0.375.
        let Ok(it) = load_text("[tool.2]\nx = 0.75\nz = -0.93\n") else {
            panic!("loads")
        };
        let t = it.offsets().lathe(2);
        assert_eq!((t.x, t.z), (0.375, -0.93));
    }
}
