//! What a new user meets (issue 20): the summary on every run, --quiet and
//! --json, warnings, files given by mistake, outputs checked before the
//! run, check leaving the state alone.

use std::path::PathBuf;
use std::process::{Command, Output};

fn kerf() -> Command {
    Command::new(env!("CARGO_BIN_EXE_kerf"))
}

fn dir() -> PathBuf {
    let d = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("first_hour");
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn tmp(name: &str, bytes: &[u8]) -> PathBuf {
    let p = dir().join(name);
    std::fs::write(&p, bytes).unwrap();
    p
}

fn text(b: &[u8]) -> String {
    String::from_utf8(b.to_vec()).unwrap()
}

fn run(args: &[&str], p: &PathBuf) -> Output {
    kerf()
        .arg(args[0])
        .arg(p)
        .args(&args[1..])
        .output()
        .unwrap()
}

/// 100 mm at F600 and 50 mm at F300 with tool 1, then 60 mm at F1200 with
/// tool 2, on the HX.
const TWO_TOOLS: &str = "G90 G54 G17 G21\nT1 M06\nG0 X0 Y0\nZ5.\nM3 S1000\n\
G1 Z0 F300.\nX100. F600.\nY50. F300.\nG0 Z50.\nT2 M06\nG0 X0 Y0 Z5.\n\
G1 Z0 F300.\nX60. F1200.\nM30\n";

#[test]
fn every_run_prints_the_summary_with_cycle_time_and_tools() {
    let p = tmp("two_tools.nc", TWO_TOOLS.as_bytes());
    let out = run(&["run"], &p);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let s = text(&out.stdout);
    let first = s.lines().next().unwrap();
    assert!(
        first.starts_with(&format!("{}: completed: cycle time 0:", p.display())),
        "{s}"
    );
    // 14 blocks, 10 motions (G0 X0 Y0, Z5, G1 Z0, X100, Y50, G0 Z50,
    // G0 X0 Y0 Z5, G1 Z0, X60 … and the tool-change moves, if any, are
    // counted by the report: compare with it).
    let r = run(&["run", "--json"], &p);
    let doc: serde_json::Value = serde_json::from_slice(&r.stdout).unwrap();
    assert!(s.contains(&format!(
        "{} blocks, {} motions",
        doc["blocks"], doc["motions"]
    )));
    // Cutting time per tool: tool 1 cuts 5 mm at F300 (1 s), 100 mm at
    // F600 (10 s), 50 mm at F300 (10 s): at least 21 s; tool 2 cuts 5 mm
    // at F300 (1 s) and 60 mm at F1200 (3 s): at least 4 s.
    let tt = doc["tool_times"].as_array().unwrap();
    assert_eq!(tt.len(), 2, "{doc}");
    assert_eq!(
        (tt[0]["tool"].as_u64(), tt[1]["tool"].as_u64()),
        (Some(1), Some(2))
    );
    let (t1, t2) = (
        tt[0]["cutting_s"].as_f64().unwrap(),
        tt[1]["cutting_s"].as_f64().unwrap(),
    );
    assert!((21.0..23.0).contains(&t1), "{t1}");
    assert!((4.0..5.5).contains(&t2), "{t2}");
    // The tools' cutting times sum to the cutting time.
    let cut = doc["time_s"]["cutting"].as_f64().unwrap();
    assert!((t1 + t2 - cut).abs() < 1e-5, "{t1} + {t2} vs {cut}");
    assert!(s.contains("\n  T1    cutting 0:00:2"), "{s}");
    assert!(s.contains("\n  T2    cutting 0:00:0"), "{s}");
}

#[test]
fn check_prints_the_same_summary_and_writes_nothing() {
    let p = tmp("check.nc", TWO_TOOLS.as_bytes());
    let state = dir().join("check_state");
    let _ = std::fs::remove_dir_all(&state);
    let out = run(&["check", "--state", state.to_str().unwrap()], &p);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let s = text(&out.stdout);
    assert!(
        s.starts_with(&format!("{}: ok: cycle time 0:", p.display())),
        "{s}"
    );
    assert!(s.contains("  T2    cutting"), "{s}");
    assert!(!state.exists(), "check created the state folder");
}

#[test]
fn quiet_prints_nothing_and_json_prints_the_report() {
    let p = tmp("quiet.nc", TWO_TOOLS.as_bytes());
    let out = run(&["run", "--quiet"], &p);
    assert!(out.status.success());
    assert!(out.stdout.is_empty() && out.stderr.is_empty());
    let out = run(&["run", "--json"], &p);
    let doc: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(doc["status"], "completed");
    assert!(doc["cycle_time_s"].as_f64().unwrap() > 25.0);
}

#[test]
fn warnings_print_as_file_line_col_and_go_into_the_report() {
    // 001 p.9's G01 with F0.2 (mm/rev on the lathe) on the mill, and no M30.
    let p = tmp(
        "lathe_on_mill.nc",
        b"G0 X0 Z0\nM3 S500\nG1 X150. Z100. F0.2\n",
    );
    let rep = dir().join("lathe_on_mill.json");
    let out = run(&["run", "--report", rep.to_str().unwrap()], &p);
    assert!(out.status.success());
    let err = text(&out.stderr);
    let lines: Vec<&str> = err.lines().collect();
    assert_eq!(lines.len(), 2, "{err}");
    assert!(
        lines[0].starts_with(&format!("{}:3:1: warning KERF-W002: ", p.display())),
        "{err}"
    );
    assert!(
        lines[1].starts_with(&format!("{}:3:1: warning KERF-W005: ", p.display())),
        "{err}"
    );
    let doc: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&rep).unwrap()).unwrap();
    let w = doc["warnings"].as_array().unwrap();
    assert_eq!(w.len(), 2);
    assert_eq!(w[0]["code"], "KERF-W002");
    assert_eq!(w[0]["line"], 3);
    // The same program on the lathe: only the missing M30.
    let out = run(&["run", "--machine", "puma-lathe"], &p);
    let err = text(&out.stderr);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("warning KERF-W005"));
}

#[test]
fn spindle_stopped_while_cutting_is_a_warning_at_the_block() {
    // G99 feed per revolution with no spindle on the PUMA: the control
    // waits for ever; kerf times it as 0 s and says where.
    let p = tmp(
        "no_spindle.nc",
        b"G0 X50. Z2.\nG99 G1 Z-10. F0.2\nZ-20.\nM30\n",
    );
    let out = run(&["run", "--machine", "puma-lathe"], &p);
    assert!(out.status.success());
    let err = text(&out.stderr);
    assert_eq!(err.lines().count(), 1, "one warning per stretch: {err}");
    assert!(
        err.starts_with(&format!("{}:2:", p.display())) && err.contains("warning KERF-W004"),
        "{err}"
    );
}

#[test]
fn an_empty_file_is_a_warning() {
    let p = tmp("empty.nc", b"");
    let out = run(&["run"], &p);
    assert!(out.status.success());
    assert_eq!(
        text(&out.stderr),
        format!(
            "{}:1: warning KERF-W003: empty program: no blocks to run\n",
            p.display()
        )
    );
}

#[test]
fn a_folder_or_a_binary_file_is_a_usage_error_without_a_position() {
    let d = dir().join("a_folder");
    std::fs::create_dir_all(&d).unwrap();
    let out = run(&["run"], &d);
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(
        text(&out.stderr),
        format!("kerf: {}: is a folder, not a program\n", d.display())
    );
    let mut bin = b"\x7fELF\x02\x01\x01\0\0\0\0\0\0\0\0\0".to_vec();
    bin.extend((0..4000u32).map(|i| (i * 7 % 256) as u8));
    let p = tmp("binary.nc", &bin);
    let out = run(&["run"], &p);
    assert_eq!(out.status.code(), Some(2));
    let err = out.stderr.clone();
    assert_eq!(
        text(&err),
        format!("kerf: {}: not an NC program (binary data)\n", p.display())
    );
    assert!(out.stdout.is_empty());
}

#[test]
fn a_utf8_bom_is_accepted_and_utf16_is_named() {
    let p = tmp("bom.nc", b"\xEF\xBB\xBFG0 X1.\nG1 X2. F100.\nM30\n");
    let out = run(&["run", "-q"], &p);
    assert!(out.status.success(), "{}", text(&out.stderr));
    // An alarm on line 1 still points at the right column (the BOM is not
    // a character of the line).
    let p = tmp("bom_alarm.nc", b"\xEF\xBB\xBFG0 X1. @\n");
    let out = run(&["run"], &p);
    let err = text(&out.stderr);
    assert!(
        err.starts_with(&format!("{}:1:8: alarm", p.display())),
        "{err}"
    );
    assert!(err.contains("\n  G0 X1. @\n         ^\n"), "{err}");
    let u16: Vec<u8> = [0xFF, 0xFE]
        .into_iter()
        .chain("G0 X1.\nM30\n".bytes().flat_map(|b| [b, 0]))
        .collect();
    let p = tmp("utf16.nc", &u16);
    let out = run(&["run"], &p);
    assert_eq!(out.status.code(), Some(2));
    assert!(text(&out.stderr).contains("UTF-16"));
}

#[test]
fn an_unwritable_output_fails_before_the_run() {
    let p = tmp("never_runs.nc", b"G0 X1.\nM30\n");
    let state = dir().join("never_state");
    let _ = std::fs::remove_dir_all(&state);
    let out = run(
        &[
            "run",
            "--report",
            "/no/such/folder/r.json",
            "--state",
            state.to_str().unwrap(),
        ],
        &p,
    );
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(
        text(&out.stderr),
        "kerf: --report /no/such/folder/r.json: no folder /no/such/folder\n"
    );
    assert!(out.stdout.is_empty());
    // Nothing ran: no state was saved.
    assert!(!state.join("hx-mc.vars").exists());
}

#[test]
fn no_output_is_created_when_a_later_one_cannot_be_written() {
    // The toolpath could be written, the plot cannot: neither is made, and
    // an existing toolpath is not emptied.
    let p = tmp("never_runs2.nc", b"G0 X1.\nM30\n");
    let tp = dir().join("kept.jsonl");
    let _ = std::fs::remove_file(&tp);
    let args = [
        "run",
        "--toolpath",
        tp.to_str().unwrap(),
        "--plot",
        "/no/such/folder/p.svg",
    ];
    let out = run(&args, &p);
    assert_eq!(out.status.code(), Some(2));
    assert!(text(&out.stderr).starts_with("kerf: --plot /no/such/folder/p.svg: "));
    assert!(!tp.exists());
    std::fs::write(&tp, "an earlier run\n").unwrap();
    assert_eq!(run(&args, &p).status.code(), Some(2));
    assert_eq!(std::fs::read_to_string(&tp).unwrap(), "an earlier run\n");
    // A folder given as the file.
    let out = run(&["run", "--report", dir().to_str().unwrap()], &p);
    assert_eq!(out.status.code(), Some(2));
    assert!(text(&out.stderr).ends_with(": is a folder, not a file\n"));
}

#[test]
fn completions_and_man_page_list_the_commands() {
    let out = kerf().args(["completions", "bash"]).output().unwrap();
    assert!(out.status.success());
    let s = text(&out.stdout);
    assert!(
        s.contains("_kerf()") && s.contains("--toolpath") && s.contains("check"),
        "{s}"
    );
    let out = kerf().arg("man").output().unwrap();
    assert!(out.status.success());
    let s = text(&out.stdout);
    assert!(s.starts_with(".ie") && s.contains(".TH kerf 1"), "{s}");
    assert!(s.contains("machines"), "{s}");
}

#[test]
fn columns_after_non_ascii_comments_count_characters() {
    // "(Ø10 Maß) G01 X10. Y5." without F: the alarm is at the G01, after
    // the ten characters "(Ø10 Maß) ": byte 13 (Ø and ß are two bytes
    // each) but character 11, where the caret is.
    let p = tmp(
        "umlaut.nc",
        "G90 G00 X0 Y0\n(Ø10 Maß) G01 X10. Y5.\nM30\n".as_bytes(),
    );
    let out = run(&["run"], &p);
    assert_eq!(out.status.code(), Some(1));
    let err = text(&out.stderr);
    let mut lines = err.lines();
    let head = lines.next().unwrap();
    assert!(
        head.ends_with(":2:11: alarm F_84020: cutting move without a feedrate (no F commanded)"),
        "{err}"
    );
    assert_eq!(lines.next(), Some("  (Ø10 Maß) G01 X10. Y5."), "{err}");
    assert_eq!(
        lines.next(),
        Some(&*format!("  {}^", " ".repeat(10))),
        "{err}"
    );
    // A warning after "(Ø) ": X118 is character 5 (byte 6).
    let p = tmp(
        "umlaut_warn.nc",
        "G90 G00 X0 Y0\nG01 X10. Y5. F100.\n(Ø) X118 Y5.\nM30\n".as_bytes(),
    );
    let out = run(&["run", "--quiet"], &p);
    let err = text(&out.stderr);
    assert!(
        err.contains(":3:5: warning KERF-W001: X118 has no decimal point"),
        "{err}"
    );
}

#[test]
fn misspelt_machine_and_set_names_get_the_valid_one() {
    let p = tmp("names.nc", b"G0 X1.\nM30\n");
    let err = |args: &[&str]| {
        let out = run(args, &p);
        assert_eq!(out.status.code(), Some(2));
        assert!(out.stdout.is_empty());
        text(&out.stderr)
    };
    assert_eq!(
        err(&["run", "--machine", "hx-mx"]),
        "kerf: unknown machine 'hx-mx': did you mean 'hx-mc'? (built-in: hx-mc, puma-lathe, hurco-lathe)\n"
    );
    // A part of one name only.
    assert!(err(&["run", "--machine", "puma"]).contains("did you mean 'puma-lathe'?"));
    assert_eq!(
        err(&["check", "--set", "singel_block=on"]),
        "kerf: --set singel_block: unknown key; did you mean 'single_block'? (see docs/formats.md)\n"
    );
    assert_eq!(
        err(&["run", "--set", "dry_run=maybe"]),
        "kerf: --set dry_run=maybe: expected on or off\n"
    );
}

#[test]
fn a_missing_program_is_named_without_the_os_error_number() {
    let missing = dir().join("no_such_program.nc");
    let out = run(&["run"], &missing);
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(
        text(&out.stderr),
        format!("kerf: {}: No such file or directory\n", missing.display())
    );
}
