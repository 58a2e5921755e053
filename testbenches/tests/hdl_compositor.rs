//! `hdl::cube4l::compositor` against `golden_model::common::compositor::composite`, cycle by
//! cycle in rust-hdl simulation, for every mode, both orders and two RGBA
//! widths; its Verilog passes yosys.

use golden_model::common::compositor::composite;
use golden_model::common::plan::Order;
use golden_model::common::shader::Sample;
use golden_model::fixed::max_of;
use hdl::common::mode_class::ModeClass;
use hdl::cube4l::compositor::{Compositor, LATENCY};
use rust_hdl::prelude::*;
use scene::Mode;
use testbenches::{assert_trace_opens, require_tool, Vectors};

const N: usize = 600;

struct Vector {
    acc: [u32; 4],
    new: [u32; 4],
    valid: bool,
}

fn vectors(mode: Mode, bits: u32, seed: u64) -> Vec<Vector> {
    let m = max_of(bits);
    let mut r = Vectors::new(seed);
    (0..N)
        .map(|i| {
            // Extremes first: empty, opaque and full-scale operands.
            let pick = |r: &mut Vectors| match i % 7 {
                0 => 0,
                1 => m,
                _ => r.below(m),
            };
            let acc = match mode {
                Mode::Xray => [r.below(m * 300), 0, 0, 0],
                Mode::Mip | Mode::Minip => [r.below(65535), 0, 0, 0],
                _ => [pick(&mut r), pick(&mut r), pick(&mut r), pick(&mut r)],
            };
            let new = match mode {
                Mode::Xray => [r.below(m), 0, 0, 0],
                Mode::Mip | Mode::Minip => [r.below(65535), 0, 0, 0],
                _ => [pick(&mut r), pick(&mut r), pick(&mut r), pick(&mut r)],
            };
            Vector {
                acc,
                new,
                valid: r.below(3) != 0,
            }
        })
        .collect()
}

/// Simulate one configuration against the golden model; returns its VCD.
fn run(mode: Mode, order: Order, bits: u32) -> std::path::PathBuf {
    let vs = vectors(mode, bits, 17 + bits as u64);
    let expected: Vec<[u32; 4]> = vs
        .iter()
        .map(|v| {
            composite(
                mode,
                order,
                v.acc,
                &Sample {
                    value: v.new,
                    valid: v.valid,
                },
                bits,
            )
            .0
        })
        .collect();
    let mut uut = Compositor::new(ModeClass::of(mode), bits);
    uut.connect_all();
    // The `Order` register word: front to back (bit 0), MinIP (bit 1).
    let order_word = (order == Order::FrontToBack) as u64 | ((mode == Mode::Minip) as u64) << 1;
    let mut sim = Simulation::new();
    sim.add_clock(5, |x: &mut Box<Compositor>| x.clock.next = !x.clock.val());
    let label = format!("{mode:?} {order:?} rgba_bits={bits}");
    sim.add_testbench(move |mut sim: Sim<Compositor>| {
        let mut x = sim.init()?;
        x.order.next = order_word.to_bits();
        for (cycle, v) in vs.iter().enumerate() {
            x.acc_r.next = (v.acc[0] as u64).to_bits();
            x.acc_g.next = (v.acc[1] as u64).to_bits();
            x.acc_b.next = (v.acc[2] as u64).to_bits();
            x.acc_a.next = (v.acc[3] as u64).to_bits();
            x.new_r.next = (v.new[0] as u64).to_bits();
            x.new_g.next = (v.new[1] as u64).to_bits();
            x.new_b.next = (v.new[2] as u64).to_bits();
            x.new_a.next = (v.new[3] as u64).to_bits();
            x.new_valid.next = v.valid;
            wait_clock_cycle!(sim, clock, x);
            // The operands of cycle `i` come out LATENCY clocks later.
            let Some(i) = (cycle + 1).checked_sub(LATENCY) else { continue };
            let got = [x.out_r.val().to_u32(), x.out_g.val().to_u32(), x.out_b.val().to_u32(), x.out_a.val().to_u32()];
            for (c, name) in ["out_r", "out_g", "out_b", "out_a"].iter().enumerate() {
                if got[c] != expected[i][c] {
                    panic!(
                        "{label}: first mismatch at cycle {cycle}, {name}: rtl {} golden {} (acc {:?}, new {:?}, valid {})",
                        got[c], expected[i][c], vs[i].acc, vs[i].new, vs[i].valid
                    );
                }
            }
        }
        sim.done(x)
    });
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("vcd");
    std::fs::create_dir_all(&dir).unwrap();
    let vcd = dir.join(format!("compositor_{mode:?}_{order:?}_{bits}.vcd"));
    sim.run_traced(
        Box::new(uut),
        20 * N as u64 + 100,
        std::io::BufWriter::new(std::fs::File::create(&vcd).unwrap()),
    )
    .unwrap_or_else(|e| panic!("simulation failed: {e:?}"));
    vcd
}

#[test]
fn compositor_matches_golden_model() {
    for mode in [
        Mode::Composite,
        Mode::FirstOpaque,
        Mode::Mip,
        Mode::Minip,
        Mode::Xray,
    ] {
        for order in [Order::FrontToBack, Order::BackToFront] {
            for bits in [8, 12] {
                run(mode, order, bits);
            }
        }
    }
}

#[test]
fn compositor_verilog_passes_yosys() {
    require_tool("yosys");
    for mode in [Mode::Composite, Mode::Mip] {
        let mut uut = Compositor::new(ModeClass::of(mode), 8);
        uut.connect_all();
        yosys_validate(&format!("compositor_{mode:?}"), &generate_verilog(&uut))
            .unwrap_or_else(|e| panic!("yosys rejects the compositor: {e:?}"));
    }
}

#[test]
fn compositor_vcd_parses_with_vcd2fst() {
    assert_trace_opens(&run(Mode::Composite, Order::BackToFront, 8));
}
