//! Reading the main program ahead on a second thread
//! (`Interp::set_read_ahead`, kerf-lang's `ahead.rs`) gives the same
//! steps, events, alarms, end and block count as reading it on the
//! interpreter's thread, on generated programs that seek all the time:
//! GOTO forward and back, WHILE loops (the block cache), M98/M99 and G65
//! into subprograms of the same file, alarms, block delete on and off,
//! over-long lines, runs of plain blocks longer than a read-ahead batch,
//! a last line without its newline; and on Hurco programs with
//! continuation lines and a program that has no plain block at all.

use kerf_interp::{Filled, Interp, Profile, Settings};
use proptest::prelude::*;

mod common;
use common::gen::{coord, trace};

/// Every step of `text` on `machine` (block delete level 1 on when
/// `skip`), read ahead or not, then the blocks executed.
fn steps(machine: &str, text: &str, ahead: bool, skip: bool) -> Vec<String> {
    let settings = Settings {
        block_skip: skip as u16 * 2,
        ..Settings::default()
    };
    let mut it = Interp::new(Profile::builtin(machine).unwrap(), settings);
    it.set_read_ahead(ahead);
    it.load_main(
        "p.nc",
        Box::new(std::io::Cursor::new(text.as_bytes().to_vec())),
    );
    let mut out = trace(&mut it, 20_000, |it| {
        format!(" at {:?}", it.next_block_at())
    });
    out.push(format!("blocks {}", it.blocks()));
    out
}

/// The same steps taken in batches from `step_into`.
fn batched(machine: &str, text: &str, ahead: bool, room: usize) -> Vec<String> {
    let mut it = Interp::new(Profile::builtin(machine).unwrap(), Settings::default());
    it.set_read_ahead(ahead);
    it.load_main(
        "p.nc",
        Box::new(std::io::Cursor::new(text.as_bytes().to_vec())),
    );
    let mut out = Vec::new();
    let mut batch = Vec::new();
    for _ in 0..20_000 {
        let r = it.step_into(&mut batch, room);
        out.extend(batch.drain(..).map(|e| format!("{e:?}")));
        match r {
            Filled::Room => {}
            Filled::End => {
                out.push("End".into());
                break;
            }
            Filled::Alarm(a) => {
                out.push(format!("{a:?}"));
                break;
            }
        }
    }
    out.push(format!("blocks {}", it.blocks()));
    out
}

/// A block: plain ones mostly, and the ones that make the reader seek or
/// stop.
fn block() -> impl Strategy<Value = String> {
    let c = coord;
    prop_oneof![
        10 => (c(), c(), c()).prop_map(|(x, y, z)| format!("G01 X{x} Y{y} Z{z}")),
        4 => (c(), c()).prop_map(|(x, y)| format!("X{x} Y{y}")),
        2 => c().prop_map(|x| format!("/G01 X{x}")),
        2 => c().prop_map(|x| format!("G01 X{x} (NOTE)")),
        1 => Just("(A COMMENT ONLY)".to_string()),
        1 => Just(String::new()),
        1 => Just("G02 X5. Y0 R5.\nG03 X0 Y0 R5.\nG01".to_string()),
        1 => Just("#1 = 0\nWHILE [#1 LT 3] DO1\nG01 X#1 Y1.\n#1 = #1 + 1\nEND1".to_string()),
        1 => Just("#2 = 0\nN100 G01 Z#2\n#2 = #2 + 1\nIF [#2 LT 3] GOTO 100".to_string()),
        1 => Just("GOTO 200\nG01 X77.\nN200 G01 Y2.".to_string()),
        1 => Just("M98 P9003".to_string()),
        1 => Just("G65 P9002 X3. Y4.".to_string()),
        1 => Just(format!("G01 X1. (LONG{})", "-".repeat(300))),
        1 => (1usize..700, c()).prop_map(|(n, x)| {
            (0..n).map(|i| format!("G01 X{x} Y{i}.5 Z-1.\n")).collect::<String>() + "G00 Z5."
        }),
        1 => Just("G01 X100000.".to_string()),
        1 => Just("G28 Z0".to_string()),
    ]
}

const SUBS: &str =
    "O9002\nG01 X#24 Y#25\nG00 Z2.\nM99\nO9003\nG91 G01 X1. Y1.\nG00 Z1.\nG90\nM99\n";

fn program() -> impl Strategy<Value = (String, bool)> {
    (
        prop::collection::vec(block(), 1..25),
        any::<bool>(),
        any::<bool>(),
    )
        .prop_map(|(bs, newline, skip)| {
            let mut t =
                "%\nO0001\nG21 G17 G40 G49 G80 G90 G94\nG54\nS1000 M03\nF500.\n".to_string();
            for b in bs {
                t.push_str(&b);
                t.push('\n');
            }
            t.push_str("M30\n");
            t.push_str(SUBS);
            t.push('%');
            if newline {
                t.push('\n');
            }
            (t, skip)
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn read_ahead_gives_what_reading_here_gives((text, skip) in program()) {
        let here = steps("hx-mc", &text, false, skip);
        let ahead = steps("hx-mc", &text, true, skip);
        prop_assert_eq!(here, ahead, "{}", text);
    }

    #[test]
    fn read_ahead_in_batches_gives_what_reading_here_gives(
        (text, _) in program(),
        room in 1usize..600,
    ) {
        let here = batched("hx-mc", &text, false, room);
        let ahead = batched("hx-mc", &text, true, room);
        prop_assert_eq!(here, ahead, "{}", text);
    }
}

#[test]
fn hurco_continuation_lines_and_a_program_with_no_plain_block() {
    for text in [
        "G21 G07 G01 X5 \\\nZ-5 F100\nM30\n",
        "G21 G07\nG01 X5 \\\n  Z-5 \\\nF100\nG01 X1 Z-1\nM30",
        "G21 G07 G01 X5 \\",
        "(ONLY A COMMENT)\n(AND ANOTHER)\n",
        "",
    ] {
        let here = steps("hurco-lathe", text, false, false);
        assert_eq!(here, steps("hurco-lathe", text, true, false), "{text}");
    }
    let statements: String = (0..2000)
        .map(|i| format!("#{} = {i}\n", 100 + i % 50))
        .collect();
    let here = steps("hx-mc", &statements, false, false);
    assert_eq!(here.last().map(String::as_str), Some("blocks 2000"));
    assert_eq!(here, steps("hx-mc", &statements, true, false));
}

#[test]
fn a_long_surface_run_reads_ahead_in_batches() {
    // 5,000 plain blocks (batches of 16, 32, ... 512): every move's end
    // as written, the block count that of the file.
    let mut text = String::from("G90 G54 F1000.\n");
    for i in 0..5000 {
        text.push_str(&format!("G01 X{}.5 Y{}. Z-1.25\n", i % 100, i / 100));
    }
    text.push_str("M30\n");
    let ahead = batched("hx-mc", &text, true, 512);
    assert_eq!(ahead, batched("hx-mc", &text, false, 512));
    assert_eq!(ahead.last().map(String::as_str), Some("blocks 5002"));
    assert!(ahead.iter().any(|e| e.contains("99.5")));
}
