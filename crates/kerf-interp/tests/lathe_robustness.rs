//! Bad and odd input to the PUMA lathe cycles never panics or hangs: a
//! deterministic generator strings together cycle blocks, shapes and
//! chamfer blocks with random words; every run must end (completed or a
//! positioned alarm) within the block guard.

use kerf_interp::{run_text, Profile, Settings};

/// A small linear congruential generator (deterministic, no dependency).
struct Lcg(u64);

impl Lcg {
    fn next(&mut self) -> u64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        self.0 >> 33
    }
    fn pick<'a>(&mut self, v: &[&'a str]) -> &'a str {
        v[(self.next() as usize) % v.len()]
    }
    fn num(&mut self) -> String {
        let v = (self.next() % 2000) as f64 / 10.0 - 100.0;
        if self.next().is_multiple_of(4) {
            format!("{}", v as i64)
        } else {
            format!("{v:.1}")
        }
    }
}

#[test]
fn random_lathe_programs_end_cleanly() {
    let codes = [
        "G00", "G01", "G02", "G03", "G32", "G90", "G92", "G94", "G70", "G71", "G72", "G73", "G74",
        "G75", "G76", "G96", "G97", "G98", "G99", "",
    ];
    let letters = ["X", "Z", "U", "W", "R", "I", "K", "C", "P", "Q", "F", "S"];
    let mut g = Lcg(7);
    let settings = Settings {
        max_blocks: 5000,
        ..Settings::default()
    };
    for _ in 0..1500 {
        let mut p = String::from("G50 S2000\nG97 S500 M03\nG00 X80. Z5.\n");
        let n = 2 + g.next() % 10;
        for i in 0..n {
            if g.next().is_multiple_of(3) {
                p.push_str(&format!("N{} ", 10 + i));
            }
            p.push_str(g.pick(&codes));
            for _ in 0..(g.next() % 5) {
                let l = g.pick(&letters);
                if p.ends_with(l) {
                    continue;
                }
                p.push(' ');
                p.push_str(l);
                p.push_str(&g.num());
            }
            p.push('\n');
        }
        let r = run_text(
            Profile::builtin("puma-lathe").unwrap(),
            settings.clone(),
            "fuzz.nc",
            &p,
        );
        if let Some(a) = &r.alarm {
            assert!(a.src.line >= 1, "alarm without a line: {a:?}\n{p}");
        }
        assert!(r.events.len() < 2_000_000, "{p}");
    }
}
