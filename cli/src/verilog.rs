//! `cube verilog`: write the scene's pruned hardware as Verilog (one file per
//! stage, a top, Verilator lint waivers and a manifest of parameters and
//! left-out units) and summarize what was written.

use crate::common::{scene_name, HwArch};
use anyhow::Result;
use cosim::arch::Arch;
use cosim::archs::ForArch;
use scene::Scene;
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct VerilogArgs {
    #[arg(long)]
    scene: PathBuf,
    #[arg(long)]
    out: PathBuf,
    #[arg(long, value_enum, default_value = "cube4l")]
    arch: HwArch,
}

pub fn run(args: VerilogArgs) -> Result<()> {
    args.arch.arch().with(Export(&args))
}

struct Export<'a>(&'a VerilogArgs);

impl ForArch for Export<'_> {
    type Output = Result<()>;
    fn run<A: Arch>(self) -> Result<()> {
        let args = self.0;
        let scene = Scene::load(&args.scene)?;
        let cam = scene.camera()?;
        let m = cosim::export::write_export::<A>(
            &scene_name(&args.scene),
            &scene,
            &cam,
            scene.volume.render_dims(),
            &args.out,
        )
        .map_err(|e| anyhow::anyhow!("verilog: {e}"))?;
        let parts = m[format!("{}s", A::PART)].as_array().map_or(0, |a| a.len());
        let left_out: Vec<&str> = m["units_left_out"]
            .as_array()
            .map(|a| a.iter().filter_map(|v| v.as_str()).collect())
            .unwrap_or_default();
        println!(
            "wrote {} ({}, {} {}{}, {} memory); units left out: {}",
            args.out.display(),
            A::TITLE,
            parts,
            A::PART.replace('_', " "),
            if parts == 1 { "" } else { "s" },
            m["parameters"]["memory"]["kind"].as_str().unwrap_or("?"),
            left_out.join(", ")
        );
        Ok(())
    }
}
