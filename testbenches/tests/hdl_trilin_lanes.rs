//! `hdl::cube3::trilin_lanes::TrilinLanes` against `golden_model::cube3::trilin::plane`,
//! clock by clock: the golden model's PRPs of consecutive scanlines stream in
//! as the 2-D skewed buffers deliver them (ray by ray, a segment of p planes
//! per clock), for p = 1, 2, 4 and 8 on an oblique parallel view of a
//! non-cubic volume and a close perspective eye, in rust-hdl simulation and
//! as emitted Verilog under Icarus and Verilator.

use cosim::harness::{ports, run_stage};
use cosim::Engine;
use golden_model::cube3::plan::Plan;
use golden_model::cube3::{prp, trilin};
use hdl::cube3::trilin::LATENCY;
use hdl::cube3::trilin_lanes::{cell_delay, TrilinLanes};
use rust_hdl::prelude::*;
use scene::volume::Volume;
use testbenches::{for_each_p, require_tool, run_clocks, scene, Edge};

const H: usize = 8;

/// One clock: the streams entering, the weights of the cells reaching the
/// units, and the samples due `LATENCY - 1` clocks later.
#[derive(Clone, Default)]
struct Clock {
    cur: Vec<u32>,
    next: Vec<u32>,
    first: bool,
    wx: Vec<u32>,
    wy: Vec<u32>,
    want: Vec<Option<u32>>,
}

struct Case {
    name: String,
    offset: u32,
    weight_bits: u32,
    voxel_bits: u32,
    sample_frac: u32,
    segments: usize,
    clocks: Vec<Clock>,
}

fn case(name: &str, json: &str, p: usize, lines: i32) -> Case {
    let s = scene(json);
    let vol = Volume::from_spec(&s.volume, s.hardware.voxel_bits).unwrap();
    let plan = Plan::new(&s, &s.camera()).unwrap();
    let view = &plan.views[0];
    let vb = s.hardware.voxel_bits;
    let f = s.cube3.sample_bits(vb) - vb;
    let (pu0, prays) = (view.u[0] - 1, (view.u[1] - view.u[0] + 4) as usize);
    let nk = view.dims[2];
    let g = nk.div_ceil(p);
    let v0 = (view.v[0] + view.v[1]) / 2 - lines / 2;
    let lane = |prp: &prp::Prp, u: i32, k: usize| if k <= nk { prp.at(u, k) } else { 0 };
    let mut clocks: Vec<Clock> = Vec::new();
    let traversal = prp::Traversal::new(&vol, view);
    for v in v0..v0 + lines {
        let cur = prp::fetch(&traversal, view, v, pu0, prays);
        let next = prp::fetch(&traversal, view, v + 1, pu0, prays);
        let plane = trilin::plane(view, v, &cur, &next, f);
        let base = clocks.len();
        for r in 0..prays {
            let u = pu0 + r as i32;
            for seg in 0..g {
                let ks = (0..p).map(|i| seg * p + i);
                clocks.push(Clock {
                    cur: ks.clone().map(|k| lane(&cur, u, k)).collect(),
                    next: ks.map(|k| lane(&next, u, k)).collect(),
                    first: seg == 0,
                    ..Clock::default()
                });
            }
        }
        // Ray r's cells reach the units cell_delay(g) clocks after it
        // entered (ray r + 1 is entering); the last ray has no neighbour.
        for r in 0..prays - 1 {
            let u = pu0 + r as i32;
            for seg in 0..g {
                let t = base + r * g + seg + cell_delay(g);
                if clocks.len() <= t {
                    clocks.resize(t + 1, Clock::default());
                }
                let ks: Vec<usize> = (0..p).map(|i| seg * p + i).collect();
                let c = &mut clocks[t];
                c.wx = ks
                    .iter()
                    .map(|&k| if k < nk { view.x.weight(u, k) } else { 0 })
                    .collect();
                c.wy = ks
                    .iter()
                    .map(|&k| if k < nk { view.y.weight(v, k) } else { 0 })
                    .collect();
                c.want = ks
                    .iter()
                    .map(|&k| (k < nk).then(|| plane.at(u, k)))
                    .collect();
            }
        }
    }
    Case {
        name: format!("{name}, p={p}"),
        offset: view.offset,
        weight_bits: view.weight_bits,
        voxel_bits: vb,
        sample_frac: f,
        segments: g,
        clocks,
    }
}

const OBLIQUE: &str = r#"{"volume": {"builtin": "phantom", "dims": [14, 11, 9]}, "view": {"projection": "parallel", "rotate_deg": [20, 35, 0]},
    "mode": "mip", "image": [16, 16]}"#;
const PERSPECTIVE: &str = r#"{"volume": {"builtin": "sphere", "dims": [12, 12, 10]}, "view": {"projection": "perspective", "eye": [5.5, 5.5, -5], "fov_deg": 60},
    "mode": "xray", "image": [16, 16]}"#;

/// K = 8 with a non-zero offset: for p = 1, 2 and 4 the back plane of
/// sample K - 1 is lane 0 of the next segment (p = 8 would need rays of one
/// clock, which the 2-DSB streams do not support).
const WRAPPING: &str = r#"{"volume": {"builtin": "checkerboard", "dims": [12, 10, 8]}, "view": {"projection": "parallel", "rotate_deg": [20, 35, 0]},
    "mode": "mip", "image": [16, 16]}"#;

fn cases(p: usize) -> Vec<Case> {
    let mut v = vec![
        case("oblique, non-cubic", OBLIQUE, p, 2),
        case("close perspective eye", PERSPECTIVE, p, 2),
    ];
    if p < 8 {
        v.push(case("wrapping checkerboard", WRAPPING, p, 2));
    }
    v
}

fn unit<const P: usize>(c: &Case) -> TrilinLanes<P, H> {
    // Built for longer rays than the case's: the lines' length is the
    // view's, at run time.
    let mut uut =
        TrilinLanes::<P, H>::new(c.segments + 3, c.weight_bits, c.voxel_bits, c.sample_frac)
            .unwrap();
    uut.connect_all();
    uut
}

/// The inputs of clock `t` (zero past the end).
fn at(c: &Case, p: usize, t: usize) -> Clock {
    let mut k = c.clocks.get(t).cloned().unwrap_or_default();
    for v in [&mut k.cur, &mut k.next, &mut k.wx, &mut k.wy] {
        v.resize(p, 0);
    }
    k
}

/// The samples due after the edge of clock `t`.
fn due(c: &Case, t: usize) -> Vec<Option<u32>> {
    (t + 1)
        .checked_sub(LATENCY)
        .and_then(|s| c.clocks.get(s))
        .map_or(vec![], |k| k.want.clone())
}

fn rust_hdl_run<const P: usize>() {
    for c in cases(P) {
        let uut = unit::<P>(&c);
        let clocks = c.clocks.len() + LATENCY;
        let name = format!("trilin lanes {}", c.name);
        run_clocks(uut, clocks, &name, move |e, x| match e {
            Edge::Before(t) => {
                let k = at(&c, P, t);
                for i in 0..P {
                    x.cur[i].next = (k.cur[i] as u64).to_bits();
                    x.next[i].next = (k.next[i] as u64).to_bits();
                    x.wx[i].next = (k.wx[i] as u64).to_bits();
                    x.wy[i].next = (k.wy[i] as u64).to_bits();
                }
                x.first.next = k.first;
                x.offset.next = (c.offset as u64).to_bits();
                x.line_last.next = ((c.segments - 2) as u64).to_bits();
            }
            Edge::After(t) => {
                for (i, w) in due(&c, t).iter().enumerate() {
                    if let Some(w) = w {
                        let got = x.sample[i].val().to_u32();
                        assert_eq!(
                            got, *w,
                            "{}: rust-hdl: first mismatch at clock {t}, lane {i}: rtl {got} golden {w}",
                            c.name
                        );
                    }
                }
            }
            Edge::End => {}
        });
    }
}

#[test]
fn trilin_lanes_match_golden_model_in_rust_hdl() {
    for_each_p!(rust_hdl_run);
}

/// Run a case's Verilog; the samples that differ (the first panics unless
/// `count`).
fn verilog_case<const P: usize>(engine: Engine, c: &Case, verilog: &str, count: bool) -> usize {
    let ports = ports(verilog).unwrap();
    let clocks = c.clocks.len() + LATENCY;
    let vectors: Vec<Vec<u64>> = (0..clocks)
        .map(|t| {
            let k = at(c, P, t);
            ports
                .iter()
                .filter(|p| p.input)
                .map(|p| match p.name.split_once('$') {
                    Some((field, i)) => {
                        let i: usize = i.parse().unwrap();
                        (match field {
                            "cur" => k.cur[i],
                            "next" => k.next[i],
                            "wx" => k.wx[i],
                            _ => k.wy[i],
                        }) as u64
                    }
                    None => match p.name.as_str() {
                        "offset" => c.offset as u64,
                        "line_last" => c.segments as u64 - 2,
                        _ => k.first as u64,
                    },
                })
                .collect()
        })
        .collect();
    let outs = run_stage(engine, verilog, &vectors).unwrap();
    let mut wrong = 0;
    for (t, o) in outs.iter().enumerate() {
        for (i, w) in due(c, t).iter().enumerate() {
            let Some(w) = w else { continue };
            let got = o[i];
            if got != Some(*w as u64) {
                assert!(
                    count,
                    "{}: {engine:?}: first mismatch at clock {t}, lane {i}: rtl {got:?} golden {w}",
                    c.name
                );
                wrong += 1;
            }
        }
    }
    wrong
}

#[test]
fn trilin_lanes_verilog_match_golden_model_under_icarus() {
    require_tool("iverilog");
    for c in cases(4) {
        verilog_case::<4>(
            Engine::Iverilog,
            &c,
            &generate_verilog(&unit::<4>(&c)),
            false,
        );
    }
}

#[test]
fn trilin_lanes_verilog_match_golden_model_under_verilator() {
    require_tool("verilator");
    for c in cases(2) {
        verilog_case::<2>(
            Engine::Verilator,
            &c,
            &generate_verilog(&unit::<2>(&c)),
            false,
        );
    }
}

#[test]
fn a_fault_in_the_trilin_lanes_verilog_is_caught() {
    require_tool("iverilog");
    // K = 8 planes in segments of 2 with a non-zero offset: sample K - 1
    // wraps to the next segment for its back plane, which must read 0.
    let c = case("wrapping checkerboard", WRAPPING, 2, 2);
    assert!(c.offset > 0);
    let verilog = generate_verilog(&unit::<2>(&c));
    // The wrap to the next segment loses its gate: plane K reads the next
    // ray's first voxel.
    let site = "if (first) begin";
    assert!(verilog.contains(site), "the fault site exists");
    let faulty = verilog.replacen(site, "if (1'b0) begin", 1);
    let wrong = verilog_case::<2>(Engine::Iverilog, &c, &faulty, true);
    assert!(wrong > 0, "the faulty 2-DSB read went unnoticed");
}
