//! The fourth robustness round's findings that the other files do not
//! hold, one regression test each: a perspective eye near a volume edge is
//! flagged with the error it can expect, a splat kernel `f32` cannot hold
//! is refused, the thread pool starts under a 1.5 GB address-space limit
//! on many threads, and echoed strings are cut and escaped.

mod common;
use common::{cube, ok, refused};

/// The phantom seen in perspective from `eye`, toward its centre.
fn near_edge(eye: &str) -> String {
    format!(
        r#"{{"volume": {{"builtin": "phantom", "dims": [32, 32, 32]}}, "view": {{"projection": "perspective", "eye": {eye}, "target": [15.5, 15.5, 15.6], "up": [0, 1, 0], "fov_deg": 60}}, "image": [32, 32]}}"#
    )
}

/// Cube-4L's sweeps lie 18–50 % from the reference with the eye at or near
/// a corner (docs/accuracy.md#perspective): one warning line says so, and
/// the JSON carries it; from in front of a face there is none.
#[test]
fn an_eye_near_a_volume_edge_is_flagged_with_its_expected_error() {
    let d = tempfile::tempdir().unwrap();
    let p = d.path();
    for (eye, inside, range) in [
        ("[31, 31, 31]", true, [0.4, 58.0]),
        ("[33, 33, 33]", false, [8.0, 33.0]),
    ] {
        std::fs::write(p.join("s.json"), near_edge(eye)).unwrap();
        let o = cube(
            &[
                "render", "--scene", "s.json", "--arch", "cube4l", "--json", "r.json",
            ],
            p,
        );
        ok(&o);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(err.lines().count(), 1, "{eye}: one warning line: {err}");
        assert!(
            err.starts_with("cube: warning: ") && err.contains("%"),
            "{eye}: {err}"
        );
        let j: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(p.join("r.json")).unwrap()).unwrap();
        let c = &j["details"]["accuracy_caveat"];
        assert_eq!(c["eye_inside"], inside, "{eye}: {j}");
        assert_eq!(
            c["expected_error_percent"],
            serde_json::json!(range),
            "{eye}"
        );
        assert!(c["message"].as_str().unwrap().len() > 20);
    }
    std::fs::write(p.join("s.json"), near_edge("[15.5, 15.5, -20]")).unwrap();
    let o = cube(
        &[
            "render", "--scene", "s.json", "--arch", "cube4l", "--json", "r.json",
        ],
        p,
    );
    ok(&o);
    assert!(
        o.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let j: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(p.join("r.json")).unwrap()).unwrap();
    assert!(j["details"]["accuracy_caveat"].is_null(), "{j}");
}

/// The issue's scene: `b` = 1e-100 underflowed the f32 splat weights to
/// NaN (a black image, "NaN %"); it is refused in one line naming the
/// field and the range f32 holds.
#[test]
fn a_splat_kernel_f32_cannot_hold_is_refused() {
    let d = tempfile::tempdir().unwrap();
    let p = d.path();
    let s = r#"{"volume":{"builtin":"sphere","dims":[16,16,16]},"view":{"projection":"parallel","rotate_deg":[30,20,0]},"image":[32,32],"quantized":{"kernel":[1e-100,0.1]}}"#;
    std::fs::write(p.join("s.json"), s).unwrap();
    for args in [
        &[
            "render",
            "--scene",
            "s.json",
            "--arch",
            "quantized-splat",
            "--compare-reference",
        ][..],
        &[
            "angles",
            "--scene",
            "s.json",
            "--arch",
            "quantized-splat",
            "--range",
            "0",
            "10",
            "10",
        ][..],
    ] {
        refused(&cube(args, p), "quantized.kernel");
    }
}

/// `cube ARGS` in `dir` with `threads` renderer threads and at most
/// `bytes` of address space (`ulimit -v`).
fn cube_limited(
    args: &[&str],
    dir: &std::path::Path,
    threads: &str,
    bytes: u64,
) -> std::process::Output {
    cube_limited_env(args, dir, &[("RAYON_NUM_THREADS", threads)], bytes)
}

/// `cube ARGS` in `dir` with the environment `env` added and at most
/// `bytes` of address space (`ulimit -v`).
fn cube_limited_env(
    args: &[&str],
    dir: &std::path::Path,
    env: &[(&str, &str)],
    bytes: u64,
) -> std::process::Output {
    use std::os::unix::process::CommandExt;
    let mut c = std::process::Command::new(env!("CARGO_BIN_EXE_cube"));
    c.args(args)
        .current_dir(dir)
        .envs(env.iter().copied())
        .stdin(std::process::Stdio::null());
    // SAFETY: setrlimit is async-signal-safe, and the closure touches
    // nothing else.
    unsafe {
        c.pre_exec(move || {
            let l = libc::rlimit {
                rlim_cur: bytes,
                rlim_max: bytes,
            };
            if libc::setrlimit(libc::RLIMIT_AS, &l) == 0 {
                Ok(())
            } else {
                Err(std::io::Error::last_os_error())
            }
        });
    }
    c.output().expect("run cube")
}

/// 32 workers of rust-hdl's 32 MiB stack took 1 GiB of address space and
/// rayon's registry panicked under a 1.5 GB limit; the workers now take
/// 8 MiB, and a pool that cannot start is one line, not a panic.
#[test]
fn the_thread_pool_starts_under_the_documented_limit_or_says_why_not() {
    let d = tempfile::tempdir().unwrap();
    let p = d.path();
    let s = r#"{"volume":{"builtin":"sphere","dims":[16,16,16]},"view":{"projection":"parallel","rotate_deg":[30,20,0]},"image":[32,32]}"#;
    std::fs::write(p.join("s.json"), s).unwrap();
    ok(&cube_limited(
        &["render", "--scene", "s.json", "--out", "a.png"],
        p,
        "32",
        1_500_000_000,
    ));
    assert!(p.join("a.png").is_file());
    let o = cube_limited(&["render", "--scene", "s.json"], p, "1000", 1_500_000_000);
    refused(
        &o,
        "cannot start the worker threads (RAYON_NUM_THREADS=1000",
    );
}

/// A user's string echoed in an error is cut and its control characters
/// escaped, in every message: a 5 MB builtin name, a 3 MB key, a 1 MB raw
/// path, a 100 kB `--config`, ANSI escapes.
#[test]
fn echoed_strings_are_cut_and_escaped_in_every_message() {
    let d = tempfile::tempdir().unwrap();
    let p = d.path();
    let scene = |volume: &str| {
        format!(
            r#"{{"volume": {volume}, "view": {{"projection": "parallel", "rotate_deg": [30, 20, 0]}}, "image": [16, 16]}}"#
        )
    };
    let cases = [
        (
            scene(&format!(r#"{{"builtin": "{}"}}"#, "b".repeat(5 << 20))),
            vec![],
        ),
        (
            scene(&format!(
                r#"{{"builtin": "sphere", "{}": 1}}"#,
                "k".repeat(3 << 20)
            )),
            vec![],
        ),
        (
            scene(&format!(
                r#"{{"raw": "{}/v.raw", "dims": [4, 4, 4]}}"#,
                "d".repeat(1 << 20)
            )),
            vec![],
        ),
        (scene(r#"{"builtin": "\u001b[31mred\u001b[0m"}"#), vec![]),
        (
            scene(r#"{"builtin": "sphere", "dims": [8, 8, 8]}"#),
            vec!["--config".to_string(), "c".repeat(100_000)],
        ),
        (
            scene(r#"{"builtin": "sphere", "dims": [8, 8, 8]}"#),
            vec!["--config".to_string(), "\u{1b}[2Jwiped".to_string()],
        ),
    ];
    for (i, (s, extra)) in cases.iter().enumerate() {
        std::fs::write(p.join("s.json"), s).unwrap();
        let mut args = vec![if extra.is_empty() {
            "render"
        } else {
            "verilog"
        }];
        if extra.is_empty() {
            args.extend(["--scene", "s.json"]);
        } else {
            args.extend(["--out", "exp"]);
            args.extend(extra.iter().map(String::as_str));
        }
        let o = cube(&args, p);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(1), "case {i}: {err}");
        assert_eq!(err.trim_end().lines().count(), 1, "case {i}: one line");
        assert!(o.stderr.len() < 1500, "case {i}: {} bytes", o.stderr.len());
        assert!(!o.stderr.contains(&0x1b), "case {i}: a raw escape: {err}");
    }
}

/// rust-hdl's simulation threads take `RUST_MIN_STACK` each, and std's
/// `spawn` panicked where one could not start: now refused in one line,
/// exit 1, before any starts (issue 70 re-probe: a thread whose signal
/// stack could not be mapped aborted). 32 workers now fit 1.5 GB with the
/// simulation (malloc's arenas are capped under a limit).
#[test]
fn a_simulation_thread_that_cannot_start_is_one_line() {
    let d = tempfile::tempdir().unwrap();
    let p = d.path();
    let s = r#"{"volume":{"builtin":"sphere","dims":[12,12,12]},"view":{"projection":"parallel","rotate_deg":[20,30,0]},"image":[16,16]}"#;
    std::fs::write(p.join("s.json"), s).unwrap();
    let o = cube_limited_env(
        &["sim", "--scene", "s.json"],
        p,
        &[("RAYON_NUM_THREADS", "2"), ("RUST_MIN_STACK", "400000000")],
        1_500_000_000,
    );
    refused(
        &o,
        "cannot start the simulation's threads (4 of RUST_MIN_STACK=400000000",
    );
}

/// Issue 70 re-probe: 1000 workers under a 3 GB limit aborted in 3 runs of
/// 8 (std could not map a started worker's signal stack); the pool is now
/// checked against the limit before any worker starts, every time, and a
/// count that is no number or over 1024 is refused too.
#[test]
fn a_pool_over_the_address_limit_is_refused_every_time() {
    let d = tempfile::tempdir().unwrap();
    let p = d.path();
    let s = r#"{"volume":{"builtin":"sphere","dims":[16,16,16]},"view":{"projection":"parallel","rotate_deg":[30,20,0]},"image":[32,32]}"#;
    std::fs::write(p.join("s.json"), s).unwrap();
    for _ in 0..8 {
        let o = cube_limited(&["render", "--scene", "s.json"], p, "1000", 3_000_000_000);
        refused(
            &o,
            "over the limit of 2861 MiB (ulimit -v); set RAYON_NUM_THREADS to at most",
        );
    }
    for (n, why) in [
        ("5000", "at most 1024"),
        ("x", "RAYON_NUM_THREADS=x is not a whole number"),
    ] {
        let o = cube_limited(&["render", "--scene", "s.json"], p, n, u64::MAX);
        refused(&o, why);
    }
}

/// Issue 70 re-probe: identical images have no finite PSNR. `render`
/// printed "PSNR inf dB", tradeoff.csv `inf` and tradeoff.md `∞`; each now
/// says "n/a (identical images)", the CSV leaves the field empty and the
/// JSON has null. A tiny `--tolerance` is echoed in e notation.
#[test]
fn identical_images_have_no_psnr_figure() {
    let d = tempfile::tempdir().unwrap();
    let p = d.path();
    std::fs::write(
        p.join("eye.json"),
        r#"{"volume":{"builtin":"sphere","dims":[16,16,16]},"view":{"projection":"perspective","eye":[8,8,8.5],"target":[8,8,0],"up":[0,1,0],"fov_deg":40},"image":[32,32]}"#,
    )
    .unwrap();
    let out = ok(&cube(
        &[
            "render",
            "--scene",
            "eye.json",
            "--arch",
            "reference",
            "--compare-reference",
            "--json",
            "r.json",
        ],
        p,
    ));
    assert!(out.contains("PSNR n/a (identical images)"), "{out}");
    assert!(!out.contains("inf"), "{out}");
    let j: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(p.join("r.json")).unwrap()).unwrap();
    assert!(j["error"]["psnr_db"].is_null(), "{j}");
    let out = ok(&cube(
        &[
            "tradeoff",
            "--scene",
            "eye.json",
            "--out",
            "t",
            "--repeat",
            "1",
            "--tolerance",
            "1e-300",
        ],
        p,
    ));
    assert!(out.contains("1e-300 %") && out.len() < 2000, "{out}");
    let md = std::fs::read_to_string(p.join("t/tradeoff.md")).unwrap();
    assert!(!md.contains('∞') && !md.contains("inf"), "{md}");
    assert!(md.contains("| n/a (identical images) |"), "{md}");
    let csv = std::fs::read_to_string(p.join("t/tradeoff.csv")).unwrap();
    assert!(!csv.contains("inf"), "{csv}");
    let row = csv.lines().find(|l| l.starts_with("reference,")).unwrap();
    assert_eq!(row.split(',').nth(4), Some(""), "{row}");
}

/// The caveat reaches `tradeoff` too: each Cube-4L point of a near-edge
/// view carries it in the JSON, and the Markdown says it once.
#[test]
fn tradeoff_carries_the_near_edge_caveat() {
    let d = tempfile::tempdir().unwrap();
    let p = d.path();
    std::fs::write(
        p.join("s.json"),
        r#"{"volume": {"builtin": "phantom", "dims": [16, 16, 16]}, "view": {"projection": "perspective", "eye": [17, 17, 17], "target": [7.5, 7.5, 7.6], "up": [0, 1, 0], "fov_deg": 60}, "image": [16, 16]}"#,
    )
    .unwrap();
    ok(&cube(
        &[
            "tradeoff", "--scene", "s.json", "--out", "t", "--repeat", "1",
        ],
        p,
    ));
    let j: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(p.join("t/tradeoff.json")).unwrap()).unwrap();
    let points = j["points"].as_array().unwrap();
    let cube4l: Vec<_> = points.iter().filter(|x| x["method"] == "cube4l").collect();
    assert!(!cube4l.is_empty());
    for x in &cube4l {
        assert_eq!(
            x["accuracy_caveat"]["expected_error_percent"],
            serde_json::json!([8.0, 33.0]),
            "{x}"
        );
    }
    assert!(points
        .iter()
        .filter(|x| x["method"] == "reference")
        .all(|x| x["accuracy_caveat"].is_null()));
    let md = std::fs::read_to_string(p.join("t/tradeoff.md")).unwrap();
    assert_eq!(md.matches("## Accuracy caveats").count(), 1, "{md}");
    assert!(md.contains("- cube4l: the eye is"), "{md}");
}

/// A PNG whose header claims 2^31 − 1 × 1 pixels is refused by its size,
/// before any pixel is decoded, not as a memory limit.
#[test]
fn compare_names_the_size_of_a_huge_png() {
    let d = tempfile::tempdir().unwrap();
    let p = d.path();
    std::fs::write(
        p.join("s.json"),
        r#"{"volume": {"builtin": "sphere", "dims": [16, 16, 16]}, "view": {"projection": "parallel", "rotate_deg": [30, 20, 0]}, "image": [32, 32]}"#,
    )
    .unwrap();
    // IHDR of width 2^31 − 1, height 1, 8-bit RGB; an IDAT of 100 zeros.
    let chunk = |kind: &[u8], data: &[u8]| {
        let mut c = (data.len() as u32).to_be_bytes().to_vec();
        c.extend_from_slice(kind);
        c.extend_from_slice(data);
        let mut h = crc32fast::Hasher::new();
        h.update(kind);
        h.update(data);
        c.extend_from_slice(&h.finalize().to_be_bytes());
        c
    };
    // The png crate refuses 4294967295 x 4294967295 even without limits;
    // its size is read from the IHDR chunk then.
    for (w, h) in [(2147483647u32, 1u32), (u32::MAX, u32::MAX)] {
        let mut ihdr = w.to_be_bytes().to_vec();
        ihdr.extend_from_slice(&h.to_be_bytes());
        ihdr.extend_from_slice(&[8, 2, 0, 0, 0]);
        let mut png = b"\x89PNG\r\n\x1a\n".to_vec();
        png.extend(chunk(b"IHDR", &ihdr));
        png.extend(chunk(
            b"IDAT",
            &[0x78, 0x9c, 0x63, 0x60, 0x18, 0, 0, 0, 0x64, 0, 1],
        ));
        png.extend(chunk(b"IEND", &[]));
        std::fs::write(p.join("huge.png"), png).unwrap();
        refused(
            &cube(&["compare", "--scene", "s.json", "--image", "huge.png"], p),
            &format!("huge.png is {w}x{h}; the scene's image is 32x32"),
        );
    }
}

/// Issue 70 re-probe: `stage-vectors --clocks 1000000` took 3.5 GB for a
/// 298 MB JSON and aborted under a 3 GB limit; the cap is now 100000
/// (360 MB), which writes under a 1.5 GB limit. `--out /dev/full` was
/// explained as "a FIFO needs a reader"; it is not a folder.
#[test]
fn stage_vectors_fit_their_cap_and_name_a_file_as_out() {
    let d = tempfile::tempdir().unwrap();
    let p = d.path();
    refused(
        &cube(&["stage-vectors", "--out", "sv", "--clocks", "100001"], p),
        "--clocks 100001 outside 1..=100000",
    );
    let o = cube_limited(
        &["stage-vectors", "--out", "sv", "--clocks", "100000"],
        p,
        "2",
        1_500_000_000,
    );
    ok(&o);
    assert!(p.join("sv/compositor.json").is_file());
    let o = cube(&["stage-vectors", "--out", "/dev/full"], p);
    refused(&o, "--out /dev/full is not a folder");
    assert!(!String::from_utf8_lossy(&o.stderr).contains("FIFO"));
    std::fs::write(p.join("s.json"), r#"{"volume":{"builtin":"sphere","dims":[8,8,8]},"view":{"projection":"parallel"},"image":[8,8]}"#).unwrap();
    let o = cube(&["render", "--scene", "s.json", "--json", "/dev/full/x"], p);
    refused(&o, "(/dev/full is not a folder)");
}
