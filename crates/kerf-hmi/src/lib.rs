//! kerf-hmi: `kerf serve`, the controller runtime behind an HTTP and
//! WebSocket API on one local port, and the operator screen (POS, PROG,
//! MDI, OFFSET/SETTING, ALARM, GRAPH and the panel) served from files
//! embedded in the binary. The API is documented in docs/hmi.md.
//!
//! Architecture invariant: nothing here prints or exits; the CLI starts
//! the server with [`serve`] and reports what it returns.

pub mod api;
pub mod assets;
pub mod command;
pub mod control;
pub mod error;
pub mod live_part;
pub mod path;
pub mod relative;
pub mod repeat;
pub mod runtime_control;
pub mod serve_error;
pub mod server;
pub mod state;
pub mod stream;

use std::net::SocketAddr;
use std::sync::Arc;

use kerf_interp::dialect::DialectId;
use kerf_interp::Profile;

pub use control::{Control, Refusal};
pub use runtime_control::RuntimeControl;
pub use serve_error::ServeError;
pub use server::Shared;

/// Default address: loopback only.
pub const DEFAULT_BIND: &str = "127.0.0.1:7878";

/// The screen style of a machine: `fanuc` (HX, PUMA) or `hurco`.
pub fn style_of(p: &Profile) -> &'static str {
    match p.dialect {
        DialectId::Hurco => "hurco",
        _ => "fanuc",
    }
}

/// Checks the address: loopback always; anything else only with
/// `allow_remote` (the `--allow-remote` flag), and then a token is needed
/// (`Ok(true)`).
pub fn check_bind(addr: &SocketAddr, allow_remote: bool) -> Result<bool, ServeError> {
    if addr.ip().is_loopback() {
        return Ok(false);
    }
    if !allow_remote {
        return Err(ServeError::NotLoopback(*addr));
    }
    Ok(true)
}

/// A fresh random token (32 hex digits from the system's random source).
pub fn new_token() -> Result<String, ServeError> {
    use std::io::Read;
    let mut b = [0u8; 16];
    std::fs::File::open("/dev/urandom")
        .and_then(|mut f| f.read_exact(&mut b))
        .map_err(ServeError::Token)?;
    Ok(b.iter().map(|x| format!("{x:02x}")).collect())
}

/// Serves `shared` on `listener` until the process ends (the clock runs
/// on the controller's thread from [`Shared::new`]).
pub async fn run(listener: tokio::net::TcpListener, shared: Arc<Shared>) -> Result<(), ServeError> {
    axum::serve(listener, api::router(shared))
        .await
        .map_err(ServeError::Server)
}

/// Binds `addr` and serves `shared` on a new tokio runtime; `ready` is
/// called with the bound address before the first request is taken.
pub fn serve(
    addr: SocketAddr,
    shared: Arc<Shared>,
    ready: impl FnOnce(SocketAddr),
) -> Result<(), ServeError> {
    let rt = tokio::runtime::Builder::new_multi_thread()
        .worker_threads(2)
        .enable_all()
        .build()
        .map_err(ServeError::Runtime)?;
    let bind = |source| ServeError::Bind { addr, source };
    rt.block_on(async move {
        let l = tokio::net::TcpListener::bind(addr).await.map_err(bind)?;
        let at = l.local_addr().map_err(bind)?;
        ready(at);
        run(l, shared).await
    })
}
