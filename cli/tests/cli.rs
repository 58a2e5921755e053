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

/// `cube render --repeat 3` of `arch` on `scene` with `extra` arguments,
/// writing `{arch}.png` and `{arch}.json` in `dir`: its JSON report.
fn render_three_times(dir: &Path, scene: &str, arch: &str, extra: &[&str]) -> serde_json::Value {
    let json = dir.join(format!("{arch}.json"));
    let png = dir.join(format!("{arch}.png"));
    let mut args = vec!["render", "--scene", scene, "--arch", arch, "--repeat", "3"];
    args.extend(extra);
    args.extend([
        "--out",
        png.to_str().unwrap(),
        "--json",
        json.to_str().unwrap(),
    ]);
    let o = cube(&args, dir);
    assert!(
        o.status.success(),
        "{arch}: {}",
        String::from_utf8_lossy(&o.stderr)
    );
    read_json(&json)
}

const SPHERE: &str = r#"{"volume": {"builtin": "sphere", "dims": [16,16,16]}, "view": {"projection": "parallel", "rotate_deg": [70, 30, 0]}, "image": [48, 40]}"#;

/// The golden models copy the volume into a view's traversal order once
/// and keep it: its time is the volume's preparation, null where the view
/// reads the volume as it is (Cube-3: a z-major view; Cube-4L: any but a
/// y-major one, whose rows run across the dataset's slices).
#[test]
fn golden_models_prepare_a_volume_once_for_its_order() {
    let d = tempfile::tempdir().unwrap();
    for (rot, copies) in [
        ("[0, 0, 0]", [false, false]),
        ("[90, 0, 0]", [true, true]),
        ("[0, 90, 0]", [false, true]),
    ] {
        let scene = write(d.path(), "s.json", &SPHERE.replace("[70, 30, 0]", rot));
        for (arch, copied) in ["cube4l", "cube3"].into_iter().zip(copies) {
            let det = &render_three_times(d.path(), &scene, arch, &[])["details"];
            let prep = det["volume_prep_seconds"].as_f64();
            assert_eq!(prep.is_some(), copied, "{arch} {rot}: {det}");
            assert!(prep.unwrap_or(1.0) > 0.0, "{arch} {rot}: {det}");
            assert!(
                det["frame_seconds"].as_f64().unwrap() > 0.0,
                "{arch} {rot}: {det}"
            );
        }
    }
}

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
    // One line per method, and the yardstick named.
    for s in [
        "float reference",
        "Cube-4L golden model",
        "Cube-3 golden model",
        "rel. Euclidean",
        "the yardstick is the float reference",
    ] {
        assert!(text.contains(s), "'{s}' not in: {text}");
    }
    let out = d.path().join("out");
    for f in [
        "default_reference.png",
        "default_cube4l.png",
        "default_cube3.png",
    ] {
        let (w, h) = image::image_dimensions(out.join(f)).unwrap();
        assert_eq!((w, h), (256, 256), "{f}");
    }
    // The overview: three 256² renders side by side (with margins and
    // gaps of 20), over two rows with their labels and a colour bar.
    let (w, h) = image::image_dimensions(out.join("default.png")).unwrap();
    assert_eq!((w, h), (848, 804));
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
    assert_eq!(j["against"], "reference");
    let e = &j["rows"][0]["error"];
    for reading in [
        "rel_euclid_pct",
        "rel_euclid_all_pct",
        "rel_euclid_to_ref_pct",
    ] {
        assert!(e[reading].as_f64().unwrap() > 0.0, "{reading}: {e}");
    }
    // The fixed-point model against its float twin: its rounding alone,
    // and each row against True3D as well.
    let o = cube(
        &[
            "angles",
            "--scene",
            &scene,
            "--range",
            "0",
            "45",
            "45",
            "--arch",
            "cube3",
            "--against",
            "sheared-float",
            "--json",
            "q.json",
        ],
        d.path(),
    );
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(
        out.contains("error of cube3 against sheared-float"),
        "{out}"
    );
    let q: serde_json::Value = read_json(&d.path().join("q.json"));
    assert_eq!(q["against"], "sheared-float");
    assert!(q["rows"][1]["error_vs_true3d"]["rel_euclid_pct"].is_f64());
    assert!(q["rows"][1]["true3d_error"].is_null());
    let o = cube(
        &[
            "angles",
            "--scene",
            &scene,
            "--arch",
            "cube3",
            "--against",
            "cube3",
        ],
        d.path(),
    );
    assert!(String::from_utf8_lossy(&o.stderr).contains("would compare cube3 with itself"));
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
        "--engine verilator",
    );
    // The normal's width is a build parameter: a 6-bit normal builds its
    // own configuration (`_q6`), which a 5-bit build refuses, naming the
    // field; unlit, the normal's width does not matter.
    let lit = r#"{"volume": {"builtin": "sphere", "dims": [12, 12, 12]}, "view": {"projection": "parallel"}, "mode": "composite", "image": [16, 16],
            "hardware": {"normal_bits": 6, "pipelines": 2}"#;
    let wide = write(d.path(), "c.json", &format!("{lit}}}"));
    for (arch, build, five) in [
        (
            "cube4l",
            "composite_shaded_p2_12_q6",
            "composite_shaded_p2_12",
        ),
        (
            "cube3",
            "composite_shaded_n12_p2_12_q6",
            "composite_shaded_n12_p2_12",
        ),
    ] {
        let out = format!("v_{arch}");
        let o = cube(
            &["verilog", "--arch", arch, "--scene", &wide, "--out", &out],
            d.path(),
        );
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let m = read_json(&d.path().join(&out).join("manifest.json"));
        assert_eq!(m["configuration"], build, "{m}");
        assert_clean_error(
            &cube(
                &[
                    "verilog", "--arch", arch, "--config", five, "--scene", &wide, "--out", "w",
                ],
                d.path(),
            ),
            "the scene's normal_bits is 6, the configuration's 5",
        );
        assert_clean_error(
            &cube(
                &[
                    "verilog",
                    "--arch",
                    arch,
                    "--config",
                    &format!("{}_q6", five.replace("composite_shaded", "mip")),
                    "--out",
                    "w",
                ],
                d.path(),
            ),
            "6-bit normals without shading",
        );
    }
    let unlit = write(
        d.path(),
        "d.json",
        &format!("{lit}, \"shading\": {{\"enabled\": false}}}}"),
    );
    let o = cube(&["verilog", "--scene", &unlit, "--out", "v"], d.path());
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
}

#[test]
fn verilog_writes_stage_files_lint_waivers_and_manifest() {
    let d = tempfile::tempdir().unwrap();
    let mip = write(
        d.path(),
        "mip.json",
        r#"{"volume": {"builtin": "sphere", "dims": [16, 16, 16]}, "view": {"projection": "parallel", "rotate_deg": [20, 30, 0]},
            "mode": "mip", "hardware": {"pipelines": 2}}"#,
    );
    // A previous export's sweep directory, as its manifest records it:
    // replaced whole.
    std::fs::create_dir_all(d.path().join("out/sweep7")).unwrap();
    std::fs::write(d.path().join("out/sweep7/cfb.v"), "// old").unwrap();
    std::fs::write(
        d.path().join("out/manifest.json"),
        format!(
            r#"{{"files_crc32": {{"sweep7/cfb.v": "{:08x}"}}}}"#,
            crc32fast::hash(b"// old")
        ),
    )
    .unwrap();
    let o = cube(&["verilog", "--scene", &mip, "--out", "out"], d.path());
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let out = d.path().join("out");
    assert!(
        !out.join("sweep7").exists(),
        "the old export is replaced whole"
    );
    for f in [
        "top.v",
        "cfb.v",
        "shader.v",
        "compositor.v",
        "bilinear.v",
        "lint.vlt",
        "manifest.json",
    ] {
        assert!(out.join(f).exists(), "{f} missing");
    }
    let top = std::fs::read_to_string(out.join("top.v")).unwrap();
    assert!(top.starts_with("module top("));
    let m = read_json(&out.join("manifest.json"));
    assert_eq!(m["parameters"]["pipelines"], 2);
    assert_eq!(m["parameters"]["memory"]["kind"], "on-chip");
    assert_eq!(m["scene"]["name"], "mip.json");
    assert_eq!(m["configuration"], "mip_p2_16");
    let left: Vec<&str> = m["units_left_out"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_str().unwrap())
        .collect();
    assert!(
        left.contains(&"abc_gradient") && left.contains(&"sight_ray_divider"),
        "{left:?}"
    );
    assert_eq!(m["scene"]["sweeps"].as_array().unwrap().len(), 1);
    assert_eq!(m["designs"].as_array().unwrap().len(), 1);
    let bad = write(
        d.path(),
        "bad.json",
        r#"{"volume": {"builtin": "sphere", "dims": [16,16,16]}, "view": {"projection": "parallel"}, "hardware": {"pipelines": 16}}"#,
    );
    assert_clean_error(
        &cube(&["verilog", "--scene", &bad, "--out", "out2"], d.path()),
        "1, 2, 4 or 8 pipelines",
    );
    assert!(
        !d.path().join("out2").exists(),
        "nothing is written on error"
    );
}

/// `--config` builds a configuration by name and refuses, naming why, a
/// scene it cannot render; `sim` renders several scenes as frames of one
/// build, each checked, each after the host writes that changed.
#[test]
fn configurations_by_name_and_frames_in_sequence() {
    let d = tempfile::tempdir().unwrap();
    let scene = |view: &str, mode: &str| {
        format!(
            r#"{{"volume": {{"builtin": "sphere", "dims": [12, 12, 10]}}, "view": {{"projection": "parallel", "rotate_deg": {view}}},
                "mode": "{mode}", "image": [16, 16], "hardware": {{"pipelines": 2}}}}"#
        )
    };
    let a = write(d.path(), "a.json", &scene("[70, 30, 0]", "mip"));
    let b = write(d.path(), "b.json", &scene("[-20, 135, 10]", "minip"));
    let c = write(d.path(), "c.json", &scene("[-20, 135, 10]", "composite"));
    let o = cube(
        &["verilog", "--config", "mip_p2_16", "--out", "v"],
        d.path(),
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(String::from_utf8_lossy(&o.stdout).contains("configuration mip_p2_16"));
    let m = read_json(&d.path().join("v/manifest.json"));
    assert_eq!(m["configuration"], "mip_p2_16");
    assert!(m.get("scene").is_none(), "{m}");
    assert_clean_error(
        &cube(
            &[
                "verilog",
                "--config",
                "mip_p2_16",
                "--scene",
                &c,
                "--out",
                "w",
            ],
            d.path(),
        ),
        "the scene's mode needs the composite hardware",
    );
    assert_clean_error(
        &cube(
            &[
                "verilog", "--config", "mip_p2_8", "--scene", &a, "--out", "w",
            ],
            d.path(),
        ),
        "mip_p2_8 cannot render",
    );
    assert_clean_error(
        &cube(
            &["verilog", "--config", "mip_q2_16", "--out", "w"],
            d.path(),
        ),
        "mip_q2_16",
    );
    assert!(!d.path().join("w").exists(), "nothing is written on error");
    // MIP then MinIP, a new view: one build, the Order register rewritten.
    let o = cube(
        &[
            "sim", "--scene", &a, "--scene", &b, "--json", "f.json", "--out", "f.png",
        ],
        d.path(),
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let j = read_json(&d.path().join("f.json"));
    assert_eq!(j["memory_loads"], 1, "{j}");
    assert_eq!(j["configuration"], "mip_p2_12");
    let frames = j["frames"].as_array().unwrap();
    assert_eq!(frames.len(), 2);
    for f in frames {
        assert_eq!(f["mismatches"], 0, "{f}");
        assert!(f["reload_clocks"].as_u64().unwrap() > 0, "{f}");
    }
    assert!(d.path().join("f-1.png").exists() && d.path().join("f-2.png").exists());
    assert_clean_error(
        &cube(&["sim", "--scene", &a, "--scene", &c], d.path()),
        "frame 2 needs configuration composite",
    );
}

/// A VCD with a top scope `top_scope` (nested under `wrapper` if given), a
/// clock of half-period `half`, and a 4-bit `count` that counts clocks
/// except that it holds `glitch` at cycle 3 when given.
fn counter_vcd(
    wrapper: Option<&str>,
    top_scope: &str,
    timescale: &str,
    half: u64,
    glitch: Option<u32>,
) -> String {
    let mut v = format!("$timescale {timescale} $end\n");
    if let Some(w) = wrapper {
        v.push_str(&format!("$scope module {w} $end\n"));
    }
    v.push_str(&format!(
        "$scope module {top_scope} $end\n$var wire 1 ! clock $end\n$var wire 4 \" count [3:0] $end\n$upscope $end\n"
    ));
    if wrapper.is_some() {
        v.push_str("$upscope $end\n");
    }
    v.push_str("$enddefinitions $end\n#0\n0!\nb0 \"\n");
    for cycle in 0..8u32 {
        let t = half + 2 * half * cycle as u64;
        let value = match glitch {
            Some(g) if cycle == 3 => g,
            _ => cycle + 1,
        };
        // A repeated timestamp: the value change is written separately.
        v.push_str(&format!(
            "#{t}\n1!\n#{t}\nb{value:b} \"\n#{}\n0!\n",
            t + half
        ));
    }
    v
}

#[test]
fn vcd_diff_aligns_names_and_cycles_and_exits_0_1_2() {
    let d = tempfile::tempdir().unwrap();
    let a = write(d.path(), "a.vcd", &counter_vcd(None, "uut", "1ns", 5, None));
    let b = write(
        d.path(),
        "b.vcd",
        &counter_vcd(Some("TOP"), "top", "1ps", 500, None),
    );
    let c = write(
        d.path(),
        "c.vcd",
        &counter_vcd(Some("TOP"), "top", "1ps", 500, Some(9)),
    );
    let o = cube(&["vcd-diff", &a, &b], d.path());
    let text = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{text}");
    assert!(text.contains("2 signals compared over 8 cycles"), "{text}");
    let o = cube(&["vcd-diff", &a, &c], d.path());
    let text = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(1), "{text}");
    assert!(text.contains("cycle 3: count: A 0x4 B 0x9"), "{text}");
    let o = cube(&["vcd-diff", &a, &c, "--signals", "clock"], d.path());
    assert_eq!(o.status.code(), Some(0), "only the clock compared");
    let junk = write(
        d.path(),
        "junk.vcd",
        "$scope module x $end\n$var wire 1 ! y $end\n$upscope $end\n$enddefinitions $end\n#0\n1!\n",
    );
    for bad in [&junk, "missing.vcd"] {
        let o = cube(&["vcd-diff", &a, bad], d.path());
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{err}");
        assert!(
            err.starts_with("cube: vcd-diff:") && !err.contains("panicked"),
            "{err}"
        );
    }
}

#[test]
fn cube3_and_true3d_render_every_mode_with_json() {
    let d = tempfile::tempdir().unwrap();
    for mode in ["composite", "mip", "minip", "xray", "first_opaque"] {
        let text = SPHERE.replace(r#""image""#, &format!(r#""mode": "{mode}", "image""#));
        let scene = write(d.path(), "s.json", &text);
        for (arch, extra) in [
            ("cube3", ["--gradient", "6"]),
            ("true3d", ["--gradient", "26"]),
        ] {
            let json = d.path().join(format!("{arch}_{mode}.json"));
            let o = cube(
                &[
                    "render",
                    "--scene",
                    &scene,
                    "--arch",
                    arch,
                    extra[0],
                    extra[1],
                    "--compare-reference",
                    "--json",
                    json.to_str().unwrap(),
                ],
                d.path(),
            );
            assert!(
                o.status.success(),
                "{arch} {mode}: {}",
                String::from_utf8_lossy(&o.stderr)
            );
            let j = read_json(&json);
            assert_eq!(j["arch"], arch);
            assert!(
                j["error"]["rel_euclid_pct"].as_f64().unwrap() < 10.0,
                "{arch} {mode}: {j}"
            );
            if arch == "cube3" {
                assert_eq!(j["details"]["gradient"], 6);
                assert!(j["details"]["samples"].as_u64().unwrap() > 0);
            }
        }
    }
}

#[test]
fn cube3_bad_input_names_the_field() {
    let d = tempfile::tempdir().unwrap();
    let scene = write(d.path(), "s.json", SPHERE);
    let o = cube(
        &[
            "render",
            "--scene",
            &scene,
            "--arch",
            "cube3",
            "--gradient",
            "7",
        ],
        d.path(),
    );
    let e = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1));
    assert!(
        e.contains("cube3.gradient 7") && e.lines().count() == 1,
        "{e}"
    );
    let o = cube(
        &[
            "render",
            "--scene",
            &scene,
            "--arch",
            "cube4l",
            "--gradient",
            "6",
        ],
        d.path(),
    );
    assert!(String::from_utf8_lossy(&o.stderr).contains("--gradient needs"));
    let bad = SPHERE.replace(r#""image""#, r#""cube3": {"sample_bits": 40}, "image""#);
    let scene = write(d.path(), "b.json", &bad);
    let o = cube(&["render", "--scene", &scene, "--arch", "cube3"], d.path());
    let e = String::from_utf8_lossy(&o.stderr);
    assert!(
        e.contains("cube3.sample_bits 40") && e.lines().count() == 1,
        "{e}"
    );
    let o = cube(
        &[
            "gradients",
            "--scene",
            &write(d.path(), "p.json", &SPHERE.replace("sphere", "phantom")),
        ],
        d.path(),
    );
    let e = String::from_utf8_lossy(&o.stderr);
    assert!(
        e.contains("volume: gradients needs the built-in sphere"),
        "{e}"
    );
}

#[test]
fn committed_fig15_is_current() {
    // docs/cube3/fig15*.{json,png} are `cube gradients` output for two
    // sphere sizes; regenerate with the commands in docs/accuracy.md when
    // this fails.
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).parent().unwrap();
    let d = tempfile::tempdir().unwrap();
    for (scene, stem) in [
        ("scenes/fig15_sphere.json", "fig15"),
        ("scenes/fig15_sphere_128.json", "fig15_128"),
    ] {
        let (j, p) = (d.path().join("f.json"), d.path().join("f.png"));
        let o = cube(
            &[
                "gradients",
                "--scene",
                scene,
                "--json",
                j.to_str().unwrap(),
                "--plot",
                p.to_str().unwrap(),
            ],
            root,
        );
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let got = read_json(&j);
        let want = read_json(&root.join(format!("docs/cube3/{stem}.json")));
        assert_eq!(got, want, "docs/cube3/{stem}.json is stale");
        assert!(
            std::fs::read(&p).unwrap()
                == std::fs::read(root.join(format!("docs/cube3/{stem}.png"))).unwrap(),
            "docs/cube3/{stem}.png is stale"
        );
        std::fs::remove_file(&j).unwrap();
        std::fs::remove_file(&p).unwrap();
    }
}

/// At 90° f64 leaves a slope of about -6e-17 where the fixed-point model
/// has 0; the float twins once dropped the rays on the volume's faces for
/// it (3.9 % on this MIP). Now the fixed-point MIP equals them.
#[test]
fn the_float_twins_keep_the_rays_on_a_face_at_90_degrees() {
    let d = tempfile::tempdir().unwrap();
    let scene = write(
        d.path(),
        "c.json",
        r#"{"volume": {"builtin": "checkerboard", "dims": [16, 16, 16]},
        "view": {"projection": "parallel", "rotate_deg": [70, 90, 0]}, "mode": "mip", "image": [64, 64]}"#,
    );
    let o = cube(
        &[
            "angles",
            "--scene",
            &scene,
            "--arch",
            "cube3",
            "--against",
            "sheared-float",
            "--range",
            "90",
            "90",
            "1",
            "--json",
            "a.json",
        ],
        d.path(),
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let row = &read_json(&d.path().join("a.json"))["rows"][0];
    for key in ["error", "error_vs_true3d"] {
        let e = row[key]["rel_euclid_pct"].as_f64().unwrap();
        assert!(e < 0.01, "{key}: {e} %");
    }
}

/// The width knee (docs/accuracy.md, `scripts/cube3-widths`): Cube-3's
/// rounding alone, the fixed-point model against its float twin on Fig. 14's
/// phantom. At the default widths it is far from 0.5 %; with 12-bit weights
/// and 6-bit normals it is within 0.5 % (relative Euclidean, foreground) at
/// each angle.
#[test]
fn cube3_widths_knee_is_within_half_a_percent_of_the_float_twin() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).parent().unwrap();
    let d = tempfile::tempdir().unwrap();
    let worst = |widths: serde_json::Value| {
        let mut s = read_json(&root.join("scenes/fig14_phantom.json"));
        for (k, v) in widths.as_object().unwrap() {
            s["hardware"][k] = v.clone();
        }
        let scene = write(d.path(), "s.json", &s.to_string());
        let o = cube(
            &[
                "angles",
                "--scene",
                &scene,
                "--arch",
                "cube3",
                "--against",
                "sheared-float",
                "--range",
                "0",
                "90",
                "45",
                "--json",
                "a.json",
            ],
            d.path(),
        );
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let rows = read_json(&d.path().join("a.json"))["rows"].clone();
        let errors: Vec<f64> = rows
            .as_array()
            .unwrap()
            .iter()
            .map(|r| r["error"]["rel_euclid_pct"].as_f64().unwrap())
            .collect();
        assert_eq!(errors.len(), 3);
        errors.into_iter().fold(0.0, f64::max)
    };
    let default = worst(serde_json::json!({}));
    assert!(default > 1.0, "default widths: {default} %");
    let knee = worst(serde_json::json!({"frac_bits": 12, "normal_bits": 6}));
    assert!(knee < 0.5, "12-bit weights, 6-bit normals: {knee} %");
}

#[test]
fn committed_fig14_is_current() {
    // docs/cube3/fig14_phantom.{json,png} are `cube angles` output (the
    // command in docs/accuracy.md); the times in the JSON are the run's own.
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).parent().unwrap();
    let d = tempfile::tempdir().unwrap();
    let (j, p) = (d.path().join("f.json"), d.path().join("f.png"));
    let o = cube(
        &[
            "angles",
            "--scene",
            "scenes/fig14_phantom.json",
            "--arch",
            "sheared-float",
            "--json",
            j.to_str().unwrap(),
            "--plot",
            p.to_str().unwrap(),
        ],
        root,
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let untimed = |mut v: serde_json::Value| {
        for row in v["rows"].as_array_mut().unwrap() {
            row.as_object_mut()
                .unwrap()
                .retain(|k, _| !k.ends_with("seconds"));
        }
        v
    };
    let got = untimed(read_json(&j));
    let want = untimed(read_json(&root.join("docs/cube3/fig14_phantom.json")));
    assert_eq!(got, want, "docs/cube3/fig14_phantom.json is stale");
    assert!(
        std::fs::read(&p).unwrap()
            == std::fs::read(root.join("docs/cube3/fig14_phantom.png")).unwrap(),
        "docs/cube3/fig14_phantom.png is stale"
    );
}

#[test]
fn quantized_paths_report_stages_and_compare_judges_their_images() {
    let d = tempfile::tempdir().unwrap();
    let scene = write(d.path(), "s.json", SPHERE);
    for arch in ["quantized-projection", "quantized-splat"] {
        let png = d.path().join(format!("{arch}.png"));
        let j = render_three_times(d.path(), &scene, arch, &["--compare-reference"]);
        assert_eq!(j["arch"], arch);
        let det = &j["details"];
        for k in [
            "volume_prep_seconds",
            "view_prep_seconds",
            "classify_seconds",
            "render_seconds",
            "frame_seconds",
            "tf_change_seconds",
        ] {
            assert!(det[k].as_f64().unwrap() >= 0.0, "{arch} {k}: {j}");
        }
        assert!(det["voxels_treated"].as_u64().unwrap() > 0, "{j}");
        assert!(det["voxels_inspected"].as_u64() >= det["voxels_treated"].as_u64());
        let e = j["error"]["rel_euclid_pct"].as_f64().unwrap();
        assert!(e < 10.0, "{arch}: {e}");
        // `cube compare` judges the written PNG against the same reference:
        // the error of the 8-bit image is that of the render within the
        // rounding to 8 bits.
        let cj = d.path().join(format!("{arch}_cmp.json"));
        let o = cube(
            &[
                "compare",
                "--scene",
                &scene,
                "--image",
                png.to_str().unwrap(),
                "--json",
                cj.to_str().unwrap(),
            ],
            d.path(),
        );
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let c = read_json(&cj)["error"]["rel_euclid_pct"].as_f64().unwrap();
        assert!((c - e).abs() < 0.3, "{arch}: compare {c} vs render {e}");
    }
    // The reference's JSON carries its camera, for aligning peers.
    let rj = d.path().join("ref.json");
    let o = cube(
        &[
            "render",
            "--scene",
            &scene,
            "--arch",
            "reference",
            "--json",
            rj.to_str().unwrap(),
        ],
        d.path(),
    );
    assert!(o.status.success());
    let cam = &read_json(&rj)["details"]["camera"];
    assert!(
        cam["scale"].as_f64().unwrap() > 0.0 && cam["forward"].as_array().unwrap().len() == 3,
        "{cam}"
    );
    // A wrong size, a missing file and a bad --repeat are one line each.
    let small = SPHERE.replace("[48, 40]", "[20, 20]");
    let small = write(d.path(), "small.json", &small);
    let png = d.path().join("quantized-splat.png");
    let o = cube(
        &[
            "compare",
            "--scene",
            &small,
            "--image",
            png.to_str().unwrap(),
        ],
        d.path(),
    );
    let e = String::from_utf8_lossy(&o.stderr);
    assert!(
        o.status.code() == Some(1) && e.contains("48x40") && e.lines().count() == 1,
        "{e}"
    );
    let o = cube(
        &["compare", "--scene", &scene, "--image", "nope.png"],
        d.path(),
    );
    let e = String::from_utf8_lossy(&o.stderr);
    assert!(
        o.status.code() == Some(1) && e.contains("nope.png") && e.lines().count() == 1,
        "{e}"
    );
    let o = cube(&["render", "--scene", &scene, "--repeat", "0"], d.path());
    let e = String::from_utf8_lossy(&o.stderr);
    assert!(
        o.status.code() == Some(1) && e.contains("--repeat") && e.lines().count() == 1,
        "{e}"
    );
    // Perspective and splat-only refusals name the cause.
    let persp = SPHERE.replace(
        r#""projection": "parallel", "rotate_deg": [70, 30, 0]"#,
        r#""projection": "perspective", "eye": [7.5, 7.5, -40], "target": [7.5, 7.5, 7.5], "up": [0, 1, 0], "fov_deg": 30"#,
    );
    let persp = write(d.path(), "persp.json", &persp);
    let o = cube(
        &[
            "render",
            "--scene",
            &persp,
            "--arch",
            "quantized-projection",
        ],
        d.path(),
    );
    let e = String::from_utf8_lossy(&o.stderr);
    assert!(
        o.status.code() == Some(1) && e.contains("orthographic") && e.lines().count() == 1,
        "{e}"
    );
    let mip = write(
        d.path(),
        "mip.json",
        &SPHERE.replace(r#""image""#, r#""mode": "mip", "image""#),
    );
    let o = cube(
        &["render", "--scene", &mip, "--arch", "quantized-splat"],
        d.path(),
    );
    let e = String::from_utf8_lossy(&o.stderr);
    assert!(
        o.status.code() == Some(1)
            && e.contains("unsupported by quantized-splat")
            && e.lines().count() == 1,
        "{e}"
    );
}

/// `cube tradeoff` on a small scene: all four files, every method's rows,
/// a non-empty Pareto front whose points no other point dominates, and
/// errors and images byte-identical at one and two threads.
#[test]
fn tradeoff_writes_rows_and_an_undominated_front_independent_of_threads() {
    let d = tempfile::tempdir().unwrap();
    let scene = write(d.path(), "s.json", SPHERE);
    let run = |threads: &str, out: &str| {
        let o = Command::new(env!("CARGO_BIN_EXE_cube"))
            .args(["tradeoff", "--scene", &scene, "--out", out, "--repeat", "1"])
            .env("RAYON_NUM_THREADS", threads)
            .current_dir(d.path())
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        read_json(&d.path().join(out).join("tradeoff.json"))
    };
    let a = run("1", "one");
    for f in [
        "tradeoff.csv",
        "tradeoff.png",
        "tradeoff.md",
        "tradeoff_area.png",
    ] {
        let len = std::fs::metadata(d.path().join("one").join(f))
            .unwrap()
            .len();
        assert!(len > 100, "{f}: {len} bytes");
    }
    let points = a["points"].as_array().unwrap();
    for m in [
        "reference",
        "cube4l",
        "cube3",
        "true3d",
        "quantized-projection",
        "quantized-splat",
    ] {
        assert!(
            points.iter().filter(|p| p["method"] == m).count() >= 2,
            "{m}"
        );
    }
    // Hardware points: the RTL's clocks at a committed report's fmax, or an
    // assumed clock that says so.
    for p in points.iter().filter(|p| !p["hardware"].is_null()) {
        let h = &p["hardware"];
        match h["clock_from"].as_str().unwrap() {
            "measured" => assert!(
                h["build"].is_string() && h["luts"].as_u64().unwrap() > 0,
                "{p}"
            ),
            "assumed" => assert_eq!(h["clock_mhz"], 100.0, "{p}"),
            other => panic!("{other}: {p}"),
        }
        assert!(h["clocks"].as_u64().unwrap() > 0, "{p}");
    }
    let cost = |p: &serde_json::Value| p["cost_seconds"].as_f64().unwrap();
    let err = |p: &serde_json::Value| p["error"]["rel_euclid_pct"].as_f64().unwrap();
    let front: Vec<_> = points.iter().filter(|p| p["pareto"] == true).collect();
    assert!(!front.is_empty());
    for f in &front {
        for p in points {
            let dominates =
                cost(p) <= cost(f) && err(p) <= err(f) && (cost(p) < cost(f) || err(p) < err(f));
            assert!(!dominates, "{p} dominates {f}");
        }
    }
    // Every width varied shows in the image, or is named as not reaching it.
    let md = std::fs::read_to_string(d.path().join("one/tradeoff.md")).unwrap();
    assert!(
        md.contains("Pareto front") && md.contains("ASSUMED"),
        "{md}"
    );
    // Determinism: the same rows but for the times.
    let b = run("2", "two");
    let strip = |v: &serde_json::Value| {
        v["points"]
            .as_array()
            .unwrap()
            .iter()
            .map(|p| {
                (
                    p["method"].clone(),
                    p["params"].clone(),
                    p["error"].clone(),
                    p["image_hash"].clone(),
                    p["hardware"].clone(),
                )
            })
            .collect::<Vec<_>>()
    };
    assert_eq!(strip(&a), strip(&b));
    // Bad input: one line naming the option.
    let o = cube(
        &[
            "tradeoff",
            "--scene",
            &scene,
            "--out",
            "x",
            "--methods",
            "cube5",
        ],
        d.path(),
    );
    let e = String::from_utf8_lossy(&o.stderr);
    assert!(
        o.status.code() == Some(1) && e.contains("cube5") && e.lines().count() == 1,
        "{e}"
    );
    let persp = SPHERE.replace(
        r#""projection": "parallel", "rotate_deg": [70, 30, 0]"#,
        r#""projection": "perspective", "eye": [7.5, 7.5, -40], "target": [7.5, 7.5, 7.5], "up": [0, 1, 0], "fov_deg": 30"#,
    );
    let persp = write(d.path(), "p.json", &persp);
    let o = cube(
        &[
            "tradeoff",
            "--scene",
            &persp,
            "--out",
            "x",
            "--methods",
            "quantized-splat",
        ],
        d.path(),
    );
    let e = String::from_utf8_lossy(&o.stderr);
    assert!(
        o.status.code() == Some(1) && e.contains("orthographic") && e.lines().count() == 1,
        "{e}"
    );
    let file = write(d.path(), "f", "user data");
    let o = cube(&["tradeoff", "--scene", &scene, "--out", &file], d.path());
    assert_eq!(o.status.code(), Some(1));
    assert_eq!(
        std::fs::read_to_string(d.path().join("f")).unwrap(),
        "user data"
    );
}

#[test]
fn cube3_sim_verilog_and_their_refusals() {
    let d = tempfile::tempdir().unwrap();
    let mip = write(
        d.path(),
        "mip.json",
        r#"{"volume": {"builtin": "phantom", "dims": [10, 9, 8]}, "view": {"projection": "parallel", "rotate_deg": [25, 35, 0]},
            "mode": "mip", "hardware": {"pipelines": 2}}"#,
    );
    let o = cube(
        &[
            "sim", "--arch", "cube3", "--scene", &mip, "--json", "s.json",
        ],
        d.path(),
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let s = read_json(&d.path().join("s.json"));
    assert_eq!(
        (s["arch"].as_str(), s["mismatches"].as_u64()),
        (Some("cube3"), Some(0))
    );
    // The schedule's terms (the last wait counted negative) add up to the
    // clocks the RTL took.
    let c = s["clocks"].as_object().unwrap();
    let keys: Vec<&str> = c.keys().map(|k| k.as_str()).collect();
    for k in [
        "segments",
        "segments_outside",
        "rays_outside",
        "idle",
        "prologue",
        "tail",
        "drain",
    ] {
        assert!(keys.contains(&k), "{k} missing: {s}");
    }
    assert_eq!(
        s["cycles"].as_i64().unwrap(),
        c.values().map(|v| v.as_i64().unwrap()).sum::<i64>()
    );
    let o = cube(
        &["verilog", "--arch", "cube3", "--scene", &mip, "--out", "v"],
        d.path(),
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    for f in [
        "top.v",
        "beam_fetch.v",
        "trilin.v",
        "rpc.v",
        "lint.vlt",
        "manifest.json",
    ] {
        assert!(d.path().join("v").join(f).exists(), "{f} missing");
    }
    // A perspective view of two base planes: one build renders both (the
    // volume loaded in each one's traversal order), and exports as one
    // design.
    let perspective = write(
        d.path(),
        "p.json",
        r#"{"volume": {"builtin": "phantom", "dims": [9, 8, 8]}, "view": {"projection": "perspective", "eye": [-12, -5, -12], "target": [4, 3.5, 3.5], "fov_deg": 60},
            "mode": "mip", "hardware": {"pipelines": 2}}"#,
    );
    let o = cube(
        &[
            "sim",
            "--arch",
            "cube3",
            "--scene",
            &perspective,
            "--json",
            "p_sim.json",
        ],
        d.path(),
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let s = read_json(&d.path().join("p_sim.json"));
    assert_eq!(s["mismatches"].as_u64(), Some(0));
    assert_eq!(s["base_planes"].as_u64(), Some(2), "{s}");
    let o = cube(
        &[
            "verilog",
            "--arch",
            "cube3",
            "--scene",
            &perspective,
            "--out",
            "pv",
        ],
        d.path(),
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let m = read_json(&d.path().join("pv/manifest.json"));
    assert_eq!(
        m["scene"]["base_planes"].as_array().map(|b| b.len()),
        Some(2)
    );
    // One design for both base planes: the view is the host's.
    assert_eq!(m["designs"].as_array().map(|b| b.len()), Some(1));
    assert!(d.path().join("pv/beam_fetch.v").exists());
    // What the RTL does not build: the 10-neighbourhood in perspective.
    let n10 = write(
        d.path(),
        "c.json",
        r#"{"volume": {"builtin": "phantom", "dims": [10, 9, 8]}, "view": {"projection": "perspective", "eye": [-12, -5, -12], "target": [4.5, 4, 3.5], "fov_deg": 60},
            "mode": "composite", "hardware": {"pipelines": 2}, "cube3": {"gradient": 10}}"#,
    );
    for cmd in ["sim", "verilog"] {
        assert_clean_error(
            &cube(
                &[cmd, "--arch", "cube3", "--scene", &n10, "--out", "w"],
                d.path(),
            ),
            "cube3.gradient 10 is built in hardware for parallel views only",
        );
    }
}

#[test]
fn volume_writes_the_voxels_a_renderer_reads() {
    let d = tempfile::tempdir().unwrap();
    let p = d.path();
    // 8-bit: the raw file comes back byte for byte.
    let raw8: Vec<u8> = (0..24u8).map(|i| i * 10).collect();
    std::fs::write(p.join("v8.raw"), &raw8).unwrap();
    let s8 = write(
        p,
        "v8.json",
        r#"{"volume": {"raw": "v8.raw", "dims": [4, 3, 2], "type": "u8"}, "view": {"projection": "parallel"}, "image": [8, 8]}"#,
    );
    let o = cube(&["volume", "--scene", &s8, "--out", "out8.raw"], p);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(String::from_utf8_lossy(&o.stdout).contains("4x3x2 u8 voxels"));
    assert_eq!(std::fs::read(p.join("out8.raw")).unwrap(), raw8);
    // 16-bit voxels: two bytes each, little-endian.
    let raw16: Vec<u8> = (0..24u16).flat_map(|i| (i * 2731).to_le_bytes()).collect();
    std::fs::write(p.join("v16.raw"), &raw16).unwrap();
    let s16 = write(
        p,
        "v16.json",
        r#"{"volume": {"raw": "v16.raw", "dims": [4, 3, 2], "type": "u16"}, "view": {"projection": "parallel"}, "image": [8, 8],
            "hardware": {"voxel_bits": 16, "rgba_bits": 12}}"#,
    );
    let o = cube(&["volume", "--scene", &s16, "--out", "out16.raw"], p);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(std::fs::read(p.join("out16.raw")).unwrap(), raw16);
    // A built-in: one byte per voxel.
    let o = cube(
        &[
            "volume",
            "--scene",
            &write(p, "s.json", SPHERE),
            "--out",
            "s.raw",
        ],
        p,
    );
    assert!(o.status.success());
    assert_eq!(std::fs::read(p.join("s.raw")).unwrap().len(), 16 * 16 * 16);
}
