//! PUMA direct chamfer and corner R (001 p.10 "AUTO CHAMFERING C AND
//! CORNER R"): the N1-N3 example of 001 and the error cases of its note 3.
//! Expected points by hand (radius internally, compared as diameters).

use kerf_canon::Canon;
use kerf_interp::Run;

mod common;
use common::{alarm, ok, round, run_on};

const PUMA: &str = "puma-lathe";

/// (kind, X diameter, Z) of every move.
fn trace(r: &Run) -> Vec<(&'static str, f64, f64)> {
    r.events
        .iter()
        .filter_map(|e| {
            let k = match e.cmd {
                Canon::Rapid { .. } => "R",
                Canon::Feed { .. } => "F",
                Canon::Arc { .. } => "A",
                _ => return None,
            };
            let m = e.motion().unwrap();
            Some((k, round(2.0 * m.to[0]), round(m.to[2])))
        })
        .collect()
}

/// 001's example: from Ø40 Z80 (the drawing's start: Ø40 to Z30, face
/// to Ø100 with C3, Ø100 to Z0). N1 Z30 R6: the line stops 6 before the
/// corner (Z36), a quarter arc R6 about (radius 26, Z36) turns toward +X
/// and ends at (26, 30) = Ø52; moving −Z then +X is a clockwise turn in
/// the ZX plane (G02). N2 X100 K−3: from Ø52 to 3 before the corner
/// (radius 47, Ø94), chamfer to (50, 27); N3 Z0 from there.
fn example_expected() -> Vec<(&'static str, f64, f64)> {
    vec![
        ("R", 40.0, 80.0),
        ("F", 40.0, 36.0),
        ("A", 52.0, 30.0),
        ("F", 94.0, 30.0),
        ("F", 100.0, 27.0),
        ("F", 100.0, 0.0),
    ]
}

#[test]
fn example_001_n1_n3() {
    let r = run_on(
        PUMA,
        "G97 S500 M03\nG00 X40. Z80.\nN1 G01 Z30.0 R6.0 F0.2 ;\nN2 X100.0 K-3.0 ;\nN3 Z0 ;\n",
    );
    ok(&r);
    assert_eq!(trace(&r), example_expected());
    let arc = r
        .events
        .iter()
        .find_map(|e| match &e.cmd {
            Canon::Arc { center, dir, .. } => Some((round(center[0]), round(center[2]), *dir)),
            _ => None,
        })
        .unwrap();
    assert_eq!(arc, (26.0, 36.0, kerf_canon::ArcDir::Cw));
}

/// "(N2 X100.0 C3.0 :) Normal": C without a sign takes the direction
/// from the next block: the same path.
#[test]
fn example_001_with_c() {
    let r = run_on(
        PUMA,
        "G97 S500 M03\nG00 X40. Z80.\nN1 G01 Z30.0 R6.0 F0.2 ;\nN2 X100.0 C3.0 ;\nN3 Z0 ;\n",
    );
    ok(&r);
    assert_eq!(trace(&r), example_expected());
}

/// 001 note 2: the next block's incremental words count from the corner
/// B, not from where the tool stopped: U60 from B (Ø40) is Ø100, W−30 from
/// B (Z30) is Z0 — the same path again.
#[test]
fn incremental_from_corner() {
    let r = run_on(
        PUMA,
        "G97 S500 M03\nG00 X40. Z80.\nN1 G01 W-50. R6. F0.2\nN2 U60. K-3.\nN3 W-30.\n",
    );
    ok(&r);
    assert_eq!(trace(&r), example_expected());
}

#[test]
fn note_3_errors() {
    let head = "G97 S500 M03\nG00 X40. Z80.\n";
    let run = |body: &str| run_on(PUMA, &format!("{head}{body}"));
    // A chamfer word with X and Z together: PS054 at the word.
    assert_eq!(
        alarm(&run("G01 X50. Z20. R2. F0.2\nX60.\n")),
        ("PS054", 3, 15)
    );
    // Two of I, K, R in one block: PS053 at the second.
    assert_eq!(
        alarm(&run("G01 Z30. I2. R2. F0.2\nX60.\n")),
        ("PS053", 3, 14)
    );
    // X with I (I goes with a Z move): PS053.
    assert_eq!(alarm(&run("G01 X60. I2. F0.2\nZ60.\n")), ("PS053", 3, 10));
    // The next block is not G01: PS052 on the next block.
    assert_eq!(
        alarm(&run("G01 Z30. R6. F0.2\nG00 X60.\n")),
        ("PS052", 4, 1)
    );
    // The next block moves along the same axis: PS052.
    assert_eq!(alarm(&run("G01 Z30. R6. F0.2\nZ10.\n")), ("PS052", 4, 1));
    // The next block is a taper: PS054.
    assert_eq!(
        alarm(&run("G01 Z30. R6. F0.2\nX60. Z20.\n")),
        ("PS054", 4, 1)
    );
    // R+ says +X but the next block goes to Ø30: PS052.
    assert_eq!(alarm(&run("G01 Z30. R6. F0.2\nX30.\n")), ("PS052", 4, 1));
    // The next move (2 mm) is shorter than the chamfer (3): PS055 on it.
    assert_eq!(
        alarm(&run("G01 Z30. F0.2\nX100. K-3.\nZ28.\n")),
        ("PS055", 5, 1)
    );
    // The block's own move (2 mm) is shorter than the corner R (6).
    assert_eq!(alarm(&run("G01 Z78. R6. F0.2\nX60.\n")), ("PS055", 3, 10));
    // No next block.
    assert_eq!(alarm(&run("G01 Z30. R6. F0.2\n")), ("PS052", 3, 10));
}
