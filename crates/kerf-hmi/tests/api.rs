//! The HTTP API on 127.0.0.1 with an ephemeral port, against a test
//! double of the controller: routes, errors, limits, the token.

mod common;

use common::double::Double;
use common::http::{get, post_json, request, start};

#[tokio::test]
async fn the_page_and_its_scripts_are_served_from_the_binary() {
    let at = start(Box::new(Double::new()), None).await;
    let r = get(at, "/").await;
    assert_eq!(r.status, 200);
    assert!(r.header("content-type").unwrap().starts_with("text/html"));
    let html = String::from_utf8(r.body).unwrap();
    assert!(html.contains(r#""three": "/assets/vendor/three.module.js""#));
    // Nothing from the network: every src and href is a path on this server.
    for attr in ["src=\"", "href=\""] {
        for (i, _) in html.match_indices(attr) {
            let v = &html[i + attr.len()..];
            assert!(
                v.starts_with('/'),
                "external reference: {}",
                &v[..v.find('"').unwrap()]
            );
        }
    }
    for p in [
        "/assets/app.js",
        "/assets/screens.js",
        "/assets/graph.js",
        "/assets/lines.js",
        "/assets/coarse.js",
        "/assets/vendor/three.module.js",
        "/assets/vendor/three.core.js",
        "/assets/vendor/OrbitControls.js",
    ] {
        let r = get(at, p).await;
        assert_eq!(r.status, 200, "{p}");
        assert!(
            r.header("content-type")
                .unwrap()
                .starts_with("text/javascript"),
            "{p}"
        );
        assert!(r.body.len() > 1000, "{p}");
    }
    let r = get(at, "/assets/nothing.js").await;
    assert_eq!(r.status, 404);
    assert_eq!(r.json()["error"]["code"], "not_found");
}

#[tokio::test]
async fn a_loaded_program_is_read_back_by_lines() {
    let at = start(Box::new(Double::new()), None).await;
    let r = request(
        at,
        "POST",
        "/api/program?name=a.nc",
        &[],
        b"O1\r\nG00 X1.\nG01 X2. F100.\nM30\n",
    )
    .await;
    assert_eq!(r.status, 200);
    assert_eq!(r.json()["lines"], 4);
    let r = get(at, "/api/program?from=2&count=2").await;
    let j = r.json();
    assert_eq!(j["name"], "a.nc");
    assert_eq!(j["total"], 4);
    assert_eq!(j["lines"], serde_json::json!(["G00 X1.", "G01 X2. F100."]));
    // Past the end: no lines, no error.
    assert_eq!(
        get(at, "/api/program?from=9").await.json()["lines"],
        serde_json::json!([])
    );
    let r = get(at, "/api/program?from=x").await;
    assert_eq!(r.status, 400);
    let r = request(at, "POST", "/api/program?name=../etc", &[], b"M30\n").await;
    assert_eq!(r.status, 400);
    let r = request(at, "POST", "/api/program", &[], b"").await;
    assert_eq!(r.json()["error"]["message"], "program: the body is empty");
    let r = request(at, "POST", "/api/program", &[], b"G00\0X1").await;
    assert_eq!(r.status, 400);
}

#[tokio::test]
async fn commands_answer_with_the_new_state_or_a_reason() {
    let at = start(Box::new(Double::new()), None).await;
    // The double refuses a cycle start with no program: 409 with its reason.
    let r = post_json(at, "/api/command", r#"{"cmd":"cycle_start"}"#).await;
    assert_eq!(r.status, 409);
    assert_eq!(r.json()["error"]["code"], "refused");
    assert_eq!(r.json()["error"]["message"], "no program");
    let r = post_json(
        at,
        "/api/command",
        r#"{"cmd":"override","feed":150,"rapid":25}"#,
    )
    .await;
    assert_eq!(r.status, 200);
    let j = r.json();
    assert_eq!(j["ok"], true);
    assert_eq!(j["state"]["overrides"]["feed"], 150.0);
    assert_eq!(j["state"]["overrides"]["rapid"], 25.0);
    // The same state is what GET /api/state returns now.
    assert_eq!(
        get(at, "/api/state").await.json()["overrides"]["feed"],
        150.0
    );
    let r = post_json(at, "/api/command", r#"{"cmd":"override","feed":"fast"}"#).await;
    assert_eq!(r.status, 400);
    assert_eq!(r.json()["error"]["code"], "bad_json");
}

#[tokio::test]
async fn bodies_over_the_limit_are_413_and_the_server_goes_on() {
    let at = start(Box::new(Double::new()), None).await;
    let big = format!(
        r#"{{"cmd":"mdi","block":"{}"}}"#,
        "X".repeat(kerf_hmi::api::MAX_JSON)
    );
    let r = post_json(at, "/api/command", &big).await;
    assert_eq!(r.status, 413);
    assert_eq!(r.json()["error"]["code"], "too_large");
    assert_eq!(get(at, "/api/state").await.status, 200);
}

#[tokio::test]
async fn unknown_routes_and_methods_get_json_errors() {
    let at = start(Box::new(Double::new()), None).await;
    let r = get(at, "/api/nothing").await;
    assert_eq!(r.status, 404);
    assert_eq!(r.json()["error"]["code"], "not_found");
    let r = request(at, "DELETE", "/api/state", &[], b"").await;
    assert_eq!(r.status, 405);
}

#[tokio::test]
async fn offsets_are_written_and_read_back() {
    let at = start(Box::new(Double::new()), None).await;
    let r = request(at, "PUT", "/api/offsets", &[], br#"{"h": {"1": 50.5}}"#).await;
    assert_eq!(r.status, 200);
    assert_eq!(r.json()["h"]["1"], 50.5);
    assert_eq!(get(at, "/api/offsets").await.json()["h"]["1"], 50.5);
    let r = request(at, "PUT", "/api/offsets", &[], br#"[1]"#).await;
    assert_eq!(r.status, 400);
    assert_eq!(r.json()["error"]["code"], "bad_json");
    let r = request(at, "PUT", "/api/offsets", &[], br#"{"q": {}}"#).await;
    assert_eq!(r.status, 400);
    assert_eq!(r.json()["error"]["code"], "bad_request");
}

#[tokio::test]
async fn off_loopback_every_change_needs_the_token() {
    let at = start(Box::new(Double::new()), Some("s3cret".into())).await;
    // Reading is open.
    assert_eq!(get(at, "/api/state").await.status, 200);
    assert_eq!(get(at, "/api/machine").await.json()["token_required"], true);
    let r = post_json(at, "/api/command", r#"{"cmd":"reset"}"#).await;
    assert_eq!(r.status, 401);
    assert_eq!(r.json()["error"]["code"], "unauthorized");
    let wrong = [("Authorization", "Bearer s3cres")];
    assert_eq!(
        request(at, "POST", "/api/command", &wrong, br#"{"cmd":"reset"}"#)
            .await
            .status,
        401
    );
    let right = [("Authorization", "Bearer s3cret")];
    assert_eq!(
        request(at, "POST", "/api/command", &right, br#"{"cmd":"reset"}"#)
            .await
            .status,
        200
    );
    assert_eq!(
        post_json(at, "/api/command?token=s3cret", r#"{"cmd":"reset"}"#)
            .await
            .status,
        200
    );
    assert_eq!(
        request(at, "PUT", "/api/offsets", &[], br#"{"h":{}}"#)
            .await
            .status,
        401
    );
    assert_eq!(
        request(at, "POST", "/api/program", &[], b"M30\n")
            .await
            .status,
        401
    );
}

#[test]
fn binding_off_loopback_needs_the_flag() {
    let lo: std::net::SocketAddr = "127.0.0.1:7878".parse().unwrap();
    let any: std::net::SocketAddr = "0.0.0.0:7878".parse().unwrap();
    assert!(matches!(kerf_hmi::check_bind(&lo, false), Ok(false)));
    let e = kerf_hmi::check_bind(&any, false).unwrap_err();
    assert!(matches!(e, kerf_hmi::ServeError::NotLoopback(a) if a == any));
    assert!(e.to_string().contains("--allow-remote"), "{e}");
    assert!(matches!(kerf_hmi::check_bind(&any, true), Ok(true)));
    let t = kerf_hmi::new_token().unwrap();
    assert_eq!(t.len(), 32);
    assert_ne!(t, kerf_hmi::new_token().unwrap());
}

#[tokio::test]
async fn with_a_stock_the_simulated_part_is_served_as_stl() {
    let profile = kerf_interp::Profile::builtin("hx-mc").unwrap();
    let make: kerf_hmi::server::MakeControl =
        Box::new(|| Ok(Box::new(Double::new()) as Box<dyn kerf_hmi::Control>));
    let shared = kerf_hmi::Shared::new(make, profile, vec![], None, 1.0).unwrap();
    *shared.stock.lock().unwrap() = Some(kerf_sim::Stock::parse("box:0,0,-10,20,20,0").unwrap());
    let l = tokio::net::TcpListener::bind("127.0.0.1:0").await.unwrap();
    let at = l.local_addr().unwrap();
    tokio::spawn(kerf_hmi::run(l, shared));
    assert_eq!(get(at, "/api/part.stl").await.status, 404);
    // Rapids above the block only: nothing is cut.
    let r = request(
        at,
        "POST",
        "/api/program?name=p.nc",
        &[],
        b"G90 G00 X30. Y30. Z50.\nX-5.\nM30\n",
    )
    .await;
    assert_eq!(r.status, 200);
    let t0 = std::time::Instant::now();
    while !get(at, "/api/state").await.json()["path"]["part"]
        .as_bool()
        .unwrap()
    {
        assert!(t0.elapsed().as_secs() < 60, "no part");
        tokio::time::sleep(std::time::Duration::from_millis(50)).await;
    }
    let r = get(at, "/api/part.stl").await;
    assert_eq!(r.status, 200);
    assert_eq!(r.header("content-type"), Some("model/stl"));
    let c = kerf_sim::stl::check(&r.body).expect("a binary STL");
    // The whole block, 20 x 20 x 10 mm, closed.
    assert_eq!(c.bad_edges, 0);
    assert!(
        (c.volume - 4000.0).abs() < 1e-6 * 4000.0,
        "volume {}",
        c.volume
    );
}
