//! `cube volume`: the raw voxels, and the DRAM image of `--layout dram`
//! with its address map.

mod common;

use common::{cube, ok, refused};
use std::process::Command;

#[test]
fn the_dram_image_and_its_map() {
    let d = tempfile::tempdir().unwrap();
    let p = d.path();
    std::fs::write(
        p.join("s.json"),
        r#"{"volume": {"builtin": "sphere", "dims": [10, 6, 7]}, "view": {"projection": "parallel"}, "image": [16, 16], "hardware": {"pipelines": 4}}"#,
    )
    .unwrap();
    let o = cube(
        &[
            "volume", "--scene", "s.json", "--layout", "dram", "--out", "v.bin", "--map", "v.json",
        ],
        p,
    );
    ok(&o);
    let map: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(p.join("v.json")).unwrap()).unwrap();
    let image = std::fs::read(p.join("v.bin")).unwrap();
    // Three copies of 10x6x7 at a 4-byte word, each within one 4 KiB page.
    assert_eq!(map["bytes"], 3 * 4096);
    assert_eq!(image.len(), 3 * 4096);
    assert_eq!(map["word_bytes"], 4);
    let bases: Vec<u64> = map["copies"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c["base"].as_u64().unwrap())
        .collect();
    assert_eq!(bases, [0, 4096, 8192]);
    assert_eq!(
        map["copies"][2]["pipeline_dims"],
        serde_json::json!([10, 6, 7])
    );
    // The z copy is the volume skewed: voxel (u, v, w) in byte
    // (u + v + w) % 4 of word u / 4 + 3 v + 18 w; the raw file has it at
    // u + 10 v + 60 w.
    let o = cube(&["volume", "--scene", "s.json", "--out", "v.raw"], p);
    ok(&o);
    let raw = std::fs::read(p.join("v.raw")).unwrap();
    for (u, v, w) in [(0, 0, 0), (5, 3, 3), (9, 5, 6), (4, 2, 1)] {
        let at = 8192 + 4 * (u / 4 + 3 * v + 18 * w) + (u + v + w) % 4;
        assert_eq!(image[at], raw[u + 10 * v + 60 * w], "({u}, {v}, {w})");
    }
    // --map belongs to --layout dram; a refused run writes nothing.
    let o = cube(
        &[
            "volume", "--scene", "s.json", "--out", "w.raw", "--map", "w.json",
        ],
        p,
    );
    refused(&o, "--map");
    assert!(!p.join("w.raw").exists() && !p.join("w.json").exists());
}

/// A volume whose file does not fit in the memory the process may have is
/// one line naming its size, not an allocation abort (issue 70 re-probe:
/// 1024x1024x256 under a 1 GB limit aborted).
#[test]
fn a_volume_too_big_for_the_limit_is_one_line() {
    let d = tempfile::tempdir().unwrap();
    let p = d.path();
    std::fs::write(
        p.join("big.json"),
        r#"{"volume": {"builtin": "sphere", "dims": [1024, 1024, 256]}, "view": {"projection": "parallel"}, "image": [16, 16]}"#,
    )
    .unwrap();
    for layout in ["raw", "dram"] {
        let o = Command::new("prlimit")
            .arg("--as=1000000000")
            .arg(env!("CARGO_BIN_EXE_cube"))
            .args([
                "volume", "--scene", "big.json", "--layout", layout, "--out", "b.bin",
            ])
            .current_dir(p)
            .output()
            .expect("prlimit (util-linux) runs the case under a memory limit");
        refused(&o, "more memory than this process may have");
        assert!(!p.join("b.bin").exists(), "{layout}");
    }
}
