//! The picture as a list of drawing items in pixels (paths, rings, text,
//! rectangles), built once from a [`Drawing`] and its [`Layout`] and
//! written by both the SVG and the PNG writer, so the two show the same.
//!
//! Per panel: a light grid at the ticks, the frame, tick marks and
//! labels in mm (G107's C developed on its cylinder), the axis titles, the panel title;
//! on a lathe the spindle centre line (dashed grey) and the chuck on the
//! −Z side; the toolpath (rapids dashed red, cuts solid in one colour per
//! tool, holes as rings); the alarm point as a red cross. Beside the
//! panels, the legend.

use std::f64::consts::PI;

use super::drawing::{Drawing, Form, Shape};
use super::layout::{Layout, PanelLayout, LEGEND_X};
use super::shade;

/// A point, px.
pub type P = (f64, f64);

/// An sRGB colour.
pub type Rgb = (u8, u8, u8);

/// Rapid traverse colour.
pub const RAPID: Rgb = (0xd3, 0x33, 0x33);
/// Cut colours, by tool in order of first cut.
pub const TOOLS: &[Rgb] = &[
    (0x00, 0x33, 0x99),
    (0x1a, 0x7f, 0x37),
    (0x82, 0x50, 0xdf),
    (0xbf, 0x87, 0x00),
    (0x09, 0x69, 0xda),
    (0xe1, 0x6f, 0x24),
    (0x57, 0x60, 0x6a),
    (0x00, 0x99, 0x99),
];
/// Text and frame colour.
pub const INK: Rgb = (0x22, 0x22, 0x22);
/// Grid colour.
pub const GRID: Rgb = (0xe4, 0xe4, 0xe4);
/// Centre line and chuck colour.
pub const GREY: Rgb = (0x88, 0x88, 0x88);
/// Alarm colour.
pub const ALARM: Rgb = (0xdd, 0x00, 0x00);

/// Ring radius of a hole, px.
pub const HOLE_R: f64 = 4.0;
/// Half size of the alarm cross, px.
pub const CROSS: f64 = 7.0;
/// Half the side of the program start's square, px.
pub const START: f64 = 4.0;
/// Tick label size, px.
pub const SMALL: f64 = 12.0;
/// Title and legend text size, px.
pub const LARGE: f64 = 14.0;

/// The colour of a shape class (0 rapid, 1 + n the n-th tool).
pub fn colour(class: u16) -> Rgb {
    if class == 0 {
        RAPID
    } else {
        TOOLS[(class as usize - 1) % TOOLS.len()]
    }
}

/// One piece of a path.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Seg {
    /// Start a new subpath here.
    Move(P),
    /// A straight line to here.
    Line(P),
    /// A circular arc to `to` about `c`, radius `r`, `sweep` radians
    /// (positive counter-clockwise as seen on the screen).
    Arc { to: P, c: P, r: f64, sweep: f64 },
}

/// How a line is drawn.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pen {
    /// Colour.
    pub colour: Rgb,
    /// Width, px.
    pub width: f64,
    /// Dash and gap lengths, px; None solid.
    pub dash: Option<(f64, f64)>,
}

impl Pen {
    /// A solid pen.
    pub fn solid(colour: Rgb, width: f64) -> Pen {
        Pen {
            colour,
            width,
            dash: None,
        }
    }

    /// A dashed pen.
    pub fn dashed(colour: Rgb, width: f64, dash: f64, gap: f64) -> Pen {
        Pen {
            colour,
            width,
            dash: Some((dash, gap)),
        }
    }
}

/// Where a text's anchor point is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Anchor {
    /// The text starts at the point.
    Start,
    /// The text is centred on the point.
    Middle,
    /// The text ends at the point.
    End,
}

/// One drawing item, px.
#[derive(Clone, Debug, PartialEq)]
pub enum Item {
    /// A path stroked with a pen.
    Path { segs: Vec<Seg>, pen: Pen },
    /// Rings of radius `r` at the centres.
    Rings { at: Vec<P>, r: f64, pen: Pen },
    /// A rectangle, filled when `fill` is set, outlined when `pen` is.
    Rect {
        at: P,
        w: f64,
        h: f64,
        fill: Option<Rgb>,
        pen: Option<Pen>,
    },
    /// Items up to the next `Clip` are clipped to this rectangle (top
    /// left, width, height); None ends the clipping.
    Clip(Option<(P, f64, f64)>),
    /// An image drawn one pixel a picture pixel, its top left at `at`:
    /// `w` × `h` RGBA pixels, row by row (alpha 0 or 255).
    Image {
        at: P,
        w: u32,
        h: u32,
        rgba: Vec<u8>,
    },
    /// Text, its baseline at `at.1`.
    Text {
        at: P,
        size: f64,
        anchor: Anchor,
        colour: Rgb,
        text: String,
    },
}

fn text(at: P, size: f64, anchor: Anchor, s: impl Into<String>) -> Item {
    Item::Text {
        at,
        size,
        anchor,
        colour: INK,
        text: s.into(),
    }
}

/// The pen of the toolpath's rapids and cuts.
pub fn path_pen(class: u16) -> Pen {
    if class == 0 {
        Pen::dashed(RAPID, 1.0, 5.0, 4.0)
    } else {
        Pen::solid(colour(class), 1.5)
    }
}

/// The whole picture.
pub fn build(d: &Drawing, l: &Layout) -> Vec<Item> {
    let mut items = vec![Item::Rect {
        at: (0.0, 0.0),
        w: l.width,
        h: l.height,
        fill: Some((255, 255, 255)),
        pen: None,
    }];
    for pl in &l.panels {
        frame(&mut items, pl, d);
        items.push(Item::Clip(Some(((pl.left, pl.top), pl.w, pl.h))));
        let depth = d.depth_view().filter(|_| pl.index == 0);
        if let Some(map) = depth {
            items.extend(shade::image(map, pl));
        }
        let shapes = d.panels[pl.index].shapes();
        toolpath(&mut items, pl, shapes, d.tools.len(), depth.is_none());
        items.push(Item::Clip(None));
        if let Some(p) = start_in_view(d, pl) {
            start_mark(&mut items, p);
        }
        if let Some((i, p, _)) = &d.stop {
            if *i == pl.index {
                cross(&mut items, pl.px(*p));
            }
        }
    }
    legend(&mut items, d, l);
    items
}

/// The pixel point of the panel's program start, when it is inside the
/// panel's plot area.
fn start_in_view(d: &Drawing, pl: &PanelLayout) -> Option<P> {
    let (x, y) = pl.px(d.panels[pl.index].start()?);
    let inside = |v: f64, lo: f64, len: f64| v >= lo - 0.5 && v <= lo + len + 0.5;
    (inside(x, pl.left, pl.w) && inside(y, pl.top, pl.h)).then_some((x, y))
}

/// The hollow square of the program start.
fn start_mark(items: &mut Vec<Item>, (x, y): P) {
    items.push(Item::Rect {
        at: (x - START, y - START),
        w: 2.0 * START,
        h: 2.0 * START,
        fill: None,
        pen: Some(Pen::solid(INK, 1.5)),
    });
}

/// The red cross of the alarm point.
fn cross(items: &mut Vec<Item>, (x, y): P) {
    let c = CROSS;
    items.push(Item::Path {
        segs: vec![
            Seg::Move((x - c, y - c)),
            Seg::Line((x + c, y + c)),
            Seg::Move((x - c, y + c)),
            Seg::Line((x + c, y - c)),
        ],
        pen: Pen::solid(ALARM, 2.5),
    });
}

/// Grid, frame, ticks, labels, titles, centre line and chuck.
fn frame(items: &mut Vec<Item>, pl: &PanelLayout, d: &Drawing) {
    let (l, t, r, b) = (pl.left, pl.top, pl.left + pl.w, pl.top + pl.h);
    let mut grid = Vec::new();
    let mut marks = Vec::new();
    for u in pl.ticks_u() {
        let x = pl.px((u, 0.0)).0;
        grid.extend([Seg::Move((x, t)), Seg::Line((x, b))]);
        marks.extend([Seg::Move((x, b)), Seg::Line((x, b + 5.0))]);
        items.push(text((x, b + 19.0), SMALL, Anchor::Middle, pl.label(u)));
    }
    for v in pl.ticks_v() {
        let y = pl.px((0.0, v)).1;
        grid.extend([Seg::Move((l, y)), Seg::Line((r, y))]);
        marks.extend([Seg::Move((l - 5.0, y)), Seg::Line((l, y))]);
        items.push(text((l - 8.0, y + 4.0), SMALL, Anchor::End, pl.label(v)));
    }
    items.push(Item::Path {
        segs: grid,
        pen: Pen::solid(GRID, 1.0),
    });
    items.push(Item::Rect {
        at: (l, t),
        w: pl.w,
        h: pl.h,
        fill: None,
        pen: Some(Pen::solid(INK, 1.0)),
    });
    items.push(Item::Path {
        segs: marks,
        pen: Pen::solid(INK, 1.0),
    });
    let (tu, tv) = pl.view.axis_titles();
    items.push(text((l + pl.w / 2.0, b + 42.0), LARGE, Anchor::Middle, tu));
    items.push(text((l, t - 10.0), LARGE, Anchor::End, tv));
    items.push(text((l, t - 30.0), LARGE, Anchor::Start, title(pl, d)));
    if let Some(edge) = pl.chuck {
        lathe_marks(items, pl, edge, d.panels[pl.index].cut_top());
    }
}

/// The panel's title line: the view and the grid.
fn title(pl: &PanelLayout, d: &Drawing) -> String {
    let mut s = pl.view.title().to_string();
    if d.panels[pl.index].polar {
        s.push_str("; G112 on the face, C0 along +X");
    }
    match d.panels[pl.index].radius {
        Some((lo, hi)) if lo == hi => s.push_str(&format!(" on r {lo} mm")),
        Some((lo, hi)) => s.push_str(&format!(" on r {lo} to {hi} mm")),
        None => {}
    }
    format!("{s}; grid {} mm", pl.label(pl.step))
}

/// The spindle centre line across the area and the chuck left of `edge`,
/// as high as the largest radius cut (`top`) or 45 % of the area.
fn lathe_marks(items: &mut Vec<Item>, pl: &PanelLayout, edge: f64, top: Option<f64>) {
    let y0 = pl.px((0.0, 0.0)).1;
    items.push(Item::Path {
        segs: vec![Seg::Move((pl.left, y0)), Seg::Line((pl.left + pl.w, y0))],
        pen: Pen::dashed(GREY, 1.0, 12.0, 4.0),
    });
    let x1 = pl.px((edge, 0.0)).0;
    let x0 = pl.left + 4.0;
    let cut = top.map_or(f64::MAX, |v| 1.1 * v * pl.scale);
    let h = (0.45 * (y0 - pl.top)).min(cut).max(12.0);
    if x1 - x0 >= 4.0 {
        items.push(Item::Rect {
            at: (x0, y0 - h),
            w: x1 - x0,
            h,
            fill: Some((0xcc, 0xcc, 0xcc)),
            pen: Some(Pen::solid(GREY, 1.0)),
        });
        items.push(text(
            ((x0 + x1) / 2.0, y0 - h - 5.0),
            SMALL,
            Anchor::Middle,
            "chuck",
        ));
    }
}

/// One path per class (segments that continue each other chained), the
/// holes as rings in their tool's colour; the cuts' lines only when
/// `cuts` (not over the depth picture, which shows them).
fn toolpath(items: &mut Vec<Item>, pl: &PanelLayout, shapes: &[Shape], tools: usize, cuts: bool) {
    for class in 0..=tools as u16 {
        let mut segs = Vec::new();
        let mut holes = Vec::new();
        let mut at: Option<(f64, f64)> = None;
        for sh in shapes.iter().filter(|s| s.class == class) {
            if sh.form == Form::Hole {
                holes.push(pl.px(sh.a));
                continue;
            }
            if class != 0 && !cuts {
                continue;
            }
            if at != Some(sh.a) {
                segs.push(Seg::Move(pl.px(sh.a)));
            }
            segs.push(match sh.form {
                Form::Arc { c, sweep } => Seg::Arc {
                    to: pl.px(sh.b),
                    c: pl.px(c),
                    r: (sh.a.0 - c.0).hypot(sh.a.1 - c.1) * pl.scale,
                    sweep,
                },
                _ => Seg::Line(pl.px(sh.b)),
            });
            at = Some(sh.b);
        }
        if !segs.is_empty() {
            items.push(Item::Path {
                segs,
                pen: path_pen(class),
            });
        }
        if !holes.is_empty() {
            items.push(Item::Rings {
                at: holes,
                r: HOLE_R,
                pen: Pen::solid(colour(class), 1.5),
            });
        }
    }
}

/// The legend column: rapid, each tool, holes, the lathe's marks, the
/// alarm.
fn legend(items: &mut Vec<Item>, d: &Drawing, l: &Layout) {
    /// The sample drawn before a legend label.
    enum Mark {
        Line(Pen),
        Ring,
        Square,
        Cross,
        Ramp,
        Nothing,
    }
    let mut rows = vec![(Mark::Line(path_pen(0)), "rapid".to_string())];
    match d.depth_view().and_then(|m| m.z_range()) {
        Some((lo, hi)) => {
            rows.push((Mark::Ramp, "cut, lowest Z:".into()));
            rows.push((Mark::Nothing, format!("{} to {} mm", mm(lo), mm(hi))));
        }
        None => {
            for (i, t) in d.tools.iter().enumerate() {
                rows.push((Mark::Line(path_pen(i as u16 + 1)), format!("T{t} cutting")));
            }
        }
    }
    let holes = l
        .panels
        .iter()
        .flat_map(|pl| d.panels[pl.index].shapes())
        .any(|s| s.form == Form::Hole);
    if holes {
        rows.push((Mark::Ring, "hole / plunge".into()));
    }
    if d.kind() == kerf_interp::MachineKind::Lathe {
        let centre = Pen::dashed(GREY, 1.0, 12.0, 4.0);
        rows.push((Mark::Line(centre), "spindle centre".into()));
    }
    if l.panels.iter().any(|pl| start_in_view(d, pl).is_some()) {
        rows.push((Mark::Square, "program start".into()));
    }
    if let Some((_, _, label)) = &d.stop {
        // "alarm CODE" and "line N" on rows of their own.
        let (a, b) = label.split_once(" line ").unwrap_or((label, ""));
        rows.push((Mark::Cross, a.to_string()));
        if !b.is_empty() {
            rows.push((Mark::Nothing, format!("line {b}")));
        }
    }
    let x = LEGEND_X;
    for (k, (mark, label)) in rows.into_iter().enumerate() {
        let y = l.legend_top + 4.0 + 22.0 * k as f64;
        match mark {
            Mark::Line(pen) => items.push(Item::Path {
                segs: vec![Seg::Move((x, y)), Seg::Line((x + 26.0, y))],
                pen,
            }),
            Mark::Ring => items.push(Item::Rings {
                at: vec![(x + 13.0, y)],
                r: HOLE_R,
                pen: Pen::solid(INK, 1.5),
            }),
            Mark::Square => start_mark(items, (x + 13.0, y)),
            Mark::Cross => cross(items, (x + 13.0, y)),
            Mark::Ramp => ramp_mark(items, (x, y)),
            Mark::Nothing => {}
        }
        items.push(text((x + 34.0, y + 5.0), LARGE, Anchor::Start, label));
    }
}

/// A Z to two decimals, without trailing zeros.
fn mm(v: f64) -> String {
    let s = format!("{:.2}", v);
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" {
        "0".into()
    } else {
        s.into()
    }
}

/// The depth ramp as a legend sample: 26 px from lowest to highest.
fn ramp_mark(items: &mut Vec<Item>, (x, y): P) {
    for k in 0..13 {
        items.push(Item::Rect {
            at: (x + 2.0 * k as f64, y - 6.0),
            w: 2.0,
            h: 12.0,
            fill: Some(shade::ramp(k as f64 / 12.0, 1.0)),
            pen: None,
        });
    }
}

/// Points along an arc from `a`, for writers that draw arcs as chords:
/// within about a tenth of a pixel of the circle, the last one `to`.
pub fn arc_points(a: P, c: P, r: f64, sweep: f64, to: P) -> Vec<P> {
    // Sagitta r(1 - cos(θ/2)) ≤ 0.1 px: θ ≤ 2·acos(1 - 0.1/r).
    let step = if r > 0.05 {
        2.0 * (1.0 - 0.1 / r).max(-1.0).acos()
    } else {
        PI
    };
    let n = ((sweep.abs() / step).ceil() as usize).clamp(1, 4096);
    let a0 = (c.1 - a.1).atan2(a.0 - c.0);
    let mut out: Vec<P> = (1..n)
        .map(|k| {
            let t = a0 + sweep * k as f64 / n as f64;
            // Screen y grows downward: a counter-clockwise angle on the
            // screen subtracts from y.
            (c.0 + r * t.cos(), c.1 - r * t.sin())
        })
        .collect();
    out.push(to);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arc_points_follow_the_screen_direction() {
        // A counter-clockwise quarter on the screen from the right of the
        // centre goes up (y decreasing) to the top.
        let pts = arc_points(
            (110.0, 100.0),
            (100.0, 100.0),
            10.0,
            PI / 2.0,
            (100.0, 90.0),
        );
        assert!(pts.len() > 2);
        for p in &pts {
            assert!(((p.0 - 100.0).hypot(p.1 - 100.0) - 10.0).abs() < 1e-9);
            assert!(p.0 >= 100.0 - 1e-9 && p.1 <= 100.0 + 1e-9);
        }
        assert_eq!(*pts.last().unwrap(), (100.0, 90.0));
    }
}
