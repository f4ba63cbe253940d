//! Simulation speed on generated moves (docs/benchmarks.md):
//! `cargo run --release -p kerf-sim --example simbench -- mill25|mill3d|lathe [N]`.

use std::time::Instant;

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

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let which = args.get(1).map(String::as_str).unwrap_or("mill25");
    let n: usize = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(200_000);
    let (stock, tools, lathe) = match which {
        "lathe" | "g71" => ("bar:60,150", "[tool.1]\nnose_radius=0.8\ntip=3\n", true),
        "mill3d" => (
            "box:-150,-100,-30,150,100,0",
            "[tool.1]\nkind=\"ball\"\ndiameter=6\n",
            false,
        ),
        _ => (
            "box:-150,-100,-30,150,100,0",
            "[tool.1]\nkind=\"flat\"\ndiameter=10\n",
            false,
        ),
    };
    let res = if lathe { None } else { Some(0.05) };
    let mut sim = Sim::new(
        Stock::parse(stock).unwrap(),
        parse_tools(tools, lathe).unwrap(),
        res,
    )
    .unwrap();
    sim.event(
        &ev(Canon::Spindle {
            dir: SpindleDir::Cw,
            rpm: 1000.0,
            css: None,
        }),
        &[0.0; 6],
        0.0,
    );
    let mut pts = Vec::with_capacity(n);
    if which == "g71" {
        // G71-shaped: whole passes (feed along -Z to the shape, 45° lift,
        // rapid back) at 1 mm depth from r 29 to r 11 over Z-100, then a
        // finishing pass; repeated on the part already cut.
        while pts.len() < n {
            for k in 0..19 {
                let r = 29.0 - k as f64;
                pts.push([r, 0.0, 1.0]);
                pts.push([r, 0.0, -100.0]);
                pts.push([r + 0.5, 0.0, -99.5]);
                pts.push([r + 0.5, 0.0, 1.0]);
            }
            pts.extend([
                [10.0, 0.0, 1.0],
                [10.0, 0.0, -60.0],
                [20.0, 0.0, -70.0],
                [20.0, 0.0, -100.0],
                [31.0, 0.0, -100.0],
            ]);
        }
        pts.truncate(n);
    } else if lathe {
        // G71-style roughing: 1 mm depth per pass along Z, 0.05 mm feed
        // steps, then back out; passes from r 30 down to r 10.
        let mut r = 29.0;
        while pts.len() < n {
            pts.push([r, 0.0, 1.0]);
            let mut z = 1.0;
            while z > -100.0 && pts.len() < n {
                z -= 0.5;
                pts.push([r, 0.0, z]);
            }
            pts.push([r + 1.0, 0.0, z]);
            r -= 1.0;
            if r < 10.0 {
                r = 29.0;
            }
        }
    } else {
        // Raster at 0.5 mm steps and 1 mm stepover; 3-D: a wavy surface.
        let (mut x, mut y, mut dir) = (-145.0, -95.0, 1.0);
        while pts.len() < n {
            let z = if which == "mill3d" {
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
                if y > 95.0 {
                    y = -95.0;
                }
            }
        }
    }
    let mut prev: Pos = [pts[0][0], pts[0][1], pts[0][2], 0.0, 0.0, 0.0];
    let t0 = Instant::now();
    for (i, p) in pts.iter().enumerate() {
        let e = ev(feed(*p));
        sim.event(&e, &prev, i as f64);
        prev = [p[0], p[1], p[2], 0.0, 0.0, 0.0];
    }
    let dt = t0.elapsed().as_secs_f64();
    let rep = sim.report();
    println!(
        "{which}: {n} moves in {dt:.2} s = {:.0} moves/s; removed {:.0} mm3, resolution {} mm",
        n as f64 / dt,
        rep.removed_mm3,
        rep.resolution_mm
    );
}
