//! The direct path for plain blocks (interp/plain.rs: a block of only
//! G00/G01, X, Y, Z and F words, executed without the parser's block,
//! the words table and the phase walk) gives the same events, in the same
//! order, the same alarms and the same block count as the general path
//! (`Interp::set_plain_path(false)`), on generated HX programs that mix
//! plain blocks with every kind of modal state the path must leave to the
//! general one (G91, G20, G41/G42, G68, G51, G16, G66, canned cycles,
//! ,C/,R, arcs, loops, subprograms and macro calls) and with blocks that
//! look plain but are not.

use kerf_interp::{Filled, Interp, Profile, Settings, Step};
use proptest::prelude::*;

mod common;
use common::gen::{coord, trace};

fn interp(plain: bool) -> Interp {
    let mut it = Interp::new(Profile::builtin("hx-mc").unwrap(), Settings::default());
    it.set_plain_path(plain);
    it.set_h(1, 100.0);
    it.offsets_mut().d_mut(1).unwrap().geom = 2.0;
    it.offsets_mut().d_mut(2).unwrap().geom = 1.0;
    it
}

fn load(it: &mut Interp, text: &str) {
    it.load_main(
        "p.nc",
        Box::new(std::io::Cursor::new(text.as_bytes().to_vec())),
    );
}

/// Every step of `text` on hx-mc with the plain path on or off, then the
/// blocks executed.
fn steps(text: &str, plain: bool) -> Vec<String> {
    let mut it = interp(plain);
    load(&mut it, text);
    let mut out = trace(&mut it, 5000, |_| String::new());
    out.push(format!("blocks {}", it.blocks()));
    out
}

/// A block the plain path may take (or, for the last few, one that only
/// looks like it: the general path must read those).
fn plain() -> impl Strategy<Value = String> {
    let c = coord;
    let g = prop::sample::select(vec!["G01 ", "G00 ", "G1", "G0 ", "", "", "G01"]);
    let f = prop::sample::select(vec!["", "", "", " F800.", " F1500", "F200."]);
    prop_oneof![
        8 => (g.clone(), c(), c(), c(), f.clone())
            .prop_map(|(g, x, y, z, f)| format!("{g}X{x} Y{y} Z{z}{f}")),
        4 => (g.clone(), c(), c()).prop_map(|(g, x, y)| format!("{g}X{x}Y{y}")),
        3 => (g, c(), f).prop_map(|(g, z, f)| format!("  {g}Z{z}{f} ")),
        1 => Just("G01".to_string()),
        1 => Just("F300.".to_string()),
        1 => c().prop_map(|x| format!("g01 x{x}")),
        1 => c().prop_map(|x| format!("G01 X{x} X1.")),
        1 => c().prop_map(|x| format!("G02 X{x}")),
        1 => c().prop_map(|x| format!("N5 G01 X{x}")),
        1 => c().prop_map(|x| format!("G01 X{x} (NOTE)")),
        1 => c().prop_map(|x| format!("G01 X{x} Y-.5")),
        1 => Just("G01 X100000.".to_string()),
        1 => Just("X1. F-5.".to_string()),
    ]
}

/// A mode entered, plain blocks in it, and the mode left.
fn section() -> impl Strategy<Value = String> {
    let c = coord;
    let around = prop_oneof![
        Just(("G91", "G90")),
        Just(("G20", "G21")),
        Just(("G91 G20", "G90 G21")),
        Just(("G41 D1 G01 X5. Y5.", "G40 G01 X0 Y0")),
        Just(("G42 D2 G01 X5. Y5.", "G40 G01 X0 Y0")),
        Just(("G68 X0 Y0 R30.", "G69")),
        Just(("G51 X0 Y0 P2.", "G50")),
        Just(("G51 X0 Y0 I-1000 J1000", "G50")),
        Just(("G16", "G15")),
        Just(("G52 X5. Y-3.", "G52 X0 Y0")),
        Just(("G92 X3.", "G92 X0")),
        Just(("G55", "G54")),
        Just(("G66 P9001 R1.", "G67")),
        Just(("G65 P9002 X3. Y4.", "G00")),
        Just(("M98 P9003", "G90")),
        Just(("G81 X1. Y2. Z-5. R2. F100.", "G80")),
        Just(("G83 X1. Y2. Z-9. R2. Q3. F100.", "G80")),
        Just(("G43 H1 Z10.", "G49")),
        Just(("G02 X5. Y0 R5.", "G03 X0 Y0 R5.\nG01")),
        Just(("G01 X4. Y4. ,C1.", "G01 X8. Y0")),
        Just(("G01 X4. Y4. ,R1.", "G01 X8. Y0")),
        Just(("M05", "M03")),
        Just(("S2000", "S1000")),
        Just(("G18", "G17")),
        Just(("G95 F0.2", "G94 F300.")),
        Just(("G93 F2.", "G94 F300.")),
        Just(("T2 M06", "G04 X0.5")),
        Just(("G61", "G64")),
        Just(("#1 = 0\nWHILE [#1 LT 2] DO1", "#1 = #1 + 1\nEND1")),
        Just(("G22 X50. Y50. Z50. I-50. J-50. K-50.", "G23")),
        Just(("G28 Z0", "G00")),
    ];
    (around, prop::collection::vec(plain(), 0..6), c()).prop_map(|((open, close), ps, x)| {
        let mut t = format!("{open}\n");
        for p in ps {
            t.push_str(&p);
            t.push('\n');
        }
        t.push_str(close);
        t.push('\n');
        t.push_str(&format!("G01 X{x}\n"));
        t
    })
}

/// Subprograms after the end: the G66 macro, the G65 macro, an M98
/// subprogram (each with plain blocks of its own).
const SUBS: &str = "O9001\nG01 Z-1.\nG00 Z#18\nM99\nO9002\nG01 X#24 Y#25\nG00 Z2.\nM99\nO9003\nG91 G01 X1. Y1.\nG00 Z1.\nM99\n";

fn program() -> impl Strategy<Value = String> {
    let head = prop::sample::select(vec![
        "G21 G17 G40 G49 G80 G90 G94\nG54\nS1000 M03\nF500.\n",
        "G21 G17 G40 G49 G80 G90 G94\nG54\nS1000 M03\nF500.\n",
        "G20 G90\nM03 S500\nF20.\n",
        "G90\n",
    ]);
    (head, prop::collection::vec(section(), 1..10)).prop_map(|(head, ss)| {
        let mut t = format!("%\nO0001\n{head}");
        t.push_str(&ss.concat());
        t.push_str("M30\n");
        t.push_str(SUBS);
        t.push_str("%\n");
        t
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(500))]

    #[test]
    fn the_plain_path_gives_what_the_general_path_gives(text in program()) {
        let fast = steps(&text, true);
        let general = steps(&text, false);
        prop_assert_eq!(fast, general, "{}", text);
    }

    #[test]
    fn step_into_gives_what_step_gives(text in program(), room in 1usize..40) {
        let one = steps(&text, true);
        let mut it = interp(true);
        load(&mut it, &text);
        let (mut out, mut batched) = (Vec::new(), Vec::new());
        // The first few by step(), the rest in batches of `room` or more.
        for _ in 0..3 {
            let s = it.step();
            let end = !matches!(s, Step::Event(_));
            batched.push(format!("{s:?}"));
            if end {
                break;
            }
        }
        let ended = batched.last().is_some_and(|s| !s.starts_with("Event"));
        let mut end = String::new();
        for _ in 0..5000 {
            if ended {
                break;
            }
            let before = out.len();
            let r = it.step_into(&mut out, room);
            match r {
                Filled::Room => prop_assert!(out.len() >= before + room),
                Filled::End => { end = "End".to_string(); break; }
                Filled::Alarm(a) => { end = format!("{:?}", Step::Alarm(a)); break; }
            }
        }
        batched.extend(out.into_iter().map(|e| format!("{:?}", Step::Event(e))));
        if !ended {
            batched.push(end);
        }
        batched.push(format!("blocks {}", it.blocks()));
        prop_assert_eq!(one, batched, "{}", text);
    }
}

/// The events of a run as (line, kind) pairs.
fn kinds(text: &str, plain: bool) -> Vec<(u32, String)> {
    let mut it = interp(plain);
    load(&mut it, text);
    let mut out = Vec::new();
    while let Step::Event(e) = it.step() {
        let k = format!("{:?}", e.cmd);
        out.push((e.src.line, k[..k.find(' ').unwrap_or(k.len())].to_string()));
    }
    out
}

#[test]
fn a_surface_pass_moves_as_written() {
    let mut text = String::from(
        "%\nO0001\nG21 G17 G40 G49 G80 G90 G94\nG54\nS8000 M03\nG00 X0 Y0\nG01 Z40. F800.\n",
    );
    for i in 1..=20 {
        text.push_str(&format!(
            "G01 X{:.4} Y0.0000 Z-{}.5 F1500.\n",
            i as f64 * 1.25,
            i
        ));
    }
    text.push_str("M30\n%\n");
    assert_eq!(steps(&text, true), steps(&text, false));
    let mut it = interp(true);
    load(&mut it, &text);
    let mut feeds = Vec::new();
    while let Step::Event(e) = it.step() {
        if let kerf_canon::Canon::Feed { m, feed } = e.cmd {
            feeds.push((e.src.line, m.to, feed));
        }
    }
    // The plunge and 20 feeds; line 8 + i goes to X 1.25 i, Z -(i + 0.5),
    // at 1500 mm/min; Y stays 0.
    assert_eq!(feeds.len(), 21);
    for (i, (line, to, feed)) in feeds.iter().enumerate().skip(1) {
        assert_eq!(*line, 7 + i as u32);
        assert!((to[0] - 1.25 * i as f64).abs() < 1e-12, "{to:?}");
        assert_eq!(to[1], 0.0);
        assert!((to[2] + i as f64 + 0.5).abs() < 1e-12, "{to:?}");
        assert_eq!(*feed, kerf_canon::Feed::PerMin(1500.0));
    }
}

#[test]
fn incremental_inch_moves_add_up() {
    // G20 G91 from the machine's home (its upper limits): X-1 (no
    // point) is 0.0001 in = 0.00254 mm, X-1. is 25.4 mm.
    let text = "G20 G91 G01 F10.\nX-1.\nX-1\nY-2. Z-0.5\nG90 G21\nM30\n";
    assert_eq!(steps(text, true), steps(text, false));
    let mut it = interp(true);
    load(&mut it, text);
    let start = it.work_position();
    let mut last = start;
    while let Step::Event(e) = it.step() {
        if let Some(m) = e.motion() {
            last = m.to;
        }
    }
    assert!(
        (last[0] - start[0] + (25.4 + 0.00254)).abs() < 1e-9,
        "{start:?} {last:?}"
    );
    assert!((last[1] - start[1] + 50.8).abs() < 1e-9);
    assert!((last[2] - start[2] + 12.7).abs() < 1e-9);
}

#[test]
fn plain_looking_blocks_under_a_mode_take_the_general_path() {
    // G66: each move calls O9001 (Z-1 then up to R): line 4's X5. is a
    // rapid and the macro's feed and rapid.
    let text = format!("G90 G00 X0 Y0 Z10. F100.\nG66 P9001 R3.\nX5.\nG67\nX0\nM30\n{SUBS}");
    let k = kinds(&text, true);
    assert_eq!(k, kinds(&text, false));
    let line3: Vec<_> = k
        .iter()
        .filter(|e| e.0 == 3 || e.0 > 6)
        .map(|e| e.1.as_str())
        .collect();
    assert_eq!(line3, ["Rapid", "Feed", "Rapid"]);
    // In G81 a bare X is a hole: rapid over, rapid to R, feed, rapid back.
    let cycle = "G90 G00 X0 Y0 Z10.\nG81 X1. Y2. Z-5. R2. F100.\nX5. Y5.\nG80\nM30\n";
    let holes: Vec<_> = kinds(cycle, true)
        .into_iter()
        .filter(|e| e.0 == 3)
        .map(|e| e.1)
        .collect();
    assert_eq!(holes, ["Rapid", "Rapid", "Feed", "Rapid"]);
}

#[test]
fn step_into_fills_the_callers_batch_after_what_is_there() {
    // Five moves and the end; the batch already holds one event.
    let text = "G90 G00 X1.\nX2.\nX3.\nX4.\nX5.\nM30\n";
    let mut it = interp(true);
    load(&mut it, text);
    let mut out = Vec::new();
    // Room 2: two blocks of one rapid each.
    assert_eq!(it.step_into(&mut out, 2), Filled::Room);
    assert_eq!(out.len(), 2);
    assert_eq!(it.step_into(&mut out, 100), Filled::End);
    let lines: Vec<u32> = out.iter().map(|e| e.src.line).collect();
    // Lines 1-5 and the End of line 6.
    assert_eq!(lines, [1, 2, 3, 4, 5, 6]);
    assert_eq!(it.step_into(&mut out, 1), Filled::End);
    assert_eq!(it.step(), Step::End);
    // An alarm: the block's own events are dropped, the earlier ones kept.
    let text = "G90 G00 X1.\nG01 X2.\nM30\n";
    let mut it = interp(true);
    load(&mut it, text);
    let mut out = Vec::new();
    let r = it.step_into(&mut out, 10);
    assert!(
        matches!(r, Filled::Alarm(ref a) if a.src.line == 2),
        "{r:?}"
    );
    assert_eq!(out.len(), 1);
}
