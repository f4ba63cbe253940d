//! The words of one block after evaluation: a fixed-size table per address
//! letter plus the lists of G and M codes, filled without allocation.

/// One evaluated word value.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WVal {
    /// The value (expressions evaluated; still in program units and, for
    /// numbers without a decimal point, as written).
    pub v: f64,
    /// A decimal point was written (expressions count as having one).
    pub point: bool,
    /// Byte index of the address in the block text.
    pub at: u32,
}

/// Most G codes (and M codes) one block may carry (002: 10 of each).
pub const MAX_CODES: usize = 10;

/// The evaluated words of a block.
#[derive(Clone, Debug)]
pub struct Words {
    /// Single-letter addresses other than G and M, indexed by letter - 'A'.
    pub letters: [Option<WVal>; 26],
    /// G codes (value × 10, byte index) in order.
    pub g: [(u16, u32); MAX_CODES],
    pub ng: usize,
    /// M codes (value, byte index) in order.
    pub m: [(u32, u32); MAX_CODES],
    pub nm: usize,
    /// `,C` (chamfer) and `,R` (corner R), HX only; never both.
    pub comma_c: Option<WVal>,
    pub comma_r: Option<WVal>,
    /// Hurco multi-letter parameters (name index, value).
    pub long: [(u16, WVal); 32],
    pub nlong: usize,
}

impl Default for Words {
    fn default() -> Words {
        Words {
            letters: [None; 26],
            g: [(0, 0); MAX_CODES],
            ng: 0,
            m: [(0, 0); MAX_CODES],
            nm: 0,
            comma_c: None,
            comma_r: None,
            long: [(
                0,
                WVal {
                    v: 0.0,
                    point: false,
                    at: 0,
                },
            ); 32],
            nlong: 0,
        }
    }
}

impl Words {
    /// Empties the table.
    pub fn clear(&mut self) {
        self.letters = [None; 26];
        self.ng = 0;
        self.nm = 0;
        self.comma_c = None;
        self.comma_r = None;
        self.nlong = 0;
    }

    /// The value of a letter address.
    #[inline]
    pub fn get(&self, l: u8) -> Option<WVal> {
        self.letters[(l - b'A') as usize]
    }

    /// True when the letter is present.
    #[inline]
    pub fn has(&self, l: u8) -> bool {
        self.letters[(l - b'A') as usize].is_some()
    }

    /// Removes and returns a letter (so a code that consumed it can mark it).
    #[inline]
    pub fn take(&mut self, l: u8) -> Option<WVal> {
        self.letters[(l - b'A') as usize].take()
    }

    /// The G codes of the block.
    pub fn gs(&self) -> &[(u16, u32)] {
        &self.g[..self.ng]
    }

    /// The M codes of the block.
    pub fn ms(&self) -> &[(u32, u32)] {
        &self.m[..self.nm]
    }

    /// The block's `,C` (chamfer, `true`) or `,R` (corner R, `false`) word.
    #[inline]
    pub fn corner(&self) -> Option<(bool, WVal)> {
        match (self.comma_c, self.comma_r) {
            (Some(c), _) => Some((true, c)),
            (None, Some(r)) => Some((false, r)),
            (None, None) => None,
        }
    }

    /// Adds a G code (value × 10) written at byte `at`; false when the
    /// block has [`MAX_CODES`] already.
    #[inline]
    pub fn push_g(&mut self, code10: u16, at: u32) -> bool {
        let Some(slot) = self.g.get_mut(self.ng) else {
            return false;
        };
        *slot = (code10, at);
        self.ng += 1;
        true
    }

    /// Adds an M code written at byte `at`; false when the block has
    /// `max` (at most [`MAX_CODES`]) already.
    #[inline]
    pub fn push_m(&mut self, m: u32, at: u32, max: usize) -> bool {
        if self.nm >= max.min(MAX_CODES) {
            return false;
        }
        self.m[self.nm] = (m, at);
        self.nm += 1;
        true
    }

    /// True when the block carries G code `code10`.
    pub fn has_g(&self, code10: u16) -> bool {
        self.gs().iter().any(|&(g, _)| g == code10)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn w(v: f64, at: u32) -> WVal {
        WVal { v, point: true, at }
    }

    #[test]
    fn letters_are_read_taken_and_cleared() {
        let mut ws = Words::default();
        ws.letters[(b'X' - b'A') as usize] = Some(w(12.5, 4));
        assert!(ws.has(b'X') && !ws.has(b'Y'));
        assert_eq!(ws.get(b'X'), Some(w(12.5, 4)));
        assert_eq!(ws.take(b'X'), Some(w(12.5, 4)));
        assert!(!ws.has(b'X'));
        ws.letters[(b'Z' - b'A') as usize] = Some(w(-1.0, 9));
        ws.comma_r = Some(w(2.0, 12));
        assert!(ws.push_g(10, 0));
        ws.clear();
        assert!(ws.get(b'Z').is_none() && ws.corner().is_none() && ws.gs().is_empty());
    }

    #[test]
    fn codes_keep_their_order_up_to_the_limit() {
        let mut ws = Words::default();
        // G90 G01 in that order, by value × 10.
        assert!(ws.push_g(900, 0) && ws.push_g(10, 4));
        assert_eq!(ws.gs(), [(900, 0), (10, 4)]);
        assert!(ws.has_g(10) && !ws.has_g(0));
        for i in 2..MAX_CODES {
            assert!(ws.push_g(40, i as u32));
        }
        assert!(!ws.push_g(40, 99), "an 11th G code");
        assert_eq!(ws.gs().len(), MAX_CODES);
        // A control taking 3 M codes a block refuses the 4th.
        for m in [3, 8, 98] {
            assert!(ws.push_m(m, 0, 3));
        }
        assert!(!ws.push_m(30, 0, 3));
        assert_eq!(ws.ms().iter().map(|m| m.0).collect::<Vec<_>>(), [3, 8, 98]);
    }

    #[test]
    fn a_chamfer_word_comes_before_a_corner_r() {
        let mut ws = Words {
            comma_r: Some(w(3.0, 8)),
            ..Words::default()
        };
        assert_eq!(ws.corner(), Some((false, w(3.0, 8))));
        ws.comma_c = Some(w(1.0, 2));
        assert_eq!(ws.corner(), Some((true, w(1.0, 2))));
    }
}
