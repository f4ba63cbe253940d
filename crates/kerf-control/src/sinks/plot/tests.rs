//! The whole picture, SVG and PNG, against geometry worked out by hand
//! from the layout's constants (docs/formats.md "Plot").

use super::*;
use kerf_canon::{Canon, Feed, Motion, SrcRef};
use tiny_skia::Pixmap;

fn motion(rapid: bool, tool: u32, p: Pos) -> Event {
    let m = Motion { to: p, mto: p };
    Event {
        src: SrcRef::default(),
        tool,
        cmd: if rapid {
            Canon::Rapid { m, linear: true }
        } else {
            Canon::Feed {
                m,
                feed: Feed::PerMin(100.0),
            }
        },
        prog: None,
    }
}

fn xyz(x: f64, y: f64, z: f64) -> Pos {
    [x, y, z, 0.0, 0.0, 0.0]
}

fn run(d: &mut Drawing, evs: &[Event]) {
    let mut from = xyz(500.0, 500.0, 500.0);
    for e in evs {
        d.add(e, &from, Rot::Off);
        from = e.motion().unwrap().to;
    }
}

/// A 100 mm square cut with T1 from X0 Y0, then a hole drilled at X30
/// Y40 (a plunge that does not move in XY).
fn square_and_hole() -> Drawing {
    let mut d = Drawing::new(MachineKind::Mill);
    run(
        &mut d,
        &[
            motion(true, 1, xyz(0.0, 0.0, 0.0)),
            motion(false, 1, xyz(100.0, 0.0, 0.0)),
            motion(false, 1, xyz(100.0, 100.0, 0.0)),
            motion(false, 1, xyz(0.0, 100.0, 0.0)),
            motion(false, 1, xyz(0.0, 0.0, 0.0)),
            motion(true, 1, xyz(30.0, 40.0, 5.0)),
            motion(false, 1, xyz(30.0, 40.0, -5.0)),
        ],
    );
    d
}

// The square's extent is 0-100 mm with a 5 mm margin: 110 mm on the
// 680-px area, s = 6.1818 px/mm; the area's top left is (90, 56) (8 px
// of border and the 48-px title). X0 Y0 is then at
// (90 + 5s, 56 + 105s) = (120.91, 705.09) and X100 Y100 at
// (90 + 105s, 56 + 5s) = (739.09, 86.91).

#[test]
fn the_square_has_its_corners_at_the_scale() {
    let svg = String::from_utf8(render(&mut square_and_hole(), PlotFormat::Svg).unwrap()).unwrap();
    assert!(
        svg.contains(
            "<path d=\"M120.91 705.09L739.09 705.09L739.09 86.91L120.91 86.91L120.91 705.09\" fill=\"none\" stroke=\"#003399\" stroke-width=\"1.5\"/>"
        ),
        "{svg}"
    );
}

#[test]
fn ticks_every_20_mm_are_labelled_under_their_place() {
    // 70 px is 11.3 mm: the step is 20 mm. The labels sit 19 px under
    // the area's bottom edge (56 + 680 = 736) at the ticks' x.
    let svg = String::from_utf8(render(&mut square_and_hole(), PlotFormat::Svg).unwrap()).unwrap();
    let s = 680.0 / 110.0;
    for k in 0..=5 {
        let v = 20.0 * k as f64;
        let x = svg::num(90.0 + (v + 5.0) * s);
        let want = format!("<text x=\"{x}\" y=\"755\" font-size=\"12\" text-anchor=\"middle\" fill=\"#222222\">{v}</text>");
        assert!(svg.contains(&want), "{want}\n{svg}");
    }
    // Y ticks: right-aligned 8 px left of the area, 4 px below the tick.
    let y = svg::num(56.0 + (105.0 - 60.0) * s + 4.0);
    assert!(svg.contains(&format!(
        "<text x=\"82\" y=\"{y}\" font-size=\"12\" text-anchor=\"end\" fill=\"#222222\">60</text>"
    )));
    assert!(svg.contains(">X mm<") && svg.contains(">Y mm<"));
    assert!(svg.contains(">T1 cutting<") && svg.contains(">rapid<"));
}

#[test]
fn the_drilled_hole_is_a_ring_at_its_xy() {
    // X30 Y40: (90 + 35s, 56 + 65s) = (306.36, 457.82), a 4-px ring.
    let svg = String::from_utf8(render(&mut square_and_hole(), PlotFormat::Svg).unwrap()).unwrap();
    assert!(
        svg.contains("<path d=\"M302.36 457.82a4 4 0 1 0 8 0a4 4 0 1 0 -8 0\" fill=\"none\" stroke=\"#003399\""),
        "{svg}"
    );
    assert!(svg.contains(">hole / plunge<"));
}

#[test]
fn the_png_shows_the_same_geometry() {
    let png = render(&mut square_and_hole(), PlotFormat::Png).unwrap();
    let pm = Pixmap::decode_png(&png).unwrap();
    assert_eq!((pm.width(), pm.height()), (1000, 792));
    let px = |x: u32, y: u32| {
        let c = pm.pixel(x, y).unwrap().demultiply();
        (c.red() as i32, c.green() as i32, c.blue() as i32)
    };
    let blue = |c: (i32, i32, i32)| c.2 - c.0 > 60;
    // The bottom edge of the square (y 705.09) in the middle, the right
    // edge (x 739.09), the hole's ring at its rightmost point (310.36).
    assert!(blue(px(430, 705)), "{:?}", px(430, 705));
    assert!(blue(px(739, 414)), "{:?}", px(739, 414));
    assert!(blue(px(310, 458)), "{:?}", px(310, 458));
    // Inside the square away from the grid lines: white.
    assert_eq!(px(430, 394), (255, 255, 255));
    // The ring's centre is not inked in the tool's colour.
    assert!(!blue(px(306, 456)));
}

#[test]
fn a_lathe_picture_holds_the_centre_line_and_the_chuck() {
    // A turned diameter at X radius 20-30 from Z0 to Z-50: the centre
    // line X0 is brought into view, dashed grey across the area.
    let mut d = Drawing::new(MachineKind::Lathe);
    run(
        &mut d,
        &[
            motion(true, 1, xyz(30.0, 0.0, 2.0)),
            motion(false, 1, xyz(20.0, 0.0, 0.0)),
            motion(false, 1, xyz(20.0, 0.0, -50.0)),
            motion(false, 1, xyz(30.0, 0.0, -50.0)),
        ],
    );
    let svg = String::from_utf8(render(&mut d, PlotFormat::Svg).unwrap()).unwrap();
    // Side 52 mm (Z-50..2; X0..30): 2.6 mm margin, 6.24 mm more for the
    // chuck left of Z-50; the area spans Z-58.84..4.6 = 63.44 mm and
    // ..32.6 = 35.2 mm at s = 680 / 63.44. X0 is at 56 + 32.6 s.
    let s = 680.0 / 63.44;
    let y0 = svg::num(56.0 + 32.6 * s);
    let want = format!(
        "<path d=\"M90 {y0}L770 {y0}\" fill=\"none\" stroke=\"#888888\" stroke-width=\"1\" stroke-dasharray=\"12 4\"/>"
    );
    assert!(svg.contains(&want), "{want}\n{svg}");
    assert!(svg.contains(">chuck<") && svg.contains(">spindle centre<"));
    assert!(svg.contains(">Z mm<") && svg.contains(">X mm<"));
}

#[test]
fn the_alarm_point_is_crossed_and_named() {
    let mut d = square_and_hole();
    d.mark_stop("alarm F_82001 line 7".into(), &[0.0; 6]);
    let svg = String::from_utf8(render(&mut d, PlotFormat::Svg).unwrap()).unwrap();
    // The last point X30 Y40 at (306.36, 457.82), a 7-px cross.
    assert!(
        svg.contains("<path d=\"M299.36 450.82L313.36 464.82M299.36 464.82L313.36 450.82\" fill=\"none\" stroke=\"#dd0000\""),
        "{svg}"
    );
    assert!(svg.contains(">alarm F_82001<") && svg.contains(">line 7<"));
}

#[test]
fn the_format_follows_the_extension() {
    assert_eq!(PlotFormat::of_path(Path::new("a/b.PNG")), PlotFormat::Png);
    assert_eq!(PlotFormat::of_path(Path::new("b.svg")), PlotFormat::Svg);
    assert_eq!(PlotFormat::of_path(Path::new("plot")), PlotFormat::Svg);
}

#[test]
fn a_dense_raster_stays_under_5_mb() {
    // 400 rows 0.01 mm apart of 1,000 moves each: 400,000 distinct moves.
    let mut d = Drawing::new(MachineKind::Mill);
    let mut evs = Vec::new();
    for row in 0..400 {
        for k in 0..1000 {
            let x = if row % 2 == 0 {
                k as f64 * 0.1
            } else {
                100.0 - k as f64 * 0.1
            };
            evs.push(motion(false, 1, xyz(x, row as f64 * 0.01, 0.0)));
        }
    }
    run(&mut d, &evs);
    let svg = render(&mut d, PlotFormat::Svg).unwrap();
    assert!(svg.len() < 5_000_000, "{}", svg.len());
    let png = render(&mut d, PlotFormat::Png).unwrap();
    assert!(png.len() < 5_000_000, "{}", png.len());
}

#[test]
fn the_program_start_is_a_square_where_the_first_rapid_ends() {
    // The first rapid ends at X0 Y0: (120.91, 705.09), a square of 8 px
    // about it, and a legend row.
    let svg = String::from_utf8(render(&mut square_and_hole(), PlotFormat::Svg).unwrap()).unwrap();
    assert!(
        svg.contains("<rect x=\"116.91\" y=\"701.09\" width=\"8\" height=\"8\" fill=\"none\" stroke=\"#222222\""),
        "{svg}"
    );
    assert!(svg.contains(">program start<"));
}

#[test]
fn a_program_start_out_of_view_is_not_drawn_nor_listed() {
    // First to X2000 Y2000, far beyond 25 % of the 100 mm square around
    // the cuts: the start is cut off, so neither square nor legend row.
    let mut d = Drawing::new(MachineKind::Mill);
    run(
        &mut d,
        &[
            motion(true, 1, xyz(2000.0, 2000.0, 0.0)),
            motion(true, 1, xyz(0.0, 0.0, 0.0)),
            motion(false, 1, xyz(100.0, 0.0, 0.0)),
            motion(false, 1, xyz(100.0, 100.0, 0.0)),
        ],
    );
    let svg = String::from_utf8(render(&mut d, PlotFormat::Svg).unwrap()).unwrap();
    assert!(!svg.contains(">program start<"), "{svg}");
    assert!(!svg.contains("width=\"8\" height=\"8\""), "{svg}");
}

/// A 100 mm square rastered in rows 0.2 mm apart on a ramp from Z-10 at
/// X0 to Z0 at X100: dense enough that lines would fill it.
fn ramp_raster() -> Drawing {
    let mut d = Drawing::new(MachineKind::Mill);
    let mut evs = vec![motion(true, 1, xyz(0.0, 0.0, 5.0))];
    for row in 0..=500 {
        let y = row as f64 * 0.2;
        let (a, b) = if row % 2 == 0 {
            (0.0, 100.0)
        } else {
            (100.0, 0.0)
        };
        evs.push(motion(false, 1, xyz(a, y, a / 10.0 - 10.0)));
        evs.push(motion(false, 1, xyz(b, y, b / 10.0 - 10.0)));
    }
    run(&mut d, &evs);
    d
}

#[test]
fn a_dense_surface_is_drawn_by_its_depth() {
    // The map's cell is 0.25 mm (100 mm over 512 cells, a power of two),
    // each holding the lowest Z in it. The area is the square's as
    // above: s = 680/110 px/mm, X = (px - 90)/s - 5, Y = 105 - (py - 56)/s.
    let mut d = ramp_raster();
    assert!(d.depth_view().is_some());
    let png = render(&mut d, PlotFormat::Png).unwrap();
    let pm = Pixmap::decode_png(&png).unwrap();
    let px = |x: u32, y: u32| {
        let c = pm.pixel(x, y).unwrap().demultiply();
        [c.red() as f64, c.green() as f64, c.blue() as f64]
    };
    let near =
        |got: [f64; 3], want: [f64; 3]| got.iter().zip(want).all(|(g, w)| (g - w).abs() <= 2.0);
    // The slope dZ/dX = 0.1 lit from the upper left: (0.1 + 1.5) /
    // (√1.01 · √4.25) = 0.7704, light 0.55 + 0.45 · 0.7704 = 0.8967.
    let light = 0.8967;
    // Pixel (134, 396): X 2.198 in the cell 2.0-2.25, lowest Z -9.8, a
    // share 0.02 of the range -10..0: 0.08 of the way from the ramp's
    // first stop (68, 1, 84) to its second (59, 82, 139).
    let lo = [67.28 * light, 7.48 * light, 88.4 * light];
    assert!(near(px(134, 396), lo), "{:?} {lo:?}", px(134, 396));
    // Pixel (726, 396): X 97.96 in the cell 97.75-98.0, Z -0.225, share
    // 0.9775: 0.91 of the way from (94, 201, 98) to (253, 231, 37).
    let hi = [238.7 * light, 228.3 * light, 42.5 * light];
    assert!(near(px(726, 396), hi), "{:?} {hi:?}", px(726, 396));
    // The legend gives the range instead of the tool's line; the SVG
    // holds the same picture as an embedded PNG.
    let svg = String::from_utf8(render(&mut d, PlotFormat::Svg).unwrap()).unwrap();
    assert!(
        svg.contains(">-10 to 0 mm<") && !svg.contains(">T1 cutting<"),
        "{svg}"
    );
    assert!(svg.contains("<image x=\"90\" y=\"56\" width=\"680\" height=\"680\""));
    assert!(svg.contains("href=\"data:image/png;base64,iVBORw0KGgo"));
}

#[test]
fn a_few_cuts_stay_lines() {
    // The square and the hole cover a few percent of their box.
    let d = square_and_hole();
    assert!(d.depth_view().is_none());
}
