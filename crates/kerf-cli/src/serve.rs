//! `kerf serve`: the controller runtime behind the browser screen
//! (crate kerf-hmi, docs/hmi.md). Arguments and messages only.

use std::net::SocketAddr;
use std::path::PathBuf;
use std::process::ExitCode;

use kerf_control::runtime::Runtime;

/// The arguments of `kerf serve`.
#[derive(clap::Args)]
pub struct Args {
    /// A program to load at start (optional; the screen loads others).
    program: Option<PathBuf>,
    /// Machine profile: a built-in name (see `kerf machines`) or a TOML file.
    #[arg(long, default_value = "hx-mc")]
    machine: String,
    /// Address to listen on (loopback unless --allow-remote).
    #[arg(long, default_value = kerf_hmi::DEFAULT_BIND)]
    bind: String,
    /// Allow an address other than loopback; commands then need the token.
    #[arg(long)]
    allow_remote: bool,
    /// The token for commands when --allow-remote (default: random).
    #[arg(long)]
    token: Option<String>,
    /// Folder keeping offsets and retained variables across restarts.
    #[arg(long, value_name = "DIR")]
    state: Option<PathBuf>,
    /// Folder of library programs (subprograms, macros); may repeat.
    #[arg(long = "lib")]
    lib: Vec<PathBuf>,
    /// Machine seconds per wall-clock second (1 = real time).
    #[arg(long, default_value_t = 1.0)]
    rate: f64,
    /// Simulate the cut part from this stock and show it in GRAPH
    /// (box:XMIN,YMIN,ZMIN,XMAX,YMAX,ZMAX or bar:DIAMETER,LENGTH[,FACE_Z]).
    #[arg(long, value_name = "SPEC")]
    stock: Option<String>,
}

/// Runs the server until the process is stopped.
pub fn run(a: Args) -> ExitCode {
    match serve(a) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("kerf: {e}");
            ExitCode::from(2)
        }
    }
}

fn serve(a: Args) -> Result<(), String> {
    let addr: SocketAddr = a
        .bind
        .parse()
        .map_err(|_| format!("--bind {}: expected ADDR:PORT, e.g. 127.0.0.1:7878", a.bind))?;
    let remote = kerf_hmi::check_bind(&addr, a.allow_remote).map_err(|e| e.to_string())?;
    if !(a.rate.is_finite() && a.rate > 0.0 && a.rate <= 10_000.0) {
        return Err(format!("--rate {}: must be in (0, 10000]", a.rate));
    }
    let token = match (remote, a.token) {
        (false, _) => None,
        (true, Some(t)) if t.len() >= 8 => Some(t),
        (true, Some(_)) => return Err("--token: at least 8 characters".into()),
        (true, None) => Some(kerf_hmi::new_token().map_err(|e| e.to_string())?),
    };
    let profile = kerf_control::load_profile(&a.machine).map_err(|e| e.to_string())?;
    for d in &a.lib {
        if !d.is_dir() {
            return Err(format!("--lib {}: not a folder", d.display()));
        }
    }
    let program = match &a.program {
        Some(p) => {
            let text = std::fs::read(p).map_err(|e| format!("{}: {e}", p.display()))?;
            if text.contains(&0) {
                return Err(format!("{}: not NC text", p.display()));
            }
            let name = p.file_name().map(|n| n.to_string_lossy().into_owned());
            Some((
                name.unwrap_or_else(|| "program.nc".into()),
                String::from_utf8_lossy(&text).into_owned(),
            ))
        }
        None => None,
    };
    // Checked here so a bad profile is a usage error before the server starts.
    Runtime::for_machine(&a.machine)?;
    let (machine, libs, state) = (a.machine.clone(), a.lib.clone(), a.state.clone());
    let make: kerf_hmi::server::MakeControl = Box::new(move || {
        let mut rt = Runtime::for_machine(&machine)?;
        for d in libs {
            rt.add_lib_dir(d);
        }
        if let Some(dir) = state {
            std::fs::create_dir_all(&dir).map_err(|e| format!("--state {}: {e}", dir.display()))?;
            rt.set_state_dir(dir)?;
        }
        Ok(Box::new(kerf_hmi::RuntimeControl::new(rt)) as Box<dyn kerf_hmi::Control>)
    });
    let stock = match &a.stock {
        Some(spec) => {
            // The error names the option and the spec itself.
            Some(kerf_sim::Stock::parse(spec).map_err(|e| e.to_string())?)
        }
        None => None,
    };
    let shared = kerf_hmi::Shared::new(make, profile.clone(), a.lib, token.clone(), a.rate)
        .map_err(|e| e.to_string())?;
    shared.set_stock(stock).map_err(|e| e.message)?;
    if let Some((name, text)) = program {
        shared
            .load(&name, text)
            .map_err(|e| format!("{name}: {}", e.message))?;
        shared
            .with(|c| {
                let _ = c.command(&kerf_hmi::command::Command::Mode(
                    kerf_hmi::state::Mode::MEM,
                ));
            })
            .map_err(|e| e.message)?;
    }
    kerf_hmi::serve(addr, shared, |at| {
        if let Some(t) = &token {
            eprintln!("kerf: warning: serving on {at}, reachable from other machines; every command needs the token {t}");
            eprintln!("kerf: serving {} at http://{at}/?token={t}", profile.name);
        } else {
            eprintln!("kerf: serving {} at http://{at}/", profile.name);
        }
    })
    .map_err(|e| e.to_string())
}
