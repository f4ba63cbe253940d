//! Property test of the API's JSON input: any body to the command and
//! offsets endpoints gets 200, 400, 409 or 413 with a JSON error, never a
//! 5xx, a hang or a dead server. Bounded: 256 cases per property.

mod common;

use common::double::Double;
use common::http::{get, request, start};
use proptest::prelude::*;

fn json_value() -> impl Strategy<Value = serde_json::Value> {
    let leaf = prop_oneof![
        Just(serde_json::Value::Null),
        any::<bool>().prop_map(serde_json::Value::from),
        any::<i64>().prop_map(serde_json::Value::from),
        any::<f64>()
            .prop_filter("finite", |f| f.is_finite())
            .prop_map(serde_json::Value::from),
        prop_oneof![
            Just("cycle_start".to_string()),
            Just("mode".into()),
            Just("mdi".into()),
            Just("switch".into()),
            Just("override".into()),
            Just("restart".into()),
            Just("MEM".into()),
            Just("h".into()),
            "[a-z_#0-9]{0,8}".prop_map(String::from),
        ]
        .prop_map(serde_json::Value::from),
    ];
    leaf.prop_recursive(3, 24, 6, |inner| {
        prop_oneof![
            prop::collection::vec(inner.clone(), 0..4).prop_map(serde_json::Value::from),
            prop::collection::btree_map(
                prop_oneof![
                    Just("cmd".to_string()),
                    Just("mode".into()),
                    Just("block".into()),
                    Just("line".into()),
                    Just("feed".into()),
                    Just("rapid".into()),
                    Just("block_skip".into()),
                    Just("single_block".into()),
                    Just("h".into()),
                    "[a-z0-9]{1,4}".prop_map(String::from)
                ],
                inner,
                0..4,
            )
            .prop_map(|m| serde_json::Value::Object(m.into_iter().collect())),
        ]
    })
}

fn check(status: u16, body: &[u8]) -> Result<(), TestCaseError> {
    prop_assert!(
        [200, 400, 409, 413].contains(&status),
        "status {status}: {}",
        String::from_utf8_lossy(body)
    );
    if status != 200 {
        let v: serde_json::Value =
            serde_json::from_slice(body).map_err(|e| TestCaseError::fail(e.to_string()))?;
        prop_assert!(v["error"]["message"]
            .as_str()
            .is_some_and(|m| !m.is_empty()));
    }
    Ok(())
}

fn runtime() -> tokio::runtime::Runtime {
    tokio::runtime::Builder::new_multi_thread()
        .worker_threads(2)
        .enable_all()
        .build()
        .unwrap()
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, failure_persistence: None, .. ProptestConfig::default() })]

    #[test]
    fn any_json_value_is_answered(v in json_value(), path in prop_oneof![Just("/api/command"), Just("/api/offsets")]) {
        let rt = runtime();
        rt.block_on(async {
            let at = start(Box::new(Double::new()), None).await;
            let method = if path == "/api/offsets" { "PUT" } else { "POST" };
            let r = request(at, method, path, &[], v.to_string().as_bytes()).await;
            check(r.status, &r.body)?;
            prop_assert_eq!(get(at, "/api/state").await.status, 200);
            Ok(())
        })?;
    }

    #[test]
    fn any_bytes_are_answered(b in prop::collection::vec(any::<u8>(), 0..300)) {
        let rt = runtime();
        rt.block_on(async {
            let at = start(Box::new(Double::new()), None).await;
            let r = request(at, "POST", "/api/command", &[], &b).await;
            check(r.status, &r.body)?;
            prop_assert_eq!(get(at, "/api/state").await.status, 200);
            Ok(())
        })?;
    }
}
