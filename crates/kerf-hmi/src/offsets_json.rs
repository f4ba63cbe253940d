//! The offset memory in the `--offsets` format of docs/formats.md, as
//! JSON: read from the runtime, and a PUT body checked whole and turned
//! into the runtime's offset writes before any is made.
//!
//! ```json
//! {"g54": {"x": -400.0, "y": -250.0, "z": -250.0},
//!  "h": {"1": 50.0}, "h_wear": {"1": -0.02}, "d": {"8": 5.0}, "d_wear": {},
//!  "tool": {"2": {"x": 0.75, "z": -0.93, "r": 0.4, "tip": 3,
//!                 "wear_x": 0.0, "wear_z": 0.0, "wear_r": 0.0}}}
//! ```
//!
//! Lathe `x` and `wear_x` are as on the offset page: a diameter on a
//! control that programs X as a diameter (stored as a radius).

use kerf_control::runtime::{OffsetWrite, Runtime};
use serde_json::{json, Map, Value};

const SYSTEMS: [&str; 6] = ["g54", "g55", "g56", "g57", "g58", "g59"];
const LATHE_FIELDS: [&str; 7] = ["x", "z", "r", "tip", "wear_x", "wear_z", "wear_r"];

/// Every work system, and every tool offset entry that is not all zero.
pub fn read(rt: &Runtime, lathe: bool) -> Value {
    let mut top = Map::new();
    let axes = rt.axes();
    for (i, g) in SYSTEMS.iter().enumerate() {
        if let Some(p) = rt.work_offset(i) {
            let m: Map<String, Value> = axes
                .iter()
                .map(|a| (a.name().to_string(), json!(p[*a as usize])))
                .collect();
            top.insert(g.to_string(), Value::Object(m));
        }
    }
    let it = rt.interp();
    let o = it.offsets();
    if lathe {
        let xs = if it.diameter_programming() { 2.0 } else { 1.0 };
        let mut tools = Map::new();
        for n in 1..=o.count() {
            let e = o.lathe(n);
            let vals = [
                e.x * xs,
                e.z,
                e.r,
                e.tip as f64,
                e.wear_x * xs,
                e.wear_z,
                e.wear_r,
            ];
            if vals.iter().any(|v| *v != 0.0) {
                let m: Map<String, Value> = LATHE_FIELDS
                    .iter()
                    .zip(vals)
                    .map(|(k, v)| (k.to_string(), json!(v)))
                    .collect();
                tools.insert(n.to_string(), Value::Object(m));
            }
        }
        top.insert("tool".into(), Value::Object(tools));
    } else {
        let mut pages: [Map<String, Value>; 4] = Default::default();
        for n in 1..=o.count() {
            for (k, e) in [(0, o.h_entry(n)), (2, o.d_entry(n))] {
                if let Some(e) = e {
                    if e.geom != 0.0 {
                        pages[k].insert(n.to_string(), json!(e.geom));
                    }
                    if e.wear != 0.0 {
                        pages[k + 1].insert(n.to_string(), json!(e.wear));
                    }
                }
            }
        }
        for (name, p) in ["h", "h_wear", "d", "d_wear"].iter().zip(pages) {
            top.insert(name.to_string(), Value::Object(p));
        }
    }
    Value::Object(top)
}

fn number(v: &Value, what: &str) -> Result<f64, String> {
    v.as_f64()
        .filter(|f| f.is_finite())
        .ok_or_else(|| format!("offsets: {what} must be a number"))
}

fn table<'a>(v: &'a Value, what: &str) -> Result<&'a Map<String, Value>, String> {
    v.as_object()
        .ok_or_else(|| format!("offsets: {what} must be an object"))
}

fn offset_no(k: &str, page: &str) -> Result<usize, String> {
    k.parse::<usize>()
        .ok()
        .filter(|n| *n >= 1)
        .ok_or_else(|| format!("offsets: {page} key '{k}' is not an offset number"))
}

/// The writes a PUT body asks for, in order; any error in the body is
/// found before the first write. `axes` are (runtime key, name) pairs.
/// `diameter`: lathe X values are diameters (halved into the radius kept).
pub fn writes(
    v: &Value,
    lathe: bool,
    diameter: bool,
    axes: &[(String, String)],
) -> Result<Vec<OffsetWrite>, String> {
    let mut out = Vec::new();
    for (k, t) in table(v, "the body")? {
        let key = k.to_ascii_lowercase();
        let t = table(t, &format!("'{k}'"))?;
        if let Some(index) = SYSTEMS.iter().position(|g| *g == key) {
            for (a, x) in t {
                let a = a.to_ascii_lowercase();
                if !axes.iter().any(|(key, _)| *key == a) {
                    return Err(format!(
                        "offsets: {k} names axis '{a}' the machine does not have"
                    ));
                }
                let value = number(x, &format!("{k}.{a}"))?;
                out.push(OffsetWrite::Work {
                    index,
                    axis: a,
                    value,
                });
            }
            continue;
        }
        match key.as_str() {
            "h" | "h_wear" | "d" | "d_wear" if !lathe => {
                for (n, x) in t {
                    let n = offset_no(n, &key)?;
                    let x = number(x, &format!("{key}.{n}"))?;
                    let (geom, wear) = if key.ends_with("_wear") { (None, Some(x)) } else { (Some(x), None) };
                    out.push(if key.starts_with('h') {
                        OffsetWrite::H { n, geom, wear }
                    } else {
                        OffsetWrite::D { n, geom, wear }
                    });
                }
            }
            "tool" if lathe => {
                for (n, e) in t {
                    let n = offset_no(n, "tool")?;
                    out.push(lathe_write(n, table(e, &format!("tool.{n}"))?, diameter)?);
                }
            }
            "fixture" => {
                return Err("offsets: fixture offsets are set by the program (G10) or --offsets, not from the page".into())
            }
            _ => {
                let tables = if lathe { "g54 … g59, tool" } else { "g54 … g59, h, h_wear, d, d_wear" };
                return Err(format!("offsets: unknown table '{k}' on this machine ({tables})"));
            }
        }
    }
    Ok(out)
}

fn lathe_write(n: usize, t: &Map<String, Value>, diameter: bool) -> Result<OffsetWrite, String> {
    let mut f: [Option<f64>; 7] = [None; 7];
    for (k, v) in t {
        let Some(i) = LATHE_FIELDS.iter().position(|x| *x == k.as_str()) else {
            return Err(format!(
                "offsets: tool.{n}.{k}: unknown field (x, z, r, tip, wear_x, wear_z, wear_r)"
            ));
        };
        f[i] = Some(number(v, &format!("tool.{n}.{k}"))?);
    }
    let tip = match f[3] {
        None => None,
        Some(t) if t.fract() == 0.0 && (0.0..=9.0).contains(&t) => Some(t as u8),
        Some(t) => return Err(format!("offsets: tool.{n}.tip {t}: tip directions are 0-9")),
    };
    let xs = if diameter { 0.5 } else { 1.0 };
    Ok(OffsetWrite::Lathe {
        n,
        x: f[0].map(|x| x * xs),
        z: f[1],
        r: f[2],
        tip,
        wear_x: f[4].map(|x| x * xs),
        wear_z: f[5],
        wear_r: f[6],
    })
}
