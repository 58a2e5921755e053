//! The `cube` command-line contract: outputs, JSON fields, and a clear
//! one-line error (never a panic) for every kind of bad input.

use std::path::Path;
use std::process::{Command, Output};

fn cube(args: &[&str], dir: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_cube"))
        .args(args)
        .current_dir(dir)
        .output()
        .expect("run cube")
}

fn write(dir: &Path, name: &str, text: &str) -> String {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p.display().to_string()
}

fn read_json(path: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

const SPHERE: &str = r#"{"volume": {"builtin": "sphere", "dims": [16,16,16]}, "view": {"projection": "parallel", "rotate_deg": [70, 30, 0]}, "image": [48, 40]}"#;

#[test]
fn render_writes_png_and_json_with_error() {
    let d = tempfile::tempdir().unwrap();
    let scene = write(d.path(), "s.json", SPHERE);
    let o = cube(
        &[
            "render",
            "--scene",
            &scene,
            "--arch",
            "cube4l",
            "--out",
            "img/a.png",
            "--json",
            "a.json",
            "--diff",
            "d.png",
        ],
        d.path(),
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let j: serde_json::Value = read_json(&d.path().join("a.json"));
    assert_eq!(j["arch"], "cube4l");
    assert_eq!(j["image"], serde_json::json!([48, 40]));
    assert!(j["seconds"].as_f64().unwrap() > 0.0);
    for k in ["rel_euclid_pct", "rmse", "psnr_db", "max_abs"] {
        assert!(j["error"][k].is_number(), "error.{k} missing: {j}");
    }
    let img = image::open(d.path().join("img/a.png")).unwrap();
    assert_eq!((img.width(), img.height()), (48, 40));
    assert!(d.path().join("d.png").exists());
    let stray: Vec<_> = std::fs::read_dir(d.path())
        .unwrap()
        .filter_map(|e| {
            let n = e.unwrap().file_name().to_string_lossy().to_string();
            n.contains(".tmp").then_some(n)
        })
        .collect();
    assert!(stray.is_empty(), "temporary files left: {stray:?}");
}

#[test]
fn reference_arch_and_scenes_listing() {
    let d = tempfile::tempdir().unwrap();
    let scene = write(d.path(), "s.json", SPHERE);
    let o = cube(
        &[
            "render",
            "--scene",
            &scene,
            "--arch",
            "reference",
            "--json",
            "r.json",
        ],
        d.path(),
    );
    assert!(o.status.success());
    let j: serde_json::Value = read_json(&d.path().join("r.json"));
    assert_eq!(j["arch"], "reference");
    let o = cube(&["scenes"], d.path());
    let text = String::from_utf8_lossy(&o.stdout);
    for b in [
        "sphere",
        "phantom",
        "checkerboard",
        "ramp",
        "impulse",
        "empty",
    ] {
        assert!(text.contains(b), "{b} not listed");
    }
}

#[test]
fn default_run_writes_renders() {
    let d = tempfile::tempdir().unwrap();
    let o = cube(&[], d.path());
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(text.contains("rel. Euclidean"), "{text}");
    for f in [
        "default_cube4l.png",
        "default_reference.png",
        "default_diff.png",
    ] {
        assert!(d.path().join("out").join(f).exists(), "{f}");
    }
}

fn assert_clean_error(o: &Output, needle: &str) {
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(!o.status.success(), "expected failure for {needle}");
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(!err.contains("panicked"), "{err}");
    assert_eq!(
        err.trim_end().lines().count(),
        1,
        "one line expected: {err}"
    );
    assert!(err.contains(needle), "'{needle}' not in: {err}");
}

#[test]
fn bad_inputs_give_one_line_errors() {
    let d = tempfile::tempdir().unwrap();
    let p = d.path();
    std::fs::write(p.join("short.raw"), [0u8; 100]).unwrap();
    let cases: Vec<(String, &str)> = vec![
        (SPHERE.replace("[16,16,16]", "[0,16,16]"), "out of range"),
        (
            SPHERE.replace("[16,16,16]", "[99999,16,16]"),
            "out of range",
        ),
        (
            SPHERE.replace(
                "\"builtin\": \"sphere\"",
                "\"raw\": \"missing.raw\", \"type\": \"u8\"",
            ),
            "missing.raw",
        ),
        (
            SPHERE.replace(
                "\"builtin\": \"sphere\"",
                "\"raw\": \"short.raw\", \"type\": \"u8\"",
            ),
            "need 4096",
        ),
        (
            SPHERE.replace(
                "\"builtin\": \"sphere\"",
                "\"raw\": \"short.raw\", \"type\": \"f32\"",
            ),
            "unknown variant",
        ),
        (
            SPHERE.replace(
                "\"rotate_deg\": [70, 30, 0]",
                "\"rotate_deg\": [70, 30, 0], \"spin\": 1",
            ),
            "unknown field",
        ),
        (
            SPHERE.replace("}, \"image\"", "}, \"mode\": \"dvr\", \"image\""),
            "unknown variant",
        ),
        (
            SPHERE.replace(
                "\"projection\": \"parallel\", \"rotate_deg\": [70, 30, 0]",
                "\"projection\": \"perspective\", \"eye\": [0, 0, 0], \"target\": [0, 0, 0]",
            ),
            "coincide",
        ),
        (
            SPHERE.replace(
                "\"projection\": \"parallel\", \"rotate_deg\": [70, 30, 0]",
                "\"projection\": \"perspective\", \"eye\": [1, 2, -30], \"up\": [0, 0, 0]",
            ),
            "zero length",
        ),
        (
            SPHERE.replace(
                "\"image\": [48, 40]",
                "\"image\": [48, 40], \"hardware\": {\"voxel_bits\": 10}",
            ),
            "voxel_bits",
        ),
        (
            SPHERE.replace(
                "\"image\": [48, 40]",
                "\"image\": [48, 40], \"hardware\": {\"frac_bits\": 16}",
            ),
            "frac_bits",
        ),
        (
            SPHERE.replace("\"image\": [48, 40]", "\"image\": [0, 40]"),
            "image",
        ),
        ("{not json".to_string(), "scene"),
    ];
    for (i, (text, needle)) in cases.iter().enumerate() {
        let scene = write(p, &format!("bad{i}.json"), text);
        let o = cube(&["render", "--scene", &scene, "--out", "x.png"], p);
        assert_clean_error(&o, needle);
        assert!(!p.join("x.png").exists(), "no output on error");
    }
    let o = cube(&["render", "--scene", "nowhere.json"], p);
    assert_clean_error(&o, "nowhere.json");
    let scene = write(p, "ok.json", SPHERE);
    let o = cube(
        &[
            "render",
            "--scene",
            &scene,
            "--ref-step",
            "0",
            "--compare-reference",
        ],
        p,
    );
    assert_clean_error(&o, "ref-step");
}

#[test]
fn angles_reports_error_per_angle() {
    let d = tempfile::tempdir().unwrap();
    let scene = write(d.path(), "s.json", SPHERE);
    let o = cube(
        &[
            "angles", "--scene", &scene, "--range", "0", "90", "45", "--json", "a.json",
        ],
        d.path(),
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let j: serde_json::Value = read_json(&d.path().join("a.json"));
    assert_eq!(j["rows"].as_array().unwrap().len(), 3);
}

#[test]
fn sim_matches_golden_and_reports_clocks() {
    let d = tempfile::tempdir().unwrap();
    let scene = write(
        d.path(),
        "s.json",
        r#"{"volume": {"builtin": "sphere", "dims": [12, 12, 12]}, "view": {"projection": "parallel", "rotate_deg": [20, 30, 0]},
            "mode": "mip", "image": [48, 48], "hardware": {"pipelines": 2}}"#,
    );
    let o = cube(
        &[
            "sim", "--scene", &scene, "--out", "sim.png", "--json", "sim.json",
        ],
        d.path(),
    );
    assert!(
        o.status.success(),
        "{}{}",
        String::from_utf8_lossy(&o.stdout),
        String::from_utf8_lossy(&o.stderr)
    );
    let j = read_json(&d.path().join("sim.json"));
    assert_eq!(j["engine"], "rust-hdl");
    assert_eq!(j["mismatches"], 0);
    for k in ["cycles", "ideal_cycles", "seconds", "cycles_per_second"] {
        assert!(j[k].is_number(), "{k} missing: {j}");
    }
    assert_eq!(j["ideal_cycles"], 12 * 12 * 6);
    assert!(d.path().join("sim.png").exists());
}

#[test]
fn sim_shaded_scene_matches() {
    let d = tempfile::tempdir().unwrap();
    let scene = write(
        d.path(),
        "s.json",
        r#"{"volume": {"builtin": "phantom", "dims": [12, 12, 10]}, "view": {"projection": "parallel", "rotate_deg": [70, 30, 0]},
            "image": [48, 48], "hardware": {"pipelines": 4}}"#,
    );
    let o = cube(&["sim", "--scene", &scene, "--json", "sim.json"], d.path());
    assert!(
        o.status.success(),
        "{}{}",
        String::from_utf8_lossy(&o.stdout),
        String::from_utf8_lossy(&o.stderr)
    );
    assert_eq!(read_json(&d.path().join("sim.json"))["mismatches"], 0);
}

#[test]
fn sim_refuses_what_the_rtl_cannot_do() {
    let d = tempfile::tempdir().unwrap();
    let xray = write(
        d.path(),
        "a.json",
        r#"{"volume": {"builtin": "sphere", "dims": [32, 12, 12]}, "view": {"projection": "parallel"}, "mode": "xray", "image": [16, 16],
            "hardware": {"pipelines": 16}}"#,
    );
    assert_clean_error(
        &cube(&["sim", "--scene", &xray], d.path()),
        "1, 2, 4 or 8 pipelines",
    );
    let big = write(
        d.path(),
        "b.json",
        r#"{"volume": {"builtin": "sphere", "dims": [256, 256, 256]}, "view": {"projection": "parallel"}, "mode": "mip"}"#,
    );
    assert_clean_error(
        &cube(&["sim", "--scene", &big], d.path()),
        "Verilog engines",
    );
}
