//! Simulation throughput on generated moves (docs/benchmarks.md,
//! "Simulation"): `cargo bench -p kerf-sim --bench sim`, each case a
//! fresh stock per iteration, moves per second as criterion's
//! throughput. Cases:
//!
//! - `lathe_rough_0.5mm`: G71-style roughing of a Ø60 bar from r 29 to
//!   r 6 in 1 mm passes over Z0..-100, as 0.5 mm feed moves (every move
//!   cuts), 0.8 mm-nose 80° insert;
//! - `lathe_g71_passes`: the same passes as whole moves (feed to the
//!   shape, 45° lift, rapid back) and a finishing pass;
//! - `mill_2d5_0.05mm`: 0.5 mm raster moves at 1 mm stepover of a 10 mm
//!   flat end mill at Z-2 in a 300×200 block at 0.05 mm cells;
//! - `mill_3d_0.05mm`: the same raster over a wavy surface with a 6 mm
//!   ball.

use criterion::{criterion_group, criterion_main, BatchSize, Criterion, Throughput};
use kerf_canon::{Canon, Event, Feed, Motion, Pos, SpindleDir, SrcRef};
use kerf_sim::{parse_tools, Sim, Stock};

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

fn feed(p: [f64; 3]) -> Canon {
    let to: Pos = [p[0], p[1], p[2], 0.0, 0.0, 0.0];
    Canon::Feed {
        m: Motion { to, mto: to },
        feed: Feed::PerMin(1000.0),
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

fn run(s: &mut Sim, pts: &[[f64; 3]]) {
    let mut prev: Pos = [pts[0][0], pts[0][1], pts[0][2], 0.0, 0.0, 0.0];
    for (i, p) in pts.iter().enumerate() {
        s.event(&ev(feed(*p)), &prev, i as f64);
        prev = [p[0], p[1], p[2], 0.0, 0.0, 0.0];
    }
}

fn lathe_segments() -> Vec<[f64; 3]> {
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
    pts
}

fn lathe_passes() -> Vec<[f64; 3]> {
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
    pts
}

fn raster(n: usize, wavy: bool) -> Vec<[f64; 3]> {
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
    pts
}

fn case(c: &mut Criterion, name: &str, make: impl Fn() -> Sim, pts: &[[f64; 3]]) {
    let mut g = c.benchmark_group("sim");
    g.sample_size(10);
    g.throughput(Throughput::Elements(pts.len() as u64));
    g.bench_function(name, |b| {
        b.iter_batched_ref(&make, |s| run(s, pts), BatchSize::PerIteration)
    });
    g.finish();
}

fn benches(c: &mut Criterion) {
    let insert = "[tool.1]\nnose_radius=0.8\ntip=3\n";
    let lathe = || sim("bar:60,150", insert, true, None);
    case(c, "lathe_rough_0.5mm", lathe, &lathe_segments());
    case(c, "lathe_g71_passes", lathe, &lathe_passes());
    let block = "box:-150,-100,-30,150,100,0";
    let flat = "[tool.1]\nkind=\"flat\"\ndiameter=10\n";
    let mill = || sim(block, flat, false, Some(0.05));
    case(c, "mill_2d5_0.05mm", mill, &raster(20_000, false));
    let ball = "[tool.1]\nkind=\"ball\"\ndiameter=6\n";
    let mill3 = || sim(block, ball, false, Some(0.05));
    case(c, "mill_3d_0.05mm", mill3, &raster(5_000, true));
}

criterion_group!(sim_benches, benches);
criterion_main!(sim_benches);
