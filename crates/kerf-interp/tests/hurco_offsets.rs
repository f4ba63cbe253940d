//! Hurco T and E codes (002 "Tool Change and Active Tool Offsets", "E
//! Codes", Table 16): a T/E code moves nothing; the next move with an axis
//! word moves all axes (immediate activation) or only the programmed ones
//! (deferred). Expected machine positions worked out by hand from the
//! offsets below and the profile's E1 part zero (Z -400 mm).
mod common;
use common::*;
use kerf_canon::Canon;
use kerf_interp::{Interp, Profile, Run, Settings};

/// Runs on hurco-lathe with lathe offset 1 = X 10 (radius) Z 5, offset 2 =
/// X -3 Z 7, and fixture E2 = (0, -300 mm); `immediate` selects Table 16.
fn run_offsets(immediate: bool, text: &str) -> Run {
    let mut p = Profile::builtin("hurco-lathe").unwrap();
    p.tools.immediate_offsets = immediate;
    let mut it = Interp::new(p, Settings::default());
    {
        let o = it.offsets_mut().lathe_mut(1).unwrap();
        o.x = 10.0;
        o.z = 5.0;
        let o = it.offsets_mut().lathe_mut(2).unwrap();
        o.x = -3.0;
        o.z = 7.0;
    }
    assert!(it.set_fixture_offset(2, [0.0, 0.0, -300.0, 0.0, 0.0, 0.0]));
    kerf_interp::run_interp(it, "t.nc", text)
}

/// Machine (x, z) of every motion, with its line.
fn mpos(r: &Run) -> Vec<(u32, f64, f64)> {
    r.events
        .iter()
        .filter_map(|e| {
            e.motion()
                .map(|m| (e.src.line, round(m.mto[0]), round(m.mto[2])))
        })
        .collect()
}

const START: &str = "G21 G90 G07\nG00 X50 Z100\n";

#[test]
fn t_code_immediate_moves_all_axes_at_the_next_move() {
    // Line 2: machine (50, 100 - 400 = -300). Line 3 T0101 moves nothing.
    // Line 4 Z50: immediate: X too goes to X50 relative to offset 1:
    // machine X 50 + 10 = 60, Z 50 + 5 - 400 = -345.
    let r = run_offsets(true, &format!("{START}T0101\nZ50\nX40\nM30\n"));
    ok(&r);
    assert_eq!(
        mpos(&r),
        vec![(2, 50.0, -300.0), (4, 60.0, -345.0), (5, 50.0, -345.0)]
    );
    // The tool event carries tool 1 offset 1, a turret index.
    assert!(r.events.iter().any(|e| matches!(
        e.cmd,
        Canon::Tool {
            tool: 1,
            offset: 1,
            change: true
        }
    ) && e.src.line == 3));
}

#[test]
fn t_code_deferred_moves_only_programmed_axes() {
    // Line 4 Z50: only Z takes the offset: machine (50, -345); line 5 X40:
    // 40 + 10 = 50.
    let r = run_offsets(false, &format!("{START}T0101\nZ50\nX40\nM30\n"));
    ok(&r);
    assert_eq!(
        mpos(&r),
        vec![(2, 50.0, -300.0), (4, 50.0, -345.0), (5, 50.0, -345.0)]
    );
}

#[test]
fn t_code_in_a_block_with_axis_words_and_t00() {
    // T0202 X20 in one block (immediate): X 20 - 3 = 17, Z 100 + 7 - 400 =
    // -293. Then T0200 (offset 00) cancels: the next Z10 moves X back to
    // 20 and Z to 10 - 400 = -390.
    let r = run_offsets(true, &format!("{START}T0202 X20\nT0200\nZ10\nM30\n"));
    ok(&r);
    assert_eq!(
        mpos(&r),
        vec![(2, 50.0, -300.0), (3, 17.0, -293.0), (5, 20.0, -390.0)]
    );
}

#[test]
fn incremental_move_after_an_offset_change() {
    // G91 Z-10 after T0101: from the program position Z100: Z90 relative
    // to the new offset: machine 90 + 5 - 400 = -305; immediate: X 50 +
    // 10 = 60; deferred: X stays 50.
    let r = run_offsets(true, &format!("{START}T0101\nG91 Z-10\nM30\n"));
    assert_eq!(mpos(&r)[1], (4, 60.0, -305.0));
    let r = run_offsets(false, &format!("{START}T0101\nG91 Z-10\nM30\n"));
    assert_eq!(mpos(&r)[1], (4, 50.0, -305.0));
}

#[test]
fn e_codes_immediate_and_deferred() {
    // E2 = part zero at machine Z -300. Line 4 X20: immediate: Z goes to
    // Z100 relative to E2: -200; deferred: Z stays at -300. E00 cancels
    // every fixture offset: line 6 X10 Z-10 = machine (10, -10).
    let text = format!("{START}E2\nX20\nE00\nX10 Z-10\nM30\n");
    let r = run_offsets(true, &text);
    ok(&r);
    assert_eq!(
        mpos(&r),
        vec![(2, 50.0, -300.0), (4, 20.0, -200.0), (6, 10.0, -10.0)]
    );
    let r = run_offsets(false, &text);
    ok(&r);
    assert_eq!(
        mpos(&r),
        vec![(2, 50.0, -300.0), (4, 20.0, -300.0), (6, 10.0, -10.0)]
    );
    // E1 is the profile's part zero (Z -400): back to it.
    let r = run_offsets(true, &format!("{START}E2\nE1\nX20\nM30\n"));
    assert_eq!(mpos(&r)[1], (5, 20.0, -300.0));
}

#[test]
fn t_and_e_alarms() {
    // E beyond Table 3's 4 digits, T offset beyond the table (99 entries:
    // T0100 is fine, tool 13 is beyond the 12-station turret).
    let r = run_on("hurco-lathe", "E10000\n");
    assert_eq!(alarm(&r), ("HU-014", 1, 1));
    let r = run_on("hurco-lathe", "G0 X1 E2.5\n");
    assert_eq!(alarm(&r), ("HU-014", 1, 7));
    let r = run_on("hurco-lathe", "T1301\n");
    assert_eq!(alarm(&r), ("HU-014", 1, 1));
}
