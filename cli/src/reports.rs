//! The committed synthesis reports (`generated_verilog/synth/`, written by
//! `scripts/synth-reports` for the builds of
//! `generated_verilog/configurations.txt`), and the committed build that
//! prices a scene: the smallest one (in LUT4) that renders it.

use cosim::arch::Arch;
use scene::{Camera, Scene};
use std::path::{Path, PathBuf};

/// A committed build's ECP5 report.
#[derive(Debug, Clone, PartialEq)]
pub struct Measured {
    /// The build's configuration name.
    pub config: String,
    /// Place and route's fmax; none when the build does not fit the part
    /// and was synthesized only.
    pub fmax_mhz: Option<f64>,
    pub luts: u64,
    pub multipliers: u64,
    pub block_rams: u64,
}

/// The directory of the committed Verilog and reports.
pub fn generated_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../generated_verilog")
}

/// The committed builds of architecture `arch` (`cube4l`, `cube3`), in
/// the list's order.
pub fn committed(dir: &Path, arch: &str) -> Vec<String> {
    std::fs::read_to_string(dir.join("configurations.txt"))
        .unwrap_or_default()
        .lines()
        .filter(|l| !l.starts_with('#'))
        .filter_map(|l| {
            let mut f = l.split_whitespace();
            (f.next() == Some(arch)).then(|| f.next().map(String::from))?
        })
        .collect()
}

/// A build's ECP5 report, if committed and readable.
pub fn ecp5_report(dir: &Path, arch: &str, config: &str) -> Option<Measured> {
    let path = dir.join("synth").join(format!("{arch}_{config}.ecp5.json"));
    let r: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(path).ok()?).ok()?;
    Some(Measured {
        config: config.to_string(),
        fmax_mhz: r["fmax_mhz"].as_f64(),
        luts: r["luts"].as_u64()?,
        multipliers: r["dsps"].as_u64()?,
        block_rams: r["block_rams"].as_u64()?,
    })
}

/// The smallest committed build of `A` (by LUT4) with a report that
/// renders the scene; none when no committed build renders it.
pub fn pricing_build<A: Arch>(
    dir: &Path,
    scene: &Scene,
    camera: &Camera,
    dims: [usize; 3],
) -> Option<Measured> {
    let needed = A::needs(scene, camera, dims).ok()?;
    committed(dir, A::NAME)
        .iter()
        .filter(|name| {
            A::parse_config(name).is_ok_and(|build| A::refuses(&build, &needed).is_none())
        })
        .filter_map(|name| ecp5_report(dir, A::NAME, name))
        .min_by_key(|m| m.luts)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn committed_list_and_reports_are_read() {
        let d = tempfile::tempdir().unwrap();
        std::fs::write(
            d.path().join("configurations.txt"),
            "# a comment\ncube4l mip_p4_64 a.json\ncube3 mip_n12_p4_32 b.json c.json\n",
        )
        .unwrap();
        assert_eq!(committed(d.path(), "cube4l"), ["mip_p4_64"]);
        assert_eq!(committed(d.path(), "cube3"), ["mip_n12_p4_32"]);
        std::fs::create_dir(d.path().join("synth")).unwrap();
        std::fs::write(
            d.path().join("synth/cube4l_mip_p4_64.ecp5.json"),
            r#"{"fmax_mhz": 94.7, "luts": 3399, "dsps": 24, "block_rams": 132}"#,
        )
        .unwrap();
        let m = ecp5_report(d.path(), "cube4l", "mip_p4_64").unwrap();
        assert_eq!(
            m,
            Measured {
                config: "mip_p4_64".into(),
                fmax_mhz: Some(94.7),
                luts: 3399,
                multipliers: 24,
                block_rams: 132
            }
        );
        assert!(ecp5_report(d.path(), "cube3", "mip_n12_p4_32").is_none());
    }
}
