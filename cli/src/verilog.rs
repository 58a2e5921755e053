//! `cube verilog`: write a build's hardware as Verilog (one file per stage,
//! a top, Verilator lint waivers and a manifest of its configuration,
//! parameters and left-out units). The build is `--config`, or the
//! configuration `--scene` needs; with both, the scene must be one the
//! configuration renders (the refusal names why not), and the manifest
//! lists the scene's parts and the register writes each takes.

use crate::common::{choose_build, Loaded};
use crate::methods::HwArch;
use anyhow::Result;
use cosim::arch::Arch;
use cosim::archs::ForArch;
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct VerilogArgs {
    /// A scene: its configuration is the build, unless --config names one.
    #[arg(long)]
    scene: Option<PathBuf>,
    /// A configuration by name (`cube verilog --scene S` prints the one S
    /// needs), e.g. composite_shaded_p4_256.
    #[arg(long)]
    config: Option<String>,
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
        let err = |e: String| anyhow::anyhow!("verilog: {e}");
        let (loaded, build) =
            choose_build::<A>("verilog", args.scene.as_deref(), args.config.as_deref())?;
        // The export replaces --out as a whole: no input of the run may
        // lie in it.
        let mut files = crate::output::Files::default();
        if let (Some(path), Some(l)) = (&args.scene, &loaded) {
            files.scene("--scene", path, &l.scene)?;
        }
        files.output_dir("--out", &args.out)?;
        let scene = loaded.as_ref().map(Loaded::export);
        let m = cosim::export::write_export::<A>(&args.out, &build, scene.as_ref()).map_err(err)?;
        let left_out: Vec<&str> = m["units_left_out"]
            .as_array()
            .map(|a| a.iter().filter_map(|v| v.as_str()).collect())
            .unwrap_or_default();
        println!(
            "wrote {} ({} configuration {}, {} memory); units left out: {}",
            args.out.display(),
            A::TITLE,
            A::config_name(&build),
            memory_kind(&m["parameters"]["memory"]),
            if left_out.is_empty() {
                "none".into()
            } else {
                left_out.join(", ")
            }
        );
        Ok(())
    }
}

/// The manifest's memory kind (a string, or an object with `kind`).
fn memory_kind(m: &serde_json::Value) -> &str {
    m.as_str().or_else(|| m["kind"].as_str()).unwrap_or("?")
}
