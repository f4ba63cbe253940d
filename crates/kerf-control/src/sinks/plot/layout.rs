//! Where everything goes in the picture, in pixels, for the SVG and the
//! PNG alike: each panel's plot area and scale (the same mm per pixel
//! across and up), its ticks, the legend column.
//!
//! The picture is [`WIDTH`] pixels wide. A panel's plot area starts
//! [`LEFT`] pixels from the left edge (room for the tick labels) and is at
//! most [`AREA`] pixels wide and high; the drawing's extent plus a margin
//! of [`PAD`] of its larger side fills it at one scale. The legend column
//! starts at [`LEGEND_X`].

use super::drawing::{Panel, View};

/// Picture width, px.
pub const WIDTH: f64 = 1000.0;
/// Left edge of the plot areas, px.
pub const LEFT: f64 = 90.0;
/// Largest plot area side, px.
pub const AREA: f64 = 680.0;
/// Smallest plot area side, px.
pub const MIN_AREA: f64 = 160.0;
/// Left edge of the legend column, px.
pub const LEGEND_X: f64 = LEFT + AREA + 30.0;
/// Space above a plot area (the panel title, the vertical axis title), px.
pub const TITLE_H: f64 = 48.0;
/// Space below a plot area (tick labels, axis title), px.
pub const BOTTOM_H: f64 = 56.0;
/// Margin around the extent, a fraction of its larger side.
pub const PAD: f64 = 0.05;
/// Least distance between two ticks, px.
pub const MIN_TICK_PX: f64 = 70.0;
/// Smallest extent shown, mm: a point is drawn in a 1 mm square.
pub const MIN_SIDE: f64 = 1.0;
/// Rapids this far from the cuts are shown whole, a fraction of the
/// cuts' larger side.
pub const NEAR: f64 = 0.25;
/// Lathe: room left of the extent for the chuck, a fraction of the
/// larger side.
pub const CHUCK: f64 = 0.12;

/// One panel's place and scale.
#[derive(Clone, Debug, PartialEq)]
pub struct PanelLayout {
    /// Index into `Drawing::panels`.
    pub index: usize,
    /// What it shows.
    pub view: View,
    /// Top left of the plot area, px.
    pub left: f64,
    /// Top edge of the plot area, px.
    pub top: f64,
    /// Plot area width and height, px.
    pub w: f64,
    /// Plot area height, px.
    pub h: f64,
    /// View coordinates of the area's bottom left corner.
    pub lo: (f64, f64),
    /// View coordinates of the area's top right corner.
    pub hi: (f64, f64),
    /// Pixels per mm (or degree).
    pub scale: f64,
    /// Distance between ticks, mm, 1, 2 or 5 × 10ⁿ.
    pub step: f64,
    /// Lathe: the chuck's right edge, view u (its jaws are left of it).
    pub chuck: Option<f64>,
}

impl PanelLayout {
    /// Pixel position of a view point.
    pub fn px(&self, p: (f64, f64)) -> (f64, f64) {
        (
            self.left + (p.0 - self.lo.0) * self.scale,
            self.top + (self.hi.1 - p.1) * self.scale,
        )
    }

    /// Tick values along u (horizontal) inside the area.
    pub fn ticks_u(&self) -> Vec<f64> {
        ticks(self.lo.0, self.hi.0, self.step)
    }

    /// Tick values along v (vertical) inside the area.
    pub fn ticks_v(&self) -> Vec<f64> {
        ticks(self.lo.1, self.hi.1, self.step)
    }

    /// A tick value as its label: as many decimals as the step needs.
    pub fn label(&self, v: f64) -> String {
        let dec = (-self.step.log10().floor()).max(0.0) as usize;
        let t = format!("{v:.dec$}");
        if t.trim_start_matches('-')
            .trim_matches(['0', '.'])
            .is_empty()
        {
            "0".into()
        } else {
            t
        }
    }
}

/// Multiples of `step` from `lo` to `hi`.
fn ticks(lo: f64, hi: f64, step: f64) -> Vec<f64> {
    let first = (lo / step).ceil() as i64;
    let last = (hi / step).floor() as i64;
    (first..=last).map(|k| k as f64 * step).collect()
}

/// The smallest 1, 2 or 5 × 10ⁿ at least `min`.
pub fn nice_step(min: f64) -> f64 {
    let k = 10f64.powf(min.log10().floor());
    [1.0, 2.0, 5.0, 10.0]
        .into_iter()
        .map(|m| m * k)
        .find(|s| *s >= min * (1.0 - 1e-12))
        .unwrap_or(10.0 * k)
}

/// The whole picture.
#[derive(Clone, Debug, PartialEq)]
pub struct Layout {
    /// Picture width, px.
    pub width: f64,
    /// Picture height, px.
    pub height: f64,
    /// The panels that have something to show, top to bottom.
    pub panels: Vec<PanelLayout>,
    /// Top of the legend column, px.
    pub legend_top: f64,
}

impl Layout {
    /// Lays out the panels of a drawing that have content (the main
    /// panel always when nothing was drawn at all), `legend_rows` rows of
    /// legend beside them.
    /// `keep` is a point that must be in view (the alarm's: panel, point).
    pub fn new(
        panels: &[Panel],
        lathe: bool,
        legend_rows: usize,
        keep: Option<(usize, (f64, f64))>,
    ) -> Layout {
        let mut out = Vec::new();
        let mut top = 8.0 + TITLE_H;
        let others = |i: usize| {
            panels
                .iter()
                .enumerate()
                .any(|(j, p)| j != i && p.bounds().is_some() && p.has_lines())
        };
        for (i, p) in panels.iter().enumerate() {
            let kept = keep.filter(|k| k.0 == i).map(|k| k.1);
            let (mut lo, mut hi) = match p.bounds() {
                // A main panel with only a point in it (the G107 example's
                // start) gives way to a panel that has the path.
                Some(_) if !p.has_lines() && others(i) && kept.is_none() => continue,
                Some(b) => view_extent(b, p.cut_bounds()),
                None if kept.is_some() => (kept.unwrap(), kept.unwrap()),
                None if i == 0 && panels.iter().all(|p| p.bounds().is_none()) => {
                    ((0.0, 0.0), (0.0, 0.0))
                }
                None => continue,
            };
            if let Some(k) = kept {
                lo = (lo.0.min(k.0), lo.1.min(k.1));
                hi = (hi.0.max(k.0), hi.1.max(k.1));
            }
            let bounds = (lo, hi);
            let pl = place(i, p.view, bounds, lathe && i == 0, top);
            top = pl.top + pl.h + BOTTOM_H + TITLE_H;
            out.push(pl);
        }
        let bottom = top - TITLE_H;
        let legend_top = 8.0 + TITLE_H;
        let legend_bottom = legend_top + legend_rows as f64 * 22.0 + 10.0;
        Layout {
            width: WIDTH,
            height: bottom.max(legend_bottom).ceil(),
            panels: out,
            legend_top,
        }
    }
}

/// What a panel shows: the cutting moves and the rapids near them. A
/// rapid to a far home or tool change position would make the part a
/// speck; past [`NEAR`] of the cuts' larger side around them it is cut
/// off at the frame.
fn view_extent(
    all: ((f64, f64), (f64, f64)),
    cut: Option<((f64, f64), (f64, f64))>,
) -> ((f64, f64), (f64, f64)) {
    let Some((lo, hi)) = cut else { return all };
    let m = NEAR * (hi.0 - lo.0).max(hi.1 - lo.1).max(MIN_SIDE);
    (
        (all.0 .0.max(lo.0 - m), all.0 .1.max(lo.1 - m)),
        (all.1 .0.min(hi.0 + m), all.1 .1.min(hi.1 + m)),
    )
}

/// One panel's area and scale for an extent.
fn place(
    index: usize,
    view: View,
    (min, max): ((f64, f64), (f64, f64)),
    lathe: bool,
    top: f64,
) -> PanelLayout {
    let (mut min, mut max) = (min, max);
    if lathe {
        // The spindle centre line (X0) is always in view.
        min.1 = min.1.min(0.0);
        max.1 = max.1.max(0.0);
    }
    // A point or a short move is shown in at least MIN_SIDE mm.
    for (l, h) in [(&mut min.0, &mut max.0), (&mut min.1, &mut max.1)] {
        if *h - *l < MIN_SIDE {
            let mid = 0.5 * (*l + *h);
            (*l, *h) = (mid - 0.5 * MIN_SIDE, mid + 0.5 * MIN_SIDE);
        }
    }
    let side = (max.0 - min.0).max(max.1 - min.1);
    let chuck = lathe.then(|| {
        let right = min.0 - PAD * side;
        min.0 -= CHUCK * side;
        right
    });
    let pad = PAD * side;
    let (mut lo, mut hi) = ((min.0 - pad, min.1 - pad), (max.0 + pad, max.1 + pad));
    let scale = (AREA / (hi.0 - lo.0)).min(AREA / (hi.1 - lo.1));
    // A flat or narrow extent gets an area of at least MIN_AREA, centred.
    for (l, h) in [(&mut lo.0, &mut hi.0), (&mut lo.1, &mut hi.1)] {
        let need = MIN_AREA / scale;
        if *h - *l < need {
            let mid = 0.5 * (*l + *h);
            (*l, *h) = (mid - 0.5 * need, mid + 0.5 * need);
        }
    }
    PanelLayout {
        index,
        view,
        left: LEFT,
        top,
        w: (hi.0 - lo.0) * scale,
        h: (hi.1 - lo.1) * scale,
        lo,
        hi,
        scale,
        step: nice_step(MIN_TICK_PX / scale),
        chuck,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_far_rapid_does_not_shrink_the_part() {
        // Cuts over 0..100 × 0..50, a rapid out to X400 Y250: the view is
        // the cuts and 25 mm (25 % of 100) around them, within the whole.
        let v = view_extent(
            ((0.0, 0.0), (400.0, 250.0)),
            Some(((0.0, 0.0), (100.0, 50.0))),
        );
        assert_eq!(v, ((0.0, 0.0), (125.0, 75.0)));
        // Without cuts, everything.
        assert_eq!(
            view_extent(((1.0, 2.0), (3.0, 4.0)), None),
            ((1.0, 2.0), (3.0, 4.0))
        );
    }

    #[test]
    fn steps_are_round_numbers() {
        assert_eq!(nice_step(12.0), 20.0);
        assert_eq!(nice_step(20.0), 20.0);
        assert_eq!(nice_step(0.3), 0.5);
        assert_eq!(nice_step(6.0), 10.0);
        assert!((nice_step(0.0011) - 0.002).abs() < 1e-15);
    }

    #[test]
    fn labels_have_the_decimals_of_the_step() {
        let mut p = place(0, View::MillXy, ((0.0, 0.0), (1.0, 1.0)), false, 0.0);
        p.step = 0.5;
        assert_eq!(p.label(1.5), "1.5");
        assert_eq!(p.label(-0.0), "0");
        p.step = 20.0;
        assert_eq!(p.label(-40.0), "-40");
    }

    #[test]
    fn a_square_fills_the_area_at_one_scale() {
        // 0..100 mm both ways, 5 mm margin: 110 mm on 680 px.
        let p = place(0, View::MillXy, ((0.0, 0.0), (100.0, 100.0)), false, 42.0);
        let s = 680.0 / 110.0;
        assert!((p.scale - s).abs() < 1e-12);
        assert_eq!((p.w.round(), p.h.round()), (680.0, 680.0));
        // X0 Y0 is 5 mm in from the left and bottom edges.
        let (x, y) = p.px((0.0, 0.0));
        assert!((x - (90.0 + 5.0 * s)).abs() < 1e-9);
        assert!((y - (42.0 + 105.0 * s)).abs() < 1e-9);
        // 70 px is 11.3 mm: ticks every 20 mm, 0 to 100.
        assert_eq!(p.step, 20.0);
        assert_eq!(p.ticks_u(), vec![0.0, 20.0, 40.0, 60.0, 80.0, 100.0]);
    }

    #[test]
    fn a_lathe_panel_holds_the_centre_line_and_the_chuck() {
        // A part from Z-50 to Z0, radius 20 to 30: side 50, the centre
        // line X0 brought in, the chuck 6 mm left of Z-50.
        let p = place(0, View::LatheZx, ((-50.0, 20.0), (0.0, 30.0)), true, 0.0);
        assert!(p.lo.1 < 0.0 && p.hi.1 > 30.0);
        assert_eq!(p.chuck, Some(-52.5));
        assert!((p.lo.0 - (-50.0 - 6.0 - 2.5)).abs() < 1e-12);
    }
}
