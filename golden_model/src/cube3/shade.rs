//! Shading and classification of Cube-3's samples (§4, end; §5, the ABC
//! shading units): a colour LUT, shading by a reflectance map indexed by the
//! quantized gradient, and a 2-D opacity LUT indexed by sample value and
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
//! 5. `[d, s] = reflectance[quantize_normal(g)]`, `c = colour[index]`,
//!    `lut::shade_weight`: `[mul(sat(mul(c, d) + s), alpha)..., alpha]`.
//! 6. MIP and MinIP: `[(s + 2^(F-1)) >> F, 0, 0, 0]`, the sample rounded to
//!    voxel bits; X-ray: `[opacity[index][0], 0, 0, 0]`. They need no
//!    gradient, colour or reflectance: those tables are left out.

use super::plan::{View, Widths};
use super::rpc::Leaf;
use crate::cube4l::gradient::{magnitude, quantize_normal};
use crate::fixed::{max_of, quantize_unorm};
use crate::lut::{shade_weight, unlit, ColourLut, OpacityLut, ReflectanceMap};
use scene::transfer::TransferFn;
use scene::{Camera, Mode, Scene};

/// The tables of one base-plane projection, and the units the scene needs.
#[derive(Debug, Clone)]
pub struct Shader {
    pub mode: Mode,
    pub widths: Widths,
    pub colour: Option<ColourLut>,
    pub opacity: Option<OpacityLut>,
    pub reflectance: Option<ReflectanceMap>,
    pub needs_gradient: bool,
    pub threshold: u32,
}

impl Shader {
    pub fn new(scene: &Scene, camera: &Camera, view: &View) -> Shader {
        let widths = Widths::of(scene);
        let tf = TransferFn::new(scene);
        let mode = scene.mode;
        let shading = mode.uses_colour() && scene.shading.enabled;
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
        let reflectance = shading.then(|| {
            let to_dataset = view.to_traversal().transpose();
            let light = camera
                .camera_to_dataset(glam::DVec3::from_array(scene.shading.light_dir))
                .normalize();
            ReflectanceMap::new(
                &scene.shading,
                |g| to_dataset * g,
                light,
                -view.view_dir,
                rb,
            )
        });
        Shader {
            mode,
            widths,
            colour,
            opacity,
            reflectance,
            needs_gradient: shading || grad_opacity,
            threshold: quantize_unorm(scene.transfer.opaque_threshold, rb),
        }
    }

    fn index(&self, s: u32) -> u32 {
        s >> self.widths.sample_frac()
    }

    /// Certainly transparent before any gradient: the software's empty-space
    /// skip (it cannot change a bit).
    pub fn transparent(&self, s: u32, inner: bool) -> bool {
        match (&self.opacity, self.mode) {
            (_, Mode::Mip | Mode::Minip) => false,
            (Some(o), _) => (self.needs_gradient && !inner) || o.row_max[o.row(self.index(s))] == 0,
            (None, _) => unreachable!("composite, first-opaque and X-ray have an opacity LUT"),
        }
    }

    /// The RPC leaf of sample `s`; `gradient` is called only when needed.
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
                let ds = match &self.reflectance {
                    Some(r) => {
                        let [qx, qy, qz] = quantize_normal(g);
                        r.table[ReflectanceMap::index(qx, qy, qz)]
                    }
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
