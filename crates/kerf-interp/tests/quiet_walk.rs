//! The short phase walk for quiet blocks (interp/phases.rs: a block with
//! at most a motion code, no M, D, H or T, no cycle or compensation in
//! force) gives the same events, in the same order, and the same alarms
//! as the full walk, on generated HX programs that mix quiet blocks with
//! every kind of code the full walk handles around them.

use kerf_interp::{Interp, Profile, Settings, Step};
use proptest::prelude::*;

mod common;
use common::gen::trace;

/// Every step of `text` on hx-mc, with the short walk on or off.
fn steps(text: &str, quiet: bool) -> Vec<String> {
    let mut it = Interp::new(Profile::builtin("hx-mc").unwrap(), Settings::default());
    it.set_quiet_walk(quiet);
    it.set_h(1, 100.0);
    with_radii(&mut it);
    it.load_main(
        "q.nc",
        Box::new(std::io::Cursor::new(text.as_bytes().to_vec())),
    );
    trace(&mut it, 5000, |_| String::new())
}

/// D1 = 2 mm and D2 = 1 mm: compensation that moves the path.
fn with_radii(it: &mut Interp) {
    it.offsets_mut().d_mut(1).unwrap().geom = 2.0;
    it.offsets_mut().d_mut(2).unwrap().geom = 1.0;
}

/// A coordinate the generator writes (at most 20 mm): with and without
/// a point.
fn coord() -> impl Strategy<Value = String> {
    prop_oneof![
        (-160i32..160).prop_map(|v| format!("{:.3}", v as f64 / 8.0)),
        (-20i32..20).prop_map(|v| format!("{v}.")),
        (-20000i32..20000).prop_map(|v| v.to_string()),
    ]
}

/// A quiet block: a move with at most a motion code.
fn quiet() -> impl Strategy<Value = String> {
    let c = coord;
    prop_oneof![
        4 => (c(), c(), c()).prop_map(|(x, y, z)| format!("G01 X{x} Y{y} Z{z}")),
        3 => (c(), c()).prop_map(|(x, y)| format!("X{x} Y{y}")),
        2 => (c(), c()).prop_map(|(x, z)| format!("G00 X{x} Z{z}")),
        1 => c().prop_map(|z| format!("Z{z} F200")),
        1 => Just("G01".to_string()),
    ]
}

/// A mode entered, quiet blocks in it, and the mode left; or a block of
/// another kind between quiet ones.
fn section() -> impl Strategy<Value = String> {
    let c = coord;
    let around = prop_oneof![
        Just(("G81 X1. Y2. Z-5. R2. F100.", "G80")),
        Just(("G83 X1. Y2. Z-9. R2. Q3. F100.", "G80")),
        Just(("G41 D1 G01 X5. Y5.", "G40 G01 X0 Y0")),
        Just(("G42 D1 G01 X5. Y5.", "G40 G01 X0 Y0")),
        Just(("G43 H1 Z10.", "G49")),
        Just(("G68 X0 Y0 R30.", "G69")),
        Just(("G51 X0 Y0 P2.", "G50")),
        Just(("G16", "G15")),
        Just(("G52 X5. Y-3.", "G52 X0 Y0")),
        Just(("G91", "G90")),
        Just(("G92 X3.", "G92 X0")),
        Just(("G55", "G54")),
        Just(("M08", "M09")),
        Just(("M05", "M03")),
        Just(("G18", "G17")),
        Just(("G02 I5. J0", "G03 I0 J-4.\nG01")),
        Just(("G01 X4. Y4. ,C1.\nG01 X8. Y0", "G01")),
        Just(("G01 X4. Y4. ,R1.\nG01 X8. Y0", "G01")),
        Just(("T2 M06", "S2000 M03")),
        Just(("F300.", "G04 X0.5")),
        Just(("G09 X1.", "G28 Z0")),
        Just(("D2", "H1")),
        Just(("T3", "M01")),
        Just(("G95 F0.2", "G94 F300.")),
        Just(("G01 X1 Y2 Q3", "G61")),
        Just(("G64", "G20")),
        Just(("G21", "G00")),
    ];
    (around, prop::collection::vec(quiet(), 0..6), c()).prop_map(|((open, close), qs, x)| {
        let mut t = format!("{open}\n");
        for q in qs {
            t.push_str(&q);
            t.push('\n');
        }
        t.push_str(close);
        t.push('\n');
        t.push_str(&format!("X{x}\n"));
        t
    })
}

fn program() -> impl Strategy<Value = String> {
    prop::collection::vec(section(), 1..12).prop_map(|ss| {
        let mut t = String::from("%\nO0001\nG21 G17 G40 G49 G80 G90 G94\nG54\nS1000 M03\nF500.\n");
        t.push_str(&ss.concat());
        t.push_str("M30\n%\n");
        t
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(500))]

    #[test]
    fn the_short_walk_gives_what_the_full_walk_gives(text in program()) {
        let short = steps(&text, true);
        let full = steps(&text, false);
        prop_assert_eq!(short, full, "{}", text);
    }
}

#[test]
fn a_surface_pass_runs_the_same_both_ways_and_moves_as_written() {
    let mut text = String::from("%\nO0001\nG21 G17 G40 G49 G80 G90 G94\nG54\nS8000 M03\nG00 X0 Y0\nG43 H1 Z60.\nG01 Z40. F800.\n");
    for i in 1..=50 {
        text.push_str(&format!(
            "G01 X{:.4} Y0.0000 Z{:.4} F1500.\n",
            i as f64 * 1.25,
            40.0 + (i % 7) as f64
        ));
    }
    text.push_str("M30\n%\n");
    let short = steps(&text, true);
    assert_eq!(short, steps(&text, false));
    // 50 feeds after the Z plunge; the last one ends at X62.5 (50 x 1.25).
    let feeds = short.iter().filter(|s| s.contains("Feed {")).count();
    assert_eq!(feeds, 51);
    assert!(
        short.last().unwrap().starts_with("End"),
        "{:?}",
        short.last()
    );
}

/// (line, kind) of each event of `text`, with the short walk on.
fn kinds(text: &str, quiet: bool) -> Vec<(u32, String)> {
    let mut it = Interp::new(Profile::builtin("hx-mc").unwrap(), Settings::default());
    it.set_quiet_walk(quiet);
    with_radii(&mut it);
    it.load_main(
        "q.nc",
        Box::new(std::io::Cursor::new(text.as_bytes().to_vec())),
    );
    let mut out = Vec::new();
    while let Step::Event(e) = it.step() {
        let k = format!("{:?}", e.cmd);
        out.push((e.src.line, k[..k.find(' ').unwrap_or(k.len())].to_string()));
    }
    out
}

#[test]
fn in_a_canned_cycle_or_compensation_a_bare_move_is_not_quiet() {
    // Line 3: a hole at X5 Y5 in G81 mode: rapid over it, rapid to R,
    // feed to the depth, rapid back to the initial level (G98).
    let cycle = "G90 G00 X0 Y0 Z10.\nG81 X1. Y2. Z-5. R2. F100.\nX5. Y5.\nG80\nM30\n";
    let moves: Vec<String> = kinds(cycle, true)
        .into_iter()
        .filter(|e| e.0 == 3)
        .map(|e| e.1)
        .collect();
    assert_eq!(moves, ["Rapid", "Rapid", "Feed", "Rapid"]);
    assert_eq!(kinds(cycle, true), kinds(cycle, false));
    // Cutter compensation holds a move until the next one shows its
    // corner: line 3's move comes out only with line 4's block.
    let comp = "G90 G01 X0 Y0 F100.\nG41 D1 X10. Y0\nX10. Y10.\nX0 Y10.\nG40 X0 Y0\nM30\n";
    assert_eq!(steps(comp, true), steps(comp, false));
    // Blocks without a move in the plane count towards the look-ahead
    // limit (two on the HX): after the third Z-only block the held move
    // of line 2 ends on its perpendicular.
    let idle = "G90 G01 X0 Y0 F100.\nG41 D1 X5. Y5.\nZ-1.\nZ-2.\nZ-3.\nX0 Y0\nG40 X0 Y0\nM30\n";
    assert_eq!(steps(idle, true), steps(idle, false));
}
