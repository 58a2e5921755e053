//! The 2-D warp's shared parts (Cube-4L §2, "warped onto the image plane";
//! Cube-3 §2, "a 2-D warp of the base-plane projection produces the final
//! image"): `warp_with` (one ray per image pixel), `bilinear` (resampling
//! over the pixels a base plane has) and `to_rgb` (display range per mode).
//! Each architecture's map from an image ray to its base plane is its own:
//! `cube4l::warp` and `cube3::warp`.

use crate::fixed::max_of;
use glam::{DVec2, DVec3};
use scene::{Camera, Image, Mode};

/// Bilinear sample at `p` of a `width` x `height` base plane over the
/// pixels `pixel(i)` gives (weights renormalised over them); `None` if none
/// of the four is there.
pub fn bilinear(
    width: usize,
    height: usize,
    p: DVec2,
    pixel: impl Fn(usize) -> Option<[u32; 4]>,
) -> Option<[f64; 4]> {
    let (x0, y0) = (p.x.floor(), p.y.floor());
    let (fx, fy) = (p.x - x0, p.y - y0);
    let mut acc = [0.0; 4];
    let mut wsum = 0.0;
    for (ox, oy, w) in [
        (0, 0, (1.0 - fx) * (1.0 - fy)),
        (1, 0, fx * (1.0 - fy)),
        (0, 1, (1.0 - fx) * fy),
        (1, 1, fx * fy),
    ] {
        let (cx, cy) = (x0 as i64 + ox, y0 as i64 + oy);
        if w <= 0.0 || cx < 0 || cy < 0 || cx >= width as i64 || cy >= height as i64 {
            continue;
        }
        let Some(v) = pixel(cx as usize + width * cy as usize) else {
            continue;
        };
        for (a, v) in acc.iter_mut().zip(v) {
            *a += w * v as f64;
        }
        wsum += w;
    }
    (wsum > 1e-9).then(|| acc.map(|a| a / wsum))
}

/// The final image: each pixel's ray `(origin, direction)` in dataset space
/// goes to `lookup`, which returns its display RGB or `None` (background).
pub fn warp_with(
    camera: &Camera,
    lookup: impl Fn(DVec3, DVec3) -> Option<[f64; 3]> + Sync,
) -> Image {
    use rayon::prelude::*;
    let mut img = Image::black(camera.width, camera.height);
    img.rgb
        .par_chunks_mut(camera.width as usize)
        .enumerate()
        .for_each(|(j, row)| {
            for (i, px) in row.iter_mut().enumerate() {
                let (o, d) = camera.ray(i as u32, j as u32);
                if let Some(c) = lookup(o, d) {
                    *px = c;
                }
            }
        });
    img
}

/// Convert a base-plane pixel value to display RGB for `mode`; `depth` is
/// the sweep's slice count (X-ray normalisation).
pub fn to_rgb(mode: Mode, v: [f64; 4], rgba_bits: u32, voxel_bits: u32, depth: usize) -> [f64; 3] {
    let m = max_of(rgba_bits) as f64;
    let rgb = match mode {
        Mode::Composite | Mode::FirstOpaque => [v[0] / m, v[1] / m, v[2] / m],
        Mode::Mip | Mode::Minip => [v[0] / max_of(voxel_bits) as f64; 3],
        Mode::Xray => [v[0] / (m * depth as f64); 3],
    };
    // The renormalised bilinear weights can overshoot by an ulp.
    rgb.map(|c| c.clamp(0.0, 1.0))
}
