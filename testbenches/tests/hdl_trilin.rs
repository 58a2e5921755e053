//! `hdl::cube3::trilin::Trilin` against `golden_model::cube3::trilin`, clock by
//! clock: in rust-hdl simulation and as emitted Verilog under Icarus and
//! Verilator, on the cells of real views (oblique, exactly 45° about one
//! axis, a close perspective eye, a non-cubic volume, full-scale 16-bit
//! voxels with 24-bit samples) and on edge weights 0 and 1.0.

use cosim::harness::run_stage;
use cosim::Engine;
use golden_model::cube3::plan::{Plan, View};
use golden_model::cube3::{prp, trilin};
use hdl::cube3::trilin::{Trilin, LATENCY};
use rust_hdl::prelude::*;
use scene::volume::Volume;
use testbenches::{require_tool, run_clocks, scene, Edge, Vectors};

/// One TRILIN input: the eight voxels (`[front, back]` of A, B, C, D) and
/// the weights.
#[derive(Clone, Copy)]
struct Input {
    cell: trilin::Cell,
    w: trilin::Weights,
}

/// A stage case: widths, inputs and the golden model's samples.
struct Case {
    name: String,
    weight_bits: u32,
    voxel_bits: u32,
    sample_frac: u32,
    inputs: Vec<Input>,
    want: Vec<u32>,
}

/// Scanlines `v0..v0 + lines` of the scene's first base plane, in the order
/// the golden model interpolates them (`trilin::plane`): ray by ray, plane
/// by plane.
fn view_case(name: &str, json: &str, lines: i32) -> Case {
    let s = scene(json);
    let vol = Volume::from_spec(&s.volume, s.hardware.voxel_bits).unwrap();
    let plan = Plan::new(&s, &s.camera()).unwrap();
    let view: &View = &plan.views[0];
    assert!(!view.on_grid, "{name}: TRILIN is left out on the grid");
    let f = s.cube3.sample_bits(s.hardware.voxel_bits) - s.hardware.voxel_bits;
    let (pu0, rays) = (view.u[0] - 1, (view.u[1] - view.u[0] + 4) as usize);
    let v0 = (view.v[0] + view.v[1]) / 2 - lines / 2;
    let mut inputs = Vec::new();
    let mut want = Vec::new();
    let traversal = prp::Traversal::new(&vol, view);
    for v in v0..v0 + lines {
        let cur = prp::fetch(&traversal, view, v, pu0, rays);
        let next = prp::fetch(&traversal, view, v + 1, pu0, rays);
        want.extend(trilin::plane(view, v, &cur, &next, f).data);
        for i in 0..rays - 1 {
            let u = pu0 + i as i32;
            for k in 0..view.dims[2] {
                let cell = trilin::cell(&cur, &next, u, k);
                let w = trilin::Weights {
                    offset: view.offset,
                    wx: view.x.weight(u, k),
                    wy: view.y.weight(v, k),
                };
                inputs.push(Input { cell, w });
            }
        }
    }
    Case {
        name: name.into(),
        weight_bits: view.weight_bits,
        voxel_bits: s.hardware.voxel_bits,
        sample_frac: f,
        inputs,
        want,
    }
}

/// Random cells with full-scale voxels every ninth input and weights 0 and
/// 1.0 among the random ones.
fn edge_case(weight_bits: u32, voxel_bits: u32, sample_frac: u32, n: usize) -> Case {
    let mut r = Vectors::new(11 + weight_bits as u64);
    let (one, max) = (1u32 << weight_bits, (1u32 << voxel_bits) - 1);
    let inputs: Vec<Input> = (0..n)
        .map(|i| {
            let mut w = |k: usize| match (i + k) % 5 {
                0 => 0,
                1 => one,
                _ => r.below(one),
            };
            let w = trilin::Weights {
                offset: w(0),
                wx: w(1),
                wy: w(3),
            };
            let cell = std::array::from_fn(|_| {
                std::array::from_fn(|_| if i % 9 == 0 { max } else { r.below(max) })
            });
            Input { cell, w }
        })
        .collect();
    let want = inputs
        .iter()
        .map(|x| trilin::interpolate(&x.cell, x.w, weight_bits, sample_frac))
        .collect();
    Case {
        name: format!("edges W={weight_bits} voxel={voxel_bits} F={sample_frac}"),
        weight_bits,
        voxel_bits,
        sample_frac,
        inputs,
        want,
    }
}

fn cases() -> Vec<Case> {
    vec![
        view_case(
            "oblique parallel, non-cubic",
            r#"{"volume": {"builtin": "phantom", "dims": [14, 11, 9]}, "view": {"projection": "parallel", "rotate_deg": [20, 35, 0]},
                "mode": "mip", "image": [16, 16]}"#,
            3,
        ),
        view_case(
            "45 degrees about x, 20 about y",
            r#"{"volume": {"builtin": "sphere", "dims": [12, 12, 12]}, "view": {"projection": "parallel", "rotate_deg": [45, 20, 0]},
                "mode": "composite", "image": [16, 16], "hardware": {"frac_bits": 6}}"#,
            2,
        ),
        view_case(
            "close perspective eye",
            r#"{"volume": {"builtin": "phantom", "dims": [12, 12, 10]}, "view": {"projection": "perspective", "eye": [5.5, 5.5, -5], "fov_deg": 60},
                "mode": "xray", "image": [16, 16]}"#,
            3,
        ),
        view_case(
            "16-bit voxels, 24-bit samples",
            r#"{"volume": {"builtin": "checkerboard", "dims": [10, 10, 10]}, "view": {"projection": "parallel", "rotate_deg": [10, 30, 0]},
                "mode": "mip", "image": [16, 16], "hardware": {"voxel_bits": 16}, "cube3": {"sample_bits": 24}}"#,
            2,
        ),
        edge_case(8, 8, 4, 400),
        edge_case(15, 16, 8, 400),
        edge_case(2, 12, 0, 200),
    ]
}

fn trilin(c: &Case) -> Trilin {
    let mut uut = Trilin::new(c.weight_bits, c.voxel_bits, c.sample_frac);
    uut.connect_all();
    uut
}

/// The inputs of clock `t`: the case's input `t`, zero after the last.
fn at(c: &Case, t: usize) -> Input {
    c.inputs.get(t).copied().unwrap_or(Input {
        cell: [[0; 2]; 4],
        w: trilin::Weights {
            offset: 0,
            wx: 0,
            wy: 0,
        },
    })
}

fn mismatch(c: &Case, engine: &str, clock: usize, got: Option<u64>) -> ! {
    let k = clock + 1 - LATENCY;
    panic!(
        "{}: {engine}: first mismatch at clock {clock} (input {k}), sample: rtl {got:?} golden {} (cell {:?}, weights {:?})",
        c.name, c.want[k], c.inputs[k].cell, c.inputs[k].w
    )
}

#[test]
fn trilin_matches_golden_model_in_rust_hdl() {
    for c in cases() {
        let clocks = c.inputs.len() + LATENCY - 1;
        let uut = trilin(&c);
        let name = format!("trilin {}", c.name);
        run_clocks(uut, clocks, &name, move |e, x| match e {
            Edge::Before(t) => {
                let i = at(&c, t);
                let [[a0, a1], [b0, b1], [c0, c1], [d0, d1]] =
                    i.cell.map(|r| r.map(|v| (v as u64).to_bits()));
                (x.a0.next, x.a1.next, x.b0.next, x.b1.next) = (a0, a1, b0, b1);
                (x.c0.next, x.c1.next, x.d0.next, x.d1.next) = (c0, c1, d0, d1);
                x.offset.next = (i.w.offset as u64).to_bits();
                x.wx.next = (i.w.wx as u64).to_bits();
                x.wy.next = (i.w.wy as u64).to_bits();
            }
            Edge::After(t) if t + 1 >= LATENCY => {
                let got = x.sample.val().to_u32();
                if got != c.want[t + 1 - LATENCY] {
                    mismatch(&c, "rust-hdl", t, Some(got as u64));
                }
            }
            _ => {}
        });
    }
}

/// The Verilog inputs of each clock, in port order: a0, a1, b0, ..., d1,
/// offset, wx, wy.
fn vectors(c: &Case, clocks: usize) -> Vec<Vec<u64>> {
    (0..clocks)
        .map(|t| {
            let i = at(c, t);
            let mut v: Vec<u64> = i.cell.iter().flatten().map(|&x| x as u64).collect();
            v.extend([i.w.offset, i.w.wx, i.w.wy].map(u64::from));
            v
        })
        .collect()
}

fn verilog_run(engine: Engine) {
    for c in cases() {
        let verilog = generate_verilog(&trilin(&c));
        let clocks = c.inputs.len() + LATENCY - 1;
        let vectors = vectors(&c, clocks);
        let outs = run_stage(engine, &verilog, &vectors).unwrap();
        for (t, o) in outs.iter().enumerate().skip(LATENCY - 1) {
            if o[0] != Some(c.want[t + 1 - LATENCY] as u64) {
                mismatch(&c, &format!("{engine:?}"), t, o[0]);
            }
        }
    }
}

#[test]
fn trilin_verilog_matches_golden_model_under_icarus() {
    require_tool("iverilog");
    verilog_run(Engine::Iverilog);
}

#[test]
fn trilin_verilog_matches_golden_model_under_verilator() {
    require_tool("verilator");
    verilog_run(Engine::Verilator);
}

#[test]
fn a_fault_in_the_trilin_verilog_is_caught() {
    require_tool("iverilog");
    let c = edge_case(8, 8, 4, 60);
    let verilog = generate_verilog(&trilin(&c));
    // The Y lerp's rounding constant loses its value: samples drift by one.
    let at_y = verilog
        .find("module top$vertical(")
        .expect("the Y lerp's module");
    let faulty = format!(
        "{}{}",
        &verilog[..at_y],
        verilog[at_y..].replacen("localparam  half = 64'h80;", "localparam  half = 64'h0;", 1)
    );
    assert_ne!(faulty, verilog, "the fault site exists");
    let vectors = vectors(&c, c.inputs.len() + LATENCY - 1);
    let outs = run_stage(Engine::Iverilog, &faulty, &vectors).unwrap();
    let wrong = (LATENCY - 1..outs.len())
        .filter(|&t| outs[t][0] != Some(c.want[t + 1 - LATENCY] as u64))
        .count();
    assert!(wrong > 0, "the faulty TRILIN went unnoticed");
}
