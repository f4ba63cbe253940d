//! What the differential run against LinuxCNC's rs274 left for kerf
//! (issue 15), each worked out by hand on hx-mc (G54 = machine (−400,
//! −250, −250)).

mod common;
use common::{alarm, ok, round, run_on};

/// Work (tip) and machine Z of every motion.
fn z_of(r: &kerf_interp::Run) -> Vec<(f64, f64)> {
    r.events
        .iter()
        .filter_map(|e| e.motion())
        .map(|m| (round(m.to[2]), round(m.mto[2])))
        .collect()
}

/// `G91 G43 H2 G01 Z-10.` (fanuc-semantics §5.1): the tip goes down 10
/// while the machine moves by the offset change as well. H2 = 25: from
/// tip Z50 (machine −200) the tip reads 40 and the machine is at −200 −
/// 10 + 25 = −185, as `G90 G43 H2 Z40.` would put it; `G49 Z-5.` then
/// takes the 25 off again: tip 35, machine −185 − 5 − 25 = −215.
#[test]
fn offset_change_superposed_on_an_incremental_move() {
    let r = run_on(
        "hx-mc",
        "G10 L10 P2 R25.\nG54 G90 G00 X0 Y0 Z50.\nG91 G43 H2 G01 Z-10. F100.\nG49 Z-5.\nM30\n",
    );
    ok(&r);
    assert_eq!(
        z_of(&r),
        vec![(50.0, -200.0), (40.0, -185.0), (35.0, -215.0)]
    );
    let r = run_on(
        "hx-mc",
        "G10 L10 P2 R25.\nG54 G90 G00 X0 Y0 Z50.\nG90 G43 H2 G01 Z40. F100.\nM30\n",
    );
    assert_eq!(z_of(&r)[1], (40.0, -185.0));
    // With an incremental move of another axis only, Z does not move: the
    // longer tool's tip now reads 25 (machine −200), and the next Z-10.
    // goes from there (tip 15, machine −210) — the same physical tip.
    let r = run_on(
        "hx-mc",
        "G10 L10 P2 R25.\nG54 G90 G00 X0 Y0 Z50.\nG91 G43 H2 X10.\nZ-10.\nM30\n",
    );
    assert_eq!(
        z_of(&r),
        vec![(50.0, -200.0), (25.0, -200.0), (15.0, -210.0)]
    );
}

/// G53 is absolute only: in G91 the block is ignored (fanuc-semantics
/// §6.2; 000 §7.1.1 prints `G90 G53 X_Y_Z_`), no motion, and the next
/// block moves from where the tool was.
#[test]
fn g53_in_g91_is_ignored() {
    let r = run_on(
        "hx-mc",
        "G54 G90 G00 X10. Y10. Z10.\nG91 G53 X-5. Y-5. Z-5.\nG90 G00 Z20.\nM30\n",
    );
    ok(&r);
    assert_eq!(z_of(&r), vec![(10.0, -240.0), (20.0, -230.0)]);
}

/// A J word in a G18 (ZX) arc is not a centre word of that plane (K and
/// I are): an alarm at the J, never ignored. The same for K in G17 and I
/// in G19.
#[test]
fn off_plane_centre_word_alarms() {
    for (text, col) in [
        (
            "G54 G18 G00 X0 Y0 Z0\nG02 X10. Z-10. I5. J5. K0 F100.\n",
            20,
        ),
        ("G54 G17 G00 X0 Y0 Z0\nG02 X10. Y0 I5. K5. F100.\n", 17),
        ("G54 G19 G00 X0 Y0 Z0\nG02 Y10. Z0 J5. I5. F100.\n", 17),
    ] {
        let r = run_on("hx-mc", text);
        assert_eq!(alarm(&r), ("F_82001", 2, col), "{text}");
    }
}
