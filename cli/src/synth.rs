//! `cube synth`: synthesize a build (`--config`, or the configuration
//! `--scene` needs) with yosys and report cells, LUTs, flip-flops, block
//! RAMs and DSPs (also per pipeline), and the buffer memory against the
//! least its largest volume needs; a design that fits the target's part
//! (iCE40: an UP5K, ECP5: an LFE5U-85F) is placed and routed with nextpnr
//! for fmax (ECP5: with its critical path), and the frame rate is given for
//! the scene and, where the architecture projects it, for 256³ and 512³
//! volumes against the VolumePro 500's 30 frames/s at 256³. With `--keep
//! DIR` the exported Verilog, the yosys log and netlist, and nextpnr's log,
//! report and routed netlist stay in DIR. `--seed` and `--router` are
//! nextpnr's, recorded in the JSON report.

use crate::common::{choose_build, Loaded};
use crate::methods::HwArch;
use anyhow::{Context, Result};
use clap::ValueEnum;
use cosim::arch::Arch;
use cosim::archs::ForArch;
use cosim::synth::{synthesize, Pnr, Router, Target};
use serde_json::json;
use std::path::PathBuf;

#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
enum SynthTarget {
    Ice40,
    Ecp5,
    Xilinx,
    Generic,
}

#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
enum PnrRouter {
    Router1,
    Router2,
}

#[derive(clap::Args)]
pub struct SynthArgs {
    /// A scene: its configuration is the build, unless --config names one.
    #[arg(long)]
    scene: Option<PathBuf>,
    /// A configuration by name (see `cube verilog`).
    #[arg(long)]
    config: Option<String>,
    #[arg(long, value_enum, default_value = "cube4l")]
    arch: HwArch,
    #[arg(long, value_enum, default_value = "ice40")]
    target: SynthTarget,
    #[arg(long)]
    json: Option<PathBuf>,
    /// Skip placement and routing.
    #[arg(long)]
    no_pnr: bool,
    /// nextpnr's placement seed.
    #[arg(long, default_value_t = 1)]
    seed: u32,
    /// nextpnr's router (router2 for a design router1 cannot untangle).
    #[arg(long, value_enum, default_value = "router1")]
    router: PnrRouter,
    /// Keep the work in DIR, a directory this run creates: the exported
    /// Verilog, `synth.log`, the netlist `synth.json`, and after place and
    /// route `pnr.log`, `report.json` and the routed netlist `routed.json`
    /// (no bitstream: the design is placed out of context, without pins).
    #[arg(long, value_name = "DIR")]
    keep: Option<PathBuf>,
}

pub fn run(args: SynthArgs) -> Result<()> {
    args.arch.arch().with(Synth(&args))
}

struct Synth<'a>(&'a SynthArgs);

impl ForArch for Synth<'_> {
    type Output = Result<()>;
    fn run<A: Arch>(self) -> Result<()> {
        let args = self.0;
        let target = match args.target {
            SynthTarget::Ice40 => Target::Ice40,
            SynthTarget::Ecp5 => Target::Ecp5,
            SynthTarget::Xilinx => Target::Xilinx,
            SynthTarget::Generic => Target::Generic,
        };
        if let Some(j) = &args.json {
            crate::output::check_target(j)?;
        }
        let err = |e: String| anyhow::anyhow!("synth: {e}");
        let (loaded, build) =
            choose_build::<A>("synth", args.scene.as_deref(), args.config.as_deref())?;
        let mut outputs = crate::output::Files::default();
        if let (Some(path), Some(l)) = (&args.scene, &loaded) {
            outputs.scene("--scene", path, &l.scene)?;
        }
        if let Some(j) = &args.json {
            outputs.output("--json", j)?;
        }
        let scene = loaded.as_ref().map(Loaded::export);
        let parts = match &scene {
            Some(s) => A::parts(s.scene, s.camera, s.dims, &build).map_err(err)?,
            None => vec![],
        };
        let name = A::config_name(&build);
        // A temporary directory is removed when dropped, on every path out
        // of this function; a kept one is new, so nothing is replaced.
        let (_work, root) = match &args.keep {
            Some(d) => {
                if args.json.as_deref() == Some(d.as_path()) {
                    anyhow::bail!("synth: --keep and --json name the same path");
                }
                std::fs::create_dir(d).with_context(|| {
                    format!("synth: --keep {}: creating a new directory", d.display())
                })?;
                (None, d.clone())
            }
            None => {
                let t = tempfile::Builder::new()
                    .prefix("cube-synth-")
                    .tempdir()
                    .context("creating a temporary directory for yosys")?;
                let root = t.path().to_path_buf();
                crate::stop::remove_on_stop(&root);
                (Some(t), root)
            }
        };
        let dir = root.join("design");
        let m = cosim::export::write_export::<A>(&dir, &build, scene.as_ref()).map_err(err)?;
        // One design per build.
        let first = &m["designs"][0];
        let files: Vec<String> = first["files"]
            .as_array()
            .context("manifest files")?
            .iter()
            .filter_map(|f| f.as_str().map(String::from))
            .collect();
        let sub = dir.join(first["dir"].as_str().unwrap_or("."));
        let pnr = (!args.no_pnr).then_some(Pnr {
            seed: args.seed,
            router: match args.router {
                PnrRouter::Router1 => Router::Router1,
                PnrRouter::Router2 => Router::Router2,
            },
        });
        let r = synthesize(&sub, &files, target, pnr).map_err(|e| match &args.keep {
            Some(_) => anyhow::anyhow!("synth: {e} (the logs are in {})", sub.display()),
            None => anyhow::anyhow!("synth: {e} (--keep DIR keeps the logs)"),
        })?;
        let p = m["parameters"]["pipelines"].as_u64().unwrap_or(1);
        println!(
            "{} ({} {name}): {} cells, {} LUTs, {} flip-flops, {} block RAMs, {} DSPs ({:.1} s); per pipeline {:.1} LUTs, {:.1} DSPs",
            target.name(),
            A::TITLE,
            r.cells,
            r.luts,
            r.flip_flops,
            r.block_rams,
            r.dsps,
            r.synth_seconds,
            r.luts as f64 / p as f64,
            r.dsps as f64 / p as f64
        );
        // Memory: the buffers as designed against the scene's least, and
        // what the RAM primitives hold after synthesis.
        let buffer = A::buffer_memory(&build, &parts);
        let on_chip_volume = !A::external(&build);
        println!(
            "buffer memory ({}): {} bits designed, {} the least its largest volume needs ({}x); RAM primitives after synthesis: {} bits{}",
            buffer.what,
            buffer.bits,
            buffer.minimum_bits,
            buffer.ratio(),
            r.ram_bits,
            if on_chip_volume {
                " (with the on-chip voxel memory)"
            } else {
                ""
            }
        );
        let synthesized_ratio = (!on_chip_volume && buffer.minimum_bits > 0)
            .then(|| (r.ram_bits as f64 / buffer.minimum_bits as f64 * 1000.0).round() / 1000.0);
        if let Some(x) = synthesized_ratio {
            println!("  synthesized buffer memory: {x}x the least");
        }
        let frame: Option<u64> =
            (!parts.is_empty()).then(|| parts.iter().map(A::expected_clocks).sum());
        let mut projection = serde_json::Map::new();
        match (r.part, r.fits, r.fmax_mhz) {
            (Some(part), Some(false), _) => println!(
                "does not fit an {part} ({} LUTs, {} block RAMs, {} DSPs used): no place and route",
                r.luts, r.block_rams, r.dsps
            ),
            (Some(part), _, Some(f)) => {
                println!("nextpnr ({part}): fmax {f:.2} MHz");
                if let Some(t) = &r.timing {
                    println!(
                        "  critical path: {} ({}) -> {} ({}), {} cells, {:.2} ns logic + {:.2} ns routing",
                        t.from.cell,
                        t.from.stage,
                        t.to.cell,
                        t.to.stage,
                        t.cells.len(),
                        t.logic_ns,
                        t.routing_ns
                    );
                }
                let rate = f * 1e6 * p as f64;
                println!(
                    "  {:.0} M voxels/s at p = {p}; 30 frames/s at 256³ needs 503 M voxels/s: {}",
                    rate / 1e6,
                    if rate >= 503e6 {
                        "reached"
                    } else {
                        "not reached"
                    }
                );
                if let Some(frame) = frame {
                    println!(
                        "  the scene: {frame} clocks per frame, {:.2} frames/s",
                        f * 1e6 / frame as f64
                    );
                }
                for n in [256u64, 512] {
                    if let Some(clocks) = A::projected_clocks(n, &build) {
                        let fps = f * 1e6 / clocks as f64;
                        println!("  {n}³ at p = {p}: {clocks} clocks per frame, {fps:.2} frames/s");
                        projection.insert(
                            format!("{n}"),
                            json!({"clocks_per_frame": clocks, "frames_per_second": fps}),
                        );
                    }
                }
            }
            _ => {}
        }
        if let Some(j) = &args.json {
            outputs.json(
                j,
                &json!({
                    "configuration": name,
                    "scene": loaded.as_ref().map(|l| &l.name),
                    "architecture": A::NAME,
                    "target": target.name(),
                    "pipelines": p,
                    "cells": r.cells,
                    "luts": r.luts,
                    "flip_flops": r.flip_flops,
                    "block_rams": r.block_rams,
                    "dsps": r.dsps,
                    "cell_types": r.cell_types,
                    "per_pipeline": {
                        "luts": r.luts as f64 / p as f64,
                        "dsps": r.dsps as f64 / p as f64,
                    },
                    "memory": {
                        "what": buffer.what,
                        "buffer_bits": buffer.bits,
                        "minimum_bits": buffer.minimum_bits,
                        "ratio": buffer.ratio(),
                        "ram_primitive_bits": r.ram_bits,
                        "ram_primitives_hold_voxels": on_chip_volume,
                        "synthesized_ratio": synthesized_ratio,
                    },
                    "synth_seconds": r.synth_seconds,
                    "part": r.part,
                    "fits": r.fits,
                    "fmax_mhz": r.fmax_mhz,
                    "voxels_per_second": r.fmax_mhz.map(|f| f * 1e6 * p as f64),
                    "critical_path": r.timing.as_ref().map(|t| json!({
                        "from": {"cell": t.from.cell, "stage": t.from.stage},
                        "to": {"cell": t.to.cell, "stage": t.to.stage},
                        "cells": t.cells.len(),
                        "logic_ns": t.logic_ns,
                        "routing_ns": t.routing_ns,
                    })),
                    "pnr_seconds": r.pnr_seconds,
                    "pnr": r.pnr.map(|o| json!({"seed": o.seed, "router": o.router.name()})),
                    "frame_clocks": frame,
                    "frames_per_second": r.fmax_mhz.zip(frame).map(|(f, c)| f * 1e6 / c as f64),
                    "projected": projection,
                    "units_left_out": m["units_left_out"],
                    "parameters": m["parameters"],
                }),
            )?;
        }
        outputs.commit()
    }
}
