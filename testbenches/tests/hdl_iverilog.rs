//! The Verilog that rust-hdl emits for the whole pipeline, run under Icarus
//! Verilog: its base planes must equal the golden model's bit for bit, like
//! the rust-hdl simulation's.

use cosim::cube4l::Cube4l;
use cosim::sim::{simulate, simulate_altered};
use cosim::Engine;
use scene::volume::builtin;
use testbenches::{require_tool, scene};

/// Both engines on one scene: pixels bit for bit, the same clocks (which
/// `simulate` checks against the schedule's terms); the terms.
fn check(json: &str, vol_name: &str) -> Vec<&'static str> {
    let s = scene(json);
    let vol = builtin(vol_name, s.volume.dims, 8).unwrap();
    let cam = s.camera();
    let icarus = simulate::<Cube4l>(&s, &cam, &vol, Engine::Iverilog, None).unwrap();
    assert_eq!(
        icarus.mismatches, 0,
        "{json}: first differences {:?}",
        icarus.first
    );
    let rust = simulate::<Cube4l>(&s, &cam, &vol, Engine::RustHdl, None).unwrap();
    assert_eq!(
        icarus.clocks, rust.clocks,
        "both engines count the same clocks"
    );
    icarus.clock_terms.iter().map(|t| t.key).collect()
}

#[test]
fn emitted_verilog_matches_golden_model_under_icarus() {
    require_tool("iverilog");
    check(
        r#"{"volume": {"builtin": "phantom", "dims": [10, 10, 8]}, "view": {"projection": "parallel", "rotate_deg": [70, 30, 0]},
            "mode": "mip", "image": [16, 16], "hardware": {"pipelines": 2}}"#,
        "phantom",
    );
    check(
        r#"{"volume": {"builtin": "sphere", "dims": [12, 12, 10]}, "view": {"projection": "parallel", "rotate_deg": [-20, 135, 10]},
            "mode": "composite", "image": [16, 16], "hardware": {"pipelines": 4}}"#,
        "sphere",
    );
    check(
        r#"{"volume": {"builtin": "phantom", "dims": [10, 12, 9]}, "view": {"projection": "perspective", "eye": [5, 6, -10], "fov_deg": 90},
            "mode": "xray", "image": [16, 16], "hardware": {"pipelines": 2}}"#,
        "phantom",
    );
    // An eye inside the volume: sweeps that start inside it stream the
    // slice before their first for the gradient, shaded through the host's
    // tables and registers.
    let terms = check(
        r#"{"volume": {"builtin": "phantom", "dims": [10, 12, 11]}, "view": {"projection": "perspective", "eye": [5.3, 6.6, 4.2], "target": [6, 5, 11], "fov_deg": 120},
            "mode": "composite", "shading": {"enabled": true}, "image": [16, 16], "hardware": {"pipelines": 2}}"#,
        "phantom",
    );
    assert!(terms.contains(&"halo_slice"), "{terms:?}");
}

#[test]
fn a_fault_in_the_emitted_verilog_is_caught() {
    use testbenches::emitted_sweep;
    require_tool("iverilog");
    let s = scene(
        r#"{"volume": {"builtin": "phantom", "dims": [10, 10, 8]}, "view": {"projection": "parallel", "rotate_deg": [70, 30, 0]},
            "mode": "composite", "shading": {"enabled": false}, "image": [16, 16], "hardware": {"pipelines": 2}}"#,
    );
    let vol = builtin("phantom", [10, 10, 8], 8).unwrap();
    let cam = s.camera();
    let verilog = emitted_sweep(&s, &vol).verilog;
    let differing = |v: &str| {
        simulate_altered::<Cube4l>(&s, &cam, &vol, Engine::Iverilog, None, &|_| v.to_string())
            .unwrap()
            .mismatches
    };
    assert_eq!(differing(&verilog), 0, "the untouched Verilog matches");
    // Make the bilinear unit's lerps truncate instead of rounding.
    let fault = "localparam  half = 64'h80;";
    assert!(
        verilog.contains(fault),
        "fault site not found in the emitted Verilog"
    );
    let broken = verilog.replace(fault, "localparam  half = 64'h0;");
    assert!(differing(&broken) > 0, "the injected fault went unnoticed");
}
