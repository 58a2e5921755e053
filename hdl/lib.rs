//! Synthesizable rust-hdl descriptions of the Cube-4L pipeline stages, one
//! stage per file, each matched bit for bit against the golden model in
//! `golden_model` by the testbenches: [`cfb`] (skewed memory, address
//! generator, control bits) with the perspective [`divider`],
//! [`abc_gradient`], [`shader`], the bilinear unit ([`bilinear`]),
//! [`compositor`], and [`pipeline`], which joins p pipelines by
//! nearest-neighbour links, with [`ram`] (block RAM as deep as the scene
//! needs) and [`unorm`] (the exact unorm multiplier). Nothing here spawns a
//! process or touches a file: the `cosim` crate exports, simulates and
//! synthesizes these stages.

pub mod abc_gradient;
pub mod bilinear;
pub mod cfb;
pub mod compositor;
pub mod divider;
pub mod pipeline;
pub mod ram;
pub mod shader;
pub mod unorm;
