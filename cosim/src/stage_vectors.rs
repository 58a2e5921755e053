//! A stage's stimulus and expected outputs, from the golden model, as files
//! a testbench outside the kit reads: the stage's emitted Verilog and a JSON
//! of per-clock input values and the outputs each clock must bring. The
//! cocotb test in `testbenches/cocotb/` drives them under Icarus or
//! Verilator (`cube stage-vectors` writes them).
//!
//! The stage is the Cube-4L compositor (Cube-4L paper §3.7, the over
//! operator and the MIP/MinIP/X-ray accumulations): `LATENCY` clocks after
//! the operands of clock `t` go in, `composite`'s answer for them comes out.

use golden_model::common::compositor::composite;
use golden_model::common::plan::Order;
use golden_model::common::shader::Sample;
use golden_model::fixed::max_of;
use hdl::common::mode_class::ModeClass;
use hdl::common::units::TOP;
use hdl::cube4l::compositor::{Compositor, LATENCY};
use hdl::cube4l::units::{COMPOSITOR_CLOCK, COMPOSITOR_INPUTS, COMPOSITOR_OUTPUTS};
use rust_hdl::prelude::*;
use scene::Mode;
use serde_json::json;

/// The first line of a stage's Verilog: a file that does not begin with it
/// is not the kit's, and `cube stage-vectors` never replaces it.
pub const VERILOG_MARK: &str = "// written by cube stage-vectors";

/// How a stage's vectors JSON begins (its first key, `about`, sorts first).
pub const JSON_MARK: &str = "{\n  \"about\": \"written by cube stage-vectors";

/// The stages that can be exported.
pub const STAGES: &[&str] = &["compositor"];

/// A stage's files: its Verilog (module `top`) and its vectors' JSON.
pub struct StageFiles {
    pub verilog: String,
    pub vectors: serde_json::Value,
}

/// An object of the ports `names`, each with its value.
fn ports(names: &[&str], values: impl IntoIterator<Item = u64>) -> serde_json::Value {
    names
        .iter()
        .zip(values)
        .map(|(n, v)| (n.to_string(), json!(v)))
        .collect::<serde_json::Map<_, _>>()
        .into()
}

/// The compositor for `mode`, `order` and `bits`-bit RGBA on `clocks`
/// clocks of operands from a fixed generator (`seed`): extremes (empty,
/// opaque, full scale) every few clocks, random otherwise, the sample's
/// valid bit low about a third of the time.
pub fn compositor(mode: Mode, order: Order, bits: u32, clocks: usize, seed: u64) -> StageFiles {
    let m = max_of(bits);
    // xorshift64: the same operands on every run and machine.
    let mut s = seed | 1;
    let mut below = |n: u32| {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        (s % (n as u64 + 1)) as u32
    };
    // The `order` register word: front to back (bit 0), MinIP (bit 1).
    let order_word = (order == Order::FrontToBack) as u64 | ((mode == Mode::Minip) as u64) << 1;
    let mut vectors = Vec::with_capacity(clocks);
    let mut expected = Vec::with_capacity(clocks);
    for t in 0..clocks {
        let mut pick = |scale: u32| match t % 7 {
            0 => 0,
            1 => scale,
            _ => below(scale),
        };
        let (acc, new): ([u32; 4], [u32; 4]) = match mode {
            Mode::Xray => ([pick(m * 300), 0, 0, 0], [pick(m), 0, 0, 0]),
            Mode::Mip | Mode::Minip => ([pick(65535), 0, 0, 0], [pick(65535), 0, 0, 0]),
            _ => (
                [pick(m), pick(m), pick(m), pick(m)],
                [pick(m), pick(m), pick(m), pick(m)],
            ),
        };
        let valid = below(2) != 0;
        let (out, _) = composite(mode, order, acc, &Sample { value: new, valid }, bits);
        let inputs = [acc, new].concat().into_iter().map(u64::from);
        let inputs = inputs.chain([valid as u64, order_word]);
        vectors.push(ports(&COMPOSITOR_INPUTS, inputs));
        expected.push(ports(&COMPOSITOR_OUTPUTS, out.map(u64::from)));
    }
    let mut uut = Compositor::new(ModeClass::of(mode), bits);
    uut.connect_all();
    StageFiles {
        verilog: format!(
            "{VERILOG_MARK}: the next run replaces this file\n{}",
            generate_verilog(&uut)
        ),
        vectors: json!({
            "about": "written by cube stage-vectors: the next run replaces this file",
            "stage": "compositor",
            "paper": "Cube-4L §3.7",
            "mode": format!("{mode:?}").to_lowercase(),
            "order": format!("{order:?}"),
            "rgba_bits": bits,
            "top": TOP,
            "clock": COMPOSITOR_CLOCK,
            "latency": LATENCY,
            "note": "inputs[t] are set before rising edge t; after edge t + latency - 1 the outputs equal expected[t]",
            "inputs": vectors,
            "expected": expected,
        }),
    }
}
