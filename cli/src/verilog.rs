//! `cube verilog`: write the scene's pruned pipeline as Verilog (one file per
//! stage, a top, Verilator lint waivers and a manifest of parameters and
//! left-out units) and summarize what was written.

use crate::common::scene_name;
use anyhow::Result;
use scene::Scene;
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct VerilogArgs {
    #[arg(long)]
    scene: PathBuf,
    #[arg(long)]
    out: PathBuf,
}

pub fn run(args: VerilogArgs) -> Result<()> {
    let VerilogArgs {
        scene: scene_path,
        out,
    } = args;
    let scene = Scene::load(&scene_path)?;
    let cam = scene.camera()?;
    let name = scene_name(&scene_path);
    let m = cosim::export::write_export(&name, &scene, &cam, scene.volume.render_dims(), &out)
        .map_err(|e| anyhow::anyhow!("verilog: {e}"))?;
    let sweeps = m["sweeps"].as_array().map_or(0, |s| s.len());
    println!(
        "wrote {} ({} sweep{}, {} memory); units left out: {}",
        out.display(),
        sweeps,
        if sweeps == 1 { "" } else { "s" },
        m["parameters"]["memory"]["kind"].as_str().unwrap_or("?"),
        m["units_left_out"]
            .as_array()
            .map(|a| a
                .iter()
                .filter_map(|v| v.as_str())
                .collect::<Vec<_>>()
                .join(", "))
            .unwrap_or_default()
    );
    Ok(())
}
