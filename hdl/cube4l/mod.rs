//! Cube-4L (Bitter and Kaufman): ray-slice-sweeping pipelines, one voxel
//! per pipeline per clock.
//!
//! The [`cfb::Cfb`] (skewed memory, address generator, control bits, with
//! each lane's [`cfb_lane::CfbLane`] and, for perspective views, its
//! [`divider`] of [`div_stage`]s and the [`counter_lead`]) feeds
//! `P` pipelines ([`pipe_lane::PipeLane`]), joined by nearest-neighbour
//! links in [`pipeline::Pipeline`]. A lane holds the input selection
//! ([`lane_feed`], with the [`abc_gradient`] unit), the shader
//! (`common::shader`), the compositing-buffer taps ([`tap_network`] of nine
//! [`buffer_tap`]s over the [`buffer_rows`] history), the 2x2 selection
//! ([`select2x2`]), the [`bilinear`] unit and the [`compositor`], with the
//! [`control_delay`] beside them. [`config`] holds what they are built
//! from, and [`units`] which of them a configuration builds, their
//! instance names and the stage files of the emitted design.

pub mod abc_gradient;
pub mod bilinear;
pub mod buffer_rows;
pub mod buffer_tap;
pub mod cfb;
pub mod cfb_lane;
pub mod cfb_stages;
pub mod compositor;
pub mod config;
pub mod control_delay;
pub mod counter_lead;
pub mod div_stage;
pub mod divider;
pub mod lane_feed;
pub mod pipe_lane;
pub mod pipeline;
pub mod select2x2;
pub mod tap_network;
pub mod units;

pub use config::PipelineConfig;
pub use pipeline::Pipeline;
