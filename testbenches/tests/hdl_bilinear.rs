//! `hdl::cube4l::bilinear` against `golden_model::cube4l::compositor::gather`, cycle by cycle
//! in rust-hdl simulation (`bilinear::LATENCY` clocks); its Verilog passes
//! yosys.

use golden_model::cube4l::compositor::gather;
use hdl::cube4l::bilinear::Bilinear;
use rust_hdl::prelude::*;
use testbenches::{require_tool, Vectors};

const N: usize = 800;
use hdl::cube4l::bilinear::LATENCY;

struct Vector {
    cells: [[u32; 4]; 4],
    wx: u32,
    wy: u32,
}

/// Cells up to `max` (channel 0 up to `max0`, the X-ray sum when `wide`).
fn run(frac: u32, max: u32, wide: bool, max0: u32) {
    let one = 1u32 << frac;
    let mut r = Vectors::new(5 + frac as u64);
    let vs: Vec<Vector> = (0..N)
        .map(|i| {
            let w = |r: &mut Vectors, k: usize| match (i + k) % 5 {
                0 => 0,
                1 => one,
                _ => r.below(one),
            };
            Vector {
                cells: std::array::from_fn(|_| {
                    std::array::from_fn(|c| {
                        let m = if c == 0 { max0 } else { max };
                        if i % 9 == 0 {
                            m
                        } else {
                            r.below(m)
                        }
                    })
                }),
                wx: w(&mut r, 0),
                wy: w(&mut r, 2),
            }
        })
        .collect();
    // The golden bilinear unit on a 2x2 buffer whose cells are laid out so
    // that, for cell (1, 1) and positive dx and dy, the sign-selected
    // neighbours are exactly the vector's c00, c10, c01 and c11.
    let expected: Vec<[u32; 4]> = vs
        .iter()
        .map(|v| {
            let [c00, c10, c01, c11] = v.cells;
            gather(
                &[c11, c01, c10, c00],
                2,
                2,
                1,
                1,
                v.wx as i32,
                v.wy as i32,
                frac,
                [0; 4],
            )
        })
        .collect();
    let mut uut = Bilinear::new(frac, wide);
    uut.connect_all();
    let mut sim = Simulation::new();
    sim.add_clock(5, |x: &mut Box<Bilinear>| x.clock.next = !x.clock.val());
    sim.add_testbench(move |mut sim: Sim<Bilinear>| {
        let mut x = sim.init()?;
        for cycle in 0..N + LATENCY - 1 {
            if let Some(v) = vs.get(cycle) {
                for i in 0..4 {
                    x.c00[i].next = (v.cells[0][i] as u64).to_bits();
                    x.c10[i].next = (v.cells[1][i] as u64).to_bits();
                    x.c01[i].next = (v.cells[2][i] as u64).to_bits();
                    x.c11[i].next = (v.cells[3][i] as u64).to_bits();
                }
                x.wx.next = (v.wx as u64).to_bits();
                x.wy.next = (v.wy as u64).to_bits();
            }
            wait_clock_cycle!(sim, clock, x);
            if cycle + 1 >= LATENCY {
                let k = cycle + 1 - LATENCY;
                for (i, want) in expected[k].iter().enumerate() {
                    let got = x.out[i].val().to_u32();
                    if got != *want {
                        panic!(
                            "frac_bits={frac}: first mismatch at cycle {cycle} (input {k}), out[{i}]: rtl {got} golden {want} (cells {:?}, wx {}, wy {})",
                            vs[k].cells, vs[k].wx, vs[k].wy
                        );
                    }
                }
            }
        }
        sim.done(x)
    });
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("vcd");
    std::fs::create_dir_all(&dir).unwrap();
    let vcd = dir.join(format!("bilinear_{frac}_{wide}.vcd"));
    sim.run_traced(
        Box::new(uut),
        20 * (N + LATENCY) as u64 + 100,
        std::io::BufWriter::new(std::fs::File::create(&vcd).unwrap()),
    )
    .unwrap_or_else(|e| panic!("simulation failed: {e:?}"));
}

#[test]
fn bilinear_matches_golden_model() {
    run(8, 255, false, 255);
    run(8, 65535, false, 65535);
    run(12, 4095, false, 4095);
    run(15, 32767, false, 32767);
    // X-ray: a 24-bit sum in channel 0 needs both multipliers.
    run(8, 255, true, (1 << 24) - 1);
    run(12, 4095, true, (1 << 28) - 1);
}

#[test]
fn bilinear_verilog_passes_yosys() {
    require_tool("yosys");
    let mut uut = Bilinear::new(8, true);
    uut.connect_all();
    yosys_validate("bilinear", &generate_verilog(&uut))
        .unwrap_or_else(|e| panic!("yosys rejects the bilinear unit: {e:?}"));
}
