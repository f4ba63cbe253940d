//! The HTTP routes: the page, its files, and the JSON API under `/api`
//! (docs/hmi.md). Bodies are read with a limit and parsed here, so every
//! bad body gets the same JSON error.

use std::sync::Arc;

use axum::body::{Body, Bytes};
use axum::extract::{Query, Request, State as AxState};
use axum::http::{header, HeaderMap, StatusCode};
use axum::response::{IntoResponse, Response};
use axum::routing::get;
use axum::{Json, Router};
use serde::Deserialize;
use serde_json::json;

use crate::error::ApiError;
use crate::server::Shared;

/// Largest command, offsets or other JSON body, bytes.
pub const MAX_JSON: usize = 64 * 1024;
/// Largest program text, bytes: the runtime's own limit, so a body the
/// server takes is one the runtime loads.
pub const MAX_PROGRAM: usize = kerf_control::runtime::MAX_PROGRAM_BYTES;
/// Most lines one `GET /api/program` returns.
pub const MAX_LINES: usize = 2000;
/// Most toolpath points one `GET /api/toolpath` returns.
pub const MAX_TOOLPATH_POINTS: usize = 1 << 20;

type S = AxState<Arc<Shared>>;
type Answer = Result<Response, ApiError>;

/// The router of the whole server.
pub fn router(shared: Arc<Shared>) -> Router {
    Router::new()
        .route("/", get(index))
        .route("/assets/{*path}", get(asset))
        .route("/favicon.ico", get(|| async { StatusCode::NO_CONTENT }))
        .route("/api/machine", get(machine))
        .route("/api/state", get(state))
        .route("/api/program", get(program_lines).post(load_program))
        .route("/api/command", axum::routing::post(command))
        .route("/api/offsets", get(offsets).put(put_offsets))
        .route("/api/variables", get(variables).put(put_variables))
        .route("/api/parameters", get(parameters).put(put_parameters))
        .route("/api/alarms", get(alarms))
        .route("/api/toolpath", get(toolpath))
        .route("/api/part.stl", get(part))
        .route("/api/stream", get(crate::stream::upgrade))
        .fallback(not_found)
        .with_state(shared)
}

async fn not_found(req: Request) -> ApiError {
    ApiError::not_found(format!("no route {} {}", req.method(), req.uri().path()))
}

async fn index() -> Response {
    asset_response("index.html")
}

async fn asset(axum::extract::Path(path): axum::extract::Path<String>) -> Response {
    asset_response(&path)
}

fn asset_response(path: &str) -> Response {
    match crate::assets::get(path) {
        Some(a) => (
            [
                (header::CONTENT_TYPE, a.mime),
                (header::CACHE_CONTROL, "no-cache"),
            ],
            a.bytes,
        )
            .into_response(),
        None => ApiError::not_found(format!("no file {path}")).into_response(),
    }
}

/// Checks the token when the server has one (bound off loopback).
pub fn authorise(
    shared: &Shared,
    headers: &HeaderMap,
    query_token: Option<&str>,
) -> Result<(), ApiError> {
    let Some(want) = &shared.token else {
        return Ok(());
    };
    let bearer = headers
        .get(header::AUTHORIZATION)
        .and_then(|v| v.to_str().ok())
        .and_then(|v| v.strip_prefix("Bearer "));
    let given = bearer.or(query_token);
    if given.is_some_and(|g| constant_time_eq(g.as_bytes(), want.as_bytes())) {
        Ok(())
    } else {
        Err(ApiError::unauthorized())
    }
}

fn constant_time_eq(a: &[u8], b: &[u8]) -> bool {
    a.len() == b.len() && a.iter().zip(b).fold(0u8, |acc, (x, y)| acc | (x ^ y)) == 0
}

/// Reads a body up to `limit` bytes.
async fn read_body(body: Body, limit: usize) -> Result<Bytes, ApiError> {
    axum::body::to_bytes(body, limit)
        .await
        .map_err(|_| ApiError::too_large(limit))
}

#[derive(Deserialize)]
struct TokenQuery {
    token: Option<String>,
}

async fn machine(AxState(s): S) -> Json<serde_json::Value> {
    let p = &s.profile;
    let axes: Vec<&str> = kerf_canon::Axis::ALL
        .iter()
        .filter(|a| p.has_axis(**a))
        .map(|a| ["X", "Y", "Z", "A", "B", "C"][*a as usize])
        .collect();
    let kind = match p.kind {
        kerf_interp::machine::MachineKind::Lathe => "lathe",
        _ => "mill",
    };
    Json(json!({
        "name": p.name,
        "description": p.description,
        "kind": kind,
        "style": crate::style_of(p),
        "axes": axes,
        "offsets": p.tools.offsets,
        "token_required": s.token.is_some(),
    }))
}

async fn state(AxState(s): S) -> Response {
    let f = s.frames.borrow().clone();
    Json(&f.state).into_response()
}

#[derive(Deserialize)]
struct LoadQuery {
    name: Option<String>,
    token: Option<String>,
}

async fn load_program(
    AxState(s): S,
    Query(q): Query<LoadQuery>,
    headers: HeaderMap,
    body: Body,
) -> Answer {
    authorise(&s, &headers, q.token.as_deref())?;
    let bytes = read_body(body, MAX_PROGRAM).await?;
    if bytes.is_empty() {
        return Err(ApiError::bad_request("program: the body is empty"));
    }
    if bytes.contains(&0) {
        return Err(ApiError::bad_request(
            "program: the body is not NC text (it holds NUL bytes)",
        ));
    }
    // Valid UTF-8 (the usual case) is copied once; other bytes replaced.
    let text: Arc<str> = match std::str::from_utf8(&bytes) {
        Ok(t) => t.into(),
        Err(_) => String::from_utf8_lossy(&bytes).into(),
    };
    drop(bytes);
    let name = q.name.unwrap_or_else(|| "program.nc".into());
    if name.len() > 255 || name.contains(['/', '\\', '\0']) {
        return Err(ApiError::bad_request(
            "program: name must be a file name of at most 255 bytes",
        ));
    }
    let s2 = s.clone();
    let prog = tokio::task::spawn_blocking(move || s2.load(&name, text))
        .await
        .map_err(|e| ApiError::internal(e.to_string()))??;
    Ok(
        Json(json!({"name": prog.name, "lines": prog.count(), "bytes": prog.text.len()}))
            .into_response(),
    )
}

#[derive(Deserialize)]
struct LinesQuery {
    from: Option<usize>,
    count: Option<usize>,
}

async fn program_lines(
    AxState(s): S,
    q: Result<Query<LinesQuery>, axum::extract::rejection::QueryRejection>,
) -> Answer {
    let Query(q) = q.map_err(|e| ApiError::bad_request(e.body_text()))?;
    let Some(p) = s.program() else {
        return Err(ApiError::not_found("no program is loaded"));
    };
    let from = q.from.unwrap_or(1).max(1);
    let count = q.count.unwrap_or(200).min(MAX_LINES);
    let lines: Vec<&str> = (from..from.saturating_add(count))
        .map_while(|n| p.line(n))
        .collect();
    Ok(
        Json(json!({"name": p.name, "total": p.count(), "from": from, "lines": lines}))
            .into_response(),
    )
}

async fn command(
    AxState(s): S,
    Query(q): Query<TokenQuery>,
    headers: HeaderMap,
    body: Body,
) -> Answer {
    authorise(&s, &headers, q.token.as_deref())?;
    let bytes = read_body(body, MAX_JSON).await?;
    let cmd = crate::command::parse(&bytes)?;
    // One trip to the controller: the command, then the state after it
    // published there and answered.
    let (r, state) = s
        .ask(move |c, s| {
            let r = c.command(&cmd);
            s.publish_state(c.state());
            (r, s.frames.borrow().state.clone())
        })
        .await?;
    r.map_err(ApiError::from)?;
    Ok(Json(json!({"ok": true, "state": state})).into_response())
}

async fn offsets(AxState(s): S) -> Answer {
    read(s, |c| c.offsets()).await
}

/// A GET answered by the controller.
async fn read(s: Arc<Shared>, f: fn(&dyn crate::Control) -> serde_json::Value) -> Answer {
    let v = s.ask(move |c, _| f(c)).await?;
    Ok(Json(v).into_response())
}

async fn put_offsets(
    AxState(s): S,
    Query(q): Query<TokenQuery>,
    headers: HeaderMap,
    body: Body,
) -> Answer {
    put_object(
        s,
        q,
        headers,
        body,
        |c, v| c.put_offsets(v),
        |c| c.offsets(),
    )
    .await
}

async fn variables(AxState(s): S) -> Answer {
    read(s, |c| c.variables()).await
}

async fn parameters(AxState(s): S) -> Answer {
    read(s, |c| c.parameters()).await
}

/// A PUT of a JSON object: checked, written by `write`, answered by `read`.
async fn put_object(
    s: Arc<Shared>,
    q: TokenQuery,
    headers: HeaderMap,
    body: Body,
    write: fn(&mut dyn crate::Control, &serde_json::Value) -> Result<(), crate::Refusal>,
    read: fn(&dyn crate::Control) -> serde_json::Value,
) -> Answer {
    authorise(&s, &headers, q.token.as_deref())?;
    let bytes = read_body(body, MAX_JSON).await?;
    let v: serde_json::Value = crate::error::parse_json(&bytes)?;
    if !v.is_object() {
        return Err(ApiError::bad_json("the body must be a JSON object"));
    }
    let now = s
        .ask(move |c, s| {
            let r = write(c, &v).map(|_| read(c));
            s.publish_state(c.state());
            r
        })
        .await??;
    Ok(Json(now).into_response())
}

async fn put_variables(
    AxState(s): S,
    Query(q): Query<TokenQuery>,
    headers: HeaderMap,
    body: Body,
) -> Answer {
    put_object(
        s,
        q,
        headers,
        body,
        |c, v| c.put_variables(v),
        |c| c.variables(),
    )
    .await
}

async fn put_parameters(
    AxState(s): S,
    Query(q): Query<TokenQuery>,
    headers: HeaderMap,
    body: Body,
) -> Answer {
    put_object(
        s,
        q,
        headers,
        body,
        |c, v| c.put_parameters(v),
        |c| c.parameters(),
    )
    .await
}

#[derive(Deserialize)]
struct AlarmsQuery {
    since: Option<u64>,
}

async fn alarms(
    AxState(s): S,
    q: Result<Query<AlarmsQuery>, axum::extract::rejection::QueryRejection>,
) -> Answer {
    let Query(q) = q.map_err(|e| ApiError::bad_request(e.body_text()))?;
    let since = q.since.unwrap_or(0);
    let all = s.ask(|c, _| c.alarms()).await?;
    let mut all: Vec<_> = all.into_iter().filter(|a| a.seq > since).collect();
    for a in &mut all {
        s.fill_block(a);
    }
    Ok(Json(json!({"alarms": all})).into_response())
}

#[derive(Deserialize)]
struct PathQuery {
    from: Option<usize>,
}

/// The backplot records from point `from`: a 16-byte header (id, first,
/// count, done as u32 LE) then `count` records of 20 bytes.
async fn toolpath(
    AxState(s): S,
    q: Result<Query<PathQuery>, axum::extract::rejection::QueryRejection>,
) -> Answer {
    let Query(q) = q.map_err(|e| ApiError::bad_request(e.body_text()))?;
    let from = q.from.unwrap_or(0);
    let body = crate::stream::path_chunk(&s, from, MAX_TOOLPATH_POINTS)
        .map(|(b, _)| b)
        .unwrap_or_else(|| {
            let p = s.path.lock().unwrap_or_else(|p| p.into_inner());
            crate::stream::header(p.id, from as u32, 0, p.done)
        });
    Ok((
        StatusCode::OK,
        [(header::CONTENT_TYPE, "application/octet-stream")],
        body,
    )
        .into_response())
}

/// The simulated part of the loaded program (binary STL), when the server
/// has a stock (`--stock`): as cut so far once a run has started, else the
/// whole program's result once the trace is done.
async fn part(AxState(s): S) -> Answer {
    let p = s
        .path
        .lock()
        .unwrap_or_else(|p| p.into_inner())
        .shown_part();
    match p {
        Some(stl) => Ok((
            StatusCode::OK,
            [(header::CONTENT_TYPE, "model/stl")],
            stl.as_ref().clone(),
        )
            .into_response()),
        None => Err(ApiError::not_found(
            "no simulated part (kerf serve --stock SPEC, and the trace done)",
        )),
    }
}
