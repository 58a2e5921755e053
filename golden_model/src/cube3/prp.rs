//! PRP fetch (§2, Fig. 2; §5, Fig. 12): the discrete rays of one base-plane
//! scanline `v` lie on a Projection Ray Plane. It is fetched from the CFB as
//! one beam per plane `k` (the voxels along x at `y = Y_k(v)`, slice `k`),
//! and each beam is shifted into a 2-D skewed buffer so that discrete ray
//! `u` becomes row `u` of the buffer: `B[k][u] = beam_k[X_k(u)]`.
//!
//! For a parallel view the shift is the same for every voxel of a beam
//! (`X_k(u) - u = pos[k]`, a shear); between consecutive beams it changes by
//! at most one voxel, the Fast Bus's local shift. For a perspective view each
//! voxel moves by its own amount (de-fanning), and voxels between diverging
//! rays are not stored at all (Fig. 3(b)).
//!
//! Voxels outside the volume read as 0. The buffer is kept in ray-major
//! order here; the hardware's skew of the 2-DSB (module `(u + k) mod p`) is
//! an addressing choice that does not change a value.

use super::plan::View;
use scene::volume::{InOrder, Voxels};

/// The volume in one base plane's traversal order `(x, y, k)`, `x`
/// fastest: the order Cube-3's memory modules hold it in
/// (`BeamFetchConfig::modules`, without the skew), so that each beam is a
/// row (the volume itself where that is its order; a copy otherwise, made
/// once a base plane, or kept from an earlier frame by an
/// [`scene::volume::Ordered`]). Read in the dataset's own order, a beam along the dataset's
/// slowest axis is a cache miss a voxel.
#[derive(Debug, Clone)]
pub struct Traversal<'a> {
    dims: [usize; 3],
    positive: bool,
    data: InOrder<'a>,
}

impl<'a> Traversal<'a> {
    pub fn new(vol: &'a dyn Voxels, view: &View) -> Traversal<'a> {
        Traversal {
            dims: view.dims,
            positive: view.positive,
            data: vol.in_order(view.perm),
        }
    }

    /// Row `y` of plane `k`, `x` in `0..n_x`.
    fn beam(&self, y: usize, k: usize) -> &[u16] {
        let [nx, ny, nk] = self.dims;
        let slice = if self.positive { k } else { nk - 1 - k };
        &self.data[(slice * ny + y) * nx..][..nx]
    }
}

/// One 2-D skewed buffer: rays `u0..u0 + rays`, planes `0..=K` (plane `K`
/// lies behind the volume and reads 0; it is the back plane of sample
/// `K - 1`).
#[derive(Debug, Clone)]
pub struct Prp {
    pub u0: i32,
    pub rays: usize,
    pub planes: usize,
    pub data: Vec<u32>,
}

impl Prp {
    /// Voxel of discrete ray `u` on plane `k`.
    pub fn at(&self, u: i32, k: usize) -> u32 {
        self.ray(u)[k]
    }

    /// Row `u` of the buffer: discrete ray `u`'s voxels on planes `0..=K`.
    pub fn ray(&self, u: i32) -> &[u32] {
        &self.data[(u - self.u0) as usize * (self.planes + 1)..][..self.planes + 1]
    }
}

/// Fetch and align the PRP of scanline `v`, for rays `u0..u0 + rays`, from
/// the volume in `view`'s traversal order. Beam by beam: plane `k`'s row
/// `y = Y_k(v)` is found once, then each ray's voxel `X_k(u)` on it. In a
/// parallel view the rays on a beam read consecutive voxels: their range
/// is worked out once a beam, not a ray's position and range test each.
pub fn fetch(vol: &Traversal, view: &View, v: i32, u0: i32, rays: usize) -> Prp {
    let [nx, ny, nk] = view.dims;
    let mut data = vec![0; rays * (nk + 1)];
    for k in 0..nk {
        let y = view.y.pos(v, k);
        if y < 0 || y as usize >= ny {
            continue;
        }
        let beam = vol.beam(y as usize, k);
        if let Some(s) = view.x.shift(k) {
            // Rays lo..hi (those on the beam) read beam[o + i].
            let o = u0 + s;
            let lo = (-o).clamp(0, rays as i32);
            let hi = (nx as i32 - o).clamp(lo, rays as i32);
            for i in lo..hi {
                data[i as usize * (nk + 1) + k] = beam[(o + i) as usize] as u32;
            }
            continue;
        }
        for (i, d) in data.iter_mut().skip(k).step_by(nk + 1).enumerate() {
            let x = view.x.pos(u0 + i as i32, k);
            if x >= 0 && (x as usize) < nx {
                *d = beam[x as usize] as u32;
            }
        }
    }
    Prp {
        u0,
        rays,
        planes: nk,
        data,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cube3::plan::Plan;
    use scene::volume::Volume;
    use scene::Scene;

    #[test]
    fn the_traversal_copy_holds_each_voxel_where_the_view_puts_it() {
        // Every major axis, both directions: the traversal's x is then the
        // dataset's fastest or slowest axis (both copy loops).
        for rot in [
            "[10, 0, 0]",
            "[0, 180, 0]",
            "[80, 20, 0]",
            "[-80, 20, 0]",
            "[0, 80, 10]",
            "[0, -80, 10]",
        ] {
            let json = format!(
                r#"{{"volume": {{"builtin": "phantom", "dims": [9, 7, 5]}}, "view": {{"projection": "parallel", "rotate_deg": {rot}}}, "image": [16, 16]}}"#
            );
            let s = Scene::from_json(&json, None).unwrap();
            let vol = Volume::from_spec(&s.volume, 8).unwrap();
            for view in &Plan::new(&s, &s.camera()).unwrap().views {
                let t = Traversal::new(&vol, view);
                let [nx, ny, nk] = view.dims;
                for k in 0..nk {
                    for y in 0..ny {
                        for x in 0..nx {
                            let [a, b, c] = view.voxel(x as i32, y as i32, k).unwrap();
                            assert_eq!(t.beam(y, k)[x], vol.get(a, b, c), "{rot} ({x}, {y}, {k})");
                        }
                    }
                }
            }
        }
    }
}
