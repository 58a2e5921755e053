//! Synthesizable rust-hdl descriptions of the Cube-4L pipeline stages, one
//! stage per file (`cfb.rs`, `abc_gradient.rs`, `shader.rs`,
//! `compositor.rs`, ...), each matched bit for bit against the golden model
//! in `golden_model`. The stages arrive with the RTL work; this crate pins
//! the toolchain (rust-hdl 0.46 builds on this rustc) and the layout.

pub use rust_hdl;
