//! `hdl::common::shader` alone against `golden_model::cube4l::shader::Shader::sample`,
//! cycle by cycle in rust-hdl simulation: classification (1-D and 2-D with
//! gradient opacity), the normal quantizer and reflectance map, shading and
//! opacity weighting, for composite, first-opaque, X-ray and MIP, with edge
//! and invalid voxels and gradients up to full scale.
//!
//! The `valid` flag is compared for MIP, where it means what the golden
//! model's does (the voxel takes part in the maximum). In the other modes the
//! compositor takes every sample, so neither side's flag has an effect and
//! the two differ on invalid voxels (the RTL's is `!invalid`, the golden
//! model's `true` for a transparent sample); that is not compared.

use golden_model::cube4l::plan::{Control, Face, Plan};
use golden_model::cube4l::shader::Shader as Golden;
use hdl::common::shader::Shader;
use rust_hdl::prelude::*;
use testbenches::{run_sim, scene, Vectors};

const N: usize = 500;

struct Vector {
    value: u32,
    invalid: bool,
    edge: bool,
    gradient: [i32; 3],
}

fn vectors(voxel_bits: u32, seed: u64) -> Vec<Vector> {
    let vmax = (1u32 << voxel_bits) - 1;
    let mut r = Vectors::new(seed);
    (0..N)
        .map(|i| {
            // The undivided central difference spans ±vmax; extremes first.
            let component = |r: &mut Vectors| match i % 9 {
                0 => 0,
                1 => vmax as i32,
                2 => -(vmax as i32),
                _ => r.below(2 * vmax) as i32 - vmax as i32,
            };
            let gradient = [component(&mut r), component(&mut r), component(&mut r)];
            Vector {
                value: match i % 5 {
                    0 => vmax,
                    _ => r.below(vmax),
                },
                invalid: r.below(15) == 0,
                edge: r.below(15) == 0,
                gradient,
            }
        })
        .collect()
}

fn check(json: &str, seed: u64) {
    let s = scene(json);
    let cam = s.camera().unwrap();
    let sweep = &Plan::new(&s, &cam).unwrap().sweeps[0];
    let golden = Golden::new(&s, &cam, sweep);
    let vs = vectors(golden.voxel_bits, seed);
    let compare_valid = matches!(golden.mode, scene::Mode::Mip | scene::Mode::Minip);
    let expected: Vec<([u32; 4], bool)> = vs
        .iter()
        .map(|v| {
            let c = Control {
                dx: 0,
                dy: 0,
                sr: false,
                er: false,
                invalid: v.invalid,
                edge: v.edge,
                face: Face::None,
            };
            let out = golden.sample(v.value, &c, || v.gradient);
            (out.value, out.valid || !compare_valid)
        })
        .collect();
    let mut uut = Shader::new(&golden).unwrap();
    uut.connect_all();
    let mut sim = Simulation::new();
    sim.add_clock(5, |x: &mut Box<Shader>| x.clock.next = !x.clock.val());
    let label = json.to_string();
    sim.add_testbench(move |mut sim: Sim<Shader>| {
        let mut x = sim.init()?;
        for (cycle, v) in vs.iter().enumerate() {
            x.value.next = (v.value as u64).to_bits();
            x.invalid.next = v.invalid;
            x.at_edge.next = v.edge;
            let [gx, gy, gz] = v.gradient;
            x.gx_neg.next = gx < 0;
            x.gx_mag.next = (gx.unsigned_abs() as u64).to_bits();
            x.gy_neg.next = gy < 0;
            x.gy_mag.next = (gy.unsigned_abs() as u64).to_bits();
            x.gz_neg.next = gz < 0;
            x.gz_mag.next = (gz.unsigned_abs() as u64).to_bits();
            // The sample is registered: it is out one clock later.
            wait_clock_cycle!(sim, clock, x);
            let got = (
                [
                    x.r.val().to_u32(),
                    x.g.val().to_u32(),
                    x.b.val().to_u32(),
                    x.a.val().to_u32(),
                ],
                x.valid.val() || !compare_valid,
            );
            let want = expected[cycle];
            if got != want {
                panic!(
                    "{label}: first mismatch at cycle {cycle}, voxel {} invalid {} edge {} gradient {:?}: rtl {got:?}, golden {want:?}",
                    v.value, v.invalid, v.edge, v.gradient
                );
            }
        }
        sim.done(x)
    });
    run_sim(sim, Box::new(uut), 20 * (N as u64 + 4), "hdl_shader");
}

#[test]
fn shader_matches_golden_sample_by_sample() {
    let view =
        r#""view": {"projection": "parallel", "rotate_deg": [70, 30, 0]}, "image": [16, 16]"#;
    check(
        &format!(
            r#"{{"volume": {{"builtin": "sphere", "dims": [8, 8, 8]}}, {view}, "mode": "composite",
                "shading": {{"enabled": true, "specular": 0.7, "shininess": 4}},
                "transfer": {{"opacity": [[0, 0.0], [60, 0.2], [200, 1.0]], "color": [[0, 1, 0.2, 0], [255, 0.1, 0.6, 1]],
                              "gradient_opacity": [[0, 0.2], [60, 1.0]]}}}}"#
        ),
        3,
    );
    check(
        &format!(
            r#"{{"volume": {{"builtin": "sphere", "dims": [8, 8, 8]}}, {view}, "mode": "first_opaque",
                "shading": {{"enabled": true}}, "hardware": {{"voxel_bits": 12, "rgba_bits": 10}},
                "transfer": {{"opacity": [[0, 0.0], [1000, 0.3], [4095, 0.9]], "color": [[0, 1, 1, 1], [4095, 0.5, 0.5, 0.5]],
                              "opaque_threshold": 0.25}}}}"#
        ),
        5,
    );
    check(
        &format!(
            r#"{{"volume": {{"builtin": "sphere", "dims": [8, 8, 8]}}, {view}, "mode": "xray", "hardware": {{"voxel_bits": 16}},
                "transfer": {{"opacity": [[0, 0.0], [65535, 0.8]], "color": [[0, 1, 1, 1]]}}}}"#
        ),
        7,
    );
    check(
        &format!(
            r#"{{"volume": {{"builtin": "sphere", "dims": [8, 8, 8]}}, {view}, "mode": "mip"}}"#
        ),
        11,
    );
}
