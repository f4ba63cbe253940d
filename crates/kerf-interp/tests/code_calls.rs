//! Macro calls by G code (PI 85-94 → 9010-9019), by M code (PI 95-104 →
//! 9020-9029) and subprogram call by T code (PI 105 → 9000), 000
//! §14.1.3-14.1.6, with small library programs. Positions by hand.

use kerf_canon::{Alarm, Event};
use kerf_interp::{Interp, Profile, Settings, Step};

fn lib(name: &str, files: &[(&str, &str)]) -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("kerf-code-calls-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    for (f, t) in files {
        std::fs::write(d.join(f), t).unwrap();
    }
    d
}

/// (file, line, x, y, z) of a motion end point.
type Move = (String, u32, f64, f64, f64);

fn run(dir: &std::path::Path, main: &str) -> (Vec<Move>, Option<Alarm>) {
    let mut p = Profile::builtin("hx-mc").unwrap();
    p.params.insert("PI 85".into(), 100.0);
    p.params.insert("PI 95".into(), 50.0);
    p.params.insert("PI 105".into(), 1.0);
    let mut it = Interp::new(p, Settings::default());
    it.add_lib_dir(dir.to_path_buf());
    it.load_main(
        "main.nc",
        Box::new(std::io::Cursor::new(main.as_bytes().to_vec())),
    );
    let mut ev: Vec<Event> = Vec::new();
    let alarm = loop {
        match it.step() {
            Step::Event(e) => ev.push(e),
            Step::End => break None,
            Step::Alarm(a) => break Some(a),
        }
    };
    let r = |v: f64| {
        let r = (v * 1e6).round() / 1e6;
        if r == 0.0 {
            0.0
        } else {
            r
        }
    };
    let m = ev
        .iter()
        .filter_map(|e| {
            let m = e.motion()?;
            let f = std::path::Path::new(it.file_name(e.src.file))
                .file_name()
                .unwrap()
                .to_string_lossy()
                .to_string();
            Some((f, e.src.line, r(m.to[0]), r(m.to[1]), r(m.to[2])))
        })
        .collect();
    (m, alarm)
}

#[test]
fn g_m_and_t_code_calls() {
    let d = lib(
        "gmt",
        &[
            ("9010.nc", "G91 G00 X[#24 + #1] Y#25\nG90\nM99\n"),
            ("9020.nc", "G91 G00 Z-#26\nG90\nM99\n"),
            ("9000.nc", "G90 G00 X#149\nM99\n"),
        ],
    );
    let (m, a) = run(
        &d,
        "G90 G54 G00 X0 Y0 Z0\n\
         G100 X10. Y20. A5.\n\
         M50 Z3.\n\
         G90 G00 X1. T7\n\
         G100 X2. Y2. L2\n\
         M30\n",
    );
    assert!(a.is_none(), "{a:?}");
    let s = |f: &str, l, x, y, z| (f.to_string(), l, x, y, z);
    assert_eq!(
        m,
        vec![
            s("main.nc", 1, 0.0, 0.0, 0.0),
            // G100 = G65 P9010 with X10 Y20 A5: +15, +20.
            s("9010.nc", 1, 15.0, 20.0, 0.0),
            // M50 = G65 P9020 with Z3 (#26): Z-3.
            s("9020.nc", 1, 15.0, 20.0, -3.0),
            // The block of T7 runs, then M98 P9000 with #149 = 7.
            s("main.nc", 4, 1.0, 20.0, -3.0),
            s("9000.nc", 1, 7.0, 20.0, -3.0),
            // L2: two passes of +2, +2 (A vacant adds 0).
            s("9010.nc", 1, 9.0, 22.0, -3.0),
            s("9010.nc", 1, 11.0, 24.0, -3.0),
        ]
    );
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn codes_inside_a_code_called_macro_are_ordinary() {
    // M50 inside the macro M50 called is an ordinary M code, which the HX
    // does not have: F_82031 in 9020.nc line 2, not a recursive call.
    let d = lib("inner", &[("9020.nc", "G91 G00 Z-1.\nM50\nM99\n")]);
    let (m, a) = run(&d, "G90 G54 G00 X0 Y0 Z0\nM50\nM30\n");
    let a = a.expect("alarm");
    assert_eq!((a.code.as_str(), a.src.line), ("F_82031", 2));
    assert_eq!(m.len(), 2);
    // Another G code in a block that calls by code is refused.
    let d2 = lib("other", &[("9010.nc", "M99\n")]);
    let (_, a) = run(&d2, "G00 G100 X1.\nM30\n");
    assert_eq!(a.expect("alarm").src.line, 1);
    // A missing library program is the usual program-not-found alarm.
    let (_, a) = run(&d2, "M50\nM30\n");
    assert_eq!(a.expect("alarm").src.line, 1);
    let _ = std::fs::remove_dir_all(&d);
    let _ = std::fs::remove_dir_all(&d2);
}
