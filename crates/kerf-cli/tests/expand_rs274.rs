//! `kerf expand --to linuxcnc` checked by LinuxCNC itself: for every
//! program (the examples, the corpus, kerf-interp's rs274 reference
//! programs, `tests/expand/`) that kerf completes, LinuxCNC's stand-alone
//! interpreter `rs274` runs the expanded output without an error, and its
//! canonical moves (STRAIGHT_TRAVERSE, STRAIGHT_FEED, ARC_FEED) end where
//! kerf's toolpath records do, record for record: X Y Z C to 1 µm plus
//! rs274's print rounding (four decimals), arcs with the same centre and
//! direction. The mill programs are the contract; the lathe programs run
//! in LinuxCNC's lathe radius mode (G18 G8), their threads as G33. So
//! rs274 checks the macros, cycles and compensation kerf resolved on
//! programs it could not run itself.
//!
//! rs274 prints positions in the coordinate system in force (its G92
//! included), which is the output's own numbers: the toolpath's `to`.
//!
//! Needs LinuxCNC (`apt-get install -y --no-install-recommends
//! linuxcnc-uspace`); without `rs274` on the PATH the test prints why and
//! passes.

mod common;

use std::process::{Command, Stdio};

use common::generate::{hurco_program, lathe_program, program, PROGRAMS};
use common::programs::{corpus, examples, expand_programs, records, rs274_programs, scratch, Case};
use serde_json::Value;

const TOL: f64 = 1e-3 + 1e-4;

/// One rs274 move: kind, end point (x y z c), arc centre in the plane and
/// direction.
#[derive(Debug)]
struct Move {
    kind: &'static str,
    to: [f64; 4],
    centre: Option<([f64; 3], &'static str)>,
    line: usize,
}

fn args(l: &str) -> Vec<f64> {
    let (a, b) = (l.find('(').unwrap() + 1, l.rfind(')').unwrap());
    l[a..b]
        .split([',', ' '])
        .filter(|s| !s.is_empty())
        .filter_map(|s| s.parse().ok())
        .collect()
}

/// rs274's canonical moves, or its error text.
fn parse_canon(text: &str) -> Result<Vec<Move>, String> {
    let mut plane = [0usize, 1, 2];
    let mut out = Vec::new();
    for (n, l) in text.lines().enumerate() {
        if !l.contains("N.....") {
            if l.trim().is_empty() || l.trim() == "executing" {
                continue;
            }
            return Err(format!("rs274: {l}"));
        }
        if l.contains("SELECT_PLANE(") {
            plane = if l.contains("PLANE_XZ") {
                [2, 0, 1]
            } else if l.contains("PLANE_YZ") {
                [1, 2, 0]
            } else {
                [0, 1, 2]
            };
        } else if l.contains("STRAIGHT_TRAVERSE(") || l.contains("STRAIGHT_FEED(") {
            let a = args(l);
            out.push(Move {
                kind: if l.contains("TRAVERSE") {
                    "rapid"
                } else {
                    "feed"
                },
                to: [a[0], a[1], a[2], a[5]],
                centre: None,
                line: n + 1,
            });
        } else if l.contains("ARC_FEED(") {
            let a = args(l);
            let (mut p, mut c) = ([0.0; 3], [f64::NAN; 3]);
            p[plane[0]] = a[0];
            p[plane[1]] = a[1];
            p[plane[2]] = a[5];
            c[plane[0]] = a[2];
            c[plane[1]] = a[3];
            let dir = if a[4] < 0.0 { "cw" } else { "ccw" };
            out.push(Move {
                kind: "arc",
                to: [p[0], p[1], p[2], a[8]],
                centre: Some((c, dir)),
                line: n + 1,
            });
        }
    }
    Ok(out)
}

/// The tool table rs274 needs for every T word of the output.
fn tool_table(ngc: &str) -> String {
    let mut tools: Vec<u32> = ngc
        .split(|c: char| c.is_whitespace())
        .filter_map(|w| w.strip_prefix('T')?.parse().ok())
        .collect();
    tools.sort_unstable();
    tools.dedup();
    tools
        .iter()
        .filter(|t| **t > 0)
        .map(|t| format!("T{t} P{t} Z0 D0\n"))
        .collect()
}

fn axis(r: &Value, key: &str, a: &str) -> f64 {
    r[key][a].as_f64().unwrap_or(0.0)
}

/// Compares one program; returns its problems, or None when kerf does not
/// complete it.
fn check(case: &Case) -> Option<(usize, Vec<String>)> {
    let tp = scratch(&format!("{}-rs274", case.label), "jsonl");
    let _ = std::fs::remove_file(&tp);
    let run = case
        .kerf("run", &case.program, &["--toolpath", tp.to_str().unwrap()])
        .output()
        .unwrap();
    if run.status.code() != Some(0) {
        return None;
    }
    let want: Vec<Value> = records(&tp)
        .into_iter()
        .filter(|r| r["kind"] != "dwell")
        .collect();
    let ngc = scratch(&case.label, "ngc");
    let out = case
        .kerf(
            "expand",
            &case.program,
            &["--to", "linuxcnc", "-o", ngc.to_str().unwrap()],
        )
        .output()
        .unwrap();
    if !out.status.success() {
        return Some((
            0,
            vec![format!("expand: {}", String::from_utf8_lossy(&out.stderr))],
        ));
    }
    let text = std::fs::read_to_string(&ngc).unwrap();
    let tbl = scratch(&case.label, "tbl");
    std::fs::write(&tbl, tool_table(&text)).unwrap();
    // rs274 shares its tool table through `$HOME/.tool.mmap` (truncated by
    // every run) and keeps its parameter file in the working folder: each
    // run gets a folder of its own as both, so runs at the same time (these
    // tests' threads, anyone else's rs274) never see each other's tables.
    let home = scratch(&case.label, "rs274");
    std::fs::create_dir_all(&home).unwrap();
    let rs = Command::new("rs274")
        .current_dir(&home)
        .env("HOME", &home)
        .arg("-g")
        .arg("-t")
        .arg(&tbl)
        .arg(&ngc)
        .arg("/dev/stdout")
        .stdin(Stdio::null())
        .output()
        .unwrap();
    let canon =
        String::from_utf8_lossy(&rs.stdout).to_string() + &String::from_utf8_lossy(&rs.stderr);
    let got = match parse_canon(&canon) {
        Ok(g) => g,
        Err(e) => return Some((0, vec![format!("{e} ({})", ngc.display())])),
    };
    let mut problems = Vec::new();
    if got.len() != want.len() {
        problems.push(format!("kerf {} moves, rs274 {}", want.len(), got.len()));
    }
    for (i, (w, g)) in want.iter().zip(&got).enumerate() {
        let kerf_kind = if w["kind"] == "thread" {
            "feed"
        } else {
            w["kind"].as_str().unwrap()
        };
        let to = ["x", "y", "z", "c"].map(|a| axis(w, "to", a));
        let mut bad = kerf_kind != g.kind || (0..4).any(|k| (to[k] - g.to[k]).abs() > TOL);
        if let Some((c, dir)) = g.centre {
            let wc = ["x", "y", "z"].map(|a| axis(w, "center", a));
            bad |= w["dir"] != dir || (0..3).any(|k| !c[k].is_nan() && (c[k] - wc[k]).abs() > TOL);
        }
        if bad {
            problems.push(format!(
                "move {i}: kerf line {} {kerf_kind} {to:?}, rs274 canon line {} {} {:?} {:?} ({})",
                w["line"],
                g.line,
                g.kind,
                g.to,
                g.centre,
                ngc.display()
            ));
            break;
        }
    }
    Some((want.len().min(got.len()), problems))
}

#[test]
fn rs274_runs_the_linuxcnc_output_to_kerfs_end_points() {
    if Command::new("rs274")
        .arg("-h")
        .stdin(Stdio::null())
        .output()
        .is_err()
    {
        println!(
            "skipped: rs274 not installed (apt-get install -y --no-install-recommends linuxcnc-uspace)"
        );
        return;
    }
    let mut cases: Vec<Case> = examples();
    cases.extend(corpus());
    cases.extend(rs274_programs());
    cases.extend(expand_programs());
    let (mut compared, mut mills, mut moves, mut failures) = (0, 0, 0, Vec::new());
    for case in &cases {
        if let Some((n, problems)) = check(case) {
            compared += 1;
            mills += case.is_mill() as usize;
            moves += n;
            failures.extend(problems.into_iter().map(|p| format!("{}: {p}", case.label)));
        }
    }
    println!(
        "{compared} of {} programs ({mills} mill), {moves} moves compared with rs274",
        cases.len()
    );
    assert!(
        failures.is_empty(),
        "{} differences:\n{}",
        failures.len(),
        failures.join("\n")
    );
    assert!(mills >= 40, "only {mills} mill programs compared");
    assert!(moves >= 1000, "only {moves} moves compared");
}

#[test]
fn rs274_runs_the_generated_programs_to_kerfs_end_points() {
    if Command::new("rs274")
        .arg("-h")
        .stdin(Stdio::null())
        .output()
        .is_err()
    {
        println!(
            "skipped: rs274 not installed (apt-get install -y --no-install-recommends linuxcnc-uspace)"
        );
        return;
    }
    let (mut compared, mut moves, mut failures) = (0, 0, Vec::new());
    type Make = fn(u64) -> String;
    let makers: [(&str, Make); 3] = [
        ("hx-mc", program),
        ("puma-lathe", lathe_program),
        ("hurco-lathe", hurco_program),
    ];
    // A third of the seeds of tests/expand_random.rs per machine: each
    // program costs three processes here.
    let seeds = PROGRAMS / 3;
    for (machine, make) in makers {
        for seed in 0..seeds {
            let path = scratch(&format!("generated-{machine}-{seed}"), "nc");
            std::fs::write(&path, make(seed)).unwrap();
            let case = Case {
                label: format!("generated/{machine}/{seed}"),
                program: path,
                machine: machine.into(),
                sets: Vec::new(),
                libs: Vec::new(),
            };
            if let Some((n, problems)) = check(&case) {
                compared += 1;
                moves += n;
                failures.extend(problems.into_iter().map(|p| format!("{}: {p}", case.label)));
            }
        }
    }
    println!(
        "{compared} of {} generated programs, {moves} moves compared with rs274",
        3 * seeds
    );
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    assert!(
        compared as u64 >= PROGRAMS,
        "only {compared} programs compared"
    );
}
