//! `hdl::cube3::Cube3System`, Cube-3 from the volume in its memory
//! modules to the base plane (beam fetch, Fast Bus, 2-DSBs, TRILIN, RPC),
//! against the golden model's base-plane pixels, in stream order and on the
//! clocks `Cube3SystemConfig` predicts: MIP, MinIP and X-ray on parallel
//! views (one at exactly 45°) of non-cubic volumes, p = 1, 2, 4 and 8, in
//! rust-hdl simulation and as emitted Verilog under Icarus and Verilator.

use cosim::drive_host_port;
use cosim::harness::{host_writes, ports, start_only};
use cosim::Engine;
use hdl::cube3::Cube3System;
use rust_hdl::prelude::*;
use testbenches::cube3::{cases, emitted_verilog, verilog_pixels, Case, Pixels};
use testbenches::{for_each_p, pixel_port, require_tool, run_clocks, Edge};

const A: usize = 13;
const B: usize = 10;
const H: usize = 10;

fn system<const P: usize>(c: &Case) -> Cube3System<P, A, B, H> {
    let mut uut = Cube3System::<P, A, B, H>::new(&c.config.pipeline, &c.sizes).unwrap();
    uut.preload(&c.modules);
    if let Some(s) = &c.config.pipeline.shading {
        uut.preload_tables(&s.tables());
    }
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
        let l = c.loads.len();
        let (n, name) = (l + c.config.clocks(), format!("cube3 system {}", c.name));
        let mut pixels = Pixels::new(&c, first_pixel(&c));
        let loads = c.loads.clone();
        run_clocks(uut, n, &name, move |e, x| match e {
            Edge::Before(t) if t < l => drive_host_port!(x, Some(&loads[t])),
            Edge::Before(t) => {
                drive_host_port!(x, None::<&golden_model::host::Write>);
                x.start.next = t == l;
            }
            Edge::After(t) if t >= l => pixels.read("rust-hdl", t - l, pixel_port!(x)),
            Edge::After(_) => {}
            Edge::End => {
                let errors = pixels.finish();
                assert!(errors.is_empty(), "{}", errors[0]);
            }
        });
    }
}

#[test]
fn cube3_system_matches_golden_base_plane_in_rust_hdl() {
    for_each_p!(rust_hdl_run);
}

/// Run a case's Verilog; its mismatches.
fn verilog_case<const P: usize>(engine: Engine, c: &Case, verilog: &str) -> Vec<String> {
    let ports = ports(verilog).unwrap();
    let mut vectors = host_writes(&ports, &c.loads);
    vectors.extend((0..c.config.clocks()).map(|t| start_only(&ports, t)));
    verilog_pixels(engine, c, verilog, &vectors, c.loads.len() + first_pixel(c))
}

fn check<const P: usize>(engine: Engine) {
    for c in cases(P) {
        let errors = verilog_case::<P>(engine, &c, &emitted_verilog(&c, &system::<P>(&c)));
        assert!(errors.is_empty(), "{}", errors[0]);
    }
}

#[test]
fn cube3_system_verilog_matches_golden_base_plane_under_icarus() {
    require_tool("iverilog");
    check::<4>(Engine::Iverilog);
}

#[test]
fn cube3_system_verilog_matches_golden_base_plane_under_verilator() {
    require_tool("verilator");
    check::<2>(Engine::Verilator);
}

#[test]
fn a_fault_in_the_cube3_system_verilog_is_caught() {
    require_tool("iverilog");
    let c = cases(4).remove(0);
    let verilog = emitted_verilog(&c, &system::<4>(&c));
    // The Fast Bus sends lane 1's voxel one 2-DSB module too far.
    let site = "lane_dsb$1 = (s1_ray$1$q + s1_plane$q) & mask;";
    assert!(verilog.contains(site), "the fault site exists");
    let faulty = verilog.replacen(
        site,
        "lane_dsb$1 = (s1_ray$1$q + s1_plane$q + 16'h1) & mask;",
        1,
    );
    let errors = verilog_case::<4>(Engine::Iverilog, &c, &faulty);
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
    let mut uut = Cube3System::<2, A, B, H>::new(&c.config.pipeline, &c.sizes).unwrap();
    uut.connect_all();
    let words: Vec<(usize, usize, u16)> = c
        .modules
        .iter()
        .enumerate()
        .flat_map(|(m, ws)| ws.iter().enumerate().map(move |(a, &w)| (m, a, w)))
        .collect();
    if let Some(s) = &c.config.pipeline.shading {
        uut.preload_tables(&s.tables());
    }
    let loads = c.loads.clone();
    let writes = words.len() + loads.len();
    let (loading, n) = (writes, writes + c.config.clocks());
    let mut pixels = Pixels::new(&c, first_pixel(&c));
    run_clocks(uut, n, "cube3 system load port", move |e, x| match e {
        Edge::Before(t) if t < words.len() => {
            let (m, a, w) = words[t];
            x.load_enable.next = true;
            x.load_module.next = (m as u64).to_bits();
            x.load_address.next = (a as u64).to_bits();
            x.load_data.next = (w as u64).to_bits();
        }
        Edge::Before(t) if t < loading => {
            let w = loads[t - words.len()];
            x.load_enable.next = false;
            drive_host_port!(x, Some(&w));
        }
        Edge::Before(t) => {
            x.load_enable.next = false;
            drive_host_port!(x, None::<&golden_model::host::Write>);
            x.start.next = t == loading;
        }
        Edge::After(t) if t >= loading => pixels.read("rust-hdl", t - loading, pixel_port!(x)),
        Edge::After(_) => {}
        Edge::End => {
            let errors = pixels.finish();
            assert!(errors.is_empty(), "{}", errors[0]);
        }
    });
}
