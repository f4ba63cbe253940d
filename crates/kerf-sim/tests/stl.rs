//! The STL of the cut part is closed (every edge shared by exactly two
//! triangles, consistently oriented) and encloses the remaining volume.

mod common;

use common::Run;
use kerf_canon::Plane;
use kerf_sim::{parse_tools, stl};

fn checked(r: &Run) -> stl::StlCheck {
    let mut bytes = Vec::new();
    let n = stl::write(&r.sim, &mut bytes).unwrap();
    let c = stl::check(&bytes).expect("a binary STL");
    assert_eq!(c.triangles as u64, n);
    assert_eq!((c.bad_edges, c.flipped_edges), (0, 0), "{c:?}");
    c
}

#[test]
fn a_milled_pocket_and_through_slot_make_a_closed_mesh_of_the_remaining_volume() {
    let t = parse_tools(
        "[tool.1]\nkind=\"ball\"\ndiameter=6\n[tool.2]\nkind=\"flat\"\ndiameter=8\n",
        false,
    )
    .unwrap();
    let mut r = Run::new("box:0,0,-10,60,40,0", t, Some(0.1)).at(10.0, 10.0, 5.0);
    r.spindle(true);
    r.feed(1, 10.0, 10.0, -4.0);
    r.feed(2, 50.0, 30.0, -2.0);
    r.arc(
        3,
        [30.0, 20.0, -2.0],
        [40.0, 25.0, -2.0],
        false,
        Plane::XY,
        0,
    );
    // A slot cut right through the block and out of its side.
    r.tool(2, 0);
    r.feed(4, 30.0, 20.0, -12.0);
    r.feed(5, 70.0, 20.0, -12.0);
    let rep = r.sim.report();
    let c = checked(&r);
    let rel = (c.volume - rep.remaining_mm3).abs() / rep.remaining_mm3;
    // f32 coordinates, and cut-through cells kept 0.1 µm thick.
    assert!(rel < 2e-6, "{} vs {} ({rel})", c.volume, rep.remaining_mm3);
}

#[test]
fn a_turned_part_revolves_into_a_closed_mesh_of_the_remaining_volume() {
    let t = parse_tools(
        "[tool.1]\nnose_radius=0.4\ntip=3\n[tool.2]\nnose_radius=0\ntip=2\n[tool.3]\nkind=\"groove\"\nwidth=3\ntip=3\n",
        true,
    )
    .unwrap();
    let mut r = Run::new("tube:50,10,60", t, Some(0.01)).at(40.0, 0.0, 10.0);
    r.tool(1, 1);
    r.spindle(true);
    r.lrapid(1, 27.0, -1.0);
    r.lfeed(2, 3.0, -1.0);
    r.lrapid(3, 20.0, 2.0);
    r.lfeed(4, 20.0, -20.0);
    r.lfeed(5, 24.0, -35.0);
    r.lfeed(6, 26.0, -35.0);
    r.tool(3, 3);
    r.lrapid(7, 27.0, -45.0);
    r.lfeed(8, 15.0, -45.0);
    r.lfeed(9, 27.0, -45.0);
    r.tool(2, 2);
    r.lrapid(10, 9.0, 2.0);
    r.lfeed(11, 9.0, -15.0);
    r.lfeed(12, 5.0, -15.0);
    r.lrapid(13, 5.0, 2.0);
    let rep = r.sim.report();
    let c = checked(&r);
    // Column centres joined by lines where r changes by at most 4 dz
    // (π dz (4 dz)² / 6 per column at most), steps elsewhere; f32
    // coordinates.
    let rel = (c.volume - rep.remaining_mm3).abs() / rep.remaining_mm3;
    assert!(rel < 2e-6, "{} vs {} ({rel})", c.volume, rep.remaining_mm3);
}
