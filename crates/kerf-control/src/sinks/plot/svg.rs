//! The picture's items as an SVG document, in pixels (one user unit is a
//! pixel of the PNG), coordinates to 0.01 px.

use std::f64::consts::PI;
use std::fmt::Write as _;

use super::scene::{Anchor, Item, Pen, Rgb, Seg};

/// The SVG text of a picture `width` × `height` px.
pub fn write(items: &[Item], width: f64, height: f64) -> String {
    let mut s = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 {width} {height}\" width=\"{width}\" height=\"{height}\" font-family=\"DejaVu Sans, Verdana, sans-serif\">\n"
    );
    let mut clips = 0;
    for it in items {
        if let Item::Clip(c) = it {
            match c {
                Some((at, w, h)) => {
                    clips += 1;
                    let _ = writeln!(
                        s,
                        "<clipPath id=\"area{clips}\"><rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\"/></clipPath><g clip-path=\"url(#area{clips})\">",
                        num(at.0),
                        num(at.1),
                        num(*w),
                        num(*h)
                    );
                }
                None => s.push_str("</g>\n"),
            }
            continue;
        }
        item(&mut s, it);
    }
    s.push_str("</svg>\n");
    s
}

fn hex((r, g, b): Rgb) -> String {
    format!("#{r:02x}{g:02x}{b:02x}")
}

fn pen_attrs(p: &Pen) -> String {
    format!(" fill=\"none\"{}", stroke_attrs(p))
}

fn stroke_attrs(p: &Pen) -> String {
    let mut a = format!(
        " stroke=\"{}\" stroke-width=\"{}\"",
        hex(p.colour),
        num(p.width)
    );
    if let Some((d, g)) = p.dash {
        let _ = write!(a, " stroke-dasharray=\"{} {}\"", num(d), num(g));
    }
    a
}

fn item(s: &mut String, it: &Item) {
    match it {
        Item::Path { segs, pen } => {
            let _ = writeln!(s, "<path d=\"{}\"{}/>", path(segs), pen_attrs(pen));
        }
        Item::Rings { at, r, pen } => {
            let mut d = String::new();
            for p in at {
                // Two half circles.
                let _ = write!(
                    d,
                    "M{} {}a{r} {r} 0 1 0 {} 0a{r} {r} 0 1 0 {} 0",
                    num(p.0 - r),
                    num(p.1),
                    num(2.0 * r),
                    num(-2.0 * r),
                    r = num(*r)
                );
            }
            let _ = writeln!(s, "<path d=\"{d}\"{}/>", pen_attrs(pen));
        }
        Item::Rect {
            at,
            w,
            h,
            fill,
            pen,
        } => {
            let fill = fill.map(hex).unwrap_or_else(|| "none".into());
            let mut a = format!(" fill=\"{fill}\"");
            if let Some(p) = pen {
                a.push_str(&stroke_attrs(p));
            }
            let _ = writeln!(
                s,
                "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\"{a}/>",
                num(at.0),
                num(at.1),
                num(*w),
                num(*h)
            );
        }
        Item::Clip(_) => {}
        Item::Image { at, w, h, rgba } => {
            let Some(png) = super::raster::image(*w, *h, rgba).and_then(|p| p.encode_png().ok())
            else {
                return;
            };
            let _ = writeln!(
                s,
                "<image x=\"{}\" y=\"{}\" width=\"{w}\" height=\"{h}\" image-rendering=\"pixelated\" href=\"data:image/png;base64,{}\"/>",
                num(at.0),
                num(at.1),
                base64(&png)
            );
        }
        Item::Text {
            at,
            size,
            anchor,
            colour,
            text,
        } => {
            let anchor = match anchor {
                Anchor::Start => "start",
                Anchor::Middle => "middle",
                Anchor::End => "end",
            };
            let _ = writeln!(
                s,
                "<text x=\"{}\" y=\"{}\" font-size=\"{}\" text-anchor=\"{anchor}\" fill=\"{}\">{}</text>",
                num(at.0),
                num(at.1),
                num(*size),
                hex(*colour),
                escape(text)
            );
        }
    }
}

/// Standard base64 (RFC 4648, padded) of `bytes`.
fn base64(bytes: &[u8]) -> String {
    const A: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut out = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for c in bytes.chunks(3) {
        let n = (c[0] as u32) << 16
            | (*c.get(1).unwrap_or(&0) as u32) << 8
            | *c.get(2).unwrap_or(&0) as u32;
        for k in 0..4 {
            if k <= c.len() {
                out.push(A[(n >> (18 - 6 * k) & 63) as usize] as char);
            } else {
                out.push('=');
            }
        }
    }
    out
}

/// Path data; arcs as SVG arcs (a full circle as two halves).
fn path(segs: &[Seg]) -> String {
    let mut d = String::new();
    let mut cur = (0.0, 0.0);
    for seg in segs {
        match *seg {
            Seg::Move(p) => {
                let _ = write!(d, "M{} {}", num(p.0), num(p.1));
                cur = p;
            }
            Seg::Line(p) => {
                let _ = write!(d, "L{} {}", num(p.0), num(p.1));
                cur = p;
            }
            Seg::Arc { to, c, r, sweep } => {
                // Counter-clockwise on the screen is SVG's negative angle
                // direction: sweep flag 0.
                let flag = u8::from(sweep < 0.0);
                let rr = num(r);
                if sweep.abs() > 1.999 * PI {
                    let mid = (2.0 * c.0 - cur.0, 2.0 * c.1 - cur.1);
                    let _ = write!(d, "A{rr} {rr} 0 0 {flag} {} {}", num(mid.0), num(mid.1));
                }
                let large = u8::from(sweep.abs() > PI && sweep.abs() <= 1.999 * PI);
                let _ = write!(d, "A{rr} {rr} 0 {large} {flag} {} {}", num(to.0), num(to.1));
                cur = to;
            }
        }
    }
    d
}

/// A number to 0.01, trailing zeros and `-0` left out.
pub fn num(v: f64) -> String {
    let t = format!("{v:.2}");
    let t = t.trim_end_matches('0').trim_end_matches('.');
    if t == "-0" {
        "0".into()
    } else {
        t.into()
    }
}

fn escape(t: &str) -> String {
    t.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn base64_is_the_rfc_4648_alphabet_with_padding() {
        // RFC 4648 §10's test vectors.
        let v = [
            "", "Zg==", "Zm8=", "Zm9v", "Zm9vYg==", "Zm9vYmE=", "Zm9vYmFy",
        ];
        for (n, want) in v.iter().enumerate() {
            assert_eq!(base64(&b"foobar"[..n]), *want);
        }
    }

    #[test]
    fn numbers_are_short() {
        assert_eq!(num(12.0), "12");
        assert_eq!(num(-0.001), "0");
        assert_eq!(num(1.23456), "1.23");
    }

    #[test]
    fn a_counter_clockwise_half_circle_has_sweep_flag_0() {
        let segs = [
            Seg::Move((110.0, 100.0)),
            Seg::Arc {
                to: (90.0, 100.0),
                c: (100.0, 100.0),
                r: 10.0,
                sweep: PI,
            },
        ];
        assert_eq!(path(&segs), "M110 100A10 10 0 0 0 90 100");
    }
}
