//! Shading and classification of Cube-3's samples (§4, end; §5, the ABC
//! shading units): a colour LUT, shading by the quantized gradient's
//! lighting (`lut::Lighting`), and a 2-D opacity LUT indexed by sample value and
//! gradient magnitude. The tables are the kit's (`lut`), filled from the
//! scene's transfer function and lighting.
//!
//! Fixed-point steps (`F = sample_bits - voxel_bits`, `M = 2^rgba_bits - 1`):
//! 1. `inside`: the sample's continuous position lies in the volume's box;
//!    otherwise it is the RPC's identity (nothing to composite).
//! 2. `index = s >> F`: the LUTs take the sample's integer part (truncation).
//! 3. Composite and first-opaque with gradients: samples outside the inner
//!    box `[1, n - 2]` are transparent (their neighbourhood leaves the
//!    volume; Cube-4L's edge rule, and the reference's).
//! 4. `gm = isqrt(gx² + gy² + gz²) >> F` (the gradient word is in sample
//!    units); `alpha = opacity[index][gm]`, first-opaque: `alpha >= threshold
//!    ? M : 0`.
//! 5. `[d, s] = lighting.reflect(quantize_normal(g, normal_bits))`, `c = colour[index]`,
//!    `lut::shade_weight`: `[mul(sat(mul(c, d) + s), alpha)..., alpha]`.
//! 6. MIP and MinIP: `[(s + 2^(F-1)) >> F, 0, 0, 0]`, the sample rounded to
//!    voxel bits; X-ray: `[opacity[index][0], 0, 0, 0]`. They need no
//!    gradient, colour or lighting: those tables are left out.

use super::plan::{View, Widths};
use super::rpc::Leaf;
use crate::cube4l::gradient::{magnitude, quantize_normal};
use crate::fixed::{max_of, quantize_unorm};
use crate::lut::{shade_weight, unlit, ColourLut, Lighting, OpacityLut};
use scene::transfer::TransferFn;
use scene::{Camera, Mode, Scene};

/// The tables of one base-plane projection, and the units the scene needs.
#[derive(Debug, Clone)]
pub struct Shader {
    pub mode: Mode,
    pub widths: Widths,
    pub colour: Option<ColourLut>,
    pub opacity: Option<OpacityLut>,
    pub lighting: Option<Lighting>,
    pub needs_gradient: bool,
    pub threshold: u32,
    /// [`Shader::is_identity`] by the sample's integer part, built once
    /// (empty for MIP and MinIP, which have no identity sample).
    identity: Vec<bool>,
}

impl Shader {
    pub fn new(scene: &Scene, camera: &Camera, view: &View) -> Shader {
        let widths = Widths::of(scene);
        let tf = TransferFn::new(scene);
        let mode = scene.mode;
        let shading = scene.lit();
        let grad_opacity = mode.uses_colour() && tf.has_gradient_opacity();
        let spacing = if mode == Mode::Composite {
            view.spacing
        } else {
            1.0
        };
        let (vb, rb) = (widths.voxel_bits, widths.rgba_bits);
        let opacity = matches!(mode, Mode::Composite | Mode::FirstOpaque | Mode::Xray)
            .then(|| OpacityLut::new(&tf, vb, rb, spacing, grad_opacity));
        let colour = mode.uses_colour().then(|| ColourLut::new(&tf, vb, rb));
        let lighting = shading.then(|| {
            let to_dataset = view.to_traversal().transpose();
            let light = camera
                .camera_to_dataset(glam::DVec3::from_array(scene.shading.light_dir))
                .normalize();
            Lighting::new(
                &scene.shading,
                to_dataset,
                light,
                -view.view_dir,
                rb,
                scene.hardware.normal_bits,
            )
        });
        // A zero opacity row: the leaf is zero wherever the sample lies.
        let identity = match (&opacity, mode) {
            (_, Mode::Mip | Mode::Minip) => Vec::new(),
            (Some(o), _) => (0..1u32 << vb).map(|i| o.row_max[o.row(i)] == 0).collect(),
            (None, _) => unreachable!("composite, first-opaque and X-ray have an opacity LUT"),
        };
        Shader {
            mode,
            widths,
            colour,
            opacity,
            lighting,
            needs_gradient: shading || grad_opacity,
            threshold: quantize_unorm(scene.transfer.opaque_threshold, rb),
            identity,
        }
    }

    /// The tables and registers the hardware's shaders take from the host:
    /// the value is the sample's integer part, the gradient's magnitude
    /// shifted by the sample's fractional bits more.
    pub fn tables(&self) -> crate::host::ShaderTables<'_> {
        crate::host::ShaderTables {
            mode: self.mode,
            rgba_bits: self.widths.rgba_bits,
            colour: self.colour.as_ref(),
            opacity: self.opacity.as_ref(),
            lighting: self.lighting.as_ref(),
            threshold: self.threshold,
            magnitude_shift: self.widths.sample_frac(),
        }
    }

    fn index(&self, s: u32) -> u32 {
        s >> self.widths.sample_frac()
    }

    /// Whether sample `s` gives a zero leaf wherever it lies (composite,
    /// first-opaque and X-ray: its opacity row is zero, and outside the
    /// volume the leaf is zero too). MIP and MinIP take every sample inside.
    pub fn is_identity(&self, s: u32) -> bool {
        !self.identity.is_empty() && self.identity[self.index(s) as usize]
    }

    /// Certainly transparent before any gradient: the software's empty-space
    /// skip (it cannot change a bit).
    pub fn transparent(&self, s: u32, inner: bool) -> bool {
        match self.mode {
            Mode::Mip | Mode::Minip => false,
            _ => (self.needs_gradient && !inner) || self.is_identity(s),
        }
    }

    /// The RPC leaf of sample `s`; `gradient` is called only when needed.
    /// Inlined into the ray's loop, which the compiler stops doing on its
    /// own once the lighting's memo is in the shader (3.7 % more
    /// instructions a frame on the engine).
    #[inline(always)]
    pub fn leaf(
        &self,
        s: u32,
        inside: bool,
        inner: bool,
        gradient: impl FnOnce() -> [i32; 3],
    ) -> Leaf {
        let f = self.widths.sample_frac();
        let empty = Leaf {
            value: [0; 4],
            valid: false,
        };
        if !inside {
            return empty;
        }
        let clear = Leaf {
            value: [0; 4],
            valid: true,
        };
        match self.mode {
            Mode::Mip | Mode::Minip => {
                let r = if f == 0 { s } else { (s + (1 << (f - 1))) >> f };
                Leaf {
                    value: [r, 0, 0, 0],
                    valid: true,
                }
            }
            _ if self.transparent(s, inner) => clear,
            Mode::Xray => Leaf {
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
                        max_of(self.widths.rgba_bits)
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
                    None => unlit(self.widths.rgba_bits),
                };
                Leaf {
                    value: shade_weight(rgb, ds, alpha, self.widths.rgba_bits),
                    valid: true,
                }
            }
        }
    }
}
