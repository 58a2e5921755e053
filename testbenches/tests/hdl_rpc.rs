//! `hdl::cube3::compositor::Rpc` against `golden_model::cube3::rpc`, clock by clock, for
//! p = 1, 2, 4 and 8 leaves and every mode: in rust-hdl simulation and as
//! emitted Verilog under Icarus (every case) and Verilator (four). Rays of
//! 1 to 3p + 1 samples follow each other without a gap; leaves cover
//! near-opaque and near-transparent α, empty MIP / MinIP samples and rays
//! without any valid sample.

use cosim::harness::{ports, run_stage};
use cosim::Engine;
use golden_model::cube3::rpc::{identity, node, pixel, tree, Leaf};
use hdl::cube3::compositor::{latency, Rpc};
use rust_hdl::prelude::*;
use scene::Mode;
use testbenches::{for_each_p, require_tool, run_clocks, Edge, Vectors};

const MODES: [Mode; 5] = [
    Mode::Composite,
    Mode::FirstOpaque,
    Mode::Mip,
    Mode::Minip,
    Mode::Xray,
];

/// One clock at the leaves, and what the RPC must put out `latency - 1`
/// clocks later (after that clock's edge).
#[derive(Clone)]
struct Clock {
    leaves: Vec<Leaf>,
    first: bool,
    last: bool,
    /// The ray's pixel and whether it had a valid sample, on its last segment.
    want: Option<([u32; 4], bool)>,
}

struct Case {
    name: String,
    mode: Mode,
    rgba_bits: u32,
    voxel_bits: u32,
    clocks: Vec<Clock>,
}

fn leaf(mode: Mode, r: &mut Vectors, rgba_bits: u32, voxel_bits: u32) -> Leaf {
    let m = (1u32 << rgba_bits) - 1;
    // α at the extremes half of the time: near-opaque and near-transparent.
    let alpha = |r: &mut Vectors| match r.below(7) {
        0 => 0,
        1 => 1,
        2 => m - 1,
        3 => m,
        _ => r.below(m),
    };
    match mode {
        Mode::Composite => {
            let a = alpha(r);
            Leaf {
                value: [r.below(m), r.below(m), r.below(m), a],
                valid: true,
            }
        }
        Mode::FirstOpaque => {
            let a = if r.below(3) == 0 { m } else { 0 };
            Leaf {
                value: [r.below(m), r.below(m), r.below(m), a],
                valid: true,
            }
        }
        Mode::Mip | Mode::Minip => {
            if r.below(3) == 0 {
                identity(mode)
            } else {
                Leaf {
                    value: [r.below((1 << voxel_bits) - 1), 0, 0, 0],
                    valid: true,
                }
            }
        }
        Mode::Xray => Leaf {
            value: [r.below(m), 0, 0, 0],
            valid: true,
        },
    }
}

fn case(p: usize, mode: Mode, rgba_bits: u32, voxel_bits: u32, rays: usize) -> Case {
    let mut r = Vectors::new(7 + p as u64 * 31 + rgba_bits as u64);
    let mut clocks = Vec::new();
    for ray in 0..rays {
        // Every fifth MIP / MinIP ray has no valid sample at all.
        let empty = matches!(mode, Mode::Mip | Mode::Minip) && ray % 5 == 4;
        let k = 1 + r.below(3 * p as u32) as usize;
        let segments = k.div_ceil(p);
        let mut acc = identity(mode);
        for s in 0..segments {
            let leaves: Vec<Leaf> = (0..p)
                .map(|i| {
                    if s * p + i >= k || empty {
                        identity(mode)
                    } else {
                        leaf(mode, &mut r, rgba_bits, voxel_bits)
                    }
                })
                .collect();
            acc = node(mode, acc, tree(mode, &leaves, rgba_bits).0, rgba_bits).0;
            let last = s + 1 == segments;
            clocks.push(Clock {
                leaves,
                first: s == 0,
                last,
                want: last.then(|| (pixel(mode, acc, voxel_bits), acc.valid)),
            });
        }
    }
    Case {
        name: format!("p={p} {mode:?} rgba_bits={rgba_bits}"),
        mode,
        rgba_bits,
        voxel_bits,
        clocks,
    }
}

fn cases(p: usize) -> Vec<Case> {
    let mut v: Vec<Case> = MODES.iter().map(|&m| case(p, m, 8, 8, 60)).collect();
    v.push(case(p, Mode::Composite, 12, 12, 40));
    v.push(case(p, Mode::Minip, 8, 16, 40));
    v
}

/// The clock `t` of a case, all identity leaves after the last ray.
fn at(c: &Case, p: usize, t: usize) -> Clock {
    c.clocks.get(t).cloned().unwrap_or(Clock {
        leaves: vec![identity(c.mode); p],
        first: false,
        last: false,
        want: None,
    })
}

/// Check the outputs after the edge of clock `t`: `done` on exactly the
/// clocks a ray ends, and then its pixel.
fn check(
    c: &Case,
    p: usize,
    engine: &str,
    t: usize,
    done: bool,
    px: [u64; 4],
    has: bool,
) -> Result<(), String> {
    let lat = latency(p);
    let want = (t + 1 >= lat).then(|| at(c, p, t + 1 - lat).want).flatten();
    let ok = match want {
        None => !done,
        Some((w, valid)) => done && px == w.map(u64::from) && has == valid,
    };
    if ok {
        Ok(())
    } else {
        Err(format!(
            "{}: {engine}: first mismatch at clock {t}: rtl done {done} pixel {px:?} has_sample {has}, golden {want:?}",
            c.name
        ))
    }
}

fn rust_hdl_run<const P: usize>() {
    for c in cases(P) {
        let clocks = c.clocks.len() + latency(P);
        let mut uut = Rpc::<P>::new(c.mode, c.rgba_bits, c.voxel_bits);
        uut.connect_all();
        let name = format!("rpc {}", c.name);
        run_clocks(uut, clocks, &name, move |e, x| match e {
            Edge::Before(t) => {
                let k = at(&c, P, t);
                for (i, l) in k.leaves.iter().enumerate() {
                    x.leaf_r[i].next = (l.value[0] as u64).to_bits();
                    x.leaf_g[i].next = (l.value[1] as u64).to_bits();
                    x.leaf_b[i].next = (l.value[2] as u64).to_bits();
                    x.leaf_a[i].next = (l.value[3] as u64).to_bits();
                    x.leaf_valid[i].next = l.valid;
                }
                x.first.next = k.first;
                x.last.next = k.last;
            }
            Edge::After(t) => {
                let px = [
                    x.pixel_r.val().to_u64(),
                    x.pixel_g.val().to_u64(),
                    x.pixel_b.val().to_u64(),
                    x.pixel_a.val().to_u64(),
                ];
                if let Err(e) = check(&c, P, "rust-hdl", t, x.done.val(), px, x.has_sample.val()) {
                    panic!("{e}");
                }
            }
            Edge::End => {}
        });
    }
}

#[test]
fn rpc_matches_golden_model_in_rust_hdl() {
    for_each_p!(rust_hdl_run);
}

/// Run a case's emitted Verilog and check every clock; the mismatches.
fn verilog_case<const P: usize>(engine: Engine, c: &Case, verilog: &str) -> Vec<String> {
    let ports = ports(verilog).unwrap();
    let clocks = c.clocks.len() + latency(P);
    let vectors: Vec<Vec<u64>> = (0..clocks)
        .map(|t| {
            let k = at(c, P, t);
            ports
                .iter()
                .filter(|p| p.input)
                .map(|p| match p.name.split_once('$') {
                    Some((field, i)) => {
                        let l = k.leaves[i.parse::<usize>().unwrap()];
                        match field {
                            "leaf_r" => l.value[0] as u64,
                            "leaf_g" => l.value[1] as u64,
                            "leaf_b" => l.value[2] as u64,
                            "leaf_a" => l.value[3] as u64,
                            _ => l.valid as u64,
                        }
                    }
                    None => (if p.name == "first" { k.first } else { k.last }) as u64,
                })
                .collect()
        })
        .collect();
    let outs = run_stage(engine, verilog, &vectors).unwrap();
    let outputs: Vec<&str> = ports
        .iter()
        .filter(|p| !p.input)
        .map(|p| p.name.as_str())
        .collect();
    let get = |o: &[Option<u64>], name: &str| {
        o[outputs.iter().position(|n| *n == name).unwrap()].unwrap_or(u64::MAX)
    };
    let mut errors = Vec::new();
    for (t, o) in outs.iter().enumerate() {
        let px = ["pixel_r", "pixel_g", "pixel_b", "pixel_a"].map(|n| get(o, n));
        let (done, has) = (get(o, "done") == 1, get(o, "has_sample") == 1);
        if let Err(e) = check(c, P, &format!("{engine:?}"), t, done, px, has) {
            errors.push(e);
        }
    }
    errors
}

fn verilog_of<const P: usize>(c: &Case) -> String {
    let mut uut = Rpc::<P>::new(c.mode, c.rgba_bits, c.voxel_bits);
    uut.connect_all();
    generate_verilog(&uut)
}

fn verilog_run<const P: usize>(engine: Engine, modes: &[Mode]) {
    for c in cases(P).iter().filter(|c| modes.contains(&c.mode)) {
        if let Some(e) = verilog_case::<P>(engine, c, &verilog_of::<P>(c)).first() {
            panic!("{e}");
        }
    }
}

#[test]
fn rpc_verilog_matches_golden_model_under_icarus() {
    require_tool("iverilog");
    verilog_run::<1>(Engine::Iverilog, &MODES);
    verilog_run::<2>(Engine::Iverilog, &MODES);
    verilog_run::<4>(Engine::Iverilog, &MODES);
    verilog_run::<8>(Engine::Iverilog, &MODES);
}

#[test]
fn rpc_verilog_matches_golden_model_under_verilator() {
    require_tool("verilator");
    verilog_run::<2>(Engine::Verilator, &[Mode::Composite]);
    verilog_run::<8>(Engine::Verilator, &[Mode::Minip, Mode::Xray]);
}

#[test]
fn a_fault_in_the_rpc_verilog_is_caught() {
    require_tool("iverilog");
    let c = case(4, Mode::Composite, 8, 8, 30);
    let verilog = verilog_of::<4>(&c);
    // The root node composites back over front: its over operator takes
    // the back child's alpha.
    let at_root = verilog
        .find("module top$nodes$2(")
        .expect("the root node's module");
    let (head, tail) = verilog.split_at(at_root);
    let site = "ch_r$front_alpha = front_a;";
    assert!(tail.contains(site), "the fault site exists");
    let faulty = format!(
        "{head}{}",
        tail.replacen(site, "ch_r$front_alpha = back_a;", 1)
    );
    let wrong = verilog_case::<4>(Engine::Iverilog, &c, &faulty);
    assert!(!wrong.is_empty(), "the faulty RPC went unnoticed");
}
