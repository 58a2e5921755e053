//! `cube synth`: synthesize the scene's pipeline with yosys and report cells,
//! LUTs, flip-flops, block RAMs and DSPs (also per pipeline), and the memory
//! bits against the least the scene needs; a design that fits the target's
//! part (iCE40: an UP5K, ECP5: an LFE5U-85F) is placed and routed with
//! nextpnr for fmax (ECP5: with its critical path), and the frame rate is
//! projected for 256³ and 512³ volumes against the VolumePro 500's
//! 30 frames/s at 256³.

use crate::common::scene_name;
use crate::output::write_json;
use anyhow::{Context, Result};
use clap::ValueEnum;
use cosim::synth::{frame_clocks, synthesize, Target};
use scene::Scene;
use serde_json::json;
use std::path::PathBuf;

#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
enum SynthTarget {
    Ice40,
    Ecp5,
    Xilinx,
    Generic,
}

/// The architecture synthesized.
#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
enum SynthArch {
    Cube4l,
    /// Cube-3: parallel and perspective views in every mode (the 6 or the
    /// 12 gradient neighbourhood).
    Cube3,
}

#[derive(clap::Args)]
pub struct SynthArgs {
    #[arg(long)]
    scene: PathBuf,
    #[arg(long, value_enum, default_value = "cube4l")]
    arch: SynthArch,
    #[arg(long, value_enum, default_value = "ice40")]
    target: SynthTarget,
    #[arg(long)]
    json: Option<PathBuf>,
    /// Skip placement and routing.
    #[arg(long)]
    no_pnr: bool,
}

pub fn run(args: SynthArgs) -> Result<()> {
    let SynthArgs {
        scene: scene_path,
        arch,
        target,
        json: json_path,
        no_pnr,
    } = args;
    let pnr = !no_pnr;
    let target = match target {
        SynthTarget::Ice40 => Target::Ice40,
        SynthTarget::Ecp5 => Target::Ecp5,
        SynthTarget::Xilinx => Target::Xilinx,
        SynthTarget::Generic => Target::Generic,
    };
    if let Some(j) = &json_path {
        crate::output::check_target(j)?;
    }
    let scene = Scene::load(&scene_path)?;
    let cam = scene.camera()?;
    // Removed when dropped, on every path out of this function.
    let work = tempfile::Builder::new()
        .prefix("cube-synth-")
        .tempdir()
        .context("creating a temporary directory for yosys")?;
    let dir = work.path().join("design");
    let name = scene_name(&scene_path);
    if arch == SynthArch::Cube3 {
        return run_cube3(&name, &scene, &dir, target, pnr, json_path);
    }
    let result = (|| {
        let m = cosim::export::write_export(&name, &scene, &cam, scene.volume.render_dims(), &dir)
            .map_err(|e| anyhow::anyhow!("synth: {e}"))?;
        let sweep = &m["sweeps"][0];
        let files: Vec<String> = sweep["files"]
            .as_array()
            .context("manifest files")?
            .iter()
            .filter_map(|f| f.as_str().map(String::from))
            .collect();
        let sub = dir.join(sweep["dir"].as_str().unwrap_or("."));
        let r = synthesize(&sub, &files, target, pnr).map_err(|e| anyhow::anyhow!("synth: {e}"))?;
        Ok::<_, anyhow::Error>((m, r))
    })();
    let (m, r) = result?;
    let p = scene.hardware.pipelines as u64;
    let gradient = !m["units_left_out"]
        .as_array()
        .is_some_and(|a| a.iter().any(|u| u == "abc_gradient"));
    println!(
        "{}: {} cells, {} LUTs, {} flip-flops, {} block RAMs, {} DSPs ({:.1} s)",
        target.name(),
        r.cells,
        r.luts,
        r.flip_flops,
        r.block_rams,
        r.dsps,
        r.synth_seconds
    );
    let sweeps = m["sweeps"].as_array().map_or(1, |s| s.len());
    if sweeps > 1 {
        println!("(sweep 0 of {sweeps}; every sweep's pipeline has the same structure, with its own constants)");
    }
    println!(
        "per pipeline: {:.1} LUTs, {:.1} DSPs",
        r.luts as f64 / p as f64,
        r.dsps as f64 / p as f64
    );
    // Memory: the buffers as designed against the scene's least, and what
    // the RAM primitives hold after synthesis.
    let buffer = &m["parameters"]["buffer_memory"];
    let on_chip_volume = m["parameters"]["memory"]["kind"] == "on-chip";
    let minimum = buffer["minimum_bits"].as_u64().unwrap_or(0);
    println!(
        "buffer memory: {} bits designed, {} the least the scene needs ({}x); RAM primitives after synthesis: {} bits{}",
        buffer["bits"],
        minimum,
        buffer["ratio"],
        r.ram_bits,
        if on_chip_volume {
            " (with the on-chip voxel memory)"
        } else {
            ""
        }
    );
    let synthesized_ratio = (!on_chip_volume && minimum > 0)
        .then(|| (r.ram_bits as f64 / minimum as f64 * 1000.0).round() / 1000.0);
    if let Some(x) = synthesized_ratio {
        println!("  synthesized buffer memory: {x}x the least");
    }
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
            for n in [256u64, 512] {
                let clocks = frame_clocks(n, p, gradient);
                let fps = f * 1e6 / clocks as f64;
                println!("  {n}³ at p = {p}: {clocks} clocks per frame, {fps:.2} frames/s");
                projection.insert(
                    format!("{n}"),
                    json!({"clocks_per_frame": clocks, "frames_per_second": fps}),
                );
            }
        }
        _ => {}
    }
    if let Some(j) = json_path {
        write_json(
            &j,
            &json!({
                "scene": name,
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
                    "buffer_bits": buffer["bits"],
                    "minimum_bits": minimum,
                    "ratio": buffer["ratio"],
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
                "projected": projection,
                "units_left_out": m["units_left_out"],
                "parameters": m["parameters"],
            }),
        )?;
    }
    Ok(())
}

/// `cube synth --arch cube3`: the scene's Cube-3 system, its resources, the
/// 2-DSBs' bits, and with place and route the fmax and this scene's frame
/// rate.
fn run_cube3(
    name: &str,
    scene: &Scene,
    dir: &std::path::Path,
    target: Target,
    pnr: bool,
    json_path: Option<PathBuf>,
) -> Result<()> {
    let cam = scene.camera()?;
    let m = cosim::export::write_cube3_export(name, scene, &cam, scene.volume.render_dims(), dir)
        .map_err(|e| anyhow::anyhow!("synth: {e}"))?;
    // A perspective view's base planes are systems of one build, but for
    // their ROMs' contents: the first stands for them.
    let first = &m["base_planes"][0];
    let files: Vec<String> = first["files"]
        .as_array()
        .context("manifest files")?
        .iter()
        .filter_map(|f| f.as_str().map(String::from))
        .collect();
    let sub = dir.join(first["dir"].as_str().unwrap_or("."));
    let r = synthesize(&sub, &files, target, pnr).map_err(|e| anyhow::anyhow!("synth: {e}"))?;
    let p = scene.hardware.pipelines as u64;
    let par = &m["parameters"];
    println!(
        "{} (cube3): {} cells, {} LUTs, {} flip-flops, {} block RAMs, {} DSPs ({:.1} s); per unit {:.1} LUTs, {:.1} DSPs",
        target.name(),
        r.cells,
        r.luts,
        r.flip_flops,
        r.block_rams,
        r.dsps,
        r.synth_seconds,
        r.luts as f64 / p as f64,
        r.dsps as f64 / p as f64
    );
    let words = par["buffers"]["words_per_buffer_module"]
        .as_u64()
        .unwrap_or(0);
    let dsb_bits = 3 * p * words * 16;
    println!(
        "2-DSBs: 3 x {p} modules x {words} words of 16 bits = {dsb_bits} bits; RAM primitives after synthesis: {} bits ({} voxel memory)",
        r.ram_bits,
        par["memory"]["kind"].as_str().unwrap_or("?")
    );
    let frame = par["frame_clocks"].as_u64().unwrap_or(0);
    if let (Some(part), Some(f)) = (r.part, r.fmax_mhz) {
        println!(
            "nextpnr ({part}): fmax {f:.2} MHz; this scene's frame, {frame} clocks: {:.2} frames/s",
            f * 1e6 / frame as f64
        );
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
    } else if r.fits == Some(false) {
        println!(
            "does not fit an {}: no place and route",
            r.part.unwrap_or("?")
        );
    }
    if let Some(j) = json_path {
        write_json(
            &j,
            &json!({
                "scene": name,
                "architecture": "cube3",
                "target": target.name(),
                "pipelines": p,
                "cells": r.cells,
                "luts": r.luts,
                "flip_flops": r.flip_flops,
                "block_rams": r.block_rams,
                "dsps": r.dsps,
                "cell_types": r.cell_types,
                "dsb_bits": dsb_bits,
                "ram_primitive_bits": r.ram_bits,
                "synth_seconds": r.synth_seconds,
                "part": r.part,
                "fits": r.fits,
                "fmax_mhz": r.fmax_mhz,
                "critical_path": r.timing.as_ref().map(|t| json!({
                    "from": {"cell": t.from.cell, "stage": t.from.stage},
                    "to": {"cell": t.to.cell, "stage": t.to.stage},
                    "cells": t.cells.len(),
                    "logic_ns": t.logic_ns,
                    "routing_ns": t.routing_ns,
                })),
                "pnr_seconds": r.pnr_seconds,
                "frame_clocks": frame,
                "frames_per_second": r.fmax_mhz.map(|f| f * 1e6 / frame as f64),
                "units_left_out": m["units_left_out"],
                "parameters": m["parameters"],
            }),
        )?;
    }
    Ok(())
}
