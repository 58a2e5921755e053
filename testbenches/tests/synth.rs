//! Synthesis with yosys and place and route with nextpnr-ice40 of a pipeline
//! small enough for an iCE40 UP5K.

use cosim::synth::{frame_clocks, parse_stat, synthesize, Target};
use testbenches::{require_tool, scene};

#[test]
fn a_small_mip_pipeline_synthesizes_and_routes_on_an_up5k() {
    require_tool("yosys");
    require_tool("nextpnr-ice40");
    let s = scene(
        r#"{"volume": {"builtin": "sphere", "dims": [8, 8, 8]}, "view": {"projection": "parallel", "rotate_deg": [20, 30, 0]},
            "mode": "mip", "hardware": {"pipelines": 1}}"#,
    );
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("mip");
    let m = cosim::export::write_export("mip.json", &s, &s.camera().unwrap(), s.volume.dims, &out)
        .unwrap();
    let files: Vec<String> = m["sweeps"][0]["files"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| f.as_str().unwrap().to_string())
        .collect();
    let r = synthesize(&out, &files, Target::Ice40, true).unwrap();
    // Measured: 1275 LUTs, 511 flip-flops, 5 SB_RAM40_4K (the 512-voxel
    // memory module of 8-bit words and the 128-deep, 8-bit compositing-buffer
    // rings), 6 SB_MAC16 (the bilinear unit's lerps); fmax 29.9 MHz.
    assert!((1000..3000).contains(&r.luts), "{r:?}");
    assert!(r.flip_flops > 300, "{r:?}");
    assert!((1..=12).contains(&r.block_rams), "{r:?}");
    assert!((1..=8).contains(&r.dsps), "{r:?}");
    assert_eq!(r.fits_up5k, Some(true));
    let f = r.fmax_mhz.expect("placed and routed");
    assert!((15.0..100.0).contains(&f), "fmax {f} MHz");
    assert!(out.join("pnr.log").exists());
}

#[test]
fn stat_parsing_and_frame_clocks() {
    let stat = "=== top ===\n\n   Number of cells:               2738\n     SB_CARRY                      720\n     SB_LUT4                      1455\n\n";
    let (cells, types) = parse_stat(stat);
    assert_eq!(cells, 2738);
    assert_eq!(types["SB_LUT4"], 1455);
    assert_eq!(types.len(), 2);
    // 256 slices of 256 beams of 64 partial beams, one gradient slice, fill.
    assert_eq!(frame_clocks(256, 4, true), 256 * 256 * 64 + 256 * 64 + 6);
    assert_eq!(frame_clocks(8, 1, false), 512 + 6);
}
