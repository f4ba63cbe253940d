//! The offset pages as one JSON document, in the `--offsets` format of
//! docs/formats.md ("Offsets"): `GET`/`PUT /api/offsets`.
//!
//! ```json
//! {"g54": {"x": -400.0, "y": -250.0, "z": -250.0, "c": 0.0},
//!  "h": {"1": 50.0}, "h_wear": {"1": -0.02}, "d": {"8": 5.0}, "d_wear": {},
//!  "tool": {"2": {"x": 0.75, "z": -0.93, "r": 0.4, "tip": 3,
//!                 "wear_x": 0.0, "wear_z": 0.0, "wear_r": 0.0}}}
//! ```
//!
//! Mills have the `h`/`d` pages, lathes `tool` (X as on the offset page:
//! a diameter on diameter programming). Only entries that are not zero are
//! listed. A PUT applies all of the document or none of it.

use serde_json::{json, Map, Value};

use super::command::{Op, Refusal};
use super::offset_error::OffsetError;
use super::pages::OffsetWrite;
use super::persist::Part;
use super::Runtime;

const WORK: [&str; 6] = ["g54", "g55", "g56", "g57", "g58", "g59"];

impl Runtime {
    /// The offset pages as a JSON document.
    pub fn offsets_document(&self) -> Value {
        let mut doc = Map::new();
        for (i, name) in WORK.iter().enumerate() {
            let p = self.work_offset(i).unwrap_or_default();
            let axes: Map<String, Value> = self
                .axes()
                .into_iter()
                .map(|a| (a.name().to_string(), json!(p[a as usize])))
                .collect();
            doc.insert(name.to_string(), Value::Object(axes));
        }
        let t = self.interp.offsets();
        if self.profile.kind == kerf_interp::MachineKind::Lathe {
            let xs = if self.interp.diameter_programming() {
                2.0
            } else {
                1.0
            };
            let mut tools = Map::new();
            for n in 1..=t.count() {
                let e = t.lathe(n);
                let all = [e.x, e.z, e.r, e.wear_x, e.wear_z, e.wear_r, e.tip as f64];
                if all.iter().any(|v| *v != 0.0) {
                    tools.insert(
                        n.to_string(),
                        json!({"x": e.x * xs, "z": e.z, "r": e.r, "tip": e.tip,
                               "wear_x": e.wear_x * xs, "wear_z": e.wear_z, "wear_r": e.wear_r}),
                    );
                }
            }
            doc.insert("tool".into(), Value::Object(tools));
        } else {
            for (page, h, wear) in [
                ("h", true, false),
                ("h_wear", true, true),
                ("d", false, false),
                ("d_wear", false, true),
            ] {
                let mut m = Map::new();
                for n in 1..=t.count() {
                    let e = if h { t.h_entry(n) } else { t.d_entry(n) };
                    let v = e.map(|e| if wear { e.wear } else { e.geom }).unwrap_or(0.0);
                    if v != 0.0 {
                        m.insert(n.to_string(), json!(v));
                    }
                }
                doc.insert(page.into(), Value::Object(m));
            }
        }
        Value::Object(doc)
    }

    /// Applies an offsets document (all of it or, when any entry is bad,
    /// none of it); saved to `--state` before it returns Ok.
    pub fn put_offsets_document(&mut self, doc: &Value) -> Result<(), Refusal> {
        let op = Op::WriteOffset;
        self.check(op)?;
        let writes = self
            .writes_of(doc)
            .map_err(|r| self.refuse(op, r.to_string()))?;
        for w in &writes {
            self.validate_offset(w)
                .map_err(|r| self.refuse(op, r.to_string()))?;
        }
        for w in writes {
            self.apply_offset(w);
        }
        self.save_state_now(Part::All)
            .map_err(|e| self.refuse(op, e.to_string()))
    }

    fn writes_of(&self, doc: &Value) -> Result<Vec<OffsetWrite>, OffsetError> {
        let top = doc.as_object().ok_or(OffsetError::NotADocument)?;
        let num = |v: &Value, what: &str| {
            v.as_f64()
                .ok_or_else(|| OffsetError::NotANumber(what.to_string()))
        };
        let index = |k: &str, page: &str| {
            k.parse::<usize>().map_err(|_| OffsetError::BadKey {
                page: page.to_string(),
                key: k.to_string(),
            })
        };
        let lathe = self.profile.kind == kerf_interp::MachineKind::Lathe;
        let xs = if self.interp.diameter_programming() {
            0.5
        } else {
            1.0
        };
        let mut out = Vec::new();
        for (k, v) in top {
            let page = v
                .as_object()
                .ok_or_else(|| OffsetError::PageNotObject(k.clone()))?;
            if let Some(i) = WORK.iter().position(|w| w == k) {
                for (a, x) in page {
                    out.push(OffsetWrite::Work {
                        index: i,
                        axis: a.clone(),
                        value: num(x, &format!("[{k}] {a}"))?,
                    });
                }
                continue;
            }
            match k.as_str() {
                "h" | "h_wear" | "d" | "d_wear" if !lathe => {
                    for (n, x) in page {
                        let (n, x) = (index(n, k)?, Some(num(x, &format!("[{k}] {n}"))?));
                        let (geom, wear) = if k.ends_with("_wear") {
                            (None, x)
                        } else {
                            (x, None)
                        };
                        out.push(if k.starts_with('h') {
                            OffsetWrite::H { n, geom, wear }
                        } else {
                            OffsetWrite::D { n, geom, wear }
                        });
                    }
                }
                "tool" if lathe => {
                    for (n, e) in page {
                        out.push(self.lathe_write(index(n, "tool")?, e, xs)?);
                    }
                }
                _ => return Err(OffsetError::UnknownPage(k.clone())),
            }
        }
        Ok(out)
    }

    fn lathe_write(&self, n: usize, e: &Value, xs: f64) -> Result<OffsetWrite, OffsetError> {
        let e = e.as_object().ok_or(OffsetError::ToolNotObject(n))?;
        let get = |k: &str| -> Result<Option<f64>, OffsetError> {
            e.get(k)
                .map(|v| {
                    v.as_f64().ok_or_else(|| OffsetError::ToolNotANumber {
                        n,
                        key: k.to_string(),
                    })
                })
                .transpose()
        };
        for k in e.keys() {
            if !["x", "z", "r", "tip", "wear_x", "wear_z", "wear_r"].contains(&k.as_str()) {
                return Err(OffsetError::ToolUnknownField { n, key: k.clone() });
            }
        }
        let tip = match get("tip")? {
            Some(t) if t.fract() == 0.0 && (0.0..=9.0).contains(&t) => Some(t as u8),
            Some(t) => return Err(OffsetError::ToolTip { n, tip: t }),
            None => None,
        };
        Ok(OffsetWrite::Lathe {
            n,
            x: get("x")?.map(|x| x * xs),
            z: get("z")?,
            r: get("r")?,
            tip,
            wear_x: get("wear_x")?.map(|x| x * xs),
            wear_z: get("wear_z")?,
            wear_r: get("wear_r")?,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rt(name: &str) -> Runtime {
        Runtime::for_machine(name).unwrap()
    }

    #[test]
    fn document_round_trip_and_all_or_nothing() {
        let mut r = rt("hx-mc");
        let doc = json!({"g55": {"x": -100.0}, "h": {"1": 50.0}, "d_wear": {"8": 0.01}});
        r.put_offsets_document(&doc).unwrap();
        let got = r.offsets_document();
        assert_eq!(got["h"]["1"], 50.0);
        assert_eq!(got["d_wear"]["8"], 0.01);
        assert_eq!(got["g55"]["x"], -100.0);
        // One bad entry: nothing applied.
        let bad = json!({"h": {"2": 7.0, "9999": 1.0}});
        assert!(r.put_offsets_document(&bad).is_err());
        assert_eq!(r.offsets_document()["h"].get("2"), None);
        assert!(r.put_offsets_document(&json!({"tool": {}})).is_err());
    }

    #[test]
    fn lathe_x_is_a_diameter_on_the_page() {
        let mut r = rt("puma-lathe");
        r.put_offsets_document(&json!({"tool": {"2": {"x": 1.5, "z": -0.9, "tip": 3}}}))
            .unwrap();
        assert_eq!(r.interp().offsets().lathe(2).x, 0.75);
        assert_eq!(r.offsets_document()["tool"]["2"]["x"], 1.5);
    }
}
