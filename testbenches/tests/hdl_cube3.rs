//! `hdl::cube3::Cube3`, the Cube-3 pipeline from the 2-D skewed buffers to
//! the base plane, against the golden model's base plane
//! (`golden_model::cube3::render_view`), pixel by pixel and on the clock
//! `Cube3Config::pixel_delay` predicts: every mode on parallel views of
//! non-cubic volumes (composite and first-opaque through the ABC units with
//! the 6 and the 12), p = 1, 2, 4 and 8, in rust-hdl simulation and
//! as emitted Verilog under Icarus and Verilator. The 2-DSB streams are the
//! golden model's PRPs (`prp::fetch`), as the beam fetch would fill them.

use cosim::drive_host_port;
use cosim::harness::{host_writes, ports};
use cosim::Engine;
use hdl::cube3::Cube3;
use rust_hdl::prelude::*;
use testbenches::cube3::{cases, emitted_verilog, verilog_pixels, Case, Pixels};
use testbenches::{for_each_p, pixel_port, require_tool, run_clocks, Edge};

const H: usize = 10;

fn pipeline<const P: usize>(c: &Case) -> Cube3<P, H> {
    let mut uut = Cube3::<P, H>::new(&c.config.pipeline, &c.sizes).unwrap();
    if let Some(s) = &c.config.pipeline.shading {
        uut.preload_tables(&s.tables());
    }
    uut.connect_all();
    uut
}

/// Clocks to run: `start`, the streams, and the last pixel's delay.
fn clocks(c: &Case) -> usize {
    let p = &c.config.pipeline;
    1 + p.stream_clocks() + p.pixel_delay() + 2
}

/// Ray 0's last segment enters at clock G (start at clock 0, the first
/// segment at clock 1).
fn first_pixel(c: &Case) -> usize {
    c.config.pipeline.segments + c.config.pipeline.pixel_delay()
}

/// Clock `t`'s `start`, `valid` and streams: start at clock 0, the
/// segments from clock 1, a scanline every `scanline_clocks` (the fetch's
/// period: pauses between scanlines).
fn stream(c: &Case, t: usize) -> (bool, bool, &[u32], &[u32]) {
    let p = &c.config.pipeline;
    let empty: &[u32] = &[0; 8][..p.p];
    let rg = p.rays * p.segments;
    let segment = t.checked_sub(1).and_then(|s| {
        let (line, at) = (s / p.scanline_clocks, s % p.scanline_clocks);
        (at < rg).then_some(line * rg + at)
    });
    match segment.and_then(|s| c.cur.get(s).zip(c.next.get(s))) {
        Some((a, b)) => (false, true, a, b),
        None => (t == 0, false, empty, empty),
    }
}

fn rust_hdl_run<const P: usize>() {
    for c in cases(P) {
        let uut = pipeline::<P>(&c);
        let l = c.loads.len();
        let (n, name) = (l + clocks(&c), format!("cube3 {}", c.name));
        let mut pixels = Pixels::new(&c, first_pixel(&c));
        run_clocks(uut, n, &name, move |e, x| match e {
            Edge::Before(t) if t < l => drive_host_port!(x, Some(&c.loads[t])),
            Edge::Before(t) => {
                drive_host_port!(x, None::<&golden_model::host::Write>);
                let (start, valid, cur, next) = stream(&c, t - l);
                x.start.next = start;
                x.valid.next = valid;
                for i in 0..P {
                    x.cur[i].next = (cur[i] as u64).to_bits();
                    x.next[i].next = (next[i] as u64).to_bits();
                }
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
fn cube3_pipeline_matches_golden_base_plane_in_rust_hdl() {
    for_each_p!(rust_hdl_run);
}

/// Run a case's Verilog; its mismatches.
fn verilog_case<const P: usize>(engine: Engine, c: &Case, verilog: &str) -> Vec<String> {
    let ports = ports(verilog).unwrap();
    let mut vectors = host_writes(&ports, &c.loads);
    vectors.extend((0..clocks(c)).map(|t| {
        let (start, valid, cur, next) = stream(c, t);
        ports
            .iter()
            .filter(|p| p.input)
            .map(|p| match p.name.split_once('$') {
                Some(("cur", i)) => cur[i.parse::<usize>().unwrap()] as u64,
                Some((_, i)) => next[i.parse::<usize>().unwrap()] as u64,
                None if p.name == "start" => start as u64,
                None if p.name == "valid" => valid as u64,
                None => 0,
            })
            .collect::<Vec<u64>>()
    }));
    verilog_pixels(engine, c, verilog, &vectors, c.loads.len() + first_pixel(c))
}

fn check<const P: usize>(engine: Engine) {
    for c in cases(P) {
        let errors = verilog_case::<P>(engine, &c, &emitted_verilog(&c, &pipeline::<P>(&c)));
        assert!(errors.is_empty(), "{}", errors[0]);
    }
}

#[test]
fn cube3_verilog_matches_golden_base_plane_under_icarus() {
    require_tool("iverilog");
    check::<2>(Engine::Iverilog);
    check::<4>(Engine::Iverilog);
}

#[test]
fn cube3_verilog_matches_golden_base_plane_under_verilator() {
    require_tool("verilator");
    check::<4>(Engine::Verilator);
}

#[test]
fn a_fault_in_the_cube3_verilog_is_caught() {
    require_tool("iverilog");
    let c = cases(2).remove(0);
    let verilog = emitted_verilog(&c, &pipeline::<2>(&c));
    // Unit 0's leaf stage takes the inside bits of the previous clock's
    // cell.
    let site = "(flags_q$6$q & lane_bit$0)";
    assert!(verilog.contains(site), "the fault site exists");
    let faulty = verilog.replace(site, "(flags_q$5$q & lane_bit$0)");
    let errors = verilog_case::<2>(Engine::Iverilog, &c, &faulty);
    assert!(
        !errors.is_empty(),
        "the faulty Cube-3 pipeline went unnoticed"
    );
}
