//! Bit-accurate fixed-point golden model of the Cube-4L ray-slice-sweep
//! pipeline (Bitter & Kaufman), stage by stage, plus the scene, volume and
//! transfer-function definitions the whole kit shares.
//!
//! Stages, in pipeline order: [`cfb`] (skewed memory, voxel stream, control
//! bits), [`plan`] (view planning, dx/dy), [`gradient`] (ABC central
//! differences), [`shader`] (classification and shading LUTs),
//! [`compositor`] (bilinear unit and compositing), [`cube4l`] (the sweep),
//! [`warp`] (base plane to final image). [`fixed`] names every rounding,
//! truncation and saturation.

pub mod cfb;
pub mod compositor;
pub mod cube4l;
pub mod error;
pub mod fixed;
pub mod gradient;
pub mod plan;
pub mod scene;
pub mod shader;
pub mod transfer;
pub mod volume;
pub mod warp;

pub use error::{CubeError, Result};
