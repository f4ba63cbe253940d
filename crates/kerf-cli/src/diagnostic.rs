//! Alarms on stderr as compilers print errors: `FILE:LINE:COL: alarm CODE:
//! MESSAGE`, the source line, a caret under the column.

use std::fs::File;
use std::io::Write;

use kerf_canon::Alarm;

/// Prints the alarm with its source line and caret.
pub fn print_alarm(a: &Alarm, file: &str) {
    let mut err = std::io::stderr().lock();
    let _ = writeln!(
        err,
        "{}:{}:{}: alarm {}: {}",
        file, a.src.line, a.src.col, a.code, a.message
    );
    if let Some(line) = source_line(file, a.src.line) {
        let shown: String = line
            .chars()
            .map(|c| if c == '\t' { ' ' } else { c })
            .collect();
        let _ = writeln!(err, "  {shown}");
        let col = (a.src.col as usize).saturating_sub(1).min(shown.len());
        let _ = writeln!(err, "  {}^", " ".repeat(col));
    }
}

fn source_line(file: &str, line: u32) -> Option<String> {
    use std::io::{BufRead, Read};
    let f = File::open(file).ok()?;
    let mut r = std::io::BufReader::new(f);
    let mut buf = Vec::new();
    for n in 1..=line {
        buf.clear();
        // Bound what one line may cost: read at most 4 KiB of it.
        let got = (&mut r).take(4096).read_until(b'\n', &mut buf).ok()?;
        if got == 0 {
            return None;
        }
        if n == line {
            let s = String::from_utf8_lossy(&buf);
            return Some(s.trim_end_matches(['\n', '\r']).to_string());
        }
        if buf.last() != Some(&b'\n') {
            // The rest of an over-long line.
            let mut sink = Vec::new();
            r.read_until(b'\n', &mut sink).ok()?;
        }
    }
    None
}
