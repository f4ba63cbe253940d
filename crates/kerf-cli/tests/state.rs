//! Retained macro variables across runs (`--state DIR`): #200-#699 on the
//! HX, #500-#999 on the Fanuc lathe; commons #100-#199 start vacant.

use std::path::PathBuf;
use std::process::Command;

fn kerf() -> Command {
    Command::new(env!("CARGO_BIN_EXE_kerf"))
}

/// Asserts the run exited 0, showing its stderr otherwise.
fn assert_success(out: &std::process::Output) {
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

fn dir(name: &str) -> PathBuf {
    let d = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join("state")
        .join(name);
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Runs `prog` and returns the work x (`to`) of every motion.
fn xs(prog: &PathBuf, machine: &str, state: &PathBuf) -> Vec<f64> {
    xs_of("to", prog, machine, state)
}

/// Runs `prog` and returns the x of `field` (`to` or `mto`) of every motion.
fn xs_of(field: &str, prog: &PathBuf, machine: &str, state: &PathBuf) -> Vec<f64> {
    let tp = prog.with_extension("jsonl");
    let out = kerf()
        .arg("run")
        .arg(prog)
        .args(["--machine", machine, "--state"])
        .arg(state)
        .arg("--toolpath")
        .arg(&tp)
        .output()
        .unwrap();
    assert_success(&out);
    std::fs::read_to_string(&tp)
        .unwrap()
        .lines()
        .map(|l| {
            let v: serde_json::Value = serde_json::from_str(l).unwrap();
            v[field]["x"].as_f64().unwrap()
        })
        .collect()
}

#[test]
fn retained_variables_survive_between_runs_hx() {
    let d = dir("hx");
    // #200 counts runs; #100 must be vacant at the start of every run
    // (X0 when vacant, X50 when it kept a value), #699 keeps a fraction.
    let prog = d.join("count.nc");
    std::fs::write(
        &prog,
        "G90 G00 X0 Y0 Z0\n\
         #200 = #200 + 1\n\
         IF [#100 EQ #0] GOTO 5\n\
         G00 X50.\n\
         N5 #100 = 7\n\
         #699 = #699 + 0.125\n\
         G00 X[#200 + #699]\n\
         M30\n",
    )
    .unwrap();
    // Run 1: #200 = 1, #699 = 0.125 → X1.125. Run 2: 2 + 0.25 → X2.25.
    assert_eq!(xs(&prog, "hx-mc", &d), vec![0.0, 1.125]);
    assert_eq!(xs(&prog, "hx-mc", &d), vec![0.0, 2.25]);
    let text = std::fs::read_to_string(d.join("hx-mc.vars")).unwrap();
    assert!(text.contains("#200 = 2.0\n"), "{text}");
    assert!(text.contains("#699 = 0.25\n"), "{text}");
    assert!(!text.contains("#100"), "{text}");
    // No temporary file is left behind.
    let n = std::fs::read_dir(&d)
        .unwrap()
        .filter(|e| {
            e.as_ref()
                .unwrap()
                .file_name()
                .to_string_lossy()
                .contains("tmp")
        })
        .count();
    assert_eq!(n, 0);
}

#[test]
fn retained_variables_on_the_lathe_and_after_an_alarm() {
    let d = dir("lathe");
    let prog = d.join("lathe.nc");
    // #500 is written before the alarm and kept; X is a diameter (radius
    // in the toolpath): run 1 X10. → 5, run 2 X20. → 10.
    std::fs::write(
        &prog,
        "#500 = #500 + 10.\nG00 X#500 Z5.\n#3000 = 1 (STOP)\n",
    )
    .unwrap();
    for want in [5.0, 10.0] {
        let tp = prog.with_extension("jsonl");
        let out = kerf()
            .arg("run")
            .arg(&prog)
            .args(["--machine", "puma-lathe", "--state"])
            .arg(&d)
            .arg("--toolpath")
            .arg(&tp)
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(1));
        let text = std::fs::read_to_string(&tp).unwrap();
        let v: serde_json::Value = serde_json::from_str(text.lines().next().unwrap()).unwrap();
        assert_eq!(v["to"]["x"].as_f64().unwrap(), want);
    }
    // A value outside the retained range in the file is refused.
    std::fs::write(d.join("puma-lathe.vars"), "#100 = 1\n").unwrap();
    let out = kerf()
        .arg("check")
        .arg(&prog)
        .args(["--machine", "puma-lathe", "--state"])
        .arg(&d)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
}

/// `--set in.7000=1` sets interface input UI000 (#7000) for the run.
#[test]
fn interface_inputs_from_set() {
    let d = dir("inputs");
    let prog = d.join("branch.nc");
    std::fs::write(
        &prog,
        "G90 G00 X0 Y0 Z0\nIF [#7000 EQ 1] GOTO 5\nG00 X1.\nN5 G00 X[2 + #7033]\nM30\n",
    )
    .unwrap();
    let tp = prog.with_extension("jsonl");
    let xs = |sets: &[&str]| -> Vec<f64> {
        let mut cmd = kerf();
        cmd.arg("run").arg(&prog).arg("--toolpath").arg(&tp);
        for s in sets {
            cmd.args(["--set", s]);
        }
        let out = cmd.output().unwrap();
        assert_success(&out);
        std::fs::read_to_string(&tp)
            .unwrap()
            .lines()
            .map(|l| {
                let v: serde_json::Value = serde_json::from_str(l).unwrap();
                v["to"]["x"].as_f64().unwrap()
            })
            .collect()
    };
    assert_eq!(xs(&[]), vec![0.0, 1.0, 2.0]);
    assert_eq!(xs(&["in.7000=1", "in.7033=3"]), vec![0.0, 5.0]);
}

#[test]
fn offset_memory_survives_between_runs() {
    let d = dir("offsets");
    // Each run adds 0.5 to D1 (G10 G91 L12) and moves to X = D1 (#2112).
    // Run 1: 0 + 0.5 -> X0.5; run 2: 1.0 -> X1.
    let prog = d.join("wear.nc");
    std::fs::write(&prog, "G10 G91 L12 P1 R0.5\nG90 G00 X#2112 Y0 Z0\nM30\n").unwrap();
    assert_eq!(xs(&prog, "hx-mc", &d), vec![0.5]);
    assert_eq!(xs(&prog, "hx-mc", &d), vec![1.0]);
    let text = std::fs::read_to_string(d.join("hx-mc.offsets")).unwrap();
    assert!(text.contains("\nD 1 1.0 0.0\n"), "{text}");
    // Lathe: offset 3 written by G10 (X as a diameter: 2.0 -> 1.0 radius)
    // is kept and used by T0303 in the next run: the turret stops 1 mm
    // (radius) further out for X40 than with T0300, while the tool tip
    // (`to`) is at the programmed radius 20 both times.
    let set = d.join("set.nc");
    std::fs::write(&set, "G10 P10003 X2. Z0.5 Q3\nM30\n").unwrap();
    assert_eq!(xs(&set, "puma-lathe", &d), Vec::<f64>::new());
    let t = d.join("use.nc");
    std::fs::write(&t, "G00 X40. Z5. T0303\nG00 X40. Z5. T0300\nM30\n").unwrap();
    assert_eq!(xs(&t, "puma-lathe", &d), vec![20.0, 20.0]);
    let m = xs_of("mto", &t, "puma-lathe", &d);
    assert!((m[0] - m[1] - 1.0).abs() < 1e-9, "{m:?}");
    // A damaged file is a usage error naming the line.
    std::fs::write(d.join("hx-mc.offsets"), "H 1 x\n").unwrap();
    let out = kerf()
        .arg("run")
        .arg(&prog)
        .args(["--machine", "hx-mc", "--state"])
        .arg(&d)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("hx-mc.offsets:1"));
}
