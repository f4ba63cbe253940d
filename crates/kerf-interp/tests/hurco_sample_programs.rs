//! Sample programs of the Hurco MAX turning manual (002) not run
//! elsewhere: "Creating NC Part Programs" (the typical part program, which
//! switches to radius programming halfway), the G93 inverse time examples
//! and the G81 example copied from the mill manual.

mod common;
use common::{alarm, ok, round, run_on};
use kerf_canon::{Canon, Feed};
use kerf_interp::Run;

/// "Creating NC Part Programs", exactly as extracted: two comments are
/// wrapped onto the next line ("reset tool" / "offset)", "radius
/// programming," / "X axis at .5in.)").
const CREATING: &str = "\
N20 G90 G40 G94 T0000      (absolute mode, CRC off, reset tool
                           offset)
N30 G00 X2.5 T0101        (rapid to X, tool 1 offset 1)
N40 Z3                    (rapid to Z)
N60 X.5                   (rapid to X)
N70 G96 G07 S350 M03      (CSS, radius programming,
                           X axis at .5in.)
                           (350 SFM and clockwise)
N80 G01 G95 F.01 X0       (face, IPR 0.01)
N120 G00 Z4               (rapid to Z)
N130 X.5 Z3               (rapid to XZ)
N160 G01 X1 Z2            (taper)
N170 X1.7                 (face)
N180 Z0.3                 (turn)
N190 X1.9                 (face)
N200 Z0                   (turn)
N230 G00 X2.5             (rapid to X)
N240 Z3                   (rapid to Z)
N900 M30                  (end of program, rewind)
";

/// (line, kind, X radius, Z) of every motion.
fn path(r: &Run) -> Vec<(u32, &'static str, f64, f64)> {
    r.events
        .iter()
        .filter_map(|e| {
            let k = match e.cmd {
                Canon::Rapid { .. } => "R",
                Canon::Feed { .. } => "F",
                _ => return None,
            };
            let m = e.motion()?;
            Some((e.src.line, k, round(m.to[0]), round(m.to[2])))
        })
        .collect()
}

/// As extracted the first comment is not closed on its line: HU-004 at
/// its '(' (line 1, column 28), before any move.
#[test]
fn creating_nc_part_programs_as_extracted_alarms() {
    let r = run_on("hurco-lathe", CREATING);
    assert_eq!(alarm(&r), ("HU-004", 1, 28));
    assert!(path(&r).is_empty());
}

/// With the wrapped comments joined onto their lines (as the manual's
/// page shows them), the program runs. N30 and N60 come before `N70 G96
/// G07`, so their X words are diameters (G08 is the power-on mode,
/// docs/dialects.md §4): X2.5 → radius 1.25, X.5 → radius 0.25. From N80
/// on X is a radius: X0, then the taper (0.5, 3) → (1, 2), faces and
/// turns at radius 1.7 and 1.9, out to radius 2.5.
#[test]
fn creating_nc_part_programs_switches_to_radius_at_n70() {
    let text = CREATING
        .replace(
            "reset tool\n                           offset)",
            "reset tool offset)",
        )
        .replace(
            "radius programming,\n                           X axis at .5in.)",
            "radius programming, X axis at .5in.)",
        );
    let r = run_on("hurco-lathe", &text);
    ok(&r);
    let got: Vec<_> = path(&r).into_iter().skip(1).collect();
    // Joined lines: N30 2, N40 3, N60 4, N70 5 (+1 comment line), N80 7,
    // N120 8, N130 9, N160 10, N170 11, N180 12, N190 13, N200 14,
    // N230 15, N240 16.
    assert_eq!(
        got,
        vec![
            (3, "R", 1.25, 3.0),
            (4, "R", 0.25, 3.0),
            (7, "F", 0.0, 3.0),
            (8, "R", 0.0, 4.0),
            (9, "R", 0.5, 3.0),
            (10, "F", 1.0, 2.0),
            (11, "F", 1.7, 2.0),
            (12, "F", 1.7, 0.3),
            (13, "F", 1.9, 0.3),
            (14, "F", 1.9, 0.0),
            (15, "R", 2.5, 0.0),
            (16, "R", 2.5, 3.0),
        ]
    );
    let first = path(&r)[0];
    assert_eq!((first.0, first.1, first.2), (2, "R", 1.25));
}

/// The F values of the inverse-time feed moves, in order.
fn inverse_time(r: &Run) -> Vec<f64> {
    r.events
        .iter()
        .filter_map(|e| match e.cmd {
            Canon::Feed {
                feed: Feed::InverseTime(f),
                ..
            } => Some(f),
            _ => None,
        })
        .collect()
}

/// G93 example 1: "a four-minute cut … F = 1/(4 minutes) = 0.25", block
/// `N100 G93 X2 F.25`. The block has no G01; it cuts when G01 is in
/// force (in the power-on G00 it would be a rapid), so a `G01` block comes
/// first. X2 is a diameter (G08): radius 1.
#[test]
fn g93_example_1_four_minutes() {
    let r = run_on(
        "hurco-lathe",
        "G00 X0 Z0\nG01 G94 F10 Z-1\nN100 G93 X2 F.25\nM30\n",
    );
    ok(&r);
    assert_eq!(inverse_time(&r), vec![0.25]);
    assert_eq!(path(&r).last().copied(), Some((3, "F", 1.0, -1.0)));
}

/// G93 example 2: a 20-second cut, F = 1 / (1/3 min) = 3.
#[test]
fn g93_example_2_twenty_seconds() {
    let r = run_on("hurco-lathe", "G00 X0 Z0\nG01 G93 X2 F3\nM30\n");
    ok(&r);
    assert_eq!(inverse_time(&r), vec![3.0]);
}

/// 002's G81 example `N020 G81 X2 Y2 Z-1.2 R.1 F10 G99` is copied from
/// the mill manual; the lathe has no Y address: HU-001 at the Y word
/// (docs/dialects.md §4).
#[test]
fn g81_example_with_y_is_an_illegal_address() {
    let r = run_on(
        "hurco-lathe",
        "N010 G90\nN020 G81 X2 Y2 Z-1.2 R.1 F10 G99\n",
    );
    assert_eq!(alarm(&r), ("HU-001", 2, 13));
}
