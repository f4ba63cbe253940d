//! The summary printed after a run: cycle time as h:mm:ss, blocks and
//! motions, feed and rapid length, each tool with its cutting time.

use std::fmt::Write as _;

use kerf_control::sinks::report::Document;

/// `h:mm:ss`, seconds rounded to the nearest.
pub fn hms(s: f64) -> String {
    let t = s.max(0.0).round() as u64;
    format!("{}:{:02}:{:02}", t / 3600, t / 60 % 60, t % 60)
}

/// The summary lines for program `name` (`ok` for check, `completed`
/// for run).
pub fn text(name: &str, verdict: &str, d: &Document) -> String {
    let mut s = String::new();
    let t = &d.time_s;
    let _ = writeln!(
        s,
        "{name}: {verdict}: cycle time {} ({:.1} s)",
        hms(d.cycle_time_s),
        d.cycle_time_s
    );
    let _ = writeln!(
        s,
        "  {} blocks, {} motions; feed {:.1} mm, rapid {:.1} mm",
        d.blocks, d.motions, d.feed_length_mm, d.rapid_length_mm
    );
    let _ = writeln!(
        s,
        "  cutting {}, rapid {}, dwell {}, tool change {}, other {}",
        hms(t.cutting),
        hms(t.rapid),
        hms(t.dwell),
        hms(t.tool_change),
        hms(t.other)
    );
    for tt in &d.tool_times {
        let _ = writeln!(s, "  T{:<4} cutting {}", tt.tool, hms(tt.cutting_s));
    }
    if !d.warnings.is_empty() {
        let n = d.warnings.len();
        let _ = writeln!(s, "  {n} warning{}", if n == 1 { "" } else { "s" });
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hours_minutes_seconds() {
        assert_eq!(hms(0.0), "0:00:00");
        assert_eq!(hms(59.4), "0:00:59");
        assert_eq!(hms(59.6), "0:01:00");
        // The 259345.5 s: 72 h 2 min 25.5 s.
        assert_eq!(hms(259_345.5), "72:02:26");
        assert_eq!(hms(3_600.0 + 61.0), "1:01:01");
    }
}
