//! Sheared tri-linear interpolation (§3, Fig. 4): the TRILIN unit.
//!
//! A sample of ray `(u, v)` on plane `k` takes the eight voxels of the four
//! neighbouring discrete rays `A = (u, v)`, `B = (u + 1, v)`, `C = (u, v + 1)`
//! and `D = (u + 1, v + 1)` on planes `k` (front) and `k + 1` (back): an
//! oblique parallelepiped for a parallel view, a pyramid frustum for a
//! perspective one. `A` and `B` come from the 2-D buffer of scanline `v`,
//! `C` and `D` from that of `v + 1`.
//!
//! Fixed-point steps, all `lerp = fixed::lerp_frac` (product rounded half up)
//! with `W` fractional bits:
//! 1. `widen`: each voxel `<< F` (`F = sample_bits - voxel_bits` fractional
//!    bits; exact).
//! 2. Four lerps along the major axis, one weight, the offset `O`:
//!    `a = lerp(A_k, A_k+1, O)`, likewise `b`, `c`, `d`.
//! 3. Two lerps in X with the template weight `wx(u, k)`:
//!    `top = lerp(a, b, wx)`, `bottom = lerp(c, d, wx)`.
//! 4. One lerp in Y with `wy(v, k)`: `s = lerp(top, bottom, wy)`.
//!
//! Each lerp lies between its ends, so `s` fits `sample_bits` unsigned.
//! Where the planner finds every weight 0 (`View::on_grid`) the unit is left
//! out and `s = A_k << F`, which the four lerps also give.

use super::plan::View;
use super::prp::Prp;
use crate::fixed::lerp_frac;

/// The eight voxels of one sample: `[front, back]` of rays A, B, C, D.
pub type Cell = [[u32; 2]; 4];

/// Weights of one sample: offset, X and Y, each `W` fractional bits.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Weights {
    pub offset: u32,
    pub wx: u32,
    pub wy: u32,
}

/// One sheared tri-linear interpolation. Eight equal voxels give that voxel
/// (`lerp(a, a, w) = a` at every step), without the seven lerps.
pub fn interpolate(cell: &Cell, w: Weights, weight_bits: u32, sample_frac: u32) -> u32 {
    let a = cell[0][0];
    if cell.iter().all(|&[f, b]| f == a && b == a) {
        return a << sample_frac;
    }
    let z = |[f, b]: [u32; 2]| lerp_frac(f << sample_frac, b << sample_frac, w.offset, weight_bits);
    let [a, b, c, d] = cell.map(z);
    let top = lerp_frac(a, b, w.wx, weight_bits);
    let bottom = lerp_frac(c, d, w.wx, weight_bits);
    lerp_frac(top, bottom, w.wy, weight_bits)
}

/// [`interpolate`] of every sample of one ray at once, in i32, where every
/// voxel `<< sample_frac` is below `2^(30 - weight_bits)`: `out[k]` from
/// samples `k` and `k + 1` of the rays `r` = A, B, C, D, the weights
/// `wx[k]`, `wy[k]` and the offset. The same lerps, step by step, without
/// [`interpolate`]'s equal-voxel shortcut (which the lerps also give), so
/// the loop runs across samples in vector lanes.
fn ray_i32(out: &mut [u32], r: [&[u32]; 4], wx: &[u32], wy: &[u32], w: [u32; 3]) {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx2") {
        // SAFETY: the CPU has AVX2, checked just above.
        return unsafe { ray_i32_avx2(out, r, wx, wy, w) };
    }
    ray_i32_lanes(out, r, wx, wy, w)
}

/// [`ray_i32_lanes`] compiled for AVX2's eight 32-bit lanes (a vector
/// multiply of 32-bit words, which the x86-64 baseline lacks).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn ray_i32_avx2(out: &mut [u32], r: [&[u32]; 4], wx: &[u32], wy: &[u32], w: [u32; 3]) {
    ray_i32_lanes(out, r, wx, wy, w)
}

/// The body of [`ray_i32`]; `w` is `[offset, weight_bits, sample_frac]`.
#[inline(always)]
fn ray_i32_lanes(out: &mut [u32], r: [&[u32]; 4], wx: &[u32], wy: &[u32], w: [u32; 3]) {
    let [offset, wb, frac] = w;
    let n = out.len();
    let lerp = |a: i32, b: i32, w: i32| crate::fixed::lerp_i32(a, b, w, wb);
    // Exact lengths, so that the loop has no bounds checks.
    let [a, b, c, d] = r.map(|ray| &ray[..n + 1]);
    let (wx, wy) = (&wx[..n], &wy[..n]);
    let o = offset as i32;
    let z = |ray: &[u32], k: usize| lerp((ray[k] << frac) as i32, (ray[k + 1] << frac) as i32, o);
    for k in 0..n {
        let top = lerp(z(a, k), z(b, k), wx[k] as i32);
        let bottom = lerp(z(c, k), z(d, k), wx[k] as i32);
        out[k] = lerp(top, bottom, wy[k] as i32) as u32;
    }
}

/// One interpolated plane of continuous rays: scanline `v`, rays
/// `u0..u0 + rays`, samples `0..K`.
#[derive(Debug, Clone)]
pub struct SamplePlane {
    pub v: i32,
    pub u0: i32,
    pub rays: usize,
    pub planes: usize,
    pub data: Vec<u32>,
}

impl SamplePlane {
    pub fn at(&self, u: i32, k: usize) -> u32 {
        self.ray(u)[k]
    }

    /// Ray `u`'s samples `0..K`.
    pub fn ray(&self, u: i32) -> &[u32] {
        &self.data[(u - self.u0) as usize * self.planes..][..self.planes]
    }

    /// An all-zero plane (a scanline beyond the base plane).
    pub fn zero(v: i32, u0: i32, rays: usize, planes: usize) -> SamplePlane {
        SamplePlane {
            v,
            u0,
            rays,
            planes,
            data: vec![0; rays * planes],
        }
    }
}

/// The eight voxels of sample `k` of ray `u`: rays A, B from the 2-D
/// buffer of scanline `v` (`cur`), C, D from that of `v + 1` (`next`).
pub fn cell(cur: &Prp, next: &Prp, u: i32, k: usize) -> Cell {
    rays_at(
        [cur.ray(u), cur.ray(u + 1), next.ray(u), next.ray(u + 1)],
        k,
    )
}

/// `[front, back]` at sample `k` of the four rays A, B, C, D.
fn rays_at(r: [&[u32]; 4], k: usize) -> Cell {
    r.map(|ray| [ray[k], ray[k + 1]])
}

/// Interpolate the plane of scanline `v` from the 2-D buffers of `v` and
/// `v + 1`, for rays `cur.u0..cur.u0 + cur.rays - 1`.
pub fn plane(view: &View, v: i32, cur: &Prp, next: &Prp, sample_frac: u32) -> SamplePlane {
    let nk = view.dims[2];
    let rays = cur.rays - 1;
    let wb = view.weight_bits;
    let wy = view.y.weights(v);
    let mut data = Vec::with_capacity(rays * nk);
    for i in 0..rays {
        let u = cur.u0 + i as i32;
        let r = [cur.ray(u), cur.ray(u + 1), next.ray(u), next.ray(u + 1)];
        if view.on_grid {
            data.extend(r[0][..nk].iter().map(|&a| a << sample_frac));
            continue;
        }
        let any = r.iter().fold(0, |o, ray| ray.iter().fold(o, |o, &v| o | v));
        if any == 0 {
            // Four empty rays: every sample is 0.
            data.resize(data.len() + nk, 0);
            continue;
        }
        // Every product of a difference and a weight fits 31 bits: the
        // same lerps in i32, the ray's samples at once.
        let narrow = wb <= 16 && (any as u64) << sample_frac < 1 << (30 - wb);
        let wx = view.x.weights(u);
        if narrow {
            let at = data.len();
            data.resize(at + nk, 0);
            ray_i32(&mut data[at..], r, wx, wy, [view.offset, wb, sample_frac]);
            continue;
        }
        for k in 0..nk {
            let w = Weights {
                offset: view.offset,
                wx: wx[k],
                wy: wy[k],
            };
            data.push(interpolate(&rays_at(r, k), w, wb, sample_frac));
        }
    }
    SamplePlane {
        v,
        u0: cur.u0,
        rays,
        planes: nk,
        data,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn w(offset: u32, wx: u32, wy: u32) -> Weights {
        Weights { offset, wx, wy }
    }

    #[test]
    fn corners_return_their_voxel() {
        let cell = [[10, 20], [30, 40], [50, 60], [70, 80]];
        assert_eq!(interpolate(&cell, w(0, 0, 0), 8, 0), 10);
        assert_eq!(interpolate(&cell, w(256, 0, 0), 8, 0), 20);
        assert_eq!(interpolate(&cell, w(0, 256, 0), 8, 0), 30);
        assert_eq!(interpolate(&cell, w(0, 0, 256), 8, 0), 50);
        assert_eq!(interpolate(&cell, w(256, 256, 256), 8, 0), 80);
        // Four fractional bits: the same voxels, scaled by 16.
        assert_eq!(interpolate(&cell, w(256, 256, 256), 8, 4), 80 * 16);
    }

    #[test]
    fn centre_by_hand() {
        // Half weights everywhere: the mean of the eight, 45, rounded per
        // step: z gives 15, 35, 55, 75; x gives 25, 65; y gives 45.
        let cell = [[10, 20], [30, 40], [50, 60], [70, 80]];
        assert_eq!(interpolate(&cell, w(128, 128, 128), 8, 0), 45);
        // Odd ends: z lerp of 0 and 1 at 1/2 rounds half up to 1; with
        // 1 fractional bit it is exactly 1 (0.5 in voxel units).
        let cell = [[0, 1], [0, 1], [0, 1], [0, 1]];
        assert_eq!(interpolate(&cell, w(128, 0, 0), 8, 0), 1);
        assert_eq!(interpolate(&cell, w(128, 0, 0), 8, 1), 1);
        // A quarter at 2 fractional bits: 0.25 * 4 = 1.
        assert_eq!(interpolate(&cell, w(64, 0, 0), 8, 2), 1);
    }

    #[test]
    fn trilinear_of_a_linear_field_is_exact() {
        // f = 3x + 5y + 7z on the unit cell, 8 fractional bits of sample:
        // (wx, wy, o) = (0.25, 0.5, 0.75) gives 0.75 + 2.5 + 5.25 = 8.5.
        let f = |x: u32, y: u32, z: u32| 3 * x + 5 * y + 7 * z;
        let cell = [
            [f(0, 0, 0), f(0, 0, 1)],
            [f(1, 0, 0), f(1, 0, 1)],
            [f(0, 1, 0), f(0, 1, 1)],
            [f(1, 1, 0), f(1, 1, 1)],
        ];
        assert_eq!(
            interpolate(&cell, w(192, 64, 128), 8, 8),
            (8.5 * 256.0) as u32
        );
    }

    #[test]
    fn the_i32_lerps_equal_the_i64_ones_where_they_apply() {
        // 8-bit voxels with 8 fractional bits of sample and 8 of weight,
        // 16-bit voxels with none and 12 of weight: the widest that fit.
        let mut x = 0x2545_f491_4f6c_dd1du64;
        let mut next = |m: u32| {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            (x % (m as u64 + 1)) as u32
        };
        for (vmax, frac, wb) in [(255, 8, 8), (65535, 0, 12), (255, 0, 16)] {
            for _ in 0..20_000 {
                let random: Cell = std::array::from_fn(|_| [next(vmax), next(vmax)]);
                let w = Weights {
                    offset: next(1 << wb),
                    wx: next(1 << wb),
                    wy: next(1 << wb),
                };
                assert!((vmax as u64) << frac < 1 << (30 - wb));
                // Eight equal voxels too, which `interpolate` returns
                // without lerping.
                for cell in [random, [[random[0][0]; 2]; 4]] {
                    // A ray of one sample: its rays A, B, C, D hold the
                    // cell's front and back voxels.
                    let rays = cell.map(|fb| fb.to_vec());
                    let mut out = [0];
                    ray_i32(
                        &mut out,
                        std::array::from_fn(|i| &rays[i][..]),
                        &[w.wx],
                        &[w.wy],
                        [w.offset, wb, frac],
                    );
                    assert_eq!(out[0], interpolate(&cell, w, wb, frac), "{cell:?} {w:?}");
                }
            }
        }
    }

    #[test]
    fn full_scale_16_bit_voxels_stay_in_range() {
        let m = 65535;
        let cell = [[m, m], [m, 0], [0, m], [m, m]];
        for wt in [0, 1, 127, 128, 255, 256] {
            let s = interpolate(&cell, w(wt, wt, wt), 8, 8);
            assert!(s <= m << 8, "{s}");
        }
        assert_eq!(interpolate(&[[m, m]; 4], w(77, 200, 13), 8, 8), m << 8);
    }
}
