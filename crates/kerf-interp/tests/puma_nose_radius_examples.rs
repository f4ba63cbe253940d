//! The two "Tool diameter compensation" examples of the PUMA 450 training
//! manual (001 pp. 27-28): a Ø30 shaft with a C2 chamfer, nose R0.8.
//! Example 1 is the program without compensation (the chamfer points
//! corrected by hand); example 2 writes the part and lets G42 do it.
//!
//! The extraction prints the end of block `;` as ` :` and the zeros of
//! `G28 U0 W0` as the letter O (`G28 UO WO`); the programs below read
//! them as `;` and `0` (docs/dialects.md §3, typos). Neither example has a
//! start point or a T code: example 2 gets a preamble `T0101` / `G00
//! X40.0 Z5.0` (offset 1 = nose R0.8, tip 3, 001 p.29's offset page),
//! written before the printed blocks.
//!
//! Hand computation in (Z, X radius), tip 3 (centre → tip = (−r, −r)),
//! G42 (right of travel; direction (u, v) → right normal (v, −u)):
//! - start-up (type A, the PUMA default) `G42 X26.0 Z0` from (5, 20):
//!   ends on the normal of the chamfer at its start. The chamfer runs
//!   (0, 13) → (−2, 15), direction (−1, 1)/√2, normal (1, 1)/√2: centre
//!   (0, 13) + 0.8(1, 1)/√2, tip = that − (0.8, 0.8) = (−a, 13 − a),
//!   a = 0.8(1 − 1/√2) = 0.234315 → Ø25.531371 Z−0.234315;
//! - chamfer → Z−30 (direction (−1, 0), normal (0, 1)): a left turn of
//!   45°, outer obtuse → the offset lines meet: Z + X = 13 + 0.8√2 and
//!   X = 15.8 → centre Z = −2.8 + 0.8√2, tip Z = −2 − 0.8(2 − √2) =
//!   −2.468629, tip X = 15 → Ø30 Z−2.468629 (001's correction b);
//! - `G00 U1.0 Z1.0` with G42 still in force runs (−30, 15) → (1, 15.5):
//!   a right turn of 179.08° from −Z, an inner corner. The offset lines
//!   X = 15.8 (Z−30's) and N4's, 0.8 to its −X side (through
//!   (−29.987, 14.200), slope 0.5/31), meet where X rises 1.6 along N4:
//!   ΔZ = 1.6·31/0.5 ≈ 99 ahead, at Z ≈ +69. The compensated Z−30 cut
//!   would then run from Z−1.67 to Z+69, against its programmed −Z: the
//!   interference alarm PS041 before that block starts (fanuc-semantics
//!   §4.7, "step smaller than r": the lift is 0.5, the radius 0.8).

mod common;
use common::lathe::{mv, trace};
use common::{alarm, ok, round};
use kerf_interp::{Interp, Profile, Run, Settings};

/// 001 p.27 example 1, as printed (`:` → `;`, `UO WO` → `U0 W0`).
const EXAMPLE_1: &str = "\
G01 X25.0 Z0 F0.2 ;
X30.0 Z-2.5 ;
G00 U1.0 Z1.0 ;
G28 U0 W0 ;
M30 ;
";

/// Preamble (lines 1-2) before example 2.
const PREAMBLE: &str = "T0101 ;\nG00 X40.0 Z5.0 ;\n";

/// 001 p.28 example 2, as printed (`:` → `;`, `UO WO` → `U0 W0`); lines
/// 3-8 after the preamble.
const EXAMPLE_2: &str = "\
G42 X26.0 Z0 F0.2 ;
G01 X30.0 Z-2.0 ;
Z-30.0 ;
G00 U1.0 Z1.0 ;
G28 U0 W0 ;
M30 ;
";

/// Runs `text` on the PUMA with offset 1 = nose R0.8, tip 3.
fn run(text: &str) -> Run {
    let mut it = Interp::new(Profile::builtin("puma-lathe").unwrap(), Settings::default());
    let o = it.offsets_mut().lathe_mut(1).unwrap();
    o.r = 0.8;
    o.tip = 3;
    kerf_interp::run_interp(it, "t.nc", text)
}

/// The PUMA's reference position: machine X330. (diameter) Z0, which the
/// power-on work system reads as Z 529 (its zero is at machine Z −529;
/// examples/puma/one_block_g71.expect.toml).
const REF: (f64, f64) = (330.0, 529.0);

/// Example 1 moves exactly as written: the hand-corrected points, the
/// retract (U1.0 is a diameter: X31) and G28 U0 W0 (the intermediate
/// point is where the tool is, so one move: to the reference position).
#[test]
fn example_1_without_compensation() {
    let r = run(EXAMPLE_1);
    ok(&r);
    assert_eq!(
        trace(&r),
        vec![
            mv("F", 12.5, 0.0, 0.2),
            mv("F", 15.0, -2.5, 0.2),
            mv("R", 15.5, 1.0, 0.0),
            mv("R", REF.0 / 2.0, REF.1, 0.0),
        ]
    );
}

/// Example 2 as printed: the start-up and the chamfer are compensated
/// (module comment), then the retract with G42 still on makes the Z−30
/// cut interfere: PS041 at line 5 (`Z-30.0`), column 1, nothing of it
/// cut.
#[test]
fn example_2_as_printed_interferes_on_the_retract() {
    let r = run(&format!("{PREAMBLE}{EXAMPLE_2}"));
    assert_eq!(alarm(&r), ("PS041", 5, 1));
    let a = 0.8 * (1.0 - 1.0 / 2f64.sqrt());
    let b = 0.8 * (2.0 - 2f64.sqrt());
    assert_eq!(
        trace(&r),
        vec![
            mv("R", 20.0, 5.0, 0.0),
            mv("R", 13.0 - a, -a, 0.0),
            mv("F", 15.0, -2.0 - b, 0.2),
        ]
    );
    assert_eq!(round(2.0 * (13.0 - a)), 25.531371);
    assert_eq!(round(-2.0 - b), -2.468629);
}

/// Example 2 with the G40 its retract needs (`G00 G40 U1.0 Z1.0`): type
/// A cancel ends the Z−30 cut on its own normal, centre (−30, 15.8), tip
/// (−30.8, 15) → Ø30 Z−30.8 (the tip runs r past the programmed end);
/// then straight to the programmed Ø31 Z1 and G28 to the reference.
#[test]
fn example_2_with_g40_on_the_retract() {
    let text = format!("{PREAMBLE}{EXAMPLE_2}").replace("G00 U1.0", "G00 G40 U1.0");
    let r = run(&text);
    ok(&r);
    let a = 0.8 * (1.0 - 1.0 / 2f64.sqrt());
    let b = 0.8 * (2.0 - 2f64.sqrt());
    assert_eq!(
        trace(&r),
        vec![
            mv("R", 20.0, 5.0, 0.0),
            mv("R", 13.0 - a, -a, 0.0),
            mv("F", 15.0, -2.0 - b, 0.2),
            mv("F", 15.0, -30.8, 0.2),
            mv("R", 15.5, 1.0, 0.0),
            mv("R", REF.0 / 2.0, REF.1, 0.0),
        ]
    );
}
