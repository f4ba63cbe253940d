//! Generated HX programs for the expansion tests: moves in G90 and G91, R
//! arcs in the three planes, rotation (G68), scaling (G51), local
//! coordinates (G52), two work offsets, tool length compensation, macro
//! variables, dwells and the spindle, in random order from fixed seeds,
//! sized to stay inside hx-mc's travel.

#![allow(dead_code)]

/// How many programs the tests generate (seeds 0..PROGRAMS).
pub const PROGRAMS: u64 = 150;
/// Blocks drawn per program.
const BLOCKS: usize = 40;

/// A small deterministic generator (64-bit LCG, high bits).
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        self.0 >> 33
    }
    fn below(&mut self, n: u64) -> u64 {
        self.next() % n
    }
    /// A coordinate with three decimals in [-r, r].
    fn coord(&mut self, r: f64) -> String {
        let v = (self.below(2001) as f64 / 1000.0 - 1.0) * r;
        format!("{v:.3}")
    }
}

/// The generated program of `seed`.
pub fn program(seed: u64) -> String {
    let mut g = Rng(seed.wrapping_mul(0x9E3779B97F4A7C15) ^ 0x5DEECE66D);
    let mut p = String::from(
        "G21 G17 G40 G49 G80 G90 G94\nG10 L10 P1 R50.\nG10 L2 P2 X-350. Y-200. Z-300.\nG54 G00 X0 Y0 Z20.\nS1200 M03\n",
    );
    let (mut rot, mut scale, mut local) = (false, false, false);
    for _ in 0..BLOCKS {
        let line = match g.below(16) {
            0 | 1 => format!(
                "G00 X{} Y{} Z{}",
                g.coord(40.0),
                g.coord(40.0),
                g.coord(20.0)
            ),
            2..=4 => format!(
                "G01 X{} Y{} F{}",
                g.coord(40.0),
                g.coord(40.0),
                100 + g.below(900)
            ),
            5 | 6 => {
                let code = if g.below(2) == 0 { "G02" } else { "G03" };
                // Chords up to 113 mm: R 60 always reaches.
                let r = if g.below(2) == 0 { "60." } else { "-60." };
                format!(
                    "G17 {code} X{} Y{} R{r} F300.",
                    g.coord(40.0),
                    g.coord(40.0)
                )
            }
            7 if !rot && !scale => {
                let code = if g.below(2) == 0 {
                    "G18 G02"
                } else {
                    "G19 G03"
                };
                let (a, b) = if code.starts_with("G18") {
                    ("X", "Z")
                } else {
                    ("Y", "Z")
                };
                format!(
                    "{code} {a}{} {b}{} R60. F250.\nG17",
                    g.coord(30.0),
                    g.coord(15.0)
                )
            }
            8 => format!("G91 G01 X{} Y{} F400.\nG90", g.coord(10.0), g.coord(10.0)),
            9 => {
                rot = !rot;
                if rot {
                    format!(
                        "G68 X{} Y{} R{}",
                        g.coord(20.0),
                        g.coord(20.0),
                        g.coord(90.0)
                    )
                } else {
                    "G69".into()
                }
            }
            10 if !rot => {
                scale = !scale;
                if scale {
                    format!(
                        "G51 X{} Y{} P{}",
                        g.coord(10.0),
                        g.coord(10.0),
                        500 + g.below(800)
                    )
                } else {
                    "G50".into()
                }
            }
            11 if !scale => {
                local = !local;
                if local {
                    format!("G52 X{} Y{}", g.coord(15.0), g.coord(15.0))
                } else {
                    "G52 X0 Y0".into()
                }
            }
            12 if !scale && !rot => (if g.below(2) == 0 { "G55" } else { "G54" }).into(),
            13 => (if g.below(2) == 0 { "G43 H1" } else { "G49" }).into(),
            14 => format!("#1 = {}\nG01 X#1 Y[#1 / 2] F500.", g.coord(40.0)),
            _ => format!("G04 X0.{}", 1 + g.below(9)),
        };
        p.push_str(&line);
        p.push('\n');
    }
    p.push_str("M05\nM30\n");
    p
}

/// A generated PUMA (Fanuc 0-T, system A) program: X as a diameter, moves
/// absolute (X Z) and incremental (U W), R arcs, G32 threads, G90 and G94
/// turning cycles, feed per revolution and per minute, CSS and rpm, tool
/// changes with offsets, macro variables and dwells.
pub fn lathe_program(seed: u64) -> String {
    let mut g = Rng(seed.wrapping_mul(0xD1B54A32D192ED03) ^ 0x2545F491);
    let mut p = String::from("G21\nG50 S2000\nG00 X200. Z50. T0101\nG97 S800 M03\nG00 X120. Z5.\n");
    let dia = |g: &mut Rng| format!("{:.3}", 40.0 + g.below(160_001) as f64 / 1000.0);
    let z = |g: &mut Rng| format!("{:.3}", -80.0 + g.below(90_001) as f64 / 1000.0);
    for _ in 0..BLOCKS {
        let line = match g.below(14) {
            0 | 1 => format!("G00 X{} Z{}", dia(&mut g), z(&mut g)),
            2..=4 => format!("G01 X{} Z{} F0.{}", dia(&mut g), z(&mut g), 1 + g.below(4)),
            5 | 6 => {
                let code = if g.below(2) == 0 { "G02" } else { "G03" };
                // Chords up to about 180 mm: R 100 reaches.
                format!("{code} X{} Z{} R100. F0.2", dia(&mut g), z(&mut g))
            }
            7 => format!("G01 U{} W{} F0.15", g.coord(10.0), g.coord(10.0)),
            8 => format!(
                "G00 X{} Z5.\nG32 Z{} F{}",
                dia(&mut g),
                z(&mut g),
                1 + g.below(3)
            ),
            9 => (if g.below(2) == 0 {
                "G96 S150 M03"
            } else {
                "G97 S900 M03"
            })
            .into(),
            10 => format!("G00 X200. Z50.\nT0{}0{}", 1 + g.below(3), 1 + g.below(3)),
            11 => format!(
                "G00 X{} Z5.\nG90 X{} Z{} F0.25\nG00 X200.",
                160 + g.below(20),
                dia(&mut g),
                z(&mut g)
            ),
            12 => format!("#1 = {}\nG98 G01 X#1 Z[#1 / -4] F300.\nG99", dia(&mut g)),
            _ => format!("G04 X0.{}", 1 + g.below(9)),
        };
        p.push_str(&line);
        p.push('\n');
    }
    p.push_str("G00 X200. Z50.\nM05\nM30\n");
    p
}

/// A generated Hurco MAX program (metric, calculator decimals): radius and
/// diameter programming (G07/G08), absolute and incremental (G90/G91), R
/// arcs, G33 threads along Z or X (lead K or I), feeds per minute and per
/// revolution, dwells in seconds and revolutions, CSS, tool offsets.
pub fn hurco_program(seed: u64) -> String {
    let mut g = Rng(seed.wrapping_mul(0xA0761D6478BD642F) ^ 0xE7037ED1);
    let mut p = String::from("G21 G90 G94 G08\nG00 X200 Z50 T0101\nG97 S800 M03\nG00 X120 Z5\n");
    let dia = |g: &mut Rng| format!("{:.3}", 40.0 + g.below(160_001) as f64 / 1000.0);
    let z = |g: &mut Rng| format!("{:.3}", -80.0 + g.below(90_001) as f64 / 1000.0);
    for _ in 0..BLOCKS {
        let line = match g.below(13) {
            0 | 1 => format!("G00 X{} Z{}", dia(&mut g), z(&mut g)),
            2..=4 => format!("G01 X{} Z{} F{}", dia(&mut g), z(&mut g), 50 + g.below(400)),
            5 | 6 => {
                let code = if g.below(2) == 0 { "G02" } else { "G03" };
                format!("{code} X{} Z{} R100 F150", dia(&mut g), z(&mut g))
            }
            7 => format!("G91 G01 X{} Z{} F200\nG90", g.coord(10.0), g.coord(10.0)),
            8 => format!(
                "G00 X{} Z5\nG33 Z{} K{}",
                dia(&mut g),
                z(&mut g),
                1 + g.below(3)
            ),
            9 => format!(
                "G00 X{} Z5\nG33 X{} I{}",
                dia(&mut g),
                20 + g.below(20),
                1 + g.below(2)
            ),
            10 => format!("G07 G00 X{} Z{}\nG08", 30 + g.below(60), z(&mut g)),
            11 => match g.below(4) {
                0 => "G95 G01 Z-10 F0.2\nG94".into(),
                1 => "G95 G04 F2\nG94".into(),
                2 => "G96 S150 M03".into(),
                _ => "G97 S900 M03".into(),
            },
            _ => format!(
                "G00 X200 Z50\nT0{}0{}\nG04 F0.5",
                1 + g.below(3),
                1 + g.below(3)
            ),
        };
        p.push_str(&line);
        p.push('\n');
    }
    p.push_str("G00 X200 Z50\nM05\nM30\n");
    p
}
