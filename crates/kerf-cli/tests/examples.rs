//! Runs every example program under `examples/<machine>/` that has a
//! hand-computed expectation and compares kerf's toolpath with it.
//!
//! For `examples/hx/NAME.nc` the expectations are `NAME.expect.toml` and any
//! `NAME.VARIANT.expect.toml` (the same program run with other `--set`
//! switches). An expectation file holds:
//!
//! ```toml
//! machine = "hx-mc"          # passed as --machine; a NAME.toml is a
//!                            # profile file in the program's folder
//! status = "completed"       # or "alarm" (exit status 0 / 1)
//! alarm_line = 7             # optional, with status = "alarm"
//! set = ["block_skip=1"]     # optional, each passed as --set
//! block_ends = true          # optional: compare only the last record of
//!                            # each block (G112/G107 cut moves into chords)
//! [[motion]]                 # every motion record, in order
//! kind = "arc"               # compared exactly
//! line = 3                   # compared exactly
//! to = { x = 1.0, z = 2.0 }  # listed axes only, tolerance 1e-3
//! mto = { x = 1.0 }          # optional, machine coordinates
//! center = { x = 0.0 }       # optional (arcs)
//! dir = "cw"                 # optional (arcs)
//! feed = 100.0               # optional, mm/min
//! ```
//!
//! The expectations are computed by hand from the manuals, never from kerf's
//! output. Every mismatch of every example is reported, then the test fails.

use std::path::{Path, PathBuf};
use std::process::Command;

const TOL: f64 = 1e-3;
const RECORD_KEYS: &[&str] = &["kind", "line", "to", "mto", "center", "dir", "feed"];
const TOP_KEYS: &[&str] = &[
    "machine",
    "status",
    "alarm_line",
    "set",
    "block_ends",
    "motion",
];

fn examples_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples")
}

/// (program, expectation file, variant name) for one machine folder.
/// `NAME.expect.toml` belongs to `NAME.nc`; `NAME.VARIANT.expect.toml` to
/// `NAME.nc` too when there is no `NAME.VARIANT.nc`.
fn cases(folder: &str) -> Vec<(PathBuf, PathBuf, String)> {
    let dir = examples_dir().join(folder);
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("cannot read {}: {e}", dir.display()))
        .filter_map(|e| e.ok().map(|e| e.path()))
        .collect();
    files.sort();
    let mut out = Vec::new();
    for expect in files {
        let name = expect.file_name().unwrap().to_string_lossy().to_string();
        let Some(base) = name.strip_suffix(".expect.toml") else {
            continue;
        };
        let direct = dir.join(format!("{base}.nc"));
        if direct.is_file() {
            out.push((direct, expect.clone(), String::new()));
            continue;
        }
        match base.rsplit_once('.') {
            Some((stem, variant)) if dir.join(format!("{stem}.nc")).is_file() => {
                out.push((
                    dir.join(format!("{stem}.nc")),
                    expect.clone(),
                    variant.to_string(),
                ));
            }
            _ => panic!("{}: no program for this expectation", expect.display()),
        }
    }
    out
}

fn num(v: &serde_json::Value) -> Option<f64> {
    v.as_f64()
}

fn toml_num(v: &toml::Value) -> Option<f64> {
    match v {
        toml::Value::Float(f) => Some(*f),
        toml::Value::Integer(i) => Some(*i as f64),
        _ => None,
    }
}

fn compare_axes(
    errs: &mut Vec<String>,
    what: &str,
    field: &str,
    want: &toml::Value,
    got: Option<&serde_json::Value>,
) {
    let Some(want) = want.as_table() else {
        errs.push(format!(
            "{what}: expectation field `{field}` is not a table"
        ));
        return;
    };
    let Some(got) = got.filter(|g| !g.is_null()) else {
        errs.push(format!(
            "{what}: `{field}` missing in toolpath (want {want})"
        ));
        return;
    };
    for (axis, w) in want {
        let Some(w) = toml_num(w) else {
            errs.push(format!(
                "{what}: expectation {field}.{axis} is not a number"
            ));
            continue;
        };
        match got.get(axis).and_then(num) {
            None => errs.push(format!(
                "{what}: {field}.{axis} missing in toolpath (want {w}), got {got}"
            )),
            Some(g) if (g - w).abs() > TOL => errs.push(format!(
                "{what}: {field}.{axis} = {g} but expected {w} (diff {:.6})",
                g - w
            )),
            _ => {}
        }
    }
}

/// Runs one case and returns its mismatches.
fn run_case(prog: &Path, expect: &Path, variant: &str) -> Vec<String> {
    let label = format!(
        "{}{}",
        prog.strip_prefix(examples_dir()).unwrap_or(prog).display(),
        if variant.is_empty() {
            String::new()
        } else {
            format!(" [{variant}]")
        }
    );
    let mut errs = Vec::new();
    let text = std::fs::read_to_string(expect).unwrap();
    let exp: toml::Table = match text.parse() {
        Ok(t) => t,
        Err(e) => {
            return vec![format!(
                "{label}: bad expectation {}: {e}",
                expect.display()
            )]
        }
    };
    for k in exp.keys() {
        if !TOP_KEYS.contains(&k.as_str()) {
            errs.push(format!(
                "{label}: unknown key `{k}` in {}",
                expect.display()
            ));
        }
    }
    let machine = exp
        .get("machine")
        .and_then(|v| v.as_str())
        .unwrap_or("hx-mc");
    let status = exp
        .get("status")
        .and_then(|v| v.as_str())
        .unwrap_or("completed");
    let sets: Vec<String> = exp
        .get("set")
        .and_then(|v| v.as_array())
        .map(|a| {
            a.iter()
                .filter_map(|s| s.as_str().map(String::from))
                .collect()
        })
        .unwrap_or_default();
    let empty = Vec::new();
    let motions = exp
        .get("motion")
        .and_then(|v| v.as_array())
        .unwrap_or(&empty);

    // A profile file named by the expectation lives beside the program.
    let machine_arg = if machine.ends_with(".toml") {
        prog.with_file_name(machine).into_os_string()
    } else {
        machine.into()
    };
    let tmp = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!(
        "examples-{}-{}{}.jsonl",
        machine.trim_end_matches(".toml"),
        prog.file_stem().unwrap().to_string_lossy(),
        if variant.is_empty() {
            String::new()
        } else {
            format!("-{variant}")
        }
    ));
    let _ = std::fs::remove_file(&tmp);
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_kerf"));
    cmd.arg("run")
        .arg(prog)
        .arg("--machine")
        .arg(&machine_arg)
        .arg("--toolpath")
        .arg(&tmp);
    for s in &sets {
        cmd.arg("--set").arg(s);
    }
    let out = match cmd.output() {
        Ok(o) => o,
        Err(e) => return vec![format!("{label}: cannot run kerf: {e}")],
    };
    let stderr = String::from_utf8_lossy(&out.stderr);
    let code = out.status.code();
    let want_code = if status == "alarm" { 1 } else { 0 };
    if code != Some(want_code) {
        errs.push(format!(
            "{label}: exit status {code:?}, expected {want_code} ({status}); stderr: {}",
            stderr.trim()
        ));
    }
    if let Some(al) = exp.get("alarm_line").and_then(|v| v.as_integer()) {
        // `FILE:LINE:COL: alarm CODE: MESSAGE`
        let got = stderr.lines().find_map(|l| {
            let head = l
                .split(": alarm")
                .next()
                .filter(|_| l.contains(": alarm"))?;
            let mut it = head.rsplitn(3, ':');
            let _col = it.next()?;
            it.next()?.trim().parse::<i64>().ok()
        });
        if got != Some(al) {
            errs.push(format!(
                "{label}: alarm line {got:?}, expected {al}; stderr: {}",
                stderr.trim()
            ));
        }
    }

    let path_text = std::fs::read_to_string(&tmp).unwrap_or_default();
    let mut records = Vec::new();
    for (i, l) in path_text.lines().enumerate() {
        if l.trim().is_empty() {
            continue;
        }
        match serde_json::from_str::<serde_json::Value>(l) {
            Ok(v) => records.push(v),
            Err(e) => errs.push(format!("{label}: toolpath line {} is not JSON: {e}", i + 1)),
        }
    }
    if exp.get("block_ends").and_then(|v| v.as_bool()) == Some(true) {
        // Keep the last record of each run of records from one block.
        let key = |r: &serde_json::Value| (r.get("file").cloned(), r.get("line").cloned());
        let mut ends: Vec<serde_json::Value> = Vec::new();
        for r in records {
            if ends.last().is_some_and(|l| key(l) == key(&r)) {
                ends.pop();
            }
            ends.push(r);
        }
        records = ends;
    }
    if records.len() != motions.len() {
        errs.push(format!(
            "{label}: {} motion records, expected {}",
            records.len(),
            motions.len()
        ));
    }
    for (i, want) in motions.iter().enumerate() {
        let Some(want) = want.as_table() else {
            continue;
        };
        for k in want.keys() {
            if !RECORD_KEYS.contains(&k.as_str()) {
                errs.push(format!(
                    "{label}: motion #{}: unknown expectation key `{k}`",
                    i + 1
                ));
            }
        }
        let wline = want.get("line").and_then(|v| v.as_integer());
        let what = format!(
            "{label}: motion #{} (line {})",
            i + 1,
            wline.map(|l| l.to_string()).unwrap_or_else(|| "?".into())
        );
        let Some(got) = records.get(i) else {
            errs.push(format!("{what}: missing from toolpath"));
            continue;
        };
        if let Some(k) = want.get("kind").and_then(|v| v.as_str()) {
            let g = got.get("kind").and_then(|v| v.as_str());
            if g != Some(k) {
                errs.push(format!("{what}: kind {g:?}, expected {k:?}"));
            }
        }
        if let Some(l) = wline {
            let g = got.get("line").and_then(|v| v.as_i64());
            if g != Some(l) {
                errs.push(format!("{what}: line {g:?}, expected {l}"));
            }
        }
        for field in ["to", "mto", "center"] {
            if let Some(w) = want.get(field) {
                compare_axes(&mut errs, &what, field, w, got.get(field));
            }
        }
        if let Some(d) = want.get("dir").and_then(|v| v.as_str()) {
            let g = got.get("dir").and_then(|v| v.as_str());
            if g != Some(d) {
                errs.push(format!("{what}: dir {g:?}, expected {d:?}"));
            }
        }
        if let Some(f) = want.get("feed").and_then(toml_num) {
            match got.get("feed").and_then(num) {
                Some(g) if (g - f).abs() <= TOL => {}
                g => errs.push(format!("{what}: feed {g:?}, expected {f}")),
            }
        }
    }
    // Extra records beyond the expectation: name the first few.
    for (i, r) in records.iter().enumerate().skip(motions.len()).take(3) {
        errs.push(format!("{label}: unexpected motion #{}: {r}", i + 1));
    }
    let _ = std::fs::remove_file(&tmp);
    errs
}

fn check_machine(folder: &str) {
    let cases = cases(folder);
    assert!(!cases.is_empty(), "no expectations under examples/{folder}");
    let mut errs = Vec::new();
    for (prog, expect, variant) in &cases {
        errs.extend(run_case(prog, expect, variant));
    }
    eprintln!(
        "examples/{folder}: {} case(s), {} mismatch(es)",
        cases.len(),
        errs.len()
    );
    if !errs.is_empty() {
        for e in &errs {
            eprintln!("  {e}");
        }
        panic!(
            "{} mismatch(es) in examples/{folder} (listed above)",
            errs.len()
        );
    }
}

#[test]
fn examples_hx() {
    check_machine("hx");
}

#[test]
fn examples_puma() {
    check_machine("puma");
}

#[test]
fn examples_hurco() {
    check_machine("hurco");
}
