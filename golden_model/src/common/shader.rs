//! Shading and classification, the one golden shader of both architectures
//! (Cube-4L §3.3-3.4; Cube-3 §4, end, and §5, the ABC shading units): colour
//! LUT by the sample's value, the reflectance of the quantized gradient
//! (`lut::Lighting`: the cosines with the light and half vectors, each
//! indexing a table), opacity LUT by value and gradient magnitude, and
//! opacity weighting of the colour. The tables are the kit's (`lut`), filled
//! from the scene's transfer function and lighting.
//!
//! Its input is a sample word with `F` fractional bits (Cube-4L shades
//! voxels: `F = 0`; Cube-3 shades its tri-linear samples: `F = sample_bits -
//! voxel_bits`) and the sample's place: `invalid` (Cube-4L: the sight ray
//! is beyond 45 degrees) and `edge` (its gradient's neighbourhood leaves
//! the volume: Cube-4L's `Control::edge`, outside Cube-3's inner box).
//!
//! Fixed-point steps, in order, all unorm of `rgba_bits` (`M = 2^rgba_bits - 1`):
//! 1. `index = s >> F`: the LUTs take the sample's integer part (truncation).
//! 2. MIP and MinIP: `[(s + 2^(F-1)) >> F, 0, 0, 0]` (the sample rounded to
//!    voxel bits; `s` itself at `F = 0`), valid unless `invalid`. They need no
//!    gradient, colour or lighting: those tables are left out.
//! 3. Composite, first-opaque and X-ray: `invalid` samples, `edge` samples
//!    when a gradient is needed, and samples whose opacity row is zero are
//!    transparent, `[0, 0, 0, 0]`.
//! 4. X-ray: `[opacity[index][0], 0, 0, 0]`.
//! 5. `gm = isqrt(gx² + gy² + gz²) >> F` (the gradient word is in sample
//!    units); `alpha = opacity[index][gm >> gm_shift]`; first-opaque:
//!    `alpha = alpha >= threshold ? M : 0`.
//! 6. `c = colour[index]`, `[d, s] = lighting.reflect(quantize_normal(g,
//!    normal_bits))`, `lut::shade_weight`: `shaded = sat(mul(c, d) + s)` per
//!    RGB channel (`sat`: clamp to M), `[mul(shaded, alpha)..., alpha]`.

use super::gradient::{magnitude, quantize_normal};
use crate::fixed::{max_of, quantize_unorm};
use crate::lut::{shade_weight, unlit, ColourLut, Lighting, OpacityLut};
use glam::{DMat3, DVec3};
use scene::transfer::TransferFn;
use scene::{Camera, Mode, Scene};

/// The base plane a [`Shader`] is built for (a Cube-4L sweep, a Cube-3
/// view): its geometry, and the words its samples and gradients come in.
pub trait ShadedPlane {
    /// Sample spacing along the plane's mean ray, in voxel lengths (the
    /// composite opacity's correction).
    fn spacing(&self) -> f64;
    /// Mean viewing direction (eye to volume) in dataset space.
    fn view_dir(&self) -> DVec3;
    /// The matrix taking the gradients' space to dataset space.
    fn gradient_to_dataset(&self) -> DMat3;
    /// Fractional bits of the samples on `scene` (`F`).
    fn sample_frac(scene: &Scene) -> u32;
    /// Signed width of the gradient components on `scene`.
    fn gradient_bits(scene: &Scene) -> u32;
}

/// The classification and shading tables of one base plane, and which units
/// the scene needs.
#[derive(Debug, Clone)]
pub struct Shader {
    pub mode: Mode,
    pub rgba_bits: u32,
    pub voxel_bits: u32,
    /// Fractional bits of a sample word (`F`).
    pub sample_frac: u32,
    /// Signed width of the gradient components the shader is fed.
    pub gradient_bits: u32,
    pub colour: Option<ColourLut>,
    pub opacity: Option<OpacityLut>,
    /// `None` when shading is off: the lighting unit is left out.
    pub lighting: Option<Lighting>,
    /// Gradients are computed only when shading or gradient-opacity needs them.
    pub needs_gradient: bool,
    /// First-opaque threshold, unorm.
    pub threshold: u32,
}

/// A classified and shaded sample, ready for the compositor.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Sample {
    /// Composite and first-opaque: opacity-weighted `[r, g, b, a]`.
    /// MIP/MinIP: `[value, 0, 0, 0]`. X-ray: `[alpha, 0, 0, 0]`.
    pub value: [u32; 4],
    /// MIP/MinIP: whether the sample takes part.
    pub valid: bool,
}

impl Shader {
    pub fn new<P: ShadedPlane>(scene: &Scene, camera: &Camera, plane: &P) -> Shader {
        let hw = scene.hardware;
        let (vb, rb) = (hw.voxel_bits, hw.rgba_bits);
        let tf = TransferFn::new(scene);
        let mode = scene.mode;
        let shading = scene.lit();
        let grad_opacity = mode.uses_colour() && tf.has_gradient_opacity();
        let spacing = if mode == Mode::Composite {
            plane.spacing()
        } else {
            1.0
        };
        let opacity = matches!(mode, Mode::Composite | Mode::FirstOpaque | Mode::Xray)
            .then(|| OpacityLut::new(&tf, vb, rb, spacing, grad_opacity));
        let colour = mode.uses_colour().then(|| ColourLut::new(&tf, vb, rb));
        let lighting = shading.then(|| {
            let light = camera
                .camera_to_dataset(DVec3::from_array(scene.shading.light_dir))
                .normalize();
            Lighting::new(
                &scene.shading,
                plane.gradient_to_dataset(),
                light,
                -plane.view_dir(),
                rb,
                hw.normal_bits,
            )
        });
        Shader {
            mode,
            rgba_bits: rb,
            voxel_bits: vb,
            sample_frac: P::sample_frac(scene),
            gradient_bits: P::gradient_bits(scene),
            colour,
            opacity,
            lighting,
            needs_gradient: shading || grad_opacity,
            threshold: quantize_unorm(scene.transfer.opaque_threshold, rb),
        }
    }

    /// The tables and registers the hardware's shaders take from the host:
    /// the value is the sample's integer part, the gradient's magnitude
    /// shifted by the sample's fractional bits more.
    pub fn tables(&self) -> crate::host::ShaderTables<'_> {
        crate::host::ShaderTables {
            mode: self.mode,
            rgba_bits: self.rgba_bits,
            colour: self.colour.as_ref(),
            opacity: self.opacity.as_ref(),
            lighting: self.lighting.as_ref(),
            threshold: self.threshold,
            magnitude_shift: self.sample_frac,
        }
    }

    /// The LUTs' index of sample `s`: its integer part.
    fn index(&self, s: u32) -> u32 {
        s >> self.sample_frac
    }

    /// Whether sample `s` shades to a zero sample wherever it lies:
    /// composite, first-opaque and X-ray, its opacity row is zero. Never for
    /// MIP and MinIP, whose samples are their values.
    pub fn is_zero(&self, s: u32) -> bool {
        match (&self.opacity, self.mode) {
            (_, Mode::Mip | Mode::Minip) => false,
            (Some(o), _) => o.row_max[o.row(self.index(s))] == 0,
            (None, _) => unreachable!("composite, first-opaque and X-ray have an opacity LUT"),
        }
    }

    /// Whether sample `s` is certainly transparent before any gradient is
    /// computed (step 3): the empty-space skip of the software paths.
    pub fn transparent(&self, s: u32, invalid: bool, edge: bool) -> bool {
        match self.mode {
            Mode::Mip | Mode::Minip => false,
            _ => invalid || (self.needs_gradient && edge) || self.is_zero(s),
        }
    }

    /// Classify and shade sample `s` at its place (`invalid`, `edge`);
    /// `gradient` is called only when the scene needs one and the sample is
    /// not transparent. Inlined into the callers' loops, which the compiler
    /// stops doing on its own once the lighting's memo is in the shader
    /// (Cube-3: 3.7 % more instructions a frame on the engine).
    #[inline(always)]
    pub fn sample(
        &self,
        s: u32,
        invalid: bool,
        edge: bool,
        gradient: impl FnOnce() -> [i32; 3],
    ) -> Sample {
        let f = self.sample_frac;
        let clear = Sample {
            value: [0; 4],
            valid: true,
        };
        match self.mode {
            Mode::Mip | Mode::Minip => {
                let r = if f == 0 { s } else { (s + (1 << (f - 1))) >> f };
                Sample {
                    value: [r, 0, 0, 0],
                    valid: !invalid,
                }
            }
            _ if self.transparent(s, invalid, edge) => clear,
            Mode::Xray => Sample {
                value: [
                    self.opacity.as_ref().unwrap().lookup(self.index(s), 0),
                    0,
                    0,
                    0,
                ],
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
                    magnitude(g) >> f
                } else {
                    0
                };
                let mut alpha = op.lookup(self.index(s), gm);
                if self.mode == Mode::FirstOpaque {
                    alpha = if alpha >= self.threshold {
                        max_of(self.rgba_bits)
                    } else {
                        0
                    };
                }
                if alpha == 0 {
                    return clear;
                }
                let rgb = self.colour.as_ref().unwrap().lookup(self.index(s));
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
