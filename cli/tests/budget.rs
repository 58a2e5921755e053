//! Memory bounded before it is spent: a render that would exceed the memory
//! budget (half the machine, or 80 % of `ulimit -v`) is refused in one line
//! with its estimate, before anything is allocated, and `tradeoff` leaves
//! such points out and names them. Each run here has a 1.5 or 4 GB address
//! limit, under which these scenes once ended in an allocation abort.

use std::os::unix::process::CommandExt;
use std::path::Path;
use std::process::{Command, Output, Stdio};

fn cube_limited(args: &[&str], dir: &Path, bytes: u64) -> Output {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_cube"));
    cmd.args(args).current_dir(dir).stdin(Stdio::null());
    // SAFETY: setrlimit is async-signal-safe, as pre_exec requires.
    unsafe {
        cmd.pre_exec(move || {
            let r = libc::rlimit {
                rlim_cur: bytes,
                rlim_max: bytes,
            };
            if libc::setrlimit(libc::RLIMIT_AS, &r) != 0 {
                return Err(std::io::Error::last_os_error());
            }
            Ok(())
        });
    }
    cmd.output().expect("run cube")
}

fn scene(dir: &Path, name: &str, dims: usize, zoom: f64, image: u32) {
    std::fs::write(
        dir.join(name),
        format!(
            r#"{{"volume": {{"builtin": "sphere", "dims": [{dims},{dims},{dims}]}}, "view": {{"projection": "parallel", "zoom": {zoom}}}, "image": [{image},{image}]}}"#
        ),
    )
    .unwrap();
}

#[test]
fn a_render_past_the_memory_budget_is_refused_with_its_estimate() {
    let d = tempfile::tempdir().unwrap();
    let p = d.path();
    scene(p, "z1000.json", 32, 1000.0, 256);
    scene(p, "z100.json", 32, 100.0, 256);
    scene(p, "big.json", 32, 1.0, 8192);
    for (s, arch) in [
        ("z1000.json", "quantized-projection"),
        ("z1000.json", "quantized-splat"),
        ("z100.json", "quantized-splat"),
        ("big.json", "quantized-projection"),
    ] {
        let o = cube_limited(&["render", "--scene", s, "--arch", arch], p, 4 << 30);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(1), "{s} {arch}: {err}");
        assert_eq!(err.trim_end().lines().count(), 1, "{err}");
        assert!(
            err.contains("GiB, over the memory budget"),
            "{s} {arch}: {err}"
        );
    }
    // What fits is rendered.
    let o = cube_limited(
        &[
            "render",
            "--scene",
            "z100.json",
            "--arch",
            "quantized-projection",
        ],
        p,
        4 << 30,
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
}

#[test]
fn tradeoff_leaves_out_the_points_past_the_budget() {
    let d = tempfile::tempdir().unwrap();
    let p = d.path();
    scene(p, "s.json", 12, 16.0, 64);
    let o = cube_limited(
        &[
            "tradeoff",
            "--scene",
            "s.json",
            "--out",
            "t",
            "--methods",
            "quantized-splat",
            "--repeat",
            "1",
        ],
        p,
        1536 << 20,
    );
    let out = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(
        out.contains("skipped quantized-splat subdivisions 64")
            && out.contains("over the memory budget"),
        "{out}"
    );
    let report: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(p.join("t/tradeoff.json")).unwrap()).unwrap();
    assert!(report["skipped"]
        .as_array()
        .unwrap()
        .iter()
        .any(|s| s["reason"].as_str().unwrap().contains("memory budget")));
}

/// A transfer function of 150 000 points (3.3 MB of scene) is looked up
/// by binary search: the reference at 32² took 7.3 s with the linear scan
/// (35.8 s at 128²), 0.01 s now (0.10 s at 128², the same image). The
/// estimate counts its search levels and accepts it; not a timed test.
#[test]
fn a_transfer_function_of_150k_points_renders() {
    let d = tempfile::tempdir().unwrap();
    let p = d.path();
    let n = 150_000;
    let opacity: Vec<String> = (0..n)
        .map(|i| {
            format!(
                "[{}, {}]",
                255.0 * i as f64 / (n - 1) as f64,
                0.75 * ((i * 7919) % 1000) as f64 / 1000.0
            )
        })
        .collect();
    std::fs::write(
        p.join("s.json"),
        format!(
            r#"{{"volume": {{"builtin": "sphere", "dims": [64, 64, 64]}}, "view": {{"projection": "parallel"}}, "image": [32, 32], "transfer": {{"opacity": [{}], "color": [[0, 1, 1, 1], [255, 1, 1, 1]]}}}}"#,
            opacity.join(",")
        ),
    )
    .unwrap();
    for arch in ["reference", "cube4l"] {
        let o = cube_limited(
            &[
                "render", "--scene", "s.json", "--arch", arch, "--out", "s.png",
            ],
            p,
            4 << 30,
        );
        assert!(
            o.status.success(),
            "{arch}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
    }
}
