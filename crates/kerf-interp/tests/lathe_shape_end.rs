//! G71/G72 shapes whose end turns back (issue 15): the roughing direction
//! is the one the shape starts cutting in, so a shape that comes back to
//! or past its start stops with PS064 (not monotonic, fanuc-semantics
//! §1.2) naming the segment that turns back — the last — and its line,
//! at the cycle's P word where the control stops.

mod common;
use common::run_on;

const PUMA: &str = "puma-lathe";

/// A = (41, 2); N10 rapids to A′ = (15, 2); N20 (segment 1) cuts to Z−20,
/// N30 (segment 2) rises to X radius 20 at Z−20, N40 (segment 3, line 7)
/// goes back to Z2 (the start) or Z5 (past it): segment 3 is the one that
/// is not monotonic in Z.
#[test]
fn shape_back_to_or_past_its_start() {
    for z in ["Z2.", "Z5."] {
        let r = run_on(
            PUMA,
            &format!(
                "G00 X82. Z2.\nG71 U2. R0.5\nG71 P10 Q40 F0.25\nN10 G00 X30.\nN20 G01 Z-20.\nN30 X40.\nN40 {z}\n"
            ),
        );
        let a = r.alarm.as_ref().expect("alarm");
        assert_eq!(
            (a.code.as_str(), a.src.line, a.src.col),
            ("PS064", 3, 5),
            "{z}: {}",
            a.message
        );
        assert!(
            a.message
                .contains("not monotonic in Z (segment 3 after N10, line 7)"),
            "{z}: {}",
            a.message
        );
        assert!(r
            .events
            .iter()
            .all(|e| e.motion().is_none() || e.src.line == 1));
    }
}

/// A G72 shape that does not move in X has nothing to face: the message
/// names X (G72's cutting axis), not Z.
#[test]
fn g72_shape_without_length_in_x() {
    let r = run_on(
        PUMA,
        "G00 X82. Z2.\nG72 W2. R0.5\nG72 P10 Q20 F0.25\nN10 G00 Z-10.\nN20 G01 Z-20.\n",
    );
    let a = r.alarm.as_ref().expect("alarm");
    assert_eq!((a.code.as_str(), a.src.line), ("PS062", 3));
    assert!(a.message.contains("no length in X"), "{}", a.message);
}
