//! Cube-4L's warp (§2, "warped onto the image plane"): each final-image
//! pixel's ray is followed to the face of the swept box through which it left
//! the compositing buffer, and the base plane is resampled there bilinearly
//! (`common::warp::bilinear`), using only pixels that came out of the same
//! face. Parallel and perspective views take the same path; a multi-sweep
//! perspective frame takes each pixel from the sweep of its ray's major axis
//! and direction.

use super::frame::{BasePlane, Frame};
use super::plan::{Face, Sweep};
use crate::common::plan::slab;
use crate::common::warp::{bilinear, to_rgb, warp_with};
use glam::{DAffine2, DVec2, DVec3};
use scene::{Camera, Image, Mode};

/// Map from a point on `face` (its two in-plane pipeline coordinates, plus
/// the slice for side faces) to continuous base-plane coordinates.
fn face_to_base(sweep: &Sweep, face: Face) -> DAffine2 {
    let b = sweep.border() as f64;
    let z1 = sweep.z1 as f64;
    let [nx, ny, _] = sweep.dims.map(|n| n as f64);
    // Inputs: Last (x, y); X faces (y, z); Y faces (x, z).
    let m = |cols: [f64; 6]| DAffine2::from_cols_array(&cols);
    match face {
        Face::Last | Face::None => m([1.0, 0.0, 0.0, 1.0, b, b]),
        Face::XPos => m([0.0, 1.0, -1.0, 0.0, b + nx - 1.0 + z1, b]),
        Face::XNeg => m([0.0, 1.0, 1.0, 0.0, b - z1, b]),
        Face::YPos => m([1.0, 0.0, 0.0, -1.0, b, b + ny - 1.0 + z1]),
        Face::YNeg => m([1.0, 0.0, 0.0, 1.0, b, b - z1]),
    }
}

/// Bilinear sample of a Cube-4L base plane over the pixels of `face` only.
fn sample_face(base: &BasePlane, p: DVec2, face: Face) -> Option<[f64; 4]> {
    bilinear(base.width, base.height, p, |i| {
        (base.faces[i] == face).then(|| base.pixels[i])
    })
}

/// Warp a Cube-4L frame's base planes to the final image.
pub fn warp(frame: &Frame, camera: &Camera, mode: Mode, rgba_bits: u32, voxel_bits: u32) -> Image {
    warp_with(camera, |o, d| {
        let si = frame.plan.sweep_for(d)?;
        let sweep = &frame.plan.sweeps[si];
        let m = sweep.to_pipeline();
        let (po, pd) = (m * o, m * d);
        let [nx, ny, _] = sweep.dims;
        let lo = DVec3::new(0.0, 0.0, sweep.z0 as f64);
        let hi = DVec3::new((nx - 1) as f64, (ny - 1) as f64, sweep.z1 as f64);
        let (t0, t1, a0, a1) = slab(po, pd, lo, hi)?;
        // The pixel left the buffer where the ray is highest in z.
        let (t, axis) = if pd.z > 0.0 { (t1, a1) } else { (t0, a0) };
        let q = po + pd * t;
        let near_hi = |lo: f64, hi: f64, v: f64| (v - lo).abs() >= (v - hi).abs();
        let (face, uv) = match axis {
            2 => (Face::Last, DVec2::new(q.x, q.y)),
            0 => (
                if near_hi(lo.x, hi.x, q.x) {
                    Face::XPos
                } else {
                    Face::XNeg
                },
                DVec2::new(q.y, q.z),
            ),
            _ => (
                if near_hi(lo.y, hi.y, q.y) {
                    Face::YPos
                } else {
                    Face::YNeg
                },
                DVec2::new(q.x, q.z),
            ),
        };
        let p = face_to_base(sweep, face).transform_point2(uv);
        let v = sample_face(&frame.bases[si], p, face)?;
        Some(to_rgb(mode, v, rgba_bits, voxel_bits, sweep.dims[2]))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn face_maps_agree_with_base_addresses() {
        let plan_scene = scene::Scene::from_json(
            r#"{"volume": {"builtin": "sphere", "dims": [6,5,4]}, "view": {"projection": "parallel", "rotate_deg": [20, 30, 0]}, "image": [8, 8]}"#,
            None,
        )
        .unwrap();
        let cam = plan_scene.camera();
        let plan = crate::cube4l::plan::Plan::new(&plan_scene, &cam).unwrap();
        let s: &Sweep = &plan.sweeps[0];
        let [nx, ny, _] = s.dims;
        for z in s.z0..=s.z1 {
            for y in 0..ny {
                for x in 0..nx {
                    for (face, uv) in [
                        (Face::Last, DVec2::new(x as f64, y as f64)),
                        (Face::XPos, DVec2::new(y as f64, z as f64)),
                        (Face::XNeg, DVec2::new(y as f64, z as f64)),
                        (Face::YPos, DVec2::new(x as f64, z as f64)),
                        (Face::YNeg, DVec2::new(x as f64, z as f64)),
                    ] {
                        let on_face = match face {
                            Face::Last => z == s.z1,
                            Face::XPos => x == nx - 1,
                            Face::XNeg => x == 0,
                            Face::YPos => y == ny - 1,
                            _ => y == 0,
                        };
                        if !on_face {
                            continue;
                        }
                        let a = s.base_address(x, y, z, face).unwrap();
                        let p = face_to_base(s, face).transform_point2(uv);
                        assert_eq!([p.x as usize, p.y as usize], a, "{face:?} {x} {y} {z}");
                    }
                }
            }
        }
    }
}
