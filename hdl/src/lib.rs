//! Synthesizable rust-hdl descriptions of the Cube-4L pipeline stages, one
//! stage per file, each matched bit for bit against the golden model in
//! `golden_model` by the testbenches: [`cfb`] (skewed memory, address
//! generator, control bits) with the perspective [`divider`],
//! [`abc_gradient`], [`shader`], the bilinear unit ([`bilinear`]),
//! [`compositor`], and [`pipeline`], which joins p pipelines by
//! nearest-neighbour links. Around them: [`ram`] (block RAM as deep as the
//! scene needs), [`export`] (Verilog per stage, lint waivers, manifest),
//! [`sim`] with the [`verilator`] engine, [`vcd_diff`] and [`synth`].

pub mod abc_gradient;
pub mod bilinear;
pub mod cfb;
pub mod compositor;
pub mod divider;
pub mod export;
pub mod pipeline;
pub mod ram;
pub mod shader;
pub mod sim;
pub mod synth;
pub mod tool;
pub mod unorm;
pub mod vcd_diff;
pub mod verilator;
