//! The two-level grid (Mora, Jessel & Caubet, §3.2), built once per
//! volume. Each first-level element is a block of `B³` voxels holding its
//! own voxel grid, each voxel's value beside its quantized normal (§3.1),
//! so that the renderer finds both in one cache line; its gradient
//! magnitudes; and its minimum and maximum value. A transfer function then
//! marks a block empty when its opacity is zero over the block's value
//! range (`min..=max`) or, as the paper does, over `min..` to the top of
//! the range (`EmptySpace::Min`); the renderer skips empty blocks without
//! looking at their voxels. Neither needs a pass over the volume when the
//! transfer function changes.

use super::normals::{NormalCode, EDGE};
use glam::DVec3;
use rayon::prelude::*;
use scene::volume::Volume;

/// Block side, in voxels.
pub const B: usize = 8;
/// Voxels per block.
pub const B3: usize = B * B * B;
/// Levels of the stored gradient magnitude (for gradient opacity).
pub const GMAG_LEVELS: u32 = 256;

/// A voxel's value and its normal code (`NormalCode`, or `EDGE`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Voxel {
    pub value: u16,
    pub normal: u16,
}

/// The volume regrouped into blocks.
#[derive(Debug, Clone)]
pub struct Grid {
    pub dims: [usize; 3],
    /// Blocks along each axis.
    pub blocks: [usize; 3],
    /// Per block, `B3` voxels, x fastest; voxels beyond the volume are 0
    /// with normal `EDGE`.
    pub voxels: Vec<Voxel>,
    /// Per block, `B3` gradient magnitudes, `0..GMAG_LEVELS` over
    /// `[0, gmag_max]`.
    pub gmag: Vec<u8>,
    pub min: Vec<u16>,
    pub max: Vec<u16>,
    pub code: NormalCode,
    /// The largest possible gradient magnitude, `vmax·√3 / 2`.
    pub gmag_max: f64,
}

impl Grid {
    /// Regroup `vol` and quantize its normals to `normals` directions.
    pub fn new(vol: &Volume, normals: u32) -> Grid {
        let dims = vol.dims;
        let blocks = dims.map(|n| n.div_ceil(B));
        let code = NormalCode::new(normals);
        let vmax = ((1u64 << vol.bits) - 1) as f64;
        let gmag_max = vmax * 3f64.sqrt() / 2.0;
        let per_slab = blocks[0] * blocks[1] * B3;
        let edge = Voxel {
            value: 0,
            normal: EDGE,
        };
        let mut voxels = vec![edge; per_slab * blocks[2]];
        let mut gmag = vec![0u8; voxels.len()];
        // One slab of blocks (constant bz) per task.
        voxels
            .par_chunks_mut(per_slab)
            .zip(gmag.par_chunks_mut(per_slab))
            .enumerate()
            .for_each(|(bz, (vs, gs))| {
                for (i, (v, g)) in vs.iter_mut().zip(gs).enumerate() {
                    let (b, o) = (i / B3, i % B3);
                    let p = [
                        (b % blocks[0]) * B + o % B,
                        (b / blocks[0]) * B + o / B % B,
                        bz * B + o / (B * B),
                    ];
                    if (0..3).any(|a| p[a] >= dims[a]) {
                        continue;
                    }
                    v.value = vol.get(p[0], p[1], p[2]);
                    if (0..3).any(|a| p[a] == 0 || p[a] == dims[a] - 1) {
                        continue;
                    }
                    // Central differences, half the span (voxel units per
                    // voxel), as the reference takes them.
                    let d = |a: usize| {
                        let mut q = p;
                        q[a] += 1;
                        let hi = vol.get(q[0], q[1], q[2]) as f64;
                        q[a] -= 2;
                        (hi - vol.get(q[0], q[1], q[2]) as f64) / 2.0
                    };
                    let grad = DVec3::new(d(0), d(1), d(2));
                    let len = grad.length();
                    v.normal = if len == 0.0 {
                        code.flat()
                    } else {
                        // The shading normal faces against the gradient.
                        code.encode(-grad / len)
                    };
                    *g = ((len / gmag_max * (GMAG_LEVELS - 1) as f64).round() as u32)
                        .min(GMAG_LEVELS - 1) as u8;
                }
            });
        let count = blocks.iter().product::<usize>();
        let (min, max) = (0..count)
            .into_par_iter()
            .map(|b| {
                let ext = extent(dims, blocks, b);
                let vals = &voxels[b * B3..(b + 1) * B3];
                let (mut lo, mut hi) = (u16::MAX, 0u16);
                for k in 0..ext[2] {
                    for j in 0..ext[1] {
                        for v in &vals[(k * B + j) * B..(k * B + j) * B + ext[0]] {
                            lo = lo.min(v.value);
                            hi = hi.max(v.value);
                        }
                    }
                }
                (lo, hi)
            })
            .unzip();
        Grid {
            dims,
            blocks,
            voxels,
            gmag,
            min,
            max,
            code,
            gmag_max,
        }
    }

    /// Block index of block coordinates `b`.
    pub fn block(&self, b: [usize; 3]) -> usize {
        b[0] + self.blocks[0] * (b[1] + self.blocks[1] * b[2])
    }

    /// Coordinates of block `b`'s first voxel.
    pub fn first(&self, b: usize) -> [usize; 3] {
        [
            b % self.blocks[0] * B,
            b / self.blocks[0] % self.blocks[1] * B,
            b / (self.blocks[0] * self.blocks[1]) * B,
        ]
    }

    /// Voxels of block `b` along each axis (fewer than `B` at the far
    /// faces).
    pub fn extent(&self, b: usize) -> [usize; 3] {
        extent(self.dims, self.blocks, b)
    }

    /// Number of voxels in block `b`.
    pub fn voxels(&self, b: usize) -> u64 {
        self.extent(b).iter().product::<usize>() as u64
    }

    /// The stored gradient magnitude of level `g`, voxel units per voxel.
    pub fn gmag_of(&self, g: u8) -> f64 {
        g as f64 * self.gmag_max / (GMAG_LEVELS - 1) as f64
    }
}

fn extent(dims: [usize; 3], blocks: [usize; 3], b: usize) -> [usize; 3] {
    let c = [
        b % blocks[0],
        b / blocks[0] % blocks[1],
        b / (blocks[0] * blocks[1]),
    ];
    [0, 1, 2].map(|a| (dims[a] - c[a] * B).min(B))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ramp(dims: [usize; 3]) -> Volume {
        let mut data = Vec::new();
        for w in 0..dims[2] {
            for v in 0..dims[1] {
                for u in 0..dims[0] {
                    data.push((u + 2 * v + 3 * w) as u16);
                }
            }
        }
        Volume {
            dims,
            bits: 8,
            data,
        }
    }

    #[test]
    fn blocks_hold_the_volume_with_min_and_max() {
        let vol = ramp([10, 9, 3]);
        let g = Grid::new(&vol, 256);
        assert_eq!(g.blocks, [2, 2, 1]);
        assert_eq!(g.extent(1), [2, 8, 3]);
        assert_eq!(g.voxels(3), 2 * 3);
        // Block 3 is (1, 1, 0): u 8..10, v 8, w 0..3.
        assert_eq!((g.min[3], g.max[3]), (8 + 16, 9 + 16 + 6));
        let b = g.block([1, 1, 0]);
        assert_eq!(
            g.voxels[b * B3 + (2 * B) * B + 1].value,
            (9 + 16 + 6) as u16
        );
    }

    #[test]
    fn normals_face_against_the_gradient_and_edges_are_marked() {
        let vol = ramp([10, 9, 4]);
        let g = Grid::new(&vol, 8192);
        // Voxel (1, 1, 2) of block 0.
        let at = (2 * B + 1) * B + 1;
        let inner = g.voxels[at].normal;
        assert_ne!(inner, EDGE);
        let n = g.code.decode(inner);
        let want = -DVec3::new(1.0, 2.0, 3.0).normalize();
        assert!(n.dot(want) > 0.999, "{n}");
        // |(1, 2, 3)| = 3.742 of 127.5·√3 = 220.8 -> level 4.
        assert_eq!(g.gmag[at], 4);
        assert_eq!(g.voxels[0].normal, EDGE);
    }
}
