//! The LUTs of the Cube-4L shader and classifier (paper §3.3-3.4), filled
//! from the scene's transfer function and lighting formulas (`scene`): the
//! colour LUT, the opacity LUT (2-D with a gradient-magnitude index when the
//! scene has gradient opacity) and the lighting tables (diffuse and specular
//! by cosine, with the light and half vectors as registers). Only the golden
//! models go through these quantized tables; the float reference evaluates
//! the formulas exactly.

use crate::fixed::{max_of, mul_unorm, quantize_unorm, sat_u};
use glam::DVec3;
use scene::transfer::{correct_opacity, TransferFn};
use scene::Shading;

/// Index bits of the intensity LUTs: the voxel's top bits, at most 12.
pub fn lut_bits(voxel_bits: u32) -> u32 {
    voxel_bits.min(12)
}

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

    #[inline]
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

    #[inline]
    pub fn row(&self, v: u32) -> usize {
        (v >> self.shift) as usize
    }

    /// Opacity of intensity `v` with integer gradient magnitude `gm`
    /// (ignored when the LUT has no gradient dimension).
    #[inline]
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

/// Bits of the cosine index of the lighting tables: `2^COS_BITS` entries,
/// entry `i` for the cosine `i / (2^COS_BITS - 1)`, so 0 and 1 are exact.
pub const COS_BITS: u32 = 10;
/// Fractional bits of the light and half-vector registers (signed, a unit
/// vector's components in `[-2^DIR_FRAC, 2^DIR_FRAC]`).
pub const DIR_FRAC: u32 = 11;
/// Fractional bits of the reciprocal norms [`rnorm`].
pub const RNORM_FRAC: u32 = 15;
/// Widest normal the golden models take (`hardware.normal_bits`, checked
/// by the scene).
pub const MAX_NORMAL_BITS: u32 = *scene::spec::NORMAL_BITS.end();

/// Largest magnitude of a quantized normal's `normal_bits`-bit component,
/// `2^(normal_bits - 1) - 1` (15 at 5 bits): the quantizer saturates to it.
pub const fn normal_limit(normal_bits: u32) -> i32 {
    (1 << (normal_bits - 1)) - 1
}

/// Largest squared length of a quantized normal of `normal_bits`-bit
/// components: three of magnitude [`normal_limit`] (675 at 5 bits).
pub const fn max_n2(normal_bits: u32) -> u32 {
    let m = normal_limit(normal_bits) as u32;
    3 * m * m
}

/// Words of the reciprocal-norm ROM for `normal_bits`-bit normals: the power
/// of two that holds every `|q|²` up to [`max_n2`] (1 024 at 5 bits, the
/// default; 4 096 at 6; 65 536 at 8).
pub const fn rnorm_words(normal_bits: u32) -> u32 {
    (max_n2(normal_bits) + 1).next_power_of_two()
}

/// `1 / |q|` of a quantized normal of squared length `n2` (at most
/// [`max_n2`] of [`MAX_NORMAL_BITS`]), in [`RNORM_FRAC`] fractional bits,
/// rounded to nearest; 0 for `n2 = 0`. A constant table of the hardware (it
/// depends on no scene; a narrower normal reads its first
/// [`rnorm_words`]), built once.
pub fn rnorm(n2: u32) -> u32 {
    static TABLE: std::sync::LazyLock<Vec<u32>> =
        std::sync::LazyLock::new(|| (0..rnorm_words(MAX_NORMAL_BITS)).map(rnorm_entry).collect());
    TABLE[n2 as usize]
}

/// One entry of the [`rnorm`] table.
fn rnorm_entry(n2: u32) -> u32 {
    if n2 == 0 {
        return 0;
    }
    // round(2^15 / sqrt(n2)) exactly: the largest r with
    // (2r - 1)^2 * n2 <= 4 * 2^30, by integer search.
    let target = 4u64 << (2 * RNORM_FRAC);
    let mut r = ((1u64 << RNORM_FRAC) as f64 / (n2 as f64).sqrt()).round() as u64 + 1;
    while r > 0 && (2 * r - 1) * (2 * r - 1) * n2 as u64 > target {
        r -= 1;
    }
    r as u32
}

/// Phong lighting by quantized normal, as a small datapath computes it
/// (paper §3.4's reflectance, with the map factored): for the quantized
/// gradient `q` (signed `normal_bits`-bit components in the sweep's or
/// base plane's space; the normal is `-q / |q|`), the cosines with the light
/// and the half vector from two dot products and a reciprocal norm, each an
/// index into a table of the diffuse multiplier and of the specular term.
///
/// Fixed-point steps, for a direction register `d` (`light` or `half`):
/// 1. `dot = q · d` (exact integers; the registers hold `-L` and `-H` in the
///    gradient's space, [`DIR_FRAC`] fractional bits);
/// 2. `dot <= 0`: index 0 and no light on the surface; else
///    `t = min(dot, 2^(normal_bits + DIR_FRAC) - 1) · rnorm(|q|²)` (exact;
///    a unit register never saturates) and
///    `i = min(2^COS_BITS - 1, (t · (2^COS_BITS - 1) + 2^25) >> 26)`, the
///    cosine `t / 2^26` to the nearest table entry;
/// 3. `diffuse = diffuse[i_light]`; `specular = specular[i_half]` when the
///    light's dot product is positive, else 0 (as Phong).
///
/// A zero gradient lights with the ambient term only: its dot products are
/// 0, and `diffuse[0]` is the ambient term.
///
/// The fields are what the host writes; read them, but build a new
/// `Lighting` for other registers or tables: `reflect` remembers what it
/// returned for each normal.
#[derive(Debug, Clone)]
pub struct Lighting {
    /// `round(-L · 2^DIR_FRAC)` and `round(-H · 2^DIR_FRAC)`, the light and
    /// half vectors in the gradient's space: registers the host writes.
    pub light: [i32; 3],
    pub half: [i32; 3],
    /// `sat(ambient + diffuse · c)` and `sat(specular · c^shininess)` for
    /// `c = i / (2^COS_BITS - 1)`, unorm of `rgba_bits`: tables the host
    /// loads (they depend on the lighting coefficients only, not the view).
    pub diffuse: Vec<u32>,
    pub specular: Vec<u32>,
    /// Bits per signed component of the quantized normal
    /// (`hardware.normal_bits`): [`quantize_normal`](crate::common::gradient::quantize_normal)'s
    /// width and the dot products' saturation.
    pub normal_bits: u32,
    /// [`Lighting::reflect`] of each normal once computed: a software memo
    /// of the same function (the hardware computes every sample).
    memo: ReflectMemo,
}

/// Widest normals whose every [`Lighting::reflect`] is remembered:
/// `(2^bits - 1)^3` entries of 8 bytes, 29 791 at 5 bits and 250 047 at 6.
const MEMO_BITS: u32 = 6;

/// One word per quantized normal `q` (components within
/// `±(2^(bits - 1) - 1)`): 0 until the normal is first lit, then
/// `1 << 63 | diffuse << 32 | specular`. Filled as the samples need it, by
/// any thread (two threads that race store the same word), so that a small
/// volume does not pay for every normal.
#[derive(Debug, Default)]
struct ReflectMemo(Vec<std::sync::atomic::AtomicU64>);

impl Clone for ReflectMemo {
    fn clone(&self) -> Self {
        use std::sync::atomic::{AtomicU64, Ordering::Relaxed};
        ReflectMemo(
            self.0
                .iter()
                .map(|w| AtomicU64::new(w.load(Relaxed)))
                .collect(),
        )
    }
}

impl Lighting {
    /// `to_dataset` maps the gradient's space to dataset space (an
    /// orthogonal matrix); `light` and `viewer` are unit vectors in dataset
    /// space.
    pub fn new(
        shading: &Shading,
        to_dataset: glam::DMat3,
        light: DVec3,
        viewer: DVec3,
        rgba_bits: u32,
        normal_bits: u32,
    ) -> Lighting {
        let h = (light + viewer).normalize_or_zero();
        // The normal is the negated gradient: n · l = -q · (to_dataset^T l) / |q|.
        let reg = |v: DVec3| {
            let p = -(to_dataset.transpose() * v) * (1u32 << DIR_FRAC) as f64;
            [p.x, p.y, p.z].map(|c| c.round() as i32)
        };
        let n = 1u32 << COS_BITS;
        let cos = |i: u32| i as f64 / (n - 1) as f64;
        Lighting::from_registers(
            reg(light),
            reg(h),
            (0..n)
                .map(|i| {
                    quantize_unorm(
                        (shading.ambient + shading.diffuse * cos(i)).min(1.0),
                        rgba_bits,
                    )
                })
                .collect(),
            (0..n)
                .map(|i| {
                    let s = shading.specular * cos(i).powf(shading.shininess);
                    quantize_unorm(s.min(1.0), rgba_bits)
                })
                .collect(),
            normal_bits,
        )
    }

    /// The lighting of the registers and tables as the host writes them
    /// (any direction registers, not only unit vectors).
    pub fn from_registers(
        light: [i32; 3],
        half: [i32; 3],
        diffuse: Vec<u32>,
        specular: Vec<u32>,
        normal_bits: u32,
    ) -> Lighting {
        // The memo packs both words in 31 bits each (the tables are unorm
        // of at most 16 bits).
        assert!(
            diffuse.iter().chain(&specular).all(|&w| w < 1 << 31),
            "lighting table words wider than 31 bits"
        );
        let memo = if normal_bits <= MEMO_BITS {
            let side = 2 * normal_limit(normal_bits) as usize + 1;
            (0..side.pow(3)).map(|_| Default::default()).collect()
        } else {
            Vec::new()
        };
        Lighting {
            light,
            half,
            diffuse,
            specular,
            normal_bits,
            memo: ReflectMemo(memo),
        }
    }

    /// The table index of the cosine between `-q` (of `normal_bits`-bit
    /// components) and the direction `d`, and whether it is positive (steps
    /// 1-2 above).
    pub fn cos_index(q: [i32; 3], d: [i32; 3], normal_bits: u32) -> (u32, bool) {
        let dot: i64 = (0..3).map(|i| q[i] as i64 * d[i] as i64).sum();
        if dot <= 0 {
            return (0, false);
        }
        // A unit direction keeps |dot| <= |q| * 2^DIR_FRAC, below
        // 2^(normal_bits + DIR_FRAC) (at 5 bits: 26 * 2048, one 16-bit
        // multiplier's operand in the RTL; wider normals take two); other registers saturate.
        let dot = dot.min((1 << (normal_bits + DIR_FRAC)) - 1);
        let n2 = q.iter().map(|c| (c * c) as u32).sum();
        let t = dot as u64 * rnorm(n2) as u64;
        let last = (1u64 << COS_BITS) - 1;
        let shift = DIR_FRAC + RNORM_FRAC;
        (
            ((t * last + (1 << (shift - 1))) >> shift).min(last) as u32,
            true,
        )
    }

    /// `[diffuse, specular]` for the quantized gradient `q` (remembered
    /// per normal where the normals are at most [`MEMO_BITS`] wide).
    #[inline]
    pub fn reflect(&self, q: [i32; 3]) -> [u32; 2] {
        use std::sync::atomic::Ordering::Relaxed;
        let lim = normal_limit(self.normal_bits);
        if self.memo.0.is_empty() || q.iter().any(|c| c.abs() > lim) {
            return self.reflect_uncached(q);
        }
        let side = 2 * lim + 1;
        let i = ((q[0] + lim) * side + q[1] + lim) * side + q[2] + lim;
        let word = &self.memo.0[i as usize];
        match word.load(Relaxed) {
            0 => {
                let [d, s] = self.reflect_uncached(q);
                word.store(1 << 63 | (d as u64) << 32 | s as u64, Relaxed);
                [d, s]
            }
            w => [((w >> 32) & 0x7fff_ffff) as u32, w as u32],
        }
    }

    /// [`Lighting::reflect`], computed (steps 1-3 above).
    fn reflect_uncached(&self, q: [i32; 3]) -> [u32; 2] {
        let (il, lit) = Self::cos_index(q, self.light, self.normal_bits);
        let s = if lit {
            self.specular[Self::cos_index(q, self.half, self.normal_bits).0 as usize]
        } else {
            0
        };
        [self.diffuse[il as usize], s]
    }
}

/// Shade and weight one sample (both architectures): per RGB channel
/// `shaded = sat(mul(c, d) + s)` (`sat`: clamp to `M = 2^rgba_bits - 1`), then
/// `mul(shaded, alpha)`; emitted as `[r, g, b, alpha]`.
#[inline]
pub fn shade_weight(rgb: [u32; 3], [d, s]: [u32; 2], alpha: u32, rgba_bits: u32) -> [u32; 4] {
    let m = max_of(rgba_bits);
    let shade = |c: u32| sat_u(mul_unorm(c, d, rgba_bits) as u64 + s as u64, m);
    let w = |c: u32| mul_unorm(shade(c), alpha, rgba_bits);
    [w(rgb[0]), w(rgb[1]), w(rgb[2]), alpha]
}

/// A flat reflectance: full diffuse, no specular (shading disabled).
pub fn unlit(rgba_bits: u32) -> [u32; 2] {
    [max_of(rgba_bits), 0]
}

#[cfg(test)]
mod tests {
    use super::*;
    use scene::lighting::phong;
    use scene::Scene;

    /// The transfer function of a scene with `transfer` (JSON) and `voxel_bits`.
    fn transfer(json: &str, voxel_bits: u32) -> TransferFn {
        let text = format!(
            r#"{{"volume": {{"builtin": "sphere", "dims": [4, 4, 4]}},
                "view": {{"projection": "parallel"}}, "transfer": {json},
                "hardware": {{"voxel_bits": {voxel_bits}}}}}"#
        );
        TransferFn::new(&Scene::from_json(&text, None).unwrap())
    }

    /// `got` is `num / den` rounded to nearest; at an exact half, where the
    /// float evaluation may land on either side, either neighbour.
    fn assert_rounded(got: u32, num: u128, den: u128, what: &str) {
        let (q, r) = ((num / den) as u32, num % den);
        match (2 * r).cmp(&den) {
            std::cmp::Ordering::Less => assert_eq!(got, q, "{what}"),
            std::cmp::Ordering::Greater => assert_eq!(got, q + 1, "{what}"),
            std::cmp::Ordering::Equal => assert!(got == q || got == q + 1, "{what}"),
        }
    }

    #[test]
    fn lut_index_bits() {
        assert_eq!(lut_bits(8), 8);
        assert_eq!(lut_bits(12), 12);
        assert_eq!(lut_bits(16), 12);
    }

    #[test]
    fn bin_centres() {
        assert_eq!(bin_centre(0, 0), 0.0);
        assert_eq!(bin_centre(5, 0), 5.0);
        assert_eq!(bin_centre(255, 0), 255.0);
        assert_eq!(bin_centre(2, 1), 4.5);
        assert_eq!(bin_centre(0, 4), 7.5);
        assert_eq!(bin_centre(3, 4), 55.5);
        assert_eq!(bin_centre(4095, 4), 65527.5);
        assert_eq!(bin_centre(1, 5), 47.5);
    }

    #[test]
    fn colour_lut_8_bit_entries() {
        // r = v / 255, g = 0.2 v / 255, b = 1 - v / 255: entries v,
        // round(v / 5) (never a half) and 255 - v.
        let tf = transfer(
            r#"{"opacity": [[0, 1]], "color": [[0, 0, 0, 1], [255, 1, 0.2, 0]]}"#,
            8,
        );
        let lut = ColourLut::new(&tf, 8, 8);
        assert_eq!(lut.shift, 0);
        assert_eq!(lut.table.len(), 256);
        for v in 0..256u32 {
            let want = [v, (v + 2) / 5, 255 - v];
            assert_eq!(lut.table[v as usize], want, "{v}");
            assert_eq!(lut.lookup(v), want, "{v}");
        }
    }

    #[test]
    fn colour_lut_16_bit_voxels_use_bin_centres() {
        // 16-bit voxels index a 12-bit LUT: entry i stands for the bin
        // centre (32 i + 15) / 2. r ramps over the whole range, g reaches 1
        // at 4095, b is flat 0.6; 15-bit colour (M = 32767).
        let tf = transfer(
            r#"{"opacity": [[0, 1]],
                "color": [[0, 0, 0, 0.6], [4095, 0.062485694666971844, 1, 0.6],
                          [65535, 1, 1, 0.6]]}"#,
            16,
        );
        let lut = ColourLut::new(&tf, 16, 15);
        assert_eq!(lut.shift, 4);
        assert_eq!(lut.table.len(), 4096);
        let m = 32767u128;
        for v in 0..65536u32 {
            let got = lut.lookup(v);
            let i = (v / 16) as u128;
            assert_eq!(got, lut.table[i as usize]);
            if v % 16 != 0 {
                continue;
            }
            assert_rounded(got[0], (32 * i + 15) * m, 2 * 65535, &format!("r {i}"));
            if i < 256 {
                assert_rounded(got[1], (32 * i + 15) * m, 2 * 4095, &format!("g {i}"));
            } else {
                assert_eq!(got[1], 32767, "g {i}");
            }
            assert_eq!(got[2], 19660, "b {i}"); // 0.6 * 32767 = 19660.2
        }
        // Hand values: bin 0 (centre 7.5), bin 100 (centre 1607.5).
        assert_eq!(lut.lookup(0), [4, 60, 19660]); // 3.75, 60.0
        assert_eq!(lut.lookup(1615), [804, 12863, 19660]); // 803.7, 12862.9
    }

    #[test]
    fn opacity_lut_without_gradient() {
        let tf = transfer(
            r#"{"opacity": [[0, 0], [255, 1]], "color": [[0, 1, 1, 1]],
                "gradient_opacity": [[0, 0], [100, 1]]}"#,
            8,
        );
        // The scene has gradient opacity but the caller leaves the unit out.
        let lut = OpacityLut::new(&tf, 8, 8, 1.0, false);
        assert_eq!(lut.shift, 0);
        assert_eq!(lut.gm_shift, None);
        assert_eq!(lut.table, (0..256).collect::<Vec<u32>>());
        assert_eq!(lut.row_max, lut.table);
        for v in 0..256u32 {
            assert_eq!(lut.row(v), v as usize);
            for gm in [0, 1, 31, 1000] {
                assert_eq!(lut.lookup(v, gm), v);
            }
        }
    }

    #[test]
    fn opacity_lut_16_bit_voxels_use_bin_centres() {
        let tf = transfer(
            r#"{"opacity": [[0, 0], [65535, 1]], "color": [[0, 1, 1, 1]]}"#,
            16,
        );
        let lut = OpacityLut::new(&tf, 16, 15, 1.0, true);
        assert_eq!((lut.shift, lut.gm_shift), (4, None));
        assert_eq!(lut.table.len(), 4096);
        for v in 0..65536u32 {
            let i = v / 16;
            assert_eq!(lut.row(v), i as usize);
            assert_eq!(lut.lookup(v, 77), lut.table[i as usize]);
            let num = (32 * i as u128 + 15) * 32767;
            assert_rounded(lut.lookup(v, 0), num, 2 * 65535, &format!("{v}"));
        }
    }

    #[test]
    fn opacity_correction_for_spacing() {
        // a' = 1 - (1 - a)^spacing, quantized to 8 bits.
        let tf = transfer(
            r#"{"opacity": [[0, 0], [1, 0], [2, 0.5], [3, 1], [255, 1]],
                "color": [[0, 1, 1, 1]]}"#,
            8,
        );
        let at = |spacing: f64| {
            let lut = OpacityLut::new(&tf, 8, 8, spacing, false);
            [lut.table[0], lut.table[2], lut.table[3], lut.table[200]]
        };
        assert_eq!(at(1.0), [0, 128, 255, 255]); // 127.5 -> 128
        assert_eq!(at(2.0), [0, 191, 255, 255]); // 0.75 -> 191.25
        assert_eq!(at(0.5), [0, 75, 255, 255]); // 1 - sqrt(1/2) -> 74.7
        assert_eq!(at(3f64.sqrt()), [0, 178, 255, 255]); // 0.699 -> 178.2
    }

    #[test]
    fn opacity_lut_with_gradient_magnitude() {
        // Gradient map up to 100 voxel units per voxel: the integer magnitude
        // (of the undivided difference) covers [0, 400), 9 bits, so its
        // 4-bit index is gm >> 5. Entry (i, g) holds
        // a(i) * f((32 g + 15.5) / 2) = i * min((64 g + 31) / 400, 1).
        let tf = transfer(
            r#"{"opacity": [[0, 0], [255, 1]], "color": [[0, 1, 1, 1]],
                "gradient_opacity": [[0, 0], [100, 1]]}"#,
            8,
        );
        let lut = OpacityLut::new(&tf, 8, 8, 1.0, true);
        assert_eq!((lut.shift, lut.gm_shift), (0, Some(5)));
        assert_eq!(lut.table.len(), 256 * 16);
        let entry = |i: u32, g: u64| lut.table[i as usize * 16 + g as usize];
        for i in 0..256u32 {
            for g in 0..16u64 {
                let what = format!("({i}, {g})");
                if g <= 5 {
                    assert_rounded(entry(i, g), (i as u128) * (64 * g as u128 + 31), 400, &what);
                } else {
                    assert_eq!(entry(i, g), i, "{what}");
                }
            }
            assert_eq!(lut.row_max[i as usize], i);
            for gm in 0..1500u64 {
                assert_eq!(lut.lookup(i, gm), entry(i, (gm / 32).min(15)), "{i} {gm}");
            }
        }
        // Hand values: 100 * 31 / 400 = 7.75, 100 * 223 / 400 = 55.75.
        assert_eq!(entry(100, 0), 8); // 7.75
        assert_eq!(entry(100, 3), 56); // 55.75
        assert_eq!(lut.lookup(100, 100), 56);
        assert_eq!(lut.lookup(100, 10_000), 100);
    }

    #[test]
    fn opacity_lut_small_gradient_range_has_no_shift() {
        // Range 2: magnitudes up to 8, 4 bits, index = gm itself; entry g
        // stands for gradient g / 2: factor 1 - g / 8 up to g = 4, then 0.5.
        let tf = transfer(
            r#"{"opacity": [[0, 1]], "color": [[0, 1, 1, 1]],
                "gradient_opacity": [[0, 1], [2, 0.5]]}"#,
            8,
        );
        let lut = OpacityLut::new(&tf, 8, 8, 1.0, true);
        assert_eq!(lut.gm_shift, Some(0));
        let row: Vec<u32> = (0..16).map(|gm| lut.lookup(9, gm)).collect();
        let mut want = vec![255, 223, 191, 159, 128];
        want.resize(16, 128);
        assert_eq!(row, want);
        assert_eq!(lut.lookup(9, 99), 128);
        assert_eq!(lut.row_max[9], 255);
    }

    fn shading() -> Shading {
        Shading {
            enabled: true,
            light_dir: [0.0, 0.0, 1.0],
            ambient: 0.25,
            diffuse: 0.5,
            specular: 0.5,
            shininess: 10.0,
        }
    }

    #[test]
    fn reciprocal_norms_round_to_nearest() {
        assert_eq!(rnorm(0), 0);
        assert_eq!(rnorm(1), 32768);
        assert_eq!(rnorm(4), 16384);
        // 32768 / sqrt 2 = 23170.48; / sqrt 3 = 18918.9; / sqrt 18 = 7723.49;
        // / 7 = 4681.14; / sqrt 675 = 1261.24.
        assert_eq!(rnorm(2), 23170);
        assert_eq!(rnorm(3), 18919);
        assert_eq!(rnorm(18), 7723);
        assert_eq!(rnorm(49), 4681);
        assert_eq!(rnorm(max_n2(5)), 1261);
        assert_eq!((max_n2(5), rnorm_words(5)), (675, 1024));
        assert_eq!((max_n2(6), rnorm_words(6)), (2883, 4096));
        assert_eq!((max_n2(8), rnorm_words(8)), (48387, 65536));
        for n2 in 1..=max_n2(MAX_NORMAL_BITS) {
            let exact = 32768.0 / (n2 as f64).sqrt();
            assert!((rnorm(n2) as f64 - exact).abs() <= 0.5, "{n2}");
        }
    }

    #[test]
    fn cosine_index_hand_values() {
        let z = [0, 0, -2048];
        // Facing the light: dot 14336, rnorm(49) = 4681, t = 67 106 816,
        // (t * 1023 + 2^25) >> 26 = 1023 (1023.47 clamped to the last).
        assert_eq!(Lighting::cos_index([0, 0, -7], z, 5), (1023, true));
        // 45 degrees: t = 6144 * 7723, the cosine 0.70706 -> index 723.83 -> 723.
        assert_eq!(Lighting::cos_index([-3, 0, -3], z, 5), (723, true));
        // Facing away and grazing: no light.
        assert_eq!(Lighting::cos_index([0, 0, 5], z, 5), (0, false));
        assert_eq!(Lighting::cos_index([4, 0, 0], z, 5), (0, false));
        assert_eq!(Lighting::cos_index([0, 0, 0], z, 5), (0, false));
        // Cube diagonal: t = 30720 * 1261, 0.57723 -> 591.02 -> 591.
        assert_eq!(Lighting::cos_index([-15, -15, -15], z, 5), (591, true));
        // A 6-bit normal: dot 21 * 2048 = 43 008, rnorm(841) = 1130
        // (32768 / 29 = 1129.93), t = 48 599 040, 0.72420 -> 741.35 -> 741
        // (the exact cosine 21/29 is 740.8 entries).
        assert_eq!(Lighting::cos_index([-20, 0, -21], z, 6), (741, true));
    }

    #[test]
    fn lighting_head_on() {
        // Light and viewer both along +z: h = +z. The normal is -g.
        let z = DVec3::Z;
        let l = Lighting::new(&shading(), glam::DMat3::IDENTITY, z, z, 8, 5);
        assert_eq!((l.light, l.half), ([0, 0, -2048], [0, 0, -2048]));
        assert_eq!(l.diffuse.len(), 1024);
        // Zero gradient: ambient only, 0.25 * 255 = 63.75.
        assert_eq!(l.reflect([0, 0, 0]), [64, 0]);
        // Facing the light: 0.75 -> 191.25; specular 0.5 -> 127.5 -> 128.
        assert_eq!(l.reflect([0, 0, -7]), [191, 128]);
        assert_eq!(l.reflect([0, 0, -1]), [191, 128]);
        // Facing away, and grazing (n.l = 0, so no specular): ambient only.
        assert_eq!(l.reflect([0, 0, 5]), [64, 0]);
        assert_eq!(l.reflect([4, 0, 0]), [64, 0]);
        assert_eq!(l.reflect([0, -9, 0]), [64, 0]);
        // 45 degrees, index 723: 0.25 + 0.5 * 723/1023 = 0.60337 -> 153.9;
        // specular 0.5 * (723/1023)^10 = 0.01552 -> 3.96.
        assert_eq!(l.reflect([-3, 0, -3]), [154, 4]);
        assert_eq!(l.reflect([0, 11, -11]), [154, 4]);
        // Cube diagonal, index 591: 0.25 + 0.5 * 0.57771 -> 137.4;
        // 0.5 * 0.57771^10 = 0.00207 -> 0.53.
        assert_eq!(l.reflect([-15, -15, -15]), [137, 1]);
        // Past the remembered width (every component beyond ±15): computed,
        // not looked up. |q|² = 768, rnorm 1182 (32768 / 27.713 = 1182.41),
        // t = 32768 * 1182, index 590.42 -> 590: 0.25 + 0.5 * 590/1023
        // -> 137.28; 0.5 * (590/1023)^10 -> 0.52.
        assert_eq!(l.reflect([-16, -16, -16]), [137, 1]);
        assert_eq!(l.reflect([16, 16, 16]), [64, 0]);
        // 12-bit words: 0.75 * 4095 = 3071.25, 0.5 * 4095 = 2047.5.
        let l12 = Lighting::new(&shading(), glam::DMat3::IDENTITY, z, z, 12, 5);
        assert_eq!(l12.reflect([0, 0, -2]), [3071, 2048]);
        assert_eq!(l12.reflect([0, 0, 0]), [1024, 0]);
    }

    #[test]
    fn remembered_reflectance_is_the_computed_one() {
        // Every normal of each remembered width, read twice (computed and
        // stored, then loaded), at 16-bit words (the widest packed), and
        // from a clone; a normal beyond the width is computed.
        let light = DVec3::new(0.3, -0.5, 0.8).normalize();
        let perm = glam::DMat3::from_cols(DVec3::Y, DVec3::Z, DVec3::X);
        for bits in 3..=MEMO_BITS {
            let l = Lighting::new(&shading(), perm, light, DVec3::Z, 16, bits);
            let lim = normal_limit(bits);
            let all = || {
                (-lim..=lim).flat_map(move |a| {
                    (-lim..=lim).flat_map(move |b| (-lim..=lim).map(move |c| [a, b, c]))
                })
            };
            for q in all() {
                assert_eq!(l.reflect(q), l.reflect_uncached(q), "{bits} bits, {q:?}");
            }
            let copy = l.clone();
            for q in all() {
                assert_eq!(l.reflect(q), l.reflect_uncached(q), "{bits} bits, {q:?}");
                assert_eq!(copy.reflect(q), l.reflect_uncached(q), "{bits} bits, {q:?}");
            }
            let beyond = [lim + 1, -lim - 3, 1];
            assert_eq!(l.reflect(beyond), l.reflect_uncached(beyond));
        }
        let wide = Lighting::new(&shading(), perm, light, DVec3::Z, 8, MEMO_BITS + 1);
        assert!(wide.memo.0.is_empty());
        assert_eq!(
            wide.reflect([-40, 3, -63]),
            wide.reflect_uncached([-40, 3, -63])
        );
    }

    #[test]
    fn lighting_side_light_and_axis_permutation() {
        // Light along +x, viewer along +z: h = (1, 0, 1) / sqrt 2, whose
        // register components are round(-0.70711 * 2048) = -1448.
        let id = glam::DMat3::IDENTITY;
        let l = Lighting::new(&shading(), id, DVec3::X, DVec3::Z, 8, 5);
        assert_eq!((l.light, l.half), ([-2048, 0, 0], [-1448, 0, -1448]));
        assert_eq!(l.reflect([-1, 0, 0]), [191, 4]);
        assert_eq!(l.reflect([0, 0, -1]), [64, 0]);
        assert_eq!(l.reflect([6, 0, 0]), [64, 0]);
        // Pipeline (x, y, z) is dataset (z, x, y): pipeline -z faces dataset +x.
        let perm = glam::DMat3::from_cols(DVec3::Y, DVec3::Z, DVec3::X);
        let l = Lighting::new(&shading(), perm, DVec3::X, DVec3::Z, 8, 5);
        assert_eq!((l.light, l.half), ([0, 0, -2048], [0, -1448, -1448]));
        assert_eq!(l.reflect([0, 0, -2]), [191, 4]);
        assert_eq!(l.reflect([-2, 0, 0]), [64, 0]);
        assert_eq!(l.reflect([0, -2, 0]), [64, 0]);
    }

    #[test]
    fn unlit_is_full_diffuse_no_specular() {
        assert_eq!(unlit(8), [255, 0]);
        assert_eq!(unlit(12), [4095, 0]);
        assert_eq!(unlit(4), [15, 0]);
    }

    #[test]
    fn lighting_is_phong_within_a_unit_of_the_last_place() {
        // Every quantized normal, a light off every axis: the diffuse term
        // within 1 of exact Phong at the normal (cosine rounded to 1/1023,
        // then to 8 bits), the specular (shininess 10) within 2.
        let (l, v) = (DVec3::new(0.3, -0.5, 0.8).normalize(), DVec3::Z);
        let lt = Lighting::new(&shading(), glam::DMat3::IDENTITY, l, v, 8, 5);
        let mut worst = [0f64; 2];
        for qz in -15..=15 {
            for qy in -15..=15 {
                for qx in -15..=15 {
                    let g = DVec3::new(qx as f64, qy as f64, qz as f64);
                    let exact = if g == DVec3::ZERO {
                        (0.25, 0.0)
                    } else {
                        phong(&shading(), -g.normalize(), l, v)
                    };
                    let got = lt.reflect([qx, qy, qz]);
                    for (k, e) in [exact.0, exact.1].into_iter().enumerate() {
                        worst[k] = worst[k].max((got[k] as f64 - e * 255.0).abs());
                    }
                }
            }
        }
        assert!(worst[0] <= 1.0 && worst[1] <= 2.0, "{worst:?}");
    }
}
