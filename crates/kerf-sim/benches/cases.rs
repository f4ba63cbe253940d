//! The simulation benchmark's cases (docs/benchmarks.md, "Simulation"),
//! shared by `benches/sim.rs` (criterion, moves/s) and
//! `examples/sim_case.rs` (one run of one case, for instruction counts).
//!
//! - `lathe_rough_0.5mm`: G71-style roughing of a Ø60 bar from r 29 to
//!   r 6 in 1 mm passes over Z0..-100, as 0.5 mm feed moves (every move
//!   cuts), 0.8 mm-nose 80° insert;
//! - `lathe_g71_passes`: the same passes as whole moves (feed to the
//!   shape, 45° lift, rapid back) and a finishing pass;
//! - `lathe_groove`: 12 grooves of a 3 mm blade pecked 0.25 mm at a
//!   time from r 30 to r 22 (each peck a plunge and a 0.1 mm retract);
//! - `lathe_thread`: 40 threading passes of a 60° insert (0.1 mm nose,
//!   tip 8) over Z3..-40, 0.025 mm deeper each, each pass the rapid in,
//!   the cut, the rapid out and back;
//! - `mill_2d5_0.05mm`: 0.5 mm raster moves at 1 mm stepover of a 10 mm
//!   flat end mill at Z-2 in a 300×200 block at 0.05 mm cells;
//! - `mill_3d_0.05mm`: the same raster over a wavy surface with a 6 mm
//!   ball;
//! - `mill_surface_0.05mm`: surface_1m's moves (../shared/bench/
//!   gen_programs.py: 48 moves of 6.23 mm a pass over X0.5..299.5, 0.5 mm
//!   stepover, the turnaround as a straight step) with its 10 mm ball on
//!   its 300×200×50 block, the first 40 passes of its first layer (base
//!   Z40, 1,960 moves) and then of its second (base Z39.4, 1,960 more);
//! - `mill_drill_0.05mm`: a 20×20 grid of 8 mm 118° drill holes 10 mm
//!   deep at 12 mm pitch, each a rapid over the hole, a rapid down to
//!   Z1, three 4 mm pecks with rapid retracts to Z1, and the rapid up.

#![allow(dead_code)]

use kerf_canon::{Canon, Event, Feed, Motion, Pos, SpindleDir, SrcRef};
use kerf_sim::{parse_tools, Sim, Stock};

/// One move of a case: a feed (true) or a rapid, to a tip position.
pub type Move = (bool, [f64; 3]);

/// A benchmark case: its name, how to make its simulation, its moves.
pub struct Case {
    pub name: &'static str,
    pub make: fn() -> Sim,
    pub moves: Vec<Move>,
}

fn ev(cmd: Canon) -> Event {
    Event {
        src: SrcRef {
            file: 0,
            line: 1,
            col: 1,
        },
        tool: 1,
        cmd,
        prog: None,
    }
}

fn motion(m: &Move) -> Canon {
    let p = m.1;
    let to: Pos = [p[0], p[1], p[2], 0.0, 0.0, 0.0];
    let m2 = Motion { to, mto: to };
    if m.0 {
        Canon::Feed {
            m: m2,
            feed: Feed::PerMin(1000.0),
        }
    } else {
        Canon::Rapid {
            m: m2,
            linear: true,
        }
    }
}

fn sim(stock: &str, tools: &str, lathe: bool, res: Option<f64>) -> Sim {
    let mut s = Sim::new(
        Stock::parse(stock).unwrap(),
        parse_tools(tools, lathe).unwrap(),
        res,
    )
    .unwrap();
    let on = Canon::Spindle {
        dir: SpindleDir::Cw,
        rpm: 1000.0,
        css: None,
    };
    s.event(&ev(on), &[0.0; 6], 0.0);
    s
}

/// Runs the moves from the first one's position, to the pending cut
/// applied.
pub fn run(s: &mut Sim, moves: &[Move]) {
    let p = moves[0].1;
    let mut prev: Pos = [p[0], p[1], p[2], 0.0, 0.0, 0.0];
    for (i, m) in moves.iter().enumerate() {
        s.event(&ev(motion(m)), &prev, i as f64);
        prev = [m.1[0], m.1[1], m.1[2], 0.0, 0.0, 0.0];
    }
    s.settle();
}

fn feeds(pts: Vec<[f64; 3]>) -> Vec<Move> {
    pts.into_iter().map(|p| (true, p)).collect()
}

fn lathe_segments() -> Vec<Move> {
    let mut pts = Vec::new();
    for k in 0..24 {
        let r = 29.0 - k as f64;
        pts.push([r, 0.0, 1.0]);
        let mut z = 1.0;
        while z > -100.0 {
            z -= 0.5;
            pts.push([r, 0.0, z]);
        }
        pts.push([r + 1.0, 0.0, z]);
        pts.push([r + 1.0, 0.0, 1.0]);
    }
    feeds(pts)
}

fn lathe_passes() -> Vec<Move> {
    let mut pts = Vec::new();
    for k in 0..19 {
        let r = 29.0 - k as f64;
        pts.extend([
            [r, 0.0, 1.0],
            [r, 0.0, -100.0],
            [r + 0.5, 0.0, -99.5],
            [r + 0.5, 0.0, 1.0],
        ]);
    }
    pts.extend([
        [10.0, 0.0, 1.0],
        [10.0, 0.0, -60.0],
        [20.0, 0.0, -70.0],
        [20.0, 0.0, -100.0],
        [31.0, 0.0, -100.0],
    ]);
    feeds(pts)
}

fn lathe_grooves() -> Vec<Move> {
    let mut m = Vec::new();
    for g in 0..12 {
        let z = -50.0 - 6.0 * g as f64;
        m.push((false, [31.0, 0.0, z]));
        let mut r = 30.0;
        while r > 22.0 {
            r -= 0.25;
            m.push((true, [r, 0.0, z]));
            m.push((false, [r + 0.1, 0.0, z]));
        }
        m.push((false, [31.0, 0.0, z]));
    }
    m
}

fn lathe_threads() -> Vec<Move> {
    let mut m = vec![(false, [31.0, 0.0, 3.0])];
    for k in 0..40 {
        let r = 29.95 - 0.025 * k as f64;
        m.extend([
            (false, [r, 0.0, 3.0]),
            (true, [r, 0.0, -40.0]),
            (false, [31.0, 0.0, -40.0]),
            (false, [31.0, 0.0, 3.0]),
        ]);
    }
    m
}

fn raster(n: usize, wavy: bool) -> Vec<Move> {
    let (mut x, mut y, mut dir) = (-145.0, -95.0, 1.0);
    let mut pts = Vec::with_capacity(n);
    while pts.len() < n {
        let z = if wavy {
            -3.0 + 1.5 * (x / 20.0f64).sin() * (y / 15.0f64).cos()
        } else {
            -2.0
        };
        pts.push([x, y, z]);
        x += 0.5 * dir;
        if !(-145.0..=145.0).contains(&x) {
            dir = -dir;
            x += 0.5 * dir;
            y += 1.0;
        }
    }
    feeds(pts)
}

/// gen_programs.py's surface: ±8 mm about `base`.
fn surface_z(x: f64, y: f64, base: f64) -> f64 {
    use std::f64::consts::PI;
    base + 5.0 * (2.0 * PI * x / 150.0).sin() * (2.0 * PI * y / 100.0).cos()
        + 3.0 * (2.0 * PI * (x + y) / 70.0).sin()
}

fn surface() -> Vec<Move> {
    let xs: Vec<f64> = (0..=48).map(|i| 0.5 + 299.0 * i as f64 / 48.0).collect();
    let mut pts = vec![[xs[0], 0.0, surface_z(xs[0], 0.0, 40.0)]];
    for base in [40.0, 39.4] {
        for p in 0..40 {
            let y = 0.5 * p as f64;
            let order: Vec<f64> = if p % 2 == 0 {
                xs[1..].to_vec()
            } else {
                xs[..48].iter().rev().copied().collect()
            };
            for x in order {
                pts.push([x, y, surface_z(x, y, base)]);
            }
        }
    }
    feeds(pts)
}

fn drill_grid() -> Vec<Move> {
    let mut m = vec![(false, [-114.0, -114.0, 5.0])];
    for j in 0..20 {
        for i in 0..20 {
            let (x, y) = (-114.0 + 12.0 * i as f64, -90.0 + 9.0 * j as f64);
            m.push((false, [x, y, 5.0]));
            m.push((false, [x, y, 1.0]));
            for d in 1..=3 {
                let z = -(10.0f64).min(4.0 * d as f64);
                m.push((true, [x, y, z]));
                m.push((false, [x, y, 1.0]));
            }
            m.push((false, [x, y, 5.0]));
        }
    }
    m
}

const INSERT: &str = "[tool.1]\nnose_radius=0.8\ntip=3\n";
const BLOCK: &str = "box:-150,-100,-30,150,100,0";

fn lathe() -> Sim {
    sim("bar:60,150", INSERT, true, None)
}

fn groover() -> Sim {
    let tools = "[tool.1]\nkind=\"groove\"\nwidth=3\ndepth=20\nnose_radius=0.2\ntip=3\n";
    sim("bar:60,150", tools, true, None)
}

fn threader() -> Sim {
    let tools = "[tool.1]\nangle=60\nedge_length=4\nbisector=90\nnose_radius=0.1\ntip=8\n";
    sim("bar:60,150", tools, true, None)
}

fn mill_flat() -> Sim {
    sim(
        BLOCK,
        "[tool.1]\nkind=\"flat\"\ndiameter=10\n",
        false,
        Some(0.05),
    )
}

fn mill_ball() -> Sim {
    sim(
        BLOCK,
        "[tool.1]\nkind=\"ball\"\ndiameter=6\n",
        false,
        Some(0.05),
    )
}

fn mill_ball10() -> Sim {
    let tools = "[tool.1]\nkind=\"ball\"\ndiameter=10\n";
    sim("box:0,0,0,300,200,50", tools, false, Some(0.05))
}

fn mill_drill() -> Sim {
    let tools = "[tool.1]\nkind=\"drill\"\ndiameter=8\npoint_angle=118\n";
    sim(BLOCK, tools, false, Some(0.05))
}

/// Every case.
pub fn all() -> Vec<Case> {
    vec![
        Case {
            name: "lathe_rough_0.5mm",
            make: lathe,
            moves: lathe_segments(),
        },
        Case {
            name: "lathe_g71_passes",
            make: lathe,
            moves: lathe_passes(),
        },
        Case {
            name: "lathe_groove",
            make: groover,
            moves: lathe_grooves(),
        },
        Case {
            name: "lathe_thread",
            make: threader,
            moves: lathe_threads(),
        },
        Case {
            name: "mill_2d5_0.05mm",
            make: mill_flat,
            moves: raster(20_000, false),
        },
        Case {
            name: "mill_3d_0.05mm",
            make: mill_ball,
            moves: raster(5_000, true),
        },
        Case {
            name: "mill_surface_0.05mm",
            make: mill_ball10,
            moves: surface(),
        },
        Case {
            name: "mill_drill_0.05mm",
            make: mill_drill,
            moves: drill_grid(),
        },
    ]
}
