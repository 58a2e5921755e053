//! Everything that takes the rust-hdl stages (`hdl`) elsewhere, and checks
//! them there against the golden model, written once for every
//! architecture ([`arch`]):
//!
//! - [`export`]: the Verilog of each part of a frame (a Cube-4L sweep, a
//!   Cube-3 base plane), split into one file per stage, width-clean, with
//!   the units the scene does not need pruned, lint waivers and a manifest;
//! - [`sim`]: a whole frame on one of three [`Engine`]s, checked pixel by
//!   pixel against the golden model; [`harness`] runs emitted Verilog
//!   (a stage or a frame) under Icarus or Verilator, with cached Verilator
//!   builds; [`gtkw`] writes save files for GTKWave;
//! - [`vcd_diff`]: two traces compared cycle by cycle;
//! - [`synth`]: yosys synthesis and nextpnr place and route;
//! - [`tool`]: running an external tool, with a message naming the set-up
//!   command when it is missing.

pub mod arch;
pub mod export;
pub mod gtkw;
pub mod harness;
pub mod sim;
pub mod synth;
pub mod tool;
pub mod vcd_diff;

/// The simulator that runs a design.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Engine {
    /// rust-hdl's own simulator, on the Rust description.
    RustHdl,
    /// Icarus Verilog on the emitted Verilog.
    Iverilog,
    /// Verilator on the emitted Verilog, with a generated C++ harness.
    Verilator,
}

impl Engine {
    pub fn name(self) -> &'static str {
        match self {
            Engine::RustHdl => "rust-hdl",
            Engine::Iverilog => "iverilog",
            Engine::Verilator => "verilator",
        }
    }
}
