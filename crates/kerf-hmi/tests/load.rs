//! Load on loopback: 100 WebSocket clients on a server running a real
//! program through the runtime; every client gets states at 20 Hz or more
//! and no error. Bounded: KERF_LOAD_SECS seconds (default 10; the issue's
//! figure is 60). The clients run in this process on the same two cores,
//! so it is measured on an optimised build:
//! `KERF_LOAD_SECS=60 cargo test --release -p kerf-hmi --test load -- --ignored`.

use std::time::{Duration, Instant};

use futures_util::StreamExt;
use tokio_tungstenite::tungstenite::Message;

const CLIENTS: usize = 100;

async fn server() -> std::net::SocketAddr {
    let profile = kerf_interp::Profile::builtin("hx-mc").unwrap();
    let p2 = profile.clone();
    let make: kerf_hmi::server::MakeControl = Box::new(move || {
        let d = kerf_control::dynamics::dynamics_of(&p2, 100.0, 100.0, false)?;
        let rt = kerf_control::runtime::Runtime::new(p2, d)?;
        Ok(Box::new(kerf_hmi::RuntimeControl::new(rt)) as Box<dyn kerf_hmi::Control>)
    });
    let shared = kerf_hmi::Shared::new(make, profile, vec![], None, 1.0).unwrap();
    // A square of 100 mm sides at F300, three laps: 80 s a lap (longer
    // than the longest run; not an endless loop, whose backplot trace
    // would keep a core busy up to the 50-million-block guard).
    let prog = "G90 G17 G21 G54\nG00 X0. Y0. Z5.\n#100=0\nWHILE [#100 LT 3] DO1\nG01 X100. F300.\nY100.\nX0.\nY0.\n#100=#100+1\nEND1\nM30\n";
    shared.load("square.nc", prog).unwrap();
    for c in [
        kerf_hmi::command::Command::Mode(kerf_hmi::state::Mode::MEM),
        kerf_hmi::command::Command::CycleStart,
    ] {
        shared.with(move |ctl| ctl.command(&c)).unwrap().unwrap();
    }
    shared.publish();
    let l = tokio::net::TcpListener::bind("127.0.0.1:0").await.unwrap();
    let at = l.local_addr().unwrap();
    tokio::spawn(kerf_hmi::run(l, shared));
    at
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
#[ignore = "a load test: run on a release build (see the file's doc)"]
async fn a_hundred_clients_each_get_20_hz() {
    let secs: u64 = std::env::var("KERF_LOAD_SECS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(10)
        .clamp(1, 120);
    let at = server().await;
    let mut tasks = Vec::new();
    for _ in 0..CLIENTS {
        tasks.push(tokio::spawn(async move {
            let (mut ws, _) = tokio_tungstenite::connect_async(format!("ws://{at}/api/stream"))
                .await
                .map_err(|e| e.to_string())?;
            let end = Instant::now() + Duration::from_secs(secs);
            let (mut active, mut t_last) = (0u64, 0.0f64);
            while Instant::now() < end {
                let m = tokio::time::timeout(Duration::from_secs(5), ws.next())
                    .await
                    .map_err(|_| format!("no message for 5 s after {active} states, t {t_last}"))?
                    .ok_or("closed")?
                    .map_err(|e| e.to_string())?;
                if let Message::Text(t) = m {
                    // Read only what is checked (the clients share the
                    // server's two cores): the execution state and t.
                    if !t.contains(r#""execution":"ACTIVE""#) {
                        // The state from before the cycle start, at most
                        // once, first.
                        if active > 0 {
                            return Err(format!("not ACTIVE: {}", &t[..t.len().min(200)]));
                        }
                        continue;
                    }
                    let i = t.rfind(r#""t":"#).ok_or("no t")? + 4;
                    let t: f64 = t[i..]
                        .split([',', '}'])
                        .next()
                        .unwrap_or("")
                        .parse()
                        .map_err(|_| "bad t".to_string())?;
                    if t < t_last {
                        return Err(format!("machine time went back: {t_last} → {t}"));
                    }
                    t_last = t;
                    active += 1;
                }
            }
            Ok::<u64, String>(active)
        }));
    }
    let mut counts = Vec::new();
    for t in tasks {
        counts.push(t.await.unwrap().unwrap());
    }
    counts.sort();
    let rate = counts[0] as f64 / secs as f64;
    let (load, cores) = load_and_cores();
    eprintln!(
        "{CLIENTS} clients, {secs} s: states per client min {} median {} max {} (slowest {rate:.1} Hz); load average {load:.1} on {cores} cores",
        counts[0],
        counts[CLIENTS / 2],
        counts[CLIENTS - 1]
    );
    // The clients and the server share this machine's cores: on a machine
    // already oversubscribed by other work the figure is printed, not judged.
    if load > cores as f64 {
        eprintln!("not judged: the run queue is longer than the cores");
        return;
    }
    assert!(rate >= 20.0, "the slowest client got {rate:.1} states/s");
}

/// The 1-minute load average (Linux /proc/loadavg; 0 elsewhere) and the
/// number of cores.
fn load_and_cores() -> (f64, usize) {
    let load = std::fs::read_to_string("/proc/loadavg")
        .ok()
        .and_then(|s| s.split_whitespace().next().and_then(|v| v.parse().ok()))
        .unwrap_or(0.0);
    let cores = std::thread::available_parallelism()
        .map(|n| n.get())
        .unwrap_or(1);
    (load, cores)
}
