//! `hdl::cube3_system::Cube3System`, Cube-3 from the volume in its memory
//! modules to the base plane (beam fetch, Fast Bus, 2-DSBs, TRILIN, RPC),
//! against the golden model's base-plane pixels, in stream order and on the
//! clocks `Cube3SystemConfig` predicts: MIP, MinIP and X-ray on parallel
//! views (one at exactly 45°) of non-cubic volumes, p = 1, 2, 4 and 8, in
//! rust-hdl simulation and as emitted Verilog under Icarus and Verilator.

use cosim::stage::{ports, start_only, StageEngine};
use hdl::cube3_system::Cube3System;
use rust_hdl::prelude::*;
use testbenches::cube3::{cases, emitted_verilog, verilog_pixels, Case, Pixels};
use testbenches::{require_tool, run_sim};

const A: usize = 12;
const B: usize = 10;
const H: usize = 10;

fn system<const P: usize>(c: &Case) -> Cube3System<P, A, B, H> {
    let mut uut = Cube3System::<P, A, B, H>::new(&c.config).unwrap();
    uut.preload(&c.modules);
    uut.connect_all();
    uut
}

/// Ray 0's last segment enters `G - 1` clocks after the first.
fn first_pixel(c: &Case) -> usize {
    let p = &c.config.pipeline;
    c.config.first_entry() + p.segments - 1 + p.pixel_delay()
}

fn rust_hdl_run<const P: usize>() {
    for c in cases(P) {
        let uut = system::<P>(&c);
        let n = c.config.clocks();
        let case = std::sync::Arc::new(c);
        let tb = case.clone();
        let mut sim = Simulation::new();
        sim.add_clock(5, |x: &mut Box<Cube3System<P, A, B, H>>| {
            x.clock.next = !x.clock.val()
        });
        sim.add_testbench(move |mut sim: Sim<Cube3System<P, A, B, H>>| {
            let mut x = sim.init()?;
            let mut pixels = Pixels::new(&tb, first_pixel(&tb));
            for t in 0..n {
                x.start.next = t == 0;
                wait_clock_cycle!(sim, clock, x);
                let px = [
                    x.pixel_r.val().to_u64(),
                    x.pixel_g.val().to_u64(),
                    x.pixel_b.val().to_u64(),
                    x.pixel_a.val().to_u64(),
                ];
                pixels.clock("rust-hdl", t, x.done.val(), px, x.has_sample.val());
            }
            let errors = pixels.finish();
            assert!(errors.is_empty(), "{}", errors[0]);
            sim.done(x)
        });
        run_sim(
            sim,
            Box::new(uut),
            10 * n as u64 + 100,
            &format!("cube3 system {}", case.name),
        );
    }
}

#[test]
fn cube3_system_matches_golden_base_plane_in_rust_hdl() {
    rust_hdl_run::<1>();
    rust_hdl_run::<2>();
    rust_hdl_run::<4>();
    rust_hdl_run::<8>();
}

/// Run a case's Verilog; its mismatches.
fn verilog_case<const P: usize>(engine: StageEngine, c: &Case, verilog: &str) -> Vec<String> {
    let ports = ports(verilog).unwrap();
    let vectors: Vec<Vec<u64>> = (0..c.config.clocks())
        .map(|t| start_only(&ports, t))
        .collect();
    verilog_pixels(engine, c, verilog, &vectors, first_pixel(c))
}

fn check<const P: usize>(engine: StageEngine) {
    for c in cases(P) {
        let errors = verilog_case::<P>(engine, &c, &emitted_verilog(&c, &system::<P>(&c)));
        assert!(errors.is_empty(), "{}", errors[0]);
    }
}

#[test]
fn cube3_system_verilog_matches_golden_base_plane_under_icarus() {
    require_tool("iverilog");
    check::<4>(StageEngine::Iverilog);
}

#[test]
fn cube3_system_verilog_matches_golden_base_plane_under_verilator() {
    require_tool("verilator");
    check::<2>(StageEngine::Verilator);
}

#[test]
fn a_fault_in_the_cube3_system_verilog_is_caught() {
    require_tool("iverilog");
    let c = cases(4).remove(0);
    let verilog = emitted_verilog(&c, &system::<4>(&c));
    // The Fast Bus sends lane 1's voxel one 2-DSB module too far.
    let site = "if (holds_q$1$q & (((ray_q$1$q + plane_q$q) & mask) == index$0)) begin";
    assert!(verilog.contains(site), "the fault site exists");
    let faulty = verilog.replacen(
        site,
        "if (holds_q$1$q & (((ray_q$1$q + plane_q$q + 16'h1) & mask) == index$0)) begin",
        1,
    );
    let errors = verilog_case::<4>(StageEngine::Iverilog, &c, &faulty);
    assert!(
        !errors.is_empty(),
        "the faulty Cube-3 system went unnoticed"
    );
}

/// The volume loaded through the load port, one word per clock, instead
/// of preloaded: the same pixels.
#[test]
fn cube3_system_loads_its_memory_through_the_load_port() {
    let c = cases(2).remove(0);
    let mut uut = Cube3System::<2, A, B, H>::new(&c.config).unwrap();
    uut.connect_all();
    let words: Vec<(usize, usize, u16)> = c
        .modules
        .iter()
        .enumerate()
        .flat_map(|(m, ws)| ws.iter().enumerate().map(move |(a, &w)| (m, a, w)))
        .collect();
    let n = words.len() + c.config.clocks();
    let case = std::sync::Arc::new(c);
    let tb = case.clone();
    let mut sim = Simulation::new();
    sim.add_clock(5, |x: &mut Box<Cube3System<2, A, B, H>>| {
        x.clock.next = !x.clock.val()
    });
    sim.add_testbench(move |mut sim: Sim<Cube3System<2, A, B, H>>| {
        let mut x = sim.init()?;
        for &(m, a, w) in &words {
            x.load_enable.next = true;
            x.load_module.next = (m as u64).to_bits();
            x.load_address.next = (a as u64).to_bits();
            x.load_data.next = (w as u64).to_bits();
            wait_clock_cycle!(sim, clock, x);
        }
        x.load_enable.next = false;
        let mut pixels = Pixels::new(&tb, first_pixel(&tb));
        for t in 0..n - words.len() {
            x.start.next = t == 0;
            wait_clock_cycle!(sim, clock, x);
            let px = [
                x.pixel_r.val().to_u64(),
                x.pixel_g.val().to_u64(),
                x.pixel_b.val().to_u64(),
                x.pixel_a.val().to_u64(),
            ];
            pixels.clock("rust-hdl", t, x.done.val(), px, x.has_sample.val());
        }
        let errors = pixels.finish();
        assert!(errors.is_empty(), "{}", errors[0]);
        sim.done(x)
    });
    run_sim(
        sim,
        Box::new(uut),
        10 * n as u64 + 100,
        "cube3 system load port",
    );
}
