//! The compositor's emitted Verilog stands on its own: cocotb (Python, the
//! verification engineers' tool) drives it under Icarus and under
//! Verilator from the files `cube stage-vectors` writes, and checks every
//! output against the golden model's; a wrong expected value makes the
//! cocotb test fail.

use cosim::stage_vectors::compositor;
use golden_model::common::plan::Order;
use hdl::cube4l::compositor::LATENCY;
use scene::Mode;
use std::path::{Path, PathBuf};
use std::process::Command;
use testbenches::require_tool;

/// The venv's Python with cocotb 2.x, which `scripts/setup` installs.
fn python() -> PathBuf {
    let py = Path::new(env!("CARGO_MANIFEST_DIR")).join("../target/fpga/venv/bin/python");
    let ok = Command::new(&py)
        .args([
            "-c",
            "import cocotb, sys; sys.exit(int(cocotb.__version__.split('.')[0]) < 2)",
        ])
        .status()
        .is_ok_and(|s| s.success());
    assert!(
        ok,
        "cocotb 2.x is not installed in {}: run scripts/setup, which installs it",
        py.display()
    );
    py
}

/// Write the compositor's files into a folder of their own and run the
/// cocotb test on them; its exit status and output.
fn cocotb(
    name: &str,
    simulator: &str,
    mode: Mode,
    edit: impl Fn(&mut serde_json::Value),
) -> (bool, String) {
    require_tool(match simulator {
        "icarus" => "iverilog",
        other => other,
    });
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("cocotb")
        .join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let mut files = compositor(mode, Order::FrontToBack, 8, 600, 7);
    edit(&mut files.vectors);
    std::fs::write(dir.join("compositor.v"), &files.verilog).unwrap();
    std::fs::write(dir.join("compositor.json"), files.vectors.to_string()).unwrap();
    let run = Path::new(env!("CARGO_MANIFEST_DIR")).join("cocotb/run.py");
    // cocotb finds its simulator on the PATH: the kit's Verilator first.
    let verilator = cosim::tool::verilator();
    let mut path =
        std::env::split_paths(&std::env::var_os("PATH").unwrap_or_default()).collect::<Vec<_>>();
    if let Some(bin) = verilator.parent().filter(|d| !d.as_os_str().is_empty()) {
        path.insert(0, bin.to_path_buf());
    }
    let out = Command::new(python())
        .arg(run)
        .arg(&dir)
        .arg(simulator)
        .env("PATH", std::env::join_paths(path).unwrap())
        .output()
        .unwrap();
    let text =
        String::from_utf8_lossy(&out.stdout).to_string() + &String::from_utf8_lossy(&out.stderr);
    (out.status.success(), text)
}

#[test]
fn cocotb_drives_the_emitted_compositor_and_every_output_matches() {
    for (name, mode) in [
        ("composite", Mode::Composite),
        ("mip", Mode::Mip),
        ("xray", Mode::Xray),
    ] {
        let (ok, text) = cocotb(name, "icarus", mode, |_| {});
        assert!(ok, "{name}: {text}");
        assert!(text.contains(&checked()), "{name}: {text}");
        assert!(
            text.contains("cocotb: 1 of 1 tests passed"),
            "{name}: {text}"
        );
    }
}

/// 600 clocks of four outputs, the first `LATENCY - 1` before the
/// pipeline's first output.
fn checked() -> String {
    format!("{} outputs checked over 600 clocks", (601 - LATENCY) * 4)
}

/// One expected value changed at clock 300 fails the cocotb test under
/// `simulator` at clock `300 + LATENCY - 1`.
fn a_wrong_expected_output_fails_under(name: &str, simulator: &str) {
    let (ok, text) = cocotb(name, simulator, Mode::Composite, |v| {
        let g = v["expected"][300]["out_g"].as_u64().unwrap();
        v["expected"][300]["out_g"] = (g ^ 1).into();
    });
    assert!(!ok, "{text}");
    let at = format!("clock {}: out_g", 300 + LATENCY - 1);
    assert!(text.contains(&at), "{text}");
}

#[test]
fn a_wrong_expected_output_fails_the_cocotb_test() {
    a_wrong_expected_output_fails_under("wrong", "icarus");
}

/// The same files under Verilator (5.048, which cocotb 2.x needs): the
/// composite stage passes, and the wrong expected value fails it.
#[test]
fn cocotb_drives_the_emitted_compositor_under_verilator_too() {
    let (ok, text) = cocotb("verilator", "verilator", Mode::Composite, |_| {});
    assert!(ok, "{text}");
    assert!(text.contains(&checked()), "{text}");
    a_wrong_expected_output_fails_under("verilator_wrong", "verilator");
}
