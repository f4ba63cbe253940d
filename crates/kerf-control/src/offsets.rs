//! `--offsets FILE`: work offsets and tool offset memory in TOML
//! (docs/formats.md "Offsets"):
//!
//! ```toml
//! [g54]          # machine coordinates of the G54 work zero
//! x = -400.0
//! y = -250.0
//! z = -250.0
//!
//! [h]            # tool length offsets (geometry), mm
//! 1 = 50.0
//! [h_wear]
//! 1 = -0.02
//! [d]            # cutter radius offsets (geometry), mm
//! 8 = 5.0
//! [d_wear]
//! 8 = 0.01
//!
//! [tool.2]       # lathe tool offset 02
//! x = 0.75       # as on the offset page: a diameter on diameter programming
//! z = -0.93
//! r = 0.4
//! tip = 3
//!
//! [fixture.2]    # Hurco fixture offset E2: machine coordinates of its
//! z = -300.0     # part zero, mm (X a radius), like [g54] (= E1)
//! ```

use std::path::Path;

use kerf_interp::machine::{axis_by_name, AxisMap};
use kerf_interp::offsets::MillOffset;
use kerf_interp::{Interp, Profile};
use toml::{Table, Value};

/// Loads the file into the interpreter's work offsets and offset memory.
pub fn load(path: &Path, it: &mut Interp) -> Result<(), String> {
    let p = path.display();
    let text = std::fs::read_to_string(path).map_err(|e| format!("{p}: {e}"))?;
    let top: Table = toml::from_str(&text).map_err(|e| format!("{p}: {e}"))?;
    for (k, v) in &top {
        let key = k.to_ascii_lowercase();
        let Value::Table(t) = v else {
            return Err(format!("{p}: '{k}' must be a table"));
        };
        match key.as_str() {
            "h" | "h_wear" | "d" | "d_wear" => {
                mill_page(&key, t, it).map_err(|e| format!("{p}: {e}"))?
            }
            "tool" => {
                for (n, e) in t {
                    lathe_entry(n, e, it).map_err(|e| format!("{p}: {e}"))?;
                }
            }
            "fixture" => {
                for (n, e) in t {
                    fixture_entry(n, e, it).map_err(|e| format!("{p}: {e}"))?;
                }
            }
            _ => work_system(&key, v, it).map_err(|e| format!("{p}: {e}"))?,
        }
    }
    Ok(())
}

fn number(v: &Value, what: &str) -> Result<f64, String> {
    match v {
        Value::Float(f) => Ok(*f),
        Value::Integer(i) => Ok(*i as f64),
        _ => Err(format!("{what} must be a number")),
    }
}

fn offset_number(n: &str, page: &str, it: &Interp) -> Result<usize, String> {
    let max = it.offsets().count();
    match n.parse::<usize>() {
        Ok(i) if (1..=max).contains(&i) => Ok(i),
        _ => Err(format!(
            "[{page}] key '{n}' is not an offset number (1-{max} on this machine)"
        )),
    }
}

fn mill_page(page: &str, t: &Table, it: &mut Interp) -> Result<(), String> {
    for (n, v) in t {
        let i = offset_number(n, page, it)?;
        let x = number(v, &format!("[{page}] {n}"))?;
        let table = it.offsets_mut();
        let e: &mut MillOffset = if page.starts_with('h') {
            table.h_mut(i)
        } else {
            table.d_mut(i)
        }
        .expect("offset number checked");
        if page.ends_with("_wear") {
            e.wear = x;
        } else {
            e.geom = x;
        }
    }
    Ok(())
}

fn lathe_entry(n: &str, v: &Value, it: &mut Interp) -> Result<(), String> {
    let i = offset_number(n, "tool", it)?;
    let Value::Table(t) = v else {
        return Err(format!("[tool.{n}] must be a table"));
    };
    // X values are written as on the offset page: a diameter on a control
    // that programs X as a diameter; stored as a radius.
    let xs = if it.diameter_programming() { 0.5 } else { 1.0 };
    let e = it
        .offsets_mut()
        .lathe_mut(i)
        .expect("offset number checked");
    for (k, v) in t {
        let what = format!("[tool.{n}] {k}");
        let x = number(v, &what)?;
        match k.as_str() {
            "x" => e.x = x * xs,
            "z" => e.z = x,
            "r" => e.r = x,
            "wear_x" => e.wear_x = x * xs,
            "wear_z" => e.wear_z = x,
            "wear_r" => e.wear_r = x,
            "tip" if x.fract() == 0.0 && (0.0..=9.0).contains(&x) => e.tip = x as u8,
            "tip" => return Err(format!("{what}: tip direction is 0-9")),
            _ => {
                return Err(format!(
                    "{what}: unknown field (x, z, r, tip, wear_x, wear_z, wear_r)"
                ))
            }
        }
    }
    Ok(())
}

fn work_system(k: &str, v: &Value, it: &mut Interp) -> Result<(), String> {
    let idx = match k {
        "g54" => 0,
        "g55" => 1,
        "g56" => 2,
        "g57" => 3,
        "g58" => 4,
        "g59" => 5,
        other => {
            return Err(format!(
                "unknown table '{other}' (g54 … g59, h, h_wear, d, d_wear, tool.N, fixture.N)"
            ))
        }
    };
    let axes: AxisMap = v.clone().try_into().map_err(|e| format!("[{k}]: {e}"))?;
    for a in axes.keys() {
        match axis_by_name(a) {
            Some(ax) if it.profile().has_axis(ax) => {}
            _ => return Err(format!("[{k}] names axis '{a}' the machine does not have")),
        }
    }
    it.set_work_offset(idx, Profile::pos_of(&axes));
    Ok(())
}

/// `[fixture.N]`: Hurco fixture offset E`N` (1-9999), machine coordinates
/// of its part zero in mm, X as a radius ([g54] is E1).
fn fixture_entry(n: &str, v: &Value, it: &mut Interp) -> Result<(), String> {
    let i: u32 = n
        .parse()
        .map_err(|_| format!("[fixture.{n}]: not a fixture offset number (1-9999)"))?;
    let axes: AxisMap = v
        .clone()
        .try_into()
        .map_err(|e| format!("[fixture.{n}]: {e}"))?;
    for a in axes.keys() {
        match axis_by_name(a) {
            Some(ax) if it.profile().has_axis(ax) => {}
            _ => {
                return Err(format!(
                    "[fixture.{n}] names axis '{a}' the machine does not have"
                ))
            }
        }
    }
    if !it.set_fixture_offset(i, Profile::pos_of(&axes)) {
        return Err(format!(
            "[fixture.{n}]: not a fixture offset number (1-9999)"
        ));
    }
    Ok(())
}
