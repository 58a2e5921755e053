//! `generated_verilog/` against a fresh `cube verilog` export, and every
//! committed file through `verilator --lint-only -Wall` and `iverilog`.

use cosim::arch::Arch;
use cosim::cube3::Cube3;
use cosim::cube4l::Cube4l;
use cosim::export::write_export;
use cosim::verilog::lint_waivers;
use scene::Scene;
use std::path::{Path, PathBuf};
use std::process::Command;
use testbenches::require_tool;

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// The committed configurations: (name, scene path), Cube-4L's in
/// `scenes/verilog/`, Cube-3's in `scenes/verilog/cube3/` (named
/// `cube3/NAME`, as their directories under `generated_verilog/`).
fn configs() -> Vec<(String, PathBuf)> {
    let scenes = |dir: &str, prefix: &str| -> Vec<(String, PathBuf)> {
        let mut v: Vec<(String, PathBuf)> = std::fs::read_dir(root().join(dir))
            .unwrap()
            .map(|e| e.unwrap().path())
            .filter(|p| p.extension().is_some_and(|e| e == "json"))
            .map(|p| {
                (
                    format!("{prefix}{}", p.file_stem().unwrap().to_string_lossy()),
                    p,
                )
            })
            .collect();
        v.sort();
        v
    };
    let (cube4l, cube3) = (
        scenes("scenes/verilog", ""),
        scenes("scenes/verilog/cube3", "cube3/"),
    );
    assert!(
        cube4l.len() >= 3,
        "scenes/verilog holds {} configurations",
        cube4l.len()
    );
    assert!(
        cube3.len() >= 2,
        "scenes/verilog/cube3 holds {} configurations",
        cube3.len()
    );
    cube4l.into_iter().chain(cube3).collect()
}

/// Every file under `dir`, relative to it, sorted.
fn files_under(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                stack.push(p);
            } else {
                out.push(p.strip_prefix(dir).unwrap().to_path_buf());
            }
        }
    }
    out.sort();
    out
}

#[test]
fn committed_verilog_is_fresh() {
    let tmp = tempfile::tempdir().unwrap();
    for (name, scene_path) in configs() {
        let scene = Scene::load(&scene_path).unwrap();
        let cam = scene.camera().unwrap();
        let fresh = tmp.path().join(&name);
        let dims = scene.volume.render_dims();
        match name.strip_prefix("cube3/") {
            Some(n) => write_export::<Cube3>(&format!("{n}.json"), &scene, &cam, dims, &fresh),
            None => write_export::<Cube4l>(&format!("{name}.json"), &scene, &cam, dims, &fresh),
        }
        .unwrap();
        let committed = root().join("generated_verilog").join(&name);
        let stale = "generated_verilog is stale: run scripts/generate-verilog";
        assert_eq!(
            files_under(&committed),
            files_under(&fresh),
            "{name}: the file sets differ; {stale}"
        );
        for f in files_under(&fresh) {
            let (a, b) = (
                std::fs::read_to_string(committed.join(&f)).unwrap(),
                std::fs::read_to_string(fresh.join(&f)).unwrap(),
            );
            if a != b {
                let line = a
                    .lines()
                    .zip(b.lines())
                    .position(|(x, y)| x != y)
                    .unwrap_or(a.lines().count().min(b.lines().count()));
                panic!(
                    "{name}/{}: first difference at line {}; {stale}",
                    f.display(),
                    line + 1
                );
            }
        }
    }
}

/// Each design directory (one per sweep) with its Verilog files, top first.
fn designs() -> Vec<(PathBuf, Vec<String>)> {
    let mut out = Vec::new();
    for (name, _) in configs() {
        let dir = root().join("generated_verilog").join(&name);
        let m: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(dir.join("manifest.json")).unwrap())
                .unwrap();
        let key = if name.starts_with("cube3/") {
            "base_planes"
        } else {
            "sweeps"
        };
        for s in m[key].as_array().unwrap() {
            let files = s["files"]
                .as_array()
                .unwrap()
                .iter()
                .map(|f| f.as_str().unwrap().to_string())
                .collect();
            out.push((dir.join(s["dir"].as_str().unwrap()), files));
        }
    }
    out
}

fn run(dir: &Path, program: &str, args: &[String]) -> (bool, String) {
    let o = Command::new(program)
        .args(args)
        .current_dir(dir)
        .output()
        .unwrap();
    (
        o.status.success(),
        String::from_utf8_lossy(&o.stderr).to_string() + &String::from_utf8_lossy(&o.stdout),
    )
}

#[test]
fn committed_verilog_lints_clean() {
    require_tool("verilator");
    for (dir, files) in designs() {
        let mut args: Vec<String> = vec!["--lint-only".into(), "-Wall".into(), "lint.vlt".into()];
        args.extend(files);
        let (ok, log) = run(&dir, "verilator", &args);
        assert!(ok, "{}: verilator -Wall:\n{log}", dir.display());
    }
}

/// The lint is live: without the waivers the same files are flagged, and
/// only for what the waivers name.
#[test]
fn lint_without_waivers_flags_exactly_the_waived_rules() {
    require_tool("verilator");
    for (design, waivers) in [
        ("mip_p4_64/.", lint_waivers(&[], &Cube4l::LAYOUT)),
        ("cube3/mip_p4_32/.", lint_waivers(&[], &Cube3::LAYOUT)),
    ] {
        let (dir, files) = designs()
            .into_iter()
            .find(|(d, _)| d.ends_with(design))
            .unwrap();
        let mut args: Vec<String> = vec!["--lint-only".into(), "-Wall".into()];
        args.extend(files);
        let (ok, log) = run(&dir, "verilator", &args);
        assert!(!ok, "{design}: lint passed without its waivers");
        for line in log.lines().filter(|l| l.starts_with("%Warning-")) {
            let rule = &line["%Warning-".len()..line.find(':').unwrap()];
            assert!(
                waivers.contains(&format!("-rule {rule} ")),
                "{design}: an unwaived warning: {line}"
            );
        }
    }
}

#[test]
fn committed_verilog_compiles_with_iverilog() {
    require_tool("iverilog");
    for (dir, files) in designs() {
        let mut args: Vec<String> = vec!["-g2012".into(), "-o".into(), "/dev/null".into()];
        args.extend(files);
        let (ok, log) = run(&dir, "iverilog", &args);
        assert!(ok, "{}: iverilog:\n{log}", dir.display());
    }
}

/// Every module's combinational block writes each output once a pass, so
/// event-driven simulators settle (`cosim::verilog::write_once`); the
/// design as rust-hdl emits it does not.
#[test]
fn committed_verilog_writes_each_output_once() {
    let mut modules = 0;
    for (dir, files) in designs() {
        let text: String = files
            .iter()
            .map(|f| std::fs::read_to_string(dir.join(f)).unwrap())
            .collect::<Vec<_>>()
            .join("\n");
        modules += cosim::verilog::split_modules(&text).len();
        let twice = cosim::verilog::outputs_written_twice(&text);
        assert!(twice.is_empty(), "{}: {twice:?}", dir.display());
    }
    assert!(modules > 100, "only {modules} modules read");
}
