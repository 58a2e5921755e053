//! ABC gradient estimation (§4, Figs. 8-11, Eq. 4): the gradient of a sample
//! from the interpolated samples of the above (`v - 1`), current (`v`) and
//! below (`v + 1`) sample planes.
//!
//! Notation: `S(i, j, l)` is the sample of ray `(u + i, v + j)` on plane
//! `k + l`. Ray `u ± 1` runs parallel to ray `u`, one voxel away along x, so
//! `S(i, j, l)` sits at `p + i·e_x + j·e_y + l·r` with `r = (dx, dy, 1)`: the
//! samples form a sheared lattice. For a field `f` with gradient `∇`, a
//! difference of samples at `p ± a` is `2∇·a`; every estimator below returns
//! `2∇` in traversal axes, in sample units (the gradient "undivided", as
//! Cube-4L's central difference).
//!
//! The OCR text of the paper is garbled; each estimator is derived here from
//! the figures and the prose.
//!
//! - **6** (Fig. 8): `G = (S(1,0,0) - S(-1,0,0), S(0,1,0) - S(0,-1,0),
//!   S(0,0,1) - S(0,0,-1))`, differences along `e_x`, `e_y` and the ray `r`
//!   ("P(n,m+1) - P(n,m-1) parallel to the base plane, P(n+1,m-1) -
//!   P(n-1,m+1) in direction of the ray"). The ray component is slanted.
//! - **26** (Fig. 9, Eq. 4): all 26 lattice neighbours, each weighted by its
//!   inverse Manhattan distance, 1/3 replaced by 1/4 ("to avoid the
//!   unfavorable hardware division by 3"). Eq. 4 in 2-D reads `G_base =
//!   [½P(n+1,m) + P(n,m+1) + ½P(n-1,m+2)] - [½P(n+1,m-2) + P(n,m-1) +
//!   ½P(n-1,m)]`: the right neighbour with weight 1 and its two neighbours
//!   along the ray with ½. In 3-D, x: `Σ_{j,l} w(1+|j|+|l|)·(S(1,j,l) -
//!   S(-1,j,l))` with integer weights 4, 2, 1 for distances 1, 2, 3 (the
//!   1, ½, ¼ scaled by 4); they total 16 per side, so `(Σ + 8) >> 4`
//!   (arithmetic) brings it to the 6-neighbourhood's scale. Likewise y, and
//!   the ray: `Σ_{i,j} w(i,j,1)·(S(i,j,1) - S(i,j,-1))`.
//! - **10** (Fig. 10): as the 6, but the left and right (above and below)
//!   samples are replaced by points orthogonal to the ray, linearly
//!   interpolated on the neighbour rays. The plane through `p` orthogonal to
//!   `r` meets ray `u + 1` at `l = -t_x`, `t_x = dx/|r|²`, between its samples
//!   `k` and `k - sign(dx)`, weight `T_x = round(|t_x|·2^W)`; ray `u - 1` at
//!   `l = +t_x`. That is 4 + 4 + 2 = 10 samples. The three differences are
//!   along `a_x = e_x - t_x·r`, `a_y = e_y - t_y·r` and `r`, which are not the
//!   volume axes ("the light vector must be represented in a local
//!   coordinate system"), and the weights change per ray in perspective.
//! - **12** (Fig. 11): x and y from `S(±1, 0, 0)` and `S(0, ±1, 0)`, which lie
//!   exactly along `e_x` and `e_y`; z from `p ± e_z`. `p + e_z = p + r -
//!   dx·e_x - dy·e_y` lies on plane `k + 1` at lattice offset `(-dx, -dy)`: one
//!   bilinear interpolation of the rays `(0|-sx, 0|-sy)` with weights `|dx|`,
//!   `|dy|` (`sx = sign(dx)`). `p - e_z` likewise on plane `k - 1` at
//!   `(dx, dy)`. 2 + 2 + 4 + 4 = 12 samples, and the result is already along
//!   the primary axes, whatever the base plane: no jump at 45°.
//!
//! **Basis correction.** The 6, 26 and 10 give differences along a basis `B`
//! (rows `b_i`, `G_i = 2∇·b_i`); `2∇ = B⁻¹·G`. For the 6 and 26 `B⁻¹` is the
//! shear `g = (G_x, G_y, G_r - dx·G_x - dy·G_y)`:
//! `g_z = G_r - ((DX·G_x + DY·G_y + 2^(W-1)) >> W)`. For the 10, `B⁻¹` is
//! computed per ray in f64 from the quantized `dx, dy, T`, each entry
//! quantized to `W` fractional bits, and `g_i = (Σ_j C_ij·G_j + 2^(W-1)) >>
//! W`. The 12 needs none.
//!
//! **Gradient word.** Each component is saturated to `±(2^(gradient_bits-1)
//! - 1)` (counted in `Stats::gradient_saturations`).

use super::plan::Neighbourhood;
use super::trilin::SamplePlane;
use crate::fixed::{lerp_frac, quantize};
use glam::{DMat3, DVec3};

/// The above, current and below sample planes.
pub struct Planes<'a> {
    pub above: &'a SamplePlane,
    pub current: &'a SamplePlane,
    pub below: &'a SamplePlane,
}

impl Planes<'_> {
    /// `S(i, j, l)` around ray `u`, plane `k`.
    fn s(&self, u: i32, k: usize, i: i32, j: i32, l: i32) -> u32 {
        let p = match j {
            -1 => self.above,
            0 => self.current,
            _ => self.below,
        };
        p.at(u + i, (k as i64 + l as i64) as usize)
    }
}

/// Per-ray constants of the estimators: the quantized increments, the
/// 10-neighbourhood's weights and its basis correction.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct RayCoeffs {
    pub dx: i32,
    pub dy: i32,
    pub t: [u32; 2],
    pub c10: [[i64; 3]; 3],
}

impl RayCoeffs {
    pub fn new(dx: i32, dy: i32, w: u32) -> RayCoeffs {
        let one = (1u64 << w) as f64;
        let (fx, fy) = (dx as f64 / one, dy as f64 / one);
        let r2 = 1.0 + fx * fx + fy * fy;
        let t = [
            quantize(fx.abs() / r2, w) as u32,
            quantize(fy.abs() / r2, w) as u32,
        ];
        // The basis of the 10: rows a_x, a_y, r with the quantized weights.
        let tx = fx.signum() * t[0] as f64 / one;
        let ty = fy.signum() * t[1] as f64 / one;
        let r = DVec3::new(fx, fy, 1.0);
        let ax = DVec3::X - tx * r;
        let ay = DVec3::Y - ty * r;
        let inv = DMat3::from_cols(ax, ay, r).transpose().inverse();
        let c10 = std::array::from_fn(|i| std::array::from_fn(|j| quantize(inv.col(j)[i], w)));
        RayCoeffs { dx, dy, t, c10 }
    }
}

/// The three differences an estimator takes, along its own basis `B` (the
/// 6, 26 and 10: see the module's notes) or along the axes (the 12), before
/// any basis correction: `2∇·b_i` in sample units.
pub fn differences(
    n: Neighbourhood,
    planes: &Planes,
    u: i32,
    k: usize,
    c: &RayCoeffs,
    w: u32,
) -> [i64; 3] {
    let s = |i, j, l| planes.s(u, k, i, j, l) as i64;
    match n {
        Neighbourhood::N6 => [
            s(1, 0, 0) - s(-1, 0, 0),
            s(0, 1, 0) - s(0, -1, 0),
            s(0, 0, 1) - s(0, 0, -1),
        ],
        Neighbourhood::N26 => {
            let wt = |d: i32| 4i64 >> (d - 1);
            let mut g = [0i64; 3];
            for a in -1..=1i32 {
                for b in -1..=1i32 {
                    let wgt = wt(1 + a.abs() + b.abs());
                    g[0] += wgt * (s(1, a, b) - s(-1, a, b));
                    g[1] += wgt * (s(a, 1, b) - s(a, -1, b));
                    g[2] += wgt * (s(a, b, 1) - s(a, b, -1));
                }
            }
            g.map(|v| (v + 8) >> 4)
        }
        Neighbourhood::N10 => {
            let (sx, sy) = (c.dx.signum(), c.dy.signum());
            let l = |a: u32, b: u32, t: u32| lerp_frac(a, b, t, w) as i64;
            let p = |i, j, l0| planes.s(u, k, i, j, l0);
            let gx = l(p(1, 0, 0), p(1, 0, -sx), c.t[0]) - l(p(-1, 0, 0), p(-1, 0, sx), c.t[0]);
            let gy = l(p(0, 1, 0), p(0, 1, -sy), c.t[1]) - l(p(0, -1, 0), p(0, -1, sy), c.t[1]);
            [gx, gy, s(0, 0, 1) - s(0, 0, -1)]
        }
        Neighbourhood::N12 => {
            let (sx, sy) = (c.dx.signum(), c.dy.signum());
            let (wx, wy) = (c.dx.unsigned_abs(), c.dy.unsigned_abs());
            let p = |i, j, l0| planes.s(u, k, i, j, l0);
            let bilinear = |l0: i32, ex: i32, ey: i32| {
                let top = lerp_frac(p(0, 0, l0), p(ex, 0, l0), wx, w);
                let bottom = lerp_frac(p(0, ey, l0), p(ex, ey, l0), wx, w);
                lerp_frac(top, bottom, wy, w) as i64
            };
            [
                s(1, 0, 0) - s(-1, 0, 0),
                s(0, 1, 0) - s(0, -1, 0),
                bilinear(1, -sx, -sy) - bilinear(-1, sx, sy),
            ]
        }
    }
}

/// `B⁻¹` applied to an estimator's [`differences`]: the shear for the 6 and
/// 26, the per-ray matrix `C` for the 10, nothing for the 12.
pub fn basis_corrected(n: Neighbourhood, g: [i64; 3], c: &RayCoeffs, w: u32) -> [i64; 3] {
    let half = 1i64 << (w - 1);
    match n {
        Neighbourhood::N6 | Neighbourhood::N26 => {
            let [gx, gy, gr] = g;
            [
                gx,
                gy,
                gr - ((c.dx as i64 * gx + c.dy as i64 * gy + half) >> w),
            ]
        }
        Neighbourhood::N10 => std::array::from_fn(|i| {
            (c.c10[i].iter().zip(g).map(|(a, b)| a * b).sum::<i64>() + half) >> w
        }),
        Neighbourhood::N12 => g,
    }
}

/// Gradient word: `2∇` in traversal axes, sample units, saturated; and
/// whether a component saturated.
pub fn gradient(
    n: Neighbourhood,
    planes: &Planes,
    u: i32,
    k: usize,
    c: &RayCoeffs,
    w: u32,
    gradient_bits: u32,
) -> ([i32; 3], bool) {
    let g = basis_corrected(n, differences(n, planes, u, k, c, w), c, w);
    let lim = (1i64 << (gradient_bits - 1)) - 1;
    let mut sat = false;
    let out = g.map(|v| {
        sat |= v.abs() > lim;
        v.clamp(-lim, lim) as i32
    });
    (out, sat)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Sample planes of the field `f(x, y, z)` sampled on the sheared
    /// lattice of rays with increments `(fx, fy)`: ray `(u, v)`, plane `k`
    /// at `(u + k·fx, v + k·fy, k)`.
    fn lattice(f: impl Fn(f64, f64, f64) -> f64, fx: f64, fy: f64) -> [SamplePlane; 3] {
        std::array::from_fn(|j| {
            let v = j as i32 - 1;
            let mut data = vec![];
            for u in -3..=3 {
                for k in 0..5 {
                    let k = k as f64;
                    data.push(f(u as f64 + k * fx, v as f64 + k * fy, k).round() as u32);
                }
            }
            SamplePlane {
                v,
                u0: -3,
                rays: 7,
                planes: 5,
                data,
            }
        })
    }

    fn grad(n: Neighbourhood, f: impl Fn(f64, f64, f64) -> f64, dx: i32, dy: i32) -> [i32; 3] {
        let [a, c, b] = lattice(f, dx as f64 / 256.0, dy as f64 / 256.0);
        let planes = Planes {
            above: &a,
            current: &c,
            below: &b,
        };
        gradient(n, &planes, 0, 2, &RayCoeffs::new(dx, dy, 8), 8, 24).0
    }

    const ALL: [Neighbourhood; 4] = [
        Neighbourhood::N6,
        Neighbourhood::N10,
        Neighbourhood::N12,
        Neighbourhood::N26,
    ];

    #[test]
    fn every_neighbourhood_is_exact_on_a_linear_field_head_on() {
        // f = 1000 + 30x + 20y + 10z: 2∇ = (60, 40, 20).
        let f = |x: f64, y: f64, z: f64| 1000.0 + 30.0 * x + 20.0 * y + 10.0 * z;
        for n in ALL {
            assert_eq!(grad(n, f, 0, 0), [60, 40, 20], "{n:?}");
        }
    }

    #[test]
    fn every_neighbourhood_recovers_the_axes_on_a_sheared_lattice() {
        // dx = 0.5, dy = -0.25 (exact in 8 bits), the same linear field:
        // sample values are exact integers (30·0.5k, 20·0.25k, ...), so
        // each estimator's shear/basis correction must give (60, 40, 20)
        // up to the rounding of its weights.
        let f = |x: f64, y: f64, z: f64| 1000.0 + 32.0 * x + 24.0 * y + 8.0 * z;
        for n in ALL {
            let g = grad(n, f, 128, -64);
            let want = [64, 48, 16];
            for i in 0..3 {
                assert!((g[i] - want[i]).abs() <= 1, "{n:?}: {g:?}");
            }
        }
        // The 6 and 12 by hand: G_r = S(k+1) - S(k-1) = 2·(32·0.5 - 24·0.25
        // + 8) = 36; g_z = 36 - (128·64 + (-64)·48 + 128) >> 8 = 36 - 20 = 16.
        assert_eq!(grad(Neighbourhood::N6, f, 128, -64), [64, 48, 16]);
        assert_eq!(grad(Neighbourhood::N12, f, 128, -64), [64, 48, 16]);
    }

    #[test]
    fn at_45_degrees_the_12_is_exact_and_the_6_differs_in_samples_used() {
        // dx = 1: p + e_z is exactly the sample of ray u - 1 on plane k + 1.
        let f = |x: f64, y: f64, z: f64| 500.0 + 7.0 * x * x + 3.0 * y + 11.0 * z;
        let g12 = grad(Neighbourhood::N12, f, 256, 0);
        // Along x: f(x+1) - f(x-1) at x = 2 (ray 0, plane 2): 7·(9 - 1) = 56.
        assert_eq!(g12[0], 56);
        assert_eq!(g12[2], 22);
    }

    #[test]
    fn the_26_uses_quarter_weights_at_the_corners() {
        // Only the corner sample S(1, 1, 1) differs from 0: its weight is
        // 1 of 16, so G_x = (1·160 + 8) >> 4 = 10, G_y = 10, G_r = 10, and
        // head on the shear leaves them.
        let mut planes = lattice(|_, _, _| 0.0, 0.0, 0.0);
        let i = 4 * 5 + 3; // ray u = 1, plane k + 1 = 3, below plane.
        planes[2].data[i] = 160;
        let [a, c, b] = planes;
        let p = Planes {
            above: &a,
            current: &c,
            below: &b,
        };
        let (g, _) = gradient(
            Neighbourhood::N26,
            &p,
            0,
            2,
            &RayCoeffs::new(0, 0, 8),
            8,
            24,
        );
        assert_eq!(g, [10, 10, 10]);
    }

    #[test]
    fn ten_neighbourhood_weights_by_hand() {
        // dx = 0.5, dy = 0: t_x = 0.5 / 1.25 = 0.4 -> round(102.4) = 102.
        let c = RayCoeffs::new(128, 0, 8);
        assert_eq!(c.t, [102, 0]);
        // Head on the basis is the identity.
        let c = RayCoeffs::new(0, 0, 8);
        assert_eq!(c.c10, [[256, 0, 0], [0, 256, 0], [0, 0, 256]]);
    }

    #[test]
    fn gradient_word_saturates_and_says_so() {
        let f = |x: f64, _: f64, _: f64| 60000.0 * (x > 0.0) as u8 as f64;
        let [a, c, b] = lattice(f, 0.0, 0.0);
        let p = Planes {
            above: &a,
            current: &c,
            below: &b,
        };
        let (g, sat) = gradient(Neighbourhood::N6, &p, 0, 2, &RayCoeffs::new(0, 0, 8), 8, 16);
        assert_eq!((g[0], sat), (32767, true));
    }
}
