//! The command-line contract of design.md: exit statuses, the alarm line
//! with its caret, the report and the plot.

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

/// Reads a JSON file the run wrote (the report).
fn read_json(p: &std::path::Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(p).unwrap()).unwrap()
}

fn tmp(name: &str, text: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("cli");
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

#[test]
fn alarm_line_caret_and_exit_status() {
    let p = tmp("bad.nc", "G90 G00 X0 Y0\nG01 X10. Y5.\n");
    let out = kerf().arg("run").arg(&p).output().unwrap();
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8(out.stderr).unwrap();
    let mut lines = err.lines();
    // G01 without any F: F_84020 at line 2, column 1 (the G01 word).
    assert_eq!(
        lines.next().unwrap(),
        format!(
            "{}:2:1: alarm F_84020: cutting move without a feedrate (no F commanded)",
            p.display()
        )
    );
    assert_eq!(lines.next().unwrap(), "  G01 X10. Y5.");
    assert_eq!(lines.next().unwrap(), "  ^");
}

#[test]
fn caret_under_the_column() {
    let p = tmp("col.nc", "G00 X1. @\n");
    let out = kerf().arg("check").arg(&p).output().unwrap();
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(
        err.starts_with(&format!("{}:1:9: alarm F_82001:", p.display())),
        "{err}"
    );
    assert!(err.contains("\n  G00 X1. @\n          ^\n"), "{err}");
}

#[test]
fn usage_and_io_errors_exit_2() {
    let out = kerf().args(["run", "/nonexistent/x.nc"]).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    let p = tmp("ok.nc", "G00 X0\n");
    let out = kerf()
        .arg("run")
        .arg(&p)
        .args(["--machine", "no-such"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let out = kerf()
        .arg("run")
        .arg(&p)
        .args(["--set", "bogus=1"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn machines_lists_the_three_profiles() {
    let out = kerf().arg("machines").output().unwrap();
    assert!(out.status.success());
    let s = String::from_utf8(out.stdout).unwrap();
    for m in ["hx-mc", "puma-lathe", "hurco-lathe"] {
        assert!(s.contains(m), "{s}");
    }
}

#[test]
fn report_and_plot() {
    // A 100 x 50 rectangle at F600 after a rapid: feed length 300 mm = 30 s.
    let p = tmp(
        "rect.nc",
        "G90 G00 X0 Y0 Z0\nG01 X100. F600.\nY50.\nX0\nY0\nG00 X10. Y10.\nM30\n",
    );
    let rep = p.with_extension("json");
    let svg = p.with_extension("svg");
    let out = kerf()
        .arg("run")
        .arg(&p)
        .arg("--report")
        .arg(&rep)
        .arg("--plot")
        .arg(&svg)
        .output()
        .unwrap();
    assert_success(&out);
    let r: serde_json::Value = read_json(&rep);
    assert_eq!(r["status"], "completed");
    assert_eq!(r["alarm"], serde_json::Value::Null);
    assert_eq!(r["blocks"], 7);
    assert_eq!(r["motions"], 6);
    assert_eq!(r["feed_length_mm"], 300.0);
    assert_eq!(r["bbox"]["max"]["x"], 100.0);
    assert_eq!(r["bbox"]["max"]["y"], 50.0);
    // hx-mc planner (docs/motion.md), worked by hand: path acceleration
    // A = accel/2 = 1000 mm/s², smoothing T = 2·rapid_accel/jerk =
    // 2·3000/200000 = 0.03 s, 2 stages. At the 90° corners the smoothing
    // of the braking alone, A·T²/24 = 0.0375 mm, exceeds the 0.02 mm path
    // tolerance: each corner is an exact stop. At F600 = 10 mm/s each move
    // from rest to rest takes L/10 + 10/1000 s: 10.01 + 5.01 + 10.01 + 5.01
    // = 30.04 s, plus four stops of 2·T = 0.06 s: 30.28 s, plus four
    // in-position waits (K = 30/s, width 0.01 mm): lag v/K = 0.33333 mm in
    // the cruise; after the 0.01 s braking (x = 0.3, E = e^-0.3 = 0.740818)
    // 0.33333·E + 10·(1 − E)/30 − 1000·(0.3 − (1 − E))/900 = 0.287980 mm;
    // times ((1 − e^-0.9)/0.9)² = 0.434765: 0.125203 mm; the wait
    // ln(12.5203)/30 = 0.084245 s. 30.28 + 4·0.084245 = 30.616981 s.
    assert!(
        (r["time_s"]["cutting"].as_f64().unwrap() - 30.616981).abs() < 2e-6,
        "{}",
        r["time_s"]
    );
    assert_eq!(r["final"]["work"]["x"], 10.0);
    let s = std::fs::read_to_string(&svg).unwrap();
    // One dashed path for the rapid (and the legend's dashed sample), one
    // chained path for the four cuts of tool 0: a move then four lines that
    // close a rectangle twice as wide as it is high, drawn at one scale in
    // X and Y with Y up (screen y falls as Y rises).
    assert!(s.starts_with("<svg"), "{s}");
    assert_eq!(s.matches("stroke-dasharray").count(), 2, "{s}");
    let rect = s
        .split("<path d=\"")
        .skip(1)
        .map(|p| p.split('"').next().unwrap())
        .map(svg_points)
        .find(|pts| pts.len() == 5)
        .unwrap_or_else(|| panic!("no five-point path: {s}"));
    let [(x0, y0), (x1, y1), (x2, y2), (x3, y3), (x4, y4)] = rect[..] else {
        unreachable!()
    };
    let (w, h) = (x1 - x0, y1 - y2);
    assert!(w > 100.0 && (w - 2.0 * h).abs() < 0.02, "{rect:?}");
    assert!((y1 - y0).abs() < 0.01 && (x2 - x1).abs() < 0.01, "{rect:?}");
    assert!((x3 - x0).abs() < 0.01 && (y3 - y2).abs() < 0.01, "{rect:?}");
    assert!((x4 - x0).abs() < 0.01 && (y4 - y0).abs() < 0.01, "{rect:?}");
}

/// The points of an SVG path made of `M x y` and `L x y` commands.
fn svg_points(d: &str) -> Vec<(f64, f64)> {
    d.split(['M', 'L'])
        .filter(|p| !p.trim().is_empty())
        .filter_map(|p| {
            let mut it = p.split_whitespace().map(|v| v.parse::<f64>());
            match (it.next(), it.next()) {
                (Some(Ok(x)), Some(Ok(y))) => Some((x, y)),
                _ => None,
            }
        })
        .collect()
}

#[test]
fn lathe_toolpath_x_is_a_radius() {
    let p = tmp("lathe.nc", "G00 X50. Z5.\nG01 X40. Z0 F0.2\n");
    let tp = p.with_extension("jsonl");
    let out = kerf()
        .arg("run")
        .arg(&p)
        .args(["--machine", "puma-lathe", "--toolpath"])
        .arg(&tp)
        .output()
        .unwrap();
    assert_success(&out);
    let text = std::fs::read_to_string(&tp).unwrap();
    let recs: Vec<serde_json::Value> = text
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(recs.len(), 2);
    assert_eq!(recs[0]["to"]["x"], 25.0);
    assert_eq!(recs[1]["to"]["x"], 20.0);
    assert_eq!(recs[1]["kind"], "feed");
    assert_eq!(recs[1]["line"], 2);
    assert!(recs[0]["to"].get("y").is_none(), "a 2-axis lathe has no Y");
}

#[test]
fn block_longer_than_the_control_allows() {
    let long = format!("G00 X1.{}\n", " ".repeat(400));
    let p = tmp("long.nc", &long);
    let out = kerf().arg("run").arg(&p).output().unwrap();
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(
        err.contains(":1:") && err.contains("alarm F_82111"),
        "{err}"
    );
}

#[test]
fn user_profile_and_offsets_file() {
    // A user profile: the built-in HX with a G54 at machine X -100.
    let text = include_str!("../../../machines/hx-mc.toml")
        .replace("name = \"hx-mc\"", "name = \"my-mill\"");
    let prof = tmp("my-mill.toml", &text);
    let offs = tmp(
        "offs.toml",
        "[g54]\nx = -100.0\ny = -100.0\nz = -100.0\n[h]\n1 = 25.0\n[h_wear]\n1 = -0.5\n",
    );
    let p = tmp("offs.nc", "G90 G00 X10. Y0 Z0\nG43 H1 Z0\n");
    let tp = p.with_extension("jsonl");
    let out = kerf()
        .arg("run")
        .arg(&p)
        .arg("--machine")
        .arg(&prof)
        .arg("--offsets")
        .arg(&offs)
        .arg("--toolpath")
        .arg(&tp)
        .output()
        .unwrap();
    assert_success(&out);
    let recs: Vec<serde_json::Value> = std::fs::read_to_string(&tp)
        .unwrap()
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    // Machine = G54 origin + work: X -100 + 10; with H1 = 25 - 0.5 (wear)
    // the gauge line is 24.5 above Z0.
    assert_eq!(recs[0]["mto"]["x"], -90.0);
    assert_eq!(recs[0]["mto"]["z"], -100.0);
    assert_eq!(recs[1]["mto"]["z"], -75.5);
    // H129 is beyond the HX's 128 offsets: a usage error naming it.
    let offs = tmp("offs-bad.toml", "[h]\n129 = 1.0\n");
    let out = kerf()
        .arg("run")
        .arg(&p)
        .arg("--offsets")
        .arg(&offs)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("129"));
    // A bad profile is a usage error.
    let bad = tmp("bad.toml", "name = 1\n");
    let out = kerf()
        .arg("run")
        .arg(&p)
        .arg("--machine")
        .arg(&bad)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
}

/// `--lib DIR`: programs called by number come from the folder; toolpath
/// records and alarms name the library file.
#[test]
fn lib_folder_programs() {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("cli-lib");
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("O0100.nc"), "O0100\nG00 X5.\nM99\n").unwrap();
    std::fs::write(dir.join("200.nc"), "G00 X1.\nG01 X2.\nM99\n").unwrap();
    let main = tmp("libmain.nc", "G54 G90 G00 X0. Y0. Z0.\nM98 P100\nM30\n");
    let tp = dir.join("tp.jsonl");
    let out = kerf()
        .args(["run", "--lib"])
        .arg(&dir)
        .arg(&main)
        .arg("--toolpath")
        .arg(&tp)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0), "{out:?}");
    let text = std::fs::read_to_string(&tp).unwrap();
    let last: serde_json::Value = serde_json::from_str(text.lines().last().unwrap()).unwrap();
    assert!(
        last["file"].as_str().unwrap().ends_with("O0100.nc"),
        "{last}"
    );
    assert_eq!(last["line"], 2);
    assert_eq!(last["to"]["x"], 5.0);
    // Without --lib the program is missing: F_82109 at the M98.
    let out = kerf().arg("check").arg(&main).output().unwrap();
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(err.starts_with(&format!("{}:2:", main.display())), "{err}");
    assert!(err.contains("alarm F_82109"), "{err}");
    // An alarm inside the library program points into its file.
    let main2 = tmp("libmain2.nc", "M98 P200\nM30\n");
    let out = kerf()
        .args(["check", "--lib"])
        .arg(&dir)
        .arg(&main2)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(
        err.starts_with(&format!(
            "{}:2:1: alarm F_84020",
            dir.join("200.nc").display()
        )),
        "{err}"
    );
    assert!(err.contains("\n  G01 X2.\n"), "{err}");
    // --lib must name a folder.
    let out = kerf()
        .args(["check", "--lib", "/nonexistent-kerf-lib"])
        .arg(&main)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn inverse_time_feed_is_reported_in_mm_per_min() {
    // Hurco G93: F2 means the move takes 1/2 minute. Z from 0 to -2 in
    // (50.8 mm) in 0.5 min is 101.6 mm/min.
    let p = tmp("g93.nc", "G20 G90 G07 G00 X1 Z0\nG93 G01 Z-2 F2\n");
    let tp = p.with_extension("jsonl");
    let out = kerf()
        .arg("run")
        .arg(&p)
        .args(["--machine", "hurco-lathe", "--toolpath"])
        .arg(&tp)
        .output()
        .unwrap();
    assert_success(&out);
    let recs: Vec<serde_json::Value> = std::fs::read_to_string(&tp)
        .unwrap()
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(recs[1]["kind"], "feed");
    assert_eq!(recs[1]["feed"], 101.6);
}

#[test]
fn message_log_and_report_messages() {
    // Hurco G38 S0 against a surface at Z7.55 (expected 7.6): the recorded
    // datum line in 002's format goes to --log and to the report.
    let p = tmp(
        "probe.nc",
        "G20\nG0 X10 Z10\nG38 S0 Z7.6 A.5 T.125 V20 F10\nM30\n",
    );
    let log = p.with_extension("log");
    let rep = p.with_extension("json");
    let out = kerf()
        .arg("run")
        .arg(&p)
        .args([
            "--machine",
            "hurco-lathe",
            "--set",
            "probe.z=7.55",
            "--set",
            "probe.time=08:30:05",
            "--log",
        ])
        .arg(&log)
        .arg("--report")
        .arg(&rep)
        .output()
        .unwrap();
    assert_success(&out);
    // -Z offset = 7.6 - 7.55 = .05; at X10 (diameter) Z7.55.
    let line = "08:30:05 Probe Datum: Probe #-1; -Z Offset 0.0500 at X10.0000, Z7.5500";
    assert_eq!(std::fs::read_to_string(&log).unwrap(), format!("{line}\n"));
    let r: serde_json::Value = read_json(&rep);
    assert_eq!(r["messages"][0]["line"], 3);
    assert_eq!(r["messages"][0]["text"], line);
}

#[test]
fn sample_output_and_t_end() {
    // hx-mc: X -20 mm at F1200 (20 mm/s) from the start position, then back.
    let p = tmp("sample.nc", "G91 G01 X-20. F1200.\nX20.\nM30\n");
    let csv = p.with_extension("csv");
    let tp = p.with_extension("jsonl");
    let rep = p.with_extension("json");
    let out = kerf()
        .arg("run")
        .arg(&p)
        .args(["--sample", "0.001"])
        .arg(&csv)
        .arg("--toolpath")
        .arg(&tp)
        .arg("--report")
        .arg(&rep)
        .output()
        .unwrap();
    assert_success(&out);
    let text = std::fs::read_to_string(&csv).unwrap();
    let mut lines = text.lines();
    assert_eq!(lines.next().unwrap(), "t,x,y,z,c");
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    // hx-mc starts at machine zero.
    assert_eq!(rows[0], vec![0.0, 0.0, 0.0, 0.0, 0.0]);
    let xmin = rows.iter().map(|r| r[1]).fold(f64::MAX, f64::min);
    assert!((xmin + 20.0).abs() < 1e-9, "{xmin}");
    // By hand (docs/motion.md): T = 2·3000/200000 = 0.03 s, A = 1000 mm/s².
    // The reversal is an exact stop: the smoothing of the braking alone
    // would miss the turning point by 2·A·T²/24 = 0.075 mm > 0.02 mm. Each
    // move from rest to rest: 20/20 + 20/1000 = 1.02 s, plus the stop
    // 2·T = 0.06 s, plus the in-position wait (docs/motion.md, position
    // gain K = 30/s, width 0.01 mm): the loop's error behind the
    // unsmoothed command, v/K = 0.6667 mm in the cruise, after the 0.02 s
    // braking (x = K·0.02 = 0.6, E = e^-0.6 = 0.548812):
    // 0.6667·E + 20·(1 − E)/30 − 1000·(0.6 − (1 − E))/900 = 0.501320 mm;
    // when the smoothed command arrives, times ((1 − e^-0.9)/0.9)² =
    // 0.434765: 0.217957 mm; the wait ln(21.7957)/30 = 0.102724 s.
    // t_end 1.182724 s and 2.365447 s.
    let r: serde_json::Value = read_json(&rep);
    let ct = r["cycle_time_s"].as_f64().unwrap();
    assert!((ct - 2.365447).abs() < 2e-6, "{ct}");
    let last_t = rows.last().unwrap()[0];
    assert!(last_t <= ct && ct - last_t < 0.001, "{last_t}");
    assert_eq!(rows.last().unwrap()[1], 0.0);
    let recs: Vec<serde_json::Value> = std::fs::read_to_string(&tp)
        .unwrap()
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(recs.len(), 2);
    assert!((recs[0]["t_end"].as_f64().unwrap() - 1.182724).abs() < 2e-6);
    assert!((recs[1]["t_end"].as_f64().unwrap() - 2.365447).abs() < 2e-6);
}

#[test]
fn profile_without_a_limit_names_the_parameter() {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../machines/hx-mc.toml"
    ))
    .unwrap();
    let bad = text.replacen("jerk = 200000.0", "jerk = 0.0", 1);
    assert_ne!(bad, text);
    let p = tmp("ok.nc", "G00 X0\nM30\n");
    // A usage error (exit 2); its message.
    let rejected = |name: &str, profile: &str| {
        let out = kerf()
            .arg("run")
            .arg(&p)
            .arg("--machine")
            .arg(tmp(name, profile))
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(2));
        String::from_utf8(out.stderr).unwrap()
    };
    let err = rejected("nojerk.toml", &bad);
    assert!(err.contains("motion.axes.x.jerk"), "{err}");
    let missing = text.replacen("path_tolerance_mm = 0.02", "", 1);
    assert_ne!(missing, text);
    let err = rejected("notol.toml", &missing);
    assert!(err.contains("motion.path_tolerance_mm is missing"), "{err}");
}

#[test]
fn puma_css_facing_follows_the_g50_clamp() {
    // Facing from X80 to X10 (diameter: radius 40 → 5) at 0.2 mm/rev under
    // G96 S200 (m/min). rpm(x) = 200000/(2π·x) at radius x; G50 S1500
    // clamps it below x_c = 200000/(2π·1500) = 21.2207 mm. Worked by hand:
    //  x in [x_c, 40]: ∫ 60·2π·x/(0.2·200000) dx = 0.0094248·(40² − x_c²)/2
    //                 = 0.0094248·574.84 = 5.4178 s;
    //  x in [5, x_c]:  (21.2207 − 5)/(0.2·1500/60 = 5 mm/s) = 3.2441 s;
    // 8.6619 s; the stop 2T = 0.05 s (T = 2·2500/200000); the in-position
    // wait (docs/motion.md; braking 5 mm/s at 750 mm/s², K = 30/s):
    // lag 0.151058 mm, times ((1 − e^-0.75)/0.75)² = 0.494928: 0.074763 mm,
    // ln(7.4763)/30 = 0.067058 s. Cutting time 8.778946 s.
    // Without the program's clamp the machine's 2000 rpm binds below
    // 15.9155 mm: 6.3462 + 1.6373 + 0.05 + 0.075579 (the wait from
    // 6.667 mm/s) = 8.109064 s.
    for (clamp, want) in [("G50 S1500\n", 8.778946), ("", 8.109064)] {
        let p = tmp(
            "facing.nc",
            &format!("{clamp}G96 S200 M03\nG00 X80. Z0\nG99 G01 X10. F0.2\nM30\n"),
        );
        let rep = p.with_extension("json");
        let out = kerf()
            .arg("run")
            .arg(&p)
            .args(["--machine", "puma-lathe", "--report"])
            .arg(&rep)
            .output()
            .unwrap();
        assert_success(&out);
        let r: serde_json::Value = read_json(&rep);
        let got = r["time_s"]["cutting"].as_f64().unwrap();
        // The 16 pieces of the move ramp between their feeds (a few ms):
        // within 0.5 %.
        assert!(
            (got - want).abs() <= 0.005 * want,
            "clamp {clamp:?}: cutting {got} s, by hand {want} s"
        );
    }
}

#[test]
fn hx_g62_slows_inside_corners_of_the_compensated_path() {
    // A 50 mm square, CCW, cutter radius 10 on the left (G41): the tool
    // centre runs (0,10) → (40,10) → (40,40) → (10,40) → (10,0); the
    // corners at (40,10), (40,40), (10,40) are inside, the one at (0,10)
    // (after the start-up move) outside. hx-mc: F600 = 10 mm/s, path
    // acceleration 1000 mm/s²; every 90° corner is an exact stop there
    // (0.02 mm tolerance). G62 (hx-mc: 50 %, 1 mm before, 1 mm after):
    // a move ending in a 1 mm tail at 5 mm/s takes, by hand,
    // 0.01 + 0.005 (0 → 10 → 5) + (L − 1 − 0.0875)/10 + (1 − 0.0125)/5
    // + 0.005 (5 → 0) = L/10 + 0.10875 s instead of L/10 + 0.01 s:
    // 0.09875 s more; the same for a 1 mm head at 5 mm/s after a corner.
    // Three inside corners: 6 · 0.09875 = 0.5925 s more cutting time. (The
    // servo is made stiff, position_gain 1e9/s, so that the in-position
    // waits, which depend on the braking speed, are 0 in both runs.)
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../machines/hx-mc.toml"
    ))
    .unwrap();
    let stiff = text.replacen("position_gain = 30.0", "position_gain = 1e9", 1);
    assert_ne!(stiff, text);
    let prof = tmp("stiff.toml", &stiff);
    let cutting = |mode: &str| {
        let p = tmp(
            &format!("g62_{mode}.nc"),
            &format!(
                "G10 L12 P1 R10.\nG54 G90 G00 X-20. Y-20. Z0\n{mode} G41 D1 G01 X0 Y0 F600.\n\
                 X50.\nY50.\nX0.\nY0.\nG40 G00 X-20. Y-20.\nM30\n"
            ),
        );
        let rep = p.with_extension("json");
        let out = kerf()
            .arg("run")
            .arg(&p)
            .arg("--machine")
            .arg(&prof)
            .arg("--report")
            .arg(&rep)
            .output()
            .unwrap();
        assert_success(&out);
        let r: serde_json::Value = read_json(&rep);
        r["time_s"]["cutting"].as_f64().unwrap()
    };
    let (g64, g62) = (cutting("G64"), cutting("G62"));
    assert!(
        (g62 - g64 - 0.5925).abs() < 2e-6,
        "G62 {g62} s, G64 {g64} s"
    );
}

/// A main program ending in M99 (a bar-feed loop) runs one pass and exits
/// 0, with the operator message and warning KERF-W006 in the report;
/// `--set main_passes=3` runs three passes (3 × 2 moves). The system-B
/// and calculator-type decimal point keys reach the interpreter (issue 15).
#[test]
fn main_m99_passes_and_issue_15_keys() {
    let p = tmp("m99.nc", "%\nG54 G91 G00 X-1.\nX1.\nM99\n%\n");
    let rep = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("cli/m99.json");
    for (passes, motions) in [(None, 2), (Some("main_passes=3"), 6)] {
        let mut c = kerf();
        c.arg("run").arg(&p).arg("--report").arg(&rep);
        if let Some(s) = passes {
            c.args(["--set", s]);
        }
        let out = c.output().unwrap();
        assert_success(&out);
        let r = read_json(&rep);
        assert_eq!(r["status"], "completed");
        assert_eq!(r["motions"], motions);
        assert_eq!(r["warnings"][0]["code"], "KERF-W006");
        assert!(r["messages"][0]["text"]
            .as_str()
            .unwrap()
            .starts_with("M99 in the main program: ended after"));
    }
    // G-code system B: G90/G95 and G92 S are accepted with the key.
    let p = tmp(
        "sysb.nc",
        "G21 G90 G40 G95\nG92 S500\nG97 S300 M3\nG0 X50. Z5.\nM30\n",
    );
    let out = kerf()
        .arg("run")
        .arg(&p)
        .args(["--machine", "puma-lathe"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1), "system A: G95 is unknown");
    let out = kerf()
        .arg("run")
        .arg(&p)
        .args(["--machine", "puma-lathe", "--set", "gcode_system_b=1"])
        .output()
        .unwrap();
    assert_success(&out);
    // Calculator-type decimal point: X40 = 40 mm diameter.
    let p = tmp("calc.nc", "G0 X40 Z-2\nM30\n");
    let out = kerf()
        .arg("run")
        .arg(&p)
        .args(["--machine", "puma-lathe", "--set", "calculator_decimal=on"])
        .args(["--report"])
        .arg(&rep)
        .output()
        .unwrap();
    assert_success(&out);
    let r = read_json(&rep);
    assert_eq!(r["final"]["work"]["z"], -2.0, "{r}");
}

/// The PUMA's G55 takes its zero from the `--offsets` table (machine Z
/// −500): `G55 G00 X50. Z10.` ends at machine (radius 25, −490), reading
/// (25, 10).
#[test]
fn puma_work_offsets_from_the_offset_table() {
    let p = tmp("g55.nc", "G55 G00 X50. Z10.\nM30\n");
    let off = tmp("g55.toml", "[g55]\nx = 0.0\nz = -500.0\n");
    let tp = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("cli/g55.jsonl");
    let out = kerf()
        .arg("run")
        .arg(&p)
        .args(["--machine", "puma-lathe", "--offsets"])
        .arg(&off)
        .arg("--toolpath")
        .arg(&tp)
        .output()
        .unwrap();
    assert_success(&out);
    let line = std::fs::read_to_string(&tp).unwrap();
    let v: serde_json::Value = serde_json::from_str(line.lines().next().unwrap()).unwrap();
    assert_eq!(v["to"]["x"], 25.0);
    assert_eq!(v["to"]["z"], 10.0);
    assert_eq!(v["mto"]["z"], -490.0);
}

#[test]
fn g107_is_plotted_unrolled_on_its_cylinder() {
    // G107 C10 (000 §4.7): Z0 → Z20, then C0 → C180, half a turn of a
    // 10 mm cylinder, π·10 = 31.416 mm on the developed surface. Drawn at
    // one scale, the C leg is π/2 = 1.5708 times the Z leg (in degrees it
    // would be 9 times).
    let p = tmp(
        "g107.nc",
        "G54 G00 G90 Z0 C0\nG18\nG107 C10.\nG01 Z20. F100\nC180.\nG107 C0\nM30\n",
    );
    let svg = p.with_extension("svg");
    let out = kerf()
        .args(["run", "--quiet", "--plot"])
        .arg(&svg)
        .arg(&p)
        .output()
        .unwrap();
    assert_success(&out);
    let s = std::fs::read_to_string(&svg).unwrap();
    assert!(s.contains("C as arc length on r 10 mm"), "{s}");
    let leg = s
        .split("<path d=\"")
        .skip(1)
        .map(|p| p.split('"').next().unwrap())
        .map(svg_points)
        .find(|pts| pts.len() == 3)
        .unwrap_or_else(|| panic!("no three-point path: {s}"));
    let [(x0, y0), (x1, y1), (x2, y2)] = leg[..] else {
        unreachable!()
    };
    let (z, c) = (x1 - x0, y1 - y2);
    assert!((y1 - y0).abs() < 0.01 && (x2 - x1).abs() < 0.01, "{leg:?}");
    assert!(
        (c / z - std::f64::consts::FRAC_PI_2).abs() < 1e-3,
        "{leg:?}"
    );
}
