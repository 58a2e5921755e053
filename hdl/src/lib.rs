//! Synthesizable rust-hdl descriptions of the Cube-4L pipeline stages, one
//! stage per file, each matched bit for bit against the golden model in
//! `golden_model` by the testbenches. Present so far: [`cfb`] (skewed
//! memory, address generator and control bits, parallel views),
//! [`compositor`] (the compositing unit) and [`bilinear`] (the bilinear
//! unit's interpolation datapath). Still to come: the perspective sight-ray
//! divider, the ABC gradient, the shader, the bilinear unit's 3x3 neighbour
//! forwarding and compositing-buffer FIFO, and the p-pipeline top level.

pub mod abc_gradient;
pub mod bilinear;
pub mod cfb;
pub mod compositor;
pub mod divider;
pub mod export;
pub mod pipeline;
pub mod shader;
pub mod sim;
pub mod unorm;
pub mod vcd_diff;
pub mod verilator;
