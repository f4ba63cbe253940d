//! The loaded program: its name and text, with the start of every line
//! (for the block display and for program restart by line or N number).

/// Largest program text the runtime takes, bytes: 512 MiB, room for a
/// CAM program of 10 million blocks (the benchmarks' surface_10m.nc is
/// 310 MiB, 32.5 bytes a block). The text is held in memory while the
/// program runs (design: memory bounded by the text plus a small window);
/// `kerf serve` refuses larger bodies.
pub const MAX_PROGRAM_BYTES: usize = 512 << 20;

/// A program held in memory.
#[derive(Clone, Debug)]
pub(crate) struct Program {
    pub name: String,
    pub text: String,
    starts: Vec<usize>,
}

impl Program {
    /// Indexes the lines of `text`.
    pub fn new(name: &str, text: &str) -> Program {
        let mut starts = vec![0];
        for (i, b) in text.bytes().enumerate() {
            if b == b'\n' {
                starts.push(i + 1);
            }
        }
        if starts.last() == Some(&text.len()) && starts.len() > 1 {
            starts.pop();
        }
        Program {
            name: name.to_string(),
            text: text.to_string(),
            starts,
        }
    }

    /// Number of lines.
    pub fn lines(&self) -> u32 {
        self.starts.len() as u32
    }

    /// The text of 1-based line `n` (without its line end).
    pub fn line(&self, n: u32) -> Option<&str> {
        let i = (n as usize).checked_sub(1)?;
        let s = *self.starts.get(i)?;
        let e = self.starts.get(i + 1).copied().unwrap_or(self.text.len());
        Some(self.text[s..e].trim_end_matches(['\n', '\r']))
    }

    /// The first line whose block carries sequence number `n` (`N0012`,
    /// also after a block-delete slash).
    pub fn line_of_sequence(&self, n: u32) -> Option<u32> {
        (1..=self.lines()).find(|&l| {
            let mut t = self.line(l).unwrap_or("").trim_start();
            if let Some(r) = t.strip_prefix('/') {
                t = r
                    .trim_start_matches(|c: char| c.is_ascii_digit())
                    .trim_start();
            }
            let Some(rest) = t.strip_prefix(['N', 'n']) else {
                return false;
            };
            let digits: String = rest.chars().take_while(|c| c.is_ascii_digit()).collect();
            digits.parse::<u32>().ok() == Some(n)
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lines_and_sequence_numbers() {
        let p = Program::new("a", "O1\r\nN10 G00 X0\n/2 N0020 X1\n\nN30\n");
        assert_eq!(p.lines(), 5);
        assert_eq!(p.line(1), Some("O1"));
        assert_eq!(p.line(4), Some(""));
        assert_eq!(p.line(6), None);
        assert_eq!(p.line(0), None);
        assert_eq!(p.line_of_sequence(10), Some(2));
        assert_eq!(p.line_of_sequence(20), Some(3));
        assert_eq!(p.line_of_sequence(30), Some(5));
        assert_eq!(p.line_of_sequence(40), None);
    }
}
