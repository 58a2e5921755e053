//! How Cube-3 feeds its samples to the kit's shader (`common::shader`; §4,
//! end, and §5, the ABC shading units): a view is the shader's base plane
//! (its samples have `sample_bits - voxel_bits` fractional bits, its
//! gradients `gradient_bits`), and a shaded sample is a leaf of the Ray
//! Projection Cone.
//!
//! A sample whose continuous position lies outside the volume's box is the
//! RPC's empty leaf (nothing to composite). One inside is shaded; outside the
//! inner box `[1, n - 2]` its gradient's neighbourhood leaves the volume (the
//! shader's `edge`: transparent when a gradient is needed, as Cube-4L's edge
//! rule and the reference's).

use super::plan::{View, Widths};
use super::rpc::Leaf;
use crate::common::shader::{Sample, ShadedPlane, Shader};
use glam::{DMat3, DVec3};
use scene::Scene;

impl ShadedPlane for View {
    fn spacing(&self) -> f64 {
        self.spacing
    }

    fn view_dir(&self) -> DVec3 {
        self.view_dir
    }

    fn gradient_to_dataset(&self) -> DMat3 {
        self.to_traversal().transpose()
    }

    fn sample_frac(scene: &Scene) -> u32 {
        Widths::of(scene).sample_frac()
    }

    fn gradient_bits(scene: &Scene) -> u32 {
        Widths::of(scene).gradient_bits
    }
}

/// Per sample integer part, whether the sample's leaf is the RPC's identity
/// wherever it lies (`Shader::is_zero`), built once a view: the ray's
/// segment skip asks it of every sample.
pub fn identity_table(shader: &Shader) -> Vec<bool> {
    (0..1u32 << shader.voxel_bits)
        .map(|i| shader.is_zero(i << shader.sample_frac))
        .collect()
}

/// The RPC leaf of sample `s`: `inside` the volume's box, `inner` within
/// the inner box; `gradient` is called only when needed.
#[inline(always)]
pub fn leaf(
    shader: &Shader,
    s: u32,
    inside: bool,
    inner: bool,
    gradient: impl FnOnce() -> [i32; 3],
) -> Leaf {
    if !inside {
        return Leaf {
            value: [0; 4],
            valid: false,
        };
    }
    let Sample { value, valid } = shader.sample(s, false, !inner, gradient);
    Leaf { value, valid }
}
