//! The alarm and message history: append-only, every entry numbered, read
//! by any number of readers from any sequence number (nothing is consumed
//! by reading, unlike a queue whose first reader takes the message).

use serde::{Deserialize, Serialize};

/// What an entry is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum RecordKind {
    /// An alarm: the program stopped.
    Alarm,
    /// An operator message (#3006, M00 comments, Hurco probe records).
    Message,
    /// RESET pressed (clears the alarm in force).
    Reset,
}

/// One entry of the history.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Record {
    /// Sequence number, from 1, never reused.
    pub seq: u64,
    /// Machine time, s.
    pub t: f64,
    pub kind: RecordKind,
    /// The control's code (`F_82001`, `PS0010` …), empty for messages.
    pub code: String,
    pub message: String,
    /// Source file name, line and column (0 when not from a program).
    pub file: String,
    pub line: u32,
    pub col: u32,
}

/// The history. Memory is bounded: beyond `cap` entries the oldest go
/// (their sequence numbers are not reused, so a reader sees the gap).
#[derive(Clone, Debug)]
pub struct AlarmLog {
    entries: std::collections::VecDeque<Record>,
    next: u64,
    cap: usize,
}

impl Default for AlarmLog {
    fn default() -> AlarmLog {
        AlarmLog::with_capacity(10_000)
    }
}

impl AlarmLog {
    /// A history keeping the newest `cap` entries.
    pub fn with_capacity(cap: usize) -> AlarmLog {
        AlarmLog {
            entries: Default::default(),
            next: 1,
            cap: cap.max(1),
        }
    }

    /// Appends an entry, returning its sequence number.
    pub fn push(&mut self, mut r: Record) -> u64 {
        r.seq = self.next;
        self.next += 1;
        if self.entries.len() == self.cap {
            self.entries.pop_front();
        }
        self.entries.push_back(r);
        self.next - 1
    }

    /// Entries with a sequence number greater than `after`, oldest first
    /// (`after` = 0: all kept).
    pub fn since(&self, after: u64) -> Vec<Record> {
        let first = self.entries.front().map(|r| r.seq).unwrap_or(self.next);
        let skip = after.saturating_sub(first - 1) as usize;
        self.entries.iter().skip(skip).cloned().collect()
    }

    /// The sequence number the next entry gets.
    pub fn next_seq(&self) -> u64 {
        self.next
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rec(m: &str) -> Record {
        Record {
            seq: 0,
            t: 0.0,
            kind: RecordKind::Message,
            code: String::new(),
            message: m.into(),
            file: String::new(),
            line: 0,
            col: 0,
        }
    }

    #[test]
    fn readers_do_not_consume_and_sequence_survives_the_cap() {
        let mut log = AlarmLog::with_capacity(3);
        for i in 0..5 {
            assert_eq!(log.push(rec(&i.to_string())), i + 1);
        }
        // Two readers see the same kept entries 3, 4, 5.
        let a = log.since(0);
        let b = log.since(0);
        assert_eq!(a, b);
        assert_eq!(a.iter().map(|r| r.seq).collect::<Vec<_>>(), vec![3, 4, 5]);
        assert_eq!(log.since(4).len(), 1);
        assert_eq!(log.since(5).len(), 0);
        assert_eq!(log.since(1).len(), 3);
    }
}
