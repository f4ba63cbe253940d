//! 002's G93 inverse time examples, timed end to end by `kerf check`:
//! example 1 "a four-minute cut … F = 0.25", example 2 "a 20-second cut
//! … F = 3". Each program moves only the G93 cut after a rapid to the
//! start, so the report's cutting time is the G93 move: 240 s and 20 s,
//! plus the few tens of milliseconds the planner spends accelerating and
//! stopping the 1 mm move (hence the 0.1 s tolerance).

use std::path::PathBuf;
use std::process::Command;

/// The report's cutting time of `text` run on hurco-lathe.
fn cutting_s(name: &str, text: &str) -> f64 {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("inverse_time");
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_kerf"))
        .args(["check", "--machine", "hurco-lathe", "--json"])
        .arg(&p)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    v["time_s"]["cutting"].as_f64().unwrap()
}

#[test]
fn g93_example_1_is_a_four_minute_cut() {
    let t = cutting_s("g93_1.nc", "G00 X0 Z0\nN100 G01 G93 X2 F.25\nM30\n");
    assert!((t - 240.0).abs() < 0.1, "cutting {t} s");
}

#[test]
fn g93_example_2_is_a_twenty_second_cut() {
    let t = cutting_s("g93_2.nc", "G00 X0 Z0\nG01 G93 X2 F3\nM30\n");
    assert!((t - 20.0).abs() < 0.1, "cutting {t} s");
}
