//! The rest of the third robustness round's findings, one regression test
//! each: a scene FIFO with no writer, a byte-order mark, a huge echoed
//! value, a transparent PNG, a cropped sphere's gradients, vcd-diff's deep
//! scopes and usage exit code, tradeoff with the eye inside the volume, and
//! a synthesis stopped by SIGTERM.

mod common;
use common::{cube, ok, refused_with as refused};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

const SCENE: &str = r#"{"volume": {"builtin": "sphere", "dims": [12,12,10]}, "view": {"projection": "parallel", "rotate_deg": [70, 30, 0]}, "image": [24, 24], "hardware": {"pipelines": 2}}"#;

#[test]
fn a_scene_fifo_with_no_writer_is_an_error_not_a_hang() {
    let d = tempfile::tempdir().unwrap();
    let p = d.path();
    assert!(Command::new("mkfifo")
        .arg(p.join("s.json"))
        .status()
        .unwrap()
        .success());
    let t = Instant::now();
    refused(
        &cube(&["render", "--scene", "s.json"], p),
        1,
        "a FIFO with no writer",
    );
    assert!(t.elapsed() < Duration::from_secs(30));
    // A FIFO with a writer is read.
    let fifo = p.join("s.json");
    let writer = std::thread::spawn(move || std::fs::write(fifo, SCENE).unwrap());
    ok(&cube(&["render", "--scene", "s.json"], p));
    writer.join().unwrap();
}

#[test]
fn a_byte_order_mark_is_skipped_and_a_huge_value_is_not_echoed() {
    let d = tempfile::tempdir().unwrap();
    let p = d.path();
    std::fs::write(p.join("bom.json"), format!("\u{feff}{SCENE}")).unwrap();
    ok(&cube(&["render", "--scene", "bom.json"], p));
    let huge = SCENE.replace("\"parallel\"", &format!("\"{}\"", "x".repeat(10 << 20)));
    std::fs::write(p.join("huge.json"), huge).unwrap();
    let o = cube(&["render", "--scene", "huge.json"], p);
    refused(&o, 1, "more characters");
    assert!(o.stderr.len() < 1000, "{} bytes of stderr", o.stderr.len());
    // Past the size limit, the file is refused unread.
    let big = format!("{SCENE}{}", " ".repeat(17 << 20));
    std::fs::write(p.join("big.json"), big).unwrap();
    refused(&cube(&["render", "--scene", "big.json"], p), 1, "MiB");
}

#[test]
fn compare_composites_a_transparent_png_on_black() {
    let d = tempfile::tempdir().unwrap();
    let p = d.path();
    std::fs::write(p.join("s.json"), SCENE).unwrap();
    ok(&cube(
        &["render", "--scene", "s.json", "--out", "opaque.png"],
        p,
    ));
    // The same image, every pixel at alpha 0: black where it is composited.
    let img = image::open(p.join("opaque.png")).unwrap().to_rgba8();
    let mut clear = img.clone();
    for px in clear.pixels_mut() {
        px.0[3] = 0;
    }
    clear.save(p.join("clear.png")).unwrap();
    image::RgbImage::new(24, 24)
        .save(p.join("black.png"))
        .unwrap();
    let json = |name: &str| -> serde_json::Value {
        serde_json::from_str(&std::fs::read_to_string(p.join(name)).unwrap()).unwrap()
    };
    let out = ok(&cube(
        &[
            "compare",
            "--scene",
            "s.json",
            "--image",
            "clear.png",
            "--json",
            "c.json",
        ],
        p,
    ));
    assert!(out.contains("composited on black"), "{out}");
    ok(&cube(
        &[
            "compare",
            "--scene",
            "s.json",
            "--image",
            "black.png",
            "--json",
            "b.json",
        ],
        p,
    ));
    assert_eq!(json("c.json")["error"], json("b.json")["error"]);
    // An image of the wrong size is refused from its header.
    image::RgbImage::new(30000, 1)
        .save(p.join("wide.png"))
        .unwrap();
    refused(
        &cube(&["compare", "--scene", "s.json", "--image", "wide.png"], p),
        1,
        "30000x1",
    );
}

#[test]
fn gradients_of_a_cropped_sphere_use_its_true_centre() {
    let d = tempfile::tempdir().unwrap();
    let p = d.path();
    // The 64x48x48 sphere cropped to 48³ at x = 8 holds the same voxels as
    // the 48³ sphere: the same crossings, the same errors.
    std::fs::write(
        p.join("crop.json"),
        r#"{"volume": {"builtin": "sphere", "dims": [64,48,48], "crop": {"offset": [8,0,0], "dims": [48,48,48]}}, "view": {"projection": "parallel"}, "image": [64,64]}"#,
    )
    .unwrap();
    std::fs::write(
        p.join("full.json"),
        r#"{"volume": {"builtin": "sphere", "dims": [48,48,48]}, "view": {"projection": "parallel"}, "image": [64,64]}"#,
    )
    .unwrap();
    let a = ok(&cube(
        &[
            "gradients",
            "--scene",
            "crop.json",
            "--range",
            "0",
            "30",
            "30",
        ],
        p,
    ));
    let b = ok(&cube(
        &[
            "gradients",
            "--scene",
            "full.json",
            "--range",
            "0",
            "30",
            "30",
        ],
        p,
    ));
    assert_eq!(a, b);
}

#[test]
fn vcd_diff_exits_2_on_usage_errors_and_deep_scopes() {
    let d = tempfile::tempdir().unwrap();
    let p = d.path();
    let n = 30_000;
    let mut vcd = String::from("$timescale 1ps $end\n");
    for i in 0..n {
        vcd.push_str(&format!("$scope module m{i} $end\n"));
    }
    vcd.push_str("$var wire 1 ! clock $end\n");
    vcd.push_str(&"$upscope $end\n".repeat(n));
    vcd.push_str("$enddefinitions $end\n#0\n0!\n#1\n1!\n");
    std::fs::write(p.join("deep.vcd"), vcd).unwrap();
    refused(
        &cube(&["vcd-diff", "deep.vcd", "deep.vcd"], p),
        2,
        "nest deeper",
    );
    refused(&cube(&["vcd-diff", "deep.vcd"], p), 2, "<B>");
    refused(&cube(&["vcd-diff", "--bogus", "a", "b"], p), 2, "--bogus");
}

#[test]
fn tradeoff_skips_cube3_and_true3d_with_the_eye_inside_the_volume() {
    let d = tempfile::tempdir().unwrap();
    let p = d.path();
    std::fs::write(
        p.join("inside.json"),
        r#"{"volume": {"builtin": "sphere", "dims": [12,12,12]}, "view": {"projection": "perspective", "eye": [5.5,5.5,5.5], "target": [5.5,5.5,20], "fov_deg": 60}, "image": [16,16]}"#,
    )
    .unwrap();
    let out = ok(&cube(
        &[
            "tradeoff",
            "--scene",
            "inside.json",
            "--out",
            "t",
            "--repeat",
            "1",
        ],
        p,
    ));
    assert!(
        out.contains("skipped cube3: view: cube3 casts rays from a face"),
        "{out}"
    );
    assert!(out.contains("skipped true3d"), "{out}");
    assert!(p.join("t/tradeoff.json").exists());
}

#[test]
fn a_synthesis_stopped_by_sigterm_leaves_no_work_behind() {
    let d = tempfile::tempdir().unwrap();
    let p = d.path();
    std::fs::write(p.join("s.json"), SCENE).unwrap();
    let tmp = p.join("tmp");
    std::fs::create_dir(&tmp).unwrap();
    let mut child = Command::new(env!("CARGO_BIN_EXE_cube"))
        .args(["synth", "--scene", "s.json", "--target", "ecp5"])
        .current_dir(p)
        .env("TMPDIR", &tmp)
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    // Stop it once its work directory holds the design.
    let t = Instant::now();
    let started = || {
        std::fs::read_dir(&tmp)
            .unwrap()
            .filter_map(|e| e.ok())
            .any(|e| e.path().join("design").exists())
    };
    while !started() {
        assert!(child.try_wait().unwrap().is_none(), "synth ended first");
        assert!(t.elapsed() < Duration::from_secs(60), "no work directory");
        std::thread::sleep(Duration::from_millis(20));
    }
    // SAFETY: kill has no memory preconditions.
    unsafe {
        libc::kill(child.id() as libc::pid_t, libc::SIGTERM);
    }
    let o = child.wait_with_output().unwrap();
    assert_eq!(o.status.code(), Some(128 + libc::SIGTERM));
    assert!(String::from_utf8_lossy(&o.stderr).contains("temporary work removed"));
    let left: Vec<_> = std::fs::read_dir(&tmp).unwrap().collect();
    assert!(left.is_empty(), "{left:?}");
}
