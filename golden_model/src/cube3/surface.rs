//! Gradients at threshold crossings (§6.2, Fig. 15): along every cast ray,
//! the first sample (inside the inner box) whose value reaches a threshold,
//! with the gradient of each ABC neighbourhood there. The paper compares
//! these with the analytic normal of a volume-sampled sphere; the caller
//! supplies the surface, this module only finds the crossings.
//!
//! The gradients are the golden model's gradient words (`abc::gradient`),
//! turned to dataset space; the crossings and sample values are the
//! golden model's too, so every neighbourhood is measured at the same points.

use super::abc::{gradient, RayCoeffs};
use super::plan::{sample_pos, Neighbourhood, Plan, Widths};
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

/// One threshold crossing: its dataset position and, per neighbourhood in
/// `ALL` order, the gradient in dataset space.
#[derive(Debug, Clone, Copy)]
pub struct Crossing {
    pub position: DVec3,
    pub gradients: [DVec3; 4],
}

/// The crossings of `threshold` (voxel units) over every base plane.
pub fn crossings(
    scene: &Scene,
    camera: &Camera,
    vol: &Volume,
    threshold: u32,
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
                        for k in 0..nk as usize {
                            let (xq, yq) = (sample_pos(u, k, dx, w), sample_pos(v, k, dy, w));
                            let zq = ((k as i64) << w) + view.offset as i64;
                            let inner = |q: i64, n: i64| q >= 1 << w && q <= (n - 2) << w;
                            if !(inner(xq, nx) && inner(yq, ny) && inner(zq, nk)) {
                                continue;
                            }
                            if planes.current.at(u, k) < t {
                                continue;
                            }
                            let g = ALL.map(|n| {
                                let (g, _) = gradient(n, planes, u, k, &c, w, wd.gradient_bits);
                                to_dataset * DVec3::new(g[0] as f64, g[1] as f64, g[2] as f64)
                            });
                            let p = DVec3::new(xq as f64 / one, yq as f64 / one, zq as f64 / one);
                            let mut q = p;
                            if !view.positive {
                                q.z -= (nk - 1) as f64;
                            }
                            found.push(Crossing {
                                position: to_dataset * q,
                                gradients: g,
                            });
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
