//! Cube-3 (Pfister, Wessels and Kaufman): ray-parallel casting with
//! template rays, one sample per unit per clock.
//!
//! The [`system::Cube3System`] joins the [`cfb::BeamFetch`] (the CFB's
//! memory modules, the Fast Bus and the three 2-D skewed buffers, fed by
//! [`groups`] and [`schedule`]) to the [`pipeline::Cube3`] pipeline: the
//! [`ray_control`] (with its [`templates`] and [`increments`]), the
//! TRILIN units ([`trilin_lanes`] of [`trilin`]), the ABC gradient units
//! ([`abc_gradient`], with [`plane_taps`] and the [`abc_estimator`], and
//! for the 26- and 10-neighbourhoods [`abc_sums26`] and [`abc_basis10`],
//! their products [`signed_product`]s), the
//! shaders (`common::shader`) and the Ray Projection Cone
//! ([`compositor`], a tree of [`rpc_node`]s). [`config`] holds what they
//! are built from, and [`units`] which of them a configuration builds,
//! their instance names and the stage files of the emitted design.

pub mod abc_basis10;
pub mod abc_estimator;
pub mod abc_gradient;
pub mod abc_sums26;
pub mod cfb;
pub mod compositor;
pub mod config;
pub mod groups;
pub mod increments;
pub mod pipeline;
pub mod plane_taps;
pub mod ray_control;
pub mod rpc_node;
pub mod schedule;
pub mod signed_product;
pub mod system;
pub mod templates;
pub mod trilin;
pub mod trilin_lanes;
pub mod units;

pub use config::{AbcConfig, BeamFetchConfig, Cube3Config, Cube3Sizes, Cube3SystemConfig, Group};
pub use pipeline::Cube3;
pub use system::Cube3System;
