//! Runs every program of the shared real-world corpus (`../shared/corpus`,
//! beside the repository) through the `kerf` binary and checks the product
//! contract, not the motion:
//!
//! - the run ends within 20 s;
//! - the exit status is 0 (completed) or 1 (alarm): never 2 (usage/I-O
//!   error on a file that exists) and never a panic (101) or a signal;
//! - on an alarm, stderr's first line is `FILE:LINE:COL: alarm CODE: MESSAGE`
//!   with LINE >= 1.
//!
//! The machine follows the folder: `mill*` → `hx-mc`, `lathe*` →
//! `puma-lathe`, `hurco*` → `hurco-lathe`. A table of file → outcome is
//! printed (see it with `cargo test --test corpus -- --nocapture`). When the
//! corpus folder is absent the test prints a note and passes.

use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

const TIMEOUT: Duration = Duration::from_secs(20);

fn corpus_dir() -> PathBuf {
    let p = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared/corpus");
    p.canonicalize().unwrap_or(p)
}

fn machine_for(folder: &str) -> Option<&'static str> {
    let f = folder.to_ascii_lowercase();
    if f.starts_with("mill") {
        Some("hx-mc")
    } else if f.starts_with("lathe") {
        Some("puma-lathe")
    } else if f.starts_with("hurco") {
        Some("hurco-lathe")
    } else {
        None
    }
}

fn collect(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(rd) = std::fs::read_dir(dir) else {
        return;
    };
    let mut entries: Vec<PathBuf> = rd.filter_map(|e| e.ok()).map(|e| e.path()).collect();
    entries.sort();
    for p in entries {
        if p.is_dir() {
            collect(&p, out);
        } else {
            out.push(p);
        }
    }
}

/// `^.+:\d+:\d+: alarm \S+: .+` by hand (no regex dependency); returns the
/// line number.
fn parse_alarm_line(s: &str) -> Option<u64> {
    let idx = s.find(": alarm ")?;
    let (loc, rest) = (&s[..idx], &s[idx + ": alarm ".len()..]);
    // loc = FILE:LINE:COL, FILE non-empty (and may itself contain ':').
    let mut parts = loc.rsplitn(3, ':');
    let col = parts.next()?;
    let line = parts.next()?;
    let file = parts.next()?;
    if file.is_empty() || col.is_empty() || line.is_empty() {
        return None;
    }
    if !col.bytes().all(|b| b.is_ascii_digit()) || !line.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    let (code, msg) = rest.split_once(": ")?;
    if code.is_empty() || code.chars().any(char::is_whitespace) || msg.is_empty() {
        return None;
    }
    line.parse().ok()
}

struct Outcome {
    file: String,
    machine: &'static str,
    status: String,
    detail: String,
    ok: bool,
    secs: f64,
}

fn run_one(path: &Path, machine: &'static str, rel: String) -> Outcome {
    let start = Instant::now();
    let mut child = match Command::new(env!("CARGO_BIN_EXE_kerf"))
        .arg("run")
        .arg(path)
        .arg("--machine")
        .arg(machine)
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
    {
        Ok(c) => c,
        Err(e) => {
            return Outcome {
                file: rel,
                machine,
                status: "spawn failed".into(),
                detail: e.to_string(),
                ok: false,
                secs: 0.0,
            }
        }
    };
    // Drain stderr on a thread so a chatty child cannot block on a full pipe.
    let mut stderr = child.stderr.take().expect("piped stderr");
    let reader = std::thread::spawn(move || {
        let mut buf = Vec::new();
        let _ = stderr.read_to_end(&mut buf);
        buf
    });
    let status = loop {
        match child.try_wait() {
            Ok(Some(st)) => break Some(st),
            Ok(None) if start.elapsed() >= TIMEOUT => {
                let _ = child.kill();
                let _ = child.wait();
                break None;
            }
            Ok(None) => std::thread::sleep(Duration::from_millis(10)),
            Err(_) => break None,
        }
    };
    let secs = start.elapsed().as_secs_f64();
    let err = String::from_utf8_lossy(&reader.join().unwrap_or_default()).into_owned();
    let first = err.lines().next().unwrap_or("").to_string();
    let Some(status) = status else {
        return Outcome {
            file: rel,
            machine,
            status: "TIMEOUT".into(),
            detail: format!("killed after {} s", TIMEOUT.as_secs()),
            ok: false,
            secs,
        };
    };
    match status.code() {
        Some(0) => Outcome {
            file: rel,
            machine,
            status: "completed".into(),
            detail: String::new(),
            ok: true,
            secs,
        },
        Some(1) => match parse_alarm_line(&first) {
            Some(line) if line >= 1 => Outcome {
                file: rel,
                machine,
                status: "alarm".into(),
                detail: first,
                ok: true,
                secs,
            },
            Some(_) => Outcome {
                file: rel,
                machine,
                status: "alarm, line 0".into(),
                detail: first,
                ok: false,
                secs,
            },
            None => Outcome {
                file: rel,
                machine,
                status: "alarm, bad format".into(),
                detail: first,
                ok: false,
                secs,
            },
        },
        Some(c) => Outcome {
            file: rel,
            machine,
            status: format!("exit {c}"),
            detail: err.lines().take(6).collect::<Vec<_>>().join(" | "),
            ok: false,
            secs,
        },
        None => Outcome {
            file: rel,
            machine,
            status: "killed by signal".into(),
            detail: err.lines().take(6).collect::<Vec<_>>().join(" | "),
            ok: false,
            secs,
        },
    }
}

#[test]
fn alarm_line_format() {
    assert_eq!(
        parse_alarm_line("a.nc:3:7: alarm PS0010: bad thing"),
        Some(3)
    );
    assert_eq!(
        parse_alarm_line("C:/x/a.nc:12:1: alarm F_82001: msg: more"),
        Some(12)
    );
    assert_eq!(parse_alarm_line("a.nc:3: alarm PS0010: bad"), None);
    assert_eq!(parse_alarm_line("a.nc:x:1: alarm PS0010: bad"), None);
    assert_eq!(parse_alarm_line("a.nc:3:1: alarm : bad"), None);
    assert_eq!(parse_alarm_line("a.nc:3:1: alarm PS 1: bad"), None);
    assert_eq!(parse_alarm_line(":3:1: alarm PS1: bad"), None);
}

#[test]
fn shared_corpus_runs_within_contract() {
    let dir = corpus_dir();
    if !dir.is_dir() {
        eprintln!("note: corpus folder {} is absent; skipping", dir.display());
        return;
    }
    let mut files = Vec::new();
    collect(&dir, &mut files);
    let mut outcomes = Vec::new();
    for path in &files {
        let rel = path.strip_prefix(&dir).unwrap_or(path);
        let mut comps = rel.components();
        let folder = comps
            .next()
            .map(|c| c.as_os_str().to_string_lossy().into_owned())
            .unwrap_or_default();
        // Top-level files (SOURCES.md, LICENSES.md) are not programs.
        if comps.next().is_none() {
            continue;
        }
        let Some(machine) = machine_for(&folder) else {
            eprintln!(
                "note: no machine for folder '{folder}', skipping {}",
                rel.display()
            );
            continue;
        };
        outcomes.push(run_one(path, machine, rel.display().to_string()));
    }

    let w = outcomes
        .iter()
        .map(|o| o.file.len())
        .max()
        .unwrap_or(4)
        .max(4);
    println!();
    println!(
        "{:<w$}  {:<11}  {:>6}  {:<18}  detail",
        "file", "machine", "secs", "outcome"
    );
    for o in &outcomes {
        println!(
            "{:<w$}  {:<11}  {:>6.2}  {:<18}  {}",
            o.file,
            o.machine,
            o.secs,
            if o.ok {
                o.status.clone()
            } else {
                format!("FAIL {}", o.status)
            },
            o.detail
        );
    }
    let completed = outcomes
        .iter()
        .filter(|o| o.ok && o.status == "completed")
        .count();
    let alarms = outcomes
        .iter()
        .filter(|o| o.ok && o.status == "alarm")
        .count();
    let failed: Vec<&Outcome> = outcomes.iter().filter(|o| !o.ok).collect();
    println!(
        "{} programs: {} completed, {} alarm, {} failed",
        outcomes.len(),
        completed,
        alarms,
        failed.len()
    );
    assert!(
        !outcomes.is_empty(),
        "no programs found under {}",
        dir.display()
    );
    assert!(
        failed.is_empty(),
        "corpus programs broke the contract:\n{}",
        failed
            .iter()
            .map(|o| format!("  {} ({}): {} {}", o.file, o.machine, o.status, o.detail))
            .collect::<Vec<_>>()
            .join("\n")
    );
}
