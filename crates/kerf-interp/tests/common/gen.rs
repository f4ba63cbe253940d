//! Program text generators shared by the property tests.

use proptest::prelude::*;

/// A coordinate as a CAM post writes it: with a point, a bare point,
/// without one (least input increment), negative, with many digits.
pub fn coord() -> impl Strategy<Value = String> {
    prop_oneof![
        (-160i32..160).prop_map(|v| format!("{:.4}", v as f64 / 8.0)),
        (-20i32..20).prop_map(|v| format!("{v}.")),
        (-20000i32..20000).prop_map(|v| v.to_string()),
        (-9i32..9).prop_map(|v| format!("{v}.123456789")),
    ]
}

/// Every step of a loaded interpreter, at most `max` (each as `{:?}`
/// followed by `note` of the interpreter after it), up to its end or
/// alarm.
pub fn trace(
    it: &mut kerf_interp::Interp,
    max: usize,
    note: impl Fn(&kerf_interp::Interp) -> String,
) -> Vec<String> {
    let mut out = Vec::new();
    for _ in 0..max {
        let s = it.step();
        let end = !matches!(s, kerf_interp::Step::Event(_));
        out.push(format!("{s:?}{}", note(it)));
        if end {
            break;
        }
    }
    out
}
