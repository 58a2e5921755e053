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
        self.data[(u - self.u0) as usize * (self.planes + 1) + k]
    }
}

/// Fetch and align the PRP of scanline `v`, for rays `u0..u0 + rays`.
pub fn fetch(vol: &Volume, view: &View, v: i32, u0: i32, rays: usize) -> Prp {
    let nk = view.dims[2];
    let mut data = Vec::with_capacity(rays * (nk + 1));
    let index = |d: [usize; 3]| d[0] + vol.dims[0] * (d[1] + vol.dims[1] * d[2]);
    for i in 0..rays {
        let u = u0 + i as i32;
        for k in 0..=nk {
            let y = view.y.pos(v, k);
            let x = view.x.pos(u, k);
            data.push(view.voxel(x, y, k).map_or(0, |d| vol.data[index(d)] as u32));
        }
    }
    Prp {
        u0,
        rays,
        planes: nk,
        data,
    }
}
