//! `cube sim --arch cube3`'s flow (`cosim::sim` with `Cube3`) on a small scene:
//! the Cube-3 system in rust-hdl, and its emitted Verilog under Icarus and
//! Verilator, all equal to the golden model's base plane on the same clock
//! count; the rust-hdl and Verilator traces equal under `vcd-diff`; and a
//! fault injected into the Verilog caught by both the pixel comparison and
//! the trace comparison.

use cosim::cube3::Cube3;
use cosim::sim::Outcome;
use cosim::vcd_diff::{compare, Trace};
use cosim::Engine;
use scene::volume::Volume;
use testbenches::{assert_trace_opens, require_tool, scene};

const SCENE: &str = r#"{"volume": {"builtin": "phantom", "dims": [10, 9, 8]},
    "view": {"projection": "parallel", "rotate_deg": [25, 35, 0]},
    "mode": "mip", "image": [32, 32], "hardware": {"pipelines": 2}}"#;

fn simulate(
    s: &scene::Scene,
    cam: &scene::Camera,
    vol: &Volume,
    engine: Engine,
    trace: Option<&std::path::Path>,
) -> Result<Outcome<Cube3>, String> {
    let trace = trace.map(testbenches::trace_to);
    cosim::sim::simulate::<Cube3>(s, cam, vol, engine, trace.as_ref())
}

/// The frame's clocks of one term of the schedule.
fn term(r: &Outcome<Cube3>, key: &str) -> i64 {
    r.clock_terms.iter().find(|t| t.key == key).unwrap().clocks
}

fn dir() -> std::path::PathBuf {
    let d = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("cube3_cosim");
    std::fs::create_dir_all(&d).unwrap();
    d
}

#[test]
fn every_engine_matches_the_golden_model_and_the_traces_agree() {
    require_tool("iverilog");
    require_tool("verilator");
    let s = scene(SCENE);
    let vol = Volume::from_spec(&s.volume, s.hardware.voxel_bits).unwrap();
    let cam = s.camera();
    let (rust_vcd, verilator_vcd, icarus_fst) = (
        dir().join("rust.vcd"),
        dir().join("verilator.vcd"),
        dir().join("icarus.fst"),
    );
    let rust = simulate(&s, &cam, &vol, Engine::RustHdl, Some(&rust_vcd)).unwrap();
    let icarus = simulate(&s, &cam, &vol, Engine::Iverilog, Some(&icarus_fst)).unwrap();
    let verilator = simulate(&s, &cam, &vol, Engine::Verilator, Some(&verilator_vcd)).unwrap();
    for (name, r) in [
        ("rust-hdl", &rust),
        ("Icarus", &icarus),
        ("Verilator", &verilator),
    ] {
        assert_eq!(r.mismatches, 0, "{name}: {:?}", r.first);
        assert_eq!(r.clocks, rust.clocks, "{name}: the same clock count");
    }
    assert_eq!(
        rust.clocks as i64,
        rust.clock_terms.iter().map(|t| t.clocks).sum::<i64>(),
        "every clock accounted for"
    );
    assert!(rust.clocks > rust.ideal_clocks);
    assert_trace_opens(&rust_vcd);
    assert!(rust_vcd.with_extension("gtkw").exists());
    let rust_trace = Trace::load(&rust_vcd).unwrap();
    let cmp = compare(&rust_trace, &Trace::load(&verilator_vcd).unwrap(), None).unwrap();
    assert!(cmp.compared > 500, "{} signals compared", cmp.compared);
    assert!(
        cmp.equal(),
        "rust-hdl and Verilator traces differ: {:?}",
        cmp.mismatches.first()
    );
    // Icarus's trace, written as FST, holds the run's clocks (its values
    // are four-state, X until first written, so it is not compared with
    // rust-hdl's two-state trace).
    assert_trace_opens(&icarus_fst);
    assert_eq!(Trace::load(&icarus_fst).unwrap().cycles, rust_trace.cycles);
}

#[test]
fn a_fault_in_the_emitted_verilog_is_caught_by_pixels_and_traces() {
    require_tool("verilator");
    let s = scene(SCENE);
    let vol = Volume::from_spec(&s.volume, s.hardware.voxel_bits).unwrap();
    let cam = s.camera();
    let (rust_vcd, faulty_vcd) = (dir().join("rust_f.vcd"), dir().join("faulty.vcd"));
    simulate(&s, &cam, &vol, Engine::RustHdl, Some(&rust_vcd)).unwrap();
    // The RPC's accumulator forgets a ray's first segment: it starts from
    // the previous ray's value instead of the identity.
    let site = "if (root_flags['h0]) begin";
    let faulty = cosim::sim::simulate_altered::<Cube3>(
        &s,
        &cam,
        &vol,
        Engine::Verilator,
        Some(&testbenches::trace_to(&faulty_vcd)),
        &|v| {
            assert!(v.contains(site), "the fault site exists");
            v.replacen(site, "if (1'b0) begin", 1)
        },
    )
    .unwrap();
    assert!(
        faulty.mismatches > 0,
        "the pixel comparison missed the fault"
    );
    let cmp = compare(
        &Trace::load(&rust_vcd).unwrap(),
        &Trace::load(&faulty_vcd).unwrap(),
        None,
    )
    .unwrap();
    assert!(!cmp.equal(), "the trace comparison missed the fault");
}

/// A committed scene of the engine data set, and its volume.
fn engine_scene(name: &str) -> (scene::Scene, Volume) {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../scenes")
        .join(name);
    let s = scene::Scene::load(&path).unwrap();
    let vol = Volume::from_spec(&s.volume, 8).unwrap_or_else(|e| {
        panic!(
            "{e}\nThe engine data set is missing: run scripts/fetch-engine (scripts/setup does it)."
        )
    });
    (s, vol)
}

#[test]
fn the_engine_frame_runs_through_verilator_bit_exact() {
    require_tool("verilator");
    let (s, vol) = engine_scene("engine_mip.json");
    let r = simulate(&s, &s.camera(), &vol, Engine::Verilator, None).unwrap();
    assert_eq!(r.mismatches, 0, "{:?}", r.first);
    // 414 scanlines of 207 rays of 64 segments (K = 256, p = 4): 5 484 672
    // segments, of which 1 809 447 hold a sample inside the volume (1.004
    // times the ideal), 2 571 673 lie outside on rays that cross it, and
    // 1 103 552 belong to rays that miss it; periods of 13 316 clocks bound
    // by the PRP writes (256 planes x 52 chunks, and their latency of 4).
    let terms = [
        "segments",
        "segments_outside",
        "rays_outside",
        "idle",
        "prologue",
        "tail",
        "drain",
    ]
    .map(|k| term(&r, k));
    assert_eq!(
        (r.clocks, terms),
        (
            5_539_467,
            [1_809_447, 2_571_673, 1_103_552, 28_152, 26_635, -68, 76]
        )
    );
    assert_eq!(r.ideal_clocks, 256 * 256 * 110 / 4);
}

/// The 10 (its weights and basis correction written through the system's
/// host port) and the 26 in perspective, through the whole system under
/// Verilator (`hdl_abc_unit.rs` holds both to the golden model clock by
/// clock in rust-hdl, Icarus and Verilator).
#[test]
fn the_10_and_the_26_render_bit_exact_through_the_system() {
    require_tool("verilator");
    for (view, n, planes) in [
        (
            r#"{"projection": "parallel", "rotate_deg": [25, 35, 0]}"#,
            10,
            1,
        ),
        (
            r#"{"projection": "perspective", "eye": [-12, -5, -12], "target": [4.5, 4, 3.5], "fov_deg": 60}"#,
            26,
            3,
        ),
    ] {
        let s = scene(&format!(
            r#"{{"volume": {{"builtin": "phantom", "dims": [10, 9, 8]}}, "view": {view},
            "mode": "composite", "image": [32, 32], "hardware": {{"pipelines": 2}}, "cube3": {{"gradient": {n}}}}}"#
        ));
        let vol = Volume::from_spec(&s.volume, s.hardware.voxel_bits).unwrap();
        let r = simulate(&s, &s.camera(), &vol, Engine::Verilator, None).unwrap();
        assert_eq!(r.mismatches, 0, "the {n}: {:?}", r.first);
        assert_eq!(r.bases.len(), planes, "the {n}: base planes");
        let built = if n == 10 {
            "abc_10_basis"
        } else {
            "abc_26_sums"
        };
        assert!(
            r.left_out.iter().all(|u| !u.starts_with(built)),
            "the {n}'s unit is built: {:?}",
            r.left_out
        );
    }
}

#[test]
fn a_perspective_engine_frame_runs_through_verilator_bit_exact() {
    require_tool("verilator");
    let (s, vol) = engine_scene("engine_cube3_perspective.json");
    let r = simulate(&s, &s.camera(), &vol, Engine::Verilator, None).unwrap();
    assert_eq!(r.mismatches, 0, "{:?}", r.first);
    // The eye off a corner sees the volume's rays leave through three
    // faces: three base planes, each with its own memory order and
    // de-fanning groups (up to 2^18 of them in a 256 class).
    assert_eq!(r.bases.len(), 3);
    assert_eq!(r.clocks, 1_981_904);
}

/// Composite through the ABC units (the 12-neighbourhood, shaded) and
/// first-opaque (the 6, gradient opacity), and a perspective composite
/// view from a corner, three base planes (the first one's traces): rust-hdl and
/// Verilator equal the golden model on the same clocks, and their traces
/// agree.
#[test]
fn the_abc_units_match_the_golden_model_in_rust_hdl_and_verilator() {
    require_tool("verilator");
    const PARALLEL: &str = r#"{"projection": "parallel", "rotate_deg": [25, 35, 0]}"#;
    for (name, mode, view, more) in [
        (
            "composite",
            "composite",
            PARALLEL,
            r#""cube3": {"gradient": 12}"#,
        ),
        (
            "first_opaque",
            "first_opaque",
            PARALLEL,
            r#""cube3": {"gradient": 6}, "transfer": {"opacity": [[0, 0.0], [60, 0.0], [200, 1.0], [255, 1.0]],
                "color": [[0, 1.0, 1.0, 1.0], [255, 0.8, 0.5, 0.3]], "gradient_opacity": [[0, 0.3], [40, 1.0]]}"#,
        ),
        (
            "perspective_composite",
            "composite",
            r#"{"projection": "perspective", "eye": [-12, -5, -12], "target": [4.5, 4, 3.5], "fov_deg": 60}"#,
            r#""cube3": {"gradient": 12}"#,
        ),
    ] {
        let s = scene(&format!(
            r#"{{"volume": {{"builtin": "phantom", "dims": [10, 9, 8]}},
            "view": {view},
            "mode": "{mode}", "image": [32, 32], "hardware": {{"pipelines": 2}}, {more}}}"#
        ));
        let vol = Volume::from_spec(&s.volume, s.hardware.voxel_bits).unwrap();
        let cam = s.camera();
        let (rust_vcd, verilator_vcd) = (
            dir().join(format!("{name}_rust.vcd")),
            dir().join(format!("{name}_verilator.fst")),
        );
        let rust = simulate(&s, &cam, &vol, Engine::RustHdl, Some(&rust_vcd)).unwrap();
        let verilator = simulate(&s, &cam, &vol, Engine::Verilator, Some(&verilator_vcd)).unwrap();
        for (engine, r) in [("rust-hdl", &rust), ("Verilator", &verilator)] {
            assert_eq!(r.mismatches, 0, "{name}: {engine}: {:?}", r.first);
        }
        let planes = if view == PARALLEL { 1 } else { 3 };
        assert_eq!(rust.bases.len(), planes, "{name}: base planes");
        assert_eq!(
            verilator.clocks, rust.clocks,
            "{name}: the same clock count"
        );
        let cmp = compare(
            &Trace::load(&rust_vcd).unwrap(),
            &Trace::load(&verilator_vcd).unwrap(),
            None,
        )
        .unwrap();
        assert!(
            cmp.compared > 500,
            "{name}: {} signals compared",
            cmp.compared
        );
        // Each base plane is a simulation of its own (the volume loaded in
        // its order); the traces hold them all, one after another.
        assert!(
            cmp.cycles_a >= rust.clocks && cmp.cycles_b >= verilator.clocks,
            "{name}: traces of {} and {} cycles for {} clocks of base planes",
            cmp.cycles_a,
            cmp.cycles_b,
            rust.clocks
        );
        assert!(
            cmp.equal(),
            "{name}: rust-hdl and Verilator traces differ: {:?}",
            cmp.mismatches.first()
        );
    }
}
