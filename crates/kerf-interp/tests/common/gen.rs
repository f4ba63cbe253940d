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
