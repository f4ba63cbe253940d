//! Fuzz target `macro_text`: programs assembled from custom-macro pieces
//! (WHILE/DO/END, IF/GOTO/THEN, N numbers, #-variables and expressions,
//! G65/G66/G67, M98/M99, O headers, block delete), so that the fuzzer
//! spends its time in the macro engine, the call stack and the
//! parsed-block cache instead of in the lexer's error paths. Each input is
//! run on hx-mc and puma-lathe; halfway through, the run is RESET and
//! started again, so `Interp::reset` and the cache hand-back are covered.
//! Failure: panic, hang, OOM, an alarm with line 0 or an empty code or
//! message.
#![no_main]

use std::sync::OnceLock;

use kerf_interp::{Interp, Profile, Settings, Step};
use libfuzzer_sys::fuzz_target;

const MAX_STEPS: usize = 3_000;
const MAX_BLOCKS: u64 = 3_000;

/// Block pieces; a byte picks one, the next bytes fill its holes.
const PIECES: &[&str] = &[
    "#@=@",
    "#@=#@+@",
    "#@=#@*@-#@",
    "#@=[#@+@]/#@",
    "#[@]=@",
    "#@=#[#@]",
    "#@=SIN[#@]+COS[@]",
    "#@=SQRT[ABS[#@]]",
    "#@=ROUND[#@]+FIX[@]-FUP[#@]",
    "#@=#@ AND @ OR #@ XOR @",
    "#@=#@ MOD @",
    "#@=#0",
    "WHILE [#@ LT @] DO@",
    "WHILE [#@ NE #0] DO@",
    "DO@",
    "END@",
    "IF [#@ GT @] GOTO@",
    "IF [#@ EQ #@] THEN #@=@",
    "GOTO@",
    "GOTO#@",
    "N@",
    "N@ #@=#@+1",
    "/N@ #@=@",
    "/@ G01 X#@",
    "G00 X#@ Y@",
    "G01 X[#@/@] F100",
    "G65 P@ A@ B#@",
    "G65 P@ L@ X@",
    "G66 P@ A@",
    "G67",
    "M98 P@",
    "M98 P@ L@",
    "M99",
    "M99 P@",
    "O@",
    "%",
    "M30",
    "#3000=@ (STOP)",
    "#3003=@",
    "#3004=@",
    "#@=#3003+#3004",
    "#@=#4018",
];

fn program(data: &[u8]) -> String {
    let mut out = String::new();
    let mut bytes = data.iter().copied();
    while let Some(b) = bytes.next() {
        let piece = PIECES[b as usize % PIECES.len()];
        for c in piece.chars() {
            if c == '@' {
                // Small numbers mostly, so labels, N numbers, variable
                // numbers and program numbers meet each other.
                let n = bytes.next().unwrap_or(1);
                let v = match n >> 6 {
                    0 => (n & 7) as u32,
                    1 => 100 + (n & 15) as u32,
                    2 => (n & 63) as u32,
                    _ => 1000 + (n & 63) as u32 * 37,
                };
                out.push_str(&v.to_string());
            } else {
                out.push(c);
            }
        }
        out.push('\n');
    }
    out
}

fn profiles() -> &'static Vec<Profile> {
    static P: OnceLock<Vec<Profile>> = OnceLock::new();
    P.get_or_init(|| {
        ["hx-mc", "puma-lathe"]
            .iter()
            .map(|m| Profile::builtin(m).expect("built-in profile"))
            .collect()
    })
}

fn check(a: &kerf_canon::Alarm) {
    assert!(a.src.line >= 1, "alarm with line 0: {a:?}");
    assert!(
        !a.code.is_empty() && !a.message.is_empty(),
        "empty alarm: {a:?}"
    );
}

fuzz_target!(|data: &[u8]| {
    let text = program(data);
    for profile in profiles() {
        let settings = Settings {
            max_blocks: MAX_BLOCKS,
            block_skip: 0b10,
            ..Settings::default()
        };
        let mut it = Interp::new(profile.clone(), settings);
        it.load_main(
            "fuzz.nc",
            Box::new(std::io::Cursor::new(text.clone().into_bytes())),
        );
        for round in 0..2 {
            for i in 0..MAX_STEPS {
                if round == 0 && i == MAX_STEPS / 2 {
                    break;
                }
                match it.step() {
                    Step::Event(_) => {}
                    Step::End => break,
                    Step::Alarm(a) => {
                        check(&a);
                        break;
                    }
                }
            }
            it.reset();
        }
    }
});
