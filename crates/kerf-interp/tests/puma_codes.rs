//! The Fanuc 0-T codes real lathe programs start with, which 001 does not
//! print (G18, G53, G54-G59, G80, G10 L2, #5221-#5326), and the PUMA's
//! addresses that only some blocks read (docs/dialects.md §3). Machine
//! positions are worked out by hand from puma-lathe.toml: G54 = (X 0, Z
//! −529), X a radius in machine coordinates, programmed as a diameter.

use kerf_interp::Run;

mod common;
use common::{alarm, ok, round, run_on};

const PUMA: &str = "puma-lathe";

/// Machine (X radius, Z) and work (X radius, Z) of every motion.
fn ends(r: &Run) -> Vec<((f64, f64), (f64, f64))> {
    r.events
        .iter()
        .filter_map(|e| e.motion())
        .map(|m| {
            (
                (round(m.mto[0]), round(m.mto[2])),
                (round(m.to[0]), round(m.to[2])),
            )
        })
        .collect()
}

/// The first lines of real lathe programs: G18 is the lathe's plane (the
/// power-on state, #4016 = 18), G80 the cancel of a group the PUMA has no
/// cycles in; both run, glued or spaced.
#[test]
fn g18_and_g80_are_accepted() {
    let r = run_on(
        PUMA,
        "G18 G21 G40 G80 G99\nG21G40G80G99\n#100 = #4016\n#101 = #4010\nG00 X50. Z5.\nM30\n",
    );
    ok(&r);
    assert_eq!(ends(&r), vec![((25.0, -524.0), (25.0, 5.0))]);
    let r = run_on(
        PUMA,
        "#1 = #4016\n#2 = #4010\nIF [#1 NE 18] GOTO 9\nIF [#2 NE 80] GOTO 9\nG00 X10. Z0\nN9 M30\n",
    );
    ok(&r);
    assert_eq!(ends(&r).len(), 1, "#4016 = 18 and #4010 = 80");
    // G17 and G19 are planes the two-axis lathe has no axes for.
    for g in ["G17", "G19"] {
        let r = run_on(PUMA, &format!("{g} G00 X10.\n"));
        assert_eq!(alarm(&r), ("PS010", 1, 1), "{g}");
    }
}

/// G54-G59 with the offset table: `G10 L2 P2 X0 Z-500.` makes G55's zero
/// machine Z −500, so `G55 G00 X50. Z10.` goes to machine (25, −490) and
/// reads (25, 10); `#5262 = -450.` sets G56 Z (20 numbers per system:
/// #5221 + 2·20 + 1), `#5261 = 10.` G56 X as a diameter (machine radius
/// 5); G54 stays the profile's −529. #5242 reads G55 Z back.
#[test]
fn work_coordinate_systems_and_their_variables() {
    let r = run_on(
        PUMA,
        "G10 L2 P2 X0 Z-500.\nG55 G00 X50. Z10.\n#5262 = -450.\n#5261 = 10.\nG56 G00 X0 Z0\nG54 G00 X20. Z0\n#100 = #5242\nG55 G00 X[#100 + 600.] Z0\nM30\n",
    );
    ok(&r);
    assert_eq!(
        ends(&r),
        vec![
            ((25.0, -490.0), (25.0, 10.0)),
            ((5.0, -450.0), (0.0, 0.0)),
            ((10.0, -529.0), (10.0, 0.0)),
            // #100 = −500 (program units: the G55 Z) → X100. = radius 50.
            ((50.0, -500.0), (50.0, 0.0)),
        ]
    );
    // G10 L2 with U/W adds to the offset: G55 Z −500 + 20 = −480.
    let r = run_on(
        PUMA,
        "G10 L2 P2 X0 Z-500.\nG10 L2 P2 W20.\nG55 G00 X0 Z0\nM30\n",
    );
    ok(&r);
    assert_eq!(ends(&r), vec![((0.0, -480.0), (0.0, 0.0))]);
}

/// G53 one-shot: `G53 G00 X200. Z-100.` goes to machine X radius 100, Z
/// −100, which reads Z 429 in G54 (−100 + 529); the next block is in work
/// coordinates again. With U/W (incremental) the G53 block is ignored,
/// as Fanuc ignores G53 in incremental (fanuc-semantics §6.2).
#[test]
fn g53_machine_coordinates_one_shot() {
    let r = run_on(
        PUMA,
        "G00 X50. Z5.\nG53 G00 X200. Z-100.\nZ5.\nG53 U10. W-5.\nM30\n",
    );
    ok(&r);
    assert_eq!(
        ends(&r),
        vec![
            ((25.0, -524.0), (25.0, 5.0)),
            ((100.0, -100.0), (100.0, 429.0)),
            ((100.0, -524.0), (100.0, 5.0)),
        ]
    );
}

/// Addresses the two-axis PUMA does not have (B, H, J, V, Y) and the ones
/// only some codes read (A: one-block G76; D: one-block G71-G76; L:
/// M98) stop the block with PS009 at the word instead of being ignored.
#[test]
fn stray_addresses_alarm() {
    for (text, col) in [
        ("G00 X40. A5.\n", 10),
        ("G00 X40. B5.\n", 10),
        ("G00 X40. D5.\n", 10),
        ("G00 X40. E5.\n", 10),
        ("G00 X40. H5.\n", 10),
        ("G01 X40. J5. F0.2\n", 10),
        ("G00 X40. L2\n", 10),
        ("G00 X40. Y5.\n", 10),
    ] {
        let r = run_on(PUMA, text);
        assert_eq!(alarm(&r), ("PS009", 1, col), "{text}");
        assert!(ends(&r).is_empty(), "{text}");
    }
    // G65 arguments may use any letter.
    let r = run_on(
        PUMA,
        "G65 P9 B1. H2. J3.\nM30\nO9\n#100 = #2 + #11 + #5\nM99\n",
    );
    ok(&r);
}

/// E is the thread lead (001 "F, E: designation of feedrate and thread
/// lead"): `G32 Z-20. E1.5` cuts the same thread as `F1.5`; F and E in
/// one block are an alarm.
#[test]
fn e_is_the_thread_lead() {
    let lead = |t: &str| {
        let r = run_on(PUMA, t);
        ok(&r);
        r.events
            .iter()
            .find_map(|e| match e.cmd {
                kerf_canon::Canon::Thread { lead, .. } => Some(round(lead)),
                _ => None,
            })
            .expect("a thread")
    };
    let head = "G97 S300 M03\nG00 X30. Z5.\n";
    assert_eq!(lead(&format!("{head}G32 Z-20. E1.5\nM30\n")), 1.5);
    assert_eq!(lead(&format!("{head}G32 Z-20. F1.5\nM30\n")), 1.5);
    let r = run_on(PUMA, &format!("{head}G32 Z-20. F1.5 E1.5\n"));
    assert_eq!(alarm(&r), ("PS009", 3, 11));
}
