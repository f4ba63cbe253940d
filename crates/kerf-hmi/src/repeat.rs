//! Telling when a traced path only retraces itself: a program that loops
//! for ever (`WHILE [1 EQ 1]`, a `GOTO` back) draws the same points again
//! and again, and tracing it to the block limit costs a core for tens of
//! seconds and sends clients megabytes of path that add nothing to the
//! picture.
//!
//! Every move (its kind, its start and end points, and for an arc its
//! centre and direction: what the picture draws of it) is marked in a
//! fixed set of bits by a hash. A move whose bit is already set has been
//! drawn before (or collides with one that has); once a long run of
//! consecutive moves have all been drawn before, the path is repeating
//! itself and tracing further adds nothing to the picture. A hash
//! collision can only make a run longer by chance, and a run of a million
//! chance collisions in a row does not happen: the set holds 2^24 bits,
//! so even holding 50 million moves (the trace's block limit) a new move
//! collides with fewer than 96 chances in 100 (1 - e^-3), and a million
//! in a row has a probability below 0.96^1000000.

/// Bits in the set of drawn points (2 MiB).
const BITS: usize = 1 << 24;

/// Counts the moves that retrace the path drawn so far.
pub struct Repeats {
    bits: Vec<u64>,
    run: u64,
    limit: u64,
}

impl Repeats {
    /// A detector that reports a repeat after `limit` consecutive moves
    /// that were all drawn before.
    pub fn new(limit: u64) -> Repeats {
        Repeats {
            bits: vec![0; BITS / 64],
            run: 0,
            limit,
        }
    }

    /// Marks the move described by `words` as drawn, and tells whether the
    /// last `limit` moves, this one included, had all been drawn before.
    pub fn retraces(&mut self, words: &[u32]) -> bool {
        let h = hash(words);
        let (word, bit) = ((h / 64) as usize % self.bits.len(), h % 64);
        let mask = 1u64 << bit;
        if self.bits[word] & mask != 0 {
            self.run += 1;
        } else {
            self.bits[word] |= mask;
            self.run = 0;
        }
        self.run >= self.limit
    }
}

/// A 64-bit mix of the words (each folded in and stirred with the
/// finaliser of splitmix64): the same move always gives the same value,
/// nearby moves unrelated ones.
fn hash(words: &[u32]) -> u64 {
    let mut z = 0x9e37_79b9_7f4a_7c15u64;
    for &w in words {
        z = (z ^ u64::from(w)).wrapping_mul(0x9e37_79b9_7f4a_7c15);
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^= z >> 31;
    }
    z
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The words of a line move from `a` to `b`.
    fn line(a: [f32; 3], b: [f32; 3]) -> [u32; 7] {
        [
            1,
            a[0].to_bits(),
            a[1].to_bits(),
            a[2].to_bits(),
            b[0].to_bits(),
            b[1].to_bits(),
            b[2].to_bits(),
        ]
    }

    #[test]
    fn a_square_drawn_again_is_a_repeat_after_the_limit() {
        let c = [
            [0.0, 0.0, 0.0],
            [10.0, 0.0, 0.0],
            [10.0, 10.0, 0.0],
            [0.0, 10.0, 0.0],
        ];
        let mut r = Repeats::new(8);
        let mut first = None;
        for i in 0..40 {
            if r.retraces(&line(c[i % 4], c[(i + 1) % 4])) {
                first = Some(i);
                break;
            }
        }
        // Sides 0-3 are new; 4-11 are the 8 repeats, so the 12th side
        // (index 11) is the first at which the last 8 were all drawn.
        assert_eq!(first, Some(11));
    }

    #[test]
    fn a_new_move_ends_the_run() {
        let mut r = Repeats::new(3);
        let (a, b, c) = ([1.0, 2.0, 3.0], [4.0, 5.0, 6.0], [4.0, 5.0, 6.5]);
        // a-b new, twice again (a run of 2), a-c new (the run ends), a-b
        // three times again: the third makes a run of 3.
        let moves = [
            (b, false),
            (b, false),
            (b, false),
            (c, false),
            (b, false),
            (b, false),
            (b, true),
        ];
        for (i, (to, want)) in moves.into_iter().enumerate() {
            assert_eq!(r.retraces(&line(a, to)), want, "move {i}");
        }
    }

    #[test]
    fn the_same_points_in_the_other_direction_or_kind_are_new() {
        let mut r = Repeats::new(1);
        let (a, b) = ([5.0, 5.0, 5.0], [6.0, 5.0, 5.0]);
        assert!(!r.retraces(&line(a, b)));
        assert!(!r.retraces(&line(b, a)));
        let mut rapid = line(a, b);
        rapid[0] = 0;
        assert!(!r.retraces(&rapid));
        assert!(r.retraces(&rapid));
    }

    #[test]
    fn a_million_distinct_moves_never_look_like_a_repeat() {
        // A raster of distinct moves, as a long finite program draws;
        // with a limit of 20, chance collisions (each below 1 in 16 here)
        // would have to come 20 in a row to stop it.
        let mut r = Repeats::new(20);
        let p = |i: u32| [(i % 1000) as f32 * 0.3, (i / 1000) as f32 * 0.03, 0.0];
        for i in 0..1_000_000u32 {
            assert!(
                !r.retraces(&line(p(i), p(i + 1))),
                "move {i} taken for a repeat"
            );
        }
    }
}
