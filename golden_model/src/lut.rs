//! The LUTs of the Cube-4L shader and classifier (paper §3.3-3.4), filled
//! from the scene's transfer function and lighting formulas (`scene`): the
//! colour LUT, the opacity LUT (2-D with a gradient-magnitude index when the
//! scene has gradient opacity) and the reflectance map. Only the golden
//! models go through these quantized tables; the float reference evaluates
//! the formulas exactly.

use crate::fixed::{max_of, quantize_unorm};
use glam::DVec3;
use scene::lighting::phong;
use scene::transfer::{correct_opacity, TransferFn};
use scene::Shading;

/// Index bits of the intensity LUTs: the voxel's top bits, at most 12.
pub fn lut_bits(voxel_bits: u32) -> u32 {
    voxel_bits.min(12)
}

/// Bits per component of the quantized gradient that indexes the reflectance map.
pub const NORMAL_BITS: u32 = 5;
/// Bits of the gradient-magnitude index of the 2-D opacity LUT.
pub const GM_BITS: u32 = 4;

/// Intensity-indexed colour LUT (unorm RGB of `rgba_bits`).
#[derive(Debug, Clone)]
pub struct ColourLut {
    pub shift: u32,
    pub table: Vec<[u32; 3]>,
}

impl ColourLut {
    pub fn new(tf: &TransferFn, voxel_bits: u32, rgba_bits: u32) -> ColourLut {
        let lb = lut_bits(voxel_bits);
        let shift = voxel_bits - lb;
        let table = (0..1u32 << lb)
            .map(|i| {
                let c = tf.colour(bin_centre(i, shift));
                [
                    quantize_unorm(c.x, rgba_bits),
                    quantize_unorm(c.y, rgba_bits),
                    quantize_unorm(c.z, rgba_bits),
                ]
            })
            .collect();
        ColourLut { shift, table }
    }

    pub fn lookup(&self, v: u32) -> [u32; 3] {
        self.table[(v >> self.shift) as usize]
    }
}

/// Intensity the LUT entry `i` stands for: the centre of its bin of `2^shift` values.
fn bin_centre(i: u32, shift: u32) -> f64 {
    let lo = (i << shift) as f64;
    lo + (((1u32 << shift) - 1) as f64) / 2.0
}

/// Opacity LUT indexed by intensity and (only when the scene asks for it)
/// gradient magnitude. Entries are unorm of `rgba_bits` and already hold the
/// opacity for the sweep's sample spacing.
#[derive(Debug, Clone)]
pub struct OpacityLut {
    pub shift: u32,
    /// Right shift of the integer gradient magnitude to its index; `None`
    /// when the LUT has no gradient dimension (the unit is left out).
    pub gm_shift: Option<u32>,
    pub table: Vec<u32>,
    /// Per intensity entry: the largest opacity over all gradient indices, so
    /// the pipeline can tell transparent voxels before computing a gradient.
    pub row_max: Vec<u32>,
}

impl OpacityLut {
    pub fn new(
        tf: &TransferFn,
        voxel_bits: u32,
        rgba_bits: u32,
        spacing: f64,
        with_gradient: bool,
    ) -> OpacityLut {
        let lb = lut_bits(voxel_bits);
        let shift = voxel_bits - lb;
        let gm_shift = (with_gradient && tf.has_gradient_opacity()).then(|| {
            // The integer magnitude is of the undivided central difference
            // (twice the per-voxel gradient); bins cover [0, 2 * 2 * range).
            let top = (4.0 * tf.gradient_range()).ceil().max(1.0) as u64;
            crate::fixed::bit_len(top).saturating_sub(GM_BITS)
        });
        let gm_n = if gm_shift.is_some() {
            1u32 << GM_BITS
        } else {
            1
        };
        let mut table = Vec::with_capacity(((1usize) << lb) * gm_n as usize);
        for i in 0..1u32 << lb {
            let a = tf.opacity(bin_centre(i, shift));
            for g in 0..gm_n {
                let f = match gm_shift {
                    Some(s) => tf.gradient_factor(bin_centre(g, s) / 2.0),
                    None => 1.0,
                };
                table.push(quantize_unorm(correct_opacity(a * f, spacing), rgba_bits));
            }
        }
        let row_max = table
            .chunks(gm_n as usize)
            .map(|r| *r.iter().max().unwrap())
            .collect();
        OpacityLut {
            shift,
            gm_shift,
            table,
            row_max,
        }
    }

    pub fn row(&self, v: u32) -> usize {
        (v >> self.shift) as usize
    }

    /// Opacity of intensity `v` with integer gradient magnitude `gm`
    /// (ignored when the LUT has no gradient dimension).
    pub fn lookup(&self, v: u32, gm: u64) -> u32 {
        match self.gm_shift {
            None => self.table[self.row(v)],
            Some(s) => {
                let g = (gm >> s).min((1u64 << GM_BITS) - 1) as usize;
                self.table[(self.row(v) << GM_BITS) + g]
            }
        }
    }
}

/// Reflectance map: for each quantized gradient `(qx, qy, qz)` (signed
/// `NORMAL_BITS`-bit components in pipeline space) the diffuse multiplier and
/// the specular term, unorm of `rgba_bits`. The normal is the negated
/// gradient; a zero gradient gets ambient light only.
#[derive(Debug, Clone)]
pub struct ReflectanceMap {
    pub table: Vec<[u32; 2]>,
}

impl ReflectanceMap {
    /// `to_dataset` maps a pipeline-space vector to dataset space; `light` and
    /// `viewer` are unit vectors in dataset space.
    pub fn new(
        shading: &Shading,
        to_dataset: impl Fn(DVec3) -> DVec3,
        light: DVec3,
        viewer: DVec3,
        rgba_bits: u32,
    ) -> ReflectanceMap {
        let n = 1i32 << NORMAL_BITS;
        let mut table = vec![[0u32; 2]; (n * n * n) as usize];
        for qz in -n / 2..n / 2 {
            for qy in -n / 2..n / 2 {
                for qx in -n / 2..n / 2 {
                    let g = DVec3::new(qx as f64, qy as f64, qz as f64);
                    let (d, s) = if g == DVec3::ZERO {
                        (shading.ambient, 0.0)
                    } else {
                        phong(shading, -to_dataset(g).normalize(), light, viewer)
                    };
                    table[Self::index(qx, qy, qz)] =
                        [quantize_unorm(d, rgba_bits), quantize_unorm(s, rgba_bits)];
                }
            }
        }
        ReflectanceMap { table }
    }

    pub fn index(qx: i32, qy: i32, qz: i32) -> usize {
        let m = (1i32 << NORMAL_BITS) - 1;
        ((qx & m) | (qy & m) << NORMAL_BITS | (qz & m) << (2 * NORMAL_BITS)) as usize
    }
}

/// A flat reflectance: full diffuse, no specular (shading disabled).
pub fn unlit(rgba_bits: u32) -> [u32; 2] {
    [max_of(rgba_bits), 0]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reflectance_index_is_a_bijection() {
        let n = 1i32 << NORMAL_BITS;
        let mut seen = vec![false; (n * n * n) as usize];
        for z in -n / 2..n / 2 {
            for y in -n / 2..n / 2 {
                for x in -n / 2..n / 2 {
                    let i = ReflectanceMap::index(x, y, z);
                    assert!(!seen[i]);
                    seen[i] = true;
                }
            }
        }
    }
}
