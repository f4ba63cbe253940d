//! `kerf expand --to fanuc` round trip: for every example, corpus program
//! and rs274 reference program, `kerf run` of the expanded output gives
//! the same motions as `kerf run` of the original, record for record:
//! the kind, the end point `to` and `mto` (the output sets the original's
//! frame where it changes) on every axis and the arc centre to 1 µm, the
//! arc direction, the feed (mm/min), the thread lead, the dwell time and
//! the tool. The source lines differ (the output has its own) and so may
//! `t_end` (the output's blocks are not the original's).
//!
//! A program that stops on an alarm must expand up to the alarm: `kerf
//! expand` exits 1 with the same alarm line as `kerf run`, and the
//! output runs to its end with the records the original made before the
//! alarm.

mod common;

use std::path::{Path, PathBuf};

use common::programs::{corpus, examples, expand_programs, records, rs274_programs, scratch, Case};
use common::records::differs;
use serde_json::Value;

/// `kerf run` with a toolpath: (exit code, first stderr line, records).
fn run(case: &Case, program: &Path, tag: &str) -> (Option<i32>, String, Vec<Value>) {
    let tp = scratch(&format!("{}-{tag}", case.label), "jsonl");
    let _ = std::fs::remove_file(&tp);
    let out = case
        .kerf("run", program, &["--toolpath", tp.to_str().unwrap()])
        .output()
        .expect("kerf runs");
    let err = String::from_utf8_lossy(&out.stderr);
    let first = err
        .lines()
        .find(|l| l.contains(": alarm "))
        .unwrap_or("")
        .to_string();
    (out.status.code(), first, records(&tp))
}

/// Runs one case; returns its problems (empty when the round trip holds)
/// and whether it was compared.
fn round_trip(case: &Case) -> (Vec<String>, bool) {
    let (code, alarm, want) = run(case, &case.program, "orig");
    if !matches!(code, Some(0) | Some(1)) {
        return (Vec::new(), false);
    }
    let nc = scratch(&case.label, "expanded.nc");
    let out = case
        .kerf("expand", &case.program, &["-o", nc.to_str().unwrap()])
        .output()
        .expect("kerf expands");
    let err = String::from_utf8_lossy(&out.stderr);
    let mut problems = Vec::new();
    if out.status.code() != code {
        problems.push(format!(
            "expand exit {:?}, run exit {code:?}: {}",
            out.status.code(),
            err.trim()
        ));
        return (problems, true);
    }
    let expand_alarm = err.lines().find(|l| l.contains(": alarm ")).unwrap_or("");
    if expand_alarm != alarm {
        problems.push(format!(
            "expand alarm '{expand_alarm}', run alarm '{alarm}'"
        ));
    }
    let (code2, alarm2, got) = run(case, &nc, "expanded");
    if code2 != Some(0) {
        problems.push(format!(
            "the expanded program ({}) exits {code2:?}: {alarm2}",
            nc.display()
        ));
        return (problems, true);
    }
    if want.len() != got.len() {
        problems.push(format!(
            "{} records from the original, {} from the expanded program",
            want.len(),
            got.len()
        ));
    }
    for (i, (a, b)) in want.iter().zip(&got).enumerate() {
        let prev = |r: &[Value]| i.checked_sub(1).map(|k| r[k].clone());
        if surface_feed_same_time(prev(&want).as_ref(), a, prev(&got).as_ref(), b) {
            continue;
        }
        if let Some(d) = differs(a, b) {
            problems.push(format!(
                "record {i} (original line {}, expanded line {}): {d}",
                a["line"], b["line"]
            ));
            break;
        }
    }
    (problems, true)
}

/// A G112 or G107 move turns C while F is a speed on the programmed
/// surface: the output, without that surface, writes the F that takes
/// the same time. Such a pair of records (`a` after `pa`, `b` after
/// `pb`) is the same motion when everything but the feed is and the
/// durations agree to 0.5 % (plus 1 ms).
fn surface_feed_same_time(pa: Option<&Value>, a: &Value, pb: Option<&Value>, b: &Value) -> bool {
    let (Some(pa), Some(pb)) = (pa, pb) else {
        return false;
    };
    let c = |r: &Value| r["mto"]["c"].as_f64();
    if a["kind"] != "feed" || c(a) == c(pa) {
        return false;
    }
    let mut without = (a.clone(), b.clone());
    without.0.as_object_mut().unwrap().remove("feed");
    without.1.as_object_mut().unwrap().remove("feed");
    if differs(&without.0, &without.1).is_some() {
        return false;
    }
    let t = |r: &Value, p: &Value| r["t_end"].as_f64().unwrap() - p["t_end"].as_f64().unwrap();
    let (ta, tb) = (t(a, pa), t(b, pb));
    (ta - tb).abs() <= 0.005 * ta + 1e-3
}

fn check_all(cases: &[Case]) -> usize {
    let mut failures = Vec::new();
    let mut compared = 0;
    for case in cases {
        let (problems, done) = round_trip(case);
        compared += done as usize;
        for p in problems {
            failures.push(format!("{}: {p}", case.label));
        }
    }
    assert!(
        failures.is_empty(),
        "{} of {} programs differ:\n{}",
        failures.len(),
        cases.len(),
        failures.join("\n")
    );
    compared
}

#[test]
fn examples_expand_to_the_same_motions() {
    let cases = examples();
    let n = check_all(&cases);
    // Every example either completes or stops on an alarm.
    assert_eq!(n, cases.len());
    assert!(n > 50, "only {n} examples found");
}

#[test]
fn corpus_and_reference_programs_expand_to_the_same_motions() {
    let mut cases = corpus();
    cases.extend(rs274_programs());
    let n = check_all(&cases);
    println!("{n} of {} programs compared", cases.len());
    assert!(n >= rs274_programs().len());
}

#[test]
fn macro_cycle_transform_programs_expand_to_the_same_motions() {
    let cases = expand_programs();
    assert!(cases.len() >= 4);
    // Each of them completes (they are written to), so each is compared.
    assert_eq!(check_all(&cases), cases.len());
}

#[test]
fn standard_output_unknown_target_and_unwritable_output() {
    let prog = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/hx/contour.nc");
    let kerf = || std::process::Command::new(env!("CARGO_BIN_EXE_kerf"));
    // Without -o the program goes to stdout, the same text as -o writes.
    let out = kerf().arg("expand").arg(&prog).output().unwrap();
    assert_eq!(out.status.code(), Some(0));
    let file = scratch("stdout-vs-file", "nc");
    let o2 = kerf()
        .arg("expand")
        .arg(&prog)
        .arg("-o")
        .arg(&file)
        .output()
        .unwrap();
    assert_eq!(o2.status.code(), Some(0));
    assert_eq!(out.stdout, std::fs::read(&file).unwrap());
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.starts_with("%\nO0001 (KERF EXPAND OF contour.nc TO fanuc)\n"));
    assert!(
        text.contains("\nG17 G03 X50. Y10. I0. J10. (contour.nc:10)\n"),
        "{text}"
    );
    // A target kerf does not write, and a folder that is not there: exit 2.
    let bad = kerf()
        .args(["expand", "--to", "haas"])
        .arg(&prog)
        .output()
        .unwrap();
    assert_eq!(bad.status.code(), Some(2));
    let err = String::from_utf8_lossy(&bad.stderr);
    assert!(err.contains("'haas'") && err.contains("linuxcnc"), "{err}");
    let nowhere = kerf()
        .arg("expand")
        .arg(&prog)
        .args(["-o", "/nonexistent-folder/out.nc"])
        .output()
        .unwrap();
    assert_eq!(nowhere.status.code(), Some(2));
}

/// `kerf run --json`'s cycle time of a program on the HX.
fn cycle_time(prog: &Path) -> f64 {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_kerf"))
        .args(["run", "--machine", "hx-mc", "--json"])
        .arg(prog)
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    v["cycle_time_s"].as_f64().unwrap()
}

#[test]
fn g107_moves_keep_their_surface_speed() {
    // 000 §4.7's example: F250 is the speed along the developed surface
    // of a cylinder of radius 57.299 mm. Its chords reach the output as
    // machine Z and C; without G107 the same F would time them by Z
    // alone (89 s instead of 113 s).
    let prog = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/hx/cylindrical_g107.nc");
    let kerf = || std::process::Command::new(env!("CARGO_BIN_EXE_kerf"));
    let fanuc = scratch("g107-fanuc", "nc");
    let out = kerf()
        .args(["expand", "--machine", "hx-mc", "-o"])
        .arg(&fanuc)
        .arg(&prog)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    // The same control has G107: the output selects it again, in the
    // plane the original named, and cancels it where the original did.
    let text = std::fs::read_to_string(&fanuc).unwrap();
    assert!(
        text.contains("\nG18 G107 C57.299 (cylindrical_g107.nc:4)\n"),
        "{text}"
    );
    assert!(
        text.contains("\nG107 C0 (cylindrical_g107.nc:16)\n"),
        "{text}"
    );
    let (want, got) = (cycle_time(&prog), cycle_time(&fanuc));
    assert!(
        (want - got).abs() < 0.01,
        "original {want} s, expanded {got} s"
    );
    // LinuxCNC has no G107: each F is scaled to the length the control
    // times. Line 6's C30 alone (Z fixed): LinuxCNC times it in degrees,
    // 30 "mm"; on the surface it is 30·π·57.299/180 = 30.00169 mm: F250
    // becomes 250 · 30 / 30.00169 = 249.98595 (written to 4 decimals).
    let out = kerf()
        .args(["expand", "--machine", "hx-mc", "--to", "linuxcnc"])
        .arg(&prog)
        .output()
        .unwrap();
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(!text.contains("G107"), "{text}");
    let line6 = text
        .lines()
        .find(|l| l.contains("(cylindrical_g107.nc:6)"))
        .unwrap();
    assert!(line6.starts_with("C30. F249.98"), "{line6}");
    let f: f64 = line6["C30. F".len()..]
        .split(' ')
        .next()
        .unwrap()
        .parse()
        .unwrap();
    let k = 57.299 * std::f64::consts::PI / 180.0;
    assert!((f - 250.0 / k).abs() < 1e-4, "{f}");
}

/// 000 §4.6's G112 example expanded for the HX (`--to fanuc`) into a
/// scratch file named by `tag`: (the program, the output, its text).
fn expand_g112(tag: &str) -> (PathBuf, PathBuf, String) {
    let prog = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/hx/polar_interp_g112.nc");
    let out = scratch(tag, "nc");
    let st = std::process::Command::new(env!("CARGO_BIN_EXE_kerf"))
        .args(["expand", "--machine", "hx-mc", "--quiet", "-o"])
        .arg(&out)
        .arg(&prog)
        .status()
        .unwrap();
    assert!(st.success());
    let text = std::fs::read_to_string(&out).unwrap();
    (prog, out, text)
}

#[test]
fn g112_moves_keep_their_speed_on_the_face() {
    // 000 §4.6's example: F100 along the contour in the face's Cartesian
    // plane, 231.4 mm of it (40 + 10 + 5π + 30 + 30 + 5π + 30 + 20 + 40),
    // so at least 138.8 s of cutting. Its chords reach the output as
    // machine X and C (no G112 on any target), each F scaled so that it
    // takes that time timed by X.
    let (prog, out, text) = expand_g112("g112-fanuc");
    assert!(!text.contains("G112"), "{text}");
    let (want, got) = (cycle_time(&prog), cycle_time(&out));
    let contour = 40.0 + 10.0 + 30.0 + 30.0 + 30.0 + 20.0 + 40.0 + 10.0 * std::f64::consts::PI;
    assert!(want > contour / 100.0 * 60.0, "{want}");
    assert!(
        (want - got).abs() < 0.01 * want,
        "original {want} s, expanded {got} s"
    );
}

#[test]
fn expanded_g112_output_runs_without_a_lathe_warning() {
    // Issue 21: the expansion's chords that are mostly rotation get
    // feeds below 1 (line 7: X20.002 C0.895 F0.64), which once read as a
    // lathe's feed per revolution (KERF-W002). The original gives no
    // warning, nor must its expansion.
    let (prog, out, text) = expand_g112("g112-w002");
    assert!(text.contains(" F0.64 "), "{text}");
    for p in [&prog, &out] {
        let run = std::process::Command::new(env!("CARGO_BIN_EXE_kerf"))
            .args(["run", "--machine", "hx-mc"])
            .arg(p)
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&run.stderr);
        assert!(run.status.success(), "{err}");
        assert!(!err.contains("warning"), "{}: {err}", p.display());
    }
}
