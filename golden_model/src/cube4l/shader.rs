//! Shading and classification (Cube-4L §3.3-3.4): colour LUT by intensity,
//! the reflectance of the quantized gradient (`lut::Lighting`: the cosines
//! with the light and half vectors, each indexing a table), opacity LUT by
//! intensity and gradient magnitude, and opacity weighting of the colour.
//!
//! Fixed-point steps, in order, all unorm of `rgba_bits` (M = 2^rgba_bits - 1):
//! 1. `alpha = opacity_lut[v >> shift][gm >> gm_shift]` (0 on invalid voxels);
//!    first-opaque: `alpha = alpha >= threshold ? M : 0`.
//! 2. `c = colour_lut[v >> shift]`, `[d, s] = lighting.reflect(quantize_normal(g, normal_bits))`.
//! 3. `shaded = sat(mul(c, d) + s)` per RGB channel (`sat`: clamp to M).
//! 4. `weighted = mul(shaded, alpha)`, emitted as `[r, g, b, alpha]`.

use super::gradient::{magnitude, quantize_normal};
use super::plan::{Control, Sweep};
use crate::fixed::{max_of, quantize_unorm};
use crate::lut::{shade_weight, unlit, ColourLut, Lighting, OpacityLut};
use scene::transfer::TransferFn;
use scene::{Camera, Mode, Scene};

/// The classification and shading tables of one sweep, and which units the
/// scene needs.
#[derive(Debug, Clone)]
pub struct Shader {
    pub mode: Mode,
    pub rgba_bits: u32,
    pub voxel_bits: u32,
    pub colour: Option<ColourLut>,
    pub opacity: Option<OpacityLut>,
    /// `None` when shading is off: the lighting unit is left out.
    pub lighting: Option<Lighting>,
    /// Gradients are computed only when shading or gradient-opacity needs them.
    pub needs_gradient: bool,
    /// First-opaque threshold, unorm.
    pub threshold: u32,
}

/// A classified and shaded voxel, ready for the compositor.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Sample {
    /// Composite and first-opaque: opacity-weighted `[r, g, b, a]`.
    /// MIP/MinIP: `[intensity, 0, 0, 0]`. X-ray: `[alpha, 0, 0, 0]`.
    pub value: [u32; 4],
    /// MIP/MinIP: whether the voxel takes part.
    pub valid: bool,
}

impl Shader {
    pub fn new(scene: &Scene, camera: &Camera, sweep: &Sweep) -> Shader {
        let hw = scene.hardware;
        let tf = TransferFn::new(scene);
        let mode = scene.mode;
        let shading = scene.lit();
        let grad_opacity = mode.uses_colour() && tf.has_gradient_opacity();
        let spacing = if mode == Mode::Composite {
            sweep.spacing
        } else {
            1.0
        };
        let opacity = matches!(mode, Mode::Composite | Mode::FirstOpaque | Mode::Xray)
            .then(|| OpacityLut::new(&tf, hw.voxel_bits, hw.rgba_bits, spacing, grad_opacity));
        let colour = mode
            .uses_colour()
            .then(|| ColourLut::new(&tf, hw.voxel_bits, hw.rgba_bits));
        let lighting = shading.then(|| {
            let to_dataset = sweep.to_dataset();
            let light = camera
                .camera_to_dataset(glam::DVec3::from_array(scene.shading.light_dir))
                .normalize();
            Lighting::new(
                &scene.shading,
                to_dataset,
                light,
                -sweep.view_dir,
                hw.rgba_bits,
                hw.normal_bits,
            )
        });
        Shader {
            mode,
            rgba_bits: hw.rgba_bits,
            voxel_bits: hw.voxel_bits,
            colour,
            opacity,
            lighting,
            needs_gradient: shading || grad_opacity,
            threshold: quantize_unorm(scene.transfer.opaque_threshold, hw.rgba_bits),
        }
    }

    /// The tables and registers the hardware's shader takes from the host.
    pub fn tables(&self) -> crate::host::ShaderTables<'_> {
        crate::host::ShaderTables {
            mode: self.mode,
            rgba_bits: self.rgba_bits,
            colour: self.colour.as_ref(),
            opacity: self.opacity.as_ref(),
            lighting: self.lighting.as_ref(),
            threshold: self.threshold,
            magnitude_shift: 0,
        }
    }

    /// Whether the voxel is certainly transparent before any gradient is
    /// computed: the empty-space skip of the software path.
    pub fn transparent(&self, v: u32, c: &Control) -> bool {
        match self.mode {
            Mode::Mip | Mode::Minip => false,
            _ => c.invalid || (self.needs_gradient && c.edge) || self.is_identity(v),
        }
    }

    /// Whether compositing voxel `v` leaves every cell as it is, whatever
    /// its control bits: composite, first-opaque and X-ray, its opacity row
    /// is zero (a zero sample: `acc + mul(M - a, 0) = acc` front to back,
    /// `0 + mul(M, acc) = acc` back to front, `acc + 0` in X-ray); MIP, it is
    /// 0 (`max(acc, 0)`); MinIP, it is the largest voxel (`min(acc, max)`).
    pub fn is_identity(&self, v: u32) -> bool {
        match (&self.opacity, self.mode) {
            (_, Mode::Mip) => v == 0,
            (_, Mode::Minip) => v == max_of(self.voxel_bits),
            (Some(o), _) => o.row_max[o.row(v)] == 0,
            (None, _) => unreachable!("composite, first-opaque and X-ray have an opacity LUT"),
        }
    }

    /// Classify and shade voxel `v` with control `c`; `gradient` is called only
    /// when the scene needs one and the voxel is not transparent.
    pub fn sample(&self, v: u32, c: &Control, gradient: impl FnOnce() -> [i32; 3]) -> Sample {
        let m = max_of(self.rgba_bits);
        match self.mode {
            Mode::Mip | Mode::Minip => Sample {
                value: [v, 0, 0, 0],
                valid: !c.invalid,
            },
            _ if self.transparent(v, c) => Sample {
                value: [0; 4],
                valid: true,
            },
            Mode::Xray => Sample {
                value: [self.opacity.as_ref().unwrap().lookup(v, 0), 0, 0, 0],
                valid: true,
            },
            Mode::Composite | Mode::FirstOpaque => {
                let g = if self.needs_gradient {
                    gradient()
                } else {
                    [0; 3]
                };
                let op = self.opacity.as_ref().unwrap();
                let gm = if op.gm_shift.is_some() {
                    magnitude(g)
                } else {
                    0
                };
                let mut alpha = op.lookup(v, gm);
                if self.mode == Mode::FirstOpaque {
                    alpha = if alpha >= self.threshold { m } else { 0 };
                }
                if alpha == 0 {
                    return Sample {
                        value: [0; 4],
                        valid: true,
                    };
                }
                let rgb = self.colour.as_ref().unwrap().lookup(v);
                let ds = match &self.lighting {
                    Some(l) => l.reflect(quantize_normal(g, l.normal_bits)),
                    None => unlit(self.rgba_bits),
                };
                Sample {
                    value: shade_weight(rgb, ds, alpha, self.rgba_bits),
                    valid: true,
                }
            }
        }
    }
}
