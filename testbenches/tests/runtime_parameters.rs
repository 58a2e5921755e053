//! One build renders many scenes, on Cube-4L and on Cube-3: the view, the
//! transfer function and the light are registers and tables the host loads
//! between frames, never constants of the Verilog. Two scenes of one
//! configuration that differ in view, table and light emit byte-identical
//! Verilog, and one Verilator build renders a sequence of such frames bit
//! for bit against the golden model, each frame after only the host writes
//! that changed.

use cosim::arch::Arch;
use cosim::cube3::Cube3;
use cosim::cube4l::Cube4l;
use cosim::export::{write_export, ExportScene};
use cosim::sim::simulate_frames;
use cosim::Engine;
use scene::volume::builtin;
use scene::{Camera, Scene};
use testbenches::{require_tool, scene};

/// A parallel shaded scene of the sphere with `view`, table and light.
fn parallel(view: &str, transfer_and_light: &str) -> Scene {
    scene(&format!(
        r#"{{"volume": {{"builtin": "sphere", "dims": [12, 12, 10]}}, "view": {{"projection": "parallel", "rotate_deg": {view}}},
            "mode": "composite", {transfer_and_light}, "image": [32, 32], "hardware": {{"pipelines": 2}}}}"#
    ))
}

/// A perspective shaded scene of the phantom seen from `eye`.
fn perspective(eye: &str, transfer_and_light: &str) -> Scene {
    scene(&format!(
        r#"{{"volume": {{"builtin": "phantom", "dims": [10, 12, 11]}}, "view": {{"projection": "perspective", "eye": {eye}, "target": [6, 5, 11], "fov_deg": 120}},
            "mode": "composite", {transfer_and_light}, "image": [16, 16], "hardware": {{"pipelines": 2}}}}"#
    ))
}

const LIGHT_A: &str = r#""shading": {"enabled": true, "specular": 0.6}"#;
const LIGHT_B: &str = r#""transfer": {"opacity": [[0, 0], [100, 0.5], [255, 1.0]], "color": [[0, 1, 0, 0], [255, 0, 0, 1]]},
    "shading": {"enabled": true, "specular": 0.2, "light_dir": [-1, 0.5, 1]}"#;

fn with_cameras(scenes: Vec<Scene>) -> Vec<(Scene, Camera)> {
    scenes
        .into_iter()
        .map(|s| {
            let c = s.camera();
            (s, c)
        })
        .collect()
}

/// A parallel shaded Cube-3 scene of the phantom with `view`, table and
/// light, and a perspective one from `eye`.
fn cube3_parallel(view: &str, transfer_and_light: &str) -> Scene {
    scene(&format!(
        r#"{{"volume": {{"builtin": "phantom", "dims": [12, 10, 11]}}, "view": {{"projection": "parallel", "rotate_deg": {view}}},
            "mode": "composite", {transfer_and_light}, "image": [24, 24], "hardware": {{"pipelines": 2}}}}"#
    ))
}

fn cube3_perspective(eye: &str, transfer_and_light: &str) -> Scene {
    scene(&format!(
        r#"{{"volume": {{"builtin": "sphere", "dims": [9, 11, 10]}}, "view": {{"projection": "perspective", "eye": {eye}, "target": [4, 5, 4.5], "fov_deg": 60}},
            "mode": "composite", {transfer_and_light}, "image": [16, 16], "hardware": {{"pipelines": 2}}}}"#
    ))
}

/// The Verilog files (name, text) of an export of `s` on the build it needs.
fn exported<A: Arch>(s: &Scene, dir: &std::path::Path) -> (String, Vec<(String, String)>) {
    let camera = s.camera();
    let dims = s.volume.render_dims();
    let build = A::needs(s, &camera, dims).unwrap();
    let es = ExportScene {
        name: "scene.json",
        scene: s,
        camera: &camera,
        dims,
    };
    write_export::<A>(dir, &build, Some(&es)).unwrap();
    let mut files: Vec<(String, String)> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "v"))
        .map(|p| {
            let name = p.file_name().unwrap().to_string_lossy().to_string();
            (name, std::fs::read_to_string(&p).unwrap())
        })
        .collect();
    files.sort();
    (A::config_name(&build), files)
}

#[test]
fn scenes_of_one_configuration_emit_identical_verilog() {
    identical::<Cube4l>([
        (
            parallel("[70, 30, 0]", LIGHT_A),
            parallel("[-20, 135, 10]", LIGHT_B),
        ),
        (
            perspective("[5.3, 6.6, 4.2]", LIGHT_A),
            perspective("[8.5, 2.0, 14.0]", LIGHT_B),
        ),
    ]);
    identical::<Cube3>([
        (
            cube3_parallel("[25, 35, 0]", LIGHT_A),
            cube3_parallel("[-40, 160, 20]", LIGHT_B),
        ),
        (
            cube3_perspective("[-14, -6, -14]", LIGHT_A),
            cube3_perspective("[4, 18, -9]", LIGHT_B),
        ),
    ]);
}

fn identical<A: Arch>(pairs: [(Scene, Scene); 2]) {
    for (a, b) in pairs {
        let tmp = tempfile::tempdir().unwrap();
        let (name_a, va) = exported::<A>(&a, &tmp.path().join("a"));
        let (name_b, vb) = exported::<A>(&b, &tmp.path().join("b"));
        assert_eq!(name_a, name_b, "both scenes need one configuration");
        assert!(va.len() >= 5, "{name_a}: {} Verilog files", va.len());
        assert_eq!(
            va.iter().map(|f| &f.0).collect::<Vec<_>>(),
            vb.iter().map(|f| &f.0).collect::<Vec<_>>()
        );
        for ((file, x), (_, y)) in va.iter().zip(&vb) {
            if x != y {
                let line = x.lines().zip(y.lines()).position(|(p, q)| p != q);
                panic!("{name_a}: {file} differs between two views at line {line:?}");
            }
        }
    }
}

/// Three frames on one Verilator build: a view, a new view, then a new
/// table and light; every frame bit for bit, the later ones after only the
/// words that changed.
fn frames_on_one_build<A: Arch>(frames: Vec<Scene>, vol: &scene::volume::Volume) -> String {
    let frames = with_cameras(frames);
    let r = simulate_frames::<A>(&frames, None, vol, Engine::Verilator, None, &|v| {
        v.to_string()
    })
    .unwrap();
    let name = A::config_name(&r.config);
    assert_eq!(r.frames.len(), 3);
    for (i, f) in r.frames.iter().enumerate() {
        assert_eq!(
            f.mismatches,
            0,
            "{name} frame {}: first differences {:?}",
            i + 1,
            f.first
        );
        assert!(
            f.clocks > 0 && f.reload_clocks > 0,
            "{name} frame {}",
            i + 1
        );
    }
    // The first frame loads every table and register; a new view rewrites
    // registers only, fewer words than the tables.
    let reload: Vec<u64> = r.frames.iter().map(|f| f.reload_clocks).collect();
    assert!(reload[1] < reload[0], "{name}: reloads {reload:?}");
    assert!(reload[2] < reload[0], "{name}: reloads {reload:?}");
    name
}

#[test]
fn one_parallel_build_renders_new_views_tables_and_lights() {
    require_tool("verilator");
    let vol = builtin("sphere", [12, 12, 10], 8).unwrap();
    frames_on_one_build::<Cube4l>(
        vec![
            parallel("[70, 30, 0]", LIGHT_A),
            parallel("[-20, 135, 10]", LIGHT_A),
            parallel("[-20, 135, 10]", LIGHT_B),
        ],
        &vol,
    );
}

#[test]
fn one_perspective_build_renders_new_eyes_tables_and_lights() {
    require_tool("verilator");
    let vol = builtin("phantom", [10, 12, 11], 8).unwrap();
    frames_on_one_build::<Cube4l>(
        vec![
            perspective("[5.3, 6.6, 4.2]", LIGHT_A),
            perspective("[8.5, 2.0, 14.0]", LIGHT_A),
            perspective("[8.5, 2.0, 14.0]", LIGHT_B),
        ],
        &vol,
    );
}

#[test]
fn one_cube3_build_renders_new_views_tables_and_lights() {
    require_tool("verilator");
    let vol = builtin("phantom", [12, 10, 11], 8).unwrap();
    frames_on_one_build::<Cube3>(
        vec![
            // (Views of one traversal order: one volume load.)
            cube3_parallel("[25, 35, 0]", LIGHT_A),
            cube3_parallel("[35, 20, 0]", LIGHT_A),
            cube3_parallel("[35, 20, 0]", LIGHT_B),
        ],
        &vol,
    );
}

#[test]
fn one_cube3_perspective_build_renders_new_eyes_tables_and_lights() {
    require_tool("verilator");
    let vol = builtin("sphere", [9, 11, 10], 8).unwrap();
    frames_on_one_build::<Cube3>(
        vec![
            cube3_perspective("[-14, -6, -14]", LIGHT_A),
            cube3_perspective("[4, 18, -9]", LIGHT_A),
            cube3_perspective("[4, 18, -9]", LIGHT_B),
        ],
        &vol,
    );
}

/// The widths at the accuracy knee (docs/accuracy.md: 12-bit weights and
/// 6-bit normals) are a build like any other: on each architecture one
/// `_f12_q6` build renders new views, tables and lights bit for bit.
#[test]
fn the_knee_widths_build_on_both_architectures() {
    require_tool("verilator");
    let knee = |arch_volume: &str, view: &str, light: &str| {
        scene(&format!(
            r#"{{"volume": {arch_volume}, "view": {{"projection": "parallel", "rotate_deg": {view}}},
                "mode": "composite", {light}, "image": [24, 24],
                "hardware": {{"pipelines": 2, "frac_bits": 12, "normal_bits": 6}}}}"#
        ))
    };
    let sphere = r#"{"builtin": "sphere", "dims": [12, 12, 10]}"#;
    let built = frames_on_one_build::<Cube4l>(
        vec![
            knee(sphere, "[70, 30, 0]", LIGHT_A),
            knee(sphere, "[-20, 135, 10]", LIGHT_A),
            knee(sphere, "[-20, 135, 10]", LIGHT_B),
        ],
        &builtin("sphere", [12, 12, 10], 8).unwrap(),
    );
    assert!(built.ends_with("_f12_q6"), "{built}");
    let phantom = r#"{"builtin": "phantom", "dims": [12, 10, 11]}"#;
    let built = frames_on_one_build::<Cube3>(
        vec![
            knee(phantom, "[25, 35, 0]", LIGHT_A),
            knee(phantom, "[35, 20, 0]", LIGHT_A),
            knee(phantom, "[35, 20, 0]", LIGHT_B),
        ],
        &builtin("phantom", [12, 10, 11], 8).unwrap(),
    );
    assert!(built.ends_with("_f12_q6"), "{built}");
}
