//! The picture's items rasterised with tiny-skia and encoded as a PNG
//! (8-bit RGBA). Text uses the public-domain 8×8 bitmap font of the
//! `font8x8` crate, each set bit a block of `size / 8` pixels snapped to
//! whole pixels, so labels stay sharp.

use std::io;

use font8x8::legacy::BASIC_LEGACY;
use tiny_skia::{
    FillRule, IntSize, Mask, Paint, PathBuilder, Pixmap, PixmapPaint, Rect, Stroke, StrokeDash,
    Transform,
};

use super::scene::{arc_points, Anchor, Item, Pen, Rgb, Seg};

/// The PNG bytes of a picture `width` × `height` px; an error when the
/// picture cannot be allocated or encoded.
pub fn write(items: &[Item], width: f64, height: f64) -> io::Result<Vec<u8>> {
    let mut pm = Pixmap::new(width.ceil() as u32, height.ceil() as u32)
        .ok_or_else(|| io::Error::other(format!("cannot make a {width}x{height} picture")))?;
    let mut mask = None;
    for it in items {
        if let Item::Clip(c) = it {
            mask = c.and_then(|(at, w, h)| clip(&pm, at, w, h));
            continue;
        }
        draw(&mut pm, it, mask.as_ref());
    }
    pm.encode_png().map_err(io::Error::other)
}

/// A mask letting through a rectangle.
fn clip(pm: &Pixmap, at: (f64, f64), w: f64, h: f64) -> Option<Mask> {
    let mut m = Mask::new(pm.width(), pm.height())?;
    let r = Rect::from_xywh(at.0 as f32, at.1 as f32, w as f32, h as f32)?;
    let path = PathBuilder::from_rect(r);
    m.fill_path(&path, FillRule::Winding, false, Transform::identity());
    Some(m)
}

fn paint((r, g, b): Rgb, aa: bool) -> Paint<'static> {
    let mut p = Paint::default();
    p.set_color_rgba8(r, g, b, 255);
    p.anti_alias = aa;
    p
}

fn stroke(pm: &mut Pixmap, pb: PathBuilder, pen: &Pen, mask: Option<&Mask>) {
    let Some(path) = pb.finish() else { return };
    let st = Stroke {
        width: pen.width as f32,
        dash: pen
            .dash
            .and_then(|(d, g)| StrokeDash::new(vec![d as f32, g as f32], 0.0)),
        ..Stroke::default()
    };
    pm.stroke_path(
        &path,
        &paint(pen.colour, true),
        &st,
        Transform::identity(),
        mask,
    );
}

fn draw(pm: &mut Pixmap, it: &Item, mask: Option<&Mask>) {
    match it {
        Item::Path { segs, pen } => {
            let mut pb = PathBuilder::new();
            let mut cur = (0.0, 0.0);
            for seg in segs {
                match *seg {
                    Seg::Move(p) => {
                        pb.move_to(p.0 as f32, p.1 as f32);
                        cur = p;
                    }
                    Seg::Line(p) => {
                        pb.line_to(p.0 as f32, p.1 as f32);
                        cur = p;
                    }
                    Seg::Arc { to, c, r, sweep } => {
                        for p in arc_points(cur, c, r, sweep, to) {
                            pb.line_to(p.0 as f32, p.1 as f32);
                        }
                        cur = to;
                    }
                }
            }
            stroke(pm, pb, pen, mask);
        }
        Item::Rings { at, r, pen } => {
            let mut pb = PathBuilder::new();
            for p in at {
                pb.push_circle(p.0 as f32, p.1 as f32, *r as f32);
            }
            stroke(pm, pb, pen, mask);
        }
        Item::Rect {
            at,
            w,
            h,
            fill,
            pen,
        } => {
            let Some(rect) = Rect::from_xywh(at.0 as f32, at.1 as f32, *w as f32, *h as f32) else {
                return;
            };
            if let Some(f) = fill {
                pm.fill_rect(rect, &paint(*f, false), Transform::identity(), mask);
            }
            if let Some(pen) = pen {
                let mut pb = PathBuilder::new();
                pb.push_rect(rect);
                stroke(pm, pb, pen, mask);
            }
        }
        Item::Text {
            at,
            size,
            anchor,
            colour,
            text,
        } => text_at(pm, *at, *size, *anchor, *colour, text),
        Item::Image { at, w, h, rgba } => {
            if let Some(img) = image(*w, *h, rgba) {
                let (x, y) = (at.0.round() as i32, at.1.round() as i32);
                let paint = PixmapPaint::default();
                pm.draw_pixmap(x, y, img.as_ref(), &paint, Transform::identity(), mask);
            }
        }
        Item::Clip(_) => {}
    }
}

/// An image's pixels as a pixmap (alpha is 0 or 255, so straight and
/// premultiplied RGBA are the same); None when the size does not match.
pub fn image(w: u32, h: u32, rgba: &[u8]) -> Option<Pixmap> {
    let size = IntSize::from_wh(w, h)?;
    Pixmap::from_vec(rgba.to_vec(), size)
}

/// Width of a text in the bitmap font, px.
pub fn text_width(text: &str, size: f64) -> f64 {
    text.chars().count() as f64 * size * 0.75
}

/// Draws `text` with its baseline at `at.1`.
fn text_at(pm: &mut Pixmap, at: (f64, f64), size: f64, anchor: Anchor, c: Rgb, text: &str) {
    // The glyphs are 8 units high; the advance is 6 of them (the font's
    // glyphs leave their two right columns empty).
    let s = size / 8.0;
    let w = text_width(text, size);
    let x0 = match anchor {
        Anchor::Start => at.0,
        Anchor::Middle => at.0 - w / 2.0,
        Anchor::End => at.0 - w,
    };
    // Row 7 is below the baseline (descenders).
    let top = at.1 - 7.0 * s;
    let mut pb = PathBuilder::new();
    for (i, ch) in text.chars().enumerate() {
        let glyph = BASIC_LEGACY.get(ch as usize).copied().unwrap_or([0; 8]);
        let gx = x0 + i as f64 * 6.0 * s;
        for (row, bits) in glyph.iter().enumerate() {
            for col in 0..8 {
                if bits & (1 << col) == 0 {
                    continue;
                }
                let x = (gx + col as f64 * s).round();
                let y = (top + row as f64 * s).round();
                let x1 = (gx + (col + 1) as f64 * s).round();
                let y1 = (top + (row + 1) as f64 * s).round();
                if let Some(r) = Rect::from_ltrb(x as f32, y as f32, x1 as f32, y1 as f32) {
                    pb.push_rect(r);
                }
            }
        }
    }
    if let Some(path) = pb.finish() {
        pm.fill_path(
            &path,
            &paint(c, false),
            FillRule::Winding,
            Transform::identity(),
            None,
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sinks::plot::scene::INK;

    fn decode(png: &[u8]) -> Pixmap {
        Pixmap::decode_png(png).unwrap()
    }

    #[test]
    fn a_line_is_drawn_where_it_is_placed() {
        // A 3 px black line across row 20 of a 40 × 40 picture.
        let items = [
            Item::Rect {
                at: (0.0, 0.0),
                w: 40.0,
                h: 40.0,
                fill: Some((255, 255, 255)),
                pen: None,
            },
            Item::Path {
                segs: vec![Seg::Move((0.0, 20.0)), Seg::Line((40.0, 20.0))],
                pen: Pen::solid(INK, 3.0),
            },
        ];
        let pm = decode(&write(&items, 40.0, 40.0).unwrap());
        let at = |x: u32, y: u32| pm.pixel(x, y).unwrap();
        assert_eq!((at(10, 20).red(), at(10, 20).alpha()), (INK.0, 255));
        assert_eq!(at(10, 10).red(), 255);
        assert_eq!(at(10, 30).red(), 255);
    }

    #[test]
    fn text_is_drawn_left_of_an_end_anchor() {
        let items = [Item::Text {
            at: (60.0, 20.0),
            size: 16.0,
            anchor: Anchor::End,
            colour: INK,
            text: "88".into(),
        }];
        let pm = decode(&write(&items, 80.0, 30.0).unwrap());
        let inked = |x0: u32, x1: u32| {
            (x0..x1).any(|x| (0..30).any(|y| pm.pixel(x, y).unwrap().alpha() > 0))
        };
        // Two glyphs of 12 px advance end at x = 60.
        assert!(inked(36, 60));
        assert!(!inked(0, 36) && !inked(61, 80));
    }
}
