//! The README's figures that come from the committed synthesis reports
//! (`generated_verilog/synth/`) are those reports' figures: the tour's
//! `cube synth` output, and every headline row that names a `--config`.
//! The layout's `cli/` row names every module of the command.

use serde_json::Value;
use std::path::Path;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR")).parent().unwrap()
}

fn readme() -> String {
    std::fs::read_to_string(root().join("README.md")).unwrap()
}

fn report(arch: &str, config: &str) -> Value {
    let p = root().join(format!("generated_verilog/synth/{arch}_{config}.ecp5.json"));
    let text = std::fs::read_to_string(&p).unwrap_or_else(|e| panic!("{}: {e}", p.display()));
    serde_json::from_str(&text).unwrap()
}

fn num(v: &Value, path: &[&str]) -> f64 {
    let mut x = v;
    for k in path {
        x = &x[*k];
    }
    x.as_f64()
        .unwrap_or_else(|| panic!("{path:?} is not a number"))
}

/// The tour shows `cube synth --config mip_p4_64 --target ecp5` as it
/// prints the committed report (the formats of `cli/src/synth.rs`).
#[test]
fn the_tours_synthesis_run_is_the_committed_report() {
    let r = report("cube4l", "mip_p4_64");
    let p = num(&r, &["pipelines"]);
    let f = num(&r, &["fmax_mhz"]);
    let t = &r["critical_path"];
    let lines = [
        format!(
            "ecp5 (Cube-4L mip_p4_64): {} cells, {} LUTs, {} flip-flops, {} block RAMs, {} DSPs ({:.1} s); per pipeline {:.1} LUTs, {:.1} DSPs",
            r["cells"],
            r["luts"],
            r["flip_flops"],
            r["block_rams"],
            r["dsps"],
            num(&r, &["synth_seconds"]),
            num(&r, &["luts"]) / p,
            num(&r, &["dsps"]) / p
        ),
        format!(
            "{} bits designed, {} the least its largest volume needs ({}x)",
            r["memory"]["buffer_bits"], r["memory"]["minimum_bits"], r["memory"]["ratio"]
        ),
        format!("nextpnr ({}): fmax {f:.2} MHz", r["part"].as_str().unwrap()),
        format!(
            "critical path: {} ({}) -> {} ({}), {} cells, {:.2} ns logic + {:.2} ns routing",
            t["from"]["cell"].as_str().unwrap(),
            t["from"]["stage"].as_str().unwrap(),
            t["to"]["cell"].as_str().unwrap(),
            t["to"]["stage"].as_str().unwrap(),
            t["cells"],
            num(t, &["logic_ns"]),
            num(t, &["routing_ns"])
        ),
        format!("{:.0} M voxels/s at p = {p}", f * p),
        format!(
            "256³ at p = {p}: {} clocks per frame, {:.2} frames/s",
            r["projected"]["256"]["clocks_per_frame"],
            num(&r, &["projected", "256", "frames_per_second"])
        ),
    ];
    let text = readme();
    for l in &lines {
        assert!(
            text.contains(l.as_str()),
            "README.md lacks the report's line:\n{l}"
        );
    }
}

/// The number written just before `unit` in `text` (digits, a point, and
/// spaces between digit groups), first occurrence.
fn before(text: &str, unit: &str) -> Option<f64> {
    let at = text.find(unit)?;
    let head: Vec<char> = text[..at].chars().collect();
    let mut i = head.len();
    while i > 0 {
        let c = head[i - 1];
        let grouped = matches!(c, ' ' | '\u{202f}' | '\u{2009}' | '\u{a0}')
            && i >= 2
            && head[i - 2].is_ascii_digit()
            && i < head.len()
            && head[i].is_ascii_digit();
        if c.is_ascii_digit() || c == '.' || grouped {
            i -= 1;
        } else {
            break;
        }
    }
    let n: String = head[i..]
        .iter()
        .filter(|c| c.is_ascii_digit() || **c == '.')
        .collect();
    n.parse().ok()
}

/// Every headline row that names a synthesized `--config` leads with its
/// report's clock, and any LUT4 count, block-RAM count, rate and frame rate
/// it gives are the report's.
#[test]
fn every_headline_synthesis_row_is_its_report() {
    let text = readme();
    let mut rows = 0;
    for line in text
        .lines()
        .filter(|l| l.starts_with("| ") && l.contains("--config "))
    {
        let cols: Vec<&str> = line.split(" | ").collect();
        let (value, command) = (cols[1], cols[2]);
        let config = command
            .split("--config ")
            .nth(1)
            .and_then(|c| c.split_whitespace().next())
            .unwrap();
        let arch = if command.contains("--arch cube3") {
            "cube3"
        } else {
            "cube4l"
        };
        let r = report(arch, config);
        let f = num(&r, &["fmax_mhz"]);
        let p = num(&r, &["pipelines"]);
        let mut checked = 0;
        if let Some(mhz) = before(value, " MHz") {
            assert_eq!(mhz, (f * 10.0).round() / 10.0, "{config}: MHz in {value}");
            checked += 1;
        }
        if let Some(x) = before(value, "× after ECP5 synthesis") {
            let want = num(&r, &["memory", "synthesized_ratio"]);
            assert_eq!(x, (want * 1000.0).round() / 1000.0, "{config}: {value}");
            checked += 1;
        }
        assert!(checked > 0, "{config}: no figure of its report in {value}");
        if let Some(luts) = before(value, " LUT4") {
            assert_eq!(luts, num(&r, &["luts"]), "{config}: LUT4 in {value}");
        }
        if let Some(brams) = before(value, "/208 DP16KD") {
            assert_eq!(
                brams,
                num(&r, &["block_rams"]),
                "{config}: DP16KD in {value}"
            );
        }
        for rate in [" M voxels/s", " M samples/s"] {
            if let Some(m) = before(value, rate) {
                assert_eq!(m, (f * p).round(), "{config}: {rate} in {value}");
            }
        }
        if let Some(fps) = before(value, " frames/s at 256³") {
            let want = num(&r, &["projected", "256", "frames_per_second"]);
            assert_eq!(
                fps,
                (want * 10.0).round() / 10.0,
                "{config}: frames/s in {value}"
            );
        }
        rows += 1;
    }
    assert!(rows >= 8, "only {rows} headline rows name a --config");
}

/// The layout's `cli/` row names every module of `cli/src`.
#[test]
fn the_layout_names_every_module_of_the_command() {
    let text = readme();
    let row = text.lines().find(|l| l.starts_with("| `cli/` |")).unwrap();
    for e in std::fs::read_dir(root().join("cli/src")).unwrap() {
        let name = e.unwrap().file_name().to_string_lossy().to_string();
        let Some(stem) = name.strip_suffix(".rs") else {
            continue;
        };
        assert!(
            row.contains(&format!("`{stem}`")) || row.contains(&format!("`{name}`")),
            "README.md's cli/ row does not name {name}"
        );
    }
}
