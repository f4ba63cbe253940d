//! `--set KEY=VALUE`: operator switches and control parameters.

use kerf_interp::{Profile, Settings};

fn on_off(key: &str, v: &str) -> Result<bool, String> {
    match v.to_ascii_lowercase().as_str() {
        "on" | "1" | "true" | "yes" => Ok(true),
        "off" | "0" | "false" | "no" => Ok(false),
        _ => Err(format!("--set {key}={v}: expected on or off")),
    }
}

/// Parses the `--set` list; parameters are written into the profile.
pub fn parse(sets: &[String], profile: &mut Profile) -> Result<Settings, String> {
    let mut s = Settings {
        max_blocks: 0,
        ..Settings::default()
    };
    for kv in sets {
        let Some((k, v)) = kv.split_once('=') else {
            return Err(format!("--set {kv}: expected KEY=VALUE"));
        };
        let (k, v) = (k.trim(), v.trim());
        match k {
            "block_skip" => {
                s.block_skip = 0;
                for lv in v.split(',').map(str::trim).filter(|x| !x.is_empty()) {
                    if lv == "off" {
                        continue;
                    }
                    let n: u16 = lv
                        .parse()
                        .map_err(|_| format!("--set block_skip={v}: levels are 0-9"))?;
                    if n > 9 {
                        return Err(format!("--set block_skip={v}: levels are 0-9"));
                    }
                    s.block_skip |= 1 << n;
                }
            }
            "optional_stop" => s.optional_stop = on_off(k, v)?,
            "single_block" => s.single_block = on_off(k, v)?,
            "dry_run" => s.dry_run = on_off(k, v)?,
            "max_blocks" => {
                s.max_blocks = v
                    .parse()
                    .map_err(|_| format!("--set max_blocks={v}: expected a count"))?
            }
            _ if k.starts_with("PI ")
                || k.starts_with("PM ")
                || k.starts_with("PI")
                || k.starts_with("PM")
                || profile.params.contains_key(k)
                || matches!(k, "arc_tolerance_mm" | "max_jumps" | "max_repeat_blocks") =>
            {
                let val: f64 = v
                    .parse()
                    .map_err(|_| format!("--set {k}={v}: expected a number"))?;
                let name = normalise_param(k);
                profile.params.insert(name, val);
            }
            _ => return Err(format!("--set {k}: unknown key (see docs/formats.md)")),
        }
    }
    Ok(s)
}

/// `PI144` and `PI 144` are the same parameter.
fn normalise_param(k: &str) -> String {
    for p in ["PI", "PM"] {
        if let Some(rest) = k.strip_prefix(p) {
            let rest = rest.trim();
            if !rest.is_empty() && rest.chars().all(|c| c.is_ascii_digit()) {
                return format!("{p} {rest}");
            }
        }
    }
    k.to_string()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn switches_and_params() {
        let mut p = Profile::builtin("hx-mc").unwrap();
        let s = parse(
            &[
                "block_skip=1,9".into(),
                "optional_stop=on".into(),
                "PI144=1".into(),
            ],
            &mut p,
        )
        .unwrap();
        assert_eq!(s.block_skip, (1 << 1) | (1 << 9));
        assert!(s.optional_stop);
        assert_eq!(p.params["PI 144"], 1.0);
        assert!(parse(&["nonsense=1".into()], &mut p).is_err());
        assert!(parse(&["block_skip=12".into()], &mut p).is_err());
    }
}
