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
use scene::volume::Volume;

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

/// Fetch and align the PRP of scanline `v`, for rays `u0..u0 + rays`.
/// Beam by beam: plane `k`'s row `y = Y_k(v)` is found once, then each
/// ray's voxel `X_k(u)` on it (`View::voxel`'s bounds and axes, unrolled).
pub fn fetch(vol: &Volume, view: &View, v: i32, u0: i32, rays: usize) -> Prp {
    let [nx, ny, nk] = view.dims;
    let mut data = vec![0; rays * (nk + 1)];
    let stride = [1, vol.dims[0], vol.dims[0] * vol.dims[1]];
    let [sx, sy, sk] = view.perm.map(|a| stride[a]);
    for k in 0..nk {
        let y = view.y.pos(v, k);
        if y < 0 || y as usize >= ny {
            continue;
        }
        let slice = if view.positive { k } else { nk - 1 - k };
        let beam = y as usize * sy + slice * sk;
        for (i, d) in data.iter_mut().skip(k).step_by(nk + 1).enumerate() {
            let x = view.x.pos(u0 + i as i32, k);
            if x >= 0 && (x as usize) < nx {
                *d = vol.data[beam + x as usize * sx] as u32;
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
