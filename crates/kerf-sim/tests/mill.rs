//! Machining center: removed volumes against analytic solids, and the
//! crash checks, from canonical events made by hand.

mod common;

use std::f64::consts::PI;

use common::Run;
use kerf_canon::Plane;
use kerf_sim::{parse_tools, EventKind, ToolTable};

fn tools(text: &str) -> ToolTable {
    parse_tools(text, false).unwrap()
}

const FLAT10: &str = "[tool.1]\nkind=\"flat\"\ndiameter=10\n";

/// Error bound of a flat-bottomed cut of depth `d` whose outline has
/// perimeter `p`: a cell is in or out by its centre, so the cut area is
/// right to within the band of half a cell diagonal along the outline.
fn flat_bound(p: f64, h: f64, d: f64) -> f64 {
    p * h * std::f64::consts::FRAC_1_SQRT_2 * d
}

#[test]
fn a_flat_slot_removes_width_depth_length_plus_the_end_half_discs() {
    let mut r = Run::new("box:0,0,-20,100,100,0", tools(FLAT10), Some(0.05)).at(20.0, 50.0, 5.0);
    r.spindle(true);
    r.feed(10, 20.0, 50.0, -2.0);
    r.feed(11, 80.0, 50.0, -2.0);
    let rep = r.sim.report();
    // w d L + pi R^2 d = 10*2*60 + pi*25*2.
    let want = 1200.0 + PI * 25.0 * 2.0;
    let bound = flat_bound(2.0 * 60.0 + 2.0 * PI * 5.0, 0.05, 2.0);
    assert!(
        (rep.removed_mm3 - want).abs() <= bound,
        "{} vs {want} ± {bound}",
        rep.removed_mm3
    );
    assert!((rep.stock_mm3 - rep.removed_mm3 - rep.remaining_mm3).abs() < 1e-6 * rep.stock_mm3);
    assert!(rep.events.is_empty(), "{:?}", rep.events);
    assert_eq!(rep.resolution_mm, 0.05);
}

#[test]
fn a_ball_slot_removes_the_segment_prism_and_one_cap() {
    let t = "[tool.1]\nkind=\"ball\"\ndiameter=10\n";
    let mut r = Run::new("box:0,0,-20,100,100,0", tools(t), Some(0.05)).at(20.0, 50.0, 5.0);
    r.spindle(true);
    r.feed(10, 20.0, 50.0, -3.0);
    r.feed(11, 80.0, 50.0, -3.0);
    let (rr, d, l) = (5.0f64, 3.0f64, 60.0);
    // Circular segment of depth d: R² acos((R-d)/R) - (R-d) sqrt(2Rd - d²);
    // the two half caps at the ends make one cap pi d² (3R - d) / 3.
    let seg = rr * rr * ((rr - d) / rr).acos() - (rr - d) * (2.0 * rr * d - d * d).sqrt();
    let want = seg * l + PI * d * d * (3.0 * rr - d) / 3.0;
    // Heights are exact at the cell centres: the midpoint rule's error
    // (h²/24 · |d''| · area) plus the boundary cells (perimeter · slope · h²),
    // with the slope of the cut wall at the rim (4.58 / 2) and |d''| <= 3.2.
    let h: f64 = 0.05;
    let bound = h * h / 24.0 * 3.2 * (9.2 * 60.0 + PI * 4.6 * 4.6)
        + (2.0 * 60.0 + 2.0 * PI * 4.6) * 2.3 * h * h;
    let got = r.sim.report().removed_mm3;
    assert!((got - want).abs() <= bound, "{got} vs {want} ± {bound}");
}

#[test]
fn a_drilled_hole_has_its_cone_point() {
    let t = "[tool.1]\nkind=\"drill\"\ndiameter=10\npoint_angle=118\n";
    let mut r = Run::new("box:-15,-15,-30,15,15,0", tools(t), Some(0.02)).at(0.0, 0.0, 5.0);
    r.spindle(true);
    r.feed(10, 0.0, 0.0, -15.0);
    // The point is 5 / tan 59° high: cylinder to the shoulder plus its cone.
    let hp = 5.0 / 59f64.to_radians().tan();
    let want = PI * 25.0 * (15.0 - hp) + PI * 25.0 * hp / 3.0;
    let bound =
        flat_bound(2.0 * PI * 5.0, 0.02, 15.0 - hp) + 2.0 * PI * 5.0 * 0.02 * 0.02 / hp * 5.0;
    let got = r.sim.report().removed_mm3;
    assert!((got - want).abs() <= bound, "{got} vs {want} ± {bound}");
}

#[test]
fn a_helix_down_and_a_full_circle_cut_an_annulus() {
    let t = "[tool.1]\nkind=\"flat\"\ndiameter=6\n";
    let mut r = Run::new("box:-20,-20,-10,20,20,0", tools(t), Some(0.05)).at(10.0, 0.0, 2.0);
    r.spindle(true);
    r.feed(10, 10.0, 0.0, 0.0);
    r.arc(11, [10.0, 0.0, -3.0], [0.0, 0.0, 0.0], true, Plane::XY, 0);
    r.arc(12, [10.0, 0.0, -3.0], [0.0, 0.0, -3.0], true, Plane::XY, 0);
    // Annulus between radii 7 and 13, depth 3.
    let want = PI * (169.0 - 49.0) * 3.0;
    let bound = flat_bound(2.0 * PI * 20.0, 0.05, 3.0);
    let got = r.sim.report().removed_mm3;
    assert!((got - want).abs() <= bound, "{got} vs {want} ± {bound}");
}

#[test]
fn a_rapid_into_the_stock_is_reported_at_its_line_and_first_contact() {
    let mut r = Run::new("box:0,0,-20,100,100,0", tools(FLAT10), Some(0.05)).at(50.0, 50.0, 10.0);
    r.spindle(true);
    r.rapid(7, 50.0, 50.0, -5.0);
    let rep = r.sim.report();
    assert_eq!(rep.events.len(), 1, "{:?}", rep.events);
    let e = &rep.events[0];
    assert_eq!((e.kind, e.line), (EventKind::RapidIntoStock, 7));
    // Touches the top (Z0) after 10 of the 15 mm: at t = 0 + 10/15 s.
    // (Contact is material deeper than 1 µm: the height field's EPS.)
    assert!(
        (e.at[2] - 0.0).abs() < 2e-6 && e.at[0] == 50.0,
        "{:?}",
        e.at
    );
    assert!((e.t - 10.0 / 15.0).abs() < 1e-6, "{}", e.t);
    let bound = flat_bound(2.0 * PI * 5.0, 0.05, 5.0);
    assert!((e.volume_mm3 - PI * 25.0 * 5.0).abs() <= bound);
    assert!(rep.collided());

    // From the side at Z-5: the tool's edge meets the first cell centres
    // (x = 0.025, y = 50 ± 0.025), so the tip is at x = 0.025 - sqrt(25 - 0.025²).
    let mut r = Run::new("box:0,0,-20,100,100,0", tools(FLAT10), Some(0.05)).at(-20.0, 50.0, -5.0);
    r.spindle(true);
    r.rapid(9, 50.0, 50.0, -5.0);
    let e = &r.sim.report().events[0];
    assert_eq!(e.line, 9);
    assert!(
        (e.at[0] - (0.025 - (25.0f64 - 0.025 * 0.025).sqrt())).abs() < 2e-6,
        "{:?}",
        e.at
    );

    // The same path at feed is no event.
    let mut r = Run::new("box:0,0,-20,100,100,0", tools(FLAT10), Some(0.05)).at(50.0, 50.0, 10.0);
    r.spindle(true);
    r.feed(7, 50.0, 50.0, -5.0);
    assert!(!r.sim.report().collided());
}

#[test]
fn cutting_with_the_spindle_stopped_is_reported() {
    let mut r = Run::new("box:0,0,-20,100,100,0", tools(FLAT10), Some(0.1)).at(50.0, 50.0, 10.0);
    r.feed(4, 50.0, 50.0, -1.0);
    let rep = r.sim.report();
    assert_eq!(rep.events.len(), 1);
    assert_eq!(
        (rep.events[0].kind, rep.events[0].line),
        (EventKind::SpindleOffCut, 4)
    );
    // Moving in the air with the spindle stopped is fine.
    let mut r = Run::new("box:0,0,-20,100,100,0", tools(FLAT10), Some(0.1)).at(50.0, 50.0, 10.0);
    r.feed(4, 50.0, 50.0, 1.0);
    assert!(r.sim.report().events.is_empty());
}

#[test]
fn the_holder_meets_the_stock_past_the_flute_length() {
    // 10 mm flutes, a 10 mm shank 5 long, then a 40 mm holder from 15 above the tip.
    let t = "[tool.1]\nkind=\"flat\"\ndiameter=10\nflute_length=10\nholder=[[10,5],[40,50]]\n";
    let mut r = Run::new("box:0,0,-30,100,100,0", tools(t), Some(0.1)).at(50.0, 50.0, 10.0);
    r.spindle(true);
    r.feed(5, 50.0, 50.0, -8.0);
    assert!(r.sim.report().events.is_empty());
    // Deeper: the shank follows in its own hole; the holder's bottom
    // reaches the top Z0 when the tip is at Z-15.
    r.feed(6, 50.0, 50.0, -18.0);
    let rep = r.sim.report();
    assert_eq!(rep.events.len(), 1, "{:?}", rep.events);
    let e = &rep.events[0];
    assert_eq!((e.kind, e.line), (EventKind::HolderCollision, 6));
    assert!((e.at[2] + 15.0).abs() < 2e-6, "{:?}", e.at);
    // At the end its bottom is at Z-3: 3 mm into the top over its disc
    // (radius 20) less the hole (radius 5, already 8 deep).
    let want = PI * (400.0 - 25.0) * 3.0;
    let bound = flat_bound(2.0 * PI * 25.0, 0.1, 3.0);
    assert!(
        (e.volume_mm3 - want).abs() <= bound,
        "{} vs {want}",
        e.volume_mm3
    );
}

#[test]
fn a_non_centre_cutting_tool_must_not_plunge() {
    let t = "[tool.1]\nkind=\"flat\"\ndiameter=10\ncentre_cutting=false\n";
    let mut r = Run::new("box:0,0,-20,100,100,0", tools(t), Some(0.1)).at(50.0, 50.0, 5.0);
    r.spindle(true);
    r.feed(3, 50.0, 50.0, -2.0);
    let rep = r.sim.report();
    assert_eq!(rep.events.len(), 1);
    assert_eq!(
        (rep.events[0].kind, rep.events[0].line),
        (EventKind::PlungeNonCentreCutting, 3)
    );
    // Entering from the side at depth is how such a tool cuts.
    let mut r = Run::new("box:0,0,-20,100,100,0", tools(t), Some(0.1)).at(-10.0, 50.0, 5.0);
    r.spindle(true);
    r.feed(3, -10.0, 50.0, -2.0);
    r.feed(4, 50.0, 50.0, -2.0);
    assert!(
        r.sim.report().events.is_empty(),
        "{:?}",
        r.sim.report().events
    );
}

#[test]
fn a_tool_without_geometry_is_its_d_offset_and_a_warning() {
    let mut tt = ToolTable::default();
    tt.offsets.radius.insert(3, 4.0);
    let mut r = Run::new("box:0,0,-20,100,100,0", tt, Some(0.05)).at(50.0, 50.0, 5.0);
    r.tool(3, 0);
    r.spindle(true);
    r.feed(8, 50.0, 50.0, -1.0);
    let rep = r.sim.report();
    assert_eq!(rep.events.len(), 1);
    assert_eq!(
        (rep.events[0].kind, rep.events[0].line, rep.events[0].tool),
        (EventKind::ToolUnknown, 8, 3)
    );
    assert!(!rep.collided());
    let bound = flat_bound(2.0 * PI * 4.0, 0.05, 1.0);
    assert!((rep.removed_mm3 - PI * 16.0).abs() <= bound);
}

#[test]
fn a_dog_leg_rapid_is_simulated_along_its_corners() {
    // X and Z at the same rate from (-30, 50, -5) to (10, 50, 2): Z arrives
    // after 7 mm of X, at (-23, 50, 2), then X goes on alone at Z2, clear
    // of the block. The straight line has its tool edge at the block's
    // side (centre x = -5) at Z -5 + 7 × 25/40 = -0.625: into the block.
    let mk = || Run::new("box:0,0,-20,100,100,0", tools(FLAT10), Some(0.2)).at(-30.0, 50.0, -5.0);
    let rapid = |r: &mut Run, linear: bool| {
        let to = [10.0, 50.0, 2.0, 0.0, 0.0, 0.0];
        let e = kerf_canon::Event {
            src: kerf_canon::SrcRef {
                file: 0,
                line: 4,
                col: 1,
            },
            tool: 1,
            cmd: kerf_canon::Canon::Rapid {
                m: kerf_canon::Motion { to, mto: to },
                linear,
            },
            prog: None,
        };
        let from = r.pos;
        r.sim.event(&e, &from, 1.0);
    };
    let mut r = mk();
    r.sim.set_rapid_rates([10000.0, 10000.0, 10000.0]);
    r.spindle(true);
    rapid(&mut r, false);
    assert!(
        r.sim.report().events.is_empty(),
        "{:?}",
        r.sim.report().events
    );
    let mut r = mk();
    r.sim.set_rapid_rates([10000.0, 10000.0, 10000.0]);
    r.spindle(true);
    rapid(&mut r, true);
    assert_eq!(r.sim.report().events[0].kind, EventKind::RapidIntoStock);
}
