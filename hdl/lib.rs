//! Synthesizable rust-hdl descriptions of the Cube-4L and Cube-3 stages,
//! one widget per file, each matched bit for bit against the golden model
//! in `golden_model` by the testbenches.
//!
//! - [`cube4l`]: the ray-slice-sweeping pipelines of Cube-4L (Bitter and
//!   Kaufman): CFB, ABC gradient, shader, compositing-buffer taps, bilinear
//!   unit and compositor, `P` pipelines joined by nearest-neighbour links.
//! - [`cube3`]: the ray-parallel Cube-3 (Pfister, Wessels and Kaufman): CFB
//!   and beam fetch into the 2-D skewed buffers, ray control, TRILIN, ABC
//!   gradient units, shaders and the Ray Projection Cone.
//! - [`common`]: what both architectures build from: linear interpolation,
//!   the over operator, the exact unorm multiplier, delay lines, block RAM
//!   as deep as the scene needs, and the shader.
//!
//! Each architecture keeps its configuration and the constants its stages
//! share in its own `config.rs`, so no stage imports the block that holds
//! it. Nothing here spawns a process or touches a file: the `cosim` crate
//! exports, simulates and synthesizes these stages.

pub mod common;
pub mod cube3;
pub mod cube4l;
