//! The depth map drawn as a picture: each pixel of a panel's plot area
//! coloured by the lowest Z cut there (dark purple deepest, through
//! blue and green, to yellow highest) and lit from the upper left by the
//! slope of the cut surface, so a 3-D surface reads as a relief.

use super::depth::DepthMap;
use super::layout::PanelLayout;
use super::scene::{Item, Rgb};

/// The colour ramp, lowest Z first (the viridis scale's ends and three
/// stops between).
pub const RAMP: [Rgb; 5] = [
    (0x44, 0x01, 0x54),
    (0x3b, 0x52, 0x8b),
    (0x21, 0x91, 0x8c),
    (0x5e, 0xc9, 0x62),
    (0xfd, 0xe7, 0x25),
];

/// The ramp's colour at `t` (0 lowest, 1 highest; clamped), darkened by
/// `light` (1 unchanged, 0 black).
pub fn ramp(t: f64, light: f64) -> Rgb {
    let t = if t.is_nan() { 0.5 } else { t.clamp(0.0, 1.0) };
    let x = t * (RAMP.len() - 1) as f64;
    let k = (x.floor() as usize).min(RAMP.len() - 2);
    let f = x - k as f64;
    let (a, b) = (RAMP[k], RAMP[k + 1]);
    let mix = |p: u8, q: u8| {
        let v = (p as f64 + (q as f64 - p as f64) * f) * light.clamp(0.0, 1.0);
        v.round().clamp(0.0, 255.0) as u8
    };
    (mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

/// The light on a surface of slopes `dzdx`, `dzdy` from the upper left
/// (X−, Y+, above): 1 facing it, 0.55 facing away or vertical.
pub fn light(dzdx: f64, dzdy: f64) -> f64 {
    // The surface normal (-dz/dx, -dz/dy, 1) against the light
    // (-1, 1, 1.5) / |(-1, 1, 1.5)|.
    let n = (dzdx * dzdx + dzdy * dzdy + 1.0).sqrt();
    let l = (1.0f64 + 1.0 + 2.25).sqrt();
    let dot = (dzdx - dzdy + 1.5) / (n * l);
    0.55 + 0.45 * dot.max(0.0)
}

/// The plot area of `pl` as an image of the map: one image pixel a
/// picture pixel, transparent where nothing was cut.
pub fn image(map: &DepthMap, pl: &PanelLayout) -> Option<Item> {
    let (z0, z1) = map.z_range()?;
    let (w, h) = (pl.w.round() as u32, pl.h.round() as u32);
    if w == 0 || h == 0 {
        return None;
    }
    let span = z1 - z0;
    let d = map.cell();
    let mut rgba = vec![0u8; (w * h * 4) as usize];
    for py in 0..h {
        for px in 0..w {
            let x = pl.lo.0 + (px as f64 + 0.5) / pl.scale;
            let y = pl.hi.1 - (py as f64 + 0.5) / pl.scale;
            let Some(z) = map.depth_at(x, y) else {
                continue;
            };
            // Slopes by central differences one cell either side (a side
            // not cut counts as level with this cell).
            let at = |dx: f64, dy: f64| map.depth_at(x + dx, y + dy).unwrap_or(z);
            let gx = (at(d, 0.0) - at(-d, 0.0)) / (2.0 * d);
            let gy = (at(0.0, d) - at(0.0, -d)) / (2.0 * d);
            let t = if span > 1e-9 { (z - z0) / span } else { 0.5 };
            let (r, g, b) = ramp(t, light(gx, gy));
            let k = ((py * w + px) * 4) as usize;
            rgba[k..k + 4].copy_from_slice(&[r, g, b, 255]);
        }
    }
    Some(Item::Image {
        at: (pl.left, pl.top),
        w,
        h,
        rgba,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_ramp_runs_from_its_first_to_its_last_stop() {
        assert_eq!(ramp(0.0, 1.0), RAMP[0]);
        assert_eq!(ramp(1.0, 1.0), RAMP[4]);
        assert_eq!(ramp(0.5, 1.0), RAMP[2]);
        // Half way between stops 0 and 1: (0x44+0x3b)/2 = 63.5 → 64.
        assert_eq!(ramp(0.125, 1.0).0, 64);
        // Out of range clamps; half the light halves each channel.
        assert_eq!(ramp(7.0, 0.5), (0x7f, 0x74, 0x13));
    }

    #[test]
    fn a_level_surface_is_lit_by_the_lights_height() {
        // Level: cos of the light's angle from vertical, 1.5/√4.25.
        let level = 0.55 + 0.45 * 1.5 / 4.25f64.sqrt();
        assert!((light(0.0, 0.0) - level).abs() < 1e-12);
        // A slope rising to the right tilts its normal to the left, to
        // the light: brighter than level; rising to the left, darker.
        assert!(light(1.0, 0.0) > level && light(-1.0, 0.0) < level);
        // Facing the light exactly: slopes 2/3 and -2/3 give the normal
        // (-2/3, 2/3, 1), parallel to the light: full brightness.
        assert!((light(1.0 / 1.5, -1.0 / 1.5) - 1.0).abs() < 1e-12);
    }
}
