//! The bit-accurate fixed-point golden models of the kit: the spec the RTL
//! must match bit for bit. One folder per architecture:
//!
//! - [`cube3`]: the Cube-3 template-ray caster (Pfister, Wessels & Kaufman):
//!   planning and templates, PRP fetch into 2-D buffers, sheared tri-linear
//!   interpolation, ABC gradients (6, 10, 12, 26) and the Ray Projection Cone.
//! - [`cube4l`]: the Cube-4L ray-slice-sweep pipeline (Bitter & Kaufman),
//!   stage by stage: planning, CFB stream, ABC gradient, shader, compositor,
//!   base plane.
//! - [`quantized`]: the quantized-voxel software path (Mora, Jessel &
//!   Caubet): voxel projection by quantized positions and quantized
//!   splatting, in floating point, with no hardware twin.
//!
//! What the architectures share: [`common`] (the stages both use: planning
//! helpers, the gradient helpers, the one shader, the compositing unit and
//! the warp's shared parts), [`fixed`] (every rounding, truncation and
//! saturation, named), [`lut`] (the classification and shading LUTs filled
//! from the scene's transfer function and lighting), [`host`] (the words
//! the host writes into the hardware's registers and tables between
//! frames) and [`regmap`] (those words' fields by name, which the encoders
//! pack through and `docs/registers.md` is generated from). Scenes, volumes, the camera and the float formulas come from the
//! `scene` crate.

pub mod common;
pub mod cube3;
pub mod cube4l;
pub mod fixed;
pub mod host;
pub mod lut;
pub mod quantized;
pub mod regmap;
