//! The board's committed reports are current: the ECPIX-5 DDR3
//! controller's size (`scripts/litedram-size`) was made from the committed
//! `board/ecpix5/litedram.yml` with the generator versions the script pins.

use std::path::{Path, PathBuf};
use std::process::Command;
use testbenches::require_tool;

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

#[test]
fn the_controllers_size_report_is_current() {
    require_tool("sha256sum");
    let report: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(root().join("generated_verilog/boards/ecpix5_litedram.json"))
            .expect("generated_verilog/boards/ecpix5_litedram.json: run scripts/litedram-size"),
    )
    .unwrap();
    let yaml = root().join(report["yaml"].as_str().unwrap());
    let out = Command::new("sha256sum").arg(&yaml).output().unwrap();
    let digest = String::from_utf8_lossy(&out.stdout)
        .split_whitespace()
        .next()
        .unwrap_or_default()
        .to_string();
    let stale = "the controller's report is stale: run scripts/litedram-size";
    assert_eq!(
        report["yaml_sha256"].as_str(),
        Some(digest.as_str()),
        "{stale}"
    );
    let script = std::fs::read_to_string(root().join("scripts/litedram-size")).unwrap();
    let pins = script
        .lines()
        .find_map(|l| l.strip_prefix("pins=(")?.strip_suffix(')'))
        .unwrap();
    let recorded: Vec<&str> = report["generator"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_str().unwrap())
        .collect();
    assert_eq!(
        pins.split_whitespace().collect::<Vec<_>>(),
        recorded,
        "{stale}"
    );
    // A core with no LUTs would be a failed synthesis recorded as a size.
    assert!(report["cells"]["LUT4"].as_u64().unwrap() > 1000, "{stale}");
}
