//! `cube synth`: synthesize the scene's pipeline with yosys and report cells,
//! LUTs, flip-flops, block RAMs and DSPs; on iCE40, a design that fits an UP5K
//! is placed and routed with nextpnr-ice40 for fmax, and the frame rate is
//! projected for 256³ and 512³ volumes.

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
    Xilinx,
    Generic,
}

#[derive(clap::Args)]
pub struct SynthArgs {
    #[arg(long)]
    scene: PathBuf,
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
        target,
        json: json_path,
        no_pnr,
    } = args;
    let pnr = !no_pnr;
    let target = match target {
        SynthTarget::Ice40 => Target::Ice40,
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
    let mut projection = serde_json::Map::new();
    match (r.fits_up5k, r.fmax_mhz) {
        (Some(false), _) => println!(
            "does not fit an iCE40 UP5K ({} LUTs, {} BRAMs, {} DSPs available): no place and route",
            cosim::synth::UP5K.0,
            cosim::synth::UP5K.1,
            cosim::synth::UP5K.2
        ),
        (_, Some(f)) => {
            println!("nextpnr-ice40 (UP5K): fmax {f:.2} MHz");
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
                "synth_seconds": r.synth_seconds,
                "fits_up5k": r.fits_up5k,
                "fmax_mhz": r.fmax_mhz,
                "pnr_seconds": r.pnr_seconds,
                "projected": projection,
                "units_left_out": m["units_left_out"],
                "parameters": m["parameters"],
            }),
        )?;
    }
    Ok(())
}
