//! The programs the expansion tests run: every example under `examples/`
//! (machine and `--set` switches from its `.expect.toml` files), the
//! shared corpus beside the repository (machine by folder, as
//! tests/corpus.rs), the rs274 reference programs of kerf-interp, and the
//! programs written for the expansion (`tests/expand/MACHINE/*.nc`: macros,
//! cycles, transforms and compensation together).

#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::Command;

/// One program with the arguments it runs with.
#[derive(Clone, Debug)]
pub struct Case {
    pub label: String,
    pub program: PathBuf,
    /// `--machine` argument (a built-in name or a profile file).
    pub machine: String,
    pub sets: Vec<String>,
    /// `--lib` folders.
    pub libs: Vec<PathBuf>,
}

impl Case {
    /// True for programs of the machining center.
    pub fn is_mill(&self) -> bool {
        self.machine.starts_with("hx-mc")
    }

    /// `kerf SUB PROGRAM --machine M --set …` with the extra arguments.
    pub fn kerf(&self, sub: &str, program: &Path, extra: &[&str]) -> Command {
        let mut c = Command::new(env!("CARGO_BIN_EXE_kerf"));
        c.arg(sub).arg(program).arg("--machine").arg(&self.machine);
        for s in &self.sets {
            c.arg("--set").arg(s);
        }
        for l in &self.libs {
            c.arg("--lib").arg(l);
        }
        c.args(extra);
        c
    }
}

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn sorted_files(dir: &Path) -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(dir)
        .map(|rd| rd.filter_map(|e| e.ok().map(|e| e.path())).collect())
        .unwrap_or_default();
    v.sort();
    v
}

/// Every example with each of its expectation variants.
pub fn examples() -> Vec<Case> {
    let mut out = Vec::new();
    for folder in ["hx", "puma", "hurco"] {
        let dir = root().join("examples").join(folder);
        for expect in sorted_files(&dir) {
            let name = expect.file_name().unwrap().to_string_lossy().to_string();
            let Some(base) = name.strip_suffix(".expect.toml") else {
                continue;
            };
            let stem = base.split('.').next().unwrap();
            let program = dir.join(format!("{stem}.nc"));
            let direct = dir.join(format!("{base}.nc"));
            let program = if direct.is_file() { direct } else { program };
            let t: toml::Table = std::fs::read_to_string(&expect).unwrap().parse().unwrap();
            let machine = t.get("machine").and_then(|v| v.as_str()).unwrap_or("hx-mc");
            let machine = if machine.ends_with(".toml") {
                dir.join(machine).display().to_string()
            } else {
                machine.to_string()
            };
            let sets = t
                .get("set")
                .and_then(|v| v.as_array())
                .map(|a| {
                    a.iter()
                        .filter_map(|s| s.as_str().map(String::from))
                        .collect()
                })
                .unwrap_or_default();
            out.push(Case {
                label: format!("examples/{folder}/{base}"),
                program,
                machine,
                sets,
                libs: Vec::new(),
            });
        }
    }
    out
}

/// The shared corpus programs (none when the folder is absent).
pub fn corpus() -> Vec<Case> {
    let dir = root().join("../shared/corpus");
    let mut out = Vec::new();
    for sub in sorted_files(&dir) {
        let folder = sub
            .file_name()
            .unwrap()
            .to_string_lossy()
            .to_ascii_lowercase();
        let machine = if folder.starts_with("mill") {
            "hx-mc"
        } else if folder.starts_with("lathe") {
            "puma-lathe"
        } else if folder.starts_with("hurco") {
            "hurco-lathe"
        } else {
            continue;
        };
        for p in sorted_files(&sub) {
            out.push(Case {
                label: format!(
                    "corpus/{folder}/{}",
                    p.file_name().unwrap().to_string_lossy()
                ),
                program: p,
                machine: machine.into(),
                sets: Vec::new(),
                libs: Vec::new(),
            });
        }
    }
    out
}

/// kerf-interp's rs274 reference programs (HX).
pub fn rs274_programs() -> Vec<Case> {
    let dir = root().join("crates/kerf-interp/tests/rs274");
    sorted_files(&dir)
        .into_iter()
        .filter(|p| {
            let n = p.file_name().unwrap().to_string_lossy();
            n.ends_with(".nc") && !n.ends_with(".rs274.nc")
        })
        .map(|p| Case {
            label: format!("rs274/{}", p.file_name().unwrap().to_string_lossy()),
            program: p,
            machine: "hx-mc".into(),
            sets: vec!["PI 129=0.254".into()],
            libs: Vec::new(),
        })
        .collect()
}

/// The expansion's own programs, `tests/expand/MACHINE/NAME.nc`, run
/// with `--lib tests/expand/lib`.
pub fn expand_programs() -> Vec<Case> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/expand");
    let mut out = Vec::new();
    for sub in sorted_files(&dir) {
        let machine = sub.file_name().unwrap().to_string_lossy().to_string();
        if machine == "lib" {
            continue;
        }
        for p in sorted_files(&sub) {
            out.push(Case {
                label: format!(
                    "expand/{machine}/{}",
                    p.file_name().unwrap().to_string_lossy()
                ),
                program: p,
                machine: machine.clone(),
                sets: Vec::new(),
                libs: vec![dir.join("lib")],
            });
        }
    }
    out
}

/// A scratch file path for this test binary.
pub fn scratch(label: &str, ext: &str) -> PathBuf {
    let name: String = label
        .chars()
        .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
        .collect();
    Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("{name}.{ext}"))
}

/// The toolpath records of a JSON Lines file.
pub fn records(path: &Path) -> Vec<serde_json::Value> {
    std::fs::read_to_string(path)
        .unwrap_or_default()
        .lines()
        .filter(|l| !l.trim().is_empty())
        .map(|l| serde_json::from_str(l).expect("toolpath line is JSON"))
        .collect()
}
