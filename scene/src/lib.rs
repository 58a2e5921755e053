//! Everything a renderer of the kit reads, and no rendering: the JSON scene
//! ([`spec`]), volumes raw and built-in with crop and window ([`volume`]), the
//! camera ([`camera`]), the transfer function ([`transfer`]), the lighting
//! formula ([`lighting`]) and the image every renderer produces ([`image`]).
//!
//! The golden models and the float reference both depend on this crate and
//! on nothing of each other, so the reference stays an independent judge.
//! The formulas here are checked against hand-computed values in their own
//! tests.

pub mod camera;
pub mod error;
pub mod image;
pub mod lighting;
pub mod spec;
pub mod transfer;
pub mod volume;

pub use camera::{Camera, Projection, ViewSpec};
pub use error::{CubeError, Result};
pub use image::Image;
pub use spec::{
    Cube3Spec, EmptySpace, Hardware, Mode, QuantizedSpec, Scene, SceneSpec, Shading, Transfer,
    Traversal, MAX_DIM, MAX_IMAGE, MAX_VOXELS,
};
pub use volume::{Crop, RawType, Volume, VolumeSpec, BUILTINS};
