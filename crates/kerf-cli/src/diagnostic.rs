//! Alarms and warnings on stderr as compilers print errors: `FILE:LINE:COL:
//! alarm CODE: MESSAGE`, the source line (clipped around the column when
//! long), a caret under the column. COL and the caret count characters,
//! as an editor does (the run's positions are byte columns: a line with
//! `Ø` or `ä` before the column has fewer characters than bytes there).

use std::collections::{BTreeMap, BTreeSet};
use std::fs::File;
use std::io::Write;

use kerf_canon::Alarm;
use kerf_control::Warning;

/// Characters of a source line shown around the column at most.
const WIDTH: usize = 100;

/// Prints the alarm with its source line and caret.
pub fn print_alarm(a: &Alarm, file: &str) {
    let mut err = std::io::stderr().lock();
    let line = source_line(file, a.src.line);
    let col = line
        .as_deref()
        .map_or(a.src.col, |l| char_col(l, a.src.col));
    let _ = writeln!(
        err,
        "{}:{}:{}: alarm {}: {}",
        file, a.src.line, col, a.code, a.message
    );
    if let Some(line) = line {
        let (shown, caret) = excerpt(&line, a.src.col as usize);
        let _ = writeln!(err, "  {shown}");
        let _ = writeln!(err, "  {}^", " ".repeat(caret));
    }
}

/// Prints the warning lines in order, their columns in characters (each
/// file named is read once, for the lines warned about).
pub fn print_warnings(ws: &[Warning]) {
    let mut wanted: BTreeMap<&str, BTreeSet<u32>> = BTreeMap::new();
    for w in ws.iter().filter(|w| w.col > 0) {
        wanted.entry(&w.file).or_default().insert(w.line);
    }
    let lines: BTreeMap<&str, BTreeMap<u32, Vec<u8>>> = wanted
        .into_iter()
        .map(|(f, want)| (f, source_lines(f, &want)))
        .collect();
    let mut err = std::io::stderr().lock();
    for w in ws {
        let col = match w.col {
            0 => String::new(),
            c => {
                let line = lines.get(w.file.as_str()).and_then(|m| m.get(&w.line));
                format!("{}:", line.map_or(c, |l| char_col(l, c)))
            }
        };
        let _ = writeln!(
            err,
            "{}:{}:{col} warning {}: {}",
            w.file, w.line, w.code, w.message
        );
    }
}

/// The 1-based character column of the 1-based byte column `col` of
/// `line` (the characters before it, plus one).
pub fn char_col(line: &[u8], col: u32) -> u32 {
    let at = (col as usize).saturating_sub(1).min(line.len());
    String::from_utf8_lossy(&line[..at]).chars().count() as u32 + 1
}

/// The line as shown (tabs as spaces, control characters as `?`,
/// clipped to about [`WIDTH`] characters around the column with `…` where
/// cut) and the caret's offset in characters under it. `col` is the
/// 1-based byte column of the line's bytes.
pub fn excerpt(line: &[u8], col: usize) -> (String, usize) {
    let at = col.saturating_sub(1).min(line.len());
    let before = String::from_utf8_lossy(&line[..at]).chars().count();
    let chars: Vec<char> = String::from_utf8_lossy(line)
        .chars()
        .map(|c| match c {
            '\t' => ' ',
            c if c.is_control() => '?',
            c => c,
        })
        .collect();
    let caret = before.min(chars.len());
    if chars.len() <= WIDTH {
        return (chars.into_iter().collect(), caret);
    }
    let start = caret.saturating_sub(WIDTH / 2).min(chars.len() - WIDTH);
    let end = start + WIDTH;
    let mut s = String::new();
    if start > 0 {
        s.push('…');
    }
    s.extend(&chars[start..end]);
    if end < chars.len() {
        s.push('…');
    }
    (s, caret - start + usize::from(start > 0))
}

/// Line `line` of `file` (see [`source_lines`]).
fn source_line(file: &str, line: u32) -> Option<Vec<u8>> {
    source_lines(file, &BTreeSet::from([line])).remove(&line)
}

/// The lines `want` of `file`, read in one pass that stops after the last
/// (at most 4 KiB of each, without the newline and a leading UTF-8
/// byte-order mark); a line the file does not have is left out.
fn source_lines(file: &str, want: &BTreeSet<u32>) -> BTreeMap<u32, Vec<u8>> {
    use std::io::{BufRead, Read};
    let mut out = BTreeMap::new();
    let (Some(&last), Ok(f)) = (want.last(), File::open(file)) else {
        return out;
    };
    let mut r = std::io::BufReader::new(f);
    let mut buf = Vec::new();
    for n in 1..=last {
        buf.clear();
        // Bound what one line may cost: read at most 4 KiB of it.
        match (&mut r).take(4096).read_until(b'\n', &mut buf) {
            Ok(0) | Err(_) => break,
            Ok(_) => {}
        }
        let whole = buf.last() == Some(&b'\n');
        if want.contains(&n) {
            let mut line = buf.clone();
            while matches!(line.last(), Some(b'\n' | b'\r')) {
                line.pop();
            }
            if n == 1 && line.starts_with(b"\xEF\xBB\xBF") {
                line.drain(..3);
            }
            out.insert(n, line);
        }
        if !whole {
            // The rest of an over-long line.
            let mut sink = Vec::new();
            if r.read_until(b'\n', &mut sink).is_err() {
                break;
            }
        }
    }
    out
}

/// The simulation's events on stderr, one line each
/// (`FILE:LINE: collision KIND: …` or `FILE:LINE: warning tool_unknown: …`),
/// and its volumes.
pub fn print_sim(s: &kerf_control::sinks::sim::SimOut) {
    let mut err = std::io::stderr().lock();
    for e in &s.events {
        let what = if e.kind == "tool_unknown" {
            "warning"
        } else {
            "collision"
        };
        let _ = writeln!(
            err,
            "{}:{}: {what} {}: tool {} at X{:.3} Y{:.3} Z{:.3}, t {:.3} s, {:.3} mm3",
            e.file, e.line, e.kind, e.tool, e.at[0], e.at[1], e.at[2], e.t, e.volume_mm3
        );
    }
    if s.events_dropped > 0 {
        let _ = writeln!(
            err,
            "kerf: sim: {} more events not listed",
            s.events_dropped
        );
    }
    let _ = writeln!(
        err,
        "kerf: sim: stock {:.3} mm3, removed {:.3} mm3, remaining {:.3} mm3 at {} mm; {} collision(s)",
        s.stock_mm3, s.removed_mm3, s.remaining_mm3, s.resolution_mm, s.collisions
    );
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_caret_counts_characters_not_bytes() {
        // "(Ø) X1" : the X is byte 6 (Ø is two bytes) but character 5.
        let line = "(Ø) X1".as_bytes();
        assert_eq!(line[5], b'X');
        let (shown, caret) = excerpt(line, 6);
        assert_eq!(shown, "(Ø) X1");
        assert_eq!(caret, 4);
        assert_eq!(shown.chars().nth(caret), Some('X'));
    }

    #[test]
    fn the_column_printed_counts_characters() {
        // "(Ø, ä) X1": X is byte 10 (Ø and ä two bytes each), character 8.
        let line = "(Ø, ä) X1".as_bytes();
        assert_eq!(line[9], b'X');
        assert_eq!(char_col(line, 10), 8);
        assert_eq!(char_col(b"G01 X1", 5), 5);
        // Past the end of a clipped line: the characters there are.
        assert_eq!(char_col(b"AB", 9), 3);
    }

    #[test]
    fn a_long_line_is_clipped_around_the_column() {
        let mut line = "A".repeat(3000);
        line.replace_range(2000..2001, "X");
        let (shown, caret) = excerpt(line.as_bytes(), 2001);
        assert_eq!(shown.chars().count(), WIDTH + 2);
        assert!(shown.starts_with('…') && shown.ends_with('…'));
        assert_eq!(shown.chars().nth(caret), Some('X'));
        // Near the start: no leading ellipsis.
        let (shown, caret) = excerpt(line.as_bytes(), 3);
        assert!(!shown.starts_with('…') && shown.ends_with('…'));
        assert_eq!(caret, 2);
    }
}
