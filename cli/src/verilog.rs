//! `cube verilog`: write the scene's pruned pipeline as Verilog (one file per
//! stage, a top, Verilator lint waivers and a manifest of parameters and
//! left-out units) and summarize what was written.

use crate::common::scene_name;
use anyhow::Result;
use scene::Scene;
use std::path::PathBuf;

/// The architecture exported.
#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
enum VerilogArch {
    Cube4l,
    /// Cube-3: parallel and perspective views in every mode (the 6 or the
    /// 12 gradient neighbourhood).
    Cube3,
}

#[derive(clap::Args)]
pub struct VerilogArgs {
    #[arg(long)]
    scene: PathBuf,
    #[arg(long)]
    out: PathBuf,
    #[arg(long, value_enum, default_value = "cube4l")]
    arch: VerilogArch,
}

pub fn run(args: VerilogArgs) -> Result<()> {
    let VerilogArgs {
        scene: scene_path,
        out,
        arch,
    } = args;
    let scene = Scene::load(&scene_path)?;
    let cam = scene.camera()?;
    let name = scene_name(&scene_path);
    if arch == VerilogArch::Cube3 {
        let m = cosim::export::write_cube3_export(
            &name,
            &scene,
            &cam,
            scene.volume.render_dims(),
            &out,
        )
        .map_err(|e| anyhow::anyhow!("verilog: {e}"))?;
        println!(
            "wrote {} (Cube-3, {} memory, {} clocks a frame); units left out: {}",
            out.display(),
            m["parameters"]["memory"]["kind"].as_str().unwrap_or("?"),
            m["parameters"]["frame_clocks"],
            left_out(&m)
        );
        return Ok(());
    }
    let m = cosim::export::write_export(&name, &scene, &cam, scene.volume.render_dims(), &out)
        .map_err(|e| anyhow::anyhow!("verilog: {e}"))?;
    let sweeps = m["sweeps"].as_array().map_or(0, |s| s.len());
    println!(
        "wrote {} ({} sweep{}, {} memory); units left out: {}",
        out.display(),
        sweeps,
        if sweeps == 1 { "" } else { "s" },
        m["parameters"]["memory"]["kind"].as_str().unwrap_or("?"),
        left_out(&m)
    );
    Ok(())
}

/// The manifest's units left out, as a list.
fn left_out(m: &serde_json::Value) -> String {
    m["units_left_out"]
        .as_array()
        .map(|a| {
            a.iter()
                .filter_map(|v| v.as_str())
                .collect::<Vec<_>>()
                .join(", ")
        })
        .unwrap_or_default()
}
