//! Everything that takes the rust-hdl stages (`hdl`) elsewhere, and checks
//! them there against the golden model, written once for every
//! architecture ([`arch::Arch`], implemented by [`cube4l`] and [`cube3`],
//! chosen by name in [`archs`]):
//!
//! - [`verilog`]: rust-hdl's Verilog made width-clean, pruned of the units
//!   a scene does not need, split into one file per stage with lint
//!   waivers; [`export`] writes each part of a frame (a Cube-4L sweep, a
//!   Cube-3 base plane) so, with a manifest;
//! - [`sim`]: a whole frame on one of three [`Engine`]s, checked pixel by
//!   pixel against the golden model; [`harness`] holds the engines'
//!   harnesses, one for emitted Verilog (a stage or a frame) under Icarus
//!   or Verilator, with cached Verilator builds; [`gtkw`] writes save
//!   files for GTKWave;
//! - [`vcd_diff`]: two traces compared cycle by cycle;
//! - [`synth`]: yosys synthesis and nextpnr place and route;
//! - [`tool`]: running an external tool, with a message naming the set-up
//!   command when it is missing.

pub mod arch;
pub mod archs;
pub mod cube3;
pub mod cube4l;
pub mod export;
pub mod gtkw;
pub mod harness;
pub mod sim;
pub mod stage_vectors;
pub mod synth;
pub mod tool;
pub mod trace;
pub mod vcd_diff;
pub mod verilog;

pub use harness::Engine;
