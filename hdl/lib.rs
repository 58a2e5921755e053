//! Synthesizable rust-hdl descriptions of the Cube-4L and Cube-3 stages,
//! one stage per file, each matched bit for bit against the golden model in
//! `golden_model` by the testbenches.
//!
//! Cube-4L: [`cfb`] (skewed memory, address generator, control bits) with
//! the perspective [`divider`], [`abc_gradient`], [`shader`], the bilinear
//! unit ([`bilinear`]), [`compositor`], and [`pipeline`], which joins p
//! pipelines by nearest-neighbour links. A pipeline's lane adds
//! [`lane_feed`] (input selection), [`tap_network`] (the compositing-buffer
//! taps, each a [`buffer_tap`], over [`buffer_rows`]), [`select2x2`] and
//! [`control_delay`].
//!
//! Cube-3: [`beam_fetch`] (CFB, Fast Bus, 2-DSBs), [`trilin_lanes`] and
//! [`trilin`], [`ray_control`], the ABC gradient lanes ([`abc_unit`],
//! [`abc_estimator`], [`plane_taps`]), the Ray Projection Cone ([`rpc`],
//! [`rpc_node`]), [`cube3`] (pipeline, leaf stage, and the ABC units'
//! shaders: Cube-4L's [`shader`]) and [`cube3_system`] (memory to
//! base-plane pixels).
//!
//! Shared: [`lerp`], [`over`], [`delay_line`], [`ram`] (block RAM as deep as
//! the scene needs), [`unorm`] (the exact unorm multiplier). Nothing here
//! spawns a process or touches a file: the `cosim` crate exports, simulates
//! and synthesizes these stages.

pub mod abc_estimator;
pub mod abc_gradient;
pub mod abc_unit;
pub mod beam_fetch;
pub mod bilinear;
pub mod buffer_rows;
pub mod buffer_tap;
pub mod cfb;
pub mod compositor;
pub mod control_delay;
pub mod cube3;
pub mod cube3_system;
pub mod delay_line;
pub mod divider;
pub mod lane_feed;
pub mod lerp;
pub mod over;
pub mod pipeline;
pub mod plane_taps;
pub mod ram;
pub mod ray_control;
pub mod rpc;
pub mod rpc_node;
pub mod select2x2;
pub mod shader;
pub mod tap_network;
pub mod trilin;
pub mod trilin_lanes;
pub mod unorm;
