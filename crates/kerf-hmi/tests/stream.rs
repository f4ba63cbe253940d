//! `WS /api/stream` on loopback: state pushes on the server's tick while the
//! program runs, the backplot records, the client message limit.

mod common;

use std::time::{Duration, Instant};

use common::double::Double;
use common::http::{post_json, request, start};
use futures_util::{SinkExt, StreamExt};
use tokio_tungstenite::tungstenite::Message;

async fn connect(
    at: std::net::SocketAddr,
) -> tokio_tungstenite::WebSocketStream<tokio_tungstenite::MaybeTlsStream<tokio::net::TcpStream>> {
    let (ws, _) = tokio_tungstenite::connect_async(format!("ws://{at}/api/stream"))
        .await
        .unwrap();
    ws
}

#[tokio::test]
async fn while_running_states_come_on_the_servers_tick() {
    let at = start(Box::new(Double::new()), None).await;
    request(
        at,
        "POST",
        "/api/program?name=p.nc",
        &[],
        b"G00 X100.\nM30\n",
    )
    .await;
    let mut ws = connect(at).await;
    assert_eq!(
        post_json(at, "/api/command", r#"{"cmd":"cycle_start"}"#)
            .await
            .status,
        200
    );
    // The double runs for 1 s of machine time. States are pushed on the
    // server's tick (30 Hz), not only when the execution state changes: a
    // second of motion brings many ACTIVE states, each further along X.
    // The rate is printed, not asserted (tests never assert time; a loaded
    // machine slows the ticks).
    let began = Instant::now();
    let mut xs = Vec::new();
    loop {
        let m = tokio::time::timeout(Duration::from_secs(10), ws.next())
            .await
            .expect("a state within 10 s")
            .unwrap()
            .unwrap();
        if let Message::Text(t) = m {
            let v: serde_json::Value = serde_json::from_str(&t).unwrap();
            assert_eq!(v["type"], "state");
            match v["execution"].as_str() {
                Some("ACTIVE") => xs.push(v["position"]["work"]["X"].as_f64().unwrap()),
                _ if !xs.is_empty() => break,
                _ => {}
            }
        }
    }
    let secs = began.elapsed().as_secs_f64();
    eprintln!(
        "{} ACTIVE states in {secs:.2} s ({:.0}/s)",
        xs.len(),
        xs.len() as f64 / secs
    );
    assert!(xs.len() >= 3, "{} ACTIVE states in a 1 s move", xs.len());
    assert!(xs.windows(2).all(|w| w[1] >= w[0]), "X goes back: {xs:?}");
    assert!(xs.last().unwrap() > xs.first().unwrap());
}

#[tokio::test]
async fn the_backplot_arrives_as_binary_records() {
    let at = start(Box::new(Double::new()), None).await;
    let mut ws = connect(at).await;
    request(
        at,
        "POST",
        "/api/program?name=p.nc",
        &[],
        b"G90 G00 X10. Y20. Z5.\nG01 X30. F600.\nM30\n",
    )
    .await;
    let deadline = Instant::now() + Duration::from_secs(10);
    let mut pts = Vec::new();
    while Instant::now() < deadline {
        let m = tokio::time::timeout(Duration::from_secs(5), ws.next())
            .await
            .unwrap()
            .unwrap()
            .unwrap();
        if let Message::Binary(b) = m {
            let u = |o: usize| u32::from_le_bytes([b[o], b[o + 1], b[o + 2], b[o + 3]]);
            let (first, count, done) = (u(4), u(8), u(12));
            assert_eq!(first as usize, pts.len());
            assert_eq!(b.len(), 16 + count as usize * 20);
            for i in 0..count as usize {
                let r = &b[16 + i * 20..16 + (i + 1) * 20];
                pts.push((kerf_hmi::path::record_point(r), r[16]));
            }
            if done == 1 {
                break;
            }
        }
    }
    // Start point, the rapid's end (line 1), the feed's end (line 2).
    assert_eq!(pts.len(), 3, "{pts:?}");
    assert_eq!(pts[1], ([10.0, 20.0, 5.0], kerf_hmi::path::kind::RAPID));
    assert_eq!(pts[2], ([30.0, 20.0, 5.0], kerf_hmi::path::kind::FEED));
    // The same records over HTTP.
    let r = common::http::get(at, "/api/toolpath").await;
    assert_eq!(r.body.len(), 16 + 3 * 20);
}

#[tokio::test]
async fn an_oversized_client_message_closes_only_that_client() {
    let at = start(Box::new(Double::new()), None).await;
    let mut bad = connect(at).await;
    let mut good = connect(at).await;
    let _ = bad
        .send(Message::Text(
            "x".repeat(kerf_hmi::stream::MAX_CLIENT_MESSAGE * 4).into(),
        ))
        .await;
    let closed = tokio::time::timeout(Duration::from_secs(5), async {
        loop {
            match bad.next().await {
                None | Some(Err(_)) | Some(Ok(Message::Close(_))) => return true,
                Some(Ok(_)) => {}
            }
        }
    })
    .await
    .unwrap();
    assert!(closed);
    // The other client still gets states (the heartbeat, at least once a second).
    let m = tokio::time::timeout(Duration::from_secs(3), good.next())
        .await
        .unwrap()
        .unwrap()
        .unwrap();
    assert!(matches!(m, Message::Text(_)));
    assert_eq!(common::http::get(at, "/api/state").await.status, 200);
}

/// The path of `GET /api/state` once its trace is done.
async fn done_path(at: std::net::SocketAddr) -> serde_json::Value {
    let deadline = Instant::now() + Duration::from_secs(10);
    loop {
        let p = common::http::get(at, "/api/state").await.json()["path"].clone();
        if p["done"] == true {
            return p;
        }
        assert!(Instant::now() < deadline, "the trace does not end: {p}");
        tokio::time::sleep(Duration::from_millis(20)).await;
    }
}

#[tokio::test]
async fn a_load_refused_while_running_leaves_the_old_program_and_its_path() {
    let at = start(Box::new(Double::new()), None).await;
    let old = b"G90 G00 X10. Y20. Z5.\nG01 X30. F600.\nM30\n";
    request(at, "POST", "/api/program?name=a.nc", &[], old).await;
    // Start point and two moves.
    assert_eq!(done_path(at).await["points"], 3);
    post_json(at, "/api/command", r#"{"cmd":"cycle_start"}"#).await;
    // Four moves: the trace of this program starts before the refusal.
    let new = b"G00 X1.\nG00 X2.\nG00 X3.\nG00 X4.\nM30\n";
    let r = request(at, "POST", "/api/program?name=b.nc", &[], new).await;
    assert_eq!(r.status, 409);
    let p = done_path(at).await;
    assert_eq!(p["points"], 3, "{p}");
    let s = common::http::get(at, "/api/state").await.json();
    assert_eq!(s["program"]["name"], "a.nc");
    let r = common::http::get(at, "/api/toolpath").await;
    let x = kerf_hmi::path::record_point(&r.body[16 + 40..16 + 60])[0];
    assert_eq!(x, 30.0);
}
