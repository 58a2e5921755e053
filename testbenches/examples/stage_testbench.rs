//! A stage testbench of your own, with the kit as a library: the Cube-4L
//! compositor (`hdl::cube4l::compositor`, the paper's §3.7) driven with
//! random operands in rust-hdl's simulator and checked on every clock
//! against the golden model's `composite` (its answer for the operands of
//! clock `t` comes out `LATENCY` clocks later), then its emitted Verilog run
//! under Icarus Verilog on the same operands (`cosim::harness::run_stage`)
//! and checked the same way. For a testbench outside Rust, `cube
//! stage-vectors` writes the same kind of stimulus and expected outputs as
//! JSON, and `testbenches/cocotb` drives them with cocotb.
//!
//! ```sh
//! cargo run --release -p testbenches --example stage_testbench
//! ```
//!
//! To test another stage, swap the block, its inputs and the golden
//! function: every stage in `hdl` has a golden twin in `golden_model`.

use golden_model::common::compositor::composite;
use golden_model::common::plan::Order;
use golden_model::common::shader::Sample;
use hdl::cube4l::compositor::LATENCY;
use rust_hdl::prelude::*;
use scene::Mode;
use std::sync::{Arc, Mutex};

/// Composite over 8-bit RGBA, front to back.
const MODE: Mode = Mode::Composite;
const ORDER: Order = Order::FrontToBack;
const BITS: u32 = 8;
/// The `Order` register's word: front to back (bit 0), MinIP (bit 1).
const ORDER_WORD: u64 = matches!(ORDER, Order::FrontToBack) as u64;

/// One clock's operands: the accumulated colour, the new sample and its
/// validity.
type Operands = ([u32; 4], [u32; 4], bool);

fn operands(n: usize) -> Vec<Operands> {
    // A small xorshift generator: the same operands on every run.
    let mut s = 0x2545_f491_4f6c_dd1d_u64;
    let mut next = |m: u32| {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        (s % (m as u64 + 1)) as u32
    };
    let m = (1 << BITS) - 1;
    (0..n)
        .map(|_| {
            let acc = [next(m), next(m), next(m), next(m)];
            let new = [next(m), next(m), next(m), next(m)];
            (acc, new, next(3) != 0)
        })
        .collect()
}

/// What the golden model says comes out of clock `t`.
fn golden((acc, new, valid): Operands) -> [u32; 4] {
    composite(MODE, ORDER, acc, &Sample { value: new, valid }, BITS).0
}

fn main() {
    let vs = operands(1000);
    let class = hdl::common::mode_class::ModeClass::of(MODE);
    let mut uut = hdl::cube4l::compositor::Compositor::new(class, BITS);
    uut.connect_all();
    let verilog = generate_verilog(&uut);

    // rust-hdl: set the inputs, wait a clock, compare the outputs.
    let mismatches = Arc::new(Mutex::new(0usize));
    let count = mismatches.clone();
    let tb = vs.clone();
    let mut sim = Simulation::new();
    sim.add_clock(5, |x: &mut Box<hdl::cube4l::compositor::Compositor>| {
        x.clock.next = !x.clock.val()
    });
    sim.add_testbench(move |mut sim: Sim<hdl::cube4l::compositor::Compositor>| {
        let mut x = sim.init()?;
        x.order.next = ORDER_WORD.to_bits();
        for (t, &(acc, new, valid)) in tb.iter().enumerate() {
            x.acc_r.next = (acc[0] as u64).to_bits();
            x.acc_g.next = (acc[1] as u64).to_bits();
            x.acc_b.next = (acc[2] as u64).to_bits();
            x.acc_a.next = (acc[3] as u64).to_bits();
            x.new_r.next = (new[0] as u64).to_bits();
            x.new_g.next = (new[1] as u64).to_bits();
            x.new_b.next = (new[2] as u64).to_bits();
            x.new_a.next = (new[3] as u64).to_bits();
            x.new_valid.next = valid;
            wait_clock_cycle!(sim, clock, x);
            let got = [
                x.out_r.val().to_u32(),
                x.out_g.val().to_u32(),
                x.out_b.val().to_u32(),
                x.out_a.val().to_u32(),
            ];
            let Some(i) = (t + 1).checked_sub(LATENCY) else {
                continue;
            };
            if got != golden(tb[i]) {
                *count.lock().unwrap() += 1;
            }
        }
        sim.done(x)
    });
    sim.run(Box::new(uut), 20 * vs.len() as u64 + 100)
        .expect("the simulation runs");
    let n = *mismatches.lock().unwrap();
    println!(
        "rust-hdl: {} clocks, {n} differ from the golden model",
        vs.len() + 1 - LATENCY
    );

    // The emitted Verilog under Icarus: inputs in port order (acc_r, acc_g,
    // acc_b, acc_a, new_r, ..., new_valid, order), outputs after each edge.
    let vectors: Vec<Vec<u64>> = vs
        .iter()
        .map(|(acc, new, valid)| {
            acc.iter()
                .chain(new)
                .map(|&v| v as u64)
                .chain([*valid as u64, ORDER_WORD])
                .collect()
        })
        .collect();
    match cosim::harness::run_stage(cosim::Engine::Iverilog, &verilog, &vectors) {
        Ok(outs) => {
            let wrong = outs
                .iter()
                .skip(LATENCY - 1)
                .zip(&vs)
                .filter(|(o, v)| {
                    let got: Vec<Option<u64>> = o.iter().take(4).copied().collect();
                    got != golden(**v).map(|c| Some(c as u64))
                })
                .count();
            println!(
                "Icarus:   {} clocks, {wrong} differ from the golden model",
                outs.len() + 1 - LATENCY
            );
            assert_eq!(n + wrong, 0, "the stage differs from its golden model");
        }
        Err(e) => println!("Icarus:   not run ({e})"),
    }
}
