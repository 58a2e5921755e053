//! The ray and view-planning helpers of both architectures: the base plane
//! of a view is the face perpendicular to its dominant axis (Cube-4L §3.1,
//! Cube-3 §2), a perspective view's base planes come from the sums of its
//! pixel rays' directions, a ray meets the volume's box by the slab test,
//! and compositing goes front to back or back to front (Cube-4L §3.5; Cube-3's
//! RPC composites front to back).

use glam::DVec3;
use scene::Camera;

/// The order in which a ray's samples are composited.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Order {
    FrontToBack,
    BackToFront,
}

/// The axis most parallel to `d`: the base plane of a view is the face
/// perpendicular to it (Cube-4L §3.1, Cube-3 §2).
pub fn dominant_axis(d: DVec3) -> usize {
    let a = d.abs();
    // Ties (exactly 45 degrees) go to the later axis so the choice is stable.
    if a.z >= a.x && a.z >= a.y {
        2
    } else if a.y >= a.x {
        1
    } else {
        0
    }
}

/// Intersection `[t_in, t_out]` of a ray with the box `lo..=hi`, or `None`.
pub fn slab(o: DVec3, d: DVec3, lo: DVec3, hi: DVec3) -> Option<(f64, f64, usize, usize)> {
    let (mut t0, mut t1, mut a0, mut a1) = (f64::NEG_INFINITY, f64::INFINITY, 0, 0);
    for i in 0..3 {
        if d[i].abs() < 1e-300 {
            if o[i] < lo[i] || o[i] > hi[i] {
                return None;
            }
            continue;
        }
        let (mut n, mut f) = ((lo[i] - o[i]) / d[i], (hi[i] - o[i]) / d[i]);
        if n > f {
            std::mem::swap(&mut n, &mut f);
        }
        if n > t0 {
            t0 = n;
            a0 = i;
        }
        if f < t1 {
            t1 = f;
            a1 = i;
        }
    }
    (t0 <= t1 && t1 >= 0.0).then_some((t0.max(0.0), t1, a0, a1))
}

/// Perspective planning of both architectures: the sum of the directions of
/// the pixel rays that meet the volume, per (dominant axis, positive
/// direction). A base plane is needed where a sum is non-zero, and its
/// normalised sum is the plane's mean viewing direction.
pub fn ray_sums(camera: &Camera, dims: [usize; 3]) -> [[DVec3; 2]; 3] {
    let hi = DVec3::from_array(dims.map(|n| (n - 1) as f64));
    let mut sums = [[DVec3::ZERO; 2]; 3];
    for j in 0..camera.height {
        for i in 0..camera.width {
            let (o, d) = camera.ray(i, j);
            if slab(o, d, DVec3::ZERO, hi).is_some() {
                let a = dominant_axis(d);
                sums[a][(d[a] > 0.0) as usize] += d;
            }
        }
    }
    sums
}
