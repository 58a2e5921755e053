//! `generated_verilog/` against a fresh `cube verilog` export of each build
//! in `generated_verilog/configurations.txt`, the scenes each Cube-4L build
//! claims to render, and every committed file through `verilator
//! --lint-only -Wall` and `iverilog`.

use cosim::arch::Arch;
use cosim::cube3::Cube3;
use cosim::cube4l::Cube4l;
use cosim::export::{write_export, ExportScene};
use cosim::verilog::lint_waivers;
use scene::Scene;
use std::path::{Path, PathBuf};
use std::process::Command;
use testbenches::require_tool;

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// One committed build (a line of `generated_verilog/configurations.txt`):
/// its architecture, its configuration name (also its directory under
/// `generated_verilog/ARCH/`), and the scenes it renders (a Cube-3 build
/// takes its tables' shapes from the first).
struct Committed {
    arch: String,
    name: String,
    scenes: Vec<String>,
}

impl Committed {
    fn dir(&self) -> String {
        format!("{}/{}", self.arch, self.name)
    }

    /// Its ECP5 report, `ext` `json` or `sha256` (`scripts/synth-reports`).
    fn report(&self, ext: &str) -> PathBuf {
        root()
            .join("generated_verilog/synth")
            .join(format!("{}_{}.ecp5.{ext}", self.arch, self.name))
    }
}

fn configs() -> Vec<Committed> {
    let list =
        std::fs::read_to_string(root().join("generated_verilog/configurations.txt")).unwrap();
    let out: Vec<Committed> = list
        .lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .map(|l| {
            let mut w = l.split_whitespace().map(String::from);
            Committed {
                arch: w.next().unwrap(),
                name: w.next().unwrap(),
                scenes: w.collect(),
            }
        })
        .collect();
    for arch in ["cube4l", "cube3"] {
        let n = out.iter().filter(|c| c.arch == arch).count();
        assert!(n >= 3, "configurations.txt holds {n} {arch} builds");
    }
    for c in &out {
        assert!(!c.scenes.is_empty(), "{}: no scene listed", c.name);
    }
    out
}

/// A committed build's scene `s`, loaded.
fn load(s: &str) -> (String, Scene, scene::Camera, [usize; 3]) {
    let path = root().join(s);
    let scene = Scene::load(&path).unwrap();
    let camera = scene.camera();
    let dims = scene.volume.render_dims();
    let name = path.file_name().unwrap().to_string_lossy().to_string();
    (name, scene, camera, dims)
}

/// Export a committed build afresh into `out`.
fn export(c: &Committed, out: &Path) {
    match c.arch.as_str() {
        "cube4l" => {
            let build = Cube4l::parse_config(&c.name).unwrap();
            write_export::<Cube4l>(out, &build, None)
        }
        "cube3" => {
            let build = Cube3::parse_config(&c.name).unwrap();
            let (name, scene, camera, dims) = load(&c.scenes[0]);
            let s = ExportScene {
                name: &name,
                scene: &scene,
                camera: &camera,
                dims,
            };
            write_export::<Cube3>(out, &build, Some(&s))
        }
        a => panic!("configurations.txt: unknown architecture {a}"),
    }
    .unwrap();
}

/// Each build renders the scenes it lists: what they need is the build's,
/// and its registers and tables take their views, tables and light.
#[test]
fn each_committed_build_renders_its_scenes() {
    fn check<A: Arch>(c: &Committed) {
        let build = A::parse_config(&c.name).unwrap();
        for s in &c.scenes {
            let (_, scene, camera, dims) = load(s);
            let needed = A::needs(&scene, &camera, dims).unwrap();
            assert_eq!(A::refuses(&build, &needed), None, "{}: {s}", c.name);
            A::parts(&scene, &camera, dims, &build)
                .unwrap_or_else(|e| panic!("{}: {s}: {e}", c.name));
        }
    }
    for c in configs() {
        match c.arch.as_str() {
            "cube4l" => check::<Cube4l>(&c),
            _ => check::<Cube3>(&c),
        }
    }
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
    for c in configs() {
        let name = c.dir();
        let fresh = tmp.path().join(&name);
        std::fs::create_dir_all(fresh.parent().unwrap()).unwrap();
        export(&c, &fresh);
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
    for c in configs() {
        let dir = root().join("generated_verilog").join(c.dir());
        let m: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(dir.join("manifest.json")).unwrap())
                .unwrap();
        for s in m["designs"].as_array().unwrap() {
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

fn run(dir: &Path, program: &Path, args: &[String]) -> (bool, String) {
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
        let (ok, log) = run(&dir, &cosim::tool::verilator(), &args);
        assert!(ok, "{}: verilator -Wall:\n{log}", dir.display());
    }
}

/// The lint is live: without the waivers the same files are flagged, and
/// only for what the waivers name.
#[test]
fn lint_without_waivers_flags_exactly_the_waived_rules() {
    require_tool("verilator");
    for (design, waivers) in [
        ("cube4l/mip_p4_64/.", lint_waivers(&[], &Cube4l::LAYOUT)),
        ("cube3/mip_n12_p4_32/.", lint_waivers(&[], &Cube3::LAYOUT)),
    ] {
        let (dir, files) = designs()
            .into_iter()
            .find(|(d, _)| d.ends_with(design))
            .unwrap();
        let mut args: Vec<String> = vec!["--lint-only".into(), "-Wall".into()];
        args.extend(files);
        let (ok, log) = run(&dir, &cosim::tool::verilator(), &args);
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
        let (ok, log) = run(&dir, Path::new("iverilog"), &args);
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

/// Every committed build has an ECP5 report made from its committed
/// Verilog: `scripts/synth-reports` writes, beside each report, the digest
/// of the `*.v` files it synthesized (`cat *.v | sha256sum`). A report
/// that prices its first scene's frame (Cube-3) must also count the clocks
/// the committed manifest gives that scene: a host-side change of the
/// schedule leaves the Verilog as it is but moves the frame.
#[test]
fn committed_synthesis_reports_are_current() {
    require_tool("sha256sum");
    let mut stale = Vec::new();
    for c in configs() {
        let dir = root().join("generated_verilog").join(c.dir());
        let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
            .unwrap()
            .map(|e| e.unwrap().path())
            .filter(|p| p.extension().is_some_and(|e| e == "v"))
            .collect();
        files.sort();
        let out = Command::new("sha256sum")
            .stdin(std::process::Stdio::piped())
            .stdout(std::process::Stdio::piped())
            .spawn()
            .and_then(|mut child| {
                use std::io::Write;
                let mut stdin = child.stdin.take().unwrap();
                for f in &files {
                    stdin.write_all(&std::fs::read(f).unwrap())?;
                }
                drop(stdin);
                child.wait_with_output()
            })
            .unwrap();
        let digest = String::from_utf8_lossy(&out.stdout)
            .split_whitespace()
            .next()
            .unwrap_or_default()
            .to_string();
        let recorded = std::fs::read_to_string(c.report("sha256")).unwrap_or_default();
        if !c.report("json").is_file() || recorded.trim() != digest {
            stale.push(c.name.clone());
            continue;
        }
        let json = |p: PathBuf| -> serde_json::Value {
            serde_json::from_str(&std::fs::read_to_string(p).unwrap()).unwrap()
        };
        let report = json(c.report("json"));
        if let Some(clocks) = report["frame_clocks"].as_u64() {
            let manifest = json(dir.join("manifest.json"));
            let counted: u64 = (manifest["scene"]["base_planes"].as_array())
                .map_or(0, |b| b.iter().filter_map(|b| b["clocks"].as_u64()).sum());
            if counted != clocks {
                eprintln!(
                    "{}: the report counts {clocks} frame clocks, the manifest {counted}",
                    c.name
                );
                stale.push(c.name.clone());
            }
        }
    }
    assert!(
        stale.is_empty(),
        "ECP5 reports missing or older than their Verilog or manifest: {stale:?}; run FORCE=1 ONLY=\"{}\" scripts/synth-reports",
        stale.join(" ")
    );
}

/// Every placed and routed report records the nextpnr options it was made
/// with, and they are the ones `scripts/synth-reports` runs (`cube synth`'s
/// defaults, router1 and seed 1, or the build's seed in
/// `generated_verilog/synth/seeds.txt`), so that the script makes it again
/// the same way.
#[test]
fn committed_reports_were_routed_as_the_script_routes() {
    let seeds = std::fs::read_to_string(root().join("generated_verilog/synth/seeds.txt")).unwrap();
    let seed_of = |name: &str| {
        seeds
            .lines()
            .filter(|l| !l.starts_with('#'))
            .filter_map(|l| l.split_once(' '))
            .find(|(n, _)| *n == name)
            .map_or(1, |(_, s)| s.trim().parse::<u32>().unwrap())
    };
    let mut wrong = Vec::new();
    for c in configs() {
        // A missing report is the staleness test's to name.
        let Ok(text) = std::fs::read_to_string(c.report("json")) else {
            continue;
        };
        let r: serde_json::Value = serde_json::from_str(&text).unwrap();
        let want = serde_json::json!({"seed": seed_of(&c.name), "router": "router1"});
        if !r["fmax_mhz"].is_null() && r["pnr"] != want {
            wrong.push(format!("{}: {} (want {want})", c.name, r["pnr"]));
        }
    }
    assert!(
        wrong.is_empty(),
        "routed otherwise than the script routes: {wrong:?}"
    );
}
