//! `hdl::common::shader` alone against `golden_model::common::shader::Shader::sample`,
//! clock by clock in rust-hdl simulation, its sample `shader::LATENCY`
//! clocks after its input: classification (1-D and 2-D with gradient
//! opacity), the normal quantizer and lighting, shading and opacity
//! weighting, for composite, first-opaque, X-ray and MIP, with edge and
//! invalid voxels and gradients up to full scale, and at normal widths 3, 5,
//! 6 and 8 bits; the tables preloaded, and
//! loaded by the host through the host port; and the lighting and the
//! shading's multiply-add alone.
//!
//! The `valid` flag is compared for MIP, where it means what the golden
//! model's does (the voxel takes part in the maximum). In the other modes the
//! compositor takes every sample, so neither side's flag has an effect and
//! the two differ on invalid voxels (the RTL's is `!invalid`, the golden
//! model's `true` for a transparent sample); that is not compared.

use cosim::drive_host_port;
use golden_model::common::shader::Shader as Golden;
use golden_model::cube4l::plan::Plan;
use hdl::common::shader::{Shader, ShaderConfig, LATENCY};
use rust_hdl::prelude::*;
use testbenches::{run_clocks, scene, Edge, Vectors};

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

/// Check the shader of `json`'s first sweep on random voxels; its tables
/// preloaded, or written by the host through the host port.
fn check(json: &str, seed: u64, preload: bool) {
    let s = scene(json);
    let cam = s.camera();
    let sweep = &Plan::new(&s, &cam).unwrap().sweeps[0];
    let golden = Golden::new(&s, &cam, sweep);
    let vs = vectors(golden.voxel_bits, seed);
    let compare_valid = matches!(golden.mode, scene::Mode::Mip | scene::Mode::Minip);
    let expected: Vec<([u32; 4], bool)> = vs
        .iter()
        .map(|v| {
            let out = golden.sample(v.value, v.invalid, v.edge, || v.gradient);
            (out.value, out.valid || !compare_valid)
        })
        .collect();
    let tables = golden.tables();
    let mut uut = Shader::new(&ShaderConfig::of(
        &tables,
        golden.voxel_bits,
        golden.needs_gradient,
        false,
    ));
    let mut loads = tables.register_writes();
    if preload {
        uut.preload(&tables);
    } else {
        loads.splice(0..0, tables.table_writes());
    }
    uut.connect_all();
    let label = format!("{json} (tables preloaded: {preload})");
    let n = loads.len();
    // The host's writes, then a voxel a clock; its sample LATENCY clocks
    // after its input.
    run_clocks(uut, n + N + LATENCY, &label.clone(), move |e, x| match e {
        Edge::Before(t) if t < n => drive_host_port!(x, Some(&loads[t])),
        Edge::Before(t) => {
            drive_host_port!(x, None::<&golden_model::host::Write>);
            let v = &vs[(t - n).min(N - 1)];
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
        }
        Edge::After(t) if t + 1 >= n + LATENCY && t + 1 < n + LATENCY + N => {
            let cycle = t + 1 - n - LATENCY;
            let got = (
                [
                    x.r.val().to_u32(),
                    x.g.val().to_u32(),
                    x.b.val().to_u32(),
                    x.a.val().to_u32(),
                ],
                x.valid.val() || !compare_valid,
            );
            let (want, v) = (expected[cycle], &vs[cycle]);
            if got != want {
                panic!(
                    "{label}: first mismatch at input {cycle} (clock {t}), voxel {} invalid {} edge {} gradient {:?}: rtl {got:?}, golden {want:?}",
                    v.value, v.invalid, v.edge, v.gradient
                );
            }
        }
        _ => {}
    });
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
        true,
    );
    check(
        &format!(
            r#"{{"volume": {{"builtin": "sphere", "dims": [8, 8, 8]}}, {view}, "mode": "first_opaque",
                "shading": {{"enabled": true}}, "hardware": {{"voxel_bits": 12, "rgba_bits": 10}},
                "transfer": {{"opacity": [[0, 0.0], [1000, 0.3], [4095, 0.9]], "color": [[0, 1, 1, 1], [4095, 0.5, 0.5, 0.5]],
                              "opaque_threshold": 0.25}}}}"#
        ),
        5,
        true,
    );
    check(
        &format!(
            r#"{{"volume": {{"builtin": "sphere", "dims": [8, 8, 8]}}, {view}, "mode": "xray", "hardware": {{"voxel_bits": 16}},
                "transfer": {{"opacity": [[0, 0.0], [65535, 0.8]], "color": [[0, 1, 1, 1]]}}}}"#
        ),
        7,
        true,
    );
    check(
        &format!(
            r#"{{"volume": {{"builtin": "sphere", "dims": [8, 8, 8]}}, {view}, "mode": "mip"}}"#
        ),
        11,
        true,
    );
}

/// The tables written by the host instead of preloaded: the same samples.
#[test]
fn shader_tables_load_through_the_host_port() {
    check(
        r#"{"volume": {"builtin": "sphere", "dims": [8, 8, 8]}, "view": {"projection": "parallel", "rotate_deg": [20, -40, 0]},
            "image": [16, 16], "mode": "composite", "shading": {"enabled": true, "specular": 0.5},
            "transfer": {"opacity": [[0, 0.0], [50, 0.3], [255, 0.9]], "color": [[0, 0.3, 0.9, 0.2], [255, 1, 0.5, 0.1]],
                         "gradient_opacity": [[0, 0.3], [90, 1.0]]}}"#,
        13,
        false,
    );
}

/// The normal's width is a build parameter (`hardware.normal_bits`): the
/// narrowest, the knee's 6 bits and the widest, with specular terms (the
/// half vector's dot product) and full-scale gradients.
#[test]
fn shader_lights_every_normal_width() {
    for (bits, seed) in [(3, 17), (6, 19), (8, 23)] {
        check(
            &format!(
                r#"{{"volume": {{"builtin": "sphere", "dims": [8, 8, 8]}}, "view": {{"projection": "parallel", "rotate_deg": [35, -60, 10]}},
                    "image": [16, 16], "mode": "composite", "shading": {{"enabled": true, "specular": 0.6, "shininess": 12}},
                    "hardware": {{"normal_bits": {bits}, "frac_bits": 12}},
                    "transfer": {{"opacity": [[0, 0.0], [40, 0.4], [255, 1.0]], "color": [[0, 0.9, 0.4, 0.1], [255, 0.2, 0.7, 1]]}}}}"#
            ),
            seed,
            true,
        );
    }
}

/// The lighting unit alone against `golden_model::lut::Lighting::cos_index`,
/// its tables the identity (word `i` holds `i`, so its outputs are the
/// cosine indices), with light and half registers the host may write but
/// no scene makes: unit vectors, full-scale and most-negative components,
/// and vectors whose dot products pass the saturation at every normal
/// width; each normal's components random up to full scale, extremes first.
#[test]
fn lighting_saturates_as_the_golden_model_on_any_register() {
    use golden_model::host::{pack3, Reg, Write};
    use golden_model::lut::{Lighting as GoldenLighting, COS_BITS};
    use hdl::common::lighting::{Lighting, LATENCY as LIGHTING_LATENCY};
    let registers: [([i32; 3], [i32; 3]); 5] = [
        ([1448, -1448, 0], [0, 0, 2048]),
        ([32767, 32767, 32767], [-32768, -32768, -32768]),
        ([-32768, 0, 32767], [32767, -1, 1]),
        ([4000, -3000, 2500], [2048, 2048, 2048]),
        ([1, 0, 0], [0, -2, 0]),
    ];
    let identity: Vec<u32> = (0..1u32 << COS_BITS).collect();
    for normal_bits in [3, 5, 6, 8] {
        let lim = (1i32 << (normal_bits - 1)) - 1;
        let mut r = Vectors::new(31 + normal_bits as u64);
        let normals: Vec<[i32; 3]> = (0..N)
            .map(|i| {
                let mut c = || match i % 7 {
                    0 => lim,
                    1 => -lim,
                    2 => 0,
                    _ => r.below(2 * lim as u32) as i32 - lim,
                };
                [c(), c(), c()]
            })
            .collect();
        for (light, half) in registers {
            let expected: Vec<(u32, u32)> = normals
                .iter()
                .map(|&q| {
                    let (d, lit) = GoldenLighting::cos_index(q, light, normal_bits);
                    let s = GoldenLighting::cos_index(q, half, normal_bits).0;
                    (d, if lit { s } else { 0 })
                })
                .collect();
            let mut uut = Lighting::new(16, normal_bits);
            uut.preload(&identity, &identity);
            uut.connect_all();
            let loads = [
                Write {
                    address: Reg::Light.address(),
                    data: pack3(light),
                },
                Write {
                    address: Reg::Half.address(),
                    data: pack3(half),
                },
            ];
            let n = loads.len() + 1;
            let label = format!("{normal_bits}-bit normals, light {light:?}, half {half:?}");
            let normals = normals.clone();
            run_clocks(
                uut,
                n + N + LIGHTING_LATENCY,
                &label.clone(),
                move |e, x| match e {
                    Edge::Before(t) if t < loads.len() => drive_host_port!(x, Some(&loads[t])),
                    Edge::Before(t) => {
                        drive_host_port!(x, None::<&Write>);
                        let q = normals[t.saturating_sub(n).min(N - 1)];
                        for (i, c) in q.into_iter().enumerate() {
                            x.q_neg[i].next = c < 0;
                            x.q_mag[i].next = (c.unsigned_abs() as u64).to_bits();
                        }
                    }
                    Edge::After(t)
                        if t + 1 >= n + LIGHTING_LATENCY && t + 1 < n + LIGHTING_LATENCY + N =>
                    {
                        let i = t + 1 - n - LIGHTING_LATENCY;
                        let got = (x.diffuse.val().to_u32(), x.specular.val().to_u32());
                        if got != expected[i] {
                            panic!(
                            "{label}: first mismatch at normal {i} {:?} (clock {t}): rtl {got:?}, golden {:?}",
                            normals[i], expected[i]
                        );
                        }
                    }
                    _ => {}
                },
            );
        }
    }
}

/// `hdl::common::split_mul_add` alone: `sat(mul(a, b) + c)` against
/// `golden_model::fixed::mul_unorm` and a saturated add, every operand
/// triple at 4 bits and the extremes with random words at 8 and 16.
#[test]
fn split_mul_add_is_the_saturated_sum_of_the_unorm_product() {
    use golden_model::fixed::{max_of, mul_unorm};
    use hdl::common::split_mul_add::{SplitMulAddUnorm, LATENCY as MUL_ADD_LATENCY};
    for bits in [4, 8, 16] {
        let m = max_of(bits);
        let mut r = Vectors::new(bits as u64);
        let triples: Vec<[u32; 3]> = if bits == 4 {
            (0..16 * 16 * 16)
                .map(|i| [i & 15, (i >> 4) & 15, i >> 8])
                .collect()
        } else {
            let edge = [0, 1, m / 2, m - 1, m];
            let mut v: Vec<[u32; 3]> = edge
                .iter()
                .flat_map(|&a| edge.iter().flat_map(move |&b| edge.map(|c| [a, b, c])))
                .collect();
            v.extend((0..N).map(|_| [r.below(m + 1), r.below(m + 1), r.below(m + 1)]));
            v
        };
        let expected: Vec<u32> = triples
            .iter()
            .map(|&[a, b, c]| (mul_unorm(a, b, bits) + c).min(m))
            .collect();
        let mut uut = SplitMulAddUnorm::enabled(bits, true);
        uut.connect_all();
        let n = triples.len();
        let label = format!("{bits}-bit split multiply-add");
        run_clocks(
            uut,
            n + MUL_ADD_LATENCY,
            &label.clone(),
            move |e, x| match e {
                Edge::Before(t) => {
                    let [a, b, c] = triples[t.min(n - 1)];
                    x.a.next = (a as u64).to_bits();
                    x.b.next = (b as u64).to_bits();
                    x.c.next = (c as u64).to_bits();
                }
                Edge::After(t) if t + 1 >= MUL_ADD_LATENCY && t + 1 < MUL_ADD_LATENCY + n => {
                    let i = t + 1 - MUL_ADD_LATENCY;
                    let got = x.y.val().to_u32();
                    assert_eq!(
                        got, expected[i],
                        "{label}: operands {:?} (clock {t})",
                        triples[i]
                    );
                }
                _ => {}
            },
        );
    }
}
