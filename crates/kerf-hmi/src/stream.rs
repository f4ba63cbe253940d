//! `WS /api/stream`: the state as a JSON text message whenever it changes
//! (every tick, 30 Hz, while the program runs; at least once a second when
//! nothing changes) and the backplot as binary messages of point records.
//! A slow client skips states (it always gets the newest), so memory per
//! client is bounded. Client messages larger than [`MAX_CLIENT_MESSAGE`]
//! close the connection; other client messages are ignored.

use std::sync::Arc;
use std::time::Duration;

use axum::extract::ws::{Message, WebSocket, WebSocketUpgrade};
use axum::extract::{Query, State as AxState};
use axum::http::HeaderMap;
use axum::response::{IntoResponse, Response};
use serde::Deserialize;

use crate::path::RECORD;
use crate::server::Shared;

/// Largest message a client may send, bytes.
pub const MAX_CLIENT_MESSAGE: usize = 4096;
/// Most points in one binary message.
pub const CHUNK_POINTS: usize = 65_536;
/// A state is sent at least this often.
const HEARTBEAT: Duration = Duration::from_secs(1);

#[derive(Deserialize)]
pub(crate) struct StreamQuery {
    token: Option<String>,
}

/// The upgrade handler.
pub(crate) async fn upgrade(
    AxState(s): AxState<Arc<Shared>>,
    Query(q): Query<StreamQuery>,
    headers: HeaderMap,
    ws: WebSocketUpgrade,
) -> Response {
    if let Err(e) = crate::api::authorise(&s, &headers, q.token.as_deref()) {
        return e.into_response();
    }
    ws.max_message_size(MAX_CLIENT_MESSAGE)
        .max_frame_size(MAX_CLIENT_MESSAGE)
        .on_upgrade(move |sock| client(sock, s))
}

/// The 16-byte header of a toolpath message: path id, index of the first
/// point, number of points, 1 when the path is complete (u32 LE each).
pub fn header(id: u32, first: u32, count: u32, done: bool) -> Vec<u8> {
    let mut h = Vec::with_capacity(16);
    for v in [id, first, count, done as u32] {
        h.extend_from_slice(&v.to_le_bytes());
    }
    h
}

/// Header and records of the points from `from` on (at most `max`), and
/// the path id; None when there is nothing past `from`.
pub fn path_chunk(s: &Shared, from: usize, max: usize) -> Option<(Vec<u8>, u32)> {
    let p = s.path.lock().unwrap_or_else(|p| p.into_inner());
    let n = p.points();
    if from >= n {
        return None;
    }
    let count = (n - from).min(max);
    let mut out = header(p.id, from as u32, count as u32, p.done && from + count == n);
    out.extend_from_slice(&p.bytes[from * RECORD..(from + count) * RECORD]);
    Some((out, p.id))
}

async fn client(mut sock: WebSocket, s: Arc<Shared>) {
    let mut rx = s.frames.subscribe();
    let mut beat = tokio::time::interval(HEARTBEAT);
    // Which path the client has, and how many of its points.
    let mut have: (u32, usize) = (u32::MAX, 0);
    rx.mark_changed();
    loop {
        let (id, points) = {
            let p = s.path.lock().unwrap_or_else(|p| p.into_inner());
            (p.id, p.points())
        };
        if id != have.0 {
            have = (id, 0);
        }
        let pending = points > have.1;
        tokio::select! {
            biased;
            r = rx.changed() => {
                if r.is_err() { break; }
                let json = rx.borrow_and_update().json.clone();
                if sock.send(Message::Text(json)).await.is_err() { break; }
            }
            m = sock.recv() => match m {
                Some(Ok(Message::Close(_))) | Some(Err(_)) | None => break,
                Some(Ok(_)) => {}
            },
            _ = beat.tick() => {
                let json = s.frames.borrow().json.clone();
                if sock.send(Message::Text(json)).await.is_err() { break; }
            }
            _ = std::future::ready(()), if pending => {
                if let Some((bytes, id)) = path_chunk(&s, have.1, CHUNK_POINTS) {
                    if id == have.0 {
                        let n = (bytes.len() - 16) / RECORD;
                        if sock.send(Message::Binary(bytes.into())).await.is_err() { break; }
                        have.1 += n;
                    } else {
                        have = (id, 0);
                    }
                }
            }
        }
    }
}
