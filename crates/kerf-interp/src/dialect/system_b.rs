//! The PUMA's G-code system B as a table (001 G-code table, "special G
//! code" column; fanuc-semantics §10.1): each system-B number and the
//! system-A code kerf executes for it. interp/system_b.rs translates a
//! block's codes with it as they are collected; #4001-#4031 give the
//! system-B numbers back through [`to_b`].

/// The PUMA table's code for system B's G90 (absolute).
pub const ABS: u16 = 9000;
/// The PUMA table's code for system B's G91 (incremental).
pub const INC: u16 = 9010;

/// A system-B G code (× 10) as the system-A code kerf executes; `None`
/// for the system-A numbers system B does not have (G32, G50, G98, G99:
/// in system B G98/G99 select the canned-cycle return level of drilling
/// cycles the PUMA has not got).
pub fn to_a(c10: u16) -> Option<u16> {
    Some(match c10 {
        330 => 320,
        770 => 900,
        780 => 920,
        790 => 940,
        920 => 500,
        940 => 980,
        950 => 990,
        900 => ABS,
        910 => INC,
        320 | 500 | 980 | 990 => return None,
        c => c,
    })
}

/// The system-B number of a system-A code (for #4001-#4031).
pub fn to_b(a10: u16) -> u16 {
    match a10 {
        320 => 330,
        900 => 770,
        920 => 780,
        940 => 790,
        500 => 920,
        980 => 940,
        990 => 950,
        ABS => 900,
        INC => 910,
        c => c,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// fanuc-semantics §10.1: B's G33, G77, G78, G79, G92, G94, G95 are
    /// A's G32, G90, G92, G94, G50, G98, G99; the numbers both share
    /// (G00, G71 …) are the same code; A's G32, G50, G98, G99 are not
    /// system-B codes; the #4001 numbers come back as written.
    #[test]
    fn system_b_numbers() {
        let pairs = [
            (330, 320),
            (770, 900),
            (780, 920),
            (790, 940),
            (920, 500),
            (940, 980),
            (950, 990),
            (900, ABS),
            (910, INC),
        ];
        for (b, a) in pairs {
            assert_eq!(to_a(b), Some(a), "G{b}");
            assert_eq!(to_b(a), b, "G{a}");
        }
        for same in [0, 10, 40, 400, 710, 760] {
            assert_eq!(to_a(same), Some(same));
            assert_eq!(to_b(same), same);
        }
        for a_only in [320, 500, 980, 990] {
            assert_eq!(to_a(a_only), None, "G{a_only}");
        }
    }
}
