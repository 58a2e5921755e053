//! Gradients at threshold crossings (§6.2, Fig. 15): along every cast ray,
//! where the samples (inside the inner box) first reach a threshold, at the
//! first such sample or interpolated between it and the one before, with
//! the gradient of each ABC neighbourhood there. The paper compares
//! these with the analytic normal of a volume-sampled sphere; the caller
//! supplies the surface, this module only finds the crossings.
//!
//! The gradients are the golden model's gradient words (`abc::gradient`),
//! turned to dataset space; the crossings and sample values are the
//! golden model's too, so every neighbourhood is measured at the same points.

use super::abc::{differences, gradient, RayCoeffs};
use super::plan::{sample_pos, Neighbourhood, Plan, Widths};
use super::prp::Traversal;
use super::{chunks, scanlines};
use glam::DVec3;
use rayon::prelude::*;
use scene::volume::Volume;
use scene::{Camera, Result, Scene};

pub const ALL: [Neighbourhood; 4] = [
    Neighbourhood::N6,
    Neighbourhood::N10,
    Neighbourhood::N12,
    Neighbourhood::N26,
];

/// Where a ray's crossing is taken.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum At {
    /// The first sample at or above the threshold.
    FirstSample,
    /// Between that sample and the one before it, where the linear
    /// interpolation of their values meets the threshold; position and
    /// gradients are interpolated with the same fraction (§6.2 measures
    /// "at the surface"). A ray whose first inner sample is already above
    /// the threshold has no such point and is left out.
    Interpolated,
}

/// One threshold crossing: its dataset position and, per neighbourhood in
/// `ALL` order, the gradient in dataset space, basis-corrected (the golden
/// model's gradient word) and uncorrected (the estimator's own differences
/// read as if along the axes; the 12's are the same).
#[derive(Debug, Clone, Copy)]
pub struct Crossing {
    pub position: DVec3,
    pub gradients: [DVec3; 4],
    pub uncorrected: [DVec3; 4],
}

/// The crossings of `threshold` (voxel units) over every base plane.
pub fn crossings(
    scene: &Scene,
    camera: &Camera,
    vol: &Volume,
    threshold: u32,
    at: At,
) -> Result<Vec<Crossing>> {
    let plan = Plan::new(scene, camera)?;
    let wd = Widths::of(scene);
    let f = wd.sample_frac();
    let t = threshold << f;
    let mut out = Vec::new();
    for view in &plan.views {
        let w = view.weight_bits;
        let [nx, ny, nk] = view.dims.map(|n| n as i64);
        let to_dataset = view.to_traversal().transpose();
        let one = (1i64 << w) as f64;
        let vol = &Traversal::new(vol, view);
        let rows: Vec<Vec<Crossing>> = chunks(view)
            .into_par_iter()
            .map(|run| {
                let mut found = Vec::new();
                scanlines(vol, view, f, true, run, |v, planes| {
                    for u in view.u[0]..=view.u[1] {
                        if !view.casts(u, v) {
                            continue;
                        }
                        let (dx, dy) = (view.x.d(u), view.y.d(v));
                        let c = RayCoeffs::new(dx, dy, w);
                        // Sample k's position in traversal space, W
                        // fractional bits.
                        let at_k = |k: usize| {
                            let zq = ((k as i64) << w) + view.offset as i64;
                            (sample_pos(u, k, dx, w), sample_pos(v, k, dy, w), zq)
                        };
                        // Sample k of this ray, in dataset space: position,
                        // corrected and uncorrected gradients.
                        let sample = |k: usize| {
                            let (xq, yq, zq) = at_k(k);
                            let mut q = DVec3::new(xq as f64, yq as f64, zq as f64) / one;
                            if !view.positive {
                                q.z -= (nk - 1) as f64;
                            }
                            let axes = |g: [i64; 3]| {
                                to_dataset * DVec3::new(g[0] as f64, g[1] as f64, g[2] as f64)
                            };
                            let corrected = ALL.map(|n| {
                                let (g, _) = gradient(n, planes, u, k, &c, w, wd.gradient_bits);
                                axes(g.map(i64::from))
                            });
                            let raw = ALL.map(|n| axes(differences(n, planes, u, k, &c, w)));
                            Crossing {
                                position: to_dataset * q,
                                gradients: corrected,
                                uncorrected: raw,
                            }
                        };
                        let mut before: Option<(usize, u32)> = None;
                        for k in 0..nk as usize {
                            let (xq, yq, zq) = at_k(k);
                            let inner = |q: i64, n: i64| q >= 1 << w && q <= (n - 2) << w;
                            if !(inner(xq, nx) && inner(yq, ny) && inner(zq, nk)) {
                                continue;
                            }
                            let value = planes.current.at(u, k);
                            if value < t {
                                before = Some((k, value));
                                continue;
                            }
                            match (at, before) {
                                (At::FirstSample, _) => found.push(sample(k)),
                                // The inner samples of a ray are consecutive
                                // (the inner box is convex), so `before` is
                                // sample k - 1.
                                (At::Interpolated, Some((kb, a))) => {
                                    let s = (t - a) as f64 / (value - a) as f64;
                                    found.push(mix(&sample(kb), &sample(k), s));
                                }
                                (At::Interpolated, None) => {}
                            }
                            break;
                        }
                    }
                });
                found
            })
            .collect();
        out.extend(rows.into_iter().flatten());
    }
    Ok(out)
}

/// `a + s·(b − a)` for every field of a crossing.
fn mix(a: &Crossing, b: &Crossing, s: f64) -> Crossing {
    let lerp = |x: DVec3, y: DVec3| x.lerp(y, s);
    Crossing {
        position: lerp(a.position, b.position),
        gradients: std::array::from_fn(|j| lerp(a.gradients[j], b.gradients[j])),
        uncorrected: std::array::from_fn(|j| lerp(a.uncorrected[j], b.uncorrected[j])),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// On a sphere whose shell is a linear ramp, the interpolated crossing
    /// of the half-scale threshold lies on the surface (where the ramp is
    /// 1/2); the first sample past it lies up to a sample step inside.
    #[test]
    fn interpolated_crossings_lie_on_the_surface() {
        let text = r#"{"volume": {"builtin": "sphere", "dims": [32, 32, 32], "shell": 3},
            "view": {"projection": "parallel", "rotate_deg": [0, 30, 0]}, "image": [64, 64],
            "hardware": {"voxel_bits": 16}}"#;
        let scene = Scene::from_json(text, None).unwrap();
        let vol = Volume::from_spec(&scene.volume, 16).unwrap();
        let (c, r) = scene::volume::sphere_geometry([32, 32, 32]);
        let off = |xs: &[Crossing]| {
            xs.iter()
                .map(|x| ((x.position - c).length() - r).abs())
                .sum::<f64>()
                / xs.len() as f64
        };
        let cam = scene.camera();
        let near = crossings(&scene, &cam, &vol, 32768, At::Interpolated).unwrap();
        let first = crossings(&scene, &cam, &vol, 32768, At::FirstSample).unwrap();
        assert!(near.len() > 300 && near.len() <= first.len());
        assert!(off(&near) < 0.05, "interpolated: {}", off(&near));
        assert!(off(&first) > 0.2, "first sample: {}", off(&first));
    }
}
