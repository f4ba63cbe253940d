//! The pictures: the part is drawn where it should be and collision
//! points are marked. (The PNGs are left in the target's tmp folder to
//! be looked at.)

mod common;

use common::Run;
use kerf_canon::Plane;
use kerf_sim::{parse_tools, render};

fn save(c: &render::Canvas, name: &str) -> Vec<u8> {
    let mut bytes = Vec::new();
    c.write_png(&mut bytes).unwrap();
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR"));
    std::fs::write(dir.join(name), &bytes).unwrap();
    bytes
}

fn red(c: &render::Canvas) -> usize {
    let mut n = 0;
    for y in 0..c.h {
        for x in 0..c.w {
            if c.get(x, y) == [220, 20, 20] {
                n += 1;
            }
        }
    }
    n
}

#[test]
fn a_milled_part_is_drawn_with_its_rapid_crash_marked() {
    let t = parse_tools("[tool.1]\nkind=\"ball\"\ndiameter=10\n", false).unwrap();
    let mut r = Run::new("box:-50,-40,-20,50,40,0", t, Some(0.2)).at(-30.0, 0.0, 5.0);
    r.spindle(true);
    r.feed(1, -30.0, 0.0, -5.0);
    r.feed(2, 30.0, 0.0, -5.0);
    r.arc(3, [30.0, 0.0, -5.0], [10.0, 0.0, -5.0], true, Plane::XY, 0);
    let before = render::render(&r.sim);
    assert_eq!(red(&before), 0);
    r.rapid(4, 0.0, 25.0, -3.0);
    let c = render::render(&r.sim);
    let png = save(&c, "mill.png");
    assert_eq!(&png[1..4], b"PNG");
    assert!(red(&c) > 20);
    // The middle of the picture is the part, not the background.
    assert_ne!(c.get(600, 450), [250, 250, 247]);
    assert_eq!(c.get(3, 3), [250, 250, 247]);
}

#[test]
fn a_turned_part_is_drawn_as_section_and_view() {
    let t = parse_tools(
        "[tool.1]\nnose_radius=0.8\ntip=3\n[tool.2]\nnose_radius=0.4\ntip=2\n",
        true,
    )
    .unwrap();
    let mut r = Run::new("tube:60,16,80", t, Some(0.02)).at(40.0, 0.0, 10.0);
    r.tool(1, 1);
    r.spindle(true);
    r.lrapid(1, 32.0, -1.0);
    r.lfeed(2, 6.0, -1.0);
    r.lrapid(3, 22.0, 2.0);
    r.lfeed(4, 22.0, -25.0);
    r.arc(
        5,
        [27.0, 0.0, -30.0],
        [27.0, 0.0, -25.0],
        false,
        Plane::ZX,
        0,
    );
    r.lfeed(6, 31.0, -30.0);
    r.lrapid(7, 40.0, 2.0);
    r.tool(2, 2);
    r.lrapid(8, 12.0, 2.0);
    r.lfeed(9, 12.0, -20.0);
    r.lfeed(10, 8.0, -20.0);
    r.lrapid(11, 8.0, 2.0);
    let clean = render::render(&r.sim);
    assert_eq!(red(&clean), 0, "{:?}", r.sim.report().events);
    // A rapid into the bore wall (r 12) at Z-10.
    r.lrapid(12, 15.0, -10.0);
    assert_eq!(r.sim.report().events.len(), 1);
    let c = render::render(&r.sim);
    save(&c, "lathe.png");
    assert!(red(&c) > 20);
    // The 3/4 view's cut-away: its two section faces are drawn in the
    // section colour (green under 0.6 of red: neither the gold of the
    // turned surfaces, 0.79, nor the blue-grey stock), right of x 800.
    let mut section = 0;
    for y in 0..c.h {
        for x in 800..c.w {
            let px = c.get(x, y);
            let (r, g) = (px[0] as f64, px[1] as f64);
            if px != [220, 20, 20] && r > 40.0 && g < 0.6 * r {
                section += 1;
            }
        }
    }
    assert!(section > 20_000, "{section} section pixels");
}
