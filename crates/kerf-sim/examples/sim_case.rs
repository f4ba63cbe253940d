//! One run of one simulation benchmark case (benches/cases.rs), for
//! instruction counts that do not depend on the machine's load:
//!
//! ```sh
//! cargo build --release -p kerf-sim --example sim_case
//! valgrind --tool=callgrind target/release/examples/sim_case mill_2d5_0.05mm
//! ```
//!
//! A second argument N runs the case's first N moves only;
//! `KERF_SIM_THREADS=1` keeps a height field move on one thread (the
//! simulation reads it, docs/sim.md).
//! Prints the case's moves, the material removed and the wall time of the
//! run (the stock's set-up excluded); with no argument, lists the cases.

#[path = "../benches/cases.rs"]
mod cases;

fn main() {
    let name = std::env::args().nth(1);
    let all = cases::all();
    let Some(case) = all.iter().find(|c| Some(c.name) == name.as_deref()) else {
        for c in &all {
            println!("{} ({} moves)", c.name, c.moves.len());
        }
        return;
    };
    let n = std::env::args()
        .nth(2)
        .and_then(|a| a.parse().ok())
        .unwrap_or(usize::MAX)
        .min(case.moves.len());
    let moves = &case.moves[..n];
    let mut s = (case.make)();
    let t = std::time::Instant::now();
    cases::run(&mut s, moves);
    let dt = t.elapsed().as_secs_f64();
    let r = s.report();
    println!(
        "{}: {} moves, removed {:.3} mm3, {} events, {:.3} s, {:.0} moves/s",
        case.name,
        n,
        r.removed_mm3,
        r.events.len(),
        dt,
        n as f64 / dt
    );
}
