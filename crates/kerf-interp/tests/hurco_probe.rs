//! Hurco G38 turret probe cycles (002 "G38 - Turret Probe") against a
//! declared part surface (`Settings::probe`, program units as the G38
//! block writes X/Z). Positions, offsets and log lines by hand: inch
//! programs, X a diameter (G08) so radius = X/2; A, T in radius.
mod common;
use common::*;
use kerf_canon::{Canon, Feed};
use kerf_interp::{Interp, Profile, Run, Settings, Step};

fn settings(x: Option<f64>, z: Option<f64>) -> Settings {
    let mut s = Settings::default();
    s.probe[0] = x;
    s.probe[2] = z;
    s.clock = 10 * 3600 + 15 * 60 + 30;
    s
}

fn run_probe(s: Settings, text: &str) -> (Run, Interp) {
    let mut it = Interp::new(Profile::builtin("hurco-lathe").unwrap(), s);
    it.load_main(
        "t.nc",
        Box::new(std::io::Cursor::new(text.as_bytes().to_vec())),
    );
    let mut events = Vec::new();
    let mut alarm = None;
    loop {
        match it.step() {
            Step::Event(e) => events.push(e),
            Step::End => break,
            Step::Alarm(a) => {
                alarm = Some(a);
                break;
            }
        }
    }
    let blocks = it.blocks();
    (
        Run {
            events,
            alarm,
            blocks,
        },
        it,
    )
}

fn messages(r: &Run) -> Vec<String> {
    r.events
        .iter()
        .filter_map(|e| match &e.cmd {
            Canon::Message(m) => Some(m.clone()),
            _ => None,
        })
        .collect()
}

/// (line, kind, x radius in, z in, feed in/min) of every move.
fn path(r: &Run) -> Vec<(u32, &'static str, f64, f64, f64)> {
    r.events
        .iter()
        .filter_map(|e| {
            let (k, f) = match e.cmd {
                Canon::Rapid { .. } => ("rapid", 0.0),
                Canon::Feed {
                    feed: Feed::PerMin(f),
                    ..
                } => ("feed", f),
                _ => return None,
            };
            let m = e.motion().unwrap();
            Some((
                e.src.line,
                k,
                round(m.to[0] / 25.4),
                round(m.to[2] / 25.4),
                round(f / 25.4),
            ))
        })
        .collect()
}

const DATUM: &str = "G20\nH00\nG00 G40 X10 Z5\nG38 S0 X5 A.5 T.125 V20 F10\nG0 Z10\n\
G38 S0 Z7.6 A.5 T.125 V20 F10\n";

#[test]
fn datum_sample() {
    // 002 "Datum in -X and -Z example" (E01 active instead of E00, whose
    // machine-coordinate Z5 is beyond this profile's travel). Surface:
    // X4.95 (radius 2.475), Z7.55.
    // X datum from X10 (radius 5): feed at V20 to 2.5 + .5 = 3.0, at F10
    // towards 2.5 - .125; contact at 2.475; back to 5 at V20. -X offset =
    // expected - contact = 2.5 - 2.475 = .025 radius = .05 on the diameter.
    // Z datum from Z10 at X10: to 7.6 + .5 = 8.1 at V, contact 7.55 at F,
    // back to 10 at V; -Z offset 7.6 - 7.55 = .05.
    let (r, _) = run_probe(settings(Some(4.95), Some(7.55)), &format!("{DATUM}M30\n"));
    ok(&r);
    assert_eq!(
        path(&r),
        vec![
            (3, "rapid", 5.0, 5.0, 0.0),
            (4, "feed", 3.0, 5.0, 20.0),
            (4, "feed", 2.475, 5.0, 10.0),
            (4, "feed", 5.0, 5.0, 20.0),
            (5, "rapid", 5.0, 10.0, 0.0),
            (6, "feed", 5.0, 8.1, 20.0),
            (6, "feed", 5.0, 7.55, 10.0),
            (6, "feed", 5.0, 10.0, 20.0),
        ]
    );
    assert_eq!(
        messages(&r),
        vec![
            "10:15:30 Probe Datum: Probe #-1; -X Offset 0.0500 at X4.9500, Z5.0000",
            "10:15:30 Probe Datum: Probe #-1; -Z Offset 0.0500 at X10.0000, Z7.5500",
        ]
    );
}

#[test]
fn measure_and_adjust_tool_offset() {
    // After the datums (-X .025 radius, -Z .05):
    // S2 Z7.5 P14: contact 7.55 (within 7.5 ± .125), measured 7.55 + .05 =
    // 7.6 in part coordinates; machine = 7.6 + E1's Z (-400 mm =
    // -15.748031 in) = -8.148031.
    // S3 X5.1 H8: expected radius 2.55, contact 2.475, measured 2.5;
    // offset 8 X adjusted by expected - measured = +.05 radius (1.27 mm),
    // logged on the diameter: new .1, old 0.
    let (r, it) = run_probe(
        settings(Some(4.95), Some(7.55)),
        &format!(
            "{DATUM}G38 S2 Z7.5 A.5 T.125 V20 F10 P14\nG38 S3 X5.1 H8 A.5 T.125 V20 F10\nM30\n"
        ),
    );
    ok(&r);
    let m = messages(&r);
    assert_eq!(
        m[2],
        "10:15:30 Probe Measure Z: machine: -8.1480 part: 7.6000"
    );
    assert_eq!(m[3], "10:15:30 Probe Offset X: T8 new: 0.1000 old: 0.0000");
    assert!((it.offsets().lathe(8).total_x() - 1.27).abs() < 1e-9);
}

#[test]
fn set_fixture_offset_absolute_and_incremental() {
    // E00: part coordinates = machine coordinates. Surface Z-10.02.
    // S0 Z-10: -Z offset -10 - (-10.02) = .02.
    // S1 E3 Z-10 K-1: measured -10.02 + .02 = -10; absolute: E3 Z =
    // -10 + (-1) = -11.
    // S1 E3 Z-9.95 Q1: incremental: -11 + (-10 - (-9.95)) = -11.05.
    // E3 then Z1: machine Z = 1 - 11.05 = -10.05 in.
    let (r, it) = run_probe(
        settings(None, Some(-10.02)),
        "G20\nE00\nG0 X10 Z-5\nG38 S0 Z-10 A.5 T.125 V20 F10\n\
         G38 S1 E3 Z-10 K-1 A.5 T.125 V20 F10\nG38 S1 E3 Z-9.95 Q1 A.5 T.125 V20 F10\n\
         E3\nZ1\nM30\n",
    );
    ok(&r);
    assert_eq!(
        messages(&r),
        vec![
            "10:15:30 Probe Datum: Probe #-1; -Z Offset 0.0200 at X10.0000, Z-10.0200",
            "10:15:30 Probe Fixture Z: E3 new: -11.0000 old: 0.0000",
            "10:15:30 Probe Fixture Z: E3 new: -11.0500 old: -11.0000",
        ]
    );
    assert!((it.fixture_offset(3)[2] - (-11.05 * 25.4)).abs() < 1e-9);
    let last = r.events.iter().rev().find_map(|e| e.motion()).unwrap();
    assert!((last.mto[2] - (-10.05 * 25.4)).abs() < 1e-9);
}

#[test]
fn probe_faults_feed_back_then_alarm() {
    let z = |surface: Option<f64>| {
        run_probe(
            settings(None, surface),
            "G20\nG0 X10 Z10\nG38 S0 Z7.6 A.5 T.125 V20 F10\nM30\n",
        )
        .0
    };
    // No surface: probe to 7.6 - .125 = 7.475, back to 10, alarm.
    let r = z(None);
    assert_eq!(alarm(&r), ("HU-049", 3, 1));
    let p: Vec<_> = path(&r).iter().skip(1).map(|m| m.3).collect();
    assert_eq!(p, vec![8.1, 7.475, 10.0]);
    // Surface 7.9: touched after the approach point 8.1 but more than .125
    // before 7.6 (premature, outside the tolerance): stop at 7.9, back,
    // alarm.
    let r = z(Some(7.9));
    assert_eq!(alarm(&r), ("HU-049", 3, 1));
    let p: Vec<_> = path(&r).iter().skip(1).map(|m| m.3).collect();
    assert_eq!(p, vec![8.1, 7.9, 10.0]);
    // Surface 9: touched during the approach.
    let r = z(Some(9.0));
    assert_eq!(alarm(&r), ("HU-049", 3, 1));
    let p: Vec<_> = path(&r).iter().skip(1).map(|m| m.3).collect();
    assert_eq!(p, vec![9.0, 10.0]);
    // Surface beyond the far end of the tolerance: none.
    let r = z(Some(7.3));
    assert_eq!(alarm(&r), ("HU-049", 3, 1));
}

#[test]
fn probe_alarms() {
    let s = || settings(Some(4.95), Some(7.55));
    // Measuring without a datum in that direction.
    let (r, _) = run_probe(s(), "G20\nG0 X10 Z10\nG38 S2 Z7.5 A.5 T.125 V20 F10\n");
    assert_eq!(alarm(&r), ("HU-061", 3, 1));
    // Neither X nor Z; both.
    let (r, _) = run_probe(s(), "G20\nG0 X10 Z10\nG38 S0 A.5 T.125 V20 F10\n");
    assert_eq!(alarm(&r), ("HU-015", 3, 1));
    let (r, _) = run_probe(s(), "G20\nG0 X10 Z10\nG38 S0 X5 Z7 A.5 T.125 V20 F10\n");
    assert_eq!(alarm(&r), ("HU-061", 3, 11));
    // A/F/T/V neither in the block nor in the profile.
    let (r, _) = run_probe(s(), "G20\nG0 X10 Z10\nG38 S0 X5\n");
    assert_eq!(alarm(&r), ("HU-015", 3, 1));
    // S1 without E; S3 without H.
    let (r, _) = run_probe(s(), "G20\nG0 X10 Z10\nG38 S1 Z7.6 A.5 T.125 V20 F10\n");
    assert_eq!(alarm(&r), ("HU-015", 3, 1));
    let (r, _) = run_probe(s(), "G20\nG0 X10 Z10\nG38 S3 Z7.6 A.5 T.125 V20 F10\n");
    assert_eq!(alarm(&r), ("HU-015", 3, 1));
    // S out of range.
    let (r, _) = run_probe(s(), "G20\nG0 X10 Z10\nG38 S4 Z7.6 A.5 T.125 V20 F10\n");
    assert_eq!(alarm(&r), ("HU-061", 3, 5));
}

#[test]
fn tune_file_defaults() {
    // "G38 S0 X5" with A, F, T, V from the profile (mm, mm/min): A 12.7
    // (.5 in), T 3.175 (.125 in), V 508 (20 ipm), F 254 (10 ipm): the same
    // moves as the full block.
    let mut p = Profile::builtin("hurco-lathe").unwrap();
    for (k, v) in [
        ("probe_approach", 12.7),
        ("probe_tolerance", 3.175),
        ("probe_approach_feed", 508.0),
        ("probe_feed", 254.0),
        ("probe_number", 14.0),
    ] {
        p.params.insert(k.into(), v);
    }
    let r = kerf_interp::run_text(
        p,
        settings(Some(4.95), None),
        "t.nc",
        "G20\nG00 X10 Z5\nG38 S0 X5\nM30\n",
    );
    ok(&r);
    let got: Vec<_> = path(&r).iter().skip(1).map(|m| (m.2, m.4)).collect();
    assert_eq!(got, vec![(3.0, 20.0), (2.475, 10.0), (5.0, 20.0)]);
    assert_eq!(
        messages(&r),
        vec!["10:15:30 Probe Datum: Probe #14; -X Offset 0.0500 at X4.9500, Z5.0000"]
    );
}
