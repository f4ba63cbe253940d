//! `kerf run --stock`: exit status 3 on a collision, the report's `sim`
//! section, STL and PNG files, bad simulation input refused before the
//! run (exit 2), and nothing changed without `--stock`.

use std::path::PathBuf;
use std::process::{Command, Output};

fn kerf() -> Command {
    Command::new(env!("CARGO_BIN_EXE_kerf"))
}

fn dir() -> PathBuf {
    let d = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("cli-sim");
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn tmp(name: &str, text: &str) -> PathBuf {
    let p = dir().join(name);
    std::fs::write(&p, text).unwrap();
    p
}

const SLOT: &str = "G90 G54 G17\nT1 M06\nG43 H1 Z50.\nS2000 M03\nG00 X20. Y50.\nG00 Z5.\nG01 Z-2. F200\nG01 X80. F500\nG00 Z50.\nM30\n";
const STOCK: &str = "box:0,0,-20,100,100,0";

fn run(args: &[&str], prog: &PathBuf) -> Output {
    kerf().arg("run").arg(prog).args(args).output().unwrap()
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

#[test]
fn a_clean_run_exits_0_and_a_rapid_into_the_stock_exits_3() {
    let tools = tmp("flat10.toml", "[tool.1]\nkind=\"flat\"\ndiameter=10\n");
    let clean = tmp("slot.nc", SLOT);
    let rep = dir().join("slot.json");
    let stl = dir().join("slot.stl");
    let png = dir().join("slot.png");
    let o = run(
        &[
            "--stock",
            STOCK,
            "--tools",
            tools.to_str().unwrap(),
            "--sim-res",
            "0.2",
            "--report",
            rep.to_str().unwrap(),
            "--stl",
            stl.to_str().unwrap(),
            "--png",
            png.to_str().unwrap(),
        ],
        &clean,
    );
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let r: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&rep).unwrap()).unwrap();
    let s = &r["sim"];
    assert_eq!(s["stock_mm3"], 200000.0);
    assert_eq!(s["resolution_mm"], 0.2);
    // 10 × 2 × 60 + pi 25 × 2 = 1357.08 within the 0.2 mm grid's
    // perimeter × half diagonal × depth = 151.4 × 0.141 × 2 = 43 mm³.
    let removed = s["removed_mm3"].as_f64().unwrap();
    assert!((removed - 1357.08).abs() < 43.0, "{removed}");
    let bytes = std::fs::read(&stl).unwrap();
    let c = kerf_sim::stl::check(&bytes).unwrap();
    assert_eq!(c.bad_edges, 0);
    assert!((c.volume - s["remaining_mm3"].as_f64().unwrap()).abs() < 1.0);
    assert_eq!(&std::fs::read(&png).unwrap()[1..4], b"PNG");

    let crash = tmp(
        "crash.nc",
        &SLOT.replace("M30\n", "G00 X50. Y20.\nG00 Z-1.\nM30\n"),
    );
    let o = run(
        &[
            "--stock",
            STOCK,
            "--tools",
            tools.to_str().unwrap(),
            "--sim-res",
            "0.2",
        ],
        &crash,
    );
    assert_eq!(o.status.code(), Some(3), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("crash.nc:11: collision rapid_into_stock"),
        "{}",
        stderr(&o)
    );
}

#[test]
fn without_tools_each_tool_is_a_warning_not_a_collision() {
    let p = tmp("slot2.nc", SLOT);
    let o = run(&["--stock", STOCK, "--sim-res", "0.2"], &p);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("slot2.nc:3: warning tool_unknown: tool 1"),
        "{}",
        stderr(&o)
    );
}

#[test]
fn bad_simulation_input_is_refused_before_the_run() {
    let p = tmp("slot3.nc", SLOT);
    let bad_tool = tmp("bad.toml", "[tool.1]\nkind=\"ball\"\ndiameter=-6\n");
    for (args, part) in [
        (vec!["--stock", "box:0,0,0,10,10"], "box needs 6 values"),
        (vec!["--stock", "bar:50,100"], "lathe stock"),
        (
            vec!["--stock", "box:0,0,-10,900,100,0"],
            "outside the X travel",
        ),
        (vec!["--stock", STOCK, "--sim-res", "0"], "--sim-res 0"),
        (vec!["--stock", STOCK, "--sim-res", "0.001"], "more than"),
        (
            vec!["--stock", STOCK, "--tools", bad_tool.to_str().unwrap()],
            "[tool.1]: diameter = -6",
        ),
        (vec!["--stl", "x.stl"], "--stl needs --stock"),
    ] {
        let o = run(&args, &p);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        assert!(stderr(&o).contains(part), "{args:?}: {}", stderr(&o));
        assert!(o.stdout.is_empty(), "{args:?} ran");
    }
}

#[test]
fn without_stock_the_report_has_no_sim_section() {
    let p = tmp("slot4.nc", SLOT);
    let rep = dir().join("nostock.json");
    let o = run(&["--report", rep.to_str().unwrap()], &p);
    assert_eq!(o.status.code(), Some(0));
    assert!(stderr(&o).is_empty());
    let text = std::fs::read_to_string(&rep).unwrap();
    assert!(!text.contains("\"sim\""));
}

#[test]
fn serve_refuses_a_bad_stock_before_binding_and_names_it_once() {
    let o = kerf()
        .args(["serve", "--machine", "hx-mc", "--stock", "box:1,2"])
        .output()
        .unwrap();
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    let e = stderr(&o);
    assert_eq!(e.matches("--stock box:1,2").count(), 1, "{e}");
    assert!(e.contains("box needs 6 values"), "{e}");
}
