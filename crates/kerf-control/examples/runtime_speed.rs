//! Times the runtime on a long program: `cargo run --release -p
//! kerf-control --example runtime_speed [BLOCKS]` prints the wall time per
//! 1000 blocks and the machine time reached.
use kerf_control::runtime::{Command, Execution, Mode, Runtime};

fn main() {
    let n: usize = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(20_000);
    let mut text = String::from("G90 G54 G00 X0. Y0. Z0.\nG01 F3000\n");
    for i in 0..n {
        let a = i as f64 * 0.01;
        text.push_str(&format!("X{:.3} Y{:.3}\n", 50.0 * a.cos(), 50.0 * a.sin()));
    }
    text.push_str("M30\n");
    let mut rt = Runtime::for_machine("hx-mc").unwrap();
    rt.command(Command::Mode { mode: Mode::Mem }).unwrap();
    rt.load_program("speed.nc", &text).unwrap();
    rt.set_rate(10_000.0).unwrap();
    rt.command(Command::CycleStart).unwrap();
    let wall = std::time::Instant::now();
    let mut frames = 0u64;
    while rt.execution() == Execution::Active && frames < 1_000_000 {
        rt.advance(0.05);
        let _ = serde_json::to_string(&rt.state()).unwrap();
        frames += 1;
    }
    let s = wall.elapsed().as_secs_f64();
    println!(
        "{n} blocks: {:?}, {s:.2} s wall in {frames} frames of 500 s machine time, {:.1} µs per block",
        rt.execution(),
        s * 1e6 / n as f64
    );
}
