//! `--set KEY=VALUE`: operator switches and control parameters.

use kerf_interp::{Profile, Settings};

/// Why a `--set` list was refused.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SettingsError {
    /// A key that is no setting, switch or profile parameter (the caller
    /// may offer the closest of [`KEYS`]).
    #[error("--set {key}: unknown key (see docs/formats.md)")]
    UnknownKey {
        /// The key as written.
        key: String,
    },
    /// A known key with a value it does not take, or no `=` at all.
    #[error("--set {setting}: {expected}")]
    BadValue {
        /// `KEY=VALUE` as written, or the key alone when the key is at
        /// fault.
        setting: String,
        /// What the key takes.
        expected: String,
    },
}

/// A [`SettingsError::BadValue`].
fn bad(setting: impl Into<String>, expected: impl Into<String>) -> SettingsError {
    SettingsError::BadValue {
        setting: setting.into(),
        expected: expected.into(),
    }
}

fn on_off(key: &str, v: &str) -> Result<bool, SettingsError> {
    match v.to_ascii_lowercase().as_str() {
        "on" | "1" | "true" | "yes" => Ok(true),
        "off" | "0" | "false" | "no" => Ok(false),
        _ => Err(bad(format!("{key}={v}"), "expected on or off")),
    }
}

/// The `--set` keys that are names, not families (`in.N`, `skip.AXIS`,
/// `probe.AXIS`, `PI n`, profile parameters): what "did you mean" offers.
/// A test checks that `parse` accepts every one of them.
pub const KEYS: &[&str] = &[
    "block_skip",
    "immediate_offsets",
    "optional_stop",
    "single_block",
    "dry_run",
    "main_passes",
    "calculator_decimal",
    "max_blocks",
    "probe.time",
    "probe.x",
    "probe.z",
    "arc_tolerance_mm",
    "max_jumps",
    "max_repeat_blocks",
    "peck_clearance_mm",
    "optional_format",
];

/// Parses the `--set` list; parameters are written into the profile.
pub fn parse(sets: &[String], profile: &mut Profile) -> Result<Settings, SettingsError> {
    let mut s = Settings {
        max_blocks: 0,
        ..Settings::default()
    };
    for kv in sets {
        let Some((k, v)) = kv.split_once('=') else {
            return Err(bad(kv, "expected KEY=VALUE"));
        };
        let (k, v) = (k.trim(), v.trim());
        match k {
            "block_skip" => {
                s.block_skip = 0;
                for lv in v.split(',').map(str::trim).filter(|x| !x.is_empty()) {
                    if lv == "off" {
                        continue;
                    }
                    // 0-9, and 10 (000 §2.3.3: "/0 ~ /10" on the HX).
                    let n: u16 = lv
                        .parse()
                        .map_err(|_| bad(format!("block_skip={v}"), "levels are 0-10"))?;
                    if n > 10 {
                        return Err(bad(format!("block_skip={v}"), "levels are 0-10"));
                    }
                    s.block_skip |= 1 << n;
                }
            }
            "immediate_offsets" | "tools.immediate_offsets" => {
                profile.tools.immediate_offsets = on_off(k, v)?
            }
            "optional_stop" if v.eq_ignore_ascii_case("once") => {
                s.optional_stop = true;
                s.optional_stop_once = true;
            }
            "optional_stop" => s.optional_stop = on_off(k, v)?,
            "single_block" => s.single_block = on_off(k, v)?,
            "dry_run" => s.dry_run = on_off(k, v)?,
            "main_passes" => {
                s.main_passes = v
                    .parse()
                    .map_err(|_| bad(format!("main_passes={v}"), "expected a count"))?
            }
            "calculator_decimal" => profile.calculator_decimal = on_off(k, v)?,
            "max_blocks" => {
                s.max_blocks = v
                    .parse()
                    .map_err(|_| bad(format!("max_blocks={v}"), "expected a count"))?
            }
            _ if k.starts_with("in.") => set_input(&mut s.inputs, k, v)?,
            _ if k.starts_with("skip") && k.contains('.') => set_skip(&mut s.skip, k, v)?,
            "probe.time" => s.clock = clock(v)?,
            _ if k.starts_with("probe.") => {
                let slot = match &k[6..] {
                    "x" | "X" => 0,
                    "z" | "Z" => 2,
                    _ => return Err(bad(k, "the probe surface is probe.x or probe.z")),
                };
                let val: f64 = v
                    .parse()
                    .map_err(|_| bad(format!("{k}={v}"), "expected a number"))?;
                s.probe[slot] = Some(val);
            }
            _ if k.starts_with("PI ")
                || k.starts_with("PM ")
                || k.starts_with("PI")
                || k.starts_with("PM")
                || profile.params.contains_key(k)
                || k.starts_with("probe_")
                || matches!(
                    k,
                    "arc_tolerance_mm"
                        | "max_jumps"
                        | "max_repeat_blocks"
                        | "peck_clearance_mm"
                        | "optional_format"
                ) =>
            {
                let val: f64 = v
                    .parse()
                    .map_err(|_| bad(format!("{k}={v}"), "expected a number"))?;
                let name = normalise_param(k);
                profile.params.insert(name, val);
            }
            _ => return Err(SettingsError::UnknownKey { key: k.to_string() }),
        }
    }
    Ok(s)
}

/// `probe.time=hh:mm:ss`: seconds after midnight.
fn clock(v: &str) -> Result<u32, SettingsError> {
    let wrong = || bad(format!("probe.time={v}"), "expected hh:mm:ss");
    let parts: Vec<u32> = v
        .split(':')
        .map(|p| p.trim().parse::<u32>().map_err(|_| wrong()))
        .collect::<Result<_, _>>()?;
    match parts.as_slice() {
        [h, m, s] if *h < 24 && *m < 60 && *s < 60 => Ok(h * 3600 + m * 60 + s),
        _ => Err(wrong()),
    }
}

/// `skip.AXIS=V` / `skipN.AXIS=V` (N = 1-4): where the simulated skip
/// signal comes during G31/G37 (N: G31.N/G37.N), as the program coordinate
/// of that axis.
fn set_skip(skip: &mut [[Option<f64>; 6]; 5], k: &str, v: &str) -> Result<(), SettingsError> {
    let (sig, ax) = k.split_once('.').expect("has a dot");
    let n: usize = match &sig[4..] {
        "" => 0,
        d => d
            .parse()
            .ok()
            .filter(|n| (1..=4).contains(n))
            .ok_or_else(|| bad(k, "skip signals are skip, skip1 … skip4"))?,
    };
    let slot = match ax {
        "x" | "X" => 0,
        "y" | "Y" => 1,
        "z" | "Z" => 2,
        "a" | "A" => 3,
        "b" | "B" => 4,
        "c" | "C" => 5,
        _ => return Err(bad(k, "expected an axis x, y, z, a, b or c")),
    };
    let val: f64 = v
        .parse()
        .map_err(|_| bad(format!("{k}={v}"), "expected a number"))?;
    skip[n][slot] = Some(val);
    Ok(())
}

/// `in.N=V`: interface input signals read by macros. HX: `in.7000` …
/// `in.7031` one signal (0/1), `in.7032` … `in.7035` a 32-bit word
/// (UI000-UI031 … UI300-UI331). Fanuc: `in.1000` … `in.1015` one signal,
/// `in.1032` the 16-bit word.
fn set_input(inputs: &mut [u32; 4], k: &str, v: &str) -> Result<(), SettingsError> {
    let n: u32 = k[3..].parse().map_err(|_| bad(k, "expected in.NUMBER"))?;
    let val: f64 = v
        .parse()
        .map_err(|_| bad(format!("{k}={v}"), "expected a number"))?;
    let flag = || match val {
        0.0 => Ok(false),
        1.0 => Ok(true),
        _ => Err(bad(format!("{k}={v}"), "a signal is 0 or 1")),
    };
    let word = |max: f64| {
        if val >= 0.0 && val.fract() == 0.0 && val <= max {
            Ok(val as u32)
        } else {
            Err(bad(
                format!("{k}={v}"),
                format!("expected a whole number 0-{max}"),
            ))
        }
    };
    match n {
        7000..=7031 | 1000..=1015 => {
            let b = if n >= 7000 { n - 7000 } else { n - 1000 };
            if flag()? {
                inputs[0] |= 1 << b;
            } else {
                inputs[0] &= !(1 << b);
            }
        }
        7032..=7035 => inputs[(n - 7032) as usize] = word(u32::MAX as f64)?,
        1032 => inputs[0] = (inputs[0] & !0xffff) | word(65535.0)?,
        _ => {
            return Err(bad(
                k,
                "inputs are in.7000-in.7035 (HX) or in.1000-in.1015, in.1032 (Fanuc)",
            ))
        }
    }
    Ok(())
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
    fn refusals_say_whether_the_key_or_the_value_is_wrong() {
        let mut p = Profile::builtin("hx-mc").unwrap();
        let unknown = parse(&["singel_block=on".into()], &mut p).unwrap_err();
        assert_eq!(
            unknown,
            SettingsError::UnknownKey {
                key: "singel_block".into()
            }
        );
        assert_eq!(
            unknown.to_string(),
            "--set singel_block: unknown key (see docs/formats.md)"
        );
        let bad = parse(&["single_block=maybe".into()], &mut p).unwrap_err();
        assert_eq!(
            bad,
            SettingsError::BadValue {
                setting: "single_block=maybe".into(),
                expected: "expected on or off".into()
            }
        );
        assert_eq!(
            bad.to_string(),
            "--set single_block=maybe: expected on or off"
        );
        let no_value = parse(&["dry_run".into()], &mut p).unwrap_err();
        assert_eq!(no_value.to_string(), "--set dry_run: expected KEY=VALUE");
    }

    #[test]
    fn every_listed_key_is_accepted() {
        for key in KEYS {
            let value = match *key {
                "block_skip" => "1",
                "probe.time" => "12:00:00",
                "main_passes" | "max_blocks" | "max_jumps" | "max_repeat_blocks" => "2",
                "probe.x" | "probe.z" | "arc_tolerance_mm" | "peck_clearance_mm" => "0.5",
                "optional_format" => "1",
                _ => "on",
            };
            let mut p = Profile::builtin("hx-mc").unwrap();
            let r = parse(&[format!("{key}={value}")], &mut p);
            assert!(r.is_ok(), "{key}={value}: {:?}", r.err());
        }
    }

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
        let s = parse(
            &["in.7000=1".into(), "in.7031=1".into(), "in.7033=5".into()],
            &mut p,
        )
        .unwrap();
        assert_eq!(s.inputs, [1 | (1 << 31), 5, 0, 0]);
        let s = parse(&["in.1032=3".into(), "in.1015=1".into()], &mut p).unwrap();
        assert_eq!(s.inputs[0], 3 | (1 << 15));
        assert!(parse(&["in.7000=2".into()], &mut p).is_err());
        assert!(parse(&["in.7036=1".into()], &mut p).is_err());
        assert!(parse(&["block_skip=12".into()], &mut p).is_err());
        let s = parse(&["block_skip=10".into()], &mut p).unwrap();
        assert_eq!(s.block_skip, 1 << 10);
    }

    #[test]
    fn probe_surface_and_clock() {
        let mut p = Profile::builtin("hurco-lathe").unwrap();
        let s = parse(
            &[
                "probe.x=2.5".into(),
                "probe.Z=7.5".into(),
                "probe.time=10:15:30".into(),
                "probe_feed=250".into(),
            ],
            &mut p,
        )
        .unwrap();
        assert_eq!(s.probe[0], Some(2.5));
        assert_eq!(s.probe[2], Some(7.5));
        // 10 h 15 min 30 s = 36000 + 900 + 30 s.
        assert_eq!(s.clock, 36_930);
        assert_eq!(p.params.get("probe_feed"), Some(&250.0));
        assert!(parse(&["probe.y=1".into()], &mut p).is_err());
        // Table 16 activation as a switch.
        assert!(p.tools.immediate_offsets);
        parse(&["immediate_offsets=off".into()], &mut p).unwrap();
        assert!(!p.tools.immediate_offsets);
        assert!(parse(&["probe.time=25:00:00".into()], &mut p).is_err());
    }

    /// The calculator-type decimal point and the main-program M99 passes
    /// are `--set` keys (issue 15).
    #[test]
    fn calculator_decimal_and_main_passes() {
        let mut p = Profile::builtin("puma-lathe").unwrap();
        assert!(!p.calculator_decimal);
        let s = parse(
            &["calculator_decimal=on".into(), "main_passes=3".into()],
            &mut p,
        )
        .unwrap();
        assert!(p.calculator_decimal);
        assert_eq!(s.main_passes, 3);
        parse(&["calculator_decimal=off".into()], &mut p).unwrap();
        assert!(!p.calculator_decimal);
        assert!(parse(&["calculator_decimal=maybe".into()], &mut p).is_err());
        assert!(parse(&["main_passes=-1".into()], &mut p).is_err());
        // A profile parameter of the PUMA.
        parse(&["tape_format_10_11=0".into()], &mut p).unwrap();
        assert_eq!(p.params["tape_format_10_11"], 0.0);
    }

    #[test]
    fn skip_signals() {
        let mut p = Profile::builtin("hx-mc").unwrap();
        let s = parse(&["skip.z=-12.5".into(), "skip3.X=40".into()], &mut p).unwrap();
        assert_eq!(s.skip[0][2], Some(-12.5));
        assert_eq!(s.skip[3][0], Some(40.0));
        assert_eq!(s.skip[1], [None; 6]);
        assert!(parse(&["skip5.z=1".into()], &mut p).is_err());
        assert!(parse(&["skip.q=1".into()], &mut p).is_err());
        assert!(parse(&["skip.z=deep".into()], &mut p).is_err());
    }
}
