//! Why the server could not start or stopped: the errors of [`crate::serve`],
//! [`crate::check_bind`], [`crate::new_token`] and
//! [`crate::server::Shared::new`] (the API's refusals are
//! [`crate::error::ApiError`]).

use std::net::SocketAddr;

/// The error a controller maker ([`crate::server::MakeControl`]) returns.
pub type MakeError = Box<dyn std::error::Error + Send + Sync>;

/// A failure to start or run the server.
#[derive(Debug, thiserror::Error)]
pub enum ServeError {
    /// `--bind` named an address off loopback without `--allow-remote`.
    #[error("--bind {0}: not a loopback address; pass --allow-remote to serve other machines (commands then need the token)")]
    NotLoopback(SocketAddr),
    /// The system's random source could not be read for a token.
    #[error("token: /dev/urandom: {0}")]
    Token(#[source] std::io::Error),
    /// The address could not be bound (or read back).
    #[error("--bind {addr}: {source}")]
    Bind {
        /// The address asked for.
        addr: SocketAddr,
        /// The system's reason.
        #[source]
        source: std::io::Error,
    },
    /// The tokio runtime could not be made.
    #[error("runtime: {0}")]
    Runtime(#[source] std::io::Error),
    /// Serving stopped on an I/O error.
    #[error("server: {0}")]
    Server(#[source] std::io::Error),
    /// The controller's thread could not be started.
    #[error("controller thread: {0}")]
    Thread(#[source] std::io::Error),
    /// The controller maker failed (its own message).
    #[error("{0}")]
    Control(MakeError),
    /// The controller's thread ended before it answered.
    #[error("the controller did not start")]
    ControlGone,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn messages_name_the_flag_and_the_cause() {
        let addr: SocketAddr = "10.0.0.1:80".parse().unwrap();
        assert_eq!(
            ServeError::NotLoopback(addr).to_string(),
            "--bind 10.0.0.1:80: not a loopback address; pass --allow-remote to serve other machines (commands then need the token)"
        );
        let e = ServeError::Bind {
            addr,
            source: std::io::Error::from(std::io::ErrorKind::AddrInUse),
        };
        assert_eq!(e.to_string(), "--bind 10.0.0.1:80: address in use");
        assert_eq!(
            ServeError::Control("unknown machine 'x'".into()).to_string(),
            "unknown machine 'x'"
        );
    }
}
