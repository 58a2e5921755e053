//! Everything that takes the rust-hdl stages (`hdl`) elsewhere, and checks
//! them there against the golden model:
//!
//! - [`export`]: the Verilog of each sweep's pipeline, split into one file
//!   per stage, width-clean, with the units the scene does not need pruned,
//!   lint waivers and a manifest;
//! - the simulation engines: [`sim`] (rust-hdl's simulator, and the dispatch
//!   to the others), [`iverilog`] and [`verilator`] (generated harnesses,
//!   cached builds), which share the [`pixel_log`] format; [`gtkw`] save files
//!   for GTKWave;
//! - [`vcd_diff`]: two traces compared cycle by cycle;
//! - [`synth`]: yosys synthesis and nextpnr place and route;
//! - [`tool`]: running an external tool, with a message naming the set-up
//!   command when it is missing.

pub mod cube3_sim;
pub mod export;
pub mod gtkw;
pub mod iverilog;
pub mod pixel_log;
pub mod sim;
pub mod stage;
pub mod synth;
pub mod tool;
pub mod vcd_diff;
pub mod verilator;
